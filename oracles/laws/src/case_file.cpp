// Regression case files: stored values <-> shapes, text format, replay.

#include "collide/laws/case_file.hpp"

#include "collide/laws/hash.hpp"
#include "support.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace collide::laws {

using detail::hex;

// ---------------------------------------------------------------------------------------------
// Text.

namespace {

/// Decimal comment for humans.
void write_shape_comment(std::ostream& out, const std::string& label, const ShapeData& d) {
  out << "# " << label << ": " << name(d.kind);
  if (d.kind == ShapeKind::Compound) {
    out << " of " << d.children.size() << '\n';
    for (const ShapeData& c : d.children) write_shape_comment(out, "  child", c);
    return;
  }
  for (double v : d.values) out << ' ' << detail::num(v);
  if (d.placement) {
    out << " at";
    for (double v : d.placement->values) out << ' ' << detail::num(v);
  }
  out << '\n';
}

std::string one_line(std::string s) {
  for (char& ch : s) {
    if (ch == '\n' || ch == '\r') ch = ' ';
  }
  return s;
}

/// Runs `f`, prefixing a CodecError with the line number.
template <class F>
auto at_line(int line, F&& f) {
  try {
    return f();
  } catch (const CodecError& e) {
    throw CaseError("line " + std::to_string(line) + ": " + e.what());
  }
}

double parse_double(const std::string& tok, int line) {
  return at_line(line, [&] { return parse_value(tok); });
}

/// The next value of a line, or CaseError naming the line's expected form.
double next_value(std::istream& in, int line, const char* form) {
  std::string tok;
  if (!(in >> tok)) throw CaseError("line " + std::to_string(line) + ": expected '" + form + "'");
  return parse_double(tok, line);
}

/// The next word of a line, which must be `word`.
void expect_word(std::istream& in, const char* word, int line, const char* form) {
  std::string tok;
  if (!(in >> tok) || tok != word) throw CaseError("line " + std::to_string(line) + ": expected '" + form + "'");
}

std::string rest_of(std::istringstream& in) {
  std::string rest;
  std::getline(in, rest);
  const auto b = rest.find_first_not_of(' ');
  return b == std::string::npos ? "" : rest.substr(b);
}

}  // namespace

void write_case(std::ostream& out, const Case& c) {
  const Law law = c.law;
  out << "collide-case 1\n";
  out << "law " << name(law) << '\n';
  out << "scalar " << c.scalar << '\n';
  if (info(law).inputs == LawInputs::Values) {
    out << "kind " << name(c.a.kind) << '\n';
  } else if (info(law).inputs != LawInputs::TransformValues) {
    write_shape_comment(out, "a", c.a);
    write_text(out, "shape a", c.a);
  }
  if (c.transform_a) write_text(out, "transform a", *c.transform_a);
  if (c.b) {
    write_shape_comment(out, "b", *c.b);
    write_text(out, "shape b", *c.b);
  }
  if (c.transform_b) write_text(out, "transform b", *c.transform_b);
  if (law == Law::Translation || law == Law::CastTranslation || law == Law::Mass)
    out << "# t = (" << detail::num(c.tx) << ", " << detail::num(c.ty) << ")\ntranslation " << hex(c.tx) << ' '
        << hex(c.ty) << '\n';
  if (law == Law::Rotation) out << "rotation " << c.quarter_turns << " mirror " << (c.mirror ? 1 : 0) << '\n';
  if (law == Law::Raycast || law == Law::RaycastExit || law == Law::PlacedShape || law == Law::CastRaycast)
    out << "# ray (" << detail::num(c.ox) << ", " << detail::num(c.oy) << ") + t (" << detail::num(c.dx) << ", "
        << detail::num(c.dy) << "), t <= " << detail::num(c.max_t) << "\nray " << hex(c.ox) << ' ' << hex(c.oy) << ' '
        << hex(c.dx) << ' ' << hex(c.dy) << " max_t " << hex(c.max_t) << '\n';
  if (law == Law::Contains || law == Law::SignedDistance || law == Law::PlacedShape)
    out << "# point (" << detail::num(c.px) << ", " << detail::num(c.py) << ")\npoint " << hex(c.px) << ' ' << hex(c.py)
        << '\n';
  if (law == Law::Mass) out << "# density " << detail::num(c.density) << "\ndensity " << hex(c.density) << '\n';
  if (info(law).suite == LawSuite::Moving && law != Law::CastRaycast && law != Law::Toi)
    out << "# a moves at (" << detail::num(c.vax) << ", " << detail::num(c.vay) << "), b at (" << detail::num(c.vbx)
        << ", " << detail::num(c.vby) << "), t <= " << detail::num(c.max_t) << "\nmotion " << hex(c.vax) << ' '
        << hex(c.vay) << ' ' << hex(c.vbx) << ' ' << hex(c.vby) << " max_t " << hex(c.max_t) << '\n';
  if (law == Law::Toi) {
    for (const auto& [which, sweep] : {std::pair{"a", &c.sweep_a}, std::pair{"b", &c.sweep_b}}) {
      if (!*sweep) continue;
      out << "sweep " << which;
      for (double v : **sweep) out << ' ' << hex(v);
      out << '\n';
    }
    out << "max_t " << hex(c.max_t) << '\n';
  }
  if (info(law).suite == LawSuite::Chain) {
    const std::array<double, 4> g = c.ghosts.value_or(std::array<double, 4>{});
    out << "# before a (" << detail::num(g[0]) << ", " << detail::num(g[1]) << "), after b (" << detail::num(g[2])
        << ", " << detail::num(g[3]) << ")\nghosts " << hex(g[0]) << ' ' << hex(g[1]) << ' ' << hex(g[2]) << ' '
        << hex(g[3]) << " start " << (c.owns_start ? 1 : 0) << "\n# speculative " << detail::num(c.speculative)
        << "\nspeculative " << hex(c.speculative) << '\n';
  }
  if (info(law).inputs == LawInputs::Values || info(law).inputs == LawInputs::TransformValues) {
    out << "values";
    for (double v : c.values) out << ' ' << hex(v);
    out << '\n';
  }
  out << "expected " << one_line(c.expected) << '\n';
  out << "got " << one_line(c.got) << '\n';
  out << "source " << one_line(c.source) << '\n';
  out << "account " << one_line(c.account) << '\n';
}

Case read_case(std::istream& in) {
  Case c;
  std::string raw;
  int line = 0;
  bool header = false, have_a = false, have_law = false;
  ShapeData* open_compound = nullptr;
  std::size_t children_left = 0;
  while (std::getline(in, raw)) {
    ++line;
    const auto hash = raw.find('#');
    const std::string text = hash == std::string::npos ? raw : raw.substr(0, hash);
    std::istringstream ls(text);
    std::string key;
    if (!(ls >> key)) continue;
    auto where = [&] { return "line " + std::to_string(line) + ": "; };
    if (!header) {
      int version = 0;
      if (key != "collide-case" || !(ls >> version) || version != 1)
        throw CaseError(where() + "expected 'collide-case 1'");
      header = true;
      continue;
    }
    if (children_left > 0 && key != "child") throw CaseError(where() + "expected a child line");
    if (key == "law") {
      std::string law;
      ls >> law;
      const auto l = law_from_name(law);
      if (!l) throw CaseError(where() + "unknown law '" + law + "'");
      c.law = *l;
      have_law = true;
    } else if (key == "scalar") {
      ls >> c.scalar;
      if (c.scalar != "float" && c.scalar != "double") throw CaseError(where() + "scalar must be float or double");
    } else if (key == "shape" || key == "transform") {
      std::string which;
      if (!(ls >> which) || (which != "a" && which != "b")) throw CaseError(where() + "expected '" + key + " a|b ...'");
      if (key == "transform") {
        (which == "a" ? c.transform_a : c.transform_b) = at_line(line, [&] { return read_transform_text(ls); });
        continue;
      }
      std::string kind;
      ls >> kind;
      ShapeData* target = nullptr;
      if (which == "a") {
        target = &c.a;
        have_a = true;
      } else {
        c.b = ShapeData{};
        target = &*c.b;
      }
      *target = at_line(line, [&] { return read_text(ls, parse_kind(kind), &children_left); });
      if (children_left > 0) open_compound = target;
    } else if (key == "kind") {
      std::string kind;
      ls >> kind;
      c.a = ShapeData{at_line(line, [&] { return parse_kind(kind); }), {}, {}, {}};
      have_a = true;
    } else if (key == "child") {
      if (children_left == 0 || open_compound == nullptr) throw CaseError(where() + "child line without a compound");
      std::string kind;
      ls >> kind;
      open_compound->children.push_back(at_line(line, [&] { return read_text(ls, parse_kind(kind)); }));
      --children_left;
    } else if (key == "translation") {
      constexpr const char* form = "translation X Y";
      c.tx = next_value(ls, line, form);
      c.ty = next_value(ls, line, form);
    } else if (key == "rotation") {
      std::string m;
      int mirror = 0;
      if (!(ls >> c.quarter_turns >> m >> mirror) || m != "mirror")
        throw CaseError(where() + "expected 'rotation K mirror 0|1'");
      c.mirror = mirror != 0;
    } else if (key == "ray") {
      constexpr const char* form = "ray ox oy dx dy max_t T";
      for (double* v : {&c.ox, &c.oy, &c.dx, &c.dy}) *v = next_value(ls, line, form);
      expect_word(ls, "max_t", line, form);
      c.max_t = next_value(ls, line, form);
    } else if (key == "point") {
      constexpr const char* form = "point X Y";
      c.px = next_value(ls, line, form);
      c.py = next_value(ls, line, form);
    } else if (key == "density") {
      c.density = next_value(ls, line, "density X");
    } else if (key == "motion") {
      constexpr const char* form = "motion vax vay vbx vby max_t T";
      for (double* v : {&c.vax, &c.vay, &c.vbx, &c.vby}) *v = next_value(ls, line, form);
      expect_word(ls, "max_t", line, form);
      c.max_t = next_value(ls, line, form);
    } else if (key == "sweep") {
      constexpr const char* form = "sweep a|b lx ly c0x c0y c1x c1y a0 a1";
      std::string which;
      if (!(ls >> which) || (which != "a" && which != "b")) throw CaseError(where() + "expected '" + form + "'");
      std::array<double, 8> v{};
      for (double& x : v) x = next_value(ls, line, form);
      (which == "a" ? c.sweep_a : c.sweep_b) = v;
    } else if (key == "ghosts") {
      constexpr const char* form = "ghosts px py qx qy start 0|1";
      std::array<double, 4> g{};
      for (double& x : g) x = next_value(ls, line, form);
      expect_word(ls, "start", line, form);
      int start = 0;
      if (!(ls >> start) || (start != 0 && start != 1)) throw CaseError(where() + "expected '" + form + "'");
      c.ghosts = g;
      c.owns_start = start == 1;
    } else if (key == "speculative") {
      c.speculative = next_value(ls, line, "speculative X");
    } else if (key == "max_t") {
      c.max_t = next_value(ls, line, "max_t T");
    } else if (key == "values") {
      std::string tok;
      while (ls >> tok) c.values.push_back(parse_double(tok, line));
    } else if (key == "expected") {
      c.expected = rest_of(ls);
    } else if (key == "got") {
      c.got = rest_of(ls);
    } else if (key == "source") {
      c.source = rest_of(ls);
    } else if (key == "account") {
      c.account = rest_of(ls);
    } else {
      throw CaseError(where() + "unknown key '" + key + "'");
    }
  }
  if (!header) throw CaseError("empty case file");
  if (children_left > 0) throw CaseError("compound is missing " + std::to_string(children_left) + " children");
  if (!have_law) throw CaseError("no law");
  if (!have_a && info(c.law).inputs != LawInputs::TransformValues) throw CaseError("no shape a");
  return c;
}

void write_case(const std::filesystem::path& path, const Case& c) {
  std::ofstream out(path);
  if (!out) throw CaseError("cannot write " + path.string());
  write_case(out, c);
  if (!out) throw CaseError("error writing " + path.string());
}

Case read_case(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw CaseError("cannot read " + path.string());
  try {
    return read_case(in);
  } catch (const CaseError& e) {
    throw CaseError(path.string() + ": " + e.what());
  }
}

std::string pair_name(const Case& c) {
  if (info(c.law).inputs == LawInputs::TransformValues) return "transform";
  if (!c.b) return std::string(name(c.a.kind));
  return name(make_pair(c.a.kind, c.b->kind));
}

std::string case_stem(const Case& c) {
  // A hash of the values that define the case (not the account or source).
  std::ostringstream key;
  Case bare = c;
  bare.expected.clear();
  bare.got.clear();
  bare.source.clear();
  bare.account.clear();
  write_case(key, bare);
  char buf[16];
  std::snprintf(buf, sizeof buf, "%08x", fnv1a(key.str()));
  return std::string(name(c.law)) + "-" + pair_name(c) + "-" + c.scalar + "-" + buf;
}

std::filesystem::path save_case(const std::filesystem::path& dir, const Case& c) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / (case_stem(c) + ".case");
  write_case(path, c);
  std::filesystem::path svg = path;
  svg.replace_extension(".svg");
  write_svg(svg, c);
  return path;
}

// ---------------------------------------------------------------------------------------------
// Replay.

namespace {

template <Scalar T>
Vec2<T> vec(double x, double y) {
  using codec_detail::narrow;
  return Vec2<T>(narrow<T>(x), narrow<T>(y));
}

template <Scalar T>
Sweep<T> sweep_of(const std::optional<std::array<double, 8>>& v) {
  using codec_detail::narrow;
  if (!v) return Sweep<T>{};
  const std::array<double, 8>& x = *v;
  return Sweep<T>{vec<T>(x[0], x[1]), vec<T>(x[2], x[3]), vec<T>(x[4], x[5]), narrow<T>(x[6]), narrow<T>(x[7])};
}

/// The segment of a chain case: shape a (a capsule of radius 0) between its ghosts, made by
/// Chain's factory when it owns its start (the first segment of an open chain), else by its own.
template <Scalar T>
ChainSegment<T> segment_of(const Case& c) {
  if (!c.ghosts) throw CaseError("law '" + std::string(name(c.law)) + "' needs the line 'ghosts ...'");
  const Shape<T> a = from_data<T>(c.a);
  const Capsule<T>* seg = std::get_if<Capsule<T>>(&a);
  if (seg == nullptr || seg->radius() != T(0)) throw CaseError("a chain case's shape a is a capsule of radius 0");
  const std::array<double, 4>& g = *c.ghosts;
  const Vec2<T> before = vec<T>(g[0], g[1]), after = vec<T>(g[2], g[3]);
  if (!c.owns_start) return ChainSegment<T>::make(before, seg->a(), seg->b(), after).value();
  const std::array<Vec2<T>, 4> points = {before, seg->a(), seg->b(), after};
  return Chain<T>::make(points, false).value().segment(0);
}

template <Scalar T>
Verdict replay_as(const Case& c) {
  const Law law = c.law;
  if (c.transform_a && info(law).suite == LawSuite::Chain) throw CaseError("a chain segment takes no transform");
  const bool placed = (info(law).suite == LawSuite::Placed && law != Law::TransformRejection) ||
                      info(law).suite == LawSuite::Chain || law == Law::Cast || law == Law::CastLeaving ||
                      law == Law::CastSymmetry || law == Law::CastTranslation || law == Law::Mass;
  if (!placed && (c.transform_a || c.transform_b))
    throw CaseError("law '" + std::string(name(law)) + "' takes no transform");
  auto shape_a = [&] { return from_data<T>(c.a); };
  auto shape_b = [&]() -> Shape<T> {
    if (!c.b) throw CaseError("law '" + std::string(name(law)) + "' needs shape b");
    return from_data<T>(*c.b);
  };
  auto placement = [](const std::optional<TransformData>& x) {
    return x ? transform_from_data<T>(*x) : Transform<T>();
  };
  const Transform<T> xa = placement(c.transform_a), xb = placement(c.transform_b);
  auto values = [&] {
    std::vector<T> x;
    for (double v : c.values) x.push_back(static_cast<T>(v));
    return x;
  };
  using codec_detail::narrow;
  const Ray<T> ray{vec<T>(c.ox, c.oy), vec<T>(c.dx, c.dy)};
  const Vec2<T> point = vec<T>(c.px, c.py), move = vec<T>(c.tx, c.ty);
  const CastInput<T> motion{vec<T>(c.vax, c.vay), vec<T>(c.vbx, c.vby), narrow<T>(c.max_t), xa, xb};
  const T speculative = narrow<T>(c.speculative);
  switch (law) {
    case Law::Agreement:
      return agreement(shape_a(), shape_b());
    case Law::Symmetry:
      return symmetry(shape_a(), shape_b());
    case Law::Translation:
      return translation(shape_a(), shape_b(), move);
    case Law::Rotation:
      return rotation(shape_a(), shape_b(), c.quarter_turns, c.mirror);
    case Law::Resolution:
      return resolution(shape_a(), shape_b());
    case Law::Bounds:
      return bounds_law(shape_a());
    case Law::Raycast:
      return raycast_law(shape_a(), ray, narrow<T>(c.max_t));
    case Law::RaycastExit:
      return raycast_exit_law(shape_a(), ray, narrow<T>(c.max_t));
    case Law::Hierarchy:
      return hierarchy(shape_a(), shape_b());
    case Law::Representation:
      return representation(shape_a(), shape_b());
    case Law::Contact:
      return contact_law(shape_a(), shape_b());
    case Law::Distance:
      return distance_law(shape_a(), shape_b());
    case Law::Rejection: {
      const std::vector<T> x = values();
      return rejection<T>(c.a.kind, std::span<const T>(x));
    }
    case Law::Contains:
      return contains_law(shape_a(), point);
    case Law::ContainsShape:
      return contains_shape_law(shape_a(), shape_b());
    case Law::SignedDistance:
      return signed_distance_law(shape_a(), point);
    case Law::ClosestPoints:
      return closest_points_law(shape_a(), shape_b());
    case Law::Touching:
      return touching(shape_a(), shape_b());
    case Law::Scene:
      return scene(shape_a());
    case Law::Separation:
      return manifold_separation(shape_a(), shape_b());
    case Law::FeatureIds:
      return manifold_ids(shape_a(), shape_b());
    case Law::Resting:
      return manifold_resting(shape_a(), shape_b());
    case Law::Speculative:
      return manifold_speculative(shape_a(), shape_b());
    case Law::Mass:
      if (c.transform_b) throw CaseError("law 'mass' places its shape by transform a only");
      return mass_law(shape_a(), narrow<T>(c.density), move, xa);
    case Law::PlacedAgreement:
      return placed_agreement(shape_a(), xa, shape_b(), xb);
    case Law::PlacedOutputs:
      return placed_outputs(shape_a(), xa, shape_b(), xb);
    case Law::PlacedResolution:
      return placed_resolution(shape_a(), xa, shape_b(), xb);
    case Law::PlacedShape:
      return placed_shape(shape_a(), xa, point, ray, narrow<T>(c.max_t));
    case Law::PlacedCovariance:
      if (c.transform_b) throw CaseError("law 'placed_covariance' moves both shapes by transform a only");
      return placed_covariance(shape_a(), shape_b(), xa);
    case Law::PlacedImage:
      return placed_image(shape_a(), xa, shape_b());
    case Law::TransformRejection: {
      const std::vector<T> x = values();
      return transform_rejection<T>(std::span<const T>(x));
    }
    case Law::PlacedSeparation:
      return placed_separation(shape_a(), xa, shape_b(), xb);
    case Law::PlacedFeatureIds:
      return placed_feature_ids(shape_a(), xa, shape_b(), xb);
    case Law::PlacedSpeculative:
      return placed_speculative(shape_a(), xa, shape_b(), xb);
    case Law::Cast:
      return cast_law(shape_a(), shape_b(), motion);
    case Law::CastLeaving:
      return cast_leaving(shape_a(), shape_b(), motion);
    case Law::CastSymmetry:
      return cast_symmetry(shape_a(), shape_b(), motion);
    case Law::CastTranslation:
      return cast_translation(shape_a(), shape_b(), motion, move);
    case Law::CastRaycast:
      return cast_raycast(shape_a(), ray, narrow<T>(c.max_t));
    case Law::Toi:
      return toi_law(shape_a(), sweep_of<T>(c.sweep_a), shape_b(), sweep_of<T>(c.sweep_b), narrow<T>(c.max_t),
                     std::span<const double>(kToiSamples));
    case Law::ChainAdmissible:
      return chain_admissible(segment_of<T>(c), shape_b(), xb, speculative);
    case Law::ChainOneSided:
      return chain_one_sided(segment_of<T>(c), shape_b(), xb, speculative);
    case Law::ChainSurfaces:
      return chain_surfaces(segment_of<T>(c), shape_b(), xb, speculative);
    case Law::ChainPresent:
      return chain_present(segment_of<T>(c), shape_b(), xb, speculative);
    case Law::ChainFaceComplete:
      return chain_face_complete(segment_of<T>(c), shape_b(), xb, speculative);
    case Law::ChainFaceIds:
      return chain_face_ids(segment_of<T>(c), shape_b(), xb, speculative);
  }
  throw CaseError("unknown law");
}

}  // namespace

Verdict replay(const Case& c) {
  try {
    return c.scalar == "float" ? replay_as<float>(c) : replay_as<double>(c);
  } catch (const std::exception& e) {
    Verdict v;
    v.ok = false;
    v.expected = "a replayable case";
    v.got = e.what();
    v.account = std::string("cannot replay: ") + e.what();
    return v;
  }
}

template <Scalar T>
Case make_case(Law law, const Shape<T>& a, const std::optional<Shape<T>>& b, const Verdict& v, std::string source) {
  Case c;
  c.law = law;
  c.scalar = std::is_same_v<T, float> ? "float" : "double";
  c.a = to_data(a);
  if (b) c.b = to_data(*b);
  c.expected = v.expected.empty() ? "the law holds" : v.expected;
  c.got = v.got.empty() ? (v.ok ? "the law held" : "the law broke") : v.got;
  c.source = std::move(source);
  c.account = v.account;
  return c;
}

template <Scalar T>
Case make_chain_case(Law law, const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative,
                     const Verdict& v, std::string source) {
  Case c = make_case<T>(law, Shape<T>(s.as_capsule()), b, v, std::move(source));
  if (!xb.is_identity()) c.transform_b = to_data(xb);
  c.ghosts = std::array<double, 4>{double(s.before().x()), double(s.before().y()), double(s.after().x()),
                                   double(s.after().y())};
  c.owns_start = s.owns_start_corner();
  c.speculative = double(speculative);
  return c;
}

template Case make_case<float>(Law, const Shape<float>&, const std::optional<Shape<float>>&, const Verdict&,
                               std::string);
template Case make_case<double>(Law, const Shape<double>&, const std::optional<Shape<double>>&, const Verdict&,
                                std::string);

template Case make_chain_case<float>(Law, const ChainSegment<float>&, const Shape<float>&, const Transform<float>&,
                                     float, const Verdict&, std::string);
template Case make_chain_case<double>(Law, const ChainSegment<double>&, const Shape<double>&, const Transform<double>&,
                                      double, const Verdict&, std::string);

}  // namespace collide::laws
