/// The property suite of moving shapes: the cast and time-of-impact laws (the law table's Moving
/// suite), for every pair of kinds from the registry and both scalars, one GoogleTest test each
/// (suite = law, name = <pair>_<scalar>; the raycast agreement per kind), checked by RapidCheck.
/// A counterexample is saved as a case file (law_tests.hpp).
///
/// Depth: RC_PARAMS as for the main suite; COLLIDE_CAST_DEPTH multiplies RapidCheck's
/// max_success (ctest runs depth 1; `./harness verify` runs 10).
///
/// Motions are aimed: shapes from the placed pairs of generators.hpp, then a velocity that is
/// random, aimed from one shape's inside to the other's (a head-on hit), or grazing: the pair is
/// placed touching exactly, a moved back along a direction tangent to the contact (it touches at
/// one instant or slides along a face) or along the normal (it meets head-on at a known time),
/// sometimes at high speed over a short interval (a bullet through a thin sliver). Four motions in
/// nine are then seen from another frame: the shapes become local shapes placed by transforms
/// (one transform for both, which keeps the aimed relation up to the images' rounding, or each
/// its own for random motions), the velocities turned with them; compounds sometimes carry child
/// transforms (quarter turns that keep the shape exactly, or any transform for random motions).

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "collide/laws/laws.hpp"
#include "generators.hpp"
#include "law_tests.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

namespace collide::props {
namespace {

/// A motion of a against b: a pair and its velocities.
template <Scalar T>
struct Motion {
  Shape<T> a, b;
  laws::CastInput<T> in;
  bool aimed = false;  ///< the pair's relation matters (head-on, grazing)
};

/// v scaled so that it is exact in T (components rounded to T).
template <Scalar T>
Vec2<T> to_t(const Vec2c& v) {
  return Vec2<T>(T(v.x()), T(v.y()));
}

/// Size of a pair (largest extent of either bounding box), at least 2^-30.
template <Scalar T>
double pair_size(const Shape<T>& a, const Shape<T>& b) {
  double m = 0x1p-30;
  for (const Shape<T>* s : {&a, &b}) {
    const Aabb<T> box = bounds(*s);
    m = std::max(m, (widen(box.max()) - widen(box.min())).maxCoeff());
  }
  return m;
}

/// A compound whose children are stored turned back by a quarter turn and placed by that quarter
/// turn: the same world shape, exactly (other shapes as they are).
template <Scalar T>
Shape<T> with_quarter_child_transforms(const Shape<T>& s) {
  const auto* c = std::get_if<Compound<T>>(&s);
  if (c == nullptr || !*rc::gen::arbitrary<bool>()) return s;
  using V = Vec2<T>;
  const std::array<V, 4> quarter = {V(1, 0), V(0, 1), V(-1, 0), V(0, -1)};
  std::vector<typename Compound<T>::Child> kids;
  for (const Primitive<T>& p : c->children()) {
    const int k = *rc::gen::inRange(0, 4);
    kids.push_back(
        {laws::turned(p, 4 - k, false), Transform<T>::make_with_rotation(V(0, 0), quarter[std::size_t(k)]).value()});
  }
  return Compound<T>::make_placed(std::move(kids)).value();
}

/// The motion seen from another frame (see the top of this file); aimed: the relation of the
/// pair matters, so both shapes get one transform and child transforms keep the shapes.
template <Scalar T>
Motion<T> placed_motion(Motion<T> m, bool aimed) {
  const int how = *rc::gen::inRange(0, 3);
  if (how == 0) return m;
  const double s = scale_of_pair(m.a, m.b);
  m.a = aimed ? with_quarter_child_transforms(m.a) : with_child_transforms(m.a, s);
  m.b = aimed ? with_quarter_child_transforms(m.b) : with_child_transforms(m.b, s);
  const Transform<T> x = gen_transform<T>(s);
  m.in.xa = x;
  m.in.xb = aimed || how == 1 ? x : gen_transform<T>(s);
  m.in.va = to_t<T>(x.rotate(widen(m.in.va)));
  m.in.vb = to_t<T>(x.rotate(widen(m.in.vb)));
  return m;
}

/// A motion in world space: random, aimed, or grazing / head-on (see the top of this file).
template <Scalar T>
Motion<T> gen_world_motion(ShapeKind ka, ShapeKind kb) {
  const int style = *rc::gen::weightedElement<int>({{2, 0}, {2, 1}, {4, 2}});
  const T max_t = *rc::gen::elementOf(std::vector<T>{T(0.25), T(1), T(1), T(4)});
  const double speed_scale = std::ldexp(1.0, *rc::gen::weightedElement<int>({{6, 0}, {1, 8}, {1, 20}}));
  if (style == 0) {  // random motion of any placed pair
    auto [a, b] = gen_pair<T>(ka, kb);
    const double s = pair_size(a, b);
    const Vec2<T> va = to_t<T>(Vec2c(grid(-16, 16), grid(-16, 16)) * (s / 8 * speed_scale));
    const Vec2<T> vb =
        *rc::gen::arbitrary<bool>() ? Vec2<T>(0, 0) : to_t<T>(Vec2c(grid(-16, 16), grid(-16, 16)) * (s / 8));
    return {a, b, {va, vb, max_t}, false};
  }
  if (style == 1) {  // aimed: from a's inside toward b's, arriving around t = max_t / 2 .. 2 max_t
    auto [a, b] = gen_pair<T>(ka, kb, Placement::Separated);
    const Vec2c d = inner_point(b) - inner_point(a);
    const double k = double(*rc::gen::inRange(1, 9)) / 4 / double(max_t);
    return {a, b, {to_t<T>(d * k * speed_scale), Vec2<T>(0, 0), max_t}, true};
  }
  // Grazing and head-on through a touching placement: a moved back along v by v * tc.
  auto [a, b] = gen_pair<T>(ka, kb, Placement::Touching);
  const auto c = contact(a, b);
  const Vec2c n = c ? widen(c->normal) : Vec2c(1, 0);
  const Vec2c tangent(-n.y(), n.x());
  const double s = pair_size(a, b);
  const int way = *rc::gen::inRange(0, 4);
  Vec2c v = way == 0   ? n
            : way == 1 ? tangent
            : way == 2 ? Vec2c(tangent + n * std::ldexp(1.0, -*rc::gen::inRange(2, 30)))
                       : Vec2c(tangent - n * 0x1p-20);
  v *= s * speed_scale * (*rc::gen::arbitrary<bool>() ? 1 : -1) * (way == 0 ? 1 : 1);
  if (way == 0 && v.dot(n) < 0) v = -v;  // head-on: a moves toward b
  const Vec2<T> va = to_t<T>(v);
  const double tc = double(max_t) * double(*rc::gen::inRange(1, 9)) / 8;
  const Vec2<T> back = to_t<T>(-widen(va) * tc);
  return {moved(a, back), b, {va, Vec2<T>(0, 0), max_t}, true};
}

/// A motion: in world space one time in three, otherwise through placed_motion() (which keeps
/// world space one time in three too).
template <Scalar T>
Motion<T> gen_motion(ShapeKind ka, ShapeKind kb) {
  const bool world = *rc::gen::inRange(0, 3) == 0;
  const Motion<T> m = gen_world_motion<T>(ka, kb);
  return world ? m : placed_motion(m, m.aimed);
}

/// A motion from a start where the pair overlaps, touches or lies within a nudge, a moving at
/// random (about half of these leave the overlap), seen from another frame two times in three
/// with one transform for both (the relation at the start kept).
template <Scalar T>
Motion<T> gen_overlapping_motion(ShapeKind ka, ShapeKind kb) {
  const Placement how =
      *rc::gen::element(Placement::Overlapping, Placement::Contained, Placement::Touching, Placement::Nudged);
  auto [a, b] = gen_pair<T>(ka, kb, how);
  const double s = pair_size(a, b);
  const T max_t = *rc::gen::elementOf(std::vector<T>{T(0.25), T(1), T(4)});
  const Vec2<T> va = to_t<T>(Vec2c(grid(-16, 16), grid(-16, 16)) * (s / 8));
  const Motion<T> m{a, b, {va, Vec2<T>(0, 0), max_t}, true};
  return *rc::gen::inRange(0, 3) == 0 ? m : placed_motion(m, true);
}

/// A sweep for the time-of-impact law: centre of rotation at an inner point, which stays where
/// it is at time 0; angle 0 at time 0 half the time (the pose at time 0 is then the identity up
/// to rounding), else a turned start, so that a body that does not turn is still turned; turning
/// by up to two turns, its centre moving toward `toward` or at random.
template <Scalar T>
Sweep<T> gen_sweep(const Shape<T>& s, const Vec2c& toward, double size) {
  Sweep<T> sw;
  const Vec2c lc = inner_point(s);
  sw.local_center = to_t<T>(lc);
  sw.c0 = sw.local_center;
  const int move = *rc::gen::inRange(0, 3);
  const Vec2c d = move == 0   ? Vec2c(0, 0)
                  : move == 1 ? Vec2c((toward - lc) * (double(*rc::gen::inRange(1, 9)) / 4))
                              : Vec2c(grid(-8, 8), grid(-8, 8)) * (size / 4);
  sw.c1 = to_t<T>(widen(sw.c0) + d);
  // Twice 0: a pair neither of which turns is cast as a translation.
  const std::vector<double> turns = {0, 0, 0.25, -0.25, 0.5, 1, -2, 1e-6, 0.125};
  const std::vector<double> starts = {0, 0, 0, 0, 0.1, -0.3, 0.25, 0.6};
  sw.a0 = T(*rc::gen::elementOf(starts) * 2 * std::numbers::pi);
  sw.a1 = T(double(sw.a0) + *rc::gen::elementOf(turns) * 2 * std::numbers::pi);
  return sw;
}

long depth() {
  const char* s = std::getenv("COLLIDE_CAST_DEPTH");
  const long d = s != nullptr ? std::atol(s) : 1;
  return d > 0 ? d : 1;
}

/// Runs the property with max_success multiplied by COLLIDE_CAST_DEPTH.
void check(const std::function<void()>& property) {
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess = params.maxSuccess * static_cast<int>(depth());
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  rc::detail::TestMetadata metadata;
  metadata.id = std::string(info->test_suite_name()) + "/" + info->name();
  metadata.description = info->name();
  const auto result = rc::detail::checkTestable(property, metadata, params);
  if (!result.template is<rc::detail::SuccessResult>()) {
    std::ostringstream msg;
    rc::detail::printResultMessage(result, msg);
    ADD_FAILURE() << msg.str();
  }
}

/// A case of a cast law: the shapes, the motion and the verdict.
template <Scalar T>
laws::Case motion_case(laws::Law law, const Motion<T>& m, const laws::Verdict& v, const std::string& test) {
  laws::Case c = laws::make_case<T>(law, m.a, m.b, v, "property " + test + " " + seed_text());
  c.vax = m.in.va.x();
  c.vay = m.in.va.y();
  c.vbx = m.in.vb.x();
  c.vby = m.in.vb.y();
  c.max_t = m.in.max_t;
  if (!m.in.xa.is_identity()) c.transform_a = laws::to_data(m.in.xa);
  if (!m.in.xb.is_identity()) c.transform_b = laws::to_data(m.in.xb);
  return c;
}

template <Scalar T>
std::array<double, 8> sweep_values(const Sweep<T>& s) {
  return {s.local_center.x(), s.local_center.y(), s.c0.x(), s.c0.y(), s.c1.x(), s.c1.y(), s.a0, s.a1};
}

/// The property of a law of the Moving suite for the kinds ka and kb (kb is ka for cast_raycast);
/// empty for a law of another suite.
template <Scalar T>
std::function<void()> property_of(laws::Law law, ShapeKind ka, ShapeKind kb, const std::string& test) {
  using laws::Law;
  switch (law) {
    case Law::Cast:
      return [=] {
        const Motion<T> m = gen_motion<T>(ka, kb);
        const laws::Verdict v = laws::cast_law(m.a, m.b, m.in);
        judge_case(v, [&] { return motion_case(law, m, v, test); });
      };
    case Law::CastLeaving:
      return [=] {
        const Motion<T> m = *rc::gen::arbitrary<bool>() ? gen_overlapping_motion<T>(ka, kb) : gen_motion<T>(ka, kb);
        const laws::Verdict v = laws::cast_leaving(m.a, m.b, m.in);
        judge_case(v, [&] { return motion_case(law, m, v, test); });
      };
    case Law::CastSymmetry:
      return [=] {
        const Motion<T> m = gen_motion<T>(ka, kb);
        const laws::Verdict v = laws::cast_symmetry(m.a, m.b, m.in);
        judge_case(v, [&] { return motion_case(law, m, v, test); });
      };
    case Law::CastTranslation:
      return [=] {
        const Motion<T> m = gen_motion<T>(ka, kb);
        const Vec2<T> d = gen_translation<T>(pair_size(m.a, m.b));
        const laws::Verdict v = laws::cast_translation(m.a, m.b, m.in, d);
        judge_case(v, [&] {
          laws::Case c = motion_case(law, m, v, test);
          c.tx = d.x();
          c.ty = d.y();
          return c;
        });
      };
    case Law::Toi:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, kb);
        const double size = pair_size(a, b);
        const Sweep<T> sa = gen_sweep(a, inner_point(b), size);
        const Sweep<T> sb = *rc::gen::arbitrary<bool>() ? gen_sweep(b, inner_point(a), size) : Sweep<T>{};
        const T max_t = *rc::gen::elementOf(std::vector<T>{T(1), T(1), T(0.5)});
        const laws::Verdict v = laws::toi_law(a, sa, b, sb, max_t, std::span<const double>(laws::kToiSamples));
        judge_case(v, [&] {
          laws::Case c = laws::make_case<T>(law, a, b, v, "property " + test + " " + seed_text());
          c.sweep_a = sweep_values(sa);
          c.sweep_b = sweep_values(sb);
          c.max_t = max_t;
          return c;
        });
      };
    case Law::CastRaycast:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, ka);
        const Vec2c from = inner_point(b), to = inner_point(a);
        const bool aimed = *rc::gen::inRange(0, 4) != 0;
        const Vec2<T> origin = to_t<T>(from);
        const Vec2<T> dir = aimed ? to_t<T>(to - from) : Vec2<T>(T(grid(-8, 8)), T(grid(-8, 8)));
        const T max_t = *rc::gen::elementOf(std::vector<T>{T(0.5), T(1), T(2), T(1e6)});
        const laws::Verdict v = laws::cast_raycast(a, Ray<T>{origin, dir}, max_t);
        judge_case(v, [&] {
          laws::Case c = laws::make_case<T>(law, a, std::nullopt, v, "property " + test + " " + seed_text());
          c.ox = origin.x();
          c.oy = origin.y();
          c.dx = dir.x();
          c.dy = dir.y();
          c.max_t = max_t;
          return c;
        });
      };
    default:
      break;
  }
  return {};
}

/// Every law of the Moving suite, over what it takes (law_tests.hpp); each test runs
/// COLLIDE_CAST_DEPTH times RapidCheck's max_success and saves its counterexample.
void register_all() {
  register_saving_suite(
      laws::LawSuite::Moving,
      []<Scalar T>(laws::Law law, ShapeKind ka, ShapeKind kb, const std::string& test) {
        return property_of<T>(law, ka, kb, test);
      },
      check);
}

}  // namespace
}  // namespace collide::props

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  collide::props::register_all();
  return RUN_ALL_TESTS();
}
