#pragma once
// In-process adapter for the course notes' reference code (course_notes.hpp): circles and
// axis-aligned boxes, overlap and resolution, in double, stored exactly as given.

#include "collide/judge/adapter.hpp"
#include "collide/judge/repro.hpp"
#include "course_notes.hpp"

#include <variant>

namespace collide::judge {

class CourseNotesAdapter {
 public:
  static Info info() {
    Info i;
    i.library = "course-notes";
    i.version = "reference code";
    i.kinds = {ShapeKind::Circle, ShapeKind::Aabb};
    i.queries = {Query::Overlap, Query::Push};
    // The notes: closed shapes (touching collides), the resolution moves the first shape, and
    // no tolerance: they present their tests as exact, so any rounding shows as a rounding-level
    // wrong answer, apart from the gross ones.
    i.contract = {
        "float64",    Touching::Overlap,
        0.0,          0.0,
        PushMoves::A, "the course notes' text: touching shapes collide; resolve(a, b) moves a out of b; no tolerance"};
    i.mapping = "circle -> Circle{c, r}; aabb -> Box{min, max}; values as given (double)";
    return i;
  }

  Answer answer(const Input& in) const {
    Answer out;
    out.stored_a = in.a;
    out.stored_b = in.b;
    std::visit(
        [&](const auto& a, const auto& b) {
          out.overlap = course_notes::overlaps(a, b);
          if (out.overlap) {
            const course_notes::Vec v = course_notes::resolve(a, b);
            out.has_push = true;
            out.push = Vec2<double>(v.x, v.y);
          }
        },
        build(in.a), build(in.b));
    return out;
  }

  std::string reproducer(const Input& in, Query q, const std::string& exact) const {
    std::string s = repro::cpp_prelude("Course notes' reference code: a wrong " + std::string(name(q)) + " answer.");
    s += "#include \"" COLLIDE_JUDGE_COURSE_NOTES_HEADER "\"\n\nint main() {\n";
    s += "  const auto a = " + literal(in.a) + ";\n  const auto b = " + literal(in.b) + ";\n";
    s += "  const bool o = course_notes::overlaps(a, b);\n  std::printf(\"library: overlap %s\", o ? \"true\" : "
         "\"false\");\n";
    if (q == Query::Push)
      s += "  if (o) {\n    const course_notes::Vec v = course_notes::resolve(a, b);\n"
           "    std::printf(\" push %.17g %.17g\", v.x, v.y);\n  }\n";
    s += "  std::printf(\"\\nexact:   %s\\n\", " + repro::cpp_string(exact) + ");\n}\n";
    return s;
  }

  std::string link_flags() const { return ""; }

 private:
  using Any = std::variant<course_notes::Circle, course_notes::Box>;
  static Any build(const ShapeData& d) {
    const auto& v = d.values;
    if (d.kind == ShapeKind::Circle) return course_notes::Circle{{v.at(0), v.at(1)}, v.at(2)};
    if (d.kind == ShapeKind::Aabb) return course_notes::Box{{v.at(0), v.at(1)}, {v.at(2), v.at(3)}};
    throw std::invalid_argument("course notes: no shape for kind " + std::string(name(d.kind)));
  }
  static std::string literal(const ShapeData& d) {
    const auto& v = d.values;
    if (d.kind == ShapeKind::Circle)
      return "course_notes::Circle{{" + repro::cpp(v[0]) + ", " + repro::cpp(v[1]) + "}, " + repro::cpp(v[2]) + "}";
    return "course_notes::Box{{" + repro::cpp(v[0]) + ", " + repro::cpp(v[1]) + "}, {" + repro::cpp(v[2]) + ", " +
           repro::cpp(v[3]) + "}}";
  }
};

static_assert(InProcessAdapter<CourseNotesAdapter>);

}  // namespace collide::judge
