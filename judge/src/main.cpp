// collide_judge: runs the judge on one adapter, several, or all of them.
//
//   collide_judge course-notes --seconds 10 --seed 1
//   collide_judge --all --minutes 1
//
// Exit status: 0 when every adapter ran (whatever the libraries' counts: those are
// measurements); 1 when a --require-class was not found in time; 2 when an adapter itself broke
// (it could not start, or violated the protocol) or the command line was wrong.

#include "collide/judge/judge.hpp"
#include "collide/judge/protocol.hpp"

#include "course_notes/course_notes_adapter.hpp"
#ifdef COLLIDE_JUDGE_HAVE_BOX2D
#include "box2d/box2d_adapter.hpp"
#endif
#ifdef COLLIDE_JUDGE_HAVE_CHIPMUNK
#include "chipmunk/chipmunk_adapter.hpp"
#endif

#include <CLI/CLI.hpp>

#include <functional>
#include <iostream>
#include <memory>

namespace {

using namespace collide::judge;

struct Entry {
  std::string name;
  std::function<std::unique_ptr<Adapter>(const std::string& js_dir)> make;
};

std::unique_ptr<Adapter> node_adapter(const std::string& js_dir, const std::string& lib) {
  return std::make_unique<Subprocess>(std::vector<std::string>{"node", js_dir + "/adapter.js", lib},
                                      std::chrono::milliseconds(20000));
}

std::vector<Entry> registry() {
  std::vector<Entry> r;
  r.push_back({"course-notes", [](const std::string&) { return std::make_unique<InProcess<CourseNotesAdapter>>(); }});
#ifdef COLLIDE_JUDGE_HAVE_BOX2D
  r.push_back({"box2d", [](const std::string&) { return std::make_unique<InProcess<Box2dAdapter>>(); }});
#endif
#ifdef COLLIDE_JUDGE_HAVE_CHIPMUNK
  r.push_back({"chipmunk", [](const std::string&) { return std::make_unique<InProcess<ChipmunkAdapter>>(); }});
#endif
  for (const char* lib : {"matter-js", "planck", "sat", "detect-collisions", "rapier2d"})
    r.push_back({lib, [lib](const std::string& js) { return node_adapter(js, lib); }});
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("collide's judge: another library's collision answers against exact arithmetic");
  std::vector<std::string> names;
  bool all = false, list = false, no_shrink = false, no_repro = false;
  double minutes = 0, seconds = 0, require_within = 0, shrink_seconds = 2;
  std::uint64_t seed = 1, cases = 0;
  std::string out = "build/reports/judge", js_dir = COLLIDE_JUDGE_JS_DIR;
  std::vector<std::string> require;
  app.add_option("adapters", names, "adapters to run (see --list)");
  app.add_flag("--all", all, "run every adapter");
  app.add_flag("--list", list, "print the adapters and exit");
  app.add_option("--minutes", minutes, "minutes per adapter (default 1)");
  app.add_option("--seconds", seconds, "seconds per adapter (instead of --minutes)");
  app.add_option("--cases", cases, "stop after this many cases per adapter");
  app.add_option("--seed", seed, "generator seed (default 1)");
  app.add_option("--out", out, "report directory (default build/reports/judge)");
  app.add_option("--js-dir", js_dir, "directory of the JavaScript adapters (judge/js)");
  app.add_option("--require-class", require,
                 "a class key prefix that must be found (e.g. wrong.false_apart.touching.circle_circle); "
                 "exit status 1 otherwise");
  app.add_option("--require-within", require_within, "seconds into the run by which each required class is found");
  app.add_flag("--no-shrink", no_shrink, "keep the simplest counterexample found, unshrunk");
  app.add_option("--shrink-seconds", shrink_seconds,
                 "shrinking budget per class (default 2; 30 budgets per run at most)");
  app.add_flag("--no-reproducers", no_repro, "write no reproducers");
  CLI11_PARSE(app, argc, argv);

  const std::vector<Entry> entries = registry();
  if (list) {
    for (const Entry& e : entries) std::cout << e.name << "\n";
    return 0;
  }
  if (all)
    for (const Entry& e : entries) names.push_back(e.name);
  if (names.empty()) {
    std::cerr << "collide_judge: name an adapter or --all (--list shows them)\n";
    return 2;
  }
  RunOptions o;
  o.seconds = seconds > 0 ? seconds : (minutes > 0 ? minutes : 1) * 60;
  o.max_cases = cases;
  o.seed = seed;
  o.out_dir = out;
  o.shrink = !no_shrink;
  o.shrink_seconds = shrink_seconds;
  o.reproducers = !no_repro;

  int status = 0;
  for (const std::string& n : names) {
    const auto it = std::find_if(entries.begin(), entries.end(), [&](const Entry& e) { return e.name == n; });
    if (it == entries.end()) {
      std::cerr << "collide_judge: no adapter named '" << n << "' (--list shows them)\n";
      return 2;
    }
    try {
      const std::unique_ptr<Adapter> adapter = it->make(js_dir);
      const RunReport r = run(*adapter, o);
      std::cout << r.info.library << " " << r.info.version << ": " << r.cases << " cases in " << r.seconds_total
                << " s (" << static_cast<long long>(r.cases / std::max(r.seconds_total, 1e-9))
                << " cases/s; library side " << r.seconds_library << " s, judge side " << r.seconds_judge
                << " s): agree " << r.counts[0] << ", convention " << r.counts[1] << ", wrong " << r.counts[2]
                << ", crash " << r.counts[3] << ", unjudged " << r.counts[4] << "\n";
      for (const auto& [key, rec] : r.classes)
        if (rec.outcome == Outcome::Wrong || rec.outcome == Outcome::Crash)
          std::cout << "  " << key << ": " << rec.count << " (first after " << r.first_found_seconds.at(key) << " s)"
                    << (rec.reproducer.empty() ? ""
                        : rec.reproducer_shows ? ", reproduced"
                                               : ", NOT reproduced")
                    << "\n";
      for (const std::string& req : require) {
        bool found = false;
        for (const auto& [key, t] : r.first_found_seconds)
          if (key.rfind(req, 0) == 0 && (require_within <= 0 || t <= require_within)) found = true;
        if (!found) {
          std::cerr << "collide_judge: required class " << req << " not found"
                    << (require_within > 0 ? " within " + std::to_string(require_within) + " s" : "") << " for " << n
                    << "\n";
          status = std::max(status, 1);
        }
      }
    } catch (const AdapterError& e) {
      std::cerr << "collide_judge: adapter " << n << " broke: " << e.what() << "\n";
      status = 2;
    }
  }
  write_summary(o.out_dir);
  std::cout << "reports: " << o.out_dir.string() << "/summary.md\n";
  return status;
}
