#pragma once
/// @file broadphase/sweep.hpp
/// Sort and sweep (sweep and prune) on the x axis: proxies are kept in an array sorted by min.x,
/// followed by a short unsorted tail of recent additions. A move shifts its entry to its new
/// place (cheap for coherent motion; a long jump moves it to the tail instead); the tail is merged
/// in when it outgrows a fraction of the array, and removed entries are compacted away when they
/// are half of it. Every mutation leaves the order valid, so const queries only read.

#include "collide/broadphase/common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace collide::broadphase {

/// Sort-and-sweep broadphase over closed boxes of scalar T. Boxes are not fattened.
/// Const members are re-entrant and may run on many threads at once (see ProxyOps).
template <Scalar T>
class SweepAndPrune : public ProxyOps<SweepAndPrune<T>, T> {
 public:
  using ProxyOps<SweepAndPrune<T>, T>::raycast;
  /// An empty structure.
  SweepAndPrune() = default;

  /// Calls f(ProxyId) for every proxy whose box meets q (closed) and whose filter accepts
  /// `filter`; f may return false to stop.
  template <class F>
  void query(const Aabb<T>& q, F&& f, Filter filter = Filter::everything()) const {
    const Box<T> b = box_of(q);
    visit_range(widen(b.min), widen(b.max), [&](const Entry& e) {
      const auto& s = slots_[e.slot];
      if (!boxes_overlap(s.box, b) || !accepts(s.filter, filter)) return true;
      return call_continue(f, slots_.id(e.slot));
    });
  }

  /// Calls f(ProxyId, t) for every proxy whose box meets the segment origin + t direction,
  /// t in [0, max_t] (t = entry parameter), and whose filter accepts `filter`. Errors: BadRay.
  template <class F>
  void raycast(const Vec2<T>& origin, const Vec2<T>& direction, T max_t, F&& f,
               Filter filter = Filter::everything()) const {
    const RaySegment<T> r = make_ray(origin, direction, max_t);
    const auto [lo, hi] = ray_bounds(r);
    visit_range(lo, hi, [&](const Entry& e) {
      const auto& s = slots_[e.slot];
      if (!accepts(s.filter, filter)) return true;
      const Calc t = ray_hits_box(r, s.box);
      return t < 0 || call_continue(f, slots_.id(e.slot), t);
    });
  }

  /// Calls f(ProxyId a, ProxyId b) once for every pair of proxies whose boxes overlap (closed) and
  /// whose filters accept each other; f may return bool, false stops. Builds no list of pairs;
  /// while additions are pending (see flush()) it sweeps a sorted copy of the entries.
  template <class F>
  void for_each_pair(F&& f) const {
    if (sorted_ == entries_.size()) {
      sweep_pairs(entries_.data(), entries_.size(), f);
      return;
    }
    std::vector<Entry> all(entries_.begin(), entries_.end());
    const auto mid = all.begin() + std::ptrdiff_t(sorted_);
    std::sort(mid, all.end(), by_min_x);
    std::inplace_merge(all.begin(), mid, all.end(), by_min_x);
    sweep_pairs(all.data(), all.size(), f);
  }

  /// Merges the tail of recent additions and drops removed entries, so that queries scan only
  /// the sorted array. Optional: every query is correct without it, but until then each query
  /// also scans the pending additions (up to an eighth of the proxies); call it after a batch of
  /// additions. PairTracker::update() calls it.
  void flush() {
    if (dead_ > 0) compact();
    merge_tail();
  }

 private:
  friend class ProxyOps<SweepAndPrune<T>, T>;
  static constexpr std::uint32_t kDead = 0xffffffffu;
  /// A move that would shift its entry farther than this goes to the tail instead.
  static constexpr std::size_t kMaxShift = 64;
  struct Entry {
    T min_x, max_x, min_y, max_y;
    std::uint32_t slot;
  };
  struct Extra {
    std::uint32_t pos = 0;
  };

  void unlink(std::uint32_t s) {
    entries_[slots_[s].extra.pos].slot = kDead;
    ++dead_;
    keep_tidy();
  }

  /// Amortised upkeep: compacts when half the entries are dead, merges the tail when it outgrows
  /// an eighth of the sorted part (so a query scans at most that many unsorted entries).
  void keep_tidy() {
    if (dead_ > 32 && dead_ * 2 > entries_.size()) compact();
    if (entries_.size() - sorted_ > 32 + sorted_ / 8) merge_tail();
  }

  ProxyId add_box(const Box<T>& b, std::uint64_t user, Filter filter) {
    const ProxyId id = slots_.allocate(b, user, filter);
    append(b, id.index);
    keep_tidy();
    return id;
  }

  void move_box(ProxyId id, const Box<T>& b) {
    const std::uint32_t s = slots_.check(id);
    slots_[s].box = b;
    std::size_t p = slots_[s].extra.pos;
    const Entry e = entry_of(b, s);
    max_width_ = std::max(max_width_, width(e));
    if (p >= sorted_) {
      entries_[p] = e;
      return;
    }
    // Shift the entry to its place in the sorted part, or send it to the tail if that is far.
    // Coherent motion moves an entry a few places: its neighbours tell, without a search.
    std::size_t target = p;
    while (target > 0 && e.min_x < entries_[target - 1].min_x && p - target <= kMaxShift) --target;
    while (target + 1 < sorted_ && entries_[target + 1].min_x < e.min_x && target - p <= kMaxShift) ++target;
    if ((target > p ? target - p : p - target) > kMaxShift) {
      entries_[p].slot = kDead;
      ++dead_;
      append(b, s);
      keep_tidy();
      return;
    }
    while (p > 0 && e.min_x < entries_[p - 1].min_x) place(p, entries_[p - 1]), --p;
    while (p + 1 < sorted_ && entries_[p + 1].min_x < e.min_x) place(p, entries_[p + 1]), ++p;
    place(p, e);
  }

  static bool by_min_x(const Entry& x, const Entry& y) noexcept { return x.min_x < y.min_x; }

  /// The sweep over n entries sorted by min_x (dead entries skipped).
  template <class F>
  void sweep_pairs(const Entry* e, std::size_t n, F& f) const {
    for (std::size_t i = 0; i < n; ++i) {
      const Entry& a = e[i];
      if (a.slot == kDead) continue;
      for (std::size_t j = i + 1; j < n; ++j) {
        const Entry& b = e[j];
        if (b.min_x > a.max_x) break;
        if (b.slot == kDead || b.min_y > a.max_y || a.min_y > b.max_y) continue;
        if (!accepts(slots_[a.slot].filter, slots_[b.slot].filter)) continue;
        if (!call_continue(f, slots_.id(a.slot), slots_.id(b.slot))) return;
      }
    }
  }

  static Entry entry_of(const Box<T>& b, std::uint32_t slot) noexcept {
    return {b.min.x(), b.max.x(), b.min.y(), b.max.y(), slot};
  }
  static Calc width(const Entry& e) noexcept { return Calc(e.max_x) - Calc(e.min_x); }

  /// Writes e at position p and refreshes the position its slot records.
  void place(std::size_t p, const Entry& e) noexcept {
    entries_[p] = e;
    if (e.slot != kDead) slots_[e.slot].extra.pos = static_cast<std::uint32_t>(p);
  }

  void append(const Box<T>& b, std::uint32_t s) {
    const Entry e = entry_of(b, s);
    slots_[s].extra.pos = static_cast<std::uint32_t>(entries_.size());
    entries_.push_back(e);
    max_width_ = std::max(max_width_, width(e));
  }

  /// Drops removed entries (keeping the order) and recomputes the widest box.
  void compact() {
    std::size_t w = 0, sorted = 0;
    Calc widest = 0;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      if (entries_[i].slot == kDead) continue;
      if (i < sorted_) ++sorted;
      widest = std::max(widest, width(entries_[i]));
      place(w++, entries_[i]);
    }
    entries_.resize(w);
    sorted_ = sorted;
    dead_ = 0;
    max_width_ = widest;
  }

  /// Sorts the tail and merges it into the sorted part.
  void merge_tail() {
    if (sorted_ == entries_.size()) return;
    const auto mid = entries_.begin() + std::ptrdiff_t(sorted_);
    std::sort(mid, entries_.end(), by_min_x);
    std::inplace_merge(entries_.begin(), mid, entries_.end(), by_min_x);
    for (std::size_t i = 0; i < entries_.size(); ++i) place(i, entries_[i]);
    sorted_ = entries_.size();
  }

  /// Calls f(entry) for every live entry whose x interval may meet [lo.x, hi.x] and whose y
  /// interval meets [lo.y, hi.y]; stops when f returns false.
  template <class F>
  void visit_range(const Vec2c& lo, const Vec2c& hi, F&& f) const {
    const auto near = [&](const Entry& e) {
      return e.slot != kDead && !(Calc(e.max_x) < lo.x() || Calc(e.max_y) < lo.y() || Calc(e.min_y) > hi.y());
    };
    // No entry starting before lo.x - max_width can reach lo.x (nextafter covers the rounding).
    const Calc start =
        std::nextafter(lo.x() - max_width_ * (1 + kSweepWidthSlack), -std::numeric_limits<Calc>::infinity());
    const auto end = entries_.begin() + std::ptrdiff_t(sorted_);
    auto it = std::lower_bound(entries_.begin(), end, start, [](const Entry& e, Calc v) { return Calc(e.min_x) < v; });
    for (; it != end && Calc(it->min_x) <= hi.x(); ++it)
      if (near(*it) && !f(*it)) return;
    for (it = end; it != entries_.end(); ++it)
      if (Calc(it->min_x) <= hi.x() && near(*it) && !f(*it)) return;
  }

  Slots<T, Extra> slots_;
  std::vector<Entry> entries_;  ///< [0, sorted_) ascending by min_x, then the tail in add order
  std::size_t sorted_ = 0;
  std::size_t dead_ = 0;  ///< entries of removed proxies (or moved to the tail), slot == kDead
  Calc max_width_ = 0;    ///< at least the x extent of every live entry
};

}  // namespace collide::broadphase
