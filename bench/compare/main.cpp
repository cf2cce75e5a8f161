// The driver of bench/compare/compare_headers.py: both sides' passes over each kind pair,
// alternately, the best of `reps` each; prints new / old per kind pair and over all of them.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

extern "C" std::size_t group_count_old(std::size_t bodies);
extern "C" std::size_t group_count_new(std::size_t bodies);
extern "C" const char* group_name_old(std::size_t bodies, std::size_t g, std::size_t* pairs);
extern "C" const char* group_name_new(std::size_t bodies, std::size_t g, std::size_t* pairs);
extern "C" double time_group_old(std::size_t bodies, std::size_t g, long* points);
extern "C" double time_group_new(std::size_t bodies, std::size_t g, long* points);

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s BODIES REPS\n", argv[0]);
    return 2;
  }
  const std::size_t bodies = std::strtoul(argv[1], nullptr, 10);
  const long reps = std::strtol(argv[2], nullptr, 10);
  const std::size_t groups = group_count_new(bodies);
  if (groups != group_count_old(bodies) || reps < 1) {
    std::fprintf(stderr, "the two sides replay different pairs\n");
    return 1;
  }
  double all_old = 0, all_new = 0;
  bool same = true;
  for (std::size_t g = 0; g < groups; ++g) {
    std::size_t pairs_old = 0, pairs_new = 0;
    const char* name = group_name_new(bodies, g, &pairs_new);
    if (std::strcmp(name, group_name_old(bodies, g, &pairs_old)) != 0 || pairs_old != pairs_new) same = false;
    double best_old = 1e300, best_new = 1e300;
    long points_old = 0, points_new = 0;
    for (long r = 0; r < reps; ++r) {
      best_old = std::min(best_old, time_group_old(bodies, g, &points_old));
      best_new = std::min(best_new, time_group_new(bodies, g, &points_new));
    }
    all_old += best_old;
    all_new += best_new;
    std::printf("%-18s %6zu pairs  old %7.1f  new %7.1f ns/pair  new/old %.3f%s\n", name, pairs_new,
                best_old / double(pairs_old), best_new / double(pairs_new), best_new / best_old,
                points_old == points_new ? "" : "  (points differ)");
  }
  std::printf("%-18s %6s        old %7.1f  new %7.1f us       new/old %.3f\n", "all", "", all_old / 1e3, all_new / 1e3,
              all_new / all_old);
  return same ? 0 : 1;
}
