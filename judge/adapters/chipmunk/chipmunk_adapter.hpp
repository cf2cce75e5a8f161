#pragma once
// In-process adapter for Chipmunk 7 (Debian libchipmunk-dev): cpShapesCollide.

#include "collide/judge/adapter.hpp"

namespace collide::judge {

class ChipmunkAdapter {
 public:
  Info info() const;
  Answer answer(const Input& in) const;
  std::string reproducer(const Input& in, Query q, const std::string& exact) const;
  std::string link_flags() const { return "-lchipmunk -lm"; }
};

static_assert(InProcessAdapter<ChipmunkAdapter>);

}  // namespace collide::judge
