// The judge's run: generate, ask, judge, classify, shrink, report.

#include "collide/judge/judge.hpp"
#include "collide/laws/case_file.hpp"
#include "collide/oracle/oracle.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

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
  if (in.ask == Query::Contains) c += complexity(in.p.x()) + complexity(in.p.y());
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
    if (in.ask == Query::Contains) {
      if (form == 0) c.p = Vec2<double>(c.p.x() - shift_x, c.p.y() - shift_y);
      if (form > 0)
        c.p = Vec2<double>(std::ldexp(c.p.x(), form == 1 ? -1 : 1), std::ldexp(c.p.y(), form == 1 ? -1 : 1));
    }
    if (complexity(c) < complexity(in)) out.push_back(std::move(c));
  }
  if (in.ask == Query::Contains) {
    for (int axis = 0; axis < 2; ++axis) {
      const double v = axis == 0 ? in.p.x() : in.p.y();
      std::vector<double> tries = {0.0, std::round(v), std::trunc(v)};
      for (int bits : {1, 2, 3, 4, 6, 8, 12, 16, 20, 24, 32, 40, 48}) tries.push_back(keep_bits(v, bits));
      for (double t : tries) {
        if (t == v || complexity(t) >= complexity(v)) continue;
        Input c = in;
        c.p = axis == 0 ? Vec2<double>(t, in.p.y()) : Vec2<double>(in.p.x(), t);
        out.push_back(std::move(c));
      }
    }
  }
  std::vector<Input> valid;
  for (Input& c : out)
    if (is_clean_input(c.a) && (c.ask == Query::Contains || is_clean_input(c.b))) valid.push_back(std::move(c));
  return valid;
}

/// Greedy shrinking: each round asks the adapter for every candidate (one batch; a law's class
/// with each candidate's related input beside it) and keeps the simplest one still in the same
/// class. Returns the number of rounds that improved.
int shrink(Adapter& adapter, ClassRecord& rec, double budget_seconds) {
  const auto start = Clock::now();
  int improved = 0;
  for (int round = 0; round < 200 && since(start) < budget_seconds; ++round) {
    std::vector<Input> batch;
    for (const Input& c : shrink_candidates(rec.example)) {
      if (!rec.law) {
        batch.push_back(c);
        continue;
      }
      const std::optional<Input> related = apply(*rec.law, c);
      if (!related || !is_clean_input(related->a) || !is_clean_input(related->b)) continue;
      batch.push_back(c);
      batch.push_back(*related);
    }
    if (batch.empty()) break;
    std::vector<Answer> answers(batch.size());
    adapter.answer(batch, answers);
    const std::size_t step = rec.law ? 2 : 1;
    std::optional<std::size_t> best;
    Judgement best_j;
    for (std::size_t i = 0; i < batch.size(); i += step) {
      Judgement j = judge_answer(adapter.info(), batch[i], answers[i]);
      if (rec.law)
        j = judge_law(adapter.info(), *rec.law, batch[i], answers[i], j, batch[i + 1], answers[i + 1],
                      judge_answer(adapter.info(), batch[i + 1], answers[i + 1]));
      if (j.outcome == Outcome::Agree || class_key(batch[i], j) != rec.key) continue;
      if (!best || complexity(batch[i]) < complexity(batch[*best])) best = i, best_j = j;
    }
    if (!best) break;
    rec.example = batch[*best];
    rec.answer = answers[*best];
    rec.judgement = best_j;
    if (rec.law) rec.related = batch[*best + 1], rec.related_answer = answers[*best + 1];
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

/// Whether a reproducer's answer line (the text after "library: ") is the recorded answer: the
/// boolean, and for a push the vector bit for bit (printed to round-trip).
bool line_shows(const std::string& text, Query q, const Answer& a) {
  std::istringstream line(text);
  std::string word, value;
  line >> word >> value;
  if (value != "true" && value != "false") return false;
  if (q == Query::Contains) return word == "contains" && (value == "true") == a.contains;
  if (word != "overlap" || (value == "true") != a.overlap) return false;
  if (q != Query::Push) return true;
  if (!a.has_push) return !(line >> word);
  double x = NAN, y = NAN;
  line >> word >> x >> y;
  return word == "push" && x == a.push.x() && y == a.push.y();
}

/// Runs a reproducer (under a 30 s time-out) and reports whether it printed the library's
/// recorded answer: the wrong one, both answers of a law's class in order, "library: threw"
/// for an exception, and for a hang, running into the time-out.
void run_reproducer(Adapter& adapter, ClassRecord& rec, const std::filesystem::path& file) {
  std::string cmd;
  if (adapter.reproducer_runner() == "c++") {
    const std::filesystem::path exe = file.parent_path() / file.stem();
    cmd = "c++ -std=c++17 -O1 -o '" + exe.string() + "' '" + file.string() + "' " + adapter.reproducer_link() +
          " 2>&1 && timeout 30 '" + exe.string() + "' 2>&1";
  } else {
    cmd = "timeout 30 " + adapter.reproducer_runner() + " '" + file.string() + "' 2>&1";
  }
  std::string output;
  int status = -1;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    std::array<char, 4096> buf{};
    std::size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0 && output.size() < 65536) output.append(buf.data(), n);
    status = pclose(p);
  }
  rec.reproducer_output = output.substr(0, 2000);
  if (rec.answer.status == Status::Hung) {
    rec.reproducer_shows = WIFEXITED(status) && WEXITSTATUS(status) == 124;
    return;
  }
  if (rec.outcome == Outcome::Crash && rec.answer.status == Status::Threw) {
    rec.reproducer_shows = output.find("library: threw") != std::string::npos;
    return;
  }
  std::vector<std::string> lines;
  for (std::size_t pos = output.find("library: "); pos != std::string::npos; pos = output.find("library: ", pos + 1))
    lines.push_back(output.substr(pos + 9, output.find('\n', pos) - pos - 9));
  if (rec.law)
    rec.reproducer_shows = lines.size() >= 2 && line_shows(lines[0], rec.query, rec.answer) &&
                           line_shows(lines[1], rec.query, rec.related_answer);
  else
    rec.reproducer_shows = !lines.empty() && line_shows(lines[0], rec.query, rec.answer);
}

/// One reproducer for a law's class: the adapter's reproducers of both inputs, run one after
/// the other in one program (each in its own block, so their names do not clash).
std::string combine_reproducers(const std::string& ext, const std::string& first, const std::string& second,
                                const std::string& law) {
  const std::string note = "// " + law + ": the library's answers on both inputs, in order.\n";
  if (ext == "cpp") {
    const std::string head = "int main() {\n";
    const std::size_t p1 = first.find(head), p2 = second.find(head);
    const std::size_t e1 = first.rfind('}'), e2 = second.rfind('}');
    if (p1 == std::string::npos || p2 == std::string::npos || e1 < p1 || e2 < p2) return first;
    return first.substr(0, p1) + note + head + "  {\n" + first.substr(p1 + head.size(), e1 - p1 - head.size()) +
           "  }\n  {\n" + second.substr(p2 + head.size(), e2 - p2 - head.size()) + "  }\n}\n";
  }
  return note + "{\n" + first + "}\n{\n" + second + "}\n";
}

/// The oracle's answer on an input as the library stored it, one line (for reproducers).
std::string exact_line(const Input& in, const Answer& a) {
  try {
    if (in.ask == Query::Contains) {
      const std::optional<Shape<double>> s = to_shape(a.stored_a);
      if (!s) return "(stored shape not one of ours)";
      return std::string("contains ") + (oracle::contains(*s, a.stored_p) ? "true" : "false");
    }
    const std::optional<Shape<double>> x = to_shape(a.stored_a), y = to_shape(a.stored_b);
    if (!x || !y) return "(stored shapes not ours)";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", oracle::approx_signed_distance(*x, *y));
    return std::string("overlap ") + (oracle::overlaps(*x, *y) ? "true" : "false") + ", signed distance ~" + buf;
  } catch (const std::exception& e) {
    return std::string("(no exact answer: ") + e.what() + ")";
  }
}

void write_reports(Adapter& adapter, RunReport& r, const RunOptions& o) {
  const std::string lib = r.info.library;
  const std::filesystem::path dir = o.out_dir / lib;
  std::filesystem::create_directories(dir / "cases");
  nlohmann::json classes = nlohmann::json::array();
  for (auto& [key, rec] : r.classes) {
    if (rec.outcome == Outcome::Wrong || rec.outcome == Outcome::Crash) {
      laws::Case c;
      const bool ok = rec.answer.status == Status::Ok;
      c.law = laws::Law::Agreement;
      c.scalar = "double";
      c.a = normal_form(ok ? rec.answer.stored_a : rec.example.a);
      if (rec.example.ask == Query::Contains) {
        c.law = laws::Law::Contains;
        c.b.reset();
        const Vec2<double> p = ok ? rec.answer.stored_p : rec.example.p;
        c.px = p.x(), c.py = p.y();
      } else {
        c.b = normal_form(ok ? rec.answer.stored_b : rec.example.b);
      }
      if (rec.law) {
        // The base pair as stored; the law's map gives the related pair's stored geometry.
        c.law = rec.law->relation == Relation::Symmetry      ? laws::Law::Symmetry
                : rec.law->relation == Relation::Translation ? laws::Law::Translation
                                                             : laws::Law::Rotation;
        c.tx = rec.law->tx, c.ty = rec.law->ty;
        c.quarter_turns = rec.law->quarter_turns;
        c.mirror = rec.law->mirror;
      }
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
        auto [ext, source] = adapter.reproducer(
            rec.example, rec.query, rec.law ? "base: " + exact_line(rec.example, rec.answer) : rec.judgement.expected);
        if (rec.law) {
          const auto second =
              adapter.reproducer(rec.related, rec.query, "related: " + exact_line(rec.related, rec.related_answer));
          source = combine_reproducers(ext, source, second.second, std::string(name(rec.law->relation)) + " law");
        }
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
    if (rec.example.ask == Query::Contains) {
      jc["input"] = {{"a", shape_json(rec.example.a)}, {"p", {hex(rec.example.p.x()), hex(rec.example.p.y())}}};
      if (rec.answer.status == Status::Ok)
        jc["stored"] = {{"a", shape_json(rec.answer.stored_a)},
                        {"p", {hex(rec.answer.stored_p.x()), hex(rec.answer.stored_p.y())}}};
    } else if (rec.answer.status == Status::Ok) {
      jc["stored"] = {{"a", shape_json(rec.answer.stored_a)}, {"b", shape_json(rec.answer.stored_b)}};
    }
    if (rec.law) {
      jc["law"] = {{"relation", std::string(name(rec.law->relation))},
                   {"tx", hex(rec.law->tx)},
                   {"ty", hex(rec.law->ty)},
                   {"quarter_turns", rec.law->quarter_turns},
                   {"mirror", rec.law->mirror}};
      jc["related"] = {{"a", shape_json(rec.related.a)}, {"b", shape_json(rec.related.b)}};
      if (rec.related_answer.status == Status::Ok)
        jc["related_stored"] = {{"a", shape_json(rec.related_answer.stored_a)},
                                {"b", shape_json(rec.related_answer.stored_b)}};
    }
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
                      {"law_pairs", r.law_pairs},
                      {"law_pairs_inexact", r.law_inexact},
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
  md << "Laws (pairs whose stored geometry maps exactly, judged against each other; in parentheses the pairs "
        "whose stored geometry did not map exactly, not judged):";
  for (const auto& [law, n] : r.law_pairs)
    md << " " << law << " " << n << " (" << (r.law_inexact.count(law) ? r.law_inexact.at(law) : 0) << ")";
  md << ".\n\n";
  if (r.classes.empty()) md << "Nothing beyond the library's contract was found.\n";
  for (const auto& [key, rec] : r.classes) {
    md << "## " << key << " (" << rec.count << ")\n\n";
    if (rec.example.ask == Query::Contains) {
      md << "- input shape: `" << shape_text(rec.example.a) << "`\n- input point: `" << hex(rec.example.p.x()) << " "
         << hex(rec.example.p.y()) << "`\n";
      if (rec.answer.status == Status::Ok)
        md << "- stored shape: `" << shape_text(rec.answer.stored_a) << "`\n- stored point: `"
           << hex(rec.answer.stored_p.x()) << " " << hex(rec.answer.stored_p.y()) << "`\n";
    } else {
      md << "- input a: `" << shape_text(rec.example.a) << "`\n- input b: `" << shape_text(rec.example.b) << "`\n";
      if (rec.answer.status == Status::Ok)
        md << "- stored a: `" << shape_text(rec.answer.stored_a) << "`\n- stored b: `"
           << shape_text(rec.answer.stored_b) << "`\n";
    }
    if (rec.law)
      md << "- related input (" << name(rec.law->relation) << "): a `" << shape_text(rec.related.a) << "`, b `"
         << shape_text(rec.related.b) << "`\n";
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

namespace {

int scalar_bits(const Contract& c) {
  return c.scalar == "float32" ? 24 : 53;
}

/// Counts a non-agreeing judgement into its class, keeping the simplest example.
void record(RunReport& r, const Judgement& j, const Input& in, const Answer& a, const Link* link, const Input* other,
            const Answer* other_answer, double seconds) {
  const std::string key = class_key(in, j);
  ClassRecord& rec = r.classes[key];
  if (rec.count++ != 0 && complexity(in) >= complexity(rec.example)) return;
  if (rec.count == 1) r.first_found_seconds[key] = seconds;
  rec.key = key;
  rec.outcome = j.outcome;
  rec.severity = j.severity;
  rec.query = j.query;
  rec.example = in;
  rec.answer = a;
  rec.judgement = j;
  if (link) {
    rec.law = link->map;
    rec.related = *other;
    rec.related_answer = *other_answer;
  }
}

}  // namespace

RunReport run(Adapter& adapter, const RunOptions& o) {
  RunReport r;
  r.info = adapter.info();
  Generator gen(r.info.kinds, o.seed);
  const bool points = std::find(r.info.queries.begin(), r.info.queries.end(), Query::Contains) != r.info.queries.end();
  gen.configure(points, true, scalar_bits(r.info.contract));
  const auto start = Clock::now();
  std::vector<Input> inputs;
  std::vector<Answer> answers;
  std::vector<Link> links;
  std::vector<Judgement> judged;
  while (since(start) < o.seconds && (o.max_cases == 0 || r.cases < o.max_cases)) {
    auto t0 = Clock::now();
    inputs.clear();
    links.clear();
    std::size_t n = o.batch;
    if (o.max_cases) n = std::min<std::size_t>(n, o.max_cases - r.cases);
    gen.generate(n, inputs, &links);
    r.seconds_judge += since(t0);
    answers.assign(inputs.size(), Answer{});
    t0 = Clock::now();
    adapter.answer(inputs, answers);
    r.seconds_library += since(t0);
    t0 = Clock::now();
    judged.assign(inputs.size(), Judgement{});
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const Judgement j = judge_answer(r.info, inputs[i], answers[i]);
      judged[i] = j;
      ++r.counts[static_cast<int>(j.outcome)];
      if (j.outcome != Outcome::Agree) record(r, j, inputs[i], answers[i], nullptr, nullptr, nullptr, since(start));
    }
    // The laws: each related pair of answers judged against each other.
    for (const Link& l : links) {
      const Answer &ab = answers[l.base], &ao = answers[l.other];
      if (ab.status != Status::Ok || ao.status != Status::Ok) continue;
      const std::string law(name(l.map.relation));
      if (!law_applies(l.map, ab, ao)) {
        ++r.law_inexact[law];
        continue;
      }
      ++r.law_pairs[law];
      const Judgement j =
          judge_law(r.info, l.map, inputs[l.base], ab, judged[l.base], inputs[l.other], ao, judged[l.other]);
      if (j.outcome != Outcome::Agree) record(r, j, inputs[l.base], ab, &l, &inputs[l.other], &ao, since(start));
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
