#pragma once
/// @file broadphase/sweep.hpp
/// Sort and sweep (sweep and prune) on the x axis: proxies are kept in an array sorted by min.x;
/// after coherent motion the array is nearly sorted and an insertion sort restores it in about
/// linear time. The sweep reports a pair when the x intervals overlap and then checks y.

#include "collide/broadphase/common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace collide::broadphase {

/// Sort-and-sweep broadphase over closed boxes of scalar T. Boxes are not fattened.
template <Scalar T>
class SweepAndPrune : public ProxyOps<SweepAndPrune<T>, T> {
 public:
  using ProxyOps<SweepAndPrune<T>, T>::raycast;
  SweepAndPrune() = default;

  /// Calls f(ProxyId) for every proxy whose box meets q (closed); f may return false to stop.
  template <class F>
  void query(const Aabb<T>& q, F&& f) const {
    const Box<T> b = box_of(q);
    visit_range(widen(b.min), widen(b.max), [&](const Entry& e) {
      if (!boxes_overlap(slots_[e.slot].box, b)) return true;
      return call_continue(f, slots_.id(e.slot));
    });
  }

  /// Calls f(ProxyId, t) for every proxy whose box meets the segment origin + t direction,
  /// t in [0, max_t] (t = entry parameter). Errors: BadRay.
  template <class F>
  void raycast(const Vec2<T>& origin, const Vec2<T>& direction, T max_t, F&& f) const {
    const RaySegment<T> r = make_ray(origin, direction, max_t);
    const auto [lo, hi] = ray_bounds(r);
    visit_range(lo, hi, [&](const Entry& e) {
      const Calc t = ray_hits_box(r, slots_[e.slot].box);
      return t < 0 || call_continue(f, slots_.id(e.slot), t);
    });
  }

  /// Every pair of proxies whose boxes overlap (closed), each once, a.index < b.index.
  std::vector<ProxyPair> pairs(PairOrder order = PairOrder::Any) const {
    restore_order();
    std::vector<ProxyPair> out;
    const std::size_t n = entries_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Entry& a = entries_[i];
      for (std::size_t j = i + 1; j < n; ++j) {
        const Entry& b = entries_[j];
#if defined(COLLIDE_BROADPHASE_PLANTED_FAULT) && COLLIDE_BROADPHASE_PLANTED_FAULT == 1
        // Planted fault 1 (tests only): stops at touching x intervals, so touching pairs are lost.
        if (b.min_x >= a.max_x) break;
#else
        if (b.min_x > a.max_x) break;
#endif
        if (b.min_y <= a.max_y && a.min_y <= b.max_y) out.push_back(ordered_pair(slots_.id(a.slot), slots_.id(b.slot)));
      }
    }
    finish_pairs(out, order);
    return out;
  }

 private:
  friend class ProxyOps<SweepAndPrune<T>, T>;
  void unlink(std::uint32_t s) {
    entries_[slots_[s].extra.pos].slot = kDead;
    ++dead_;
  }
  static constexpr std::uint32_t kDead = 0xffffffffu;
  struct Entry {
    T min_x, max_x, min_y, max_y;
    std::uint32_t slot;
  };
  struct Extra {
    std::uint32_t pos = 0;
  };

  ProxyId add_box(const Box<T>& b, std::uint64_t user) {
    const ProxyId id = slots_.allocate(b, user);
    slots_[id.index].extra.pos = static_cast<std::uint32_t>(entries_.size());
    entries_.push_back(entry_of(b, id.index));
    ++unsorted_;
    return id;
  }
  void move_box(ProxyId id, const Box<T>& b) {
    const std::uint32_t s = slots_.check(id);
    slots_[s].box = b;
    entries_[slots_[s].extra.pos] = entry_of(b, s);
    ++unsorted_;
  }
  static Entry entry_of(const Box<T>& b, std::uint32_t slot) noexcept {
    return {b.min.x(), b.max.x(), b.min.y(), b.max.y(), slot};
  }

  /// Drops removed entries and restores the order by min.x: insertion sort for nearly sorted
  /// input (coherent motion), a full sort when many entries changed or the insertion sort runs
  /// over its budget.
  void restore_order() const {
    if (dead_ == 0 && unsorted_ == 0) return;
    if (dead_ > 0) {
      entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [](const Entry& e) { return e.slot == kDead; }),
                     entries_.end());
      dead_ = 0;
    }
    const auto less = [](const Entry& a, const Entry& b) { return a.min_x < b.min_x; };
    const std::size_t n = entries_.size();
    bool sorted = false;
    if (unsorted_ * 8 <= n + 64) {
      std::size_t budget = 8 * n + 1024;
      sorted = true;
      for (std::size_t i = 1; i < n && sorted; ++i) {
        const Entry e = entries_[i];
        std::size_t j = i;
        while (j > 0 && less(e, entries_[j - 1])) {
          entries_[j] = entries_[j - 1];
          --j;
          if (--budget == 0) {
            sorted = false;
            break;
          }
        }
        entries_[j] = e;
      }
    }
    if (!sorted) std::sort(entries_.begin(), entries_.end(), less);
    Calc w = 0;
    for (std::size_t i = 0; i < n; ++i) {
      slots_[entries_[i].slot].extra.pos = static_cast<std::uint32_t>(i);
      w = std::max(w, Calc(entries_[i].max_x) - Calc(entries_[i].min_x));
    }
    max_width_ = w;
    unsorted_ = 0;
  }

  /// Calls f(entry) for every entry whose x interval may meet [lo.x, hi.x] and whose y interval
  /// meets [lo.y, hi.y]; stops when f returns false.
  template <class F>
  void visit_range(const Vec2c& lo, const Vec2c& hi, F&& f) const {
    restore_order();
    // No entry starting before lo.x - max_width can reach lo.x (nextafter covers the rounding).
    const Calc start = std::nextafter(lo.x() - max_width_ * (1 + 0x1p-40), -std::numeric_limits<Calc>::infinity());
    auto it = std::lower_bound(entries_.begin(), entries_.end(), start,
                               [](const Entry& e, Calc v) { return Calc(e.min_x) < v; });
    for (; it != entries_.end() && Calc(it->min_x) <= hi.x(); ++it) {
      if (Calc(it->max_x) < lo.x() || Calc(it->max_y) < lo.y() || Calc(it->min_y) > hi.y()) continue;
      if (!f(*it)) return;
    }
  }

  mutable Slots<T, Extra> slots_;  // mutable: restore_order() refreshes each slot's position
  mutable std::vector<Entry> entries_;
  mutable std::size_t unsorted_ = 0;
  mutable std::size_t dead_ = 0;
  mutable Calc max_width_ = 0;
};

}  // namespace collide::broadphase
