#pragma once
/// @file broadphase.hpp
/// Broadphase: three structures behind one interface, and the world-level helper.
///
/// - DynamicTree<T>: incremental AABB tree with fattened leaves and rotations (any distribution).
/// - SweepAndPrune<T>: array sorted on x, insertion-sorted after coherent motion.
/// - UniformGrid<T>: spatial hash of square cells (similar-sized boxes).
///
/// Interface (each structure): add(box[, user]) -> ProxyId, move(id, box), remove(id),
/// query(box, f(id)), raycast(origin, direction, max_t, f(id, t)), pairs([order]),
/// contains(id), box(id), user_data(id), size(). Boxes are closed: touching counts. The pairs
/// reported are exactly the pairs whose stored boxes overlap, each once; PairOrder::Sorted gives
/// the same list from all three. Stale or foreign handles throw BroadphaseError(InvalidProxy);
/// raw corners that do not form a valid box throw BroadphaseError(BadBox).

#include "collide/broadphase/common.hpp"
#include "collide/broadphase/grid.hpp"
#include "collide/broadphase/sweep.hpp"
#include "collide/broadphase/tree.hpp"
#include "collide/broadphase/world.hpp"

#include <algorithm>
#include <concepts>
#include <span>
#include <vector>

namespace collide::broadphase {

/// What the three structures have in common.
template <class B, class T>
concept BroadphaseOf = requires(B b, const B cb, const Aabb<T>& box, ProxyId id) {
  { b.add(box, std::uint64_t{}) } -> std::same_as<ProxyId>;
  b.move(id, box);
  b.remove(id);
  { cb.contains(id) } -> std::same_as<bool>;
  { cb.pairs(PairOrder::Sorted) } -> std::same_as<std::vector<ProxyPair>>;
  cb.query(box, [](ProxyId) {});
};

/// Pairs with at least one proxy in `moved` (e.g. the proxies moved this step), each once,
/// a.index < b.index. Errors: InvalidProxy (any handle in moved).
template <class B>
std::vector<ProxyPair> pairs_involving(const B& bp, std::span<const ProxyId> moved,
                                      PairOrder order = PairOrder::Any) {
  for (const ProxyId id : moved) {
    if (!bp.contains(id))
      throw BroadphaseError(BroadphaseErrc::InvalidProxy, "proxy handle is stale or was never issued");
  }
  std::vector<ProxyId> sorted(moved.begin(), moved.end());
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  const auto is_moved = [&](ProxyId id) { return std::binary_search(sorted.begin(), sorted.end(), id); };
  std::vector<ProxyPair> out;
  for (const ProxyId id : sorted) {
    bp.query(bp.box(id), [&](ProxyId other) {
      if (other == id) return;
      if (is_moved(other) && other.index < id.index) return;  // found from `other`
      out.push_back(ordered_pair(id, other));
    });
  }
  finish_pairs(out, order);
  return out;
}

}  // namespace collide::broadphase
