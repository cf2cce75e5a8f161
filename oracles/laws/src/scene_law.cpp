// The law on a scene of shapes: the world helpers, pairs_involving() and the Narrowphase agree
// with the pair queries taken one pair at a time.

#include "support.hpp"

#include "collide/broadphase.hpp"
#include "collide/broadphase/narrowphase.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace collide::laws {

using detail::describe;

namespace {

/// Whether two contacts hold the same bits in every field a solver reads (the valid entries of
/// points, ids and separations).
template <Scalar T>
bool same_contact(const Contact<T>& x, const Contact<T>& y) {
  using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
  const auto same = [](T u, T w) { return std::bit_cast<Bits>(u) == std::bit_cast<Bits>(w); };
  const auto same_vec = [&](const Vec2<T>& u, const Vec2<T>& w) { return same(u.x(), w.x()) && same(u.y(), w.y()); };
  if (x.count != y.count || !same_vec(x.normal, y.normal) || !same(x.depth, y.depth)) return false;
  for (int k = 0; k < std::min(x.count, 2); ++k) {
    if (!same_vec(x.points[k], y.points[k]) || x.ids[k] != y.ids[k] || !same(x.separations[k], y.separations[k]))
      return false;
  }
  return true;
}

/// What one check of the Narrowphase required and what it got; nullopt when it held.
using Failure = std::optional<std::pair<std::string, std::string>>;

/// Whether f is refused by a BroadphaseError of code `want` before its callback saw any contact
/// (`calls` counts them); `what` says which refusal, for the account.
template <class F>
Failure refuses(broadphase::BroadphaseErrc want, const std::string& what, const std::size_t& calls, F&& f) {
  try {
    f();
  } catch (const broadphase::BroadphaseError& e) {
    if (e.code() == want && calls == 0) return std::nullopt;
    return std::pair{std::string(broadphase::name(want)) + " before any contact, " + what,
                     std::string(broadphase::name(e.code())) + " after " + std::to_string(calls) + " contacts"};
  }
  return std::pair{std::string(broadphase::name(want)) + ", " + what, "no error"};
}

/// Narrowphase::for_each_contact over `pairs` of `shapes` placed by `xs`: it reports exactly the
/// pairs contact() finds (with `speculative`), each once with contact()'s bits, kind pair by kind
/// pair in the registry's order and by index within one; a call from its callback is refused
/// (Reentered) without disturbing the batch, while another Narrowphase may be used there.
template <Scalar T>
Failure judge_batch(broadphase::Narrowphase<T>& narrow, std::span<const Shape<T>> shapes,
                    std::span<const Transform<T>> xs, std::span<const broadphase::ShapePair> pairs, T speculative) {
  const auto run_of = [&](const broadphase::ShapePair& p) {
    return std::size_t(kind(shapes[p.a])) * kKindCount + std::size_t(kind(shapes[p.b]));
  };
  std::vector<std::size_t> order(pairs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return run_of(pairs[i]) < run_of(pairs[j]); });
  std::vector<std::pair<std::size_t, Contact<T>>> want;
  for (const std::size_t i : order) {
    const broadphase::ShapePair& p = pairs[i];
    if (const auto c = contact(shapes[p.a], xs[p.a], shapes[p.b], xs[p.b], speculative)) want.emplace_back(i, *c);
  }
  std::vector<std::pair<std::size_t, Contact<T>>> got;
  Failure inner;
  narrow.for_each_contact(
      shapes, xs, pairs,
      [&](std::size_t i, const Contact<T>& c) {
        if (got.empty()) {
          std::size_t calls = 0;
          inner = refuses(broadphase::BroadphaseErrc::Reentered, "for a call from its own callback", calls, [&] {
            narrow.for_each_contact(
                shapes, xs, pairs, [&](std::size_t, const Contact<T>&) { ++calls; }, speculative);
          });
          broadphase::Narrowphase<T> other;
          std::size_t others = 0;
          other.for_each_contact(
              shapes, xs, pairs.subspan(i, 1), [&](std::size_t, const Contact<T>&) { ++others; }, speculative);
          if (!inner && others != 1)
            inner = std::pair{std::string("another Narrowphase, called from the callback, reporting the pair once"),
                              std::to_string(others) + " reports"};
        }
        got.emplace_back(i, c);
      },
      speculative);
  if (inner) return inner;
  for (std::size_t k = 0; k < std::max(want.size(), got.size()); ++k) {
    if (k < want.size() && k < got.size() && want[k].first == got[k].first &&
        same_contact(want[k].second, got[k].second))
      continue;
    const auto at = [](const auto& list, std::size_t k) {
      return k < list.size() ? "pair " + std::to_string(list[k].first) : std::string("nothing");
    };
    return std::pair{std::to_string(want.size()) +
                         " contacts, as contact() one pair at a time in kind-pair order; report " + std::to_string(k) +
                         ": " + at(want, k),
                     std::to_string(got.size()) + " from the Narrowphase; report " + std::to_string(k) + ": " +
                         at(got, k) + (k < want.size() && k < got.size() ? " (or other bits)" : "")};
  }
  return std::nullopt;
}

/// The Narrowphase on the scene's shapes and compounds of neighbouring shapes (so that compounds
/// meet compounds), every ordered pair with identities, then every pair once under one turned
/// transform with a speculative distance (the same object, a smaller batch); and the batches it
/// must refuse: a pair naming a shape beyond the list, in either place, and transforms that
/// differ in number from the shapes.
template <Scalar T>
Failure judge_narrowphase(const std::vector<Primitive<T>>& prims, T size) {
  std::vector<Shape<T>> shapes;
  for (const Primitive<T>& p : prims) shapes.push_back(to_shape(p));
  for (std::size_t i = 0; i + 1 < prims.size() && i < 3; ++i)
    shapes.push_back(Compound<T>(std::vector<Primitive<T>>{prims[i], prims[i + 1]}));
  const std::size_t n = shapes.size();
  std::vector<broadphase::ShapePair> ordered, once;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i != j) ordered.push_back({i, j});
      if (i < j) once.push_back({i, j});
    }
  }
  broadphase::Narrowphase<T> narrow;
  const std::vector<Transform<T>> identities(n);
  if (Failure f = judge_batch<T>(narrow, shapes, identities, ordered, T(0))) return f;
  const std::vector<Transform<T>> turned(n, Transform<T>::make(Vec2<T>(T(0.25), T(-0.5)), T(0.5)).value());
  const T speculative = size > 0 ? std::ldexp(T(1), std::ilogb(size) - 3) : T(0);
  if (Failure f = judge_batch<T>(narrow, shapes, turned, once, speculative)) return f;
  std::size_t calls = 0;
  const auto count = [&](std::size_t, const Contact<T>&) { ++calls; };
  for (const broadphase::ShapePair beyond : {broadphase::ShapePair{0, n}, broadphase::ShapePair{n, 0}}) {
    std::vector<broadphase::ShapePair> bad = ordered;
    bad.push_back(beyond);
    const std::string what = "for the pair (" + std::to_string(beyond.a) + ", " + std::to_string(beyond.b) + ") of " +
                             std::to_string(n) + " shapes";
    if (Failure f = refuses(broadphase::BroadphaseErrc::BadPair, what, calls,
                            [&] { narrow.for_each_contact(shapes, identities, bad, count); }))
      return f;
  }
  const std::span<const Transform<T>> fewer(identities.data(), n - 1);
  return refuses(broadphase::BroadphaseErrc::BadPair, "for one transform fewer than shapes", calls,
                 [&] { narrow.for_each_contact(shapes, fewer, ordered, count); });
}

}  // namespace

template <Scalar T>
Verdict scene(const Shape<T>& group) {
  Verdict v;
  auto fail = [&](std::string expected, std::string got) {
    v.ok = false;
    v.expected = std::move(expected);
    v.got = std::move(got);
    v.account = "expected " + v.expected + "; got " + v.got + "; scene = " + describe(group);
  };
  try {
    const auto prims = detail::primitives_of(group);
    std::vector<Shape<T>> shapes;
    for (const Primitive<T>& p : prims) shapes.push_back(to_shape(p));
    const std::size_t n = shapes.size();
    // One pair at a time: which shapes overlap, and which stored boxes meet.
    std::vector<broadphase::ShapePair> want;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (overlaps(shapes[i], shapes[j])) want.push_back({i, j});
    v.account = std::to_string(n) + " shapes, " + std::to_string(want.size()) + " overlapping pairs";
    const std::span<const Shape<T>> all(shapes);
    const auto got = broadphase::find_overlapping_shapes<T>(all);
    if (got != want) {
      fail(std::to_string(want.size()) + " overlapping pairs, as overlaps() one pair at a time",
           std::to_string(got.size()) + " pairs from find_overlapping_shapes");
      return v;
    }
    const auto contacts = broadphase::find_contacts<T>(all);
    bool same = contacts.size() == want.size();
    for (std::size_t k = 0; same && k < contacts.size(); ++k) {
      const auto one = contact(shapes[contacts[k].a], shapes[contacts[k].b]);
      same = contacts[k].a == want[k].a && contacts[k].b == want[k].b && one && same_contact(*one, contacts[k].contact);
    }
    if (!same) {
      fail("one contact per overlapping pair, identical to contact()",
           std::to_string(contacts.size()) + " contacts from find_contacts");
      return v;
    }
    // pairs_involving: the pairs of meeting boxes with at least one of the first half of the proxies.
    broadphase::DynamicTree<T> tree;
    std::vector<broadphase::ProxyId> ids;
    for (std::size_t i = 0; i < n; ++i) ids.push_back(tree.add(bounds(shapes[i]), i));
    const std::vector<broadphase::ProxyId> moved(ids.begin(), ids.begin() + std::ptrdiff_t((n + 1) / 2));
    std::vector<broadphase::ProxyPair> expect;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const Aabb<T> bi = bounds(shapes[i]), bj = bounds(shapes[j]);
        const bool meet = !(bi.max().x() < bj.min().x() || bj.max().x() < bi.min().x() || bi.max().y() < bj.min().y() ||
                            bj.max().y() < bi.min().y());
        if (meet && (i < moved.size() || j < moved.size()))
          expect.push_back(ids[i].index < ids[j].index ? broadphase::ProxyPair{ids[i], ids[j]}
                                                       : broadphase::ProxyPair{ids[j], ids[i]});
      }
    }
    std::sort(expect.begin(), expect.end());
    const auto involving =
        broadphase::pairs_involving(tree, std::span<const broadphase::ProxyId>(moved), broadphase::PairOrder::Sorted);
    if (involving != expect) {
      fail(std::to_string(expect.size()) + " box pairs involving the first " + std::to_string(moved.size()) +
               " proxies, each once",
           std::to_string(involving.size()) + " from pairs_involving");
      return v;
    }
    const Aabb<T> box = bounds(group);
    if (const Failure f = judge_narrowphase(prims, (box.max() - box.min()).maxCoeff())) fail(f->first, f->second);
  } catch (const std::exception& e) {
    fail("no exception", std::string("exception: ") + e.what());
  }
  return v;
}

template Verdict scene<float>(const Shape<float>&);
template Verdict scene<double>(const Shape<double>&);

}  // namespace collide::laws
