// Broadphase scale and bad load, each case in its own child process so that its peak memory
// (ru_maxrss from wait4) is its own:
// - 1,000,000 boxes (sides 0.5 to 1.5, about 2 overlaps each) added one by one, then every pair
//   visited with for_each_pair; the three structures must count the same pairs;
// - 10,000 boxes that all overlap each other (49,995,000 pairs) visited with for_each_pair, which
//   builds no list: memory stays that of the structure;
// - a World of 1,000,000 bodies, each a circle in its own frame placed by a transform at the
//   centre of one of the spread boxes: the bodies' adding, the first step (every contact found,
//   against its own tree's pair walk), and 100,000 point queries.
// Usage: collide_broadphase_scale [N (default 1000000)] [M (default 10000)]. Exit status 1 when a
// count is wrong or a case fails.

#include "collide/broadphase.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace bp = collide::broadphase;
using V = collide::Vec2<float>;
using Clock = std::chrono::steady_clock;

/// n boxes with lower corners uniform in [0, extent)^2 and sides uniform in [lo, hi).
std::vector<collide::Aabb<float>> random_boxes(std::size_t n, unsigned seed, float extent, float lo, float hi) {
  std::mt19937 rng{seed};
  std::uniform_real_distribution<float> pos(0, extent), size(lo, hi);
  std::vector<collide::Aabb<float>> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const V corner(pos(rng), pos(rng));
    out.emplace_back(corner, corner + V(size(rng), size(rng)));
  }
  return out;
}

/// About 2 overlaps per box.
std::vector<collide::Aabb<float>> spread_boxes(std::size_t n) {
  return random_boxes(n, static_cast<unsigned>(n), std::sqrt(2.0f * float(n)), 0.5f, 1.5f);
}

/// Every box contains the square [0.5, 1]^2, so every two overlap.
std::vector<collide::Aabb<float>> piled_boxes(std::size_t n) {
  return random_boxes(n, 7, 0.5f, 1.0f, 1.5f);
}

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

/// Builds the structure, visits every pair; writes "build_ms pairs_ms pairs" to the pipe.
template <class B>
void run_case(B s, const std::vector<collide::Aabb<float>>& boxes, int fd) {
  const auto t0 = Clock::now();
  for (std::size_t i = 0; i < boxes.size(); ++i) s.add(boxes[i], i);
  const double build = ms_since(t0);
  const auto t1 = Clock::now();
  std::size_t pairs = 0;
  s.for_each_pair([&](bp::ProxyId, bp::ProxyId) { ++pairs; });
  const double walk = ms_since(t1);
  const std::string line = std::to_string(build) + " " + std::to_string(walk) + " " + std::to_string(pairs);
  if (write(fd, line.data(), line.size()) < 0) std::_Exit(3);
}

/// A World of n circles placed at the centres of `boxes`: writes "add_ms step_ms walk_ms
/// contacts query_us hits" to the pipe.
void run_world(const std::vector<collide::Aabb<float>>& boxes, int fd) {
  bp::World<float> world;
  const auto t0 = Clock::now();
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const V size = boxes[i].max() - boxes[i].min();
    const collide::Circle<float> local(V(0, 0), 0.5f * std::min(size.x(), size.y()));
    world.add(local, collide::Transform<float>::make(0.5f * (boxes[i].min() + boxes[i].max()), 0.0f).value(), i);
  }
  const double add = ms_since(t0);
  const auto t1 = Clock::now();
  world.step();
  const double step = ms_since(t1);
  const auto t2 = Clock::now();
  std::size_t pairs = 0;
  world.broadphase().for_each_pair([&](bp::ProxyId, bp::ProxyId) { ++pairs; });
  const double walk = ms_since(t2);
  std::mt19937 rng{99};
  const float extent = std::sqrt(2.0f * float(boxes.size()));
  std::uniform_real_distribution<float> pos(0, extent);
  constexpr int kQueries = 100000;
  std::vector<V> points;
  for (int q = 0; q < kQueries; ++q) points.emplace_back(pos(rng), pos(rng));
  std::size_t hits = 0;
  const auto t3 = Clock::now();
  for (const V& p : points) world.query_point(p, [&](bp::ProxyId) { ++hits; });
  const double query_us = 1e3 * ms_since(t3) / kQueries;
  const std::string line = std::to_string(add) + " " + std::to_string(step) + " " + std::to_string(walk) + " " +
                           std::to_string(world.contact_count()) + " " + std::to_string(query_us) + " " +
                           std::to_string(hits) + " " + std::to_string(pairs);
  if (write(fd, line.data(), line.size()) < 0) std::_Exit(3);
}

struct Result {
  bool ok = false;
  double build_ms = 0, pairs_ms = 0, peak_mib = 0;
  std::size_t pairs = 0;
};

/// Runs body(fd) in a child process; returns what it wrote and the child's peak memory in MiB
/// (empty text when it failed).
template <class F>
std::pair<std::string, double> child_output(F&& body) {
  int fds[2];
  if (pipe(fds) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    body(fds[1]);
    close(fds[1]);
    std::_Exit(0);
  }
  close(fds[1]);
  char buf[256] = {};
  const ssize_t got = read(fds[0], buf, sizeof buf - 1);
  close(fds[0]);
  int status = 0;
  rusage use{};
  wait4(pid, &status, 0, &use);
  const bool ok = got > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return {ok ? std::string(buf) : std::string(), double(use.ru_maxrss) / 1024.0};  // KiB on Linux
}

template <class F>
Result in_child(F&& body) {
  const auto [text, peak] = child_output(std::forward<F>(body));
  Result r;
  r.ok = std::sscanf(text.c_str(), "%lf %lf %zu", &r.build_ms, &r.pairs_ms, &r.pairs) == 3;
  r.peak_mib = peak;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
  const std::size_t m = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 10000;
  bool ok = true;
  std::printf("%-28s %10s %10s %12s %10s\n", "case", "build ms", "pairs ms", "pairs", "peak MiB");
  const auto report = [&](const std::string& name, const Result& r, std::size_t want) {
    const bool good = r.ok && (want == 0 || r.pairs == want);
    ok = ok && good;
    std::printf("%-28s %10.1f %10.1f %12zu %10.1f  %s\n", name.c_str(), r.build_ms, r.pairs_ms, r.pairs, r.peak_mib,
                good ? "OK" : "FAILED");
    return r.pairs;
  };
  {
    const auto boxes = spread_boxes(n);
    const std::string tag = "/" + std::to_string(n);
    const std::size_t want =
        report("spread/tree" + tag, in_child([&](int fd) { run_case(bp::DynamicTree<float>(0.1f), boxes, fd); }), 0);
    report("spread/sweep" + tag, in_child([&](int fd) { run_case(bp::SweepAndPrune<float>(), boxes, fd); }), want);
    report("spread/grid" + tag, in_child([&](int fd) { run_case(bp::UniformGrid<float>(2.0f), boxes, fd); }), want);
  }
  {
    const auto boxes = piled_boxes(m);
    const std::size_t want = m * (m - 1) / 2;
    const std::string tag = "/" + std::to_string(m);
    report("all-overlapping/tree" + tag, in_child([&](int fd) { run_case(bp::DynamicTree<float>(0.1f), boxes, fd); }),
           want);
    report("all-overlapping/sweep" + tag, in_child([&](int fd) { run_case(bp::SweepAndPrune<float>(), boxes, fd); }),
           want);
    report("all-overlapping/grid" + tag, in_child([&](int fd) { run_case(bp::UniformGrid<float>(2.0f), boxes, fd); }),
           want);
  }
  {
    const auto boxes = spread_boxes(n);
    const auto [text, peak] = child_output([&](int fd) { run_world(boxes, fd); });
    double add = 0, step = 0, walk = 0, query_us = 0;
    std::size_t contacts = 0, hits = 0, pairs = 0;
    const bool good = std::sscanf(text.c_str(), "%lf %lf %lf %zu %lf %zu %zu", &add, &step, &walk, &contacts, &query_us,
                                  &hits, &pairs) == 7 &&
                      contacts <= pairs && contacts > 0;
    ok = ok && good;
    std::printf(
        "world/%zu: add %.1f ms, first step %.1f ms (%.2fx its tree's pair walk, %.1f ms, %zu pairs), %zu contacts; "
        "point query %.2f us (%zu hits); peak %.1f MiB  %s\n",
        n, add, step, walk > 0 ? step / walk : 0.0, walk, pairs, contacts, query_us, hits, peak,
        good ? "OK" : "FAILED");
  }
  return ok ? 0 : 1;
}
