// One side of bench/compare/compare_headers.py: the pairs of bodies whose bounding boxes overlap
// in frames 30-39 of the game loop (bench/game_loop.cpp's scene and motion; a tree built each
// frame), grouped by kind pair (all of them, or after select() only those that contact() finds
// apart, or in contact), and the time of one pass of contact() over each group. Compiled
// twice, against two versions of the library's headers, with the library's namespace renamed
// (-Dcollide=...) so that both live in one process; COMPARE_SIDE names this side's entry points.
// time_box2d() times Box2D 2.4.1's b2Collide* on the same pairs and poses, as the game loop calls
// them (main.cpp built with COMPARE_BOX2D).

#include "../game_loop.cpp"

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#ifndef COMPARE_SIDE
#error "COMPARE_SIDE must name this side (old or new)"
#endif
#define COMPARE_JOIN2(a, b) a##_##b
#define COMPARE_JOIN(a, b) COMPARE_JOIN2(a, b)
#define COMPARE_ENTRY(name) COMPARE_JOIN(name, COMPARE_SIDE)

namespace {

struct Placed {
  std::uint32_t a, b;  // a's kind <= b's kind
  collide::Transform<float> xa, xb;
};

struct Replay {
  std::shared_ptr<bench::Scene> scene;
  std::vector<std::pair<std::string, std::vector<Placed>>> groups;  // registry order of kind pairs
};

/// Which of a kind pair's pairs are replayed: all, those contact() finds apart, or those it finds
/// in contact (select()).
enum class Selection { All = 0, Apart = 1, InContact = 2 };

/// The replay of a scene of `bodies` bodies, built at the first call (every call asks for the same).
const Replay& replay_all(std::size_t bodies) {
  static const Replay r = [bodies] {
    using namespace bench;
    Replay out;
    out.scene = make_scene(bodies);
    const Scene& s = *out.scene;
    std::vector<V> p = s.position, v = s.velocity;
    std::vector<float> angle = s.angle;
    std::map<std::pair<std::size_t, std::size_t>, std::vector<Placed>> by_kinds;
    for (int frame = 0; frame < 40; ++frame) {
      advance(p, v, angle, s);
      if (frame < 30) continue;
      Tree tree(0.1f);
      std::vector<collide::Transform<float>> xf(bodies);
      for (std::size_t i = 0; i < bodies; ++i) {
        xf[i] = *collide::Transform<float>::make(p[i], angle[i]);
        tree.add(collide::bounds(s.shapes[i], xf[i]), i);
      }
      tree.for_each_pair([&](bp::ProxyId x, bp::ProxyId y) {
        auto i = std::uint32_t(tree.user_data(x)), j = std::uint32_t(tree.user_data(y));
        if (s.shapes[j].index() < s.shapes[i].index()) std::swap(i, j);
        by_kinds[{s.shapes[i].index(), s.shapes[j].index()}].push_back({i, j, xf[i], xf[j]});
      });
    }
    for (auto& [kinds, pairs] : by_kinds) {
      const auto ka = collide::ShapeKind(kinds.first), kb = collide::ShapeKind(kinds.second);
      std::string name(collide::name(ka));
      name.append("-").append(collide::name(kb));
      out.groups.emplace_back(std::move(name), std::move(pairs));
    }
    return out;
  }();
  return r;
}

Selection selection = Selection::All;

/// The selected pairs of each kind pair of replay_all(bodies), in the same order; a kind pair
/// left without pairs keeps its place, empty.
const Replay& replay(std::size_t bodies) {
  static Replay selected;
  static Selection made = Selection::All;
  const Replay& all = replay_all(bodies);
  if (selection == Selection::All) return all;
  if (selected.scene && made == selection) return selected;
  selected = Replay{all.scene, {}};
  for (const auto& [name, pairs] : all.groups) {
    std::vector<Placed> kept;
    for (const Placed& q : pairs) {
      const bool found =
          std::visit([&](const auto& a, const auto& b) { return collide::contact(a, q.xa, b, q.xb).has_value(); },
                     all.scene->shapes[q.a], all.scene->shapes[q.b]);
      if (found == (selection == Selection::InContact)) kept.push_back(q);
    }
    selected.groups.emplace_back(name, std::move(kept));
  }
  made = selection;
  return selected;
}

}  // namespace

/// Replays from now on only the pairs of `which` (0: all, 1: those apart, 2: those in contact,
/// as this side's contact() finds them).
extern "C" void COMPARE_ENTRY(select)(int which) {
  selection = Selection(which);
}

/// The number of kind pairs among the candidate pairs.
extern "C" std::size_t COMPARE_ENTRY(group_count)(std::size_t bodies) {
  return replay(bodies).groups.size();
}
/// Kind pair g's name ("circle-obb") and its number of pairs.
extern "C" const char* COMPARE_ENTRY(group_name)(std::size_t bodies, std::size_t g, std::size_t* pairs) {
  const auto& group = replay(bodies).groups[g];
  *pairs = group.second.size();
  return group.first.c_str();
}
/// Nanoseconds of one pass of contact() over kind pair g; *points: the points found.
extern "C" double COMPARE_ENTRY(time_group)(std::size_t bodies, std::size_t g, long* points) {
  const Replay& r = replay(bodies);
  const auto& shapes = r.scene->shapes;
  const std::vector<Placed>& pairs = r.groups[g].second;
  long found = 0;
  if (pairs.empty()) {
    *points = 0;
    return 0;
  }
  const auto start = std::chrono::steady_clock::now();
  std::visit(
      [&](const auto& a0, const auto& b0) {
        using A = std::remove_cvref_t<decltype(a0)>;
        using B = std::remove_cvref_t<decltype(b0)>;
        for (const Placed& q : pairs) {
          const auto c = collide::contact(*std::get_if<A>(&shapes[q.a]), q.xa, *std::get_if<B>(&shapes[q.b]), q.xb);
          benchmark::DoNotOptimize(c);  // the whole contact, as the game loop's callback keeps it
          if (c) found += c->count;
        }
      },
      shapes[pairs.front().a], shapes[pairs.front().b]);
  const auto stop = std::chrono::steady_clock::now();
  *points = found;
  return std::chrono::duration<double, std::nano>(stop - start).count();
}

namespace {

/// Nanoseconds of one pass of Box2D 2.4.1's b2Collide* over kind pair g, each pair under the same
/// poses as contact()'s (the rotation's stored cosine and sine); with World, each manifold with
/// points is also turned into world points, normal and separations (b2WorldManifold::Initialize:
/// what contact() returns). *points: the points found.
template <bool World>
double time_box2d_pass(std::size_t bodies, std::size_t g, long* points) {
  const Replay& r = replay(bodies);
  const std::vector<Placed>& pairs = r.groups[g].second;
  static std::vector<std::vector<std::pair<b2Transform, b2Transform>>> poses;  // per group, built once
  static Selection posed = Selection::All;                                     // the pairs they are of
  if (posed != selection) {
    poses.clear();
    posed = selection;
  }
  if (poses.size() < r.groups.size()) poses.resize(r.groups.size());
  if (poses[g].empty()) {
    const auto to_b2_pose = [](const collide::Transform<float>& x) {
      b2Transform out;
      out.p.Set(x.position().x(), x.position().y());
      out.q.c = x.rotation().x();
      out.q.s = x.rotation().y();
      return out;
    };
    for (const Placed& q : pairs) poses[g].emplace_back(to_b2_pose(q.xa), to_b2_pose(q.xb));
  }
  const auto& shapes = r.scene->b2shapes;
  long found = 0;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const b2Shape *a = shapes[pairs[k].a].get(), *b = shapes[pairs[k].b].get();
    b2Manifold m;
    bench::collide_b2(m, a, poses[g][k].first, b, poses[g][k].second);
    benchmark::DoNotOptimize(m);
    found += m.pointCount;
    if (World && m.pointCount > 0) {
      b2WorldManifold w;
      w.Initialize(&m, poses[g][k].first, a->m_radius, poses[g][k].second, b->m_radius);
      benchmark::DoNotOptimize(w);
    }
  }
  const auto stop = std::chrono::steady_clock::now();
  *points = found;
  return std::chrono::duration<double, std::nano>(stop - start).count();
}

}  // namespace

/// Nanoseconds of one pass of Box2D 2.4.1's b2Collide* over kind pair g (time_box2d_pass()).
extern "C" double COMPARE_ENTRY(time_box2d)(std::size_t bodies, std::size_t g, long* points) {
  return time_box2d_pass<false>(bodies, g, points);
}
/// The same, each manifold with points also turned into world values (time_box2d_pass()).
extern "C" double COMPARE_ENTRY(time_box2d_world)(std::size_t bodies, std::size_t g, long* points) {
  return time_box2d_pass<true>(bodies, g, points);
}
