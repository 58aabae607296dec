# Installs shadowproof from the build tree into a fresh prefix, then configures, builds and runs
# tests/cmake/consumer, a separate project that uses find_package(shadowproof).
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${prefix}
  RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/cmake/consumer -B ${WORK_DIR}/build
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
  "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_FLAGS}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "building the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(rc OR NOT out MATCHES "^1/3 0 13/3\n[1-9][0-9]* implementations, 0 ulps\narea² 1\n$")
  message(FATAL_ERROR "the consumer printed '${out}' (exit ${rc}), expected '1/3 0 13/3', "
                      "'N implementations, 0 ulps' and 'area² 1'")
endif()
if(NOT EXISTS ${prefix}/bin/shadowproof)
  message(FATAL_ERROR "the shadowproof executable was not installed")
endif()

# The package version: 0.2 and 0.2.0 are satisfied; another minor version is not (0.x minor
# versions may break the API: SameMinorVersion), nor is a later one. The first probe also asks
# for the components testing and cgal (which finds CGAL).
foreach(required "0.2 COMPONENTS testing cgal" 0.2.0 0.1 0.3 1.0)
  string(REPLACE " " "-" probe_name "${required}")
  set(probe ${WORK_DIR}/version-${probe_name})
  file(WRITE ${probe}/CMakeLists.txt
    "cmake_minimum_required(VERSION 3.25)\nproject(version_probe LANGUAGES CXX)\n"
    "find_package(shadowproof ${required} CONFIG QUIET)\n"
    "message(STATUS \"found=\${shadowproof_FOUND} version=\${shadowproof_VERSION}\")\n")
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${probe} -B ${probe}/build -DCMAKE_PREFIX_PATH=${prefix}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(required MATCHES "^0\\.2")
    set(expected "found=1 version=0.2.0")
  else()
    set(expected "found=0")
  endif()
  string(FIND "${out}" "${expected}" at)
  if(rc OR at EQUAL -1)
    message(FATAL_ERROR "find_package(shadowproof ${required}) should give '${expected}':\n${out}\n${err}")
  endif()
endforeach()
