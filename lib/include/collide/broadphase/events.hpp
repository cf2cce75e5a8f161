#pragma once
/// @file broadphase/events.hpp
/// Pair events: a broadphase structure plus the set of pairs it reported at the last update, so
/// that an update after a batch of changes reports only the pairs that began and the pairs that
/// ended, each once. Work per update is proportional to the proxies changed and their partners,
/// not to the number of proxies or pairs.

#include "collide/broadphase/common.hpp"

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <utility>
#include <vector>

namespace collide::broadphase {

/// The pairs that began and ended between two updates. A pair is reported with the handles its
/// proxies had while paired (a removed proxy's handle is already stale when its pair ends).
struct PairEvents {
  std::vector<ProxyPair> began;  ///< pairs whose boxes overlap now and did not at the last update
  std::vector<ProxyPair> ended;  ///< pairs that overlapped at the last update and do not now
  /// Empties both lists, keeping their memory.
  void clear() noexcept {
    began.clear();
    ended.clear();
  }
};

/// A broadphase structure BP (DynamicTree, SweepAndPrune or UniformGrid of scalar T) that reports
/// pair events. add/move/remove/set_filter go through the tracker, which remembers what changed;
/// update() compares the changed proxies' pairs now with their pairs at the last update.
/// The current pairs are exactly those of structure().pairs() after each update(). When the
/// proxies added since the last rebuild, less those removed, make up half of a DynamicTree (and
/// at least 1,024), update() first rebuilds it top down (DynamicTree::rebuild: the same answers,
/// faster queries); a world that only moves, or adds and removes as many, never rebuilds.
///
/// Thread safety: as the structures (const members may run concurrently; nothing may run while
/// a non-const member does).
template <class BP, Scalar T>
class PairTracker {
 public:
  /// Tracks pairs in bp (which must be empty).
  explicit PairTracker(BP bp = BP()) : bp_(std::move(bp)) {}

  /// Adds a proxy; its pairs begin at the next update. Errors: as BP::add.
  ProxyId add(const Aabb<T>& box, std::uint64_t user = 0, Filter filter = {}) {
    const ProxyId id = bp_.add(box, user, filter);
    ++added_;
    grow(id.index);
    ids_[id.index] = id;
    partners_[id.index].clear();
    if constexpr (kFat) refat_[id.index] = 1;
    mark(id.index);
    return id;
  }
  /// Moves a proxy; its pairs are re-examined at the next update. Errors: InvalidProxy.
  void move(ProxyId id, const Aabb<T>& box) {
    if constexpr (kFat) {
      if (bp_.move_fat(id, box)) refat_[id.index] = 1;
    } else {
      bp_.move(id, box);
    }
    mark(id.index);
  }
  /// Replaces a proxy's filter; its pairs are re-examined at the next update. Errors: InvalidProxy.
  void set_filter(ProxyId id, Filter filter) {
    bp_.set_filter(id, filter);
    mark(id.index);
  }
  /// Removes a proxy; its pairs end at the next update. Errors: InvalidProxy.
  void remove(ProxyId id) {
    bp_.remove(id);
    if (added_ > 0) --added_;
    for (const std::uint32_t other : partners_[id.index]) {
      pending_ended_.push_back(ordered_pair(id, ids_[other]));
      erase_sorted(partners_[other], id.index);
    }
    partners_[id.index].clear();
    if constexpr (kFat) {
      for (const std::uint32_t other : near_[id.index]) erase_sorted(near_[other], id.index);
      near_[id.index].clear();
      refat_[id.index] = 0;
    }
  }

  /// Reports into out (cleared first) the pairs that began and ended since the last update, each
  /// once, in no particular order. Allocates only while its buffers grow.
  void update(PairEvents& out) {
    if constexpr (requires { bp_.flush(); }) bp_.flush();
    if constexpr (requires { bp_.rebuild(); }) {
      // Many one-by-one insertions leave a tree that queries slowly: rebuild it once the growth
      // since the last rebuild is half of it (a few rebuilds over any number of additions).
      if (added_ >= kRebuildMin && 2 * added_ >= bp_.size()) {
        bp_.rebuild();
        added_ = 0;
      }
    }
    out.clear();
    out.ended.swap(pending_ended_);
    if constexpr (kFat) refresh_fat_neighbours();
    for (const std::uint32_t i : changed_) {
      const ProxyId id = ids_[i];
      if (!bp_.contains(id)) continue;  // removed since
      found_.clear();
      if constexpr (kFat) {
        // Stored boxes that meet are inside fat boxes that meet: the neighbours hold every partner.
        for (const std::uint32_t o : near_[i])
          if (bp_.overlap(id, ids_[o])) found_.push_back(o);
      } else {
        bp_.query(
            bp_.box(id),
            [&](ProxyId o) {
              if (o.index != i) found_.push_back(o.index);
            },
            bp_.filter(id));
        std::sort(found_.begin(), found_.end());
      }
      diff(i, out);
      partners_[i].assign(found_.begin(), found_.end());
      changed_mark_[i] = kSettled;
    }
    for (const std::uint32_t i : changed_) changed_mark_[i] = 0;
    changed_.clear();
  }
  /// The pair events since the last update (allocates the two lists).
  PairEvents update() {
    PairEvents e;
    update(e);
    return e;
  }

  /// Calls f(ProxyId) for every partner of id at the last update. Errors: InvalidProxy.
  template <class F>
  void for_each_partner(ProxyId id, F&& f) const {
    if (!bp_.contains(id))
      throw BroadphaseError(BroadphaseErrc::InvalidProxy, "proxy handle is stale or was never issued");
    for (const std::uint32_t o : partners_[id.index]) f(ids_[o]);
  }
  /// The structure, for queries and raycasts.
  const BP& structure() const noexcept { return bp_; }

 private:
  /// The structure keeps fat boxes and can tell who left theirs (DynamicTree).
  static constexpr bool kFat = requires(BP & b, const BP& cb, ProxyId id, const Aabb<T>& box) {
    { b.move_fat(id, box) } -> std::same_as<bool>;
    cb.query_fat(id, [](ProxyId) {});
    cb.for_each_fat_pair([](ProxyId, ProxyId) {});
  };
  /// Below this many new proxies (or new fat boxes) the per-proxy paths are cheaper than a tree
  /// rebuild or a walk of every pair.
  static constexpr std::size_t kRebuildMin = 1024;

  void grow(std::uint32_t i) {
    if (i >= ids_.size()) {
      ids_.resize(std::size_t(i) + 1);
      partners_.resize(std::size_t(i) + 1);
      changed_mark_.resize(std::size_t(i) + 1, 0);
      if constexpr (kFat) {
        near_.resize(std::size_t(i) + 1);
        refat_.resize(std::size_t(i) + 1, 0);
      }
    }
  }

  /// Re-queries the fat-box neighbours of every proxy that got a new fat box, on both sides.
  /// Runs before any pair is decided, so every neighbour list is current when it is read. When a
  /// large share of the proxies got one (the first update of a full world), one walk of every
  /// pair of fat boxes refills all the lists instead of a query per proxy.
  void refresh_fat_neighbours() {
    std::size_t refat = 0;
    for (const std::uint32_t i : changed_) refat += refat_[i] ? 1U : 0U;
    if (refat >= kRebuildMin && 4 * refat >= bp_.size()) {
      for (std::vector<std::uint32_t>& n : near_) n.clear();
      bp_.for_each_fat_pair([&](ProxyId a, ProxyId b) {
        near_[a.index].push_back(b.index);
        near_[b.index].push_back(a.index);
      });
      for (std::vector<std::uint32_t>& n : near_) std::sort(n.begin(), n.end());
      for (const std::uint32_t i : changed_) refat_[i] = 0;
      return;
    }
    for (const std::uint32_t i : changed_) {
      if (!refat_[i] || !bp_.contains(ids_[i])) continue;
      refat_[i] = 0;
      found_.clear();
      bp_.query_fat(ids_[i], [&](ProxyId o) { found_.push_back(o.index); });
      std::sort(found_.begin(), found_.end());
      const std::vector<std::uint32_t>& was = near_[i];
      std::size_t a = 0, b = 0;
      while (a < found_.size() || b < was.size()) {
        if (b == was.size() || (a < found_.size() && found_[a] < was[b])) {
          insert_sorted(near_[found_[a++]], i);
        } else if (a == found_.size() || was[b] < found_[a]) {
          erase_sorted(near_[was[b++]], i);
        } else {
          ++a, ++b;
        }
      }
      near_[i].assign(found_.begin(), found_.end());
    }
  }
  /// changed_mark_ values: not changed, changed, changed and handled in the running update.
  static constexpr char kChanged = 1, kSettled = 2;

  void mark(std::uint32_t i) {
    if (!changed_mark_[i]) {
      changed_mark_[i] = kChanged;
      changed_.push_back(i);
    }
  }
  static void erase_sorted(std::vector<std::uint32_t>& v, std::uint32_t x) {
    const auto it = std::lower_bound(v.begin(), v.end(), x);
    if (it != v.end() && *it == x) v.erase(it);
  }
  static void insert_sorted(std::vector<std::uint32_t>& v, std::uint32_t x) {
    const auto it = std::lower_bound(v.begin(), v.end(), x);
    if (it == v.end() || *it != x) v.insert(it, x);
  }

  /// Compares found_ (partners now) with partners_[i] (at the last update), both sorted, and
  /// reports the difference. A partner that changed too and was handled earlier in this update
  /// has already settled this pair from its side.
  void diff(std::uint32_t i, PairEvents& out) {
    const std::vector<std::uint32_t>& was = partners_[i];
    std::size_t a = 0, b = 0;
    const auto settled = [&](std::uint32_t o) { return changed_mark_[o] == kSettled; };
    while (a < found_.size() || b < was.size()) {
      if (b == was.size() || (a < found_.size() && found_[a] < was[b])) {
        const std::uint32_t o = found_[a++];
        if (settled(o)) continue;
        out.began.push_back(ordered_pair(ids_[i], ids_[o]));
        insert_sorted(partners_[o], i);
      } else if (a == found_.size() || was[b] < found_[a]) {
        const std::uint32_t o = was[b++];
        if (settled(o)) continue;
        out.ended.push_back(ordered_pair(ids_[i], ids_[o]));
        erase_sorted(partners_[o], i);
      } else {
        ++a, ++b;
      }
    }
  }

  BP bp_;
  std::vector<ProxyId> ids_;                          ///< current handle of each slot
  std::vector<std::vector<std::uint32_t>> partners_;  ///< sorted partner slots at the last update
  std::vector<std::uint32_t> changed_;                ///< slots added, moved or re-filtered since
  std::vector<char> changed_mark_;
  std::vector<std::uint32_t> found_;              ///< scratch: partners now
  std::vector<ProxyPair> pending_ended_;          ///< pairs ended by removals
  std::vector<std::vector<std::uint32_t>> near_;  ///< DynamicTree only: sorted fat-box neighbours
  std::vector<char> refat_;                       ///< DynamicTree only: got a new fat box since
  std::size_t added_ = 0;                         ///< proxies added less those removed since the last rebuild
};

}  // namespace collide::broadphase
