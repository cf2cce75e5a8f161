// SVG pictures of regression cases.

#include "collide/laws/case_file.hpp"

#include "support.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace collide::laws {

namespace {

constexpr double kSize = 600;
constexpr double kMargin = 40;

/// World -> picture: fit the world box into the square, y up.
struct View {
  double x0 = -1, y0 = -1, x1 = 1, y1 = 1;
  double scale() const { return (kSize - 2 * kMargin) / std::max({x1 - x0, y1 - y0, 1e-300}); }
  double px(double x) const { return kMargin + (x - x0) * scale(); }
  double py(double y) const { return kSize - kMargin - (y - y0) * scale(); }
  std::string pt(const Vec2c& p) const { return detail::num(px(p.x())) + "," + detail::num(py(p.y())); }
};

std::string escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      default: out += ch;
    }
  }
  return out;
}

template <Scalar T>
void grow(View& v, bool& first, const Aabb<T>& b) {
  const double lx = b.min().x(), ly = b.min().y(), hx = b.max().x(), hy = b.max().y();
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

void grow_point(View& v, bool& first, const Vec2c& p) {
  grow(v, first, Aabb<double>(p, p));
}

template <Scalar T>
void draw_primitive(std::ostream& out, const View& v, const Primitive<T>& p, const std::string& style) {
  std::visit(
      [&](const auto& s) {
        using S = std::remove_cvref_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Circle<T>>) {
          out << "<circle cx='" << v.px(s.center().x()) << "' cy='" << v.py(s.center().y()) << "' r='"
              << double(s.radius()) * v.scale() << "' " << style << "/>\n";
        } else if constexpr (std::is_same_v<S, Capsule<T>>) {
          const double w = 2 * double(s.radius()) * v.scale();
          out << "<line x1='" << v.px(s.a().x()) << "' y1='" << v.py(s.a().y()) << "' x2='" << v.px(s.b().x())
              << "' y2='" << v.py(s.b().y()) << "' stroke-width='" << std::max(w, 1.0)
              << "' stroke-linecap='round' " << style << " fill='none' stroke-opacity='0.35'/>\n";
          out << "<line x1='" << v.px(s.a().x()) << "' y1='" << v.py(s.a().y()) << "' x2='" << v.px(s.b().x())
              << "' y2='" << v.py(s.b().y()) << "' " << style << "/>\n";
        } else {
          const ::collide::detail::Core core = ::collide::detail::core_of(s);
          out << "<polygon points='";
          for (const Vec2c& q : core.pts()) out << v.pt(q) << ' ';
          out << "' " << style << "/>\n";
        }
      },
      p);
}

template <Scalar T>
void draw_shape(std::ostream& out, const View& v, const Shape<T>& s, const std::string& style) {
  if (const auto* c = std::get_if<Compound<T>>(&s)) {
    for (const Primitive<T>& p : c->children()) draw_primitive(out, v, p, style);
    return;
  }
  std::visit(
      [&](const auto& x) {
        using S = std::remove_cvref_t<decltype(x)>;
        if constexpr (!std::is_same_v<S, Compound<T>>) draw_primitive(out, v, Primitive<T>(x), style);
      },
      s);
}

template <Scalar T>
void draw_box(std::ostream& out, const View& v, const Aabb<T>& b, const std::string& colour) {
  out << "<rect x='" << v.px(b.min().x()) << "' y='" << v.py(b.max().y()) << "' width='"
      << (double(b.max().x()) - double(b.min().x())) * v.scale() << "' height='"
      << (double(b.max().y()) - double(b.min().y())) * v.scale() << "' fill='none' stroke='" << colour
      << "' stroke-dasharray='4 3' stroke-width='0.8'/>\n";
}

void arrow(std::ostream& out, const View& v, const Vec2c& from, const Vec2c& to, const std::string& colour) {
  out << "<line x1='" << v.px(from.x()) << "' y1='" << v.py(from.y()) << "' x2='" << v.px(to.x()) << "' y2='"
      << v.py(to.y()) << "' stroke='" << colour << "' stroke-width='2' marker-end='url(#head)'/>\n";
}

template <Scalar T>
void draw(std::ostream& out, const Case& c) {
  const std::string blue = "fill='#3366cc' fill-opacity='0.3' stroke='#3366cc' stroke-width='1.5'";
  const std::string red = "fill='#cc3333' fill-opacity='0.3' stroke='#cc3333' stroke-width='1.5'";
  const std::string moved = "fill='none' stroke='#339933' stroke-width='1.5' stroke-dasharray='6 3'";
  View v;
  bool first = true;
  std::optional<Shape<T>> a, b, a2, b2;
  std::string note;
  std::optional<std::pair<Vec2c, Vec2c>> push;
  try {
    if (c.law != "rejection") a = from_data<T>(c.a);
    if (c.b && c.law != "rejection") b = from_data<T>(*c.b);
    if (a) grow(v, first, bounds(*a));
    if (b) grow(v, first, bounds(*b));
    if (a && b && c.law == "resolution") {
      const Vec2<T> r = resolve(*a, *b);
      const auto m = translated(*a, r);
      if (m) {
        a2 = m.value();
        grow(v, first, bounds(*a2));
      }
      const Aabb<T> box = bounds(*a);
      const Vec2c mid = (box.min().template cast<double>() + box.max().template cast<double>()) / 2;
      push = std::pair{mid, Vec2c(mid + r.template cast<double>())};
      note = "resolve(a, b) = (" + detail::num(r.x()) + ", " + detail::num(r.y()) + "), moved a dashed green";
    }
    if (a && b && c.law == "translation") {
      const Vec2<T> t(static_cast<T>(c.tx), static_cast<T>(c.ty));
      const auto ma = translated(*a, t), mb = translated(*b, t);
      if (ma && mb) {
        a2 = ma.value();
        b2 = mb.value();
        grow(v, first, bounds(*a2));
        grow(v, first, bounds(*b2));
      }
      note = "moved pair dashed green";
    }
    if (c.law == "raycast") {
      const Vec2c o(c.ox, c.oy), e = o + Vec2c(c.dx, c.dy) * c.max_t;
      grow_point(v, first, o);
      grow_point(v, first, e);
      push = std::pair{o, e};
      note = "ray to max_t";
    }
  } catch (const std::exception& e) {
    note = std::string("cannot draw: ") + e.what();
  }
  if (first) v = {-1, -1, 1, 1};
  // Square, padded world box (a point or a flat box still gets a visible frame).
  const double w = std::max({v.x1 - v.x0, v.y1 - v.y0, std::fabs(v.x0) * 1e-12, 1e-300});
  const double cx = (v.x0 + v.x1) / 2, cy = (v.y0 + v.y1) / 2;
  v = {cx - 0.55 * w, cy - 0.55 * w, cx + 0.55 * w, cy + 0.55 * w};

  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kSize << "' height='" << kSize + 60 << "' viewBox='0 0 "
      << kSize << ' ' << kSize + 60 << "'>\n";
  out << "<defs><marker id='head' markerWidth='8' markerHeight='8' refX='6' refY='3' orient='auto'>"
         "<path d='M0,0 L6,3 L0,6 z' fill='#222'/></marker></defs>\n";
  out << "<rect width='100%' height='100%' fill='white'/>\n";
  if (a) {
    draw_box(out, v, bounds(*a), "#3366cc");
    draw_shape(out, v, *a, blue);
  }
  if (b) {
    draw_box(out, v, bounds(*b), "#cc3333");
    draw_shape(out, v, *b, red);
  }
  if (a2) draw_shape(out, v, *a2, moved);
  if (b2) draw_shape(out, v, *b2, moved);
  if (push) arrow(out, v, push->first, push->second, "#222");
  auto caption = [&](double y, const std::string& text) {
    out << "<text x='8' y='" << y << "' font-family='monospace' font-size='11'>" << escape(text.substr(0, 110))
        << "</text>\n";
  };
  caption(kSize + 14, c.law + "  " + pair_name(c) + "  " + c.scalar + "  (a blue, b red)");
  caption(kSize + 28, "expected: " + c.expected);
  caption(kSize + 42, "got: " + c.got);
  caption(kSize + 56, note.empty() ? "source: " + c.source : note);
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
