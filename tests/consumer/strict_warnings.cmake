# The warnings a careful game builds with. collide's headers are included as ordinary (not
# system) headers here, so any warning they raise fails the consumer build; Eigen's stay system
# headers (their warnings are Eigen's).
function(collide_strict_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Werror)
  get_target_property(imported collide::collide IMPORTED)
  if(imported)
    # CMake 3.25+: an imported target's include directories are system headers unless SYSTEM is off.
    if(CMAKE_VERSION VERSION_LESS 3.25)
      message(FATAL_ERROR "the strict-warnings consumer needs CMake 3.25 to include an imported target's headers as ordinary headers")
    endif()
    set_target_properties(collide::collide PROPERTIES SYSTEM OFF)
  endif()
endfunction()
