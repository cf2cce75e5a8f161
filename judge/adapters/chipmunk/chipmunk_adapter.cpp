// Chipmunk 7, read for its contract (the installed headers: the package ships no source):
// cpShape.h (cpShapesCollide: "Return contact information about two shapes"), cpArbiter.h
// (cpContactPointSet: distance = dot(pointB - pointA, normal), negative when overlapping, so the
// normal points from a to b), cpPolyShape.h (cpPolyShapeNew takes the convex hull; a radius
// rounds the corners: 0 here), cpSegmentShape.h (a segment with a radius: our capsule),
// chipmunk_types.h (cpFloat is double). Touching and any tolerance are not documented: touching
// is either, the band the rounding of double arithmetic. Shapes hang on a static body at the
// origin, so world and local coordinates coincide (an identity transform is exact).
// Containment: cpShapePointQuery (cpShape.h: the distance to the nearest surface point,
// negative inside), inside when it is <= 0.

#include "chipmunk/chipmunk_adapter.hpp"

#include "collide/judge/repro.hpp"

#include <chipmunk/chipmunk.h>

#include <memory>
#include <stdexcept>

namespace collide::judge {

namespace {

struct ShapeFree {
  void operator()(cpShape* s) const { cpShapeFree(s); }
};
using ShapePtr = std::unique_ptr<cpShape, ShapeFree>;

cpBody* static_body() {
  static cpBody* body = cpBodyNewStatic();
  return body;
}

std::vector<cpVect> corners(const ShapeData& d) {
  const auto& v = d.values;
  if (d.kind == ShapeKind::Obb) {
    const double cx = v[0], cy = v[1], hx = v[2], hy = v[3], ux = v[4], uy = v[5];
    const double ex = ux * hx, ey = uy * hx, fx = -uy * hy, fy = ux * hy;
    return {cpv(cx - ex - fx, cy - ey - fy), cpv(cx + ex - fx, cy + ey - fy), cpv(cx + ex + fx, cy + ey + fy),
            cpv(cx - ex + fx, cy - ey + fy)};
  }
  std::vector<cpVect> pts;
  for (std::size_t i = 0; i + 1 < v.size(); i += 2) pts.push_back(cpv(v[i], v[i + 1]));
  return pts;
}

ShapePtr build(const ShapeData& d) {
  const auto& v = d.values;
  cpBody* body = static_body();
  cpShape* s = nullptr;
  switch (d.kind) {
    case ShapeKind::Circle:
      s = cpCircleShapeNew(body, v[2], cpv(v[0], v[1]));
      break;
    case ShapeKind::Aabb:
      s = cpBoxShapeNew2(body, cpBBNew(v[0], v[1], v[2], v[3]), 0);
      break;
    case ShapeKind::Capsule:
      s = cpSegmentShapeNew(body, cpv(v[0], v[1]), cpv(v[2], v[3]), v[4]);
      break;
    default: {
      const std::vector<cpVect> pts = corners(d);
      s = cpPolyShapeNew(body, static_cast<int>(pts.size()), pts.data(), cpTransformIdentity, 0);
    }
  }
  cpShapeCacheBB(s);
  return ShapePtr(s);
}

ShapeData stored(const ShapeData& in, const cpShape* s) {
  ShapeData d;
  switch (in.kind) {
    case ShapeKind::Circle: {
      const cpVect c = cpCircleShapeGetOffset(s);
      d.kind = ShapeKind::Circle;
      d.values = {c.x, c.y, cpCircleShapeGetRadius(s)};
      return d;
    }
    case ShapeKind::Capsule: {
      const cpVect a = cpSegmentShapeGetA(s), b = cpSegmentShapeGetB(s);
      d.kind = ShapeKind::Capsule;
      d.values = {a.x, a.y, b.x, b.y, cpSegmentShapeGetRadius(s)};
      return d;
    }
    default:
      d.kind = ShapeKind::Polygon;
      for (int i = 0; i < cpPolyShapeGetCount(s); ++i) {
        const cpVect p = cpPolyShapeGetVert(s, i);
        d.values.push_back(p.x);
        d.values.push_back(p.y);
      }
      return d;
  }
}

}  // namespace

Info ChipmunkAdapter::info() const {
  Info i;
  i.library = "chipmunk";
  i.version = std::string(cpVersionString) + " (Debian libchipmunk-dev)";
  i.kinds = {ShapeKind::Circle, ShapeKind::Aabb, ShapeKind::Obb, ShapeKind::Capsule, ShapeKind::Polygon};
  i.queries = {Query::Overlap, Query::Push, Query::Contains};
  i.contract = {"float64",
                Touching::Either,
                0.0,
                0x1p-40,
                PushMoves::A,
                "cpShape.h cpShapesCollide; cpArbiter.h cpContactPointSet (distance < 0 overlapping, normal from "
                "a to b); no tolerance documented (band: double rounding)"};
  i.mapping =
      "shapes on a static body at the origin; circle -> cpCircleShapeNew(r, centre); aabb -> cpBoxShapeNew2(bb, 0); "
      "capsule -> cpSegmentShapeNew(a, b, r); obb -> cpPolyShapeNew(4 corners computed in double, radius 0); "
      "polygon -> cpPolyShapeNew(vertices, radius 0); overlap: count > 0; push: normal * deepest distance; "
      "contains: cpShapePointQuery(shape, point, &info) <= 0";
  return i;
}

Answer ChipmunkAdapter::answer(const Input& in) const {
  Answer out;
  if (in.ask == Query::Contains) {
    const ShapePtr a = build(in.a);
    out.stored_a = stored(in.a, a.get());
    out.stored_p = in.p;
    cpPointQueryInfo info;
    out.contains = cpShapePointQuery(a.get(), cpv(in.p.x(), in.p.y()), &info) <= 0;
    return out;
  }
  const ShapePtr a = build(in.a), b = build(in.b);
  out.stored_a = stored(in.a, a.get());
  out.stored_b = stored(in.b, b.get());
  const cpContactPointSet set = cpShapesCollide(a.get(), b.get());
  out.overlap = set.count > 0;
  if (out.overlap) {
    double d = set.points[0].distance;
    for (int i = 1; i < set.count; ++i) d = std::min(d, set.points[i].distance);
    out.has_push = true;
    out.push = Vec2<double>(set.normal.x * d, set.normal.y * d);
  }
  return out;
}

std::string ChipmunkAdapter::reproducer(const Input& in, Query q, const std::string& exact) const {
  std::string s = repro::cpp_prelude("Chipmunk 7: cpShapesCollide gives a wrong " + std::string(name(q)) +
                                     " answer (build: c++ -std=c++17 this.cpp -lchipmunk -lm).");
  s += "#include <chipmunk/chipmunk.h>\n\nint main() {\n  cpBody* body = cpBodyNewStatic();\n";
  auto shape = [&](const ShapeData& d, const std::string& n) {
    const auto& v = d.values;
    switch (d.kind) {
      case ShapeKind::Circle:
        return "  cpShape* " + n + " = cpCircleShapeNew(body, " + repro::cpp(v[2]) + ", cpv(" + repro::cpp(v[0]) +
               ", " + repro::cpp(v[1]) + "));\n";
      case ShapeKind::Aabb:
        return "  cpShape* " + n + " = cpBoxShapeNew2(body, cpBBNew(" + repro::cpp(v[0]) + ", " + repro::cpp(v[1]) +
               ", " + repro::cpp(v[2]) + ", " + repro::cpp(v[3]) + "), 0);\n";
      case ShapeKind::Capsule:
        return "  cpShape* " + n + " = cpSegmentShapeNew(body, cpv(" + repro::cpp(v[0]) + ", " + repro::cpp(v[1]) +
               "), cpv(" + repro::cpp(v[2]) + ", " + repro::cpp(v[3]) + "), " + repro::cpp(v[4]) + ");\n";
      default: {
        const std::vector<cpVect> pts = corners(d);
        std::string t = "  const cpVect " + n + "_points[] = {\n";
        for (const cpVect& p : pts) t += "      cpv(" + repro::cpp(p.x) + ", " + repro::cpp(p.y) + "),\n";
        return t + "  };\n  cpShape* " + n + " = cpPolyShapeNew(body, " + std::to_string(pts.size()) + ", " + n +
               "_points, cpTransformIdentity, 0);\n";
      }
    }
  };
  if (q == Query::Contains) {
    s += shape(in.a, "a") + "  cpShapeCacheBB(a);\n  cpPointQueryInfo info;\n";
    s += "  const cpFloat d = cpShapePointQuery(a, cpv(" + repro::cpp(in.p.x()) + ", " + repro::cpp(in.p.y()) +
         "), &info);\n";
    s += "  std::printf(\"library: contains %s (distance %.17g)\", d <= 0 ? \"true\" : \"false\", d);\n";
    s += "  std::printf(\"\\nexact:   %s\\n\", " + repro::cpp_string(exact) + ");\n}\n";
    return s;
  }
  s += shape(in.a, "a") + shape(in.b, "b");
  s += "  cpShapeCacheBB(a);\n  cpShapeCacheBB(b);\n  const cpContactPointSet set = cpShapesCollide(a, b);\n";
  s += "  std::printf(\"library: overlap %s\", set.count > 0 ? \"true\" : \"false\");\n";
  if (q == Query::Push) {
    s += "  if (set.count > 0) {\n    double d = set.points[0].distance;\n    for (int i = 1; i < set.count; ++i) "
         "d = d < set.points[i].distance ? d : set.points[i].distance;\n";
    s += "    // distance < 0 when overlapping, normal from a to b: a moves by normal * distance.\n";
    s += "    std::printf(\" push %.17g %.17g\", set.normal.x * d, set.normal.y * d);\n  }\n";
  }
  s += "  std::printf(\"\\nexact:   %s\\n\", " + repro::cpp_string(exact) + ");\n}\n";
  return s;
}

}  // namespace collide::judge
