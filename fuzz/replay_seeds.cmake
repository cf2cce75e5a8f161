# ctest fuzz.seeds.<target>: unpacks a seed archive into a fresh directory and replays every
# input in it through the target's replay executable.
#
#   cmake -DREPLAY=<fuzz_replay_target> -DARCHIVE=<target>_seed_corpus.zip -DDIR=<scratch dir>
#         -P replay_seeds.cmake
#
# DIR is emptied first, so an input dropped from the archive is never replayed from an older
# unpacking.

foreach(var IN ITEMS REPLAY ARCHIVE DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "replay_seeds.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXISTS "${ARCHIVE}")
  message(FATAL_ERROR "no seed archive ${ARCHIVE}: export the seeds with `./harness fuzz --export-seeds`")
endif()

file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
file(ARCHIVE_EXTRACT INPUT "${ARCHIVE}" DESTINATION "${DIR}")
file(GLOB_RECURSE inputs LIST_DIRECTORIES false "${DIR}/*")
list(LENGTH inputs count)
if(count EQUAL 0)
  message(FATAL_ERROR "${ARCHIVE} holds no inputs")
endif()

execute_process(COMMAND "${REPLAY}" "${DIR}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "replay of the ${count} inputs of ${ARCHIVE} failed (${status})")
endif()
