# SPDX-License-Identifier: MIT
# Runs the demo and checks the SVG it writes: present, complete, and holding the scene.
# Usage: cmake -DDEMO=path/to/impulse2d_demo -DSVG=path/to/out.svg -P check_demo.cmake
if(NOT DEMO OR NOT SVG)
  message(FATAL_ERROR "usage: cmake -DDEMO=<demo> -DSVG=<out.svg> -P check_demo.cmake")
endif()

# A picture left over from an earlier run must not make this pass.
file(REMOVE ${SVG})
execute_process(COMMAND ${DEMO} ${SVG} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the demo exited with ${rc}")
endif()
if(NOT EXISTS ${SVG})
  message(FATAL_ERROR "the demo exited 0 but wrote no ${SVG}")
endif()

file(SIZE ${SVG} size)
file(READ ${SVG} text)
# The scene holds 4 balls and 14 boxes; each ball has a path polyline.
string(REGEX MATCHALL "<circle " circles "${text}")
string(REGEX MATCHALL "<rect " rects "${text}")
string(REGEX MATCHALL "<polyline " paths "${text}")
list(LENGTH circles circle_count)
list(LENGTH rects rect_count)
list(LENGTH paths path_count)
if(size LESS 2000 OR NOT text MATCHES "<svg " OR NOT text MATCHES "</svg>[ \n]*$"
   OR circle_count LESS 4 OR rect_count LESS 14 OR path_count LESS 4)
  message(FATAL_ERROR "${SVG} looks wrong: ${size} bytes, ${circle_count} circles, "
                      "${rect_count} rects, ${path_count} polylines")
endif()
message(STATUS "${SVG}: ${size} bytes, ${circle_count} circles, ${rect_count} rects, ${path_count} polylines")
