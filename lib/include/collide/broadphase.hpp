#pragma once
/// @file broadphase.hpp
/// Broadphase: three structures behind one interface, and the world-level helper.
///
/// - DynamicTree<T>: incremental AABB tree with fattened leaves and rotations (any distribution).
/// - SweepAndPrune<T>: array sorted on x, insertion-sorted after coherent motion.
/// - UniformGrid<T>: spatial hash of square cells (similar-sized boxes).
/// - PairTracker<BP, T>: any of the three plus pair events (pairs that began / ended per update).
/// - World<T, BP>: persistent bodies (shape, user data, filter); step() reports contacts that
///   began / ended; point, shape and ray queries settled by the exact predicates.
/// - move_and_slide(world, mover, from, displacement): a circle or capsule moved among a World's
///   bodies, stopping in front of what it meets and sliding along it (a character controller).
///
/// Interface (each structure): add(box[, user[, filter]]) -> ProxyId, move(id, box), remove(id),
/// set_filter(id, filter), query(box, f(id)[, filter]), query_point(p, f(id)[, filter]),
/// raycast(origin, direction, max_t, f(id, t)[, filter]), raycast_closest(...), for_each_pair(f(a, b)),
/// pairs([order]), contains(id), box(id), user_data(id), filter(id), size(). Boxes are closed:
/// touching counts. The pairs reported are exactly the pairs whose stored boxes overlap and whose
/// filters accept each other, each once; PairOrder::Sorted gives the same list from all three.
/// Stale or foreign handles throw BroadphaseError(InvalidProxy); raw corners that do not form a
/// valid box throw BroadphaseError(BadBox).
///
/// Thread safety and re-entrancy: const members only read the structure and keep their traversal
/// state on the caller's stack. Any number of threads may call const members of one structure at
/// once while no thread modifies it; a callback may call const members of the same or another
/// structure (a query from inside a query is exact). Modifying a structure (add, move, remove,
/// set_filter, flush) while any other call on it runs, including from its own callback, is a data
/// race. PairTracker and World (pair events, the persistent world) follow the same rule.

#include "collide/broadphase/common.hpp"
#include "collide/broadphase/events.hpp"
#include "collide/broadphase/grid.hpp"
#include "collide/broadphase/mover.hpp"
#include "collide/broadphase/narrowphase.hpp"
#include "collide/broadphase/sweep.hpp"
#include "collide/broadphase/tree.hpp"
#include "collide/broadphase/world.hpp"

#include <algorithm>
#include <span>
#include <vector>

namespace collide::broadphase {

/// Pairs with at least one proxy in `moved` (e.g. the proxies moved this step) whose filters
/// accept each other, each once, a.index < b.index. Errors: InvalidProxy (any handle in moved).
template <class B>
std::vector<ProxyPair> pairs_involving(const B& bp, std::span<const ProxyId> moved, PairOrder order = PairOrder::Any) {
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
    bp.query(
        bp.box(id),
        [&](ProxyId other) {
          if (other == id) return;
          if (is_moved(other) && other.index < id.index) return;  // found from `other`
          out.push_back(ordered_pair(id, other));
        },
        bp.filter(id));
  }
  finish_pairs(out, order);
  return out;
}

}  // namespace collide::broadphase
