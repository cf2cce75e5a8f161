#pragma once
/// @file broadphase/common.hpp
/// What the three broadphase structures share: proxy handles, the named errors, the exact closed
/// box test, the ray-box test, the slot table that owns stored boxes and user data, and the
/// pair list type.

#include "collide/config.hpp"
#include "collide/error.hpp"
#include "collide/ray.hpp"
#include "collide/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace collide::broadphase {

/// Why a broadphase call was refused.
enum class BroadphaseErrc : std::uint8_t {
  InvalidProxy,    ///< the handle was never issued by this structure, or its proxy was removed
  BadBox,          ///< a box given as raw corners is NaN, infinite, out of range or inverted
  BadMargin,       ///< fattening margin is negative, NaN, infinite or above max_magnitude<T>()
  BadCellSize,     ///< grid cell size is not a positive finite value
  BadRay,          ///< ray origin/direction/length is NaN or infinite, or the length is negative
  TooManyProxies,  ///< more than 2^32 - 2 live proxies
  BadPair,         ///< a candidate pair names a shape beyond its list, or the lists differ in length
  Reentered,       ///< a Narrowphase called from the callback of its own running batch
  ChainMoved       ///< a World's chain segment body given a transform: chain segments stay where they were added
};

/// Stable name of a broadphase error, e.g. "InvalidProxy".
constexpr std::string_view name(BroadphaseErrc e) noexcept {
  switch (e) {
    case BroadphaseErrc::InvalidProxy:
      return "InvalidProxy";
    case BroadphaseErrc::BadBox:
      return "BadBox";
    case BroadphaseErrc::BadMargin:
      return "BadMargin";
    case BroadphaseErrc::BadCellSize:
      return "BadCellSize";
    case BroadphaseErrc::BadRay:
      return "BadRay";
    case BroadphaseErrc::TooManyProxies:
      return "TooManyProxies";
    case BroadphaseErrc::BadPair:
      return "BadPair";
    case BroadphaseErrc::Reentered:
      return "Reentered";
    case BroadphaseErrc::ChainMoved:
      return "ChainMoved";
  }
  return "Unknown";
}

/// Thrown by every broadphase operation that refuses its input; the structure is left unchanged.
class BroadphaseError : public std::invalid_argument {
 public:
  /// The named reason and a short account ("<name>: <what>").
  BroadphaseError(BroadphaseErrc code, std::string_view what)
      : std::invalid_argument(std::string(name(code)) + ": " + std::string(what)), code_(code) {}
  /// Why the call was refused.
  BroadphaseErrc code() const noexcept { return code_; }

 private:
  BroadphaseErrc code_;
};

/// Handle of one proxy. A removed proxy's slot may be reused, but with a new generation, so an
/// old handle is detected (InvalidProxy) instead of silently naming the new proxy.
struct ProxyId {
  std::uint32_t index = std::numeric_limits<std::uint32_t>::max();  ///< the slot
  std::uint32_t generation = 0;  ///< the slot's use: a reused slot has a new generation
  /// Field-wise equality.
  friend constexpr bool operator==(const ProxyId&, const ProxyId&) = default;
  /// Field-wise order (a total order of handles).
  friend constexpr auto operator<=>(const ProxyId&, const ProxyId&) = default;
};

/// One overlapping pair, reported once, with a.index < b.index.
struct ProxyPair {
  ProxyId a;  ///< the proxy with the smaller index
  ProxyId b;  ///< the other proxy
  /// Field-wise equality.
  friend constexpr bool operator==(const ProxyPair&, const ProxyPair&) = default;
  /// Field-wise order (a total order of handles).
  friend constexpr auto operator<=>(const ProxyPair&, const ProxyPair&) = default;
};

/// Collision filter of a proxy (or of a query): a pair (or a hit) is reported only when
/// `(a.category & b.mask) != 0 && (b.category & a.mask) != 0`. A proxy whose category or mask is
/// 0 is never reported by anything.
struct Filter {
  std::uint32_t category = 1;        ///< which groups this proxy belongs to (bits)
  std::uint32_t mask = 0xffffffffu;  ///< which groups this proxy pairs with (bits)
  /// The filter that accepts every proxy with a non-zero category and mask (queries' default).
  static constexpr Filter everything() noexcept { return {0xffffffffu, 0xffffffffu}; }
  /// Same category and mask.
  friend constexpr bool operator==(const Filter&, const Filter&) = default;
};

/// The pairing rule of two filters (symmetric).
constexpr bool accepts(Filter a, Filter b) noexcept {
  return (a.category & b.mask) != 0 && (b.category & a.mask) != 0;
}

/// A proxy met by a ray: the handle and the entry parameter t (units of |direction|).
struct ProxyHit {
  ProxyId id;  ///< the proxy
  Calc t = 0;  ///< entry parameter, 0 <= t <= max_t
};

/// Order of the pair list: Any is whatever the structure finds fastest; Sorted is ascending by
/// (a.index, b.index), identical across structures and runs.
enum class PairOrder : std::uint8_t { Any, Sorted };

/// Plain box corners, the form the structures store (no invariant beyond what the slot table
/// checked on the way in).
template <Scalar T>
struct Box {
  Vec2<T> min = Vec2<T>::Zero();  ///< lower-left corner
  Vec2<T> max = Vec2<T>::Zero();  ///< upper-right corner
};

/// Closed-box overlap: touching (equal coordinates) counts. Exact (comparisons only).
template <Scalar T>
inline bool boxes_overlap(const Box<T>& a, const Box<T>& b) noexcept {
  return a.min.x() <= b.max.x() && b.min.x() <= a.max.x() && a.min.y() <= b.max.y() && b.min.y() <= a.max.y();
}

/// True when `outer` contains `inner` (closed).
template <Scalar T>
inline bool box_contains(const Box<T>& outer, const Box<T>& inner) noexcept {
  return outer.min.x() <= inner.min.x() && outer.min.y() <= inner.min.y() && inner.max.x() <= outer.max.x() &&
         inner.max.y() <= outer.max.y();
}

/// The corners of a validated box.
template <Scalar T>
inline Box<T> box_of(const Aabb<T>& a) noexcept {
  return {a.min(), a.max()};
}

/// The box grown by margin on every side. Subtracting a non-negative value never rounds up, so
/// the result always contains the input.
template <Scalar T>
inline Box<T> fattened(const Box<T>& b, T margin) noexcept {
  return {(b.min.array() - margin).matrix(), (b.max.array() + margin).matrix()};
}

/// A segment from origin along direction, parameter t in [0, max_t] (t = 1 is origin + direction).
/// Every structure decides with ray_hits_box(), so all three report the same proxies.
template <Scalar T>
struct RaySegment {
  Vec2c origin;     ///< where the segment starts (t = 0)
  Vec2c direction;  ///< step per unit of t
  Calc max_t;       ///< where the segment ends
};

/// Validates and widens a ray. Errors: BadRay.
template <Scalar T>
inline RaySegment<T> make_ray(const Vec2<T>& origin, const Vec2<T>& direction, T max_t) {
  const bool finite = std::isfinite(origin.x()) && std::isfinite(origin.y()) && std::isfinite(direction.x()) &&
                      std::isfinite(direction.y()) && std::isfinite(max_t);
  if (!finite) throw BroadphaseError(BroadphaseErrc::BadRay, "ray has a NaN or infinite value");
  if (max_t < T(0)) throw BroadphaseError(BroadphaseErrc::BadRay, "ray length is negative");
  return {widen(origin), widen(direction), Calc(max_t)};
}

/// (x - o) / d with the sign of the exact quotient: a quotient that underflows to zero becomes the
/// smallest subnormal of its sign. Without this a box 1e-288 beside a ray whose direction is
/// 1e231 long gave a slab crossed at t = -1e-519, rounded to -0, and the box was "hit" at t = 0.
/// (x - o is exact in sign, so only the division can lose it.) Monotone in x, as rounding is.
inline Calc slab_parameter(Calc x, Calc o, Calc d) noexcept {
  const Calc num = x - o, q = num / d;
  if (q != 0 || num == 0) return q;
  const Calc tiny = std::numeric_limits<Calc>::denorm_min();
  return (num > 0) == (d > 0) ? tiny : -tiny;
}

/// Slab test in double: the entry parameter of the segment into the closed box, or a negative
/// value when it misses. Monotone in the box (every operation rounds monotonically), so a box
/// that contains another is hit whenever the inner one is: fat boxes can prune safely.
template <Scalar T>
inline Calc ray_hits_box(const RaySegment<T>& r, const Box<T>& b) noexcept {
  Calc t0 = 0, t1 = r.max_t;
  for (int i = 0; i < 2; ++i) {
    const Calc lo = b.min[i], hi = b.max[i], o = r.origin[i], d = r.direction[i];
    if (d == 0) {
      if (o < lo || o > hi) return -1;
      continue;
    }
    Calc a = slab_parameter(lo, o, d), c = slab_parameter(hi, o, d);
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a);
    t1 = std::min(t1, c);
    if (t0 > t1) return -1;
  }
  return t0;
}

/// Conservative box around the segment (padded for the rounding of origin + max_t * direction).
template <Scalar T>
inline std::pair<Vec2c, Vec2c> ray_bounds(const RaySegment<T>& r) noexcept {
  const Vec2c end = r.origin + r.direction * r.max_t;
  Vec2c lo = r.origin.cwiseMin(end), hi = r.origin.cwiseMax(end);
  for (int i = 0; i < 2; ++i) {
    const Calc pad = kRayBoxPad * std::max(std::fabs(lo[i]), std::fabs(hi[i])) + kRayBoxPadFloor;
    lo[i] -= pad;
    hi[i] += pad;
  }
  return {lo, hi};
}

/// Calls f(args...); a bool result false means "stop". Returns whether to continue.
template <class F, class... A>
inline bool call_continue(F& f, A&&... args) {
  if constexpr (std::is_same_v<std::invoke_result_t<F&, A...>, bool>) {
    return f(std::forward<A>(args)...);
  } else {
    f(std::forward<A>(args)...);
    return true;
  }
}

/// Validates raw corners into a stored box. Errors: BadBox (wrapping the shape error's text).
template <Scalar T>
inline Box<T> checked_box(const Vec2<T>& min, const Vec2<T>& max) {
  const Expected<Aabb<T>> a = Aabb<T>::make(min, max);
  if (!a) throw BroadphaseError(BroadphaseErrc::BadBox, a.error().what());
  return box_of(a.value());
}

/// Validates a fattening margin. Errors: BadMargin.
template <Scalar T>
inline T checked_margin(T margin) {
  if (!(margin >= T(0)) || !(margin <= max_magnitude<T>()))
    throw BroadphaseError(BroadphaseErrc::BadMargin, "margin must be finite, >= 0 and <= max_magnitude()");
  return margin;
}

/// Slot table: stored boxes, user data and generations, indexed by ProxyId::index. `Extra` is
/// per-structure bookkeeping (a tree leaf, a grid cell range, ...).
template <Scalar T, class Extra>
class Slots {
 public:
  /// One proxy's record.
  struct Slot {
    Box<T> box{};                  ///< the stored box, as given
    std::uint64_t user = 0;        ///< the caller's user data
    Filter filter{};               ///< the proxy's filter
    std::uint32_t generation = 0;  ///< bumped on every reuse of the slot
    bool live = false;             ///< false once removed
    Extra extra{};                 ///< the structure's own bookkeeping
  };

  /// Throws InvalidProxy unless id names a live proxy.
  std::uint32_t check(ProxyId id) const {
    if (id.index >= slots_.size() || !slots_[id.index].live || slots_[id.index].generation != id.generation)
      throw BroadphaseError(BroadphaseErrc::InvalidProxy, "proxy handle is stale or was never issued");
    return id.index;
  }
  /// True when id names a live slot of this table.
  bool contains(ProxyId id) const noexcept {
    return id.index < slots_.size() && slots_[id.index].live && slots_[id.index].generation == id.generation;
  }
  /// Takes a free slot (or a new one) for a proxy. Errors: TooManyProxies.
  ProxyId allocate(const Box<T>& box, std::uint64_t user, Filter filter) {
    std::uint32_t i;
    if (!free_.empty()) {
      i = free_.back();
      free_.pop_back();
    } else {
      if (slots_.size() >= std::numeric_limits<std::uint32_t>::max() - 1)
        throw BroadphaseError(BroadphaseErrc::TooManyProxies, "too many proxies");
      i = static_cast<std::uint32_t>(slots_.size());
      slots_.emplace_back();
    }
    Slot& s = slots_[i];
    s.box = box;
    s.user = user;
    s.filter = filter;
    s.live = true;
    s.extra = Extra{};
    ++live_;
    return {i, s.generation};
  }
  /// Frees slot i; its handle becomes stale.
  void release(std::uint32_t i) {
    slots_[i].live = false;
    ++slots_[i].generation;  // wraps after 2^32 reuses of one slot; a stale handle that old is not detected
    free_.push_back(i);
    --live_;
  }
  /// Reserves room for n slots in all.
  void reserve(std::size_t n) { slots_.reserve(n); }
  /// Slot i (unchecked).
  Slot& operator[](std::uint32_t i) noexcept { return slots_[i]; }
  /// Slot i (unchecked).
  const Slot& operator[](std::uint32_t i) const noexcept { return slots_[i]; }
  /// The current handle of slot i.
  ProxyId id(std::uint32_t i) const noexcept { return {i, slots_[i].generation}; }
  /// Number of slots, live or free.
  std::size_t capacity() const noexcept { return slots_.size(); }
  /// Number of live slots.
  std::size_t size() const noexcept { return live_; }
  /// Drops every slot.
  void clear() {
    slots_.clear();
    free_.clear();
    live_ = 0;
  }

 private:
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_;
  std::size_t live_ = 0;
};

/// Orders a pair by slot index.
inline ProxyPair ordered_pair(ProxyId a, ProxyId b) noexcept {
  return a.index < b.index ? ProxyPair{a, b} : ProxyPair{b, a};
}

/// Traversal stack local to one call: kInline entries live in the call's frame, deeper
/// traversals spill to the heap. Local, so nested and concurrent queries never share it.
template <class V, std::size_t kInline = 128>
class LocalStack {
 public:
  /// Pushes v (on the heap only beyond kInline entries).
  void push(const V& v) {
    if (n_ < kInline) {
      inline_[n_] = v;
    } else {
      heap_.push_back(v);
    }
    ++n_;
  }
  /// Removes and returns the top entry (the stack must not be empty).
  V pop() {
    --n_;
    if (n_ < kInline) return inline_[n_];
    const V v = heap_.back();
    heap_.pop_back();
    return v;
  }
  /// True when nothing is on the stack.
  bool empty() const noexcept { return n_ == 0; }

 private:
  V inline_[kInline];
  std::vector<V> heap_;
  std::size_t n_ = 0;
};

/// The proxy operations all three structures offer identically. Derived supplies
/// add_box(Box, user, filter) -> ProxyId, move_box(ProxyId, Box), unlink(slot) (drop the slot from
/// its index before the slot is released), query(Aabb, f, filter), raycast(origin, direction,
/// max_t, f, filter), and a member `slots_` (a Slots table); it befriends this class and
/// re-exports raycast with a using.
///
/// Thread safety (all three structures): every const member function only reads the structure
/// and keeps its traversal state on the caller's stack, so any number of threads may call const
/// members at once while no thread calls a non-const one, and a callback may call any const
/// member of the same or another structure (nested queries). A callback must not modify the
/// structure it is called from.
template <class Derived, Scalar T>
class ProxyOps {
 public:
  /// Adds a proxy for box, carrying user (returned by user_data()) and a filter.
  ProxyId add(const Aabb<T>& box, std::uint64_t user = 0, Filter filter = {}) {
    return self().add_box(box_of(box), user, filter);
  }
  /// Adds a proxy from raw corners. Errors: BadBox.
  ProxyId add(const Vec2<T>& min, const Vec2<T>& max, std::uint64_t user = 0, Filter filter = {}) {
    return self().add_box(checked_box(min, max), user, filter);
  }
  /// Replaces the proxy's box. Errors: InvalidProxy.
  void move(ProxyId id, const Aabb<T>& box) { self().move_box(id, box_of(box)); }
  /// Errors: InvalidProxy, BadBox (the proxy is checked first).
  void move(ProxyId id, const Vec2<T>& min, const Vec2<T>& max) {
    self().slots_.check(id);
    self().move_box(id, checked_box(min, max));
  }
  /// Errors: InvalidProxy.
  void remove(ProxyId id) {
    const std::uint32_t s = self().slots_.check(id);
    self().unlink(s);
    self().slots_.release(s);
  }
  /// Replaces the proxy's filter (takes effect for every later call). Errors: InvalidProxy.
  void set_filter(ProxyId id, Filter filter) { self().slots_[self().slots_.check(id)].filter = filter; }
  /// True when id names a live proxy of this structure.
  bool contains(ProxyId id) const noexcept { return self().slots_.contains(id); }
  /// Number of live proxies.
  std::size_t size() const noexcept { return self().slots_.size(); }
  /// Stored box. Errors: InvalidProxy.
  Aabb<T> box(ProxyId id) const {
    const Box<T>& b = self().slots_[self().slots_.check(id)].box;
    return Aabb<T>::make(b.min, b.max).value();
  }
  /// Errors: InvalidProxy.
  std::uint64_t user_data(ProxyId id) const { return self().slots_[self().slots_.check(id)].user; }
  /// Errors: InvalidProxy.
  Filter filter(ProxyId id) const { return self().slots_[self().slots_.check(id)].filter; }
  /// True when the stored boxes of a and b overlap (closed) and their filters accept each other:
  /// whether pairs() lists (a, b). Errors: InvalidProxy.
  bool overlap(ProxyId a, ProxyId b) const {
    const auto& sa = self().slots_[self().slots_.check(a)];
    const auto& sb = self().slots_[self().slots_.check(b)];
    return boxes_overlap(sa.box, sb.box) && accepts(sa.filter, sb.filter);
  }
  /// Calls f(ProxyId, t) for every proxy whose stored box meets the ray (t in units of
  /// |direction|, 0 <= t <= max_t, the entry parameter; 0 if the origin is inside) and whose
  /// filter accepts `filter`. f may return bool; false stops. Errors: BadRay.
  template <class F>
  void raycast(const Ray<T>& ray, T max_t, F&& f, Filter filter = Filter::everything()) const {
    self().raycast(ray.origin, ray.direction, max_t, std::forward<F>(f), filter);
  }
  /// The proxy whose stored box the ray enters first (smallest t; ties: lowest slot index), or
  /// nothing. Errors: BadRay.
  std::optional<ProxyHit> raycast_closest(const Vec2<T>& origin, const Vec2<T>& direction, T max_t,
                                          Filter filter = Filter::everything()) const {
    std::optional<ProxyHit> best;
    self().raycast(
        origin, direction, max_t,
        [&](ProxyId id, Calc t) {
          if (!best || t < best->t || (t == best->t && id.index < best->id.index)) best = ProxyHit{id, t};
        },
        filter);
    return best;
  }
  /// Calls f(ProxyId) for every proxy whose stored box contains point p (closed) and whose filter
  /// accepts `filter`. f may return bool; false stops. Errors: BadBox (p is NaN or infinite).
  template <class F>
  void query_point(const Vec2<T>& p, F&& f, Filter filter = Filter::everything()) const {
    const Expected<Aabb<T>> b = Aabb<T>::make(p, p);
    if (!b) throw BroadphaseError(BroadphaseErrc::BadBox, b.error().what());
    self().query(b.value(), std::forward<F>(f), filter);
  }
  /// Every pair of proxies whose stored boxes overlap (closed) and whose filters accept each
  /// other, each once, a.index < b.index. Builds the list: for very many pairs use for_each_pair().
  std::vector<ProxyPair> pairs(PairOrder order = PairOrder::Any) const {
    std::vector<ProxyPair> out;
    self().for_each_pair([&](ProxyId a, ProxyId b) { out.push_back(ordered_pair(a, b)); });
    if (order == PairOrder::Sorted) std::sort(out.begin(), out.end());
    return out;
  }

 private:
  Derived& self() noexcept { return static_cast<Derived&>(*this); }
  const Derived& self() const noexcept { return static_cast<const Derived&>(*this); }
};

/// Sorts a pair list when asked to.
inline void finish_pairs(std::vector<ProxyPair>& pairs, PairOrder order) {
  if (order == PairOrder::Sorted) std::sort(pairs.begin(), pairs.end());
}

}  // namespace collide::broadphase
