# Script mode (cmake -P): configure, build and run the ThreadSanitizer build of the broadphase
# threading test. Inputs: SOURCE_DIR (this directory), WORK_DIR, COLLIDE_INCLUDE_DIR, TEST_SOURCE,
# APP_GENERATOR, APP_CXX_COMPILER, APP_LAUNCHER (optional compiler cache).
foreach(var SOURCE_DIR WORK_DIR COLLIDE_INCLUDE_DIR TEST_SOURCE APP_GENERATOR APP_CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_tsan.cmake: ${var} is not set")
  endif()
endforeach()
function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "tsan: ${what} failed (${rc})")
  endif()
  message(STATUS "tsan: ${what}: ok")
endfunction()
set(launcher_arg "")
if(APP_LAUNCHER)
  set(launcher_arg "-DCMAKE_CXX_COMPILER_LAUNCHER=${APP_LAUNCHER}")
endif()
run_step("configure" ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK_DIR}" -G "${APP_GENERATOR}"
  -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_COMPILER=${APP_CXX_COMPILER}" ${launcher_arg}
  "-DCOLLIDE_INCLUDE_DIR=${COLLIDE_INCLUDE_DIR}" "-DCOLLIDE_TEST_SOURCE=${TEST_SOURCE}")
run_step("build" ${CMAKE_COMMAND} --build "${WORK_DIR}")
# halt_on_error: the first race fails the test with its report.
set(ENV{TSAN_OPTIONS} "halt_on_error=1 second_deadlock_stack=1")
run_step("run under ThreadSanitizer" "${WORK_DIR}/broadphase_threads_tsan")
