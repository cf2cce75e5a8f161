// Box2D 2.4.1, read for its contract: b2_collision.h (b2TestOverlap; b2WorldManifold: normal
// from A to B, separations negative on penetration), b2_distance.cpp (b2TestOverlap is GJK
// distance minus both radii < 10 b2_epsilon, so touching overlaps), b2_common.h (b2_linearSlop
// 0.005, b2_polygonRadius = 2 b2_linearSlop: every polygon's skin), b2_polygon_shape.h/.cpp
// (Set: 3..8 points, convex hull, welding closer than linearSlop / 2; SetAsBox by half extents,
// centre and angle). Everything is float: values are rounded to float, and the rounded values
// (with the polygon's vertices read back) are the stored geometry. Containment:
// b2Shape::TestPoint (b2_polygon_shape.cpp: outside when dot(normal, p - vertex) > 0, so the
// sharp polygon's boundary is inside and its skin is not; b2_circle_shape.cpp: |p - c|^2 <= r^2).

#include "box2d/box2d_adapter.hpp"

#include "collide/judge/repro.hpp"

#include <box2d/box2d.h>

#include <cmath>
#include <variant>

namespace collide::judge {

namespace {

using Built = std::variant<b2CircleShape, b2PolygonShape>;

std::vector<b2Vec2> corners(const ShapeData& d) {
  const auto& v = d.values;
  std::vector<b2Vec2> pts;
  if (d.kind == ShapeKind::Aabb) {
    pts = {
        {float(v[0]), float(v[1])}, {float(v[2]), float(v[1])}, {float(v[2]), float(v[3])}, {float(v[0]), float(v[3])}};
  } else {
    for (std::size_t i = 0; i + 1 < v.size(); i += 2) pts.push_back({float(v[i]), float(v[i + 1])});
  }
  return pts;
}

Built build(const ShapeData& d) {
  const auto& v = d.values;
  if (d.kind == ShapeKind::Circle) {
    b2CircleShape c;
    c.m_p.Set(float(v[0]), float(v[1]));
    c.m_radius = float(v[2]);
    return c;
  }
  b2PolygonShape p;
  if (d.kind == ShapeKind::Obb) {
    p.SetAsBox(float(v[2]), float(v[3]), b2Vec2(float(v[0]), float(v[1])), float(std::atan2(v[5], v[4])));
    return p;
  }
  const std::vector<b2Vec2> pts = corners(d);
  p.Set(pts.data(), static_cast<int32>(pts.size()));
  return p;
}

/// Inside b2PolygonShape's domain: 3 to 8 points, none closer than b2_linearSlop to another
/// (Set welds points closer than half of it and asserts when fewer than 3 remain; SetAsBox
/// builds the same polygon unchecked, so a box's sides are held to it too), an area above its
/// centroid's assert (area > b2_epsilon), computed in float as Set does.
bool settable(const ShapeData& d) {
  if (d.kind == ShapeKind::Circle) return true;
  if (d.kind == ShapeKind::Obb)
    return 2 * float(d.values[2]) >= b2_linearSlop && 2 * float(d.values[3]) >= b2_linearSlop;
  const std::vector<b2Vec2> pts = corners(d);
  if (pts.size() < 3 || pts.size() > b2_maxPolygonVertices) return false;
  // b2PolygonShape::Set's hull and centroid take float cross products of the vertices, which
  // overflow beyond 2^63 and then trip its asserts: coordinates up to 2^48 keep them finite (the
  // area test below is then meaningful), far beyond the manual's 50 m.
  for (const b2Vec2& v : pts)
    if (!(std::fabs(v.x) <= 0x1p48f && std::fabs(v.y) <= 0x1p48f)) return false;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j)
      if (b2DistanceSquared(pts[i], pts[j]) < b2_linearSlop * b2_linearSlop) return false;
  float area = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) area += b2Cross(pts[i] - pts[0], pts[(i + 1) % pts.size()] - pts[0]);
  return std::fabs(area) / 2 > 4 * b2_epsilon;
}

ShapeData stored(const Built& b) {
  ShapeData d;
  if (const auto* c = std::get_if<b2CircleShape>(&b)) {
    d.kind = ShapeKind::Circle;
    d.values = {c->m_p.x, c->m_p.y, c->m_radius};
    return d;
  }
  const auto& p = std::get<b2PolygonShape>(b);
  d.kind = ShapeKind::Polygon;
  for (int32 i = 0; i < p.m_count; ++i) {
    d.values.push_back(p.m_vertices[i].x);
    d.values.push_back(p.m_vertices[i].y);
  }
  return d;
}

const b2Shape* base(const Built& b) {
  return std::visit([](const auto& s) -> const b2Shape* { return &s; }, b);
}

/// The manifold of (a, b), whichever order Box2D's functions take; flipped tells the caller the
/// normal points from b to a.
b2Manifold manifold(const Built& a, const Built& b, bool& flipped) {
  b2Transform id;
  id.SetIdentity();
  b2Manifold m;
  m.pointCount = 0;
  flipped = false;
  const auto* ca = std::get_if<b2CircleShape>(&a);
  const auto* cb = std::get_if<b2CircleShape>(&b);
  if (ca && cb) {
    b2CollideCircles(&m, ca, id, cb, id);
  } else if (!ca && cb) {
    b2CollidePolygonAndCircle(&m, &std::get<b2PolygonShape>(a), id, cb, id);
  } else if (ca && !cb) {
    b2CollidePolygonAndCircle(&m, &std::get<b2PolygonShape>(b), id, ca, id);
    flipped = true;
  } else {
    b2CollidePolygons(&m, &std::get<b2PolygonShape>(a), id, &std::get<b2PolygonShape>(b), id);
  }
  return m;
}

}  // namespace

Info Box2dAdapter::info() const {
  Info i;
  i.library = "box2d";
  i.version = std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
              std::to_string(b2_version.revision) + " (Debian libbox2d-dev 2.4.1)";
  i.kinds = {ShapeKind::Circle, ShapeKind::Aabb, ShapeKind::Obb, ShapeKind::Polygon};
  i.queries = {Query::Overlap, Query::Push, Query::Contains};
  // The band: both skins, the reference-face tolerance of b2CollidePolygons (k_tol = 0.1
  // b2_linearSlop, by which its depth may exceed the least one), GJK's 10 b2_epsilon, and 32
  // float ulps of the scale. Sizes: the manual's units section keeps moving objects between
  // 0.1 and 10 metres and static shapes up to 50 metres.
  i.contract = {"float32",
                Touching::Overlap,
                2 * b2_polygonRadius + 0.1 * b2_linearSlop + 10 * b2_epsilon,
                0x1p-18,
                PushMoves::A,
                "b2_distance.cpp b2TestOverlap (distance minus radii < 10 b2_epsilon); b2_common.h "
                "b2_polygonRadius 0.01 (each polygon's skin); b2_collide_polygon.cpp k_tol = 0.1 b2_linearSlop; "
                "b2WorldManifold normal from A to B, separation < 0 on penetration; float; the manual: moving "
                "objects 0.1 to 10 m, static shapes up to 50 m (min_size 0.1, max_size 50)",
                0.1,
                50.0};
  i.mapping =
      "values rounded to float; circle -> b2CircleShape; aabb -> b2PolygonShape::Set(4 corners); obb -> "
      "SetAsBox(hx, hy, centre, atan2(uy, ux)); polygon -> Set(vertices); identity transforms; stored: m_vertices "
      "(the sharp polygon; its 0.01 skin is the declared tolerance); push: -normal * deepest penetration of the "
      "world manifold; contains: TestPoint(identity, point rounded to float)";
  return i;
}

Answer Box2dAdapter::answer(const Input& in) const {
  Answer out;
  if (in.ask == Query::Contains) {
    if (!settable(in.a)) {
      out.status = Status::Unsupported;
      return out;
    }
    const Built a = build(in.a);
    out.stored_a = stored(a);
    const b2Vec2 p(float(in.p.x()), float(in.p.y()));
    out.stored_p = Vec2<double>(p.x, p.y);
    b2Transform id;
    id.SetIdentity();
    out.contains = base(a)->TestPoint(id, p);
    return out;
  }
  if (!settable(in.a) || !settable(in.b)) {
    out.status = Status::Unsupported;
    return out;
  }
  const Built a = build(in.a), b = build(in.b);
  out.stored_a = stored(a);
  out.stored_b = stored(b);
  b2Transform id;
  id.SetIdentity();
  out.overlap = b2TestOverlap(base(a), 0, base(b), 0, id, id);
  if (!out.overlap) return out;
  bool flipped = false;
  const b2Manifold m = manifold(a, b, flipped);
  if (m.pointCount == 0) return out;
  b2WorldManifold wm;
  const b2Shape* first = flipped ? base(b) : base(a);
  const b2Shape* second = flipped ? base(a) : base(b);
  wm.Initialize(&m, id, first->m_radius, id, second->m_radius);
  float sep = wm.separations[0];
  for (int32 i = 1; i < m.pointCount; ++i) sep = std::min(sep, wm.separations[i]);
  // The normal points from the first shape of the call to the second: a moves by normal * sep.
  const float s = flipped ? -sep : sep;
  out.has_push = true;
  out.push = Vec2<double>(double(wm.normal.x) * s, double(wm.normal.y) * s);
  return out;
}

std::string Box2dAdapter::reproducer(const Input& in, Query q, const std::string& exact) const {
  std::string s = repro::cpp_prelude("Box2D 2.4.1: a wrong " + std::string(name(q)) +
                                     " answer (build: c++ -std=c++17 this.cpp -lbox2d).");
  s += "#include <box2d/box2d.h>\n#include <cmath>\n\n";
  auto shape = [&](const ShapeData& d, const std::string& n) {
    const auto& v = d.values;
    std::string t;
    if (d.kind == ShapeKind::Circle) {
      t += "  b2CircleShape " + n + ";\n  " + n + ".m_p.Set(float(" + repro::cpp(v[0]) + "), float(" +
           repro::cpp(v[1]) + "));\n  " + n + ".m_radius = float(" + repro::cpp(v[2]) + ");\n";
    } else if (d.kind == ShapeKind::Obb) {
      t += "  b2PolygonShape " + n + ";\n  " + n + ".SetAsBox(float(" + repro::cpp(v[2]) + "), float(" +
           repro::cpp(v[3]) + "), b2Vec2(float(" + repro::cpp(v[0]) + "), float(" + repro::cpp(v[1]) +
           ")), float(std::atan2(" + repro::cpp(v[5]) + ", " + repro::cpp(v[4]) + ")));\n";
    } else {
      const std::vector<b2Vec2> pts = corners(d);
      t += "  const b2Vec2 " + n + "_points[] = {\n";
      for (const b2Vec2& p : pts) t += "      {float(" + repro::cpp(p.x) + "), float(" + repro::cpp(p.y) + ")},\n";
      t +=
          "  };\n  b2PolygonShape " + n + ";\n  " + n + ".Set(" + n + "_points, " + std::to_string(pts.size()) + ");\n";
    }
    return t;
  };
  if (q == Query::Contains) {
    s += "int main() {\n" + shape(in.a, "a");
    s += "  const b2Vec2 p(float(" + repro::cpp(in.p.x()) + "), float(" + repro::cpp(in.p.y()) + "));\n";
    s += "  b2Transform id;\n  id.SetIdentity();\n";
    s += "  std::printf(\"library: contains %s\", a.TestPoint(id, p) ? \"true\" : \"false\");\n";
    s += "  std::printf(\"\\nexact:   %s\\n\", " + repro::cpp_string(exact) + ");\n}\n";
    return s;
  }
  const bool ca = in.a.kind == ShapeKind::Circle, cb = in.b.kind == ShapeKind::Circle;
  s += "int main() {\n" + shape(in.a, "a") + shape(in.b, "b");
  s += "  b2Transform id;\n  id.SetIdentity();\n  const bool o = b2TestOverlap(&a, 0, &b, 0, id, id);\n";
  s += "  std::printf(\"library: overlap %s\", o ? \"true\" : \"false\");\n";
  if (q == Query::Push) {
    const std::string call = ca && cb    ? "b2CollideCircles(&m, &a, id, &b, id)"
                             : !ca && cb ? "b2CollidePolygonAndCircle(&m, &a, id, &b, id)"
                             : ca && !cb ? "b2CollidePolygonAndCircle(&m, &b, id, &a, id)"
                                         : "b2CollidePolygons(&m, &a, id, &b, id)";
    const bool flipped = ca && !cb;
    s += "  b2Manifold m;\n  m.pointCount = 0;\n  " + call + ";\n";
    s += "  if (o && m.pointCount > 0) {\n    b2WorldManifold wm;\n    wm.Initialize(&m, id, " +
         std::string(flipped ? "b" : "a") + ".m_radius, id, " + (flipped ? "a" : "b") + ".m_radius);\n";
    s += "    float sep = wm.separations[0];\n    for (int i = 1; i < m.pointCount; ++i) sep = std::fmin(sep, "
         "wm.separations[i]);\n";
    s += std::string("    // Normal from the call's first shape to its second: a moves by normal * sep.\n") +
         "    const float s = " + (flipped ? "-sep" : "sep") + ";\n";
    s += "    std::printf(\" push %.17g %.17g\", double(wm.normal.x) * s, double(wm.normal.y) * s);\n  }\n";
  }
  s += "  std::printf(\"\\nexact:   %s\\n\", " + repro::cpp_string(exact) + ");\n}\n";
  return s;
}

}  // namespace collide::judge
