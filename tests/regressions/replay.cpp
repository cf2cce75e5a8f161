/// Replays regression cases through the laws.
///
///   collide_replay_cases DIR|FILE...   replay every *.case (directories are searched, sorted);
///                                      exit 1 if any law fails or any file is malformed
///   collide_replay_cases --self-test   round-trips shapes and cases through the text format
///
/// A case that still fails prints its law, pair, scalar, expected vs got and the account.

#include "collide/laws/case_file.hpp"
#include "collide/laws/laws.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;
using namespace collide;

namespace {

int replay_all(const std::vector<std::string>& args) {
  std::vector<fs::path> files;
  for (const std::string& a : args) {
    if (fs::is_directory(a)) {
      for (const auto& e : fs::directory_iterator(a)) {
        if (e.path().extension() == ".case") files.push_back(e.path());
      }
    } else {
      files.emplace_back(a);
    }
  }
  std::sort(files.begin(), files.end());
  int failed = 0;
  for (const fs::path& f : files) {
    try {
      const laws::Case c = laws::read_case(f);
      const laws::Verdict v = laws::replay(c);
      std::cout << (v.ok ? "PASS " : "FAIL ") << f.filename().string() << "  [" << laws::name(c.law) << " "
                << laws::pair_name(c) << " " << c.scalar << "]";
      if (v.disagreement) std::cout << " (disagreement within the band)";
      std::cout << '\n';
      if (!v.ok) {
        ++failed;
        std::cout << "     expected: " << v.expected << "\n     got:      " << v.got << "\n     account:  " << v.account
                  << "\n     found by: " << c.source << '\n';
      }
    } catch (const std::exception& e) {
      ++failed;
      std::cout << "FAIL " << f.string() << ": " << e.what() << '\n';
    }
  }
  std::cout << files.size() << " cases replayed, " << failed << " failing\n";
  return failed == 0 ? 0 : 1;
}

int check(bool cond, const std::string& what) {
  if (!cond) std::cout << "self-test FAILED: " << what << '\n';
  return cond ? 0 : 1;
}

template <Scalar T>
int round_trip_shapes() {
  using V = Vec2<T>;
  int bad = 0;
  const std::vector<Shape<T>> shapes = {
      Circle<T>(V(T(0.1), T(-3)), T(1) / 3),
      Aabb<T>(V(T(-1), T(-2)), V(T(0.7), T(5))),
      Obb<T>::make_with_axis(V(T(1e6), T(0.3)), V(T(2), T(0.5)), V(T(3), T(4))).value(),
      Obb<T>(V(T(0), T(0)), V(T(1), T(1)), T(0.3)),
      Capsule<T>(V(T(0), T(0)), V(T(1), T(1) / 7), T(0.25)),
      ConvexPolygon<T>({V(T(0), T(0)), V(T(2), T(0.1)), V(T(1), T(3))}),
      Compound<T>({Circle<T>(V(T(5), T(5)), T(1)), Aabb<T>(V(T(0), T(0)), V(T(1), T(1)))}),
      // Children placed by child transforms: a quarter turn, a rounded rotation, the identity.
      Compound<T>::make_placed(
          {{Aabb<T>(V(T(0), T(0)), V(T(2), T(1))),
            Transform<T>::make_with_rotation(V(T(3), T(-1)), V(T(0), T(1))).value()},
           {Capsule<T>(V(T(0), T(0)), V(T(1), T(0)), T(0.5)), Transform<T>::make(V(T(0.1), T(7)), T(0.3)).value()},
           {Circle<T>(V(T(5), T(5)), T(1)), Transform<T>()}})
          .value(),
  };
  for (const Shape<T>& s : shapes) {
    const laws::ShapeData d = laws::to_data(s);
    const Shape<T> back = laws::from_data<T>(d);
    bad += check(laws::to_data(back).values == d.values, "shape values survive from_data(to_data(s))");
    bool placements = laws::to_data(back).children.size() == d.children.size();
    for (std::size_t i = 0; placements && i < d.children.size(); ++i)
      placements = laws::to_data(back).children[i].placement == d.children[i].placement;
    bad += check(placements, "child transforms survive from_data(to_data(s))");
    laws::Case c = laws::make_case<T>(laws::Law::Agreement, s, s, laws::agreement(s, s), "self-test");
    std::stringstream text;
    laws::write_case(text, c);
    const laws::Case r = laws::read_case(text);
    std::stringstream again;
    laws::write_case(again, r);
    bad += check(text.str() == again.str(), "case text survives read_case(write_case(c))");
    bad += check(laws::replay(r).ok, "a shape overlaps itself (agreement replays ok)");
    std::stringstream svg;
    laws::write_svg(svg, r);
    bad += check(svg.str().find("<svg") == 0 && svg.str().find("</svg>") != std::string::npos, "svg is written");
  }
  return bad;
}

/// The self-test's case of a chain law: a floor segment (front up) that owns its start, and a
/// circle sunk 0.5 into it by its transform.
template <Scalar T>
laws::Case chain_case(laws::Law law, const laws::Verdict& held) {
  using V = Vec2<T>;
  const std::array<V, 4> floor = {V(8, 0), V(4, 0), V(-4, 0), V(-8, 0)};
  return laws::make_chain_case<T>(law, Chain<T>::make(floor, false).value().segment(0),
                                  Shape<T>(Circle<T>(V(0, T(1.5)), T(1))),
                                  Transform<T>::make_translation(V(T(0.5), T(-1))).value(), T(0.25), held, "self-test");
}

/// A case for every law of the Placed, Moving and Chain suites (a circle against a triangle to its
/// right, with transforms, a motion, a ray, a point, sweeps or transform values as the law takes; a
/// circle sunk into a chain segment):
/// its text survives read_case(write_case(c)), it replays as holding and it draws.
template <Scalar T>
int round_trip_other_suites() {
  using V = Vec2<T>;
  using laws::Law;
  int bad = 0;
  const Shape<T> a = Circle<T>(V(0, 0), T(1)), b = ConvexPolygon<T>({V(3, 0), V(5, 0), V(4, 2)});
  const laws::TransformData xa = laws::to_data(Transform<T>::make_with_rotation(V(1, 2), V(0, 1)).value());
  const laws::TransformData xb = laws::to_data(Transform<T>::make_translation(V(T(0.5), T(-1))).value());
  laws::Verdict held;
  held.ok = true;
  for (const laws::LawInfo& row : laws::kLaws) {
    if (row.suite == laws::LawSuite::Static) continue;
    const bool pair = row.inputs == laws::LawInputs::Pair;
    laws::Case c =
        row.suite == laws::LawSuite::Chain
            ? chain_case<T>(row.law, held)
            : laws::make_case<T>(row.law, a, pair ? std::optional<Shape<T>>(b) : std::nullopt, held, "self-test");
    if (row.suite == laws::LawSuite::Placed && row.inputs != laws::LawInputs::TransformValues) c.transform_a = xa;
    if (row.law == Law::PlacedAgreement || row.law == Law::PlacedOutputs || row.law == Law::PlacedResolution ||
        row.law == Law::PlacedSeparation || row.law == Law::PlacedFeatureIds || row.law == Law::PlacedSpeculative)
      c.transform_b = xb;
    if (row.law == Law::Cast || row.law == Law::CastLeaving || row.law == Law::CastSymmetry) c.transform_b = xb;
    c.px = 0.5;
    c.py = 0;
    c.ox = -3;
    c.oy = 0.25;
    c.dx = 1;
    c.dy = 0;
    c.max_t = row.law == Law::Toi ? 1 : 4;
    c.vax = 1;
    c.tx = 0.5;
    c.ty = -0.25;
    c.sweep_a = std::array<double, 8>{0, 0, 0, 0, 2, 0, 0, 0.5};
    c.sweep_b = std::array<double, 8>{0, 0, 0, 0, 0, 0, 0, 0};
    if (row.inputs == laws::LawInputs::TransformValues) c.values = {1, 2, 0.5, 0.6, 0.8};
    std::stringstream text;
    laws::write_case(text, c);
    const laws::Case r = laws::read_case(text);
    std::stringstream again;
    laws::write_case(again, r);
    const std::string law(row.name);
    bad += check(text.str() == again.str(), "a " + law + " case survives read_case(write_case(c))");
    const laws::Verdict v = laws::replay(r);
    bad += check(v.ok, "a " + law + " case replays as holding (" + v.account + ")");
    std::stringstream svg;
    laws::write_svg(svg, r);
    bad += check(svg.str().find("</svg>") != std::string::npos, "a " + law + " case draws");
  }
  return bad;
}

int self_test() {
  int bad = round_trip_shapes<float>() + round_trip_shapes<double>();
  bad += round_trip_other_suites<float>() + round_trip_other_suites<double>();
  // Malformed input is rejected with the line number.
  std::stringstream broken("collide-case 1\nlaw agreement\nscalar double\nshape a circle 0x1p+0 nope 0x1p+0\n");
  try {
    (void)laws::read_case(broken);
    bad += check(false, "a malformed number is rejected");
  } catch (const laws::CaseError& e) {
    bad += check(std::string(e.what()).find("line 4") != std::string::npos, "the error names line 4");
  }
  // A child's placement: only on a child line, four values after "at".
  for (const char* bad_line : {"shape a circle 0x0p+0 0x0p+0 0x1p+0 at 0x0p+0 0x0p+0 0x1p+0 0x0p+0\n",
                               "shape a compound 1\nchild circle 0x0p+0 0x0p+0 0x1p+0 at 0x0p+0 0x0p+0 0x1p+0\n"}) {
    std::stringstream placed(std::string("collide-case 1\nlaw bounds\nscalar double\n") + bad_line);
    try {
      (void)laws::read_case(placed);
      bad += check(false, std::string("a misplaced or short 'at' is rejected: ") + bad_line);
    } catch (const laws::CaseError&) {
    }
  }
  // A float case whose value is not a float is rejected on replay, not silently rounded.
  std::stringstream inexact(
      "collide-case 1\nlaw bounds\nscalar float\nshape a circle 0x1.0000000000001p+0 0x0p+0 0x1p+0\n");
  bad += check(!laws::replay(laws::read_case(inexact)).ok, "a non-float value in a float case fails replay");
  // Every kind's codec sample rebuilds through its factory in both scalars.
  for (const ShapeKind k : kKinds) {
    const laws::KindCodec codec = laws::codec_of(k);
    laws::ShapeData d{k, std::vector<double>(codec.sample.begin(), codec.sample.end()), {}, {}};
    if (codec.layout == laws::Layout::Children) d.children.push_back({kKinds[0], {0, 0, 1}, {}, {}});
    bool ok = true;
    try {
      ok = laws::to_data(laws::from_data<float>(d)).values == d.values &&
           laws::to_data(laws::from_data<double>(d)).values == d.values;
    } catch (const laws::CodecError&) {
      ok = false;
    }
    bad += check(ok, "the codec sample of " + std::string(name(k)) + " rebuilds bit for bit");
  }
  // A transform line survives the text form; a law without transforms refuses it by name; a
  // rotation that is not unit is refused by the transform codec.
  std::stringstream placed(
      "collide-case 1\nlaw agreement\nscalar double\nshape a circle 0x0p+0 0x0p+0 0x1p+0\n"
      "transform a 0x1p+0 0x0p+0 0x0p+0 0x1p+0\nshape b circle 0x1p+0 0x0p+0 0x1p+0\n");
  const laws::Case pc = laws::read_case(placed);
  std::stringstream placed_again;
  laws::write_case(placed_again, pc);
  bad +=
      check(placed_again.str().find("transform a 0x1p+0 0x0p+0 0x0p+0 0x1p+0") != std::string::npos && !pc.transform_b,
            "a transform line survives read_case and write_case");
  bad += check(laws::replay(pc).got.find("takes no transform") != std::string::npos,
               "a law without transforms refuses a case with one, by name");
  bool refused = false;
  try {
    (void)laws::transform_from_data<double>(laws::TransformData{{0, 0, 2, 0}});
  } catch (const laws::CodecError&) {
    refused = true;
  }
  bad += check(refused && laws::transform_from_data<float>(laws::TransformData{{1, 2, 0, -1}}) ==
                              Transform<float>::make_with_rotation({1, 2}, {0, -1}).value(),
               "the transform codec keeps a unit rotation and refuses another");
  std::cout << (bad == 0 ? "self-test passed\n" : "self-test failed\n");
  return bad == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Replays regression case files through the laws"};
  std::vector<std::string> paths;
  bool self = false;
  app.add_option("paths", paths, "case files, or folders of them")->check(CLI::ExistingPath);
  app.add_flag("--self-test", self, "check the case format itself (round trips, codecs, errors)");
  CLI11_PARSE(app, argc, argv);
  if (self) return self_test();
  if (paths.empty()) {
    std::cerr << app.help();
    return 2;
  }
  return replay_all(paths);
}
