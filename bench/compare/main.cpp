// The driver of bench/compare/compare_headers.py: both sides' passes over each kind pair,
// alternately, the best of `reps` each; prints new / old per kind pair and over all of them.
// Built with COMPARE_BOX2D, the old side is Box2D 2.4.1's b2Collide* on the new side's pairs
// (time_box2d_new) and the ratio collide / Box2D; with COMPARE_WORLD too, Box2D's manifolds are also
// turned into world values (time_box2d_world_new), as contact() returns them. Best-of passes replay the same pairs, so
// both sides run with warm caches and trained branch predictors: the ratios say where the time goes, the game loop says
// how much.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

extern "C" std::size_t group_count_new(std::size_t bodies);
extern "C" const char* group_name_new(std::size_t bodies, std::size_t g, std::size_t* pairs);
extern "C" double time_group_new(std::size_t bodies, std::size_t g, long* points);
extern "C" void select_new(int which);
#ifdef COMPARE_BOX2D
extern "C" double time_box2d_new(std::size_t bodies, std::size_t g, long* points);
extern "C" double time_box2d_world_new(std::size_t bodies, std::size_t g, long* points);
#define OLD(name) name##_new
#ifdef COMPARE_WORLD
#define TIME_OLD time_box2d_world_new
#define OLD_LABEL "Box2D+world"
#else
#define TIME_OLD time_box2d_new
#define OLD_LABEL "Box2D"
#endif
#define NEW_LABEL "collide"
constexpr bool kSameAnswers = false;  // Box2D's capsules (2-gons with a radius) find other points
#else
extern "C" std::size_t group_count_old(std::size_t bodies);
extern "C" const char* group_name_old(std::size_t bodies, std::size_t g, std::size_t* pairs);
extern "C" double time_group_old(std::size_t bodies, std::size_t g, long* points);
extern "C" void select_old(int which);
#define OLD(name) name##_old
#define TIME_OLD time_group_old
#define OLD_LABEL "old"
#define NEW_LABEL "new"
constexpr bool kSameAnswers = true;
#endif

int main(int argc, char** argv) {
  // PAIRS: all of them, or only those contact() finds apart, or only those it finds in contact.
  const char* const selections[] = {"all", "apart", "contact"};
  int which = 0;
  while (argc == 4 && which < 3 && std::strcmp(argv[3], selections[which]) != 0) ++which;
  if ((argc != 3 && argc != 4) || which == 3) {
    std::fprintf(stderr, "usage: %s BODIES REPS [all|apart|contact]\n", argv[0]);
    return 2;
  }
  const std::size_t bodies = std::strtoul(argv[1], nullptr, 10);
  const long reps = std::strtol(argv[2], nullptr, 10);
  select_new(which);
  OLD(select)(which);
  const std::size_t groups = group_count_new(bodies);
  if (groups != OLD(group_count)(bodies) || reps < 1) {
    std::fprintf(stderr, "the two sides replay different pairs\n");
    return 1;
  }
  double all_old = 0, all_new = 0;
  bool same = true;
  for (std::size_t g = 0; g < groups; ++g) {
    std::size_t pairs_old = 0, pairs_new = 0;
    const char* name = group_name_new(bodies, g, &pairs_new);
    if (std::strcmp(name, OLD(group_name)(bodies, g, &pairs_old)) != 0 || pairs_old != pairs_new) same = false;
    if (pairs_new == 0 || pairs_old == 0) continue;  // a selection left none of this kind pair
    double best_old = 1e300, best_new = 1e300;
    long points_old = 0, points_new = 0;
    for (long r = 0; r < reps; ++r) {
      best_old = std::min(best_old, TIME_OLD(bodies, g, &points_old));
      best_new = std::min(best_new, time_group_new(bodies, g, &points_new));
    }
    all_old += best_old;
    all_new += best_new;
    std::printf("%-18s %6zu pairs  " OLD_LABEL " %7.1f  " NEW_LABEL " %7.1f ns/pair  " NEW_LABEL "/" OLD_LABEL
                " %.3f  points %ld / %ld%s\n",
                name, pairs_new, best_old / double(pairs_old), best_new / double(pairs_new), best_new / best_old,
                points_new, points_old, kSameAnswers && points_old != points_new ? "  (points differ)" : "");
  }
  std::printf("%-18s %6s        " OLD_LABEL " %7.1f  " NEW_LABEL " %7.1f us       " NEW_LABEL "/" OLD_LABEL " %.3f\n",
              "all", "", all_old / 1e3, all_new / 1e3, all_new / all_old);
  return same ? 0 : 1;
}
