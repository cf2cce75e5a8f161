// The judge's run: generate, ask, judge, classify, shrink, report.

#include "collide/judge/judge.hpp"
#include "collide/laws/case_file.hpp"
#include "collide/oracle/oracle.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace collide::judge {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// How complicated a value is: its significant bits plus a little for its distance (in binades)
/// from 1. Shrinking lowers the sum over a counterexample's values.
double complexity(double v) {
  if (v == 0) return 0;
  if (!std::isfinite(v)) return 1000;
  int e = 0;
  double m = std::frexp(std::fabs(v), &e);
  int bits = 0;
  while (m != 0 && bits < 64) {
    m = std::ldexp(m, 1);
    m -= std::floor(m);
    ++bits;
  }
  return bits + std::abs(e) / 8.0;
}

double complexity(const Input& in) {
  double c = 0;
  for (const ShapeData* d : {&in.a, &in.b})
    for (double v : d->values) c += complexity(v);
  return c;
}

/// v rounded to its leading `bits` significant bits.
double keep_bits(double v, int bits) {
  if (v == 0 || !std::isfinite(v)) return v;
  int e = 0;
  std::frexp(v, &e);
  return std::ldexp(std::round(std::ldexp(v, bits - e)), e - bits);
}

/// Simpler neighbours of a counterexample: each value rounded to fewer bits, moved to an integer
/// or to 0; the pair moved toward the origin and scaled toward 1.
std::vector<Input> shrink_candidates(const Input& in) {
  std::vector<Input> out;
  for (int side = 0; side < 2; ++side) {
    const ShapeData& d = side == 0 ? in.a : in.b;
    for (std::size_t i = 0; i < d.values.size(); ++i) {
      const double v = d.values[i];
      std::vector<double> tries = {0.0, std::round(v), std::trunc(v)};
      for (int bits : {1, 2, 3, 4, 6, 8, 12, 16, 20, 24, 32, 40, 48}) tries.push_back(keep_bits(v, bits));
      for (double t : tries) {
        if (t == v || complexity(t) >= complexity(v)) continue;
        Input c = in;
        (side == 0 ? c.a : c.b).values[i] = t;
        out.push_back(std::move(c));
      }
    }
  }
  // The pair moved by minus a's first position, rounded to few bits, and scaled by a power of 2.
  const laws::KindCodec codec = laws::codec_of(in.a.kind);
  const double shift_x = keep_bits(in.a.values[0], 4);
  const double shift_y = in.a.values.size() > 1 ? keep_bits(in.a.values[1], 4) : 0.0;
  for (int form = 0; form < 3; ++form) {
    Input c = in;
    for (ShapeData* d : {&c.a, &c.b}) {
      const laws::KindCodec dc = laws::codec_of(d->kind);
      for (std::size_t i = 0; i < d->values.size(); ++i) {
        const laws::Role r = dc.fields[i % dc.fields.size()].role;
        if (form == 0 && r == laws::Role::X) d->values[i] -= shift_x;
        if (form == 0 && r == laws::Role::Y) d->values[i] -= shift_y;
        if (form > 0 && r != laws::Role::Other) d->values[i] = std::ldexp(d->values[i], form == 1 ? -1 : 1);
      }
    }
    (void)codec;
    if (complexity(c) < complexity(in)) out.push_back(std::move(c));
  }
  std::vector<Input> valid;
  for (Input& c : out)
    if (is_clean_input(c.a) && is_clean_input(c.b)) valid.push_back(std::move(c));
  return valid;
}

/// Greedy shrinking: each round asks the adapter for every candidate (one batch) and keeps the
/// simplest one still in the same class. Returns the number of rounds that improved.
int shrink(Adapter& adapter, ClassRecord& rec, double budget_seconds) {
  const auto start = Clock::now();
  int improved = 0;
  for (int round = 0; round < 200 && since(start) < budget_seconds; ++round) {
    const std::vector<Input> cands = shrink_candidates(rec.example);
    if (cands.empty()) break;
    std::vector<Answer> answers(cands.size());
    adapter.answer(cands, answers);
    const Input* best = nullptr;
    std::size_t best_i = 0;
    for (std::size_t i = 0; i < cands.size(); ++i) {
      const Judgement j = judge_answer(adapter.info(), cands[i], answers[i]);
      if (j.outcome == Outcome::Agree || class_key(cands[i], j) != rec.key) continue;
      if (!best || complexity(cands[i]) < complexity(*best)) best = &cands[i], best_i = i;
    }
    if (!best) break;
    rec.example = *best;
    rec.answer = answers[best_i];
    rec.judgement = judge_answer(adapter.info(), *best, answers[best_i]);
    ++improved;
  }
  return improved;
}

std::string hex(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

nlohmann::json shape_json(const ShapeData& d) {
  nlohmann::json values = nlohmann::json::array();
  for (double v : d.values) values.push_back(hex(v));
  return {{"kind", std::string(name(d.kind))}, {"values", values}};
}

std::string shape_text(const ShapeData& d) {
  std::string s(name(d.kind));
  for (double v : d.values) s += " " + hex(v);
  return s;
}

/// The stored shapes in normal form (what the case file's factories rebuild bit for bit).
ShapeData normal_form(const ShapeData& d) {
  const std::optional<Shape<double>> s = to_shape(d);
  return s ? laws::to_data(*s) : d;
}

/// Runs a reproducer and reports whether it printed the library's recorded wrong answer (for an
/// exception: "library: threw").
void run_reproducer(Adapter& adapter, ClassRecord& rec, const std::filesystem::path& file) {
  std::string cmd;
  if (adapter.reproducer_runner() == "c++") {
    const std::filesystem::path exe = file.parent_path() / file.stem();
    cmd = "c++ -std=c++17 -O1 -o '" + exe.string() + "' '" + file.string() + "' " + adapter.reproducer_link() +
          " 2>&1 && '" + exe.string() + "' 2>&1";
  } else {
    cmd = adapter.reproducer_runner() + " '" + file.string() + "' 2>&1";
  }
  std::string output;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    std::array<char, 4096> buf{};
    std::size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0 && output.size() < 65536) output.append(buf.data(), n);
    pclose(p);
  }
  rec.reproducer_output = output.substr(0, 2000);
  if (rec.outcome == Outcome::Crash && rec.answer.status == Status::Threw) {
    rec.reproducer_shows = output.find("library: threw") != std::string::npos;
    return;
  }
  // The reproducer's first line is "library: overlap <true|false>[ push <x> <y>]" with values
  // printed to round-trip; it shows the wrong answer when they are the recorded ones.
  const auto pos = output.find("library: overlap ");
  if (pos == std::string::npos) return;
  std::istringstream line(output.substr(pos + 17, output.find('\n', pos) - pos - 17));
  std::string ov, word;
  line >> ov;
  bool shows = (ov == "true") == rec.answer.overlap && (ov == "true" || ov == "false");
  if (shows && rec.query == Query::Push && !rec.answer.has_push)
    shows = !(line >> word);
  else if (shows && rec.query == Query::Push) {
    double x = NAN, y = NAN;
    line >> word >> x >> y;
    shows = word == "push" && x == rec.answer.push.x() && y == rec.answer.push.y();
  }
  rec.reproducer_shows = shows;
}

void write_reports(Adapter& adapter, RunReport& r, const RunOptions& o) {
  const std::string lib = r.info.library;
  const std::filesystem::path dir = o.out_dir / lib;
  std::filesystem::create_directories(dir / "cases");
  nlohmann::json classes = nlohmann::json::array();
  for (auto& [key, rec] : r.classes) {
    if (rec.outcome == Outcome::Wrong || rec.outcome == Outcome::Crash) {
      laws::Case c;
      c.law = laws::Law::Agreement;
      c.scalar = "double";
      c.a = normal_form(rec.answer.status == Status::Ok ? rec.answer.stored_a : rec.example.a);
      c.b = normal_form(rec.answer.status == Status::Ok ? rec.answer.stored_b : rec.example.b);
      c.expected = rec.judgement.expected;
      c.got = rec.judgement.got;
      c.source = "judge " + lib + " " + r.info.version + " seed " + std::to_string(o.seed) + " class " + key;
      c.account = lib + " as stored; " + rec.judgement.got + "; exact: " + rec.judgement.expected;
      try {
        const std::filesystem::path p = laws::save_case(dir / "cases", c);
        rec.case_file = std::filesystem::relative(p, o.out_dir).string();
        std::filesystem::path svg = p;
        svg.replace_extension(".svg");
        if (std::filesystem::exists(svg)) rec.picture = std::filesystem::relative(svg, o.out_dir).string();
      } catch (const std::exception& e) {
        rec.case_file = std::string("(not written: ") + e.what() + ")";
      }
    }
    if ((rec.outcome == Outcome::Wrong || rec.outcome == Outcome::Crash) && o.reproducers) {
      try {
        const auto [ext, source] = adapter.reproducer(rec.example, rec.query, rec.judgement.expected);
        std::string stem = key;
        for (char& ch : stem)
          if (ch == '.') ch = '-';
        const std::filesystem::path file = dir / ("repro-" + stem + "." + ext);
        std::ofstream(file) << source;
        rec.reproducer = std::filesystem::relative(file, o.out_dir).string();
        run_reproducer(adapter, rec, file);
      } catch (const std::exception& e) {
        rec.reproducer = std::string("(not written: ") + e.what() + ")";
      }
    }
    nlohmann::json jc = {{"class", key},
                         {"outcome", std::string(name(rec.outcome))},
                         {"severity", std::string(name(rec.severity))},
                         {"query", std::string(name(rec.query))},
                         {"count", rec.count},
                         {"input", {{"a", shape_json(rec.example.a)}, {"b", shape_json(rec.example.b)}}},
                         {"expected", rec.judgement.expected},
                         {"got", rec.judgement.got}};
    if (rec.answer.status == Status::Ok)
      jc["stored"] = {{"a", shape_json(rec.answer.stored_a)}, {"b", shape_json(rec.answer.stored_b)}};
    if (!rec.case_file.empty()) jc["case_file"] = rec.case_file;
    if (!rec.picture.empty()) jc["picture"] = rec.picture;
    if (!rec.reproducer.empty()) {
      jc["reproducer"] = rec.reproducer;
      jc["reproducer_shows_wrong_answer"] = rec.reproducer_shows;
    }
    if (r.first_found_seconds.count(key)) jc["first_found_seconds"] = r.first_found_seconds.at(key);
    classes.push_back(jc);
  }
  const Contract& ct = r.info.contract;
  nlohmann::json j = {{"library", lib},
                      {"version", r.info.version},
                      {"counts",
                       {{"agree", r.counts[0]},
                        {"convention", r.counts[1]},
                        {"wrong", r.counts[2]},
                        {"crash", r.counts[3]},
                        {"unjudged", r.counts[4]}}},
                      {"contract",
                       {{"scalar", ct.scalar},
                        {"touching", std::string(name(ct.touching))},
                        {"tol_abs", ct.tol_abs},
                        {"tol_rel", ct.tol_rel},
                        {"push_moves", ct.push_moves == PushMoves::A ? "a" : "b"},
                        {"source", ct.source}}},
                      {"mapping", r.info.mapping},
                      {"seed", o.seed},
                      {"cases", r.cases},
                      {"seconds", r.seconds_total},
                      {"seconds_library", r.seconds_library},
                      {"seconds_judge", r.seconds_judge},
                      {"cases_per_second", r.seconds_total > 0 ? r.cases / r.seconds_total : 0.0},
                      {"classes", classes}};
  std::ofstream(o.out_dir / (lib + ".json")) << j.dump(2) << "\n";

  std::ofstream md(o.out_dir / (lib + ".md"));
  md << "# " << lib << " " << r.info.version << " judged\n\n";
  md << r.cases << " cases (seed " << o.seed << ") in " << r.seconds_total << " s: library side " << r.seconds_library
     << " s, judge side (generation, oracle, classification) " << r.seconds_judge << " s; "
     << static_cast<long long>(r.seconds_total > 0 ? r.cases / r.seconds_total : 0) << " cases/s.\n\n";
  md << "| agree | convention | wrong | crash | unjudged |\n|---|---|---|---|---|\n";
  md << "| " << r.counts[0] << " | " << r.counts[1] << " | " << r.counts[2] << " | " << r.counts[3] << " | "
     << r.counts[4] << " |\n\n";
  md << "Declared contract: " << ct.scalar << ", touching counts as " << name(ct.touching) << ", tolerance "
     << ct.tol_abs << " + " << ct.tol_rel << " x scale, push moves " << (ct.push_moves == PushMoves::A ? "a" : "b")
     << ". Source: " << ct.source << "\n\nHow our shapes are built: " << r.info.mapping << "\n\n";
  if (r.classes.empty()) md << "Nothing beyond the library's contract was found.\n";
  for (const auto& [key, rec] : r.classes) {
    md << "## " << key << " (" << rec.count << ")\n\n";
    md << "- input a: `" << shape_text(rec.example.a) << "`\n- input b: `" << shape_text(rec.example.b) << "`\n";
    if (rec.answer.status == Status::Ok)
      md << "- stored a: `" << shape_text(rec.answer.stored_a) << "`\n- stored b: `" << shape_text(rec.answer.stored_b)
         << "`\n";
    md << "- library: " << rec.judgement.got << "\n- exact: " << rec.judgement.expected << "\n";
    if (!rec.case_file.empty()) md << "- case file: `" << rec.case_file << "`";
    if (!rec.picture.empty()) md << ", picture: `" << rec.picture << "`";
    if (!rec.case_file.empty()) md << "\n";
    if (!rec.reproducer.empty())
      md << "- reproducer: `" << rec.reproducer << "` ("
         << (rec.reproducer_shows ? "run: prints the wrong answer" : "run: did NOT reproduce") << ")\n";
    md << "\n";
  }
}

}  // namespace

RunReport run(Adapter& adapter, const RunOptions& o) {
  RunReport r;
  r.info = adapter.info();
  Generator gen(r.info.kinds, o.seed);
  const auto start = Clock::now();
  std::vector<Input> inputs;
  std::vector<Answer> answers;
  while (since(start) < o.seconds && (o.max_cases == 0 || r.cases < o.max_cases)) {
    auto t0 = Clock::now();
    inputs.clear();
    std::size_t n = o.batch;
    if (o.max_cases) n = std::min<std::size_t>(n, o.max_cases - r.cases);
    gen.generate(n, inputs);
    r.seconds_judge += since(t0);
    answers.assign(inputs.size(), Answer{});
    t0 = Clock::now();
    adapter.answer(inputs, answers);
    r.seconds_library += since(t0);
    t0 = Clock::now();
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const Judgement j = judge_answer(r.info, inputs[i], answers[i]);
      ++r.counts[static_cast<int>(j.outcome)];
      if (j.outcome == Outcome::Agree) continue;
      const std::string key = class_key(inputs[i], j);
      ClassRecord& rec = r.classes[key];
      if (rec.count++ == 0 || complexity(inputs[i]) < complexity(rec.example)) {
        if (rec.count == 1) r.first_found_seconds[key] = since(start);
        rec.key = key;
        rec.outcome = j.outcome;
        rec.severity = j.severity;
        rec.query = j.query;
        rec.example = inputs[i];
        rec.answer = answers[i];
        rec.judgement = j;
      }
    }
    r.cases += inputs.size();
    r.seconds_judge += since(t0);
  }
  r.seconds_total = since(start);
  if (o.shrink) {
    // Each class gets its budget until the run's total shrinking budget (30 budgets) is spent.
    const auto shrink_start = Clock::now();
    for (auto& [key, rec] : r.classes)
      if ((rec.outcome == Outcome::Wrong || rec.outcome == Outcome::Crash) &&
          since(shrink_start) < 30 * o.shrink_seconds)
        shrink(adapter, rec, o.shrink_seconds);
  }
  std::filesystem::create_directories(o.out_dir);
  write_reports(adapter, r, o);
  return r;
}

void write_summary(const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  nlohmann::json rows = nlohmann::json::array();
  std::ofstream md(out_dir / "summary.md");
  md << "# The judge's reports\n\n| library | version | cases | agree | convention | wrong | crash | unjudged | wrong "
        "classes | cases/s |\n|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(out_dir))
    if (e.path().extension() == ".json" && e.path().stem() != "summary") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(std::ifstream(f));
    } catch (const std::exception&) {
      continue;
    }
    if (!j.contains("counts")) continue;
    int wrong_classes = 0;
    for (const auto& c : j["classes"])
      if (c["outcome"] == "wrong") ++wrong_classes;
    const auto& c = j["counts"];
    md << "| [" << j["library"].get<std::string>() << "](" << f.stem().string() << ".md) | "
       << j["version"].get<std::string>() << " | " << j["cases"] << " | " << c["agree"] << " | " << c["convention"]
       << " | " << c["wrong"] << " | " << c["crash"] << " | " << c["unjudged"] << " | " << wrong_classes << " | "
       << static_cast<long long>(j["cases_per_second"].get<double>()) << " |\n";
    rows.push_back({{"library", j["library"]},
                    {"version", j["version"]},
                    {"cases", j["cases"]},
                    {"counts", c},
                    {"wrong_classes", wrong_classes},
                    {"cases_per_second", j["cases_per_second"]}});
  }
  std::ofstream(out_dir / "summary.json") << rows.dump(2) << "\n";
}

}  // namespace collide::judge
