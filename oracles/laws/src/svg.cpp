// SVG pictures of regression cases.

#include "collide/laws/case_file.hpp"

#include "support.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

namespace collide::laws {

namespace {

constexpr double kSize = 600;
constexpr double kMargin = 50;
constexpr double kLineHeight = 14;
constexpr std::size_t kWrap = 96;  // characters per caption line (11 px monospace in 600 px)
constexpr double kMinVisible = 3;  // px: a shape drawn smaller gets a marker

/// World -> picture: fit the world box into the square, y up.
struct View {
  double x0 = -1, y0 = -1, x1 = 1, y1 = 1;
  double scale() const { return (kSize - 2 * kMargin) / std::max({x1 - x0, y1 - y0, 1e-300}); }
  double px(double x) const { return kMargin + (x - x0) * scale(); }
  double py(double y) const { return kSize - kMargin - (y - y0) * scale(); }
};

/// A number for an attribute: finite, short (pixels need no more).
std::string f(double x) {
  if (!std::isfinite(x)) x = 0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

/// Text content: XML-escaped, control characters dropped (they are not allowed in XML 1.0).
std::string escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '\'':
        out += "&apos;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        if (static_cast<unsigned char>(ch) >= 0x20 || ch == '\t') out += ch;
    }
  }
  return out;
}

/// Lines of at most kWrap characters, broken at spaces where possible (nothing is cut off).
std::vector<std::string> wrap(const std::string& text) {
  std::vector<std::string> lines;
  std::string rest = text;
  while (rest.size() > kWrap) {
    std::size_t cut = rest.rfind(' ', kWrap);
    if (cut == std::string::npos || cut < kWrap / 2) cut = kWrap;
    lines.push_back(rest.substr(0, cut));
    rest = rest.substr(cut == kWrap ? cut : cut + 1);
    rest.insert(0, "    ");
  }
  lines.push_back(rest);
  return lines;
}

void grow(View& v, bool& first, double lx, double ly, double hx, double hy) {
  if (!std::isfinite(lx) || !std::isfinite(ly) || !std::isfinite(hx) || !std::isfinite(hy)) return;
  if (first) {
    v = {lx, ly, hx, hy};
    first = false;
    return;
  }
  v.x0 = std::min(v.x0, lx);
  v.y0 = std::min(v.y0, ly);
  v.x1 = std::max(v.x1, hx);
  v.y1 = std::max(v.y1, hy);
}

template <Scalar T>
void grow(View& v, bool& first, const Aabb<T>& b) {
  grow(v, first, double(b.min().x()), double(b.min().y()), double(b.max().x()), double(b.max().y()));
}

/// Colour and look of one shape; every attribute written once.
struct Style {
  std::string colour;
  double fill_opacity = 0.3;
  std::string dash;  // stroke-dasharray, or empty
  std::string attrs(double stroke_width = 1.5, bool filled = true) const {
    std::string out = "stroke='" + colour + "' stroke-width='" + f(stroke_width) + "'";
    out += filled ? " fill='" + colour + "' fill-opacity='" + f(fill_opacity) + "'" : " fill='none'";
    if (!dash.empty()) out += " stroke-dasharray='" + dash + "'";
    return out;
  }
};

/// A ring and cross of fixed size at p: where a shape too small to see lies.
void marker(std::ostream& out, const View& v, const Vec2c& p, const Style& st) {
  const double x = v.px(p.x()), y = v.py(p.y());
  out << "<circle cx='" << f(x) << "' cy='" << f(y) << "' r='6' " << st.attrs(1.5, false) << "/>\n";
  out << "<path d='M" << f(x - 9) << ',' << f(y) << " H" << f(x + 9) << " M" << f(x) << ',' << f(y - 9) << " V"
      << f(y + 9) << "' " << st.attrs(1, false) << "/>\n";
}

/// Draws a primitive; returns true when it is below kMinVisible pixels (a marker is drawn too).
template <Scalar T>
bool draw_primitive(std::ostream& out, const View& v, const Primitive<T>& p, const Style& st) {
  const Aabb<T> box = bounds(p);
  const double size =
      std::max(double(box.max().x()) - double(box.min().x()), double(box.max().y()) - double(box.min().y())) *
      v.scale();
  std::visit(
      [&](const auto& s) {
        using S = std::remove_cvref_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Circle<T>>) {
          out << "<circle cx='" << f(v.px(s.center().x())) << "' cy='" << f(v.py(s.center().y())) << "' r='"
              << f(std::max(double(s.radius()) * v.scale(), 0.75)) << "' " << st.attrs() << "/>\n";
        } else if constexpr (std::is_same_v<S, Capsule<T>>) {
          const std::string ends = "x1='" + f(v.px(s.a().x())) + "' y1='" + f(v.py(s.a().y())) + "' x2='" +
                                   f(v.px(s.b().x())) + "' y2='" + f(v.py(s.b().y())) + "'";
          out << "<line " << ends << " stroke='" << st.colour << "' stroke-opacity='0.35' stroke-width='"
              << f(std::max(2 * double(s.radius()) * v.scale(), 1.0)) << "' stroke-linecap='round'/>\n";
          out << "<line " << ends << ' ' << st.attrs(1.5, false) << "/>\n";
        } else {
          const ::collide::detail::Core core = ::collide::detail::core_of(s);
          out << "<polygon points='";
          for (const Vec2c& q : core.pts()) out << f(v.px(q.x())) << ',' << f(v.py(q.y())) << ' ';
          out << "' " << st.attrs() << "/>\n";
        }
      },
      p);
  if (size < kMinVisible) {
    const Vec2c c = (box.min().template cast<double>() + box.max().template cast<double>()) / 2;
    marker(out, v, c, st);
    return true;
  }
  return false;
}

template <Scalar T>
bool draw_shape(std::ostream& out, const View& v, const Shape<T>& s, const Style& st) {
  bool tiny = false;
  // Each primitive as placed: a child with a transform is drawn as its image (in double).
  for (const auto& c : detail::placed_primitives_of(s)) {
    if (c.transform.is_identity()) {
      tiny = draw_primitive(out, v, c.shape, st) || tiny;
      continue;
    }
    std::visit(
        [&](const auto& x) {
          ::collide::detail::with_image(x, c.transform.pose(), [&](const auto& img) {
            tiny = draw_primitive(out, v, Primitive<double>(img), st) || tiny;
          });
        },
        c.shape);
  }
  return tiny;
}

template <Scalar T>
void draw_box(std::ostream& out, const View& v, const Aabb<T>& b, const std::string& colour) {
  out << "<rect x='" << f(v.px(b.min().x())) << "' y='" << f(v.py(b.max().y())) << "' width='"
      << f((double(b.max().x()) - double(b.min().x())) * v.scale()) << "' height='"
      << f((double(b.max().y()) - double(b.min().y())) * v.scale()) << "' fill='none' stroke='" << colour
      << "' stroke-dasharray='4 3' stroke-width='0.8'/>\n";
}

void arrow(std::ostream& out, const View& v, const Vec2c& from, const Vec2c& to, const std::string& colour) {
  out << "<line x1='" << f(v.px(from.x())) << "' y1='" << f(v.py(from.y())) << "' x2='" << f(v.px(to.x())) << "' y2='"
      << f(v.py(to.y())) << "' stroke='" << colour << "' stroke-width='2' marker-end='url(#head)'/>\n";
}

void text(std::ostream& out, double x, double y, const std::string& s, const std::string& anchor = "start") {
  out << "<text x='" << f(x) << "' y='" << f(y) << "' font-family='monospace' font-size='11' text-anchor='" << anchor
      << "'>" << escape(s) << "</text>\n";
}

/// The frame with the world coordinates of its corners, the axes where they cross the view, and a
/// scale bar of a round length.
void draw_axes(std::ostream& out, const View& v) {
  const double lo = kMargin, hi = kSize - kMargin;
  out << "<rect x='" << f(lo) << "' y='" << f(lo) << "' width='" << f(hi - lo) << "' height='" << f(hi - lo)
      << "' fill='none' stroke='#999' stroke-width='0.5'/>\n";
  if (v.x0 <= 0 && 0 <= v.x1)
    out << "<line x1='" << f(v.px(0)) << "' y1='" << f(lo) << "' x2='" << f(v.px(0)) << "' y2='" << f(hi)
        << "' stroke='#bbb' stroke-width='0.8'/>\n";
  if (v.y0 <= 0 && 0 <= v.y1)
    out << "<line x1='" << f(lo) << "' y1='" << f(v.py(0)) << "' x2='" << f(hi) << "' y2='" << f(v.py(0))
        << "' stroke='#bbb' stroke-width='0.8'/>\n";
  text(out, lo, hi + 13, "x " + detail::num(v.x0));
  text(out, hi, hi + 13, "x " + detail::num(v.x1), "end");
  text(out, lo - 4, hi, "y " + detail::num(v.y0), "end");
  out << "<text x='" << f(lo - 4) << "' y='" << f(lo + 10) << "' font-family='monospace' font-size='11' "
      << "text-anchor='end' transform='rotate(-90 " << f(lo - 4) << ' ' << f(lo + 10) << ")'>y "
      << escape(detail::num(v.y1)) << "</text>\n";
  // Scale bar: the largest 1, 2 or 5 times a power of ten not longer than a quarter of the view.
  const double span = (v.x1 - v.x0) / 4;
  if (span > 0 && std::isfinite(span)) {
    double unit = std::pow(10.0, std::floor(std::log10(span)));
    for (const double m : {5.0, 2.0}) {
      if (unit * m <= span) {
        unit *= m;
        break;
      }
    }
    const double len = unit * v.scale(), y = lo - 14;
    out << "<path d='M" << f(hi - len) << ',' << f(y - 4) << " V" << f(y) << " H" << f(hi) << " V" << f(y - 4)
        << "' fill='none' stroke='#222' stroke-width='1.2'/>\n";
    text(out, hi - len - 6, y, detail::num(unit), "end");
  }
}

template <Scalar T>
void draw(std::ostream& out, const Case& c) {
  const Style blue{"#3366cc", 0.3, ""}, red{"#cc3333", 0.3, ""}, moved{"#339933", 0, "6 3"};
  View v;
  bool first = true;
  std::optional<Shape<T>> a, b, a2, b2;
  std::vector<std::string> notes;
  std::optional<std::pair<Vec2c, Vec2c>> push;
  std::optional<Vec2c> point;
  try {
    const bool shapes = info(c.law).inputs != LawInputs::Values && info(c.law).inputs != LawInputs::TransformValues;
    if (shapes) a = from_data<T>(c.a);
    if (c.b && shapes) b = from_data<T>(*c.b);
    for (const auto& [which, x] : {std::pair{"a", &c.transform_a}, std::pair{"b", &c.transform_b}}) {
      if (*x)
        notes.push_back(std::string(which) + " placed by p (" + detail::num((*x)->values[0]) + ", " +
                        detail::num((*x)->values[1]) + "), q (" + detail::num((*x)->values[2]) + ", " +
                        detail::num((*x)->values[3]) + "); drawn in its own frame");
    }
    if (a) grow(v, first, bounds(*a));
    if (b) grow(v, first, bounds(*b));
    if (a && b && c.law == Law::Resolution) {
      const Vec2<T> r = resolve(*a, *b);
      const auto m = translated(*a, r);
      if (m) {
        a2 = m.value();
        grow(v, first, bounds(*a2));
      }
      const Aabb<T> box = bounds(*a);
      const Vec2c mid = (box.min().template cast<double>() + box.max().template cast<double>()) / 2;
      push = std::pair{mid, Vec2c(mid + r.template cast<double>())};
      notes.push_back("resolve(a, b) = (" + detail::num(r.x()) + ", " + detail::num(r.y()) + "), moved a dashed green");
    }
    if (a && b && c.law == Law::Translation) {
      const Vec2<T> t(static_cast<T>(c.tx), static_cast<T>(c.ty));
      const auto ma = translated(*a, t), mb = translated(*b, t);
      if (ma && mb) {
        a2 = ma.value();
        b2 = mb.value();
        grow(v, first, bounds(*a2));
        grow(v, first, bounds(*b2));
      }
      notes.push_back("moved pair dashed green, t = (" + detail::num(c.tx) + ", " + detail::num(c.ty) + ")");
    }
    if (a && b && c.law == Law::ClosestPoints) {
      const ClosestPoints<T> w = closest_points(*a, *b);
      push = std::pair{widen(w.point_a), widen(w.point_b)};
      grow(v, first, w.point_a.x(), w.point_a.y(), w.point_a.x(), w.point_a.y());
      grow(v, first, w.point_b.x(), w.point_b.y(), w.point_b.x(), w.point_b.y());
      notes.push_back("closest_points(a, b): distance " + detail::num(w.distance) + ", arrow from point_a (" +
                      detail::num(w.point_a.x()) + ", " + detail::num(w.point_a.y()) + ") to point_b (" +
                      detail::num(w.point_b.x()) + ", " + detail::num(w.point_b.y()) + ")");
    }
    if (a && b && info(c.law).suite == LawSuite::Moving && c.law != Law::Toi && c.law != Law::CastRaycast) {
      // The swept path: a's motion as an arrow, both shapes at the cast's time dashed green.
      const Vec2<T> va(static_cast<T>(c.vax), static_cast<T>(c.vay)), vb(static_cast<T>(c.vbx), static_cast<T>(c.vby));
      const auto placement = [](const std::optional<TransformData>& x) {
        return x ? transform_from_data<T>(*x) : Transform<T>();
      };
      const CastResult<T> r =
          shape_cast(*a, placement(c.transform_a), va, *b, placement(c.transform_b), vb, static_cast<T>(c.max_t));
      const T t = r.outcome == CastOutcome::Miss ? static_cast<T>(c.max_t) : r.t;
      const auto ma = translated(*a, Vec2<T>(va * t)), mb = translated(*b, Vec2<T>(vb * t));
      if (ma && mb) {
        a2 = ma.value();
        b2 = mb.value();
        grow(v, first, bounds(*a2));
        grow(v, first, bounds(*b2));
      }
      const Aabb<T> box = bounds(*a);
      const Vec2c mid = (widen(box.min()) + widen(box.max())) / 2;
      push = std::pair{mid, Vec2c(mid + widen(va) * c.max_t)};
      notes.push_back("a moves at (" + detail::num(c.vax) + ", " + detail::num(c.vay) + "), b at (" +
                      detail::num(c.vbx) + ", " + detail::num(c.vby) + "); shape_cast: " +
                      std::string(r.outcome == CastOutcome::Hit    ? "hit"
                                  : r.outcome == CastOutcome::Miss ? "miss"
                                                                   : "no answer") +
                      " at t = " + detail::num(t) + ", both drawn there dashed green");
    }
    if (c.law == Law::Raycast || c.law == Law::RaycastExit || c.law == Law::PlacedShape || c.law == Law::CastRaycast) {
      const Vec2c o(c.ox, c.oy), e = o + Vec2c(c.dx, c.dy) * c.max_t;
      grow(v, first, o.x(), o.y(), o.x(), o.y());
      grow(v, first, e.x(), e.y(), e.x(), e.y());
      push = std::pair{o, e};
      notes.push_back("ray (" + detail::num(c.ox) + ", " + detail::num(c.oy) + ") + t (" + detail::num(c.dx) + ", " +
                      detail::num(c.dy) + "), arrow to max_t " + detail::num(c.max_t));
    }
    if (c.law == Law::Contains || c.law == Law::SignedDistance || c.law == Law::PlacedShape) {
      point = Vec2c(c.px, c.py);
      grow(v, first, c.px, c.py, c.px, c.py);
      notes.push_back("point (" + detail::num(c.px) + ", " + detail::num(c.py) + "), black ring");
      if (a && c.law == Law::SignedDistance)
        notes.push_back("signed_distance(a, point) = " +
                        detail::num(signed_distance(*a, Vec2<T>(static_cast<T>(c.px), static_cast<T>(c.py)))));
    }
  } catch (const std::exception& e) {
    notes.push_back(std::string("cannot draw: ") + e.what());
  }
  if (first) v = {-1, -1, 1, 1};
  // Square, padded world box (a point or a flat box still gets a visible frame).
  const double w = std::max({v.x1 - v.x0, v.y1 - v.y0, std::fabs(v.x0) * 1e-12, std::fabs(v.y0) * 1e-12, 1e-300});
  const double cx = v.x0 / 2 + v.x1 / 2, cy = v.y0 / 2 + v.y1 / 2;
  v = {cx - 0.55 * w, cy - 0.55 * w, cx + 0.55 * w, cy + 0.55 * w};

  std::ostringstream body;
  draw_axes(body, v);
  bool tiny = false;
  if (a) {
    draw_box(body, v, bounds(*a), blue.colour);
    tiny = draw_shape(body, v, *a, blue) || tiny;
  }
  if (b) {
    draw_box(body, v, bounds(*b), red.colour);
    tiny = draw_shape(body, v, *b, red) || tiny;
  }
  if (a2) tiny = draw_shape(body, v, *a2, moved) || tiny;
  if (b2) tiny = draw_shape(body, v, *b2, moved) || tiny;
  if (push) arrow(body, v, push->first, push->second, "#222");
  if (point) marker(body, v, *point, Style{"#222", 0, ""});
  if (tiny) notes.push_back("ring and cross: a shape smaller than " + detail::num(kMinVisible) + " px, drawn enlarged");

  std::vector<std::string> lines = {std::string(name(c.law)) + "  " + pair_name(c) + "  " + c.scalar +
                                    "  (a blue, b red)"};
  if (a) lines.push_back("a = " + detail::describe(*a));
  if (b) lines.push_back("b = " + detail::describe(*b));
  lines.push_back("expected: " + c.expected);
  lines.push_back("got: " + c.got);
  for (const std::string& n : notes) lines.push_back(n);
  lines.push_back("source: " + c.source);
  std::vector<std::string> wrapped;
  for (const std::string& l : lines)
    for (const std::string& w2 : wrap(l)) wrapped.push_back(w2);
  const double height = kSize + 10 + kLineHeight * double(wrapped.size());

  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << f(kSize) << "' height='" << f(height) << "' viewBox='0 0 "
      << f(kSize) << ' ' << f(height) << "'>\n";
  out << "<defs><marker id='head' markerWidth='8' markerHeight='8' refX='6' refY='3' orient='auto'>"
         "<path d='M0,0 L6,3 L0,6 z' fill='#222'/></marker></defs>\n";
  out << "<rect width='100%' height='100%' fill='white'/>\n";
  out << body.str();
  for (std::size_t i = 0; i < wrapped.size(); ++i) text(out, 8, kSize + 6 + kLineHeight * double(i + 1), wrapped[i]);
  out << "</svg>\n";
}

}  // namespace

void write_svg(std::ostream& out, const Case& c) {
  if (c.scalar == "float") {
    draw<float>(out, c);
  } else {
    draw<double>(out, c);
  }
}

void write_svg(const std::filesystem::path& path, const Case& c) {
  std::ofstream out(path);
  if (!out) throw CaseError("cannot write " + path.string());
  write_svg(out, c);
}

}  // namespace collide::laws
