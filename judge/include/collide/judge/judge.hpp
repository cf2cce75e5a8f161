#pragma once
/// @file judge.hpp
/// The judge: generates pair inputs aimed at the hard places (touching, ulp nudges, scales from
/// tiny to huge, slivers, far from the origin), asks an adapter, judges each answer exactly with
/// the oracle on the geometry the library stored, classifies it against the library's declared
/// contract, shrinks each wrong class to a small counterexample and writes the reports.

#include "collide/judge/adapter.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace collide::judge {

/// The four outcomes of judging one answer (plus inputs that could not be judged).
enum class Outcome : std::uint8_t {
  Agree,       ///< the answer is the exact one
  Convention,  ///< differs only where the contract allows: touching, or within the declared band
  Wrong,       ///< beyond the contract
  Crash,       ///< exception, non-finite output, signal, hang
  Unjudged     ///< the stored geometry is not a shape the oracle takes (named in the class)
};

/// "agree", "convention", "wrong", "crash", "unjudged".
std::string_view name(Outcome o) noexcept;

/// How far beyond the contract a wrong answer is.
enum class Severity : std::uint8_t {
  None,      ///< not wrong
  Touching,  ///< the library breaks its own declared touching convention at exact touching
  Rounding,  ///< beyond the band by at most sqrt(epsilon of its scalar) times the scale
  Gross      ///< farther
};

/// "none", "touching", "rounding", "gross".
std::string_view name(Severity s) noexcept;

/// The judgement of one answer.
struct Judgement {
  Outcome outcome = Outcome::Agree;
  Severity severity = Severity::None;
  Query query = Query::Overlap;
  std::string what;      ///< class name part: "false_overlap", "push_leaves_overlap", ... (empty for Agree)
  std::string expected;  ///< the exact answer, one line
  std::string got;       ///< the library's answer, one line
};

/// Judges one answer against the exact oracle and the contract (queries: what the adapter declared).
Judgement judge_answer(const Info& info, const Input& input, const Answer& answer);

/// The class of a judgement that is not Agree: "<outcome>.<what>.<severity>.<kindA>_<kindB>"
/// ("<kind>_point" for a point query).
std::string class_key(const Input& input, const Judgement& j);

/// A metamorphic law: an exact map of a pair input under which the library's answers must
/// correspond (laws.cpp).
enum class Relation : std::uint8_t {
  Symmetry,     ///< the arguments swapped: the same overlap, the push negated
  Translation,  ///< both shapes moved by (tx, ty), every sum exact: the same answers
  Rotation      ///< both shapes mirrored (x -> -x) then turned by quarter turns: the answers mapped
};

/// "symmetry", "translation", "rotation".
std::string_view name(Relation r) noexcept;

/// One relation with its parameters.
struct Map {
  Relation relation = Relation::Symmetry;
  double tx = 0, ty = 0;  ///< Translation
  int quarter_turns = 0;  ///< Rotation: counter-clockwise, after the mirror
  bool mirror = false;    ///< Rotation
};

/// The input under the map (for Translation, only when every moved value is the exact sum:
/// nullopt otherwise, and for inputs the map does not take).
std::optional<Input> apply(const Map& m, const Input& in);

/// Two inputs of one batch related by a law: inputs[other] is apply(map, inputs[base]).
struct Link {
  std::size_t base = 0;
  std::size_t other = 0;
  Map map;
};

/// Judges the library's answers on two related inputs against each other: Agree when they
/// correspond (or the law does not apply: the stored geometry of `other` is not exactly the
/// mapped stored geometry of `base`, or either answer is not an answer); otherwise the class
/// "<relation>_overlap" or "<relation>_push", Convention when both answers are within the
/// contract alone (jb, jo: their own judgements), else Wrong with the worse severity.
Judgement judge_law(const Info& info, const Map& m, const Input& base, const Answer& ab, const Judgement& jb,
                    const Input& other, const Answer& ao, const Judgement& jo);

/// Whether the law applied to this pair of answers (the stored geometry maps exactly).
bool law_applies(const Map& m, const Answer& ab, const Answer& ao);

/// Generates inputs for the kinds an adapter supports.
class Generator {
 public:
  Generator(std::vector<ShapeKind> kinds, std::uint64_t seed);
  /// Also generate point inputs (a quarter of the inputs), and the laws' related inputs; the
  /// scalar's significand bits choose translations that stay exact in it.
  void configure(bool points, bool laws, int scalar_bits);
  /// Appends about n inputs: each pair in both orders (a symmetry link), and for some pairs an
  /// exactly translated and an exactly rotated or mirrored copy (their links appended to links).
  void generate(std::size_t n, std::vector<Input>& out, std::vector<Link>* links = nullptr);

 private:
  ShapeData shape(ShapeKind k, double size, double cx, double cy);
  Input family_random(ShapeKind ka, ShapeKind kb);
  Input family_touching(ShapeKind ka, ShapeKind kb);
  Input family_nudged(ShapeKind ka, ShapeKind kb);
  Input family_scaled(ShapeKind ka, ShapeKind kb);
  Input family_sliver(ShapeKind ka, ShapeKind kb);
  Input family_point(ShapeKind k);
  /// The pair snapped to a coarse grid and a translation by a power of two beyond every value
  /// that keeps each sum exact in the scalar (nullopt when snapping spoils a shape).
  std::optional<std::pair<Input, Map>> translated(const Input& in);
  std::vector<ShapeKind> kinds_;
  std::mt19937_64 rng_;
  bool points_ = false;
  bool laws_ = false;
  int scalar_bits_ = 53;
};

/// A shape's values, validated: the Shape<double> the oracle judges, or nullopt when the
/// values do not make one of our shapes (a stored polygon that is not strictly convex, say).
std::optional<Shape<double>> to_shape(const ShapeData& d);

/// An input the judge may send: one of our shapes with no redundant values (a polygon without
/// repeated or collinear vertices), so that a library is never handed a degenerate description.
bool is_clean_input(const ShapeData& d);

/// One class of non-agreeing answers.
struct ClassRecord {
  std::string key;
  Outcome outcome{};
  Severity severity{};
  Query query{};
  std::uint64_t count = 0;
  Input example;           ///< the smallest counterexample found (after shrinking)
  Answer answer;           ///< the library's answer on it
  Judgement judgement;     ///< its judgement
  std::optional<Map> law;  ///< a law's class: the map, and the related input with its answer
  Input related;
  Answer related_answer;
  std::string case_file;  ///< paths relative to the report directory
  std::string picture;
  std::string reproducer;
  std::string reproducer_output;  ///< what the reproducer printed (first lines)
  bool reproducer_shows = false;  ///< it ran and printed the library's wrong answer
};

/// Run limits and options.
struct RunOptions {
  double seconds = 60;
  std::uint64_t max_cases = 0;  ///< 0: no limit
  std::uint64_t seed = 1;
  std::size_t batch = 4096;
  std::filesystem::path out_dir = "build/reports/judge";
  bool shrink = true;
  double shrink_seconds = 2;  ///< per class (30 of them in all at most)
  bool reproducers = true;
};

/// What a run measured.
struct RunReport {
  Info info;
  std::uint64_t counts[5] = {};  ///< by Outcome
  std::map<std::string, ClassRecord> classes;
  std::uint64_t cases = 0;
  double seconds_total = 0;
  double seconds_library = 0;                         ///< inside the adapter (library + its conversions + protocol)
  double seconds_judge = 0;                           ///< generation, oracle, classification
  std::map<std::string, double> first_found_seconds;  ///< class -> seconds into the run
  std::map<std::string, std::uint64_t> law_pairs;     ///< relation -> pairs judged by it
  std::map<std::string, std::uint64_t> law_inexact;   ///< relation -> pairs whose stored geometry did not map exactly
};

/// Runs the judge on one adapter; writes <out>/<library>.json, <library>.md and the cases,
/// pictures and reproducers under <out>/<library>/.
RunReport run(Adapter& adapter, const RunOptions& options);

/// Writes <out>/summary.md and summary.json: one row per report found in out.
void write_summary(const std::filesystem::path& out_dir);

}  // namespace collide::judge
