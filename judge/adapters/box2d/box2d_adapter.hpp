#pragma once
// In-process adapter for Box2D 2.4.1 (Debian libbox2d-dev): b2TestOverlap, and the manifold
// functions (b2CollideCircles, b2CollidePolygonAndCircle, b2CollidePolygons) for the push.

#include "collide/judge/adapter.hpp"

namespace collide::judge {

class Box2dAdapter {
 public:
  Info info() const;
  Answer answer(const Input& in) const;
  std::string reproducer(const Input& in, Query q, const std::string& exact) const;
  std::string link_flags() const { return "-lbox2d"; }
};

static_assert(InProcessAdapter<Box2dAdapter>);

}  // namespace collide::judge
