# SPDX-License-Identifier: MIT
# Installs the build into a scratch prefix, then builds and runs a consumer project
# against it with find_package(impulse2d 0.2) (the shared library, the C++ header, and the
# static library when it was built too), and a C program with pkg-config's flags.
# Usage: cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... -DC_COMPILER=... -DCXX_COMPILER=...
#        [-DPKG_CONFIG=...] -P check_install.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed: ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --component Unspecified)
foreach(header impulse2d.h impulse2d.hpp base.h id.h types.h collision.h)
  if(NOT EXISTS ${prefix}/include/impulse2d/${header})
    message(FATAL_ERROR "include/impulse2d/${header} was not installed")
  endif()
endforeach()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/consumer -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(${WORK_DIR}/consumer/consumer)
run(${WORK_DIR}/consumer/consumer_cpp)
if(EXISTS ${WORK_DIR}/consumer/consumer_static)
  run(${WORK_DIR}/consumer/consumer_static)
  # Linked statically: it must not need libimpulse2d.so at run time.
  find_program(READELF readelf)
  if(READELF)
    execute_process(COMMAND ${READELF} -d ${WORK_DIR}/consumer/consumer_static OUTPUT_VARIABLE dynamic)
    if(dynamic MATCHES "libimpulse2d")
      message(FATAL_ERROR "consumer_static needs libimpulse2d.so:\n${dynamic}")
    endif()
  endif()
endif()

# pkg-config: the installed impulse2d.pc compiles and links the same program.
if(PKG_CONFIG)
  file(GLOB pc_dirs ${prefix}/lib*/pkgconfig ${prefix}/lib/*/pkgconfig)
  set(ENV{PKG_CONFIG_PATH} "${pc_dirs}")
  execute_process(COMMAND ${PKG_CONFIG} --modversion impulse2d OUTPUT_VARIABLE version
                  OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR NOT version VERSION_GREATER_EQUAL 0.2)
    message(FATAL_ERROR "pkg-config does not find impulse2d >= 0.2 in ${pc_dirs} (got '${version}')")
  endif()
  execute_process(COMMAND ${PKG_CONFIG} --cflags --libs impulse2d OUTPUT_VARIABLE flags
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  separate_arguments(flags UNIX_COMMAND "${flags}")
  run(${C_COMPILER} ${SOURCE_DIR}/main.c ${flags} -o ${WORK_DIR}/consumer_pc)
  set(ENV{LD_LIBRARY_PATH} "${pc_dirs}/..")
  run(${WORK_DIR}/consumer_pc)
endif()
