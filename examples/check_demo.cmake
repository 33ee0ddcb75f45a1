# SPDX-License-Identifier: MIT
# Runs the demo and checks the SVG it writes: present, complete, and holding the scene.
# Usage: cmake -DDEMO=path/to/impulse2d_demo -DSVG=path/to/out.svg -P check_demo.cmake
if(NOT DEMO OR NOT SVG)
  message(FATAL_ERROR "usage: cmake -DDEMO=<demo> -DSVG=<out.svg> -P check_demo.cmake")
endif()

# A picture left over from an earlier run must not make this pass.
file(REMOVE ${SVG})
execute_process(COMMAND ${DEMO} ${SVG} RESULT_VARIABLE rc OUTPUT_VARIABLE report)
message(STATUS "${report}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the demo exited with ${rc}")
endif()

# The joints held: no joint of the bridge or the ragdoll came 5 cm apart (a torn joint shows
# metres), and the car rolls at its motors' speed w r within 5 %.
if(NOT report MATCHES "during the run: ([0-9.]+) mm")
  message(FATAL_ERROR "the demo's report has no joint gap line")
endif()
set(gap ${CMAKE_MATCH_1})
if(NOT gap LESS 50)
  message(FATAL_ERROR "a joint of the bridge or the ragdoll came ${gap} mm apart (allowed: under 50)")
endif()
if(NOT report MATCHES "m/s, ([0-9.]+) % of the motors' w r")
  message(FATAL_ERROR "the demo's report has no car speed line")
endif()
set(share ${CMAKE_MATCH_1})
if(share LESS 95 OR share GREATER 105)
  message(FATAL_ERROR "the car rolls at ${share} % of its motors' w r (expected 95 to 105)")
endif()

# The world saved halfway, restored after the run and run to the end again, ends with the same
# state hash (the demo prints DIFFERS, and exits 1, when it does not).
if(NOT report MATCHES "snapshot: restored at step ([0-9]+) \\([0-9]+ bytes\\), hash after ([0-9]+) more steps matches \\(([0-9a-f]+)\\)")
  message(FATAL_ERROR "the demo's report has no snapshot line saying the hashes match")
endif()
message(STATUS "snapshot restored at step ${CMAKE_MATCH_1}: the same hash ${CMAKE_MATCH_3} after ${CMAKE_MATCH_2} steps")

if(NOT EXISTS ${SVG})
  message(FATAL_ERROR "the demo exited 0 but wrote no ${SVG}")
endif()

file(SIZE ${SVG} size)
file(READ ${SVG} text)
# The picture comes through i2d_world_draw (the bodies now, then dashed where the moving ones
# started). The scene draws 5 circles (4 balls, a disc), about 35 polygons (boxes, walls, ledge,
# ramp, triangle, pentagon, and dashed start outlines), 2 rounded shapes as <path> (a capsule and a
# rounded polygon) and 8 polylines (4 ball paths, 3 centres, the disc's rim point). The joint
# floor adds at least 36 circles (the car's 2 wheels, the bump, a dot at each of the 33 joints'
# anchors), 23 polygons (20 planks, 2 posts, the chassis; its floor's 3 boxes) and 13 paths (the
# ragdoll's 11 capsules and 2 feet).
set(counts "")
set(too_few FALSE)
foreach(kind_min IN ITEMS "circle:41" "polygon:56" "path:15" "polyline:8")
  string(REPLACE ":" ";" kind_min "${kind_min}")
  list(GET kind_min 0 kind)
  list(GET kind_min 1 minimum)
  string(REGEX MATCHALL "<${kind} " found "${text}")
  list(LENGTH found count)
  string(APPEND counts " ${count} <${kind}>")
  if(count LESS minimum)
    set(too_few TRUE)
  endif()
endforeach()
# The joint floor's parts are labelled.
foreach(label IN ITEMS "chain bridge" "car on wheel joints")
  if(NOT text MATCHES "${label}")
    set(too_few TRUE)
    string(APPEND counts " (no \"${label}\" label)")
  endif()
endforeach()
if(size LESS 10000 OR NOT text MATCHES "<svg " OR NOT text MATCHES "</svg>[ \n]*$" OR too_few)
  message(FATAL_ERROR "${SVG} looks wrong: ${size} bytes,${counts}")
endif()
message(STATUS "${SVG}: ${size} bytes,${counts}")
