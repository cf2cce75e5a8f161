// The law on a scene of shapes: the world helpers and pairs_involving() agree with the pair
// queries taken one pair at a time.

#include "support.hpp"

#include "collide/broadphase.hpp"

#include <algorithm>
#include <vector>

namespace collide::laws {

using detail::describe;

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
      same = contacts[k].a == want[k].a && contacts[k].b == want[k].b && one &&
             one->normal == contacts[k].contact.normal && one->depth == contacts[k].contact.depth;
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
    }
  } catch (const std::exception& e) {
    fail("no exception", std::string("exception: ") + e.what());
  }
  return v;
}

template Verdict scene<float>(const Shape<float>&);
template Verdict scene<double>(const Shape<double>&);

}  // namespace collide::laws
