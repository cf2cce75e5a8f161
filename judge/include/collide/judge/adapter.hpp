#pragma once
/// @file adapter.hpp
/// The adapter contract: how the judge questions another collision library. An adapter says
/// which of our shape kinds it can build in the library, answers pair queries on them, reports
/// the geometry the library actually stored (so the oracle judges the library on that geometry
/// and a conversion is never blamed on it), and declares the library's own contract (scalar,
/// touching convention, tolerance as a function of scale, direction of its push vector).
///
/// Two forms of one contract: an in-process C++ adapter (a type modelling InProcessAdapter,
/// wrapped by in_process()), and a subprocess speaking the batched binary protocol of
/// protocol.hpp (docs/judge.md). The driver sees both as an Adapter.

#include "collide/collide.hpp"
#include "collide/laws/codec.hpp"

#include <concepts>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace collide::judge {

using laws::ShapeData;

/// What a query asks. Overlap: the boolean. Push: a translation of one shape that separates the
/// pair (a minimum translation vector, or a contact normal times depth, as the library gives it).
/// Contains: whether a point lies in one shape (closed, under the contract's touching convention).
enum class Query : std::uint8_t { Overlap = 0, Push = 1, Contains = 2 };

/// How the library counts shapes that touch exactly (exact signed distance 0).
enum class Touching : std::uint8_t {
  Overlap,  ///< touching overlaps (closed shapes, collide's own convention)
  Apart,    ///< touching is apart (a strict test)
  Either    ///< not documented, or decided by rounding: both answers are the convention
};

/// Which shape the library's push vector moves (after the adapter's documented mapping).
enum class PushMoves : std::uint8_t {
  A,  ///< translating the first shape by the vector separates the pair
  B   ///< translating the second shape by the vector separates the pair
};

/// The library's declared contract. Every disagreement with the exact oracle is classified
/// against it; a band of tol_abs + tol_rel * scale (scale = the largest magnitude among the
/// stored values of both shapes) is where an answer may differ from the exact one.
struct Contract {
  std::string scalar = "float64";  ///< "float32" or "float64": what the library computes in
  Touching touching = Touching::Overlap;
  double tol_abs = 0;  ///< absolute part of the tolerance band (a skin, a slop)
  double tol_rel = 0;  ///< relative part, times the scale of the stored values
  PushMoves push_moves = PushMoves::A;
  std::string source;  ///< where the contract is documented (file, function), one line
  /// The smallest shape the library is documented (or, with the reason in `source`, designed)
  /// for: a disagreement on a pair with a smaller shape (the larger side of its bounding box)
  /// is the convention "below_min_size", counted apart from wrong answers. 0: every size.
  double min_size = 0;
  /// The largest shape the library is documented for (Box2D and planck: static shapes up to
  /// 50 m): a disagreement on a pair with a larger shape is the convention "above_max_size". 0:
  /// every size.
  double max_size = 0;
  /// Point containment's own convention where it differs from the pair queries' (a closed test
  /// beside a strict one, a probe box instead of a point); unset: touching and tol_abs above.
  std::optional<Touching> contains_touching = std::nullopt;
  std::optional<double> contains_tol_abs = std::nullopt;
};

/// One adapter's description, from its handshake.
struct Info {
  std::string library;           ///< name used in reports and file names: "matter-js"
  std::string version;           ///< the library's version, as it reports it
  std::vector<ShapeKind> kinds;  ///< our kinds it can build (never Compound)
  std::vector<Query> queries;    ///< what it answers (Overlap at least)
  Contract contract;
  std::string mapping;  ///< how each of our kinds becomes a library shape, one line per kind
};

/// One input: two of our shapes by their stored values (codec.hpp's field order; an OBB is
/// cx cy hx hy ux uy with a unit axis) for the pair queries, or one shape and a point.
struct Input {
  ShapeData a;
  ShapeData b;                 ///< pair queries only
  Query ask = Query::Overlap;  ///< Overlap: the pair queries (and push, when declared); Contains: a and p
  Vec2<double> p{0.0, 0.0};    ///< Contains: the point
};

/// What the library did with one input.
enum class Status : std::uint8_t {
  Ok = 0,           ///< it answered
  Threw = 1,        ///< it raised an exception (message in `error`)
  Unsupported = 2,  ///< the adapter cannot build this input in the library (not judged)
  Hung = 3          ///< no answer within the time-out (set by the driver, never sent by an adapter)
};

/// The library's answer to one input, with the shapes as it stored them (world coordinates,
/// our kinds: a polygonised circle is a polygon, a box rotated by angle its rotated vertices).
struct Answer {
  Status status = Status::Ok;
  bool overlap = false;
  bool has_push = false;  ///< push holds the library's vector (only with Query::Push, on overlap)
  Vec2<double> push{0.0, 0.0};
  ShapeData stored_a;
  ShapeData stored_b;
  bool contains = false;            ///< Contains: the library's answer
  Vec2<double> stored_p{0.0, 0.0};  ///< Contains: the point as the library holds it
  std::string error;                ///< Threw, Hung: the message
};

/// The driver's view of any adapter, in-process or subprocess.
class Adapter {
 public:
  virtual ~Adapter() = default;
  virtual const Info& info() const = 0;
  /// Answers a batch: out has inputs.size() elements. Throws AdapterError when the adapter
  /// itself breaks (a protocol violation, a dead or hung subprocess that cannot be isolated).
  virtual void answer(std::span<const Input> inputs, std::span<Answer> out) = 0;
  /// A standalone program in the library's own language and API (no collide) that builds the
  /// input as the adapter does, asks the query and prints its answer beside `exact` (one line
  /// naming the exact answer). Returns {file extension, source}.
  virtual std::pair<std::string, std::string> reproducer(const Input& input, Query query, const std::string& exact) = 0;
  /// How a reproducer is run: the command before the file's path ("node"), or "c++" for a C++
  /// source the driver compiles with reproducer_link() flags.
  virtual std::string reproducer_runner() const = 0;
  virtual std::string reproducer_link() const { return ""; }
};

/// An adapter that broke its contract with the driver (not a library's wrong answer).
class AdapterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An in-process adapter: a C++ type that builds shapes in the library and answers one input at
/// a time. answer() may throw (a Threw answer); a signal raised inside it (an assert's abort, a
/// segmentation fault) is caught by the wrapper and counted as a crash.
template <class A>
concept InProcessAdapter = requires(A& a, const Input& in, Query q, const std::string& exact) {
  { a.info() } -> std::convertible_to<Info>;
  { a.answer(in) } -> std::same_as<Answer>;
  { a.reproducer(in, q, exact) } -> std::convertible_to<std::string>;  // C++ source
  { a.link_flags() } -> std::convertible_to<std::string>;              // e.g. "-lbox2d"
};

namespace detail {
/// Runs f() with SIGABRT, SIGSEGV, SIGFPE, SIGBUS and SIGILL turned into a false return (and
/// the signal's name in `what`); true when f returned normally. Used around library calls only.
/// Under an armed Watchdog, a call that runs past its limit is abandoned the same way, with
/// `what` starting "hang".
bool run_guarded(void (*f)(void*), void* ctx, std::string& what);

/// Arms a hang time-out over a batch of run_guarded calls (one interval timer per batch, so a
/// call costs no system call): a single call running longer than `limit` (wall clock, checked
/// every tenth of it) is abandoned. Disarmed on destruction. One at a time per process.
class Watchdog {
 public:
  explicit Watchdog(double limit_seconds);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;
};

/// The in-process hang limit: 5 s (a library call takes microseconds; the margin is for a loaded
/// machine).
inline constexpr double kHangSeconds = 5.0;
}  // namespace detail

/// Wraps an in-process adapter as an Adapter.
template <InProcessAdapter A>
class InProcess final : public Adapter {
 public:
  explicit InProcess(A adapter = A()) : a_(std::move(adapter)), info_(a_.info()) {}
  const Info& info() const override { return info_; }
  void answer(std::span<const Input> inputs, std::span<Answer> out) override {
    const detail::Watchdog watchdog(detail::kHangSeconds);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      struct Ctx {
        A* a;
        const Input* in;
        Answer* out;
      } ctx{&a_, &inputs[i], &out[i]};
      std::string what;
      const bool returned = detail::run_guarded(
          [](void* p) {
            auto* c = static_cast<Ctx*>(p);
            try {
              *c->out = c->a->answer(*c->in);
            } catch (const std::exception& e) {
              *c->out = Answer{};
              c->out->status = Status::Threw;
              c->out->error = e.what();
            }
          },
          &ctx, what);
      if (!returned) {
        out[i] = Answer{};
        out[i].status = what.rfind("hang", 0) == 0 ? Status::Hung : Status::Threw;
        out[i].error = what;
      }
    }
  }
  std::pair<std::string, std::string> reproducer(const Input& input, Query query, const std::string& exact) override {
    return {"cpp", a_.reproducer(input, query, exact)};
  }
  std::string reproducer_runner() const override { return "c++"; }
  std::string reproducer_link() const override { return a_.link_flags(); }

 private:
  A a_;
  Info info_;
};

/// "overlap", "push", "contains".
std::string_view name(Query q) noexcept;
/// "overlap", "apart", "either".
std::string_view name(Touching t) noexcept;

}  // namespace collide::judge
