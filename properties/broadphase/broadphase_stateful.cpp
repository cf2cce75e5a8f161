// Model-based (stateful) properties of the three broadphase structures: random sequences of
// add / move / remove / set_filter / query / raycast / pairs / pair-event updates, checked against a
// brute-force model (filters included), and the three structures against each other. Both
// scalars. Plus the world helpers and the persistent World against all-pairs.

#include "collide/broadphase.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>
#include <rapidcheck/state.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <variant>
#include <vector>

namespace bp = collide::broadphase;
using collide::Aabb;
using collide::Vec2;

namespace {

/// Counters printed at the end, so a run shows what it exercised.
struct Stats {
  std::atomic<long> commands{0}, pairs_checked{0}, touching_pairs{0}, queries{0}, rays{0}, ray_hits{0},
      errors_checked{0}, sequences{0}, updates{0}, began{0}, ended{0}, filtered_out{0}, world_steps{0}, world_events{0};
};
Stats g_stats;

template <class T>
struct Entry {
  bp::Box<T> box;
  bool live = true;
  bp::Filter filter{};
};
template <class T>
using Model = std::vector<Entry<T>>;

/// A pair tracker over one structure, and the model index of every handle it issued.
template <class BP, class T>
struct Tracked {
  explicit Tracked(BP b = BP()) : tracker(std::move(b)) {}
  bp::PairTracker<BP, T> tracker;
  std::vector<bp::ProxyId> id;
  std::map<bp::ProxyId, std::size_t> index;
  void add(const bp::Box<T>& b, std::size_t k, bp::Filter f) {
    id.push_back(tracker.add(Aabb<T>(b.min, b.max), k, f));
    index[id.back()] = k;
  }
};

/// The system under test: all three structures fed the same commands; user data = model index.
/// Also each structure under a pair tracker, and the pairs the trackers reported so far.
template <class T>
struct Sut {
  bp::DynamicTree<T> tree{T(0.5)};
  bp::SweepAndPrune<T> sweep;
  bp::UniformGrid<T> grid{T(1)};
  std::vector<bp::ProxyId> tree_id, sweep_id, grid_id;
  Tracked<bp::DynamicTree<T>, T> ttree{bp::DynamicTree<T>(T(0.5))};
  Tracked<bp::SweepAndPrune<T>, T> tsweep;
  Tracked<bp::UniformGrid<T>, T> tgrid{bp::UniformGrid<T>(T(1))};
  std::vector<std::pair<std::size_t, std::size_t>> reported;  ///< pairs current at the last update
};

/// Filters from three category bits: mostly the default, sometimes restrictive (mask 0 included).
inline rc::Gen<bp::Filter> gen_filter() {
  return rc::gen::weightedOneOf<bp::Filter>({{3, rc::gen::just(bp::Filter{})},
                                             {2, rc::gen::apply(
                                                     [](int c, int m) {
                                                       return bp::Filter{std::uint32_t(c), std::uint32_t(m)};
                                                     },
                                                     rc::gen::inRange(1, 8), rc::gen::inRange(0, 8))}});
}

/// Query filters: mostly everything, sometimes three random bits.
inline rc::Gen<bp::Filter> gen_query_filter() {
  return rc::gen::weightedOneOf<bp::Filter>({{1, rc::gen::just(bp::Filter::everything())},
                                             {1, rc::gen::apply(
                                                     [](int c, int m) {
                                                       return bp::Filter{std::uint32_t(c), std::uint32_t(m)};
                                                     },
                                                     rc::gen::inRange(0, 8), rc::gen::inRange(0, 8))}});
}

/// Dyadic coordinates on a half-unit lattice (many exact touches), sometimes far away or huge,
/// so the grid's oversized list and large magnitudes are exercised.
template <class T>
rc::Gen<bp::Box<T>> gen_box() {
  const auto small = rc::gen::apply(
      [](int x, int y, int w, int h) {
        return bp::Box<T>{Vec2<T>(T(x) / 2, T(y) / 2), Vec2<T>(T(x + w) / 2, T(y + h) / 2)};
      },
      rc::gen::inRange(-16, 17), rc::gen::inRange(-16, 17), rc::gen::inRange(0, 7), rc::gen::inRange(0, 7));
  const auto big = rc::gen::apply(
      [](int x, int y, int e) {
        const T s = std::ldexp(T(1), e);  // up to 2^100: beyond the grid's hashed range
        return bp::Box<T>{Vec2<T>(T(x) / 2 - s, T(y) / 2), Vec2<T>(T(x) / 2 + s, T(y) / 2 + s)};
      },
      rc::gen::inRange(-16, 17), rc::gen::inRange(-16, 17), rc::gen::inRange(1, 101));
  return rc::gen::weightedOneOf<bp::Box<T>>({{9, small}, {1, big}});
}

template <class T>
Aabb<T> to_aabb(const bp::Box<T>& b) {
  return Aabb<T>(b.min, b.max);
}

// Plain bools for RC_PRE: its expression capture would evaluate both sides of an &&.
template <class T>
bool is_live(const Model<T>& m, std::size_t k) {
  return k < m.size() && m[k].live;
}
template <class T>
bool is_dead(const Model<T>& m, std::size_t k) {
  return k < m.size() && !m[k].live;
}

template <class T>
std::vector<std::size_t> live_indices(const Model<T>& m) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i].live) out.push_back(i);
  return out;
}

template <class T>
std::vector<std::size_t> dead_indices(const Model<T>& m) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (!m[i].live) out.push_back(i);
  return out;
}

/// Maps a structure's pair list to model indices (each pair (lo, hi)), keeping order.
template <class B>
std::vector<std::pair<std::size_t, std::size_t>> to_model(const B& b, const std::vector<bp::ProxyPair>& pairs) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const auto& p : pairs) {
    std::size_t x = b.user_data(p.a), y = b.user_data(p.b);
    RC_ASSERT(p.a.index < p.b.index);
    out.emplace_back(std::min(x, y), std::max(x, y));
  }
  return out;
}

template <class T>
bool only_touching(const bp::Box<T>& a, const bp::Box<T>& b) {
  return a.max.x() == b.min.x() || b.max.x() == a.min.x() || a.max.y() == b.min.y() || b.max.y() == a.min.y();
}

template <class T>
struct Add : rc::state::Command<Model<T>, Sut<T>> {
  bp::Box<T> box = *gen_box<T>();
  bp::Filter filter = *gen_filter();
  void apply(Model<T>& m) const override { m.push_back({box, true, filter}); }
  void run(const Model<T>& m, Sut<T>& s) const override {
    const std::uint64_t k = m.size();
    s.tree_id.push_back(s.tree.add(to_aabb(box), k, filter));
    s.sweep_id.push_back(s.sweep.add(to_aabb(box), k, filter));
    s.grid_id.push_back(s.grid.add(box.min, box.max, k, filter));  // the raw-corner overload
    s.ttree.add(box, k, filter);
    s.tsweep.add(box, k, filter);
    s.tgrid.add(box, k, filter);
    RC_ASSERT(s.sweep.filter(s.sweep_id.back()) == filter);
    RC_ASSERT(s.tree.user_data(s.tree_id.back()) == k);
    RC_ASSERT(s.grid.box(s.grid_id.back()).max() == box.max);
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override {
    os << "Add(" << box.min.transpose() << " / " << box.max.transpose() << ", filter " << filter.category << "/"
       << filter.mask << ")";
  }
};

template <class T>
struct Move : rc::state::Command<Model<T>, Sut<T>> {
  explicit Move(const Model<T>& m) {
    const auto live = live_indices(m);
    RC_PRE(!live.empty());
    k = *rc::gen::elementOf(live);
    // Mostly small coherent steps, sometimes a jump anywhere.
    box = *rc::gen::weightedOneOf<bp::Box<T>>({{3, rc::gen::apply(
                                                       [b = m[k].box](int dx, int dy) {
                                                         const Vec2<T> d(T(dx) / 4, T(dy) / 4);
                                                         return bp::Box<T>{b.min + d, b.max + d};
                                                       },
                                                       rc::gen::inRange(-3, 4), rc::gen::inRange(-3, 4))},
                                               {1, gen_box<T>()}});
  }
  std::size_t k = 0;
  bp::Box<T> box;
  void checkPreconditions(const Model<T>& m) const override { RC_PRE(is_live(m, k)); }
  void apply(Model<T>& m) const override { m[k].box = box; }
  void run(const Model<T>&, Sut<T>& s) const override {
    s.tree.move(s.tree_id[k], to_aabb(box));
    s.sweep.move(s.sweep_id[k], box.min, box.max);
    s.grid.move(s.grid_id[k], to_aabb(box));
    s.ttree.tracker.move(s.ttree.id[k], to_aabb(box));
    s.tsweep.tracker.move(s.tsweep.id[k], to_aabb(box));
    s.tgrid.tracker.move(s.tgrid.id[k], to_aabb(box));
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override {
    os << "Move(" << k << ", " << box.min.transpose() << " / " << box.max.transpose() << ")";
  }
};

template <class T>
struct Remove : rc::state::Command<Model<T>, Sut<T>> {
  explicit Remove(const Model<T>& m) {
    const auto live = live_indices(m);
    RC_PRE(!live.empty());
    k = *rc::gen::elementOf(live);
  }
  std::size_t k = 0;
  void checkPreconditions(const Model<T>& m) const override { RC_PRE(is_live(m, k)); }
  void apply(Model<T>& m) const override { m[k].live = false; }
  void run(const Model<T>&, Sut<T>& s) const override {
    s.tree.remove(s.tree_id[k]);
    s.sweep.remove(s.sweep_id[k]);
    s.grid.remove(s.grid_id[k]);
    s.ttree.tracker.remove(s.ttree.id[k]);
    s.tsweep.tracker.remove(s.tsweep.id[k]);
    s.tgrid.tracker.remove(s.tgrid.id[k]);
    RC_ASSERT(!s.tree.contains(s.tree_id[k]));
    RC_ASSERT(!s.sweep.contains(s.sweep_id[k]));
    RC_ASSERT(!s.grid.contains(s.grid_id[k]));
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override { os << "Remove(" << k << ")"; }
};

/// Every operation on a removed proxy's handle is refused with InvalidProxy and changes nothing.
template <class T>
struct UseStale : rc::state::Command<Model<T>, Sut<T>> {
  explicit UseStale(const Model<T>& m) {
    const auto dead = dead_indices(m);
    RC_PRE(!dead.empty());
    k = *rc::gen::elementOf(dead);
  }
  std::size_t k = 0;
  void checkPreconditions(const Model<T>& m) const override { RC_PRE(is_dead(m, k)); }
  void apply(Model<T>&) const override {}
  void run(const Model<T>& m, Sut<T>& s) const override {
    const auto expect_invalid = [](auto&& f) {
      try {
        f();
      } catch (const bp::BroadphaseError& e) {
        RC_ASSERT(e.code() == bp::BroadphaseErrc::InvalidProxy);
        ++g_stats.errors_checked;
        return;
      }
      RC_FAIL("stale handle accepted");
    };
    const Aabb<T> b = to_aabb(m[k].box);
    expect_invalid([&] { s.tree.move(s.tree_id[k], b); });
    expect_invalid([&] { s.sweep.remove(s.sweep_id[k]); });
    expect_invalid([&] { s.grid.user_data(s.grid_id[k]); });
    expect_invalid([&] { s.tree.remove(s.tree_id[k]); });
    expect_invalid([&] { s.sweep.move(s.sweep_id[k], b); });
    expect_invalid([&] { s.grid.move(s.grid_id[k], b.min(), b.max()); });
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override { os << "UseStale(" << k << ")"; }
};

/// Raw corners that are NaN, infinite or inverted are refused with BadBox and add nothing.
template <class T>
struct AddBad : rc::state::Command<Model<T>, Sut<T>> {
  int which = *rc::gen::inRange(0, 3);
  void apply(Model<T>&) const override {}
  void run(const Model<T>&, Sut<T>& s) const override {
    const T bad = which == 0   ? std::numeric_limits<T>::quiet_NaN()
                  : which == 1 ? std::numeric_limits<T>::infinity()
                               : T(-5);
    const std::size_t n = s.tree.size();
    for (int target = 0; target < 3; ++target) {
      try {
        const Vec2<T> lo(T(0), T(0)), hi(bad, T(1));
        if (target == 0) s.tree.add(lo, hi);
        if (target == 1) s.sweep.add(lo, hi);
        if (target == 2) s.grid.add(lo, hi);
        RC_FAIL("bad box accepted");
      } catch (const bp::BroadphaseError& e) {
        RC_ASSERT(e.code() == bp::BroadphaseErrc::BadBox);
        ++g_stats.errors_checked;
      }
    }
    RC_ASSERT(s.tree.size() == n && s.sweep.size() == n && s.grid.size() == n);
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override { os << "AddBad(" << which << ")"; }
};

template <class T>
struct SetFilter : rc::state::Command<Model<T>, Sut<T>> {
  explicit SetFilter(const Model<T>& m) {
    const auto live = live_indices(m);
    RC_PRE(!live.empty());
    k = *rc::gen::elementOf(live);
  }
  std::size_t k = 0;
  bp::Filter filter = *gen_filter();
  void checkPreconditions(const Model<T>& m) const override { RC_PRE(is_live(m, k)); }
  void apply(Model<T>& m) const override { m[k].filter = filter; }
  void run(const Model<T>&, Sut<T>& s) const override {
    s.tree.set_filter(s.tree_id[k], filter);
    s.sweep.set_filter(s.sweep_id[k], filter);
    s.grid.set_filter(s.grid_id[k], filter);
    s.ttree.tracker.set_filter(s.ttree.id[k], filter);
    s.tsweep.tracker.set_filter(s.tsweep.id[k], filter);
    s.tgrid.tracker.set_filter(s.tgrid.id[k], filter);
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override {
    os << "SetFilter(" << k << ", " << filter.category << "/" << filter.mask << ")";
  }
};

/// The model's pairs: live, overlapping (closed) and accepted by both filters; sorted (i < j).
template <class T>
std::vector<std::pair<std::size_t, std::size_t>> model_pairs(const Model<T>& m) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < m.size(); ++i) {
    for (std::size_t j = i + 1; j < m.size(); ++j) {
      if (!m[i].live || !m[j].live || !bp::boxes_overlap(m[i].box, m[j].box)) continue;
      if (!bp::accepts(m[i].filter, m[j].filter)) {
        ++g_stats.filtered_out;
        continue;
      }
      out.emplace_back(i, j);
    }
  }
  return out;
}

/// Pair events: each tracker reports exactly the model's pairs that began (now, not at the last
/// update) and ended (at the last update, not now), each once; all three agree.
template <class T>
struct Update : rc::state::Command<Model<T>, Sut<T>> {
  void apply(Model<T>&) const override {}
  void run(const Model<T>& m, Sut<T>& s) const override {
    using P = std::pair<std::size_t, std::size_t>;
    const std::vector<P> now = model_pairs(m);
    std::vector<P> began, ended;
    std::set_difference(now.begin(), now.end(), s.reported.begin(), s.reported.end(), std::back_inserter(began));
    std::set_difference(s.reported.begin(), s.reported.end(), now.begin(), now.end(), std::back_inserter(ended));
    const auto check = [&](auto& t) {
      const bp::PairEvents e = t.tracker.update();
      const auto as_model = [&](const std::vector<bp::ProxyPair>& ps) {
        std::vector<P> out;
        for (const auto& p : ps) {
          RC_ASSERT(p.a.index < p.b.index);
          const std::size_t x = t.index.at(p.a), y = t.index.at(p.b);
          out.emplace_back(std::min(x, y), std::max(x, y));
        }
        std::sort(out.begin(), out.end());  // duplicates stay and fail the comparison
        return out;
      };
      RC_ASSERT(as_model(e.began) == began);
      RC_ASSERT(as_model(e.ended) == ended);
      // The tracker's partner lists are the current pairs.
      for (std::size_t k = 0; k < m.size(); ++k) {
        if (!m[k].live) continue;
        std::size_t partners = 0;
        t.tracker.for_each_partner(t.id[k], [&](bp::ProxyId o) {
          const std::size_t x = t.index.at(o);
          RC_ASSERT(std::binary_search(now.begin(), now.end(), P(std::min(k, x), std::max(k, x))));
          ++partners;
        });
        RC_ASSERT(partners == std::size_t(std::count_if(now.begin(), now.end(),
                                                        [&](const P& p) { return p.first == k || p.second == k; })));
      }
    };
    check(s.ttree);
    check(s.tsweep);
    check(s.tgrid);
    s.reported = now;
    ++g_stats.updates;
    g_stats.began += long(began.size());
    g_stats.ended += long(ended.size());
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override { os << "Update"; }
};

template <class T>
struct Query : rc::state::Command<Model<T>, Sut<T>> {
  bp::Box<T> q = *gen_box<T>();
  bp::Filter filter = *gen_query_filter();
  void apply(Model<T>&) const override {}
  void run(const Model<T>& m, Sut<T>& s) const override {
    std::vector<std::size_t> expected;
    for (std::size_t i = 0; i < m.size(); ++i)
      if (m[i].live && bp::boxes_overlap(m[i].box, q) && bp::accepts(m[i].filter, filter)) expected.push_back(i);
    const auto collect = [&](const auto& b) {
      std::vector<std::size_t> got;
      b.query(
          to_aabb(q), [&](bp::ProxyId id) { got.push_back(b.user_data(id)); }, filter);
      std::sort(got.begin(), got.end());  // duplicates stay and fail the comparison
      return got;
    };
    RC_ASSERT(collect(s.tree) == expected);
    RC_ASSERT(collect(s.sweep) == expected);
    RC_ASSERT(collect(s.grid) == expected);
    ++g_stats.queries;
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override {
    os << "Query(" << q.min.transpose() << " / " << q.max.transpose() << ", filter " << filter.category << "/"
       << filter.mask << ")";
  }
};

template <class T>
struct Raycast : rc::state::Command<Model<T>, Sut<T>> {
  Vec2<T> origin = Vec2<T>(T(*rc::gen::inRange(-20, 21)) / 2, T(*rc::gen::inRange(-20, 21)) / 2);
  Vec2<T> direction = Vec2<T>(T(*rc::gen::inRange(-8, 9)) * 2, T(*rc::gen::inRange(-8, 9)) * 2);
  T max_t = T(*rc::gen::inRange(0, 5)) / 2;
  bp::Filter filter = *gen_query_filter();
  void apply(Model<T>&) const override {}
  void run(const Model<T>& m, Sut<T>& s) const override {
    const bp::RaySegment<T> r = bp::make_ray(origin, direction, max_t);
    std::vector<std::size_t> expected;
    collide::Calc best_t = 0;
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < m.size(); ++i) {
      if (!m[i].live || !bp::accepts(m[i].filter, filter)) continue;
      const collide::Calc t = bp::ray_hits_box(r, m[i].box);
      if (t < 0) continue;
      expected.push_back(i);
      if (!best || t < best_t) best = i, best_t = t;
    }
    const auto collect = [&](const auto& b, const std::vector<bp::ProxyId>& ids) {
      std::vector<std::size_t> got;
      b.raycast(
          origin, direction, max_t,
          [&](bp::ProxyId id, collide::Calc t) {
            const bool in_range = t >= 0 && t <= collide::Calc(max_t);
            RC_ASSERT(in_range);
            got.push_back(b.user_data(id));
          },
          filter);
      std::sort(got.begin(), got.end());
      // Closest hit: the smallest t (ties by slot index, so compare t and that the proxy is hit there).
      const auto closest = b.raycast_closest(origin, direction, max_t, filter);
      RC_ASSERT(closest.has_value() == best.has_value());
      if (closest) {
        RC_ASSERT(closest->t == best_t);
        RC_ASSERT(bp::ray_hits_box(r, m[b.user_data(closest->id)].box) == best_t);
        RC_ASSERT(b.contains(closest->id) && closest->id.index <= ids[*best].index);
      }
      return got;
    };
    RC_ASSERT(collect(s.tree, s.tree_id) == expected);
    RC_ASSERT(collect(s.sweep, s.sweep_id) == expected);
    RC_ASSERT(collect(s.grid, s.grid_id) == expected);
    ++g_stats.rays;
    g_stats.ray_hits += long(expected.size());
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override {
    os << "Raycast(" << origin.transpose() << " + t " << direction.transpose() << ", t <= " << max_t << ", filter "
       << filter.category << "/" << filter.mask << ")";
  }
};

template <class T>
struct Pairs : rc::state::Command<Model<T>, Sut<T>> {
  void apply(Model<T>&) const override {}
  void run(const Model<T>& m, Sut<T>& s) const override {
    const std::vector<std::pair<std::size_t, std::size_t>> expected = model_pairs(m);
    long touching = 0;
    for (const auto& [i, j] : expected) touching += only_touching(m[i].box, m[j].box) ? 1 : 0;
    const auto check = [&](const auto& b) {
      // Sorted order: identical list (ids ascending by slot), each pair once.
      const auto sorted = b.pairs(bp::PairOrder::Sorted);
      RC_ASSERT(std::is_sorted(sorted.begin(), sorted.end()));
      auto got = to_model(b, sorted);
      std::sort(got.begin(), got.end());
      RC_ASSERT(got == expected);
      auto any = to_model(b, b.pairs());
      std::sort(any.begin(), any.end());
      RC_ASSERT(any == expected);
      std::vector<bp::ProxyPair> walked;
      b.for_each_pair([&](bp::ProxyId x, bp::ProxyId y) { walked.push_back(bp::ordered_pair(x, y)); });
      auto w = to_model(b, walked);
      std::sort(w.begin(), w.end());
      RC_ASSERT(w == expected);
      return sorted;
    };
    const auto t = check(s.tree), w = check(s.sweep), g = check(s.grid);
    RC_ASSERT(to_model(s.tree, t) == to_model(s.sweep, w));
    RC_ASSERT(to_model(s.tree, t) == to_model(s.grid, g));
    RC_ASSERT(s.tree.check_invariants());
    // Pairs involving a subset: exactly the expected pairs touching it.
    std::vector<std::size_t> subset;
    for (std::size_t i = 0; i < m.size(); i += 2)
      if (m[i].live) subset.push_back(i);
    std::vector<bp::ProxyId> ids;
    for (std::size_t i : subset) ids.push_back(s.sweep_id[i]);
    auto inv = to_model(s.sweep, bp::pairs_involving(s.sweep, std::span<const bp::ProxyId>(ids)));
    std::sort(inv.begin(), inv.end());
    std::vector<std::pair<std::size_t, std::size_t>> want;
    for (const auto& p : expected)
      if (p.first % 2 == 0 || p.second % 2 == 0) want.push_back(p);
    RC_ASSERT(inv == want);
    g_stats.pairs_checked += long(expected.size());
    g_stats.touching_pairs += touching;
    ++g_stats.commands;
  }
  void show(std::ostream& os) const override { os << "Pairs"; }
};

template <class T>
void check_stateful() {
  Model<T> initial;
  Sut<T> sut;
  ++g_stats.sequences;
  rc::state::check(
      initial, sut,
      rc::state::gen::execOneOfWithArgs<Add<T>, Add<T>, Add<T>, Move<T>, Move<T>, Remove<T>, UseStale<T>, AddBad<T>,
                                        SetFilter<T>, Query<T>, Raycast<T>, Pairs<T>, Update<T>, Update<T>>());
}

template <class T>
rc::Gen<collide::Shape<T>> gen_shape() {
  using S = collide::Shape<T>;
  const auto c = [](int v) { return T(v) / 4; };
  return rc::gen::oneOf(
      rc::gen::apply([c](int x, int y, int r) { return S(collide::Circle<T>(Vec2<T>(c(x), c(y)), c(r))); },
                     rc::gen::inRange(-40, 41), rc::gen::inRange(-40, 41), rc::gen::inRange(0, 12)),
      rc::gen::apply([c](int x, int y, int w,
                         int h) { return S(collide::Aabb<T>(Vec2<T>(c(x), c(y)), Vec2<T>(c(x + w), c(y + h)))); },
                     rc::gen::inRange(-40, 41), rc::gen::inRange(-40, 41), rc::gen::inRange(0, 16),
                     rc::gen::inRange(0, 16)),
      rc::gen::apply(
          [c](int x, int y, int dx, int dy, int r) {
            return S(collide::Capsule<T>(Vec2<T>(c(x), c(y)), Vec2<T>(c(x + dx), c(y + dy)), c(r)));
          },
          rc::gen::inRange(-40, 41), rc::gen::inRange(-40, 41), rc::gen::inRange(-8, 9), rc::gen::inRange(-8, 9),
          rc::gen::inRange(0, 6)));
}

/// The world helper finds exactly the pairs that all-pairs overlaps() finds, with each structure.
template <class T>
void check_world(const std::vector<collide::Shape<T>>& shapes) {
  std::vector<bp::ShapePair> expected;
  for (std::size_t i = 0; i < shapes.size(); ++i)
    for (std::size_t j = i + 1; j < shapes.size(); ++j)
      if (collide::overlaps(shapes[i], shapes[j])) expected.push_back({i, j});
  const std::span<const collide::Shape<T>> s(shapes);
  RC_ASSERT(bp::find_overlapping_shapes<T>(s) == expected);
  RC_ASSERT((bp::find_overlapping_shapes<T, bp::SweepAndPrune<T>>(s)) == expected);
  RC_ASSERT((bp::find_overlapping_shapes<T, bp::UniformGrid<T>>(s, bp::UniformGrid<T>(T(2)))) == expected);
  const auto contacts = bp::find_contacts<T>(s);
  RC_ASSERT(contacts.size() == expected.size());
  for (std::size_t i = 0; i < contacts.size(); ++i)
    RC_ASSERT(contacts[i].a == expected[i].a && contacts[i].b == expected[i].b);
  RC_CLASSIFY(!expected.empty(), "some overlap");
}

/// The world raycast finds the same nearest shape as casting against every shape.
template <class T>
void check_world_ray(const std::vector<collide::Shape<T>>& shapes, const Vec2<T>& origin, const Vec2<T>& direction,
                     T max_t) {
  const collide::Ray<T> ray{origin, direction};
  std::optional<bp::ShapeHit<T>> expected;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const auto h = collide::raycast(shapes[i], ray, max_t);
    if (h && (!expected || h->t < expected->hit.t)) expected = bp::ShapeHit<T>{i, *h};
  }
  const std::span<const collide::Shape<T>> s(shapes);
  const auto check = [&](const std::optional<bp::ShapeHit<T>>& got) {
    RC_ASSERT(got.has_value() == expected.has_value());
    if (got) {
      RC_ASSERT(got->index == expected->index);
      RC_ASSERT(got->hit.t == expected->hit.t);
    }
  };
  check(bp::raycast_shapes<T>(s, ray, max_t));
  check(bp::raycast_shapes<T, bp::SweepAndPrune<T>>(s, ray, max_t));
  check(bp::raycast_shapes<T, bp::UniformGrid<T>>(s, ray, max_t, bp::UniformGrid<T>(T(2))));
  RC_CLASSIFY(expected.has_value(), "hit");
}

/// A body's shape in its own frame, near its origin so that bodies meet often: any primitive kind
/// on a quarter-unit grid, or a compound of two of them.
template <class T>
rc::Gen<collide::Shape<T>> gen_body_shape() {
  using S = collide::Shape<T>;
  using Pr = collide::Primitive<T>;
  const auto c = [](int v) { return T(v) / 4; };
  const auto primitive =
      rc::gen::oneOf(
          rc::gen::apply([c](int x, int y, int r) { return Pr(collide::Circle<T>(Vec2<T>(c(x), c(y)), c(r))); },
                         rc::gen::inRange(-4, 5), rc::gen::inRange(-4, 5), rc::gen::inRange(0, 8)),
          rc::gen::apply([c](int x, int y, int w,
                             int h) { return Pr(collide::Aabb<T>(Vec2<T>(c(x), c(y)), Vec2<T>(c(x + w), c(y + h)))); },
                         rc::gen::inRange(-6, 3), rc::gen::inRange(-6, 3), rc::gen::inRange(0, 10),
                         rc::gen::inRange(0, 10)),
          rc::gen::apply(
              [c](int x, int y, int w, int h, int turn) {
                return Pr(collide::Obb<T>(Vec2<T>(c(x), c(y)), Vec2<T>(c(w), c(h)), T(turn) / 5));
              },
              rc::gen::inRange(-4, 5), rc::gen::inRange(-4, 5), rc::gen::inRange(0, 6), rc::gen::inRange(0, 6),
              rc::gen::inRange(-8, 9)),
          rc::gen::apply(
              [c](int x, int y, int dx, int dy, int r) {
                return Pr(collide::Capsule<T>(Vec2<T>(c(x), c(y)), Vec2<T>(c(x + dx), c(y + dy)), c(r)));
              },
              rc::gen::inRange(-4, 5), rc::gen::inRange(-4, 5), rc::gen::inRange(-6, 7), rc::gen::inRange(-6, 7),
              rc::gen::inRange(0, 4)),
          rc::gen::apply(
              [c](int x, int y, int w, int h) {  // a triangle: never degenerate, w, h > 0
                return Pr(collide::ConvexPolygon<T>::make(
                              {Vec2<T>(c(x), c(y)), Vec2<T>(c(x + w), c(y)), Vec2<T>(c(x), c(y + h))})
                              .value());
              },
              rc::gen::inRange(-6, 3), rc::gen::inRange(-6, 3), rc::gen::inRange(1, 10), rc::gen::inRange(1, 10)));
  return rc::gen::weightedOneOf<S>(
      {{4, rc::gen::map(primitive, [](const Pr& p) { return std::visit([](const auto& x) { return S(x); }, p); })},
       {1, rc::gen::map(rc::gen::pair(primitive, primitive), [](const std::pair<Pr, Pr>& p) {
          return S(collide::Compound<T>({p.first, p.second}));
        })}});
}

/// A body's transform: the identity half the time (a world-space body), else a position on a
/// quarter-unit grid and an angle from a few turns (zero, exact quarter turns and others).
template <class T>
rc::Gen<collide::Transform<T>> gen_body_transform() {
  return rc::gen::weightedOneOf<collide::Transform<T>>(
      {{1, rc::gen::just(collide::Transform<T>())},
       {1, rc::gen::apply(
               [](int x, int y, int turn) {
                 const Vec2<T> p(T(x) / 4, T(y) / 4);
                 return collide::Transform<T>::make(p, T(turn) * T(0.3927)).value();  // about pi/8
               },
               rc::gen::inRange(-12, 13), rc::gen::inRange(-12, 13), rc::gen::inRange(-8, 9))}});
}

/// Field-wise identity of two contacts (every output bit for bit; NaN never occurs).
template <class T>
bool same_contact(const collide::Contact<T>& x, const collide::Contact<T>& y) {
  if (x.normal != y.normal || x.depth != y.depth || x.count != y.count) return false;
  for (int k = 0; k < x.count; ++k)
    if (x.points[std::size_t(k)] != y.points[std::size_t(k)] || !(x.ids[std::size_t(k)] == y.ids[std::size_t(k)]) ||
        x.separations[std::size_t(k)] != y.separations[std::size_t(k)])
      return false;
  return true;
}

/// The persistent World over a random script of add / move / set_shape / remove / set_filter
/// between steps, bodies placed by transforms, with a speculative distance or none: each step
/// reports exactly the pairs whose contact() (and filters) began or ended, each once; every
/// contact it keeps is contact() of the placed shapes bit for bit and keeps its ContactId while
/// it lasts; point, shape and ray queries match every placed shape tested directly.
template <class T, class BP>
void check_world_steps(BP structure) {
  using P = std::pair<std::size_t, std::size_t>;
  const T speculative = *rc::gen::element(T(0), T(0), T(0.25), T(1));
  bp::World<T, BP> w(std::move(structure), speculative);
  struct Body {
    collide::Shape<T> shape;
    collide::Transform<T> x;
    bp::Filter filter;
    bool live;
  };
  std::vector<Body> model;
  std::vector<bp::ProxyId> ids;
  std::map<bp::ProxyId, std::size_t> index;
  std::vector<P> reported;
  std::map<P, bp::ContactId> contact_ids;  ///< the id of each contact at the last step
  std::set<bp::ContactId> issued;          ///< every id a contact has had
  const int steps = *rc::gen::inRange(1, 6);
  for (int step = 0; step < steps; ++step) {
    const int ops = *rc::gen::inRange(0, 10);
    for (int o = 0; o < ops; ++o) {
      std::vector<std::size_t> live;
      for (std::size_t i = 0; i < model.size(); ++i)
        if (model[i].live) live.push_back(i);
      const int op = live.empty() ? 0 : *rc::gen::inRange(0, 6);
      if (op == 0) {
        const auto shape = *gen_body_shape<T>();
        const auto x = *gen_body_transform<T>();
        const bp::Filter f = *gen_filter();
        ids.push_back(w.add(shape, x, model.size(), f));
        index[ids.back()] = model.size();
        model.push_back({shape, x, f, true});
        continue;
      }
      const std::size_t k = *rc::gen::elementOf(live);
      if (op == 1) {
        model[k].x = *gen_body_transform<T>();
        w.move(ids[k], model[k].x);
      } else if (op == 2) {
        model[k].shape = *gen_body_shape<T>();
        model[k].x = collide::Transform<T>();
        w.move(ids[k], model[k].shape);
      } else if (op == 3) {
        model[k].shape = *gen_body_shape<T>();
        model[k].x = *gen_body_transform<T>();
        w.set_shape(ids[k], model[k].shape, model[k].x);
      } else if (op == 4) {
        model[k].live = false;
        w.remove(ids[k]);
      } else {
        model[k].filter = *gen_filter();
        w.set_filter(ids[k], model[k].filter);
      }
    }
    const auto contact_of = [&](std::size_t i, std::size_t j) {  // i the body of the lower slot
      return collide::contact(model[i].shape, model[i].x, model[j].shape, model[j].x, speculative);
    };
    const auto by_slot = [&](std::size_t i, std::size_t j) { return ids[i].index < ids[j].index ? P(i, j) : P(j, i); };
    std::vector<P> now;
    for (std::size_t i = 0; i < model.size(); ++i)
      for (std::size_t j = i + 1; j < model.size(); ++j) {
        if (!model[i].live || !model[j].live || !bp::accepts(model[i].filter, model[j].filter)) continue;
        const auto [lo, hi] = by_slot(i, j);
        if (contact_of(lo, hi)) now.emplace_back(i, j);
      }
    std::vector<P> began, ended;
    std::set_difference(now.begin(), now.end(), reported.begin(), reported.end(), std::back_inserter(began));
    std::set_difference(reported.begin(), reported.end(), now.begin(), now.end(), std::back_inserter(ended));
    const bp::PairEvents& e = w.step();
    const auto as_model = [&](const std::vector<bp::ProxyPair>& ps) {
      std::vector<P> out;
      for (const auto& p : ps)
        out.emplace_back(std::min(index.at(p.a), index.at(p.b)), std::max(index.at(p.a), index.at(p.b)));
      std::sort(out.begin(), out.end());
      return out;
    };
    RC_ASSERT(as_model(e.began) == began);
    RC_ASSERT(as_model(e.ended) == ended);
    // Every contact: the pair query's answer bit for bit, its id kept while it lasts and unique.
    std::vector<bp::ProxyPair> current;
    std::map<P, bp::ContactId> now_ids;
    std::set<bp::ContactId> seen;
    w.for_each_contact([&](const bp::BodyContact<T>& c) {
      RC_ASSERT(c.a.index < c.b.index);
      current.push_back({c.a, c.b});
      const std::size_t i = index.at(c.a), j = index.at(c.b);
      const auto want = contact_of(i, j);
      RC_ASSERT(want.has_value());
      RC_ASSERT(same_contact(c.contact, *want));
      RC_ASSERT(seen.insert(c.id).second);
      RC_ASSERT(c.id.index < w.contact_capacity());
      const P key(std::min(i, j), std::max(i, j));
      now_ids[key] = c.id;
      const auto before = contact_ids.find(key);
      const bool lasted = before != contact_ids.end() && !std::binary_search(began.begin(), began.end(), key);
      if (lasted) {
        RC_ASSERT(before->second == c.id);  // the same contact keeps its id
      } else {
        RC_ASSERT(issued.insert(c.id).second);  // a new contact never gets an id issued before
      }
      const bp::BodyContact<T>* found = w.find_contact(c.b, c.a);
      RC_ASSERT(found != nullptr && found->id == c.id);
    });
    std::vector<bp::ProxyPair> pairs_only;
    w.for_each_contact([&](bp::ProxyId a, bp::ProxyId b) { pairs_only.push_back({a, b}); });
    RC_ASSERT(pairs_only == current);
    RC_ASSERT(as_model(current) == now);
    RC_ASSERT(w.contact_count() == now.size());
    reported = now;
    contact_ids = now_ids;
    ++g_stats.world_steps;
    g_stats.world_events += long(began.size() + ended.size());
  }
  // Queries against the final state: each answer is the placed query's on every body.
  const Vec2<T> p(T(*rc::gen::inRange(-16, 17)) / 4, T(*rc::gen::inRange(-16, 17)) / 4);
  const auto probe = *gen_body_shape<T>();
  const auto probe_x = *gen_body_transform<T>();
  const bp::Filter qf = *gen_query_filter();
  std::vector<std::size_t> want_point, want_shape, got_point, got_shape;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (!model[i].live || !bp::accepts(model[i].filter, qf)) continue;
    RC_ASSERT(w.transform(ids[i]) == model[i].x);
    if (collide::contains(model[i].shape, model[i].x, p)) want_point.push_back(i);
    if (collide::overlaps(probe, probe_x, model[i].shape, model[i].x)) want_shape.push_back(i);
  }
  w.query_point(
      p, [&](bp::ProxyId id) { got_point.push_back(index.at(id)); }, qf);
  w.query_shape(
      probe, probe_x, [&](bp::ProxyId id) { got_shape.push_back(index.at(id)); }, qf);
  std::sort(got_point.begin(), got_point.end());
  std::sort(got_shape.begin(), got_shape.end());
  RC_ASSERT(got_point == want_point);
  RC_ASSERT(got_shape == want_shape);
  const collide::Ray<T> ray{p, Vec2<T>(T(*rc::gen::inRange(-16, 17)) / 2, T(*rc::gen::inRange(-16, 17)) / 2)};
  const T max_t = T(*rc::gen::inRange(0, 9)) / 2;
  std::optional<collide::Calc> want_t;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (!model[i].live || !bp::accepts(model[i].filter, qf)) continue;
    const auto h = collide::raycast(model[i].shape, model[i].x, ray, max_t);
    if (h && (!want_t || h->t < *want_t)) want_t = h->t;
  }
  const auto hit = w.raycast(ray, max_t, qf);
  RC_ASSERT(hit.has_value() == want_t.has_value());
  if (hit) RC_ASSERT(collide::Calc(hit->hit.t) == *want_t);
  RC_CLASSIFY(!reported.empty(), "contacts at the end");
  RC_CLASSIFY(speculative > 0, "speculative");
}

}  // namespace

RC_GTEST_PROP(BroadphaseWorld, FloatStepsReportBeganAndEndedContacts, ()) {
  check_world_steps<float>(bp::DynamicTree<float>(0.25f));
  check_world_steps<float>(bp::SweepAndPrune<float>());
  check_world_steps<float>(bp::UniformGrid<float>(2.0f));
}
RC_GTEST_PROP(BroadphaseWorld, DoubleStepsReportBeganAndEndedContacts, ()) {
  check_world_steps<double>(bp::DynamicTree<double>(0.25));
  check_world_steps<double>(bp::SweepAndPrune<double>());
  check_world_steps<double>(bp::UniformGrid<double>(2.0));
}

RC_GTEST_PROP(BroadphaseStateful, FloatMatchesBruteForceModel, ()) {
  check_stateful<float>();
}
RC_GTEST_PROP(BroadphaseStateful, DoubleMatchesBruteForceModel, ()) {
  check_stateful<double>();
}

RC_GTEST_PROP(BroadphaseWorld, FloatSameAsAllPairs, ()) {
  check_world<float>(*rc::gen::container<std::vector<collide::Shape<float>>>(gen_shape<float>()));
}
RC_GTEST_PROP(BroadphaseWorld, DoubleSameAsAllPairs, ()) {
  check_world<double>(*rc::gen::container<std::vector<collide::Shape<double>>>(gen_shape<double>()));
}

template <class T>
void world_ray_property() {
  const auto shapes = *rc::gen::container<std::vector<collide::Shape<T>>>(gen_shape<T>());
  const Vec2<T> o(T(*rc::gen::inRange(-48, 49)) / 4, T(*rc::gen::inRange(-48, 49)) / 4);
  const Vec2<T> d(T(*rc::gen::inRange(-16, 17)) / 2, T(*rc::gen::inRange(-16, 17)) / 2);
  check_world_ray<T>(shapes, o, d, T(*rc::gen::inRange(0, 9)) / 2);
}
RC_GTEST_PROP(BroadphaseWorld, FloatRaycastSameAsEveryShape, ()) {
  world_ray_property<float>();
}
RC_GTEST_PROP(BroadphaseWorld, DoubleRaycastSameAsEveryShape, ()) {
  world_ray_property<double>();
}

TEST(BroadphaseErrors, NamedErrorsForBadConfiguration) {
  EXPECT_THROW(bp::DynamicTree<float>(-1.0f), bp::BroadphaseError);
  EXPECT_THROW(bp::UniformGrid<double>(0.0), bp::BroadphaseError);
  try {
    bp::UniformGrid<float> g(std::numeric_limits<float>::quiet_NaN());
    FAIL() << "NaN cell size accepted";
  } catch (const bp::BroadphaseError& e) {
    EXPECT_EQ(e.code(), bp::BroadphaseErrc::BadCellSize);
  }
  bp::SweepAndPrune<double> s;
  try {
    s.raycast(Vec2<double>(0, 0), Vec2<double>(std::nan(""), 1), 1.0, [](bp::ProxyId, double) {});
    FAIL() << "NaN ray accepted";
  } catch (const bp::BroadphaseError& e) {
    EXPECT_EQ(e.code(), bp::BroadphaseErrc::BadRay);
  }
  EXPECT_THROW(s.remove(bp::ProxyId{}), bp::BroadphaseError);
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const int rc = RUN_ALL_TESTS();
  std::cout << "broadphase stats: sequences=" << g_stats.sequences << " commands=" << g_stats.commands
            << " pair_checks=" << g_stats.pairs_checked << " touching_pairs=" << g_stats.touching_pairs
            << " queries=" << g_stats.queries << " rays=" << g_stats.rays << " ray_hits=" << g_stats.ray_hits
            << " named_errors=" << g_stats.errors_checked << " updates=" << g_stats.updates
            << " began=" << g_stats.began << " ended=" << g_stats.ended << " filtered_out=" << g_stats.filtered_out
            << " world_steps=" << g_stats.world_steps << " world_events=" << g_stats.world_events << "\n";
  return rc;
}
