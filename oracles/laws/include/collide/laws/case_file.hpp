#pragma once
/// @file case_file.hpp
/// Regression cases: the values of a counterexample, stored as human-readable text with hex floats
/// (every bit survives), replayable through the laws, and drawable as SVG.
///
/// Format (one item per line, '#' starts a comment, order of lines free except `child` lines,
/// which follow their `shape ... compound N` line):
///
///     collide-case 1
///     law agreement
///     scalar float
///     shape a circle 0x1p+0 0x0p+0 0x1p-1            # circle cx cy r
///     shape b obb 0x1p+1 0x0p+0 0x1p+0 0x1p-1 0x1p+0 0x0p+0   # obb cx cy hx hy ux uy
///     shape b compound 2                              # then 2 child lines:
///     child aabb -0x1p+0 -0x1p+0 0x1p+0 0x1p+0        # aabb minx miny maxx maxy
///     child capsule 0x0p+0 0x0p+0 0x1p+0 0x0p+0 0x1p-2   # capsule ax ay bx by r
///     child polygon 3 x0 y0 x1 y1 x2 y2               # polygon n then n vertices
///     transform a 0x1p+0 0x0p+0 0x1p+0 0x0p+0         # optional: px py qx qy (identity when absent)
///     translation 0x1p+0 0x1p-3                       # translation law
///     rotation 1 mirror 0                             # rotation law
///     ray 0x0p+0 0x0p+0 0x1p+0 0x0p+0 max_t 0x1p+4    # raycast laws: origin, direction
///     point 0x1p+0 -0x1p-2                            # contains laws: the point
///     density 0x1p+0                                  # mass law: the density
///     values 0x1p+0 nan -inf                          # rejection laws: raw values (kind = shape a's)
///     motion 0x1p+0 0x0p+0 0x0p+0 0x0p+0 max_t 0x1p+0 # cast laws: va, vb, max_t
///     sweep a lx ly c0x c0y c1x c1y a0 a1             # toi law: local centre, centre at 0 and 1, angles
///     ghosts px py qx qy start 0                      # chain laws: the points before and after the
///                                                     # segment (shape a, a capsule of radius 0);
///                                                     # start 1: it owns the corner at its start
///     speculative 0x1p-2                              # chain laws: the speculative distance
///     expected overlaps true
///     got overlaps false
///     source property agreement circle_obb float seed 123
///     account <one line of text>
///
/// Float cases store each float as the hex of its exact double value; reading checks that it
/// narrows back exactly. The values of each kind are its codec's (codec.hpp), rebuilt through
/// the kind's factory, which must keep them bit for bit (an OBB's stored unit axis, a polygon in
/// normal form).

#include "collide/collide.hpp"
#include "collide/laws/codec.hpp"
#include "collide/laws/laws.hpp"

#include <array>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide::laws {

/// A malformed case file (line number and reason in what()); the codec's error.
using CaseError = CodecError;

/// One regression case: the law, the scalar, the inputs, and what was expected and found.
struct Case {
  Law law = Law::Agreement;                  ///< the law (its name in the file)
  std::string scalar = "double";             ///< "float" or "double"
  ShapeData a;                               ///< first shape (the compound for hierarchy, the shape for bounds/raycast)
  std::optional<ShapeData> b;                ///< second shape, for pair laws
  std::optional<TransformData> transform_a;  ///< a's placement (identity when absent)
  std::optional<TransformData> transform_b;  ///< b's placement (identity when absent)
  double tx = 0, ty = 0;                     ///< translation laws: the move
  int quarter_turns = 0;                     ///< rotation law
  bool mirror = false;                       ///< rotation law
  double ox = 0, oy = 0, dx = 0, dy = 0;     ///< raycast laws: ray origin and direction
  double max_t = 0;                          ///< raycast and cast laws: end of the interval
  double px = 0, py = 0;                     ///< contains laws: the point
  double density = 1;                        ///< mass law: the density
  double vax = 0, vay = 0, vbx = 0, vby = 0;     ///< cast laws: the velocities of a and b
  std::optional<std::array<double, 8>> sweep_a;  ///< toi law: a's sweep (local centre, c0, c1, a0, a1)
  std::optional<std::array<double, 8>> sweep_b;  ///< toi law: b's sweep
  std::vector<double> values;                    ///< rejection laws: raw values for shape a's kind, or of a transform
  std::optional<std::array<double, 4>> ghosts;   ///< chain laws: the points before a and after b of the segment
  bool owns_start = false;                       ///< chain laws: the segment owns the corner at its start
  double speculative = 0;                        ///< chain laws: the speculative distance
  std::string expected;                          ///< what the law expected (oracle side), one line
  std::string got;                               ///< what the library answered, one line
  std::string source;                            ///< where it came from: property + pair + seed, or fuzz target + input
  std::string account;                           ///< the law's account, one line
};

/// Pair name of the case ("circle_obb"), or the single kind name when there is no b.
std::string pair_name(const Case& c);

/// File stem: "<law>-<pair>-<scalar>-<8 hex digits of a hash of the values>".
std::string case_stem(const Case& c);

void write_case(std::ostream& out, const Case& c);
/// Throws CaseError with the line number on malformed input.
Case read_case(std::istream& in);
/// Writes the .case file. Throws CaseError when the file cannot be written.
void write_case(const std::filesystem::path& path, const Case& c);
/// Throws CaseError when the file cannot be read or is malformed.
Case read_case(const std::filesystem::path& path);

/// Runs the case's law on its values. A case that cannot be rebuilt is a failed Verdict (not a throw).
Verdict replay(const Case& c);

/// SVG picture of the case: the shapes (a blue, b red), their bounding boxes dashed, the
/// resolution vector for resolution cases, the moved shape for translation cases, the ray for
/// raycast cases; the law and account as a caption. Coordinates are scaled to fit 600x600.
void write_svg(std::ostream& out, const Case& c);
void write_svg(const std::filesystem::path& path, const Case& c);

/// Writes <dir>/<case_stem>.case and the .svg beside it (never overwrites a different case with
/// the same stem: the hash covers the values). Returns the .case path.
std::filesystem::path save_case(const std::filesystem::path& dir, const Case& c);

/// A case from a law's inputs and its verdict (expected/got are filled from the account).
template <Scalar T>
Case make_case(Law law, const Shape<T>& a, const std::optional<Shape<T>>& b, const Verdict& v, std::string source);

/// A case of a chain law (law table suite Chain): the segment as shape a (a capsule of radius 0)
/// with its ghosts, b placed by xb, and the speculative distance.
template <Scalar T>
Case make_chain_case(Law law, const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative,
                     const Verdict& v, std::string source);

}  // namespace collide::laws
