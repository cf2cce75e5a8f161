// Regression case files: stored values <-> shapes, text format, replay.

#include "collide/laws/case_file.hpp"

#include "support.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace collide::laws {

using detail::hex;

// ---------------------------------------------------------------------------------------------
// Shapes <-> stored values.

namespace {

template <Scalar T>
ShapeData primitive_data(const Primitive<T>& p) {
  return std::visit(
      [](const auto& s) {
        using S = std::remove_cvref_t<decltype(s)>;
        ShapeData d;
        d.kind = kind_of_v<S>;
        if constexpr (std::is_same_v<S, Circle<T>>) {
          d.values = {s.center().x(), s.center().y(), s.radius()};
        } else if constexpr (std::is_same_v<S, Aabb<T>>) {
          d.values = {s.min().x(), s.min().y(), s.max().x(), s.max().y()};
        } else if constexpr (std::is_same_v<S, Obb<T>>) {
          d.values = {s.center().x(),       s.center().y(), s.half_extents().x(), s.half_extents().y(),
                      s.axis().x(),         s.axis().y()};
        } else if constexpr (std::is_same_v<S, Capsule<T>>) {
          d.values = {s.a().x(), s.a().y(), s.b().x(), s.b().y(), s.radius()};
        } else {
          for (const Vec2<T>& q : s.vertices()) {
            d.values.push_back(q.x());
            d.values.push_back(q.y());
          }
        }
        return d;
      },
      p);
}

/// The value as T, exactly, or a CaseError.
template <Scalar T>
T narrow(double v) {
  const T t = static_cast<T>(v);
  if (!(double(t) == v) && !(std::isnan(v) && std::isnan(t)))
    throw CaseError("value " + hex(v) + " is not exactly representable as the case's scalar");
  return t;
}

template <Scalar T>
void need(const ShapeData& d, std::size_t n) {
  if (d.values.size() != n)
    throw CaseError(std::string(name(d.kind)) + " needs " + std::to_string(n) + " values, got " +
                    std::to_string(d.values.size()));
}

template <class S>
S valid(Expected<S> r) {
  if (!r) throw CaseError(std::string("stored values rejected: ") + r.error().what());
  return std::move(r).value();
}

/// An OBB whose stored axis is exactly u (make_with_axis keeps an axis that is already unit).
template <Scalar T>
Obb<T> obb_with_axis(const Vec2<T>& c, const Vec2<T>& h, const Vec2<T>& u) {
  Obb<T> r = valid(Obb<T>::make_with_axis(c, h, u));
  if (r.axis() != u) throw CaseError("stored OBB axis (" + hex(double(u.x())) + ", " + hex(double(u.y())) + ") is not a unit vector");
  return r;
}

template <Scalar T>
Primitive<T> primitive_from(const ShapeData& d) {
  using V = Vec2<T>;
  std::vector<T> x;
  for (double v : d.values) x.push_back(narrow<T>(v));
  switch (d.kind) {
    case ShapeKind::Circle: need<T>(d, 3); return valid(Circle<T>::make(V(x[0], x[1]), x[2]));
    case ShapeKind::Aabb: need<T>(d, 4); return valid(Aabb<T>::make(V(x[0], x[1]), V(x[2], x[3])));
    case ShapeKind::Obb: need<T>(d, 6); return obb_with_axis<T>(V(x[0], x[1]), V(x[2], x[3]), V(x[4], x[5]));
    case ShapeKind::Capsule: need<T>(d, 5); return valid(Capsule<T>::make(V(x[0], x[1]), V(x[2], x[3]), x[4]));
    case ShapeKind::Polygon: {
      if (x.size() < 6 || x.size() % 2 != 0) throw CaseError("polygon needs an even number (>= 6) of values");
      std::vector<V> pts;
      for (std::size_t i = 0; i < x.size(); i += 2) pts.emplace_back(x[i], x[i + 1]);
      ConvexPolygon<T> p = valid(ConvexPolygon<T>::make(std::span<const V>(pts)));
      if (p.size() != pts.size()) throw CaseError("stored polygon is not in normal form (vertices were dropped)");
      return p;
    }
    case ShapeKind::Compound: break;
  }
  throw CaseError("a compound cannot be a compound's child");
}

}  // namespace

template <Scalar T>
ShapeData to_data(const Shape<T>& s) {
  if (const auto* c = std::get_if<Compound<T>>(&s)) {
    ShapeData d;
    d.kind = ShapeKind::Compound;
    for (const Primitive<T>& p : c->children()) d.children.push_back(primitive_data(p));
    return d;
  }
  return std::visit(
      [](const auto& x) -> ShapeData {
        using S = std::remove_cvref_t<decltype(x)>;
        if constexpr (std::is_same_v<S, Compound<T>>) {
          return {};  // handled above
        } else {
          return primitive_data(Primitive<T>(x));
        }
      },
      s);
}

template <Scalar T>
Shape<T> from_data(const ShapeData& d) {
  if (d.kind == ShapeKind::Compound) {
    std::vector<Primitive<T>> children;
    for (const ShapeData& c : d.children) children.push_back(primitive_from<T>(c));
    return valid(Compound<T>::make(std::move(children)));
  }
  return to_shape(primitive_from<T>(d));
}

template ShapeData to_data<float>(const Shape<float>&);
template ShapeData to_data<double>(const Shape<double>&);
template Shape<float> from_data<float>(const ShapeData&);
template Shape<double> from_data<double>(const ShapeData&);

// ---------------------------------------------------------------------------------------------
// Text.

namespace {

void write_shape_line(std::ostream& out, const std::string& head, const ShapeData& d) {
  out << head << ' ' << name(d.kind);
  if (d.kind == ShapeKind::Compound) {
    out << ' ' << d.children.size() << '\n';
    for (const ShapeData& c : d.children) write_shape_line(out, "child", c);
    return;
  }
  if (d.kind == ShapeKind::Polygon) out << ' ' << d.values.size() / 2;
  for (double v : d.values) out << ' ' << hex(v);
  out << '\n';
}

/// Decimal comment for humans.
void write_shape_comment(std::ostream& out, const std::string& label, const ShapeData& d) {
  out << "# " << label << ": " << name(d.kind);
  if (d.kind == ShapeKind::Compound) {
    out << " of " << d.children.size() << '\n';
    for (const ShapeData& c : d.children) write_shape_comment(out, "  child", c);
    return;
  }
  for (double v : d.values) out << ' ' << detail::num(v);
  out << '\n';
}

std::string one_line(std::string s) {
  for (char& ch : s) {
    if (ch == '\n' || ch == '\r') ch = ' ';
  }
  return s;
}

double parse_double(const std::string& tok, int line) {
  char* end = nullptr;
  const double v = std::strtod(tok.c_str(), &end);
  if (end == tok.c_str() || *end != '\0')
    throw CaseError("line " + std::to_string(line) + ": not a number: '" + tok + "'");
  return v;
}

ShapeKind parse_kind(const std::string& tok, int line) {
  const auto k = kind_from_name(tok);
  if (!k) throw CaseError("line " + std::to_string(line) + ": unknown shape kind '" + tok + "'");
  return *k;
}

std::size_t value_count(ShapeKind k) {
  switch (k) {
    case ShapeKind::Circle: return 3;
    case ShapeKind::Aabb: return 4;
    case ShapeKind::Obb: return 6;
    case ShapeKind::Capsule: return 5;
    default: return 0;
  }
}

/// Reads "<kind> values..." (polygon: n then 2n values) from the stream.
ShapeData parse_primitive(std::istringstream& in, const std::string& kind_tok, int line) {
  ShapeData d;
  d.kind = parse_kind(kind_tok, line);
  std::size_t n = value_count(d.kind);
  if (d.kind == ShapeKind::Polygon) {
    std::size_t vertices = 0;
    if (!(in >> vertices)) throw CaseError("line " + std::to_string(line) + ": polygon needs a vertex count");
    n = 2 * vertices;
  }
  std::string tok;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(in >> tok)) throw CaseError("line " + std::to_string(line) + ": too few values");
    d.values.push_back(parse_double(tok, line));
  }
  if (in >> tok) throw CaseError("line " + std::to_string(line) + ": extra value '" + tok + "'");
  return d;
}

std::string rest_of(std::istringstream& in) {
  std::string rest;
  std::getline(in, rest);
  const auto b = rest.find_first_not_of(' ');
  return b == std::string::npos ? "" : rest.substr(b);
}

}  // namespace

void write_case(std::ostream& out, const Case& c) {
  out << "collide-case 1\n";
  out << "law " << c.law << '\n';
  out << "scalar " << c.scalar << '\n';
  if (c.law == "rejection") {
    out << "kind " << name(c.a.kind) << '\n';
  } else {
    write_shape_comment(out, "a", c.a);
    write_shape_line(out, "shape a", c.a);
  }
  if (c.b) {
    write_shape_comment(out, "b", *c.b);
    write_shape_line(out, "shape b", *c.b);
  }
  if (c.law == "translation")
    out << "# t = (" << detail::num(c.tx) << ", " << detail::num(c.ty) << ")\ntranslation " << hex(c.tx) << ' '
        << hex(c.ty) << '\n';
  if (c.law == "rotation") out << "rotation " << c.quarter_turns << " mirror " << (c.mirror ? 1 : 0) << '\n';
  if (c.law == "raycast")
    out << "# ray (" << detail::num(c.ox) << ", " << detail::num(c.oy) << ") + t (" << detail::num(c.dx) << ", "
        << detail::num(c.dy) << "), t <= " << detail::num(c.max_t) << "\nray " << hex(c.ox) << ' ' << hex(c.oy)
        << ' ' << hex(c.dx) << ' ' << hex(c.dy) << " max_t " << hex(c.max_t) << '\n';
  if (c.law == "contains")
    out << "# point (" << detail::num(c.ox) << ", " << detail::num(c.oy) << ")\npoint " << hex(c.ox) << ' ' << hex(c.oy)
        << '\n';
  if (c.law == "rejection") {
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
  bool header = false, have_a = false;
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
      ls >> c.law;
    } else if (key == "scalar") {
      ls >> c.scalar;
      if (c.scalar != "float" && c.scalar != "double") throw CaseError(where() + "scalar must be float or double");
    } else if (key == "shape") {
      std::string which, kind;
      if (!(ls >> which >> kind) || (which != "a" && which != "b")) throw CaseError(where() + "expected 'shape a|b kind ...'");
      ShapeData* target = nullptr;
      if (which == "a") {
        target = &c.a;
        have_a = true;
      } else {
        c.b = ShapeData{};
        target = &*c.b;
      }
      if (parse_kind(kind, line) == ShapeKind::Compound) {
        std::size_t n = 0;
        if (!(ls >> n) || n == 0) throw CaseError(where() + "compound needs a child count >= 1");
        *target = ShapeData{ShapeKind::Compound, {}, {}};
        open_compound = target;
        children_left = n;
      } else {
        *target = parse_primitive(ls, kind, line);
      }
    } else if (key == "kind") {
      std::string kind;
      ls >> kind;
      c.a = ShapeData{parse_kind(kind, line), {}, {}};
      have_a = true;
    } else if (key == "child") {
      if (children_left == 0 || open_compound == nullptr) throw CaseError(where() + "child line without a compound");
      std::string kind;
      ls >> kind;
      ShapeData d = parse_primitive(ls, kind, line);
      if (d.kind == ShapeKind::Compound) throw CaseError(where() + "a compound cannot be a child");
      open_compound->children.push_back(std::move(d));
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
  if (c.law.empty()) throw CaseError("no law");
  if (!have_a) throw CaseError("no shape a");
  bool known = false;
  for (std::string_view l : kLawNames) known = known || l == c.law;
  if (!known) throw CaseError("unknown law '" + c.law + "'");
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
  // FNV-1a over the values that define the case (not the account or source).
  std::ostringstream key;
  Case bare = c;
  bare.expected.clear();
  bare.got.clear();
  bare.source.clear();
  bare.account.clear();
  write_case(key, bare);
  std::uint32_t h = 2166136261u;
  for (unsigned char ch : key.str()) {
    h ^= ch;
    h *= 16777619u;
  }
  char buf[16];
  std::snprintf(buf, sizeof buf, "%08x", h);
  return c.law + "-" + pair_name(c) + "-" + c.scalar + "-" + buf;
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
  const Shape<T> a = from_data<T>(c.a);
  auto b = [&]() -> Shape<T> {
    if (!c.b) throw CaseError("law '" + c.law + "' needs shape b");
    return from_data<T>(*c.b);
  };
  if (c.law == "agreement") return agreement(a, b());
  if (c.law == "symmetry") return symmetry(a, b());
  if (c.law == "translation") return translation(a, b(), Vec2<T>(narrow<T>(c.tx), narrow<T>(c.ty)));
  if (c.law == "rotation") return rotation(a, b(), c.quarter_turns, c.mirror);
  if (c.law == "resolution") return resolution(a, b());
  if (c.law == "bounds") return bounds_law(a);
  if (c.law == "raycast")
    return raycast_law(a, RayInput<T>{Vec2<T>(narrow<T>(c.ox), narrow<T>(c.oy)), Vec2<T>(narrow<T>(c.dx), narrow<T>(c.dy))},
                       narrow<T>(c.max_t));
  if (c.law == "hierarchy") return hierarchy(a, b());
  if (c.law == "representation") return representation(a, b());
  if (c.law == "contact") return contact_law(a, b());
  if (c.law == "distance") return distance_law(a, b());
  if (c.law == "touching") return touching(a, b());
  if (c.law == "scene") return scene(a);
  if (c.law == "contains") return contains_law(a, Vec2<T>(narrow<T>(c.ox), narrow<T>(c.oy)));
  throw CaseError("unknown law '" + c.law + "'");
}

template <Scalar T>
Verdict replay_rejection(const Case& c) {
  std::vector<T> x;
  for (double v : c.values) x.push_back(static_cast<T>(v));
  return rejection<T>(c.a.kind, std::span<const T>(x));
}

}  // namespace

Verdict replay(const Case& c) {
  try {
    if (c.law == "rejection")
      return c.scalar == "float" ? replay_rejection<float>(c) : replay_rejection<double>(c);
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
Case make_case(std::string law, const Shape<T>& a, const std::optional<Shape<T>>& b, const Verdict& v,
               std::string source) {
  Case c;
  c.law = std::move(law);
  c.scalar = std::is_same_v<T, float> ? "float" : "double";
  c.a = to_data(a);
  if (b) c.b = to_data(*b);
  c.expected = v.expected.empty() ? "the law holds" : v.expected;
  c.got = v.got.empty() ? (v.ok ? "the law held" : "the law broke") : v.got;
  c.source = std::move(source);
  c.account = v.account;
  return c;
}

template Case make_case<float>(std::string, const Shape<float>&, const std::optional<Shape<float>>&, const Verdict&,
                               std::string);
template Case make_case<double>(std::string, const Shape<double>&, const std::optional<Shape<double>>&,
                                const Verdict&, std::string);

}  // namespace collide::laws
