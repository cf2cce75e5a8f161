# find_package(collide COMPONENTS judge), loaded by collideConfig.cmake: the judge's targets
# (collideJudgeTargets.cmake) and what they link. The oracle's CGAL is header-only; its target
# CGAL::CGAL brings the GMP and MPFR libraries the installed oracle links (without gmpxx, as the
# oracle was built).
if(NOT DEFINED CGAL_WITH_GMPXX)
  set(CGAL_WITH_GMPXX OFF)
endif()
find_package(CGAL QUIET)
if(NOT CGAL_FOUND)
  set(collide_judge_FOUND FALSE)
  set(collide_NOT_FOUND_MESSAGE "collide's judge component needs CGAL, GMP and MPFR (Debian: libcgal-dev)")
  return()
endif()
include("${CMAKE_CURRENT_LIST_DIR}/collideJudgeTargets.cmake")
set(collide_judge_FOUND TRUE)
