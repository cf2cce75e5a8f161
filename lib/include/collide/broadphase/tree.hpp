#pragma once
/// @file broadphase/tree.hpp
/// Dynamic AABB tree: leaves hold fattened boxes (stretched ahead along the last displacement
/// when a move leaves them) so small moves cost nothing, inner nodes the union
/// of their children; insertion descends by the smallest perimeter growth and every node on the
/// path back up whose children's heights differ by 2 or more is rotated (the taller child moves up).

#include "collide/broadphase/common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace collide::broadphase {

/// Dynamic AABB tree over closed boxes of scalar T.
///
/// Pairs and queries are decided on the stored (unfattened) boxes: fattening only adds candidates.
/// Const members are re-entrant and may run on many threads at once (see ProxyOps).
template <Scalar T>
class DynamicTree : public ProxyOps<DynamicTree<T>, T> {
 public:
  using ProxyOps<DynamicTree<T>, T>::raycast;
  /// margin: how far each stored box is grown on every side (world units). A move that keeps
  /// the new box inside the fat box does not touch the tree. Errors: BadMargin.
  explicit DynamicTree(T margin = T(0.1)) : margin_(checked_margin(margin)) {}

  /// Adds one proxy per box (user data first_user + i, one filter for all) and returns their
  /// handles in order. Into an empty tree the leaves are built top down (median split on the
  /// longer axis of the box centres), faster than adding one by one and as good a tree;
  /// otherwise they are inserted one by one. Errors: TooManyProxies (nothing is added).
  std::vector<ProxyId> add_batch(std::span<const Aabb<T>> boxes, std::uint64_t first_user = 0, Filter filter = {}) {
    std::vector<ProxyId> ids;
    ids.reserve(boxes.size());
    if (slots_.capacity() + boxes.size() >= std::numeric_limits<std::uint32_t>::max() - 1)
      throw BroadphaseError(BroadphaseErrc::TooManyProxies, "too many proxies");
    if (root_ >= 0 || boxes.size() < 2) {
      for (std::size_t i = 0; i < boxes.size(); ++i) ids.push_back(add_box(box_of(boxes[i]), first_user + i, filter));
      return ids;
    }
    nodes_.reserve(nodes_.size() + 2 * boxes.size());
    slots_.reserve(slots_.capacity() + boxes.size());
    std::vector<Centred> leaves;
    leaves.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const Box<T> b = box_of(boxes[i]);
      const ProxyId id = slots_.allocate(b, first_user + i, filter);
      const std::int32_t leaf = alloc_node();
      node(leaf).box = fattened(b, margin_);
      node(leaf).slot = id.index;
      slots_[id.index].extra.leaf = leaf;
      leaves.push_back({{Calc(b.min.x()) + Calc(b.max.x()), Calc(b.min.y()) + Calc(b.max.y())}, leaf});
      ids.push_back(id);
    }
    root_ = build_top_down(leaves.data(), leaves.data() + leaves.size());
    node(root_).parent = -1;
    return ids;
  }

  /// Moves like move() and tells whether the proxy left its fat box (and got a new one), so that
  /// a caller caching fat-box neighbours (PairTracker) knows whose to refresh. Errors: InvalidProxy.
  bool move_fat(ProxyId id, const Aabb<T>& box) { return move_box(id, box_of(box)); }

  /// Calls f(ProxyId) for every other proxy whose fat box meets id's fat box (closed): a superset
  /// of the proxies whose stored boxes meet id's. Errors: InvalidProxy.
  template <class F>
  void query_fat(ProxyId id, F&& f) const {
    const std::uint32_t self = slots_.check(id);
    const Box<T> fat = node(slots_[self].extra.leaf).box;
    visit([&](const Box<T>& b) { return boxes_overlap(b, fat); },
          [&](std::uint32_t s) { return s == self || call_continue(f, slots_.id(s)); });
  }

  /// Fat box of a proxy (contains box(id)). Errors: InvalidProxy.
  Aabb<T> fat_box(ProxyId id) const {
    const Box<T>& b = node(slots_[slots_.check(id)].extra.leaf).box;
    return Aabb<T>::make(b.min, b.max).value();
  }

  /// Calls f(ProxyId) for every proxy whose stored box meets q (closed) and whose filter accepts
  /// `filter`. f may return bool; false stops the query. Re-entrant and thread-safe (see ProxyOps).
  template <class F>
  void query(const Aabb<T>& q, F&& f, Filter filter = Filter::everything()) const {
    const Box<T> qb = box_of(q);
    visit([&](const Box<T>& b) { return boxes_overlap(b, qb); },
          [&](std::uint32_t s) {
            if (!boxes_overlap(slots_[s].box, qb) || !accepts(slots_[s].filter, filter)) return true;
            return call_continue(f, slots_.id(s));
          });
  }

  /// Calls f(ProxyId, t) for every proxy whose stored box meets the segment origin + t direction,
  /// t in [0, max_t], and whose filter accepts `filter`; t is the entry parameter (0 if origin is
  /// inside). f may return bool; false stops. Errors: BadRay.
  template <class F>
  void raycast(const Vec2<T>& origin, const Vec2<T>& direction, T max_t, F&& f,
               Filter filter = Filter::everything()) const {
    const RaySegment<T> r = make_ray(origin, direction, max_t);
    visit([&](const Box<T>& b) { return ray_hits_box(r, b) >= 0; },
          [&](std::uint32_t s) {
            if (!accepts(slots_[s].filter, filter)) return true;
            const Calc t = ray_hits_box(r, slots_[s].box);
            return t < 0 || call_continue(f, slots_.id(s), t);
          });
  }

  /// Calls f(ProxyId a, ProxyId b) once for every pair of proxies whose stored boxes overlap
  /// (closed) and whose filters accept each other; f may return bool, false stops. Builds no
  /// list, so any number of pairs can be visited in constant memory beyond the traversal stack.
  template <class F>
  void for_each_pair(F&& f) const {
    walk_leaf_pairs([&](const Node& a, const Node& b) {
      const auto& sa = slots_[a.slot];
      const auto& sb = slots_[b.slot];
      const bool hit = boxes_overlap(sa.box, sb.box);
      return !hit || !accepts(sa.filter, sb.filter) || call_continue(f, slots_.id(a.slot), slots_.id(b.slot));
    });
  }

  /// Calls f(ProxyId a, ProxyId b) once for every pair of proxies whose fat boxes meet (closed),
  /// filters ignored: all the neighbours query_fat() finds, in one walk. f may return bool, false
  /// stops.
  template <class F>
  void for_each_fat_pair(F&& f) const {
    walk_leaf_pairs(
        [&](const Node& a, const Node& b) { return call_continue(f, slots_.id(a.slot), slots_.id(b.slot)); });
  }

  /// Rebuilds the tree from its leaves top down, as add_batch() builds one (median splits of the
  /// fat boxes' centres), with every node stored after its parent: after many one-by-one
  /// insertions a query then visits fewer nodes, read closer together. Handles, stored and fat
  /// boxes and every answer stay as they were. Allocates the new nodes.
  void rebuild() {
    if (root_ < 0) return;
    std::vector<Node> old;
    old.swap(nodes_);
    free_nodes_.clear();
    std::vector<Centred> leaves;
    leaves.reserve(slots_.size());
    for (std::uint32_t s = 0; s < slots_.capacity(); ++s) {
      if (!slots_[s].live) continue;
      const std::int32_t leaf = slots_[s].extra.leaf;
      const Box<T>& fat = old[std::size_t(leaf)].box;
      leaves.push_back({{Calc(fat.min.x()) + Calc(fat.max.x()), Calc(fat.min.y()) + Calc(fat.max.y())}, leaf});
    }
    nodes_.reserve(2 * leaves.size());  // no reallocation while build_copy holds references
    root_ = build_copy(leaves.data(), leaves.data() + leaves.size(), old, -1);
  }

  /// Height of the tree (0 for one leaf, -1 when empty).
  int height() const noexcept { return root_ < 0 ? -1 : node(root_).height; }

  /// Checks the structure: parent links, heights, each inner box the union of its children, each
  /// leaf's fat box containing its stored box, leaf count == size(). (Balance is not strict: a new
  /// leaf may pair with a tall subtree when that is cheapest; rotations then shorten the path.)
  bool check_invariants() const {
    if (root_ < 0) return slots_.size() == 0;
    if (node(root_).parent != -1) return false;
    std::size_t leaves = 0;
    std::vector<std::int32_t> st{root_};
    while (!st.empty()) {
      const std::int32_t i = st.back();
      st.pop_back();
      const Node& n = node(i);
      if (n.leaf()) {
        ++leaves;
        if (n.height != 0 || !box_contains(n.box, slots_[n.slot].box) || slots_[n.slot].extra.leaf != i) return false;
        continue;
      }
      const Node &c1 = node(n.child1), &c2 = node(n.child2);
      if (c1.parent != i || c2.parent != i) return false;
      if (n.height != 1 + std::max(c1.height, c2.height)) return false;
      const Box<T> u = merged(c1.box, c2.box);
      if (u.min != n.box.min || u.max != n.box.max) return false;
      st.push_back(n.child1);
      st.push_back(n.child2);
    }
    return leaves == slots_.size();
  }

 private:
  friend class ProxyOps<DynamicTree<T>, T>;
  void unlink(std::uint32_t s) {
    remove_leaf(slots_[s].extra.leaf);
    free_node(slots_[s].extra.leaf);
  }
  struct Node {
    Box<T> box{};
    std::int32_t parent = -1;
    std::int32_t child1 = -1;
    std::int32_t child2 = -1;
    std::int32_t height = 0;
    std::uint32_t slot = 0;
    bool leaf() const noexcept { return child1 < 0; }
  };
  struct Extra {
    std::int32_t leaf = -1;
  };

  static Box<T> merged(const Box<T>& a, const Box<T>& b) noexcept {
    return {a.min.cwiseMin(b.min), a.max.cwiseMax(b.max)};
  }
  static Calc perimeter(const Box<T>& b) noexcept {
    return 2 * ((Calc(b.max.x()) - Calc(b.min.x())) + (Calc(b.max.y()) - Calc(b.min.y())));
  }

  /// Depth-first walk: descends into nodes whose (fat) box passes `enter`, calls leaf(slot) at
  /// each leaf reached; leaf returning false stops. The stack is local to the call.
  template <class Enter, class Leaf>
  void visit(Enter&& enter, Leaf&& leaf) const {
    if (root_ < 0) return;
    LocalStack<std::int32_t> stack;
    stack.push(root_);
    while (!stack.empty()) {
      const Node& n = node(stack.pop());
      if (!enter(n.box)) continue;
      if (n.leaf()) {
        if (!leaf(n.slot)) return;
      } else {
        stack.push(n.child1);
        stack.push(n.child2);
      }
    }
  }

  /// The walk of every pair of distinct leaves whose (fat) boxes meet, each once: a pair of
  /// nodes is pushed only when their boxes overlap, so the walk visits the same pairs in the same
  /// order as testing them when popped, with a fraction of the stack traffic. Calls
  /// leaf_pair(const Node&, const Node&); false stops.
  template <class LeafPair>
  void walk_leaf_pairs(LeafPair&& leaf_pair) const {
    if (root_ < 0) return;
    struct Job {
      std::int32_t a, b;
    };
    LocalStack<Job> jobs;
    const auto push_if_overlapping = [&](std::int32_t x, std::int32_t y) {
      if (boxes_overlap(node(x).box, node(y).box)) jobs.push({x, y});
    };
    jobs.push({root_, root_});
    while (!jobs.empty()) {
      const Job j = jobs.pop();
      const Node& a = node(j.a);
      if (j.a == j.b) {
        if (a.leaf()) continue;
        jobs.push({a.child1, a.child1});
        jobs.push({a.child2, a.child2});
        push_if_overlapping(a.child1, a.child2);
        continue;
      }
      const Node& b = node(j.b);
      if (a.leaf() && b.leaf()) {
        if (!leaf_pair(a, b)) return;
      } else if (b.leaf() || (!a.leaf() && a.height >= b.height)) {
        push_if_overlapping(a.child1, j.b);
        push_if_overlapping(a.child2, j.b);
      } else {
        push_if_overlapping(j.a, b.child1);
        push_if_overlapping(j.a, b.child2);
      }
    }
  }

  /// A leaf and twice its box centre, for the top-down build.
  struct Centred {
    Calc c[2];
    std::int32_t leaf;
  };

  /// Builds a subtree over leaves [first, last) (at least one): splits at the median centre on
  /// the longer axis of the centres' extent. Returns its root.
  std::int32_t build_top_down(Centred* first, Centred* last) {
    if (last - first == 1) return first->leaf;
    Centred* mid = split_at_median(first, last);
    const std::int32_t left = build_top_down(first, mid), right = build_top_down(mid, last);
    const std::int32_t parent = alloc_node();
    Node& n = node(parent);
    n.child1 = left;
    n.child2 = right;
    n.box = merged(node(left).box, node(right).box);
    n.height = 1 + std::max(node(left).height, node(right).height);
    node(left).parent = node(right).parent = parent;
    return parent;
  }

  /// Reorders [first, last) (at least two) so that the first half holds the smaller centres on
  /// the longer axis of the centres' extent; returns the middle.
  static Centred* split_at_median(Centred* first, Centred* last) {
    Calc lo[2] = {first->c[0], first->c[1]}, hi[2] = {first->c[0], first->c[1]};
    for (const Centred* i = first + 1; i != last; ++i) {
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], i->c[k]);
        hi[k] = std::max(hi[k], i->c[k]);
      }
    }
    const int axis = (hi[0] - lo[0]) >= (hi[1] - lo[1]) ? 0 : 1;
    Centred* mid = first + (last - first) / 2;
    std::nth_element(first, mid, last, [axis](const Centred& a, const Centred& b) { return a.c[axis] < b.c[axis]; });
    return mid;
  }

  /// rebuild()'s build: the subtree over leaves [first, last) of `old` (their nodes copied), each
  /// node allocated before its children, under `parent`. Returns its root.
  std::int32_t build_copy(Centred* first, Centred* last, const std::vector<Node>& old, std::int32_t parent) {
    const std::int32_t i = alloc_node();
    if (last - first == 1) {
      Node& n = node(i);
      n = old[std::size_t(first->leaf)];
      n.parent = parent;
      slots_[n.slot].extra.leaf = i;
      return i;
    }
    Centred* mid = split_at_median(first, last);
    const std::int32_t left = build_copy(first, mid, old, i), right = build_copy(mid, last, old, i);
    Node& n = node(i);
    n.parent = parent;
    n.child1 = left;
    n.child2 = right;
    n.box = merged(node(left).box, node(right).box);
    n.height = 1 + std::max(node(left).height, node(right).height);
    return i;
  }

  ProxyId add_box(const Box<T>& b, std::uint64_t user, Filter filter) {
    const ProxyId id = slots_.allocate(b, user, filter);
    const std::int32_t leaf = alloc_node();
    node(leaf).box = fattened(b, margin_);
    node(leaf).slot = id.index;
    slots_[id.index].extra.leaf = leaf;
    insert_leaf(leaf);
    return id;
  }

  /// Returns true when the leaf was reinserted with a new fat box.
  bool move_box(ProxyId id, const Box<T>& b) {
    const std::uint32_t s = slots_.check(id);
    const Box<T> old = slots_[s].box;
    slots_[s].box = b;
    const std::int32_t leaf = slots_[s].extra.leaf;
    if (box_contains(node(leaf).box, b)) return false;
    remove_leaf(leaf);
    node(leaf).box = predicted(b, old);
    insert_leaf(leaf);
    return true;
  }

  /// The fat box of a proxy that moved from `old` to `b`: grown by the margin, then stretched
  /// kLookAhead steps of the same displacement ahead (at most the box's extent plus the margin
  /// per axis, so a teleport does not leave a huge box), so that steady motion leaves it rarely.
  Box<T> predicted(const Box<T>& b, const Box<T>& old) const noexcept {
    Box<T> fat = fattened(b, margin_);
    for (int i = 0; i < 2; ++i) {
      const Calc cap = Calc(b.max[i]) - Calc(b.min[i]) + Calc(margin_);
      const Calc ahead = std::clamp(kLookAhead * (Calc(b.min[i]) - Calc(old.min[i])), -cap, cap);
      const Calc reach = ahead < 0 ? Calc(fat.min[i]) + ahead : Calc(fat.max[i]) + ahead;
      if (!(std::fabs(reach) <= Calc(max_magnitude<T>()))) continue;  // keep the plain fat box
      const T moved = T(reach);
      if (ahead < 0) fat.min[i] = std::min(fat.min[i], moved);
      if (ahead > 0) fat.max[i] = std::max(fat.max[i], moved);
    }
    return fat;
  }

  std::int32_t alloc_node() {
    if (free_nodes_.empty()) {
      nodes_.emplace_back();
      return static_cast<std::int32_t>(nodes_.size() - 1);
    }
    const std::int32_t i = free_nodes_.back();
    free_nodes_.pop_back();
    node(i) = Node{};
    return i;
  }
  void free_node(std::int32_t i) { free_nodes_.push_back(i); }

  void insert_leaf(std::int32_t leaf) {
    node(leaf).parent = node(leaf).child1 = node(leaf).child2 = -1;
    node(leaf).height = 0;
    if (root_ < 0) {
      root_ = leaf;
      return;
    }
    const Box<T> lb = node(leaf).box;
    // Descend to the sibling whose enlargement costs least (perimeter heuristic).
    std::int32_t i = root_;
    while (!node(i).leaf()) {
      const Node& n = node(i);
      const Calc area = perimeter(n.box);
      const Calc combined = perimeter(merged(n.box, lb));
      const Calc cost = 2 * combined;                // new parent here
      const Calc inherited = 2 * (combined - area);  // pushed down to every descendant
      auto child_cost = [&](std::int32_t c) {
        const Calc grown = perimeter(merged(node(c).box, lb));
        return node(c).leaf() ? grown + inherited : grown - perimeter(node(c).box) + inherited;
      };
      const Calc c1 = child_cost(n.child1), c2 = child_cost(n.child2);
      if (cost < c1 && cost < c2) break;
      i = c1 < c2 ? n.child1 : n.child2;
    }
    const std::int32_t sibling = i;
    const std::int32_t old_parent = node(sibling).parent;
    const std::int32_t parent = alloc_node();
    node(parent).parent = old_parent;
    node(parent).box = merged(lb, node(sibling).box);
    node(parent).height = node(sibling).height + 1;
    node(parent).child1 = sibling;
    node(parent).child2 = leaf;
    node(sibling).parent = parent;
    node(leaf).parent = parent;
    if (old_parent < 0) {
      root_ = parent;
    } else if (node(old_parent).child1 == sibling) {
      node(old_parent).child1 = parent;
    } else {
      node(old_parent).child2 = parent;
    }
    refit_from(node(leaf).parent);
  }

  void remove_leaf(std::int32_t leaf) {
    if (leaf == root_) {
      root_ = -1;
      return;
    }
    const std::int32_t parent = node(leaf).parent;
    const std::int32_t grand = node(parent).parent;
    const std::int32_t sibling = node(parent).child1 == leaf ? node(parent).child2 : node(parent).child1;
    if (grand < 0) {
      root_ = sibling;
      node(sibling).parent = -1;
    } else {
      if (node(grand).child1 == parent) {
        node(grand).child1 = sibling;
      } else {
        node(grand).child2 = sibling;
      }
      node(sibling).parent = grand;
      refit_from(grand);
    }
    free_node(parent);
  }

  /// Walks to the root rebalancing and refitting boxes and heights.
  void refit_from(std::int32_t i) {
    while (i >= 0) {
      i = balance(i);
      Node& n = node(i);
      n.height = 1 + std::max(node(n.child1).height, node(n.child2).height);
      n.box = merged(node(n.child1).box, node(n.child2).box);
      i = n.parent;
    }
  }

  /// If node a is unbalanced, rotates its taller child up; returns the node now in a's place.
  std::int32_t balance(std::int32_t a) {
    Node& A = node(a);
    if (A.leaf() || A.height < 2) return a;
    const std::int32_t b = A.child1, c = A.child2;
    const int diff = node(c).height - node(b).height;
    if (diff > 1) return rotate_up(a, c, b);
    if (diff < -1) return rotate_up(a, b, c);
    return a;
  }

  /// Rotates child `up` (taller) of node a into a's place; `other` is a's remaining child.
  std::int32_t rotate_up(std::int32_t a, std::int32_t up, std::int32_t other) {
    Node& U = node(up);
    const std::int32_t f = U.child1, g = U.child2;
    // up takes a's place.
    U.child1 = a;
    U.parent = node(a).parent;
    node(a).parent = up;
    if (U.parent < 0) {
      root_ = up;
    } else if (node(U.parent).child1 == a) {
      node(U.parent).child1 = up;
    } else {
      node(U.parent).child2 = up;
    }
    // The taller grandchild stays under up; the shorter one moves under a.
    const bool f_taller = node(f).height > node(g).height;
    const std::int32_t keep = f_taller ? f : g, give = f_taller ? g : f;
    U.child2 = keep;
    node(a).child1 = other;
    node(a).child2 = give;
    node(give).parent = a;
    node(other).parent = a;
    Node& A = node(a);
    A.box = merged(node(other).box, node(give).box);
    A.height = 1 + std::max(node(other).height, node(give).height);
    U.box = merged(A.box, node(keep).box);
    U.height = 1 + std::max(A.height, node(keep).height);
    return up;
  }

  /// How many steps of the last displacement a reinserted fat box reaches ahead.
  static constexpr Calc kLookAhead = 4;

  T margin_;
  Slots<T, Extra> slots_;
  /// Node i; indices are std::int32_t so that -1 can mean "none".
  Node& node(std::int32_t i) noexcept { return nodes_[std::size_t(i)]; }
  const Node& node(std::int32_t i) const noexcept { return nodes_[std::size_t(i)]; }

  std::vector<Node> nodes_;
  std::vector<std::int32_t> free_nodes_;
  std::int32_t root_ = -1;
};

}  // namespace collide::broadphase
