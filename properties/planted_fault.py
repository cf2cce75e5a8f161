#!/usr/bin/env python3
"""The planted-fault check: the property suite built against the planted fault aabb-slip
(scripts/planted_faults.txt: the course notes' slip `b.max.y < a.min.x` in decide.hpp) must FAIL
on the pairs that involve an AABB.

Runs each law of the build's law table (collide_describe) on the aabb pairs (and compounds, whose
bounding-box early-out uses the AABB test) and prints whether it caught the fault. Passes only if
every law that can see the fault caught it. Counterexamples go to CASES_DIR (never into
tests/regressions).

With --suite placed, SUITE_EXECUTABLE is the suite of placed shapes (transform_test.cpp) built
against the transform faults (scripts/planted_faults.txt: images turned the wrong way, a zero
rotation accepted, a resolution margin 64 times too long); with --suite moving, the suite of moving
shapes (cast_test.cpp) built against the cast faults. Every law of that suite (the law table's
`suite` column, from collide_describe) must catch one; the placed suite runs on pairs without an
AABB (so that the AABB slip is not what it sees).

usage: planted_fault.py SUITE_EXECUTABLE DESCRIBE_EXECUTABLE CASES_DIR [--suite placed|moving]
"""

import json
import os
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "scripts"))
import collide_tools  # noqa: E402

# Laws that compare overlaps() with something independent of aabb_aabb (the oracle, the other
# argument order, a moved/turned/re-represented pair, the children, the distance): each must see
# it. The other laws check other things (contact consistency with overlaps(), bounds, bad input):
# reported, not required.
MUST_CATCH = ["agreement", "symmetry", "translation", "rotation", "resolution", "hierarchy",
              "representation", "distance"]

# --suite: the tests each law of the suite runs on.
SUITE_FILTERS = {
    "placed": ":".join("{law}." + t for t in [
        "circle_obb*", "circle_polygon*", "obb_obb*", "obb_capsule*", "obb_polygon*", "capsule_polygon*",
        "polygon_polygon*", "obb_float", "obb_double", "polygon_float", "polygon_double", "float", "double"]),
    "moving": "{law}.*",
}


def run(exe, law, cases_dir, pattern="{law}.*aabb*:{law}.compound_compound*"):
    env = dict(os.environ)
    env["RC_PARAMS"] = "max_success=300 max_size=100 noshrink=1 seed=1"
    env["COLLIDE_CASES_DIR"] = cases_dir
    env.pop("COLLIDE_PROPS_REPORT", None)
    proc, report = collide_tools.run_gtest([exe, "--gtest_filter=" + pattern.format(law=law)], env=env,
                                           capture_output=True, text=True, timeout=600)
    return proc.returncode != 0, collide_tools.gtest_failures(report)


def law_table(describe):
    return json.loads(subprocess.run([describe, "--laws"], capture_output=True, text=True, check=True).stdout)


def main():
    suite = sys.argv[5] if len(sys.argv) == 6 and sys.argv[4] == "--suite" else None
    if len(sys.argv) != (6 if suite else 4) or (suite and suite not in SUITE_FILTERS):
        print(__doc__)
        return 2
    exe, describe, cases_dir = sys.argv[1:4]
    if suite:
        return check_suite(exe, [law["name"] for law in law_table(describe) if law["suite"] == suite], suite,
                           cases_dir)
    laws = [law["name"] for law in law_table(describe) if law["suite"] == "static"]
    unknown = [law for law in MUST_CATCH if law not in laws]
    if unknown:
        print(f"planted_fault.py: {', '.join(unknown)} not in the law table")
        return 2
    os.makedirs(cases_dir, exist_ok=True)
    ok = True
    rows = []
    for law in MUST_CATCH + [law for law in laws if law not in MUST_CATCH]:
        caught, tests = run(exe, law, cases_dir)
        required = law in MUST_CATCH
        mark = "yes" if caught else ("NO" if required else "no")
        rows.append([law, mark, ", ".join(tests[:6]) + (" ..." if len(tests) > 6 else "")])
        if required and not caught:
            ok = False
    collide_tools.print_table(["law", "caught", "failing tests"], rows)
    print("planted fault", "CAUGHT by every law that can see it" if ok else "MISSED by a law that should see it")
    return 0 if ok else 1


def check_suite(exe, laws, suite, cases_dir):
    os.makedirs(cases_dir, exist_ok=True)
    rows, ok = [], True
    for law in laws:
        caught, tests = run(exe, law, cases_dir, SUITE_FILTERS[suite])
        rows.append([law, "yes" if caught else "NO", ", ".join(tests[:6]) + (" ..." if len(tests) > 6 else "")])
        ok = ok and caught
    collide_tools.print_table(["law", "caught", "failing tests"], rows)
    print(f"planted faults of the {suite} suite", "CAUGHT by every law" if ok else "MISSED by a law")
    return 0 if ok and laws else 1


if __name__ == "__main__":
    sys.exit(main())
