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
  } else {
    write_shape_comment(out, "a", c.a);
    write_text(out, "shape a", c.a);
  }
  if (c.transform_a) write_text(out, "transform a", *c.transform_a);
  if (c.b) {
    write_shape_comment(out, "b", *c.b);
    write_text(out, "shape b", *c.b);
  }
  if (c.transform_b) write_text(out, "transform b", *c.transform_b);
  if (law == Law::Translation)
    out << "# t = (" << detail::num(c.tx) << ", " << detail::num(c.ty) << ")\ntranslation " << hex(c.tx) << ' '
        << hex(c.ty) << '\n';
  if (law == Law::Rotation) out << "rotation " << c.quarter_turns << " mirror " << (c.mirror ? 1 : 0) << '\n';
  if (law == Law::Raycast)
    out << "# ray (" << detail::num(c.ox) << ", " << detail::num(c.oy) << ") + t (" << detail::num(c.dx) << ", "
        << detail::num(c.dy) << "), t <= " << detail::num(c.max_t) << "\nray " << hex(c.ox) << ' ' << hex(c.oy)
        << ' ' << hex(c.dx) << ' ' << hex(c.dy) << " max_t " << hex(c.max_t) << '\n';
  if (law == Law::Contains)
    out << "# point (" << detail::num(c.ox) << ", " << detail::num(c.oy) << ")\npoint " << hex(c.ox) << ' ' << hex(c.oy)
        << '\n';
  if (info(law).inputs == LawInputs::Values) {
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
      if (key != "collide-case" || !(ls >> version) || version != 1) throw CaseError(where() + "expected 'collide-case 1'");
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
      std::string x, y;
      ls >> x >> y;
      c.tx = parse_double(x, line);
      c.ty = parse_double(y, line);
    } else if (key == "rotation") {
      std::string m;
      int mirror = 0;
      if (!(ls >> c.quarter_turns >> m >> mirror) || m != "mirror") throw CaseError(where() + "expected 'rotation K mirror 0|1'");
      c.mirror = mirror != 0;
    } else if (key == "ray") {
      std::string t[4], kw, mt;
      if (!(ls >> t[0] >> t[1] >> t[2] >> t[3] >> kw >> mt) || kw != "max_t") throw CaseError(where() + "expected 'ray ox oy dx dy max_t T'");
      c.ox = parse_double(t[0], line);
      c.oy = parse_double(t[1], line);
      c.dx = parse_double(t[2], line);
      c.dy = parse_double(t[3], line);
      c.max_t = parse_double(mt, line);
    } else if (key == "point") {
      std::string x, y;
      if (!(ls >> x >> y)) throw CaseError(where() + "expected 'point X Y'");
      c.ox = parse_double(x, line);
      c.oy = parse_double(y, line);
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
  if (!have_a) throw CaseError("no shape a");
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
Verdict replay_as(const Case& c) {
  const Law law = c.law;
  if (c.transform_a || c.transform_b)
    throw CaseError("law '" + std::string(name(law)) + "' takes no transform");
  auto shape_a = [&] { return from_data<T>(c.a); };
  auto shape_b = [&]() -> Shape<T> {
    if (!c.b) throw CaseError("law '" + std::string(name(law)) + "' needs shape b");
    return from_data<T>(*c.b);
  };
  using codec_detail::narrow;
  switch (law) {
    case Law::Agreement: return agreement(shape_a(), shape_b());
    case Law::Symmetry: return symmetry(shape_a(), shape_b());
    case Law::Translation: return translation(shape_a(), shape_b(), Vec2<T>(narrow<T>(c.tx), narrow<T>(c.ty)));
    case Law::Rotation: return rotation(shape_a(), shape_b(), c.quarter_turns, c.mirror);
    case Law::Resolution: return resolution(shape_a(), shape_b());
    case Law::Bounds: return bounds_law(shape_a());
    case Law::Raycast:
      return raycast_law(shape_a(), Ray<T>{Vec2<T>(narrow<T>(c.ox), narrow<T>(c.oy)), Vec2<T>(narrow<T>(c.dx), narrow<T>(c.dy))},
                         narrow<T>(c.max_t));
    case Law::Hierarchy: return hierarchy(shape_a(), shape_b());
    case Law::Representation: return representation(shape_a(), shape_b());
    case Law::Contact: return contact_law(shape_a(), shape_b());
    case Law::Distance: return distance_law(shape_a(), shape_b());
    case Law::Rejection: {
      std::vector<T> x;
      for (double v : c.values) x.push_back(static_cast<T>(v));
      return rejection<T>(c.a.kind, std::span<const T>(x));
    }
    case Law::Contains: return contains_law(shape_a(), Vec2<T>(narrow<T>(c.ox), narrow<T>(c.oy)));
    case Law::Touching: return touching(shape_a(), shape_b());
    case Law::Scene: return scene(shape_a());
    case Law::Separation: return manifold_separation(shape_a(), shape_b());
    case Law::FeatureIds: return manifold_ids(shape_a(), shape_b());
    case Law::Speculative: return manifold_speculative(shape_a(), shape_b());
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
Case make_case(Law law, const Shape<T>& a, const std::optional<Shape<T>>& b, const Verdict& v,
               std::string source) {
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

template Case make_case<float>(Law, const Shape<float>&, const std::optional<Shape<float>>&, const Verdict&,
                               std::string);
template Case make_case<double>(Law, const Shape<double>&, const std::optional<Shape<double>>&,
                                const Verdict&, std::string);

}  // namespace collide::laws
