#pragma once
/// @file broadphase/grid.hpp
/// Uniform grid as a spatial hash: each proxy is listed in every cell its box covers; a proxy
/// covering more than kMaxCellsPerProxy cells, or lying beyond the hashed index range, goes to
/// an "oversized" list tested against everything. A pair (or a query hit) is reported only in
/// the cell holding the lower-left corner of the two boxes' intersection, so each exactly once.

#include "collide/broadphase/common.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace collide::broadphase {

/// Spatial-hash grid broadphase over closed boxes of scalar T. Boxes are not fattened.
/// Const members are re-entrant and may run on many threads at once (see ProxyOps).
template <Scalar T>
class UniformGrid : public ProxyOps<UniformGrid<T>, T> {
 public:
  using ProxyOps<UniformGrid<T>, T>::raycast;
  /// A proxy covering more cells than this is kept in the oversized list instead.
  static constexpr std::int64_t kMaxCellsPerProxy = 64;
  /// A query covering more cells than this scans every proxy instead.
  static constexpr std::int64_t kMaxCellsPerQuery = 4096;
  /// Cell indices beyond +-kMaxIndex are not hashed (the proxy goes to the oversized list).
  static constexpr Calc kMaxIndex = 0x1p30;

  /// cell_size: edge of a square cell, world units; a size near the typical box size works
  /// best. Errors: BadCellSize.
  explicit UniformGrid(T cell_size = T(1)) : cell_(cell_size) {
    if (!(cell_size > T(0)) || !std::isfinite(cell_size))
      throw BroadphaseError(BroadphaseErrc::BadCellSize, "cell size must be positive and finite");
  }

  /// Calls f(ProxyId) for every proxy whose box meets q (closed) and whose filter accepts
  /// `filter`; f may return false to stop.
  template <class F>
  void query(const Aabb<T>& q, F&& f, Filter filter = Filter::everything()) const {
    const Box<T> b = box_of(q);
    visit_range(widen(b.min), widen(b.max), [&](std::uint32_t s) {
      if (!boxes_overlap(slots_[s].box, b) || !accepts(slots_[s].filter, filter)) return true;
      return call_continue(f, slots_.id(s));
    });
  }

  /// Calls f(ProxyId, t) for every proxy whose box meets the segment origin + t direction,
  /// t in [0, max_t] (t = entry parameter), and whose filter accepts `filter`. Errors: BadRay.
  template <class F>
  void raycast(const Vec2<T>& origin, const Vec2<T>& direction, T max_t, F&& f,
               Filter filter = Filter::everything()) const {
    const RaySegment<T> r = make_ray(origin, direction, max_t);
    const auto [lo, hi] = ray_bounds(r);
    visit_range(lo, hi, [&](std::uint32_t s) {
      if (!accepts(slots_[s].filter, filter)) return true;
      const Calc t = ray_hits_box(r, slots_[s].box);
      return t < 0 || call_continue(f, slots_.id(s), t);
    });
  }

  /// Calls f(ProxyId a, ProxyId b) once for every pair of proxies whose boxes overlap (closed) and
  /// whose filters accept each other; f may return bool, false stops. Builds no list.
  template <class F>
  void for_each_pair(F&& f) const {
    const auto report = [&](std::uint32_t x, std::uint32_t y) {
      if (!accepts(slots_[x].filter, slots_[y].filter)) return true;
      return call_continue(f, slots_.id(x), slots_.id(y));
    };
    for (const auto& [key, list] : cells_) {
      const std::int64_t cx = key_x(key), cy = key_y(key);
      for (std::size_t i = 0; i < list.size(); ++i) {
        const Box<T>& a = slots_[list[i]].box;
        for (std::size_t j = i + 1; j < list.size(); ++j) {
          const Box<T>& b = slots_[list[j]].box;
          if (!boxes_overlap(a, b)) continue;
          if (cell_of(std::max(Calc(a.min.x()), Calc(b.min.x()))) != cx ||
              cell_of(std::max(Calc(a.min.y()), Calc(b.min.y()))) != cy)
            continue;  // reported in the cell of the intersection's lower-left corner
          if (!report(list[i], list[j])) return;
        }
      }
    }
    for (const std::uint32_t o : oversized_) {
      for (std::uint32_t s = 0; s < slots_.capacity(); ++s) {
        if (!slots_[s].live || s == o) continue;
        if (slots_[s].extra.oversized && s < o) continue;  // that pair is found from s
        if (boxes_overlap(slots_[o].box, slots_[s].box) && !report(o, s)) return;
      }
    }
  }

 private:
  friend class ProxyOps<UniformGrid<T>, T>;
  struct Extra {
    std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    bool oversized = false;
    std::uint32_t oversized_pos = 0;
  };
  struct Range {
    std::int64_t x0, y0, x1, y1;
    bool ok;  ///< representable and small enough to list cell by cell
  };

  std::int64_t cell_of(Calc v) const noexcept { return static_cast<std::int64_t>(std::floor(v / Calc(cell_))); }
  Range range_of(const Vec2c& lo, const Vec2c& hi, std::int64_t max_cells) const noexcept {
    const Calc c = cell_;
    const Calc fx0 = std::floor(lo.x() / c), fy0 = std::floor(lo.y() / c);
    const Calc fx1 = std::floor(hi.x() / c), fy1 = std::floor(hi.y() / c);
    if (!(std::fabs(fx0) <= kMaxIndex && std::fabs(fy0) <= kMaxIndex && std::fabs(fx1) <= kMaxIndex &&
          std::fabs(fy1) <= kMaxIndex))
      return {0, 0, -1, -1, false};
    const Range r{std::int64_t(fx0), std::int64_t(fy0), std::int64_t(fx1), std::int64_t(fy1), true};
    const bool small = (r.x1 - r.x0 + 1) * (r.y1 - r.y0 + 1) <= max_cells;
    return {r.x0, r.y0, r.x1, r.y1, small};
  }
  static std::uint64_t key_of(std::int64_t x, std::int64_t y) noexcept {
    return (std::uint64_t(std::uint32_t(std::int32_t(x))) << 32) | std::uint32_t(std::int32_t(y));
  }
  static std::int64_t key_x(std::uint64_t k) noexcept { return std::int32_t(std::uint32_t(k >> 32)); }
  static std::int64_t key_y(std::uint64_t k) noexcept { return std::int32_t(std::uint32_t(k)); }

  ProxyId add_box(const Box<T>& b, std::uint64_t user, Filter filter) {
    const ProxyId id = slots_.allocate(b, user, filter);
    link(id.index);
    return id;
  }
  void move_box(ProxyId id, const Box<T>& b) {
    const std::uint32_t s = slots_.check(id);
    const Range r = range_of(widen(b.min), widen(b.max), kMaxCellsPerProxy);
    const Extra& e = slots_[s].extra;
    slots_[s].box = b;
    if (r.ok && !e.oversized && r.x0 == e.x0 && r.y0 == e.y0 && r.x1 == e.x1 && r.y1 == e.y1) return;
    unlink(s);
    link(s);
  }

  void link(std::uint32_t s) {
    auto& slot = slots_[s];
    const Range r = range_of(widen(slot.box.min), widen(slot.box.max), kMaxCellsPerProxy);
    if (!r.ok) {
      slot.extra = Extra{};
      slot.extra.oversized = true;
      slot.extra.oversized_pos = static_cast<std::uint32_t>(oversized_.size());
      oversized_.push_back(s);
      return;
    }
    slot.extra = Extra{r.x0, r.y0, r.x1, r.y1, false, 0};
    for (std::int64_t x = r.x0; x <= r.x1; ++x)
      for (std::int64_t y = r.y0; y <= r.y1; ++y) cells_[key_of(x, y)].push_back(s);
  }
  void unlink(std::uint32_t s) {
    const Extra e = slots_[s].extra;
    if (e.oversized) {
      const std::uint32_t last = oversized_.back();
      oversized_[e.oversized_pos] = last;
      slots_[last].extra.oversized_pos = e.oversized_pos;
      oversized_.pop_back();
      return;
    }
    for (std::int64_t x = e.x0; x <= e.x1; ++x) {
      for (std::int64_t y = e.y0; y <= e.y1; ++y) {
        const auto it = cells_.find(key_of(x, y));
        if (it == cells_.end()) continue;
        auto& list = it->second;
        for (std::size_t i = 0; i < list.size(); ++i) {
          if (list[i] == s) {
            list[i] = list.back();
            list.pop_back();
            break;
          }
        }
        if (list.empty()) cells_.erase(it);
      }
    }
  }

  /// Calls f(slot) once for every proxy that may meet [lo, hi]; stops when f returns false.
  template <class F>
  void visit_range(const Vec2c& lo, const Vec2c& hi, F&& f) const {
    const Range r = range_of(lo, hi, kMaxCellsPerQuery);
    if (!r.ok) {
      for (std::uint32_t s = 0; s < slots_.capacity(); ++s)
        if (slots_[s].live && !f(s)) return;
      return;
    }
    for (std::int64_t x = r.x0; x <= r.x1; ++x) {
      for (std::int64_t y = r.y0; y <= r.y1; ++y) {
        const auto it = cells_.find(key_of(x, y));
        if (it == cells_.end()) continue;
        for (const std::uint32_t s : it->second) {
          const Box<T>& b = slots_[s].box;
          // Visit once: in the cell of the lower-left corner of (query range ∩ box), clamped.
          const Calc cx = std::max(lo.x(), Calc(b.min.x())), cy = std::max(lo.y(), Calc(b.min.y()));
          if (std::clamp(cell_of(cx), r.x0, r.x1) != x || std::clamp(cell_of(cy), r.y0, r.y1) != y) continue;
          if (!f(s)) return;
        }
      }
    }
    for (const std::uint32_t s : oversized_)
      if (!f(s)) return;
  }

  T cell_;
  Slots<T, Extra> slots_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> oversized_;
};

}  // namespace collide::broadphase
