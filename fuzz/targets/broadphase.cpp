// Fuzz target broadphase: sequences of add / move / remove / query / raycast / pairs on one of the
// three broadphase structures, each answer checked against brute force over the stored boxes:
// - query(box) reports exactly the live proxies whose stored box meets the box (closed),
// - raycast reports exactly the live proxies that ray_hits_box() hits, with the same t,
// - pairs() and for_each_pair() report exactly the overlapping pairs whose filters accept each
//   other, each once (Sorted: in ascending order); raycast_closest() gives the smallest t,
// - every answer honours the category / mask filters of the proxies and of the query,
// - stale handles throw InvalidProxy, raw corners that are not a box throw BadBox and change
//   nothing, invalid rays throw BadRay, invalid margins / cell sizes are refused by name.
//
// Input: flags byte (bit 0: double; (byte >> 1) % 3: DynamicTree, SweepAndPrune, UniformGrid),
// the structure's parameter (tree margin or grid cell size; unused by sweep-and-prune), then up
// to kMaxOps operations until the input ends: an op byte (% 7) and its operands (raw scalars).
// The op byte's quotient (/ 7) picks a filter: for add and move the proxy's (move then calls
// set_filter), for query and raycast the query's; 0 keeps the default.

#include "collide/broadphase.hpp"
#include "collide/fuzz/decode.hpp"
#include "collide/fuzz/failure.hpp"
#include "collide/fuzz/reader.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#if defined(COLLIDE_FUZZ_ENGINE)
#include "collide/fuzz/mutator.hpp"
#endif

namespace {

using namespace collide;
using namespace collide::fuzz;
using namespace collide::broadphase;

constexpr int kMaxOps = 64;

/// The brute-force model: every handle ever issued, its stored box, whether it is live.
template <Scalar T>
struct Entry {
  ProxyId id;
  Box<T> box;
  bool live;
  Filter filter{};
};

/// A proxy's filter from the op byte's quotient (1..36): one of three categories, a mask of
/// three bits (0 pairs with nothing, 7 with everything); 0 is the default filter.
Filter proxy_filter(int bits) {
  if (bits == 0) return {};
  const std::uint32_t mask = std::uint32_t(bits / 3) % 8;
  return {1u << (bits % 3), mask == 7 ? 0xffffffffu : mask};
}

/// A query's filter from the op byte's quotient: 0 accepts every proxy.
Filter query_filter(int bits) {
  if (bits == 0) return Filter::everything();
  return {std::uint32_t(bits % 8), std::uint32_t(bits / 8) % 8 == 7 ? 0xffffffffu : std::uint32_t(bits / 8) % 8};
}

std::string id_text(ProxyId id) {
  return cat("#", std::to_string(id.index), "/g", std::to_string(id.generation));
}

template <class F>
std::optional<BroadphaseErrc> error_of(F&& f) {
  try {
    f();
  } catch (const BroadphaseError& e) {
    return e.code();
  }
  return std::nullopt;
}

template <Scalar T>
struct Corners {
  Vec2<T> min, max;
  std::optional<Box<T>> box() const {
    const Expected<Aabb<T>> a = Aabb<T>::make(min, max);
    if (!a) return std::nullopt;
    return box_of(a.value());
  }
};

template <Scalar T>
Corners<T> read_corners(Reader& r, int group) {
  r.set_group(group);
  const Vec2<T> lo = r.point<T>();
  const Vec2<T> hi = r.point<T>();
  return {lo, hi};
}

template <Scalar T, class BP>
void check_pairs(const BP& bp, const std::vector<Entry<T>>& model, PairOrder order) {
  std::vector<ProxyPair> want;
  for (std::size_t i = 0; i < model.size(); ++i) {
    for (std::size_t j = i + 1; j < model.size(); ++j) {
      if (model[i].live && model[j].live && boxes_overlap(model[i].box, model[j].box) &&
          accepts(model[i].filter, model[j].filter)) {
        want.push_back(ordered_pair(model[i].id, model[j].id));
      }
    }
  }
  std::sort(want.begin(), want.end());
  std::vector<ProxyPair> got = bp.pairs(order);
  for (const ProxyPair& p : got) {
    if (!(p.a.index < p.b.index)) fail_raw("pairs(): pair ", id_text(p.a), "-", id_text(p.b), " not ordered");
  }
  if (order == PairOrder::Sorted) {
    if (!std::is_sorted(got.begin(), got.end())) fail_raw("pairs(Sorted) is not sorted");
  } else {
    std::sort(got.begin(), got.end());
  }
  if (got != want) {
    fail_raw("pairs(): ", std::to_string(got.size()), " pairs, brute force finds ", std::to_string(want.size()));
  }
  std::vector<ProxyPair> walked;
  bp.for_each_pair([&](ProxyId a, ProxyId b) { walked.push_back(ordered_pair(a, b)); });
  std::sort(walked.begin(), walked.end());
  if (walked != want) {
    fail_raw("for_each_pair(): ", std::to_string(walked.size()), " pairs, brute force finds ",
             std::to_string(want.size()));
  }
}

template <Scalar T, class BP>
void run_ops(BP& bp, Reader& r) {
  std::vector<Entry<T>> model;
  auto pick_entry = [&](std::uint8_t b) -> Entry<T>* { return model.empty() ? nullptr : &model[b % model.size()]; };
  auto live_count = [&] {
    return std::size_t(std::count_if(model.begin(), model.end(), [](const Entry<T>& e) { return e.live; }));
  };
  for (int op_index = 0; op_index < kMaxOps && !r.exhausted(); ++op_index) {
    const int group = op_index + 1;
    const std::uint8_t op_byte = r.byte();
    const int op = op_byte % 7, bits = op_byte / 7;
    if (op == 0) {  // add from raw corners
      const Corners<T> c = read_corners<T>(r, group);
      const std::optional<Box<T>> box = c.box();
      std::optional<ProxyId> id;
      const auto err = error_of([&] { id = bp.add(c.min, c.max, model.size(), proxy_filter(bits)); });
      if (!box) {
        if (err != BroadphaseErrc::BadBox) fail_raw("add() with invalid corners was not refused with BadBox");
        continue;
      }
      if (err) fail_raw("add() refused a valid box");
      for (const Entry<T>& e : model) {
        if (e.live && e.id == *id) fail_raw("add() issued the live handle ", id_text(*id), " again");
        if (!e.live && e.id == *id) fail_raw("add() reissued the removed handle ", id_text(*id));
      }
      model.push_back({*id, *box, true, proxy_filter(bits)});
    } else if (op == 1 || op == 2) {  // move (raw corners) / remove, possibly through a stale handle
      Entry<T>* e = pick_entry(r.byte());
      const Corners<T> c = op == 1 ? read_corners<T>(r, group) : Corners<T>{};
      if (e == nullptr) continue;
      const std::optional<Box<T>> box = c.box();
      const auto err = op == 1 ? error_of([&] { bp.move(e->id, c.min, c.max); }) : error_of([&] { bp.remove(e->id); });
      if (!e->live) {
        if (err != BroadphaseErrc::InvalidProxy)
          fail_raw("a stale handle ", id_text(e->id), " was not refused with InvalidProxy");
        continue;
      }
      if (op == 2) {
        if (err) fail_raw("remove() refused a live handle");
        e->live = false;
        continue;
      }
      if (!box) {
        if (err != BroadphaseErrc::BadBox) fail_raw("move() with invalid corners was not refused with BadBox");
        continue;
      }
      if (err) fail_raw("move() refused a valid box");
      e->box = *box;
      if (bits != 0) {
        bp.set_filter(e->id, proxy_filter(bits));
        e->filter = proxy_filter(bits);
      }
    } else if (op == 3) {  // query
      const Corners<T> c = read_corners<T>(r, group);
      const std::optional<Box<T>> box = c.box();
      if (!box) continue;
      std::vector<ProxyId> got, want;
      const Filter qf = query_filter(bits);
      bp.query(
          Aabb<T>::make(c.min, c.max).value(), [&](ProxyId id) { got.push_back(id); }, qf);
      for (const Entry<T>& e : model) {
        if (e.live && boxes_overlap(e.box, *box) && accepts(e.filter, qf)) want.push_back(e.id);
      }
      std::sort(got.begin(), got.end());
      std::sort(want.begin(), want.end());
      if (got != want) {
        fail_raw("query(): ", std::to_string(got.size()), " proxies, brute force finds ", std::to_string(want.size()));
      }
    } else if (op == 4) {  // raycast
      r.set_group(group);
      const Vec2<T> origin = r.point<T>();
      const T dx = r.scalar<T>(Role::Other), dy = r.scalar<T>(Role::Other), max_t = r.scalar<T>(Role::Size);
      const Vec2<T> dir(dx, dy);
      std::vector<std::pair<ProxyId, Calc>> got, want;
      const Filter qf = query_filter(bits);
      const auto err = error_of([&] {
        bp.raycast(
            origin, dir, max_t, [&](ProxyId id, Calc t) { got.emplace_back(id, t); }, qf);
      });
      const bool valid = origin.allFinite() && dir.allFinite() && std::isfinite(max_t) && max_t >= T(0);
      if (!valid) {
        if (err != BroadphaseErrc::BadRay) fail_raw("raycast() with an invalid ray was not refused with BadRay");
        continue;
      }
      if (err) fail_raw("raycast() refused a valid ray");
      const RaySegment<T> ray = make_ray(origin, dir, max_t);
      for (const Entry<T>& e : model) {
        const Calc t = e.live && accepts(e.filter, qf) ? ray_hits_box(ray, e.box) : -1;
        if (t >= 0) want.emplace_back(e.id, t);
      }
      // Closest hit: the smallest t, ties to the lowest slot index.
      std::optional<std::pair<ProxyId, Calc>> nearest;
      for (const auto& h : want) {
        if (!nearest || h.second < nearest->second ||
            (h.second == nearest->second && h.first.index < nearest->first.index))
          nearest = h;
      }
      const std::optional<ProxyHit> closest = bp.raycast_closest(origin, dir, max_t, qf);
      if (closest.has_value() != nearest.has_value() ||
          (closest && (closest->id != nearest->first || closest->t != nearest->second)))
        fail_raw("raycast_closest() differs from the nearest brute-force hit");
      std::sort(got.begin(), got.end());
      std::sort(want.begin(), want.end());
      if (got != want) {
        // The first proxy the two lists disagree on, with its box and both answers.
        std::string first;
        for (const Entry<T>& e : model) {
          const auto find = [&](const std::vector<std::pair<ProxyId, Calc>>& v) {
            const auto it = std::find_if(v.begin(), v.end(), [&](const auto& h) { return h.first == e.id; });
            return it == v.end() ? std::string("no hit") : cat("t ", format_value(it->second));
          };
          const std::string g = find(got), w = find(want);
          if (g == w) continue;
          first = cat("; first difference: ", id_text(e.id), " box ", format_point(widen(e.box.min)), " - ",
                      format_point(widen(e.box.max)), ": raycast ", g, ", brute force ", w);
          break;
        }
        fail_raw("raycast(): ", std::to_string(got.size()), " hits, brute force finds ", std::to_string(want.size()),
                 "; ray ", format_point(widen(origin)), " + t ", format_point(widen(dir)), ", max_t ",
                 format_value(max_t), first);
      }
    } else {
      check_pairs<T>(bp, model, op == 5 ? PairOrder::Sorted : PairOrder::Any);
    }
    if (bp.size() != live_count()) fail_raw("size() differs from the number of live proxies");
    for (const Entry<T>& e : model) {
      if (bp.contains(e.id) != e.live) fail_raw("contains(", id_text(e.id), ") is wrong");
      if (!e.live) continue;
      const Aabb<T> stored = bp.box(e.id);
      if (stored.min() != e.box.min || stored.max() != e.box.max) fail_raw("box(", id_text(e.id), ") changed");
    }
  }
  check_pairs<T>(bp, model, PairOrder::Sorted);
}

template <Scalar T>
void run(Reader& r, std::uint8_t flags) {
  const int structure = (flags >> 1) % 3;
  r.set_group(0);
  const T param = r.scalar<T>(Role::Size);
  if (structure == 1) {
    SweepAndPrune<T> bp;
    run_ops<T>(bp, r);
    return;
  }
  const bool valid_margin = param >= T(0) && param <= max_magnitude<T>();
  const bool valid_cell = param > T(0) && std::isfinite(param);
  if (structure == 0) {
    std::optional<DynamicTree<T>> bp;
    const auto err = error_of([&] { bp.emplace(param); });
    if (err != (valid_margin ? std::nullopt : std::optional(BroadphaseErrc::BadMargin))) {
      fail_raw("DynamicTree(margin) accepted an invalid margin or refused a valid one");
    }
    if (bp) run_ops<T>(*bp, r);
  } else {
    std::optional<UniformGrid<T>> bp;
    const auto err = error_of([&] { bp.emplace(param); });
    if (err != (valid_cell ? std::nullopt : std::optional(BroadphaseErrc::BadCellSize))) {
      fail_raw("UniformGrid(cell) accepted an invalid cell size or refused a valid one");
    }
    if (bp) run_ops<T>(*bp, r);
  }
}

/// Reads the input as the target does, without running anything (for the mutator's layout).
[[maybe_unused]] void parse_only(Reader& r) {
  const std::uint8_t flags = r.byte();
  auto skim = [&]<Scalar T>() {
    r.set_group(0);
    r.scalar<T>(Role::Size);
    for (int op_index = 0; op_index < kMaxOps && !r.exhausted(); ++op_index) {
      const int op = r.byte() % 7;
      if (op == 0 || op == 3) {
        read_corners<T>(r, op_index + 1);
      } else if (op == 1) {
        r.byte();
        read_corners<T>(r, op_index + 1);
      } else if (op == 2) {
        r.byte();
      } else if (op == 4) {
        r.set_group(op_index + 1);
        r.point<T>();
        r.scalar<T>(Role::Other);
        r.scalar<T>(Role::Other);
        r.scalar<T>(Role::Size);
      }
    }
  };
  if ((flags & 1) != 0) {
    skim.template operator()<double>();
  } else {
    skim.template operator()<float>();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  current_input() = {data, size};
  Reader r(data, size);
  const std::uint8_t flags = r.byte();
  if ((flags & 1) != 0) {
    run<double>(r, flags);
  } else {
    run<float>(r, flags);
  }
  return 0;
}

#if defined(COLLIDE_FUZZ_ENGINE)
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  return mutate_fields(
      data, size, max_size, seed, [](Reader& r) { parse_only(r); }, MutatorOptions{1, false});
}
#endif
