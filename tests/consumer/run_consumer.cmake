# Script mode (cmake -P): install, configure the consumer app against the install, build, run.
# Inputs: COLLIDE_BUILD_DIR, APP_SOURCE_DIR, WORK_DIR, APP_GENERATOR, APP_CXX_COMPILER, APP_LAUNCHER.
foreach(var COLLIDE_BUILD_DIR APP_SOURCE_DIR WORK_DIR APP_GENERATOR APP_CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer.cmake: ${var} is not set")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(app_build "${WORK_DIR}/app-build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer: ${what} failed (${rc}): ${ARGN}")
  endif()
  message(STATUS "consumer: ${what}: ok")
endfunction()

run_step("install into ${prefix}" ${CMAKE_COMMAND} --install "${COLLIDE_BUILD_DIR}" --prefix "${prefix}")

set(launcher_arg "")
if(APP_LAUNCHER)
  set(launcher_arg "-DCMAKE_CXX_COMPILER_LAUNCHER=${APP_LAUNCHER}")
endif()
# Only the fresh prefix may satisfy find_package: no package registry, no build tree.
run_step("configure the consumer app"
  ${CMAKE_COMMAND} -S "${APP_SOURCE_DIR}" -B "${app_build}" -G "${APP_GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_CXX_COMPILER=${APP_CXX_COMPILER}" ${launcher_arg}
    "-DCMAKE_PREFIX_PATH=${prefix}"
    -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON
    -DCMAKE_FIND_PACKAGE_NO_SYSTEM_PACKAGE_REGISTRY=ON
    "-DCOLLIDE_EXPECTED_PREFIX=${prefix}")
run_step("build the consumer app" ${CMAKE_COMMAND} --build "${app_build}")
run_step("run the consumer app" "${app_build}/collide_consumer")
