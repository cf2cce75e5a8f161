#!/usr/bin/env python3
"""The planted-fault check: a property suite built against the planted faults
(scripts/planted_faults.txt) with the faults FAULTS turned on (COLLIDE_PLANTED) must FAIL. With
the static suite and aabb-slip (the course notes' slip `b.max.y < a.min.x` in decide.hpp), it must
fail on the pairs that involve an AABB.

Runs each law of the build's law table (collide_describe) on the aabb pairs (and compounds, whose
bounding-box early-out uses the AABB test) and prints whether it caught the fault. Passes only if
every law that can see the fault caught it. Counterexamples go to CASES_DIR (never into
tests/regressions).

With --suite placed, SUITE_EXECUTABLE is the suite of placed shapes (transform_test.cpp), run with
the transform faults on (scripts/planted_faults.txt: images turned the wrong way, a zero rotation
accepted, a resolution margin 64 times too long); with --suite moving, the suite of moving shapes
(cast_test.cpp), run with the cast faults on. Every law of that suite (the law table's `suite`
column, from collide_describe) must catch one; the placed suite runs on pairs without an AABB.

With --laws, only the laws named (comma-separated, of the static suite) run, on every kind or pair,
and each must catch one of the faults: the faults planted for those laws alone (a signed distance
whose sign is dropped inside a polygon, a witness point left on its core).

usage: planted_fault.py SUITE_EXECUTABLE DESCRIBE_EXECUTABLE CASES_DIR --faults NAMES
                        [--suite placed|moving | --laws NAMES]
"""

import argparse
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


def run(exe, law, cases_dir, faults, pattern="{law}.*aabb*:{law}.compound_compound*"):
    env = dict(os.environ)
    env["COLLIDE_PLANTED"] = faults
    env["RC_PARAMS"] = "max_success=300 max_size=100 noshrink=1 seed=1"
    env["COLLIDE_CASES_DIR"] = cases_dir
    env.pop("COLLIDE_PROPS_REPORT", None)
    proc, report = collide_tools.run_gtest([exe, "--gtest_filter=" + pattern.format(law=law)], env=env,
                                           capture_output=True, text=True, timeout=600)
    failed = collide_tools.gtest_failures(report)
    # Caught means a test failed: a crash (no report) or an unknown fault name (the switch aborts) is not.
    if proc.returncode != 0 and not failed:
        raise SystemExit(f"planted_fault.py: {exe} stopped without a report (exit status {proc.returncode}):\n"
                         f"{proc.stderr[-2000:]}")
    return bool(failed), failed


def law_table(describe):
    return json.loads(subprocess.run([describe, "--laws"], capture_output=True, text=True, check=True).stdout)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("exe", metavar="SUITE_EXECUTABLE")
    ap.add_argument("describe", metavar="DESCRIBE_EXECUTABLE")
    ap.add_argument("cases_dir", metavar="CASES_DIR")
    ap.add_argument("--faults", required=True, metavar="NAMES", help="the planted faults to turn on, comma-separated")
    ap.add_argument("--suite", choices=sorted(SUITE_FILTERS))
    ap.add_argument("--laws", metavar="NAMES", help="only these static laws, comma-separated; each must catch one")
    args = ap.parse_args()
    exe, describe, cases_dir, suite, faults = args.exe, args.describe, args.cases_dir, args.suite, args.faults
    if args.laws:
        named = args.laws.split(",")
        static = [law["name"] for law in law_table(describe) if law["suite"] == "static"]
        unknown = [law for law in named if law not in static]
        if unknown:
            print(f"planted_fault.py: {', '.join(unknown)} not among the static laws")
            return 2
        return check_suite(exe, named, "static", cases_dir, faults, "{law}.*")
    if suite:
        return check_suite(exe, [law["name"] for law in law_table(describe) if law["suite"] == suite], suite,
                           cases_dir, faults)
    laws = [law["name"] for law in law_table(describe) if law["suite"] == "static"]
    unknown = [law for law in MUST_CATCH if law not in laws]
    if unknown:
        print(f"planted_fault.py: {', '.join(unknown)} not in the law table")
        return 2
    os.makedirs(cases_dir, exist_ok=True)
    ok = True
    rows = []
    for law in MUST_CATCH + [law for law in laws if law not in MUST_CATCH]:
        caught, tests = run(exe, law, cases_dir, faults)
        required = law in MUST_CATCH
        mark = "yes" if caught else ("NO" if required else "no")
        rows.append([law, mark, ", ".join(tests[:6]) + (" ..." if len(tests) > 6 else "")])
        if required and not caught:
            ok = False
    collide_tools.print_table(["law", "caught", "failing tests"], rows)
    print("planted fault", "CAUGHT by every law that can see it" if ok else "MISSED by a law that should see it")
    return 0 if ok else 1


def check_suite(exe, laws, suite, cases_dir, faults, pattern=None):
    os.makedirs(cases_dir, exist_ok=True)
    rows, ok = [], True
    for law in laws:
        caught, tests = run(exe, law, cases_dir, faults, pattern or SUITE_FILTERS[suite])
        rows.append([law, "yes" if caught else "NO", ", ".join(tests[:6]) + (" ..." if len(tests) > 6 else "")])
        ok = ok and caught
    collide_tools.print_table(["law", "caught", "failing tests"], rows)
    print(f"planted faults of the {suite} suite", "CAUGHT by every law" if ok else "MISSED by a law")
    return 0 if ok and laws else 1


if __name__ == "__main__":
    sys.exit(main())
