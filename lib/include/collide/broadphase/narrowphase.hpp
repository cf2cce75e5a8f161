#pragma once
/// @file broadphase/narrowphase.hpp
/// The narrowphase of a frame: contact() for every candidate pair of one list of placed shapes.
///
/// A frame's candidate pairs come from the broadphase in an order that mixes the kinds (a circle
/// against a box, then two capsules, then a polygon against a circle...). Each kind pair takes its
/// own contact path, so a mixed stream jumps between paths, and the branch predictor and the
/// instruction cache keep few of them. Narrowphase runs the pairs kind pair by kind pair instead:
/// one dispatch on the kinds per kind pair present, then that path over all its pairs.

#include "collide/broadphase/common.hpp"
#include "collide/broadphase/world.hpp"
#include "collide/registry.hpp"
#include "collide/transform.hpp"
#include "collide/transformed.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <variant>
#include <vector>

namespace collide::broadphase {

/// Contacts of many candidate pairs of one list of placed shapes (shape i placed by transform i).
///
/// Every answer is contact(shapes[a], transforms[a], shapes[b], transforms[b], speculative), bit for
/// bit, with its error contract; only the order of the calls differs: by the kind pair of
/// (shapes[a], shapes[b]) in the registry's order of kinds, and within a kind pair by the pair's
/// index.
///
/// Memory: two buffers of one entry per pair, grown to the largest batch seen and then kept, so a
/// frame with no more pairs than an earlier one allocates nothing. The shapes, transforms and
/// pairs are only read. A Narrowphase is scratch space: one per thread. A call made from f on the
/// Narrowphase that is calling f is refused (Reentered), since it would reuse the buffers the
/// outer call is reading; another Narrowphase may be used there.
template <Scalar T>
class Narrowphase {
 public:
  /// Calls f(i, contact) for every pair i of `pairs` whose shapes are in contact, grouped by kind
  /// pair (see the class). `speculative` is contact()'s: points are also reported for shapes
  /// apart by at most it; 0 (the default) reports overlapping shapes only.
  /// Errors (thrown before f is first called): BadPair when transforms.size()
  /// differs from shapes.size(), or a pair names a shape at or beyond shapes.size(); Reentered
  /// when called from f of a call on this Narrowphase.
  /// Whatever f throws leaves the call at once; the Narrowphase stays usable.
  template <class F>
  void for_each_contact(std::span<const Shape<T>> shapes, std::span<const Transform<T>> transforms,
                        std::span<const ShapePair> pairs, F&& f, T speculative = T(0)) {
    if (running_) throw BroadphaseError(BroadphaseErrc::Reentered, "Narrowphase called from its own callback");
    if (transforms.size() != shapes.size())
      throw BroadphaseError(BroadphaseErrc::BadPair, "shapes and transforms differ in length");
    running_ = true;
    const struct Done {
      bool& running;
      ~Done() { running = false; }
    } done{running_};
    const std::array<std::size_t, kRuns + 1> start = sort_by_kinds(shapes, pairs);
    for (std::size_t run = 0; run < kRuns; ++run) {
      if (start[run] == start[run + 1]) continue;
      const std::span<const std::size_t> members(order_.data() + start[run], start[run + 1] - start[run]);
      const ShapePair& first = pairs[members.front()];
      std::visit(
          [&](const auto& a0, const auto& b0) {
            using A = std::remove_cvref_t<decltype(a0)>;
            using B = std::remove_cvref_t<decltype(b0)>;
            for (std::size_t k = 0; k < members.size(); ++k) {
              if (k + kPrefetchAhead < members.size())
                prefetch_pair(shapes, transforms, pairs[members[k + kPrefetchAhead]]);
              const std::size_t i = members[k];
              const ShapePair& p = pairs[i];
              const A& a = *std::get_if<A>(&shapes[p.a]);
              const B& b = *std::get_if<B>(&shapes[p.b]);
              if (auto c = contact(a, transforms[p.a], b, transforms[p.b], speculative)) f(i, *c);
            }
          },
          shapes[first.a], shapes[first.b]);
    }
  }

  /// Grows the buffers to hold a batch of `pairs` pairs, so that no later call of at most that
  /// many allocates (the first frame's included).
  void reserve(std::size_t pairs) {
    order_.reserve(pairs);
    kinds_.reserve(pairs);
  }

  /// Pairs a batch may have without the buffers growing.
  std::size_t capacity() const noexcept { return std::min(order_.capacity(), kinds_.capacity()); }

 private:
  static constexpr std::size_t kRuns = kKindCount * kKindCount;
  static_assert(kRuns <= 256, "kinds_ holds a kind pair in one byte");

  /// How many pairs ahead the shapes and transforms are fetched into the cache: the pairs visit the
  /// shapes in no order of their addresses, a large scene's shapes do not fit in the cache, and a
  /// few contacts take about as long as a load from memory (4 measured faster than 8 at 10,000).
  static constexpr std::size_t kPrefetchAhead = 4;

  /// Asks the cache for both shapes of pair p (a variant's first line and its last, where the
  /// standard library keeps the index of the alternative) and both transforms.
  static void prefetch_pair(std::span<const Shape<T>> shapes, std::span<const Transform<T>> transforms,
                            const ShapePair& p) noexcept {
#if defined(__GNUC__) || defined(__clang__)
    for (const std::size_t s : {p.a, p.b}) {
      const char* bytes = reinterpret_cast<const char*>(&shapes[s]);
      __builtin_prefetch(bytes);
      __builtin_prefetch(bytes + sizeof(Shape<T>) - 1);
      __builtin_prefetch(&transforms[s]);
    }
#else
    static_cast<void>(shapes);
    static_cast<void>(transforms);
    static_cast<void>(p);
#endif
  }

  /// A counting sort of the pairs' indices by kind pair into order_ (stable), refusing a pair
  /// beyond the list on the way (BadPair); returns where each kind pair's run begins, and its end
  /// as the next run's beginning.
  std::array<std::size_t, kRuns + 1> sort_by_kinds(std::span<const Shape<T>> shapes, std::span<const ShapePair> pairs) {
    const std::size_t n = pairs.size();
    if (order_.size() < n) {
      order_.resize(n);
      kinds_.resize(n);
    }
    std::array<std::size_t, kRuns + 1> start{};
    for (std::size_t i = 0; i < n; ++i) {
      const ShapePair& p = pairs[i];
      if (p.a >= shapes.size() || p.b >= shapes.size())
        throw BroadphaseError(BroadphaseErrc::BadPair, "a pair names a shape beyond the list");
      const auto run =
          static_cast<std::uint8_t>(std::size_t(kind(shapes[p.a])) * kKindCount + std::size_t(kind(shapes[p.b])));
      kinds_[i] = run;
      ++start[run + 1];
    }
    for (std::size_t run = 0; run < kRuns; ++run) start[run + 1] += start[run];
    std::array<std::size_t, kRuns> next{};
    std::copy(start.begin(), start.end() - 1, next.begin());
    for (std::size_t i = 0; i < n; ++i) order_[next[kinds_[i]]++] = i;
    return start;
  }

  std::vector<std::size_t> order_;   ///< pair indices, sorted by kind pair
  std::vector<std::uint8_t> kinds_;  ///< each pair's kind pair, a * kinds + b
  bool running_ = false;             ///< a batch is calling f
};

}  // namespace collide::broadphase
