# Script mode (cmake -P): builds and runs a separate consumer project the way a game would.
# MODE find_package: install this build into a fresh prefix, check its pkg-config file, then
#   configure tests/consumer/app against that prefix only, build and run it (collide::collide and
#   collide::compiled); then tests/consumer/judge_app (find_package(collide COMPONENTS judge): an
#   in-process adapter judged for a fixed number of cases, its report's keys checked), and the
#   component judge installed alone.
# MODE fetch_content: configure tests/consumer/fetch_app, which takes lib/ with FetchContent from
#   this checkout, build and run it, install it and check that nothing of collide was installed.
# Inputs: MODE, COLLIDE_BUILD_DIR, COLLIDE_SOURCE_DIR, WORK_DIR, APP_GENERATOR, APP_CXX_COMPILER,
# APP_LAUNCHER (optional).
foreach(var MODE COLLIDE_BUILD_DIR COLLIDE_SOURCE_DIR WORK_DIR APP_GENERATOR APP_CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer.cmake: ${var} is not set")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(app_build "${WORK_DIR}/app-build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer: ${what} failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "consumer: ${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(configure_args -G "${APP_GENERATOR}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_COMPILER=${APP_CXX_COMPILER}"
    -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON -DCMAKE_FIND_PACKAGE_NO_SYSTEM_PACKAGE_REGISTRY=ON)
if(APP_LAUNCHER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER_LAUNCHER=${APP_LAUNCHER}")
endif()

if(MODE STREQUAL "find_package")
  run_step("install into ${prefix}" ${CMAKE_COMMAND} --install "${COLLIDE_BUILD_DIR}" --prefix "${prefix}")

  # pkg-config: the installed file names the installed headers, wherever the prefix was moved.
  find_program(PKG_CONFIG pkg-config REQUIRED)
  set(ENV{PKG_CONFIG_PATH} "${prefix}/share/pkgconfig")
  run_step("pkg-config finds collide" ${PKG_CONFIG} --cflags collide)
  string(STRIP "${step_output}" cflags)
  separate_arguments(cflags UNIX_COMMAND "${cflags}")
  run_step("a file compiles with pkg-config's flags alone"
    ${APP_CXX_COMPILER} -std=c++20 -fsyntax-only ${cflags} -x c++ "${COLLIDE_SOURCE_DIR}/tests/consumer/app/main.cpp")

  # Only the fresh prefix may satisfy find_package: no package registry, no build tree.
  run_step("configure the consumer app"
    ${CMAKE_COMMAND} -S "${COLLIDE_SOURCE_DIR}/tests/consumer/app" -B "${app_build}" ${configure_args}
      "-DCMAKE_PREFIX_PATH=${prefix}" "-DCOLLIDE_EXPECTED_PREFIX=${prefix}")
  run_step("build the consumer app (strict warnings, collide's headers not system)" ${CMAKE_COMMAND} --build "${app_build}")
  run_step("run the consumer app" "${app_build}/collide_consumer")
  run_step("run the consumer app on collide::compiled" "${app_build}/collide_consumer_compiled")
  # The queries it calls come from the library: its own object defines no instantiation of them.
  find_program(NM nm REQUIRED)
  run_step("list the definitions of its object" ${NM} -C --defined-only
    "${app_build}/CMakeFiles/collide_consumer_compiled.dir/compiled_main.cpp.o")
  string(REGEX MATCHALL "collide::(overlaps|contact|distance|resolve|contains|raycast|bounds|shape_cast|time_of_impact)<std::variant<[^\n]*"
         instantiated "${step_output}")
  if(instantiated)
    list(JOIN instantiated "\n  " text)
    message(FATAL_ERROR "consumer: the object instantiates queries collide::compiled holds:\n  ${text}")
  endif()

  # The judge (component judge): a project judging its own circle code, then the report's keys.
  set(judge_build "${WORK_DIR}/judge-build")
  set(judge_out "${WORK_DIR}/judge-reports")
  run_step("configure the judge consumer (find_package(collide COMPONENTS judge))"
    ${CMAKE_COMMAND} -S "${COLLIDE_SOURCE_DIR}/tests/consumer/judge_app" -B "${judge_build}" ${configure_args}
      "-DCMAKE_PREFIX_PATH=${prefix}" "-DCOLLIDE_EXPECTED_PREFIX=${prefix}")
  run_step("build the judge consumer" ${CMAKE_COMMAND} --build "${judge_build}")
  run_step("run the judge consumer" "${judge_build}/collide_judge_consumer" "${judge_out}")
  file(READ "${judge_out}/tiny-circles.json" report)
  foreach(key IN ITEMS library version counts contract mapping seed cases seconds)
    string(JSON value ERROR_VARIABLE missing GET "${report}" ${key})
    if(missing)
      message(FATAL_ERROR "consumer: the judge's report has no '${key}': ${missing}")
    endif()
  endforeach()
  string(JSON library GET "${report}" library)
  string(JSON agree GET "${report}" counts agree)
  if(NOT library STREQUAL "tiny-circles" OR agree LESS 1000)
    message(FATAL_ERROR "consumer: the judge's report names '${library}' with ${agree} answers agreeing")
  endif()
  message(STATUS "consumer: the judge's report tiny-circles.json: ${agree} answers agree")
  run_step("the installed driver runs" "${prefix}/bin/collide_judge" --list)

  # The component alone: the judge's files, none of the library's.
  run_step("install the judge component alone" ${CMAKE_COMMAND} --install "${COLLIDE_BUILD_DIR}"
    --prefix "${WORK_DIR}/judge-only" --component judge)
  foreach(f IN ITEMS include/collide/judge/judge.hpp include/collide/oracle/oracle.hpp
                     include/collide/laws/codec.hpp bin/collide_judge share/cmake/collide/collide-judge.cmake
                     share/cmake/collide/collideJudgeTargets.cmake)
    if(NOT EXISTS "${WORK_DIR}/judge-only/${f}")
      message(FATAL_ERROR "consumer: --component judge did not install ${f}")
    endif()
  endforeach()
  if(EXISTS "${WORK_DIR}/judge-only/include/collide/collide.hpp")
    message(FATAL_ERROR "consumer: --component judge installed the library's headers too")
  endif()
elseif(MODE STREQUAL "fetch_content")
  run_step("configure the FetchContent consumer"
    ${CMAKE_COMMAND} -S "${COLLIDE_SOURCE_DIR}/tests/consumer/fetch_app" -B "${app_build}" ${configure_args}
      "-DFETCHCONTENT_SOURCE_DIR_COLLIDE=${COLLIDE_SOURCE_DIR}" -DFETCHCONTENT_FULLY_DISCONNECTED=ON)
  run_step("build the FetchContent consumer (strict warnings)" ${CMAKE_COMMAND} --build "${app_build}")
  run_step("run the FetchContent consumer" "${app_build}/collide_fetch_consumer")
  run_step("install the game" ${CMAKE_COMMAND} --install "${app_build}" --prefix "${prefix}")
  file(GLOB_RECURSE installed RELATIVE "${prefix}" "${prefix}/*")
  foreach(f IN LISTS installed)
    if(f MATCHES "collide/|collideConfig|collide\\.pc")
      message(FATAL_ERROR "consumer: installing the game also installed collide's ${f}")
    endif()
  endforeach()
  message(STATUS "consumer: the game's install holds only its own files: ${installed}")
else()
  message(FATAL_ERROR "run_consumer.cmake: unknown MODE '${MODE}'")
endif()
