// Judges a tiny circle-only "library" (tiny_circles below, standing for a game's own code) with
// an installed collide's judge: an in-process adapter, then a fixed number of cases.
//
//   collide_judge_consumer OUT_DIR    writes OUT_DIR/tiny-circles.json and .md
#include <collide/judge/judge.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "../app/check.hpp"

namespace tiny_circles {

struct Circle {
  double x, y, r;
};

// Closed circles: touching overlaps (up to the rounding of the squares).
inline bool overlap(const Circle& a, const Circle& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, r = a.r + b.r;
  return dx * dx + dy * dy <= r * r;
}

}  // namespace tiny_circles

namespace {

using namespace collide::judge;

class TinyCirclesAdapter {
 public:
  Info info() const {
    Info i;
    i.library = "tiny-circles";
    i.version = "1";
    i.kinds = {collide::ShapeKind::Circle};
    i.queries = {Query::Overlap};
    i.contract.scalar = "float64";
    i.contract.touching = Touching::Either;
    i.contract.tol_rel = 0x1p-40;
    i.contract.source = "tiny_circles::overlap: squared distance <= squared sum of radii, in double";
    i.mapping = "circle -> Circle{x, y, r}, values as given";
    return i;
  }
  Answer answer(const Input& in) const {
    const auto circle = [](const ShapeData& d) { return tiny_circles::Circle{d.values[0], d.values[1], d.values[2]}; };
    Answer out;
    out.overlap = tiny_circles::overlap(circle(in.a), circle(in.b));
    out.stored_a = in.a;
    out.stored_b = in.b;
    return out;
  }
  std::string reproducer(const Input&, Query, const std::string&) const { return ""; }
  std::string link_flags() const { return ""; }
};

static_assert(InProcessAdapter<TinyCirclesAdapter>);

}  // namespace

int main(int argc, char** argv) {
  using consumer::check;
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 2;
  }
  InProcess<TinyCirclesAdapter> adapter;
  RunOptions o;
  o.max_cases = 2000;
  o.seconds = 120;  // a bound only: the cases end the run
  o.seed = 1;
  o.out_dir = argv[1];
  o.shrink = false;
  o.reproducers = false;
  const RunReport r = run(adapter, o);
  std::printf("tiny-circles: %llu cases: agree %llu, convention %llu, wrong %llu, crash %llu, unjudged %llu\n",
              static_cast<unsigned long long>(r.cases), static_cast<unsigned long long>(r.counts[0]),
              static_cast<unsigned long long>(r.counts[1]), static_cast<unsigned long long>(r.counts[2]),
              static_cast<unsigned long long>(r.counts[3]), static_cast<unsigned long long>(r.counts[4]));
  check(r.cases >= o.max_cases && r.cases < o.max_cases + o.batch, "the run stops after the fixed number of cases");
  check(r.counts[0] > r.cases / 2, "most answers agree with the exact oracle");
  check(r.counts[3] == 0, "no crash");
  check(std::filesystem::exists(o.out_dir / "tiny-circles.json"), "the report tiny-circles.json is written");
  return consumer::failures == 0 ? 0 : 1;
}
