#!/usr/bin/env python3
"""The planted-fault check: the property suite built against the planted fault aabb-slip
(scripts/planted_faults.txt: the course notes' slip `b.max.y < a.min.x` in decide.hpp) must FAIL
on the pairs that involve an AABB.

Runs each law of the build's law table (collide_describe) on the aabb pairs (and compounds, whose
bounding-box early-out uses the AABB test) and prints whether it caught the fault. Passes only if
every law that can see the fault caught it. Counterexamples go to CASES_DIR (never into
tests/regressions).

With --transform, SUITE_EXECUTABLE is the transform suite (transform_test.cpp) built against the
transform faults (scripts/planted_faults.txt: images turned the wrong way, a zero rotation
accepted, a resolution margin 64 times too long): each transform law must catch one, on pairs
without an AABB (so that the AABB slip is not what it sees).

usage: planted_fault.py SUITE_EXECUTABLE DESCRIBE_EXECUTABLE CASES_DIR [--transform]
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

# --transform: every transform law must catch the transform faults; the filter avoids AABBs.
TRANSFORM_LAWS = ["placed_agreement", "placed_outputs", "placed_resolution", "placed_shape",
                  "placed_covariance", "placed_image", "transform_rejection"]
TRANSFORM_FILTER = ":".join("{law}." + t for t in [
    "circle_obb*", "circle_polygon*", "obb_obb*", "obb_capsule*", "obb_polygon*", "capsule_polygon*",
    "polygon_polygon*", "obb_float", "obb_double", "polygon_float", "polygon_double", "float", "double"])


def run(exe, law, cases_dir, pattern="{law}.*aabb*:{law}.compound_compound*"):
    env = dict(os.environ)
    env["RC_PARAMS"] = "max_success=300 max_size=100 noshrink=1 seed=1"
    env["COLLIDE_CASES_DIR"] = cases_dir
    env.pop("COLLIDE_PROPS_REPORT", None)
    proc, report = collide_tools.run_gtest([exe, "--gtest_filter=" + pattern.format(law=law)], env=env,
                                           capture_output=True, text=True, timeout=600)
    return proc.returncode != 0, collide_tools.gtest_failures(report)


def main():
    transform = "--transform" in sys.argv[4:]
    if len(sys.argv) != (5 if transform else 4):
        print(__doc__)
        return 2
    exe, describe, cases_dir = sys.argv[1:4]
    if transform:
        return check_transform_laws(exe, cases_dir)
    laws = [law["name"] for law in json.loads(subprocess.run([describe, "--laws"], capture_output=True,
                                                             text=True, check=True).stdout)]
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


def check_transform_laws(exe, cases_dir):
    os.makedirs(cases_dir, exist_ok=True)
    rows, ok = [], True
    for law in TRANSFORM_LAWS:
        caught, tests = run(exe, law, cases_dir, TRANSFORM_FILTER)
        rows.append([law, "yes" if caught else "NO", ", ".join(tests[:6]) + (" ..." if len(tests) > 6 else "")])
        ok = ok and caught
    collide_tools.print_table(["law", "caught", "failing tests"], rows)
    print("planted transform faults", "CAUGHT by every transform law" if ok else "MISSED by a transform law")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
