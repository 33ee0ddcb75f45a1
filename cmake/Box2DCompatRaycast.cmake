# SPDX-License-Identifier: MIT
# Builds bindings/box2d-compat/Box2D/_raycast.c as a module for I2D_PYTHON_WITH_PYTEST
# (target box2d_compat_raycast), when that Python has its headers (Debian: python3-dev).
# The module binds to the library ctypes loads, so it links to nothing. Without the
# headers, nothing is built and the compat Box2D runs its Python ray cast loop.
execute_process(
  COMMAND ${I2D_PYTHON_WITH_PYTEST} -c
          "import sysconfig; print(sysconfig.get_paths()['include']); print(sysconfig.get_config_var('EXT_SUFFIX'))"
  OUTPUT_VARIABLE python_facts OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE python_facts_rc)
if(python_facts_rc EQUAL 0)
  string(REPLACE "\n" ";" python_facts "${python_facts}")
  list(GET python_facts 0 python_include)
  list(GET python_facts 1 python_suffix)
endif()
if(python_facts_rc EQUAL 0 AND EXISTS "${python_include}/Python.h")
  add_library(box2d_compat_raycast MODULE ${PROJECT_SOURCE_DIR}/bindings/box2d-compat/Box2D/_raycast.c)
  target_include_directories(box2d_compat_raycast PRIVATE ${PROJECT_SOURCE_DIR}/include)
  target_include_directories(box2d_compat_raycast SYSTEM PRIVATE ${python_include})
  set_target_properties(box2d_compat_raycast PROPERTIES
    PREFIX "" OUTPUT_NAME _raycast SUFFIX "${python_suffix}"
    LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/bindings/box2d-compat)
  if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(box2d_compat_raycast PRIVATE -Wall -Wextra)
    if(I2D_WERROR)
      target_compile_options(box2d_compat_raycast PRIVATE -Werror)
    endif()
  endif()
else()
  message(STATUS "No Python headers for ${I2D_PYTHON_WITH_PYTEST}: the compat Box2D's tests run its "
                 "Python ray cast loop alone (apt-get install python3-dev)")
endif()
