#!/usr/bin/env python3
"""The planted-fault check: the property suite built with COLLIDE_PLANTED_FAULT (the course notes'
AABB slip `b.max.y < a.min.x` in decide.hpp) must FAIL on the pairs that involve an AABB.

Runs each law family on the aabb pairs (and compounds, whose bounding-box early-out uses the AABB
test) and prints whether it caught the fault. Passes only if every family that can see the fault
caught it. Counterexamples go to CASES_DIR (never into tests/regressions).

With --transform, SUITE_EXECUTABLE is the transform suite (transform_test.cpp) built with the
same define, which also plants the transform faults (images turned the wrong way, a zero rotation
accepted, a resolution margin 64 times too long): each transform law must catch one, on pairs
without an AABB (so that the AABB slip is not what it sees).

usage: planted_fault.py SUITE_EXECUTABLE CASES_DIR [--transform]
"""

import os
import subprocess
import sys

# Families that compare overlaps() with something independent of aabb_aabb (the oracle, the other
# argument order, a moved/turned/re-represented pair, the children, the distance): each must see it.
MUST_CATCH = ["agreement", "symmetry", "translation", "rotation", "resolution", "hierarchy",
              "representation", "distance"]
# Families that check other things (contact consistency with overlaps(), bounds, bad input):
# reported, not required.
MAY_CATCH = ["contact", "bounds", "raycast", "rejection", "contains", "touching", "scene"]

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
    proc = subprocess.run([exe, "--gtest_filter=" + pattern.format(law=law)], env=env,
                          capture_output=True, text=True, timeout=600)
    failed = [line.split()[3] for line in proc.stdout.splitlines()
              if line.startswith("[  FAILED  ]") and len(line.split()) > 3 and "." in line.split()[3]]
    return proc.returncode != 0, sorted(set(failed))


def main():
    transform = "--transform" in sys.argv[3:]
    if len(sys.argv) != (4 if transform else 3):
        print(__doc__)
        return 2
    exe, cases_dir = sys.argv[1], sys.argv[2]
    os.makedirs(cases_dir, exist_ok=True)
    ok = True
    must, may = (TRANSFORM_LAWS, []) if transform else (MUST_CATCH, MAY_CATCH)
    print(f"{'law':20} {'caught':7} failing tests")
    for law in must + may:
        caught, tests = run(exe, law, cases_dir, TRANSFORM_FILTER) if transform else run(exe, law, cases_dir)
        required = law in must
        mark = "yes" if caught else ("NO" if required else "no")
        print(f"{law:20} {mark:7} {', '.join(tests[:6])}{' ...' if len(tests) > 6 else ''}")
        if required and not caught:
            ok = False
    print("planted fault", "CAUGHT by every family that can see it" if ok else "MISSED by a family that should see it")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
