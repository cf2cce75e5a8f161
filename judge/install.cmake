# Install component "judge": the judge for another project's collision code, without collide's
# test tree (docs/judge.md, "Judge your own code"). Installs the judge's headers and library, the
# exact oracle and the laws it is built on (headers and static libraries), the driver
# collide_judge, and the exported targets collide::judge, collide::oracle, collide::laws and
# collide::collide_judge (the driver), loaded by find_package(collide COMPONENTS judge) through
# share/cmake/collide/collide-judge.cmake (which finds CGAL for the oracle's GMP and MPFR).
#
#   cmake --install <build> --prefix P                      # the library and the judge
#   cmake --install <build> --prefix P --component judge    # the judge, beside an installed library
#
# The installed driver runs the in-process adapters it was built with (course-notes, and box2d and
# chipmunk where their Debian packages were found); the JavaScript adapters need --js-dir naming a
# checkout's judge/js.
if(NOT COLLIDE_INSTALL)
  return()
endif()
include(GNUInstallDirs)
set(_collide_cmake_dir ${CMAKE_INSTALL_DATADIR}/cmake/collide)

set_target_properties(collide_judge PROPERTIES EXPORT_NAME judge)
set_target_properties(collide_oracle PROPERTIES EXPORT_NAME oracle)
set_target_properties(collide_laws PROPERTIES EXPORT_NAME laws)
set_target_properties(collide_judge_cli PROPERTIES EXPORT_NAME collide_judge)

install(DIRECTORY include/collide ${PROJECT_SOURCE_DIR}/oracles/exact/include/collide
                  ${PROJECT_SOURCE_DIR}/oracles/laws/include/collide
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT judge)
install(TARGETS collide_judge collide_oracle collide_laws collide_judge_cli EXPORT collideJudgeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT judge
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT judge)
install(EXPORT collideJudgeTargets NAMESPACE collide:: DESTINATION ${_collide_cmake_dir} COMPONENT judge)
install(FILES collide-judge.cmake DESTINATION ${_collide_cmake_dir} COMPONENT judge)
