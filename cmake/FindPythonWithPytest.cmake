# SPDX-License-Identifier: MIT
# Sets I2D_PYTHON_WITH_PYTEST to the first Python 3 that imports pytest and numpy: the
# one CMake finds first, then the system's /usr/bin/python3 (a pyenv or venv interpreter
# often lacks Debian's python3-pytest and python3-numpy). Empty, with a warning, if none.
if(NOT DEFINED I2D_PYTHON_WITH_PYTEST)
  find_package(Python3 COMPONENTS Interpreter QUIET)
  set(candidates ${Python3_EXECUTABLE} /usr/bin/python3)
  set(found "")
  foreach(python IN LISTS candidates)
    if(EXISTS ${python})
      execute_process(COMMAND ${python} -c "import pytest, numpy" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
      if(rc EQUAL 0)
        set(found ${python})
        break()
      endif()
    endif()
  endforeach()
  if(found)
    set(I2D_PYTHON_WITH_PYTEST "${found}" CACHE STRING "Python 3 interpreter with pytest and numpy")
  else()
    # Not cached: the next configure looks again, e.g. after apt-get install.
    message(WARNING "No Python 3 with pytest and numpy: the python tests will be skipped "
                    "(apt-get install python3-pytest python3-numpy)")
  endif()
endif()
