#!/usr/bin/env python3
"""Compares the speed of two versions of the library's headers in one process: the pairs of
bodies whose bounding boxes overlap in frames 30-39 of the game loop (bench/game_loop.cpp),
contact() kind pair by kind pair, each kind pair's pass timed with the old headers and the new
ones alternately (the best of --reps each).

On a shared machine whose speed changes from minute to minute, two binaries run one after the
other can differ by more than a change does; passes alternated within one process see the same
machine. Both sides are built from this tree's bench/game_loop.cpp, so the scene and the pairs
are the same; only the library's headers differ. Two identical sides differ by a few per cent per
kind pair (where the compiler places the code) and about 1 % over all.

With --box2d instead of OLD, the same pairs are timed against Box2D 2.4.1's b2Collide* (as the
game loop calls them, under the same poses): collide / Box2D per kind pair, which says where the
game loop's narrowphase spends more than Box2D's. With --world as well, each Box2D manifold with
points is also turned into world points, normal and separations (b2WorldManifold::Initialize), the
values contact() returns, so both sides compute the same kind of answer.

With --pairs apart (or contact), only the pairs that contact() finds apart (or in contact) are
replayed: a pair apart costs Box2D one pass over a shape's faces, and collide's answer for it
may cost more or less than for a pair in contact, so the two say where a gap comes from.

Usage: bench/compare/compare_headers.py OLD [--new NEW] [--pairs P] [--runs N] [--reps R] [--bodies B]
       bench/compare/compare_headers.py --box2d [--world] [--new NEW] [--pairs P] [--runs N] [--reps R] [--bodies B]
  OLD, NEW: git revisions whose lib/include is compared (NEW: the working tree's lib/include).
Needs g++ (or $CXX), Eigen, Box2D 2.4.1 and Google Benchmark, as collide_bench does.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def headers_of(rev, into):
    """lib/include of git revision rev, extracted under into; returns its include directory."""
    os.makedirs(into)
    archive = subprocess.run(["git", "-C", ROOT, "archive", rev, "lib/include"], stdout=subprocess.PIPE, check=True)
    subprocess.run(["tar", "-x", "-C", into], input=archive.stdout, check=True)
    return os.path.join(into, "lib", "include")


def compile_side(cxx, include, side, out):
    flags = ["-O3", "-DNDEBUG", "-std=c++20", "-I" + include, "-isystem", "/usr/include/eigen3",
             "-Dcollide=collide_" + side, "-Dbench=bench_" + side, "-DCOMPARE_SIDE=" + side]
    return subprocess.Popen([cxx, *flags, "-c", os.path.join(HERE, "replay.cpp"), "-o", out])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("old", nargs="?")
    ap.add_argument("--box2d", action="store_true", help="compare the new headers with Box2D 2.4.1 instead of OLD")
    ap.add_argument("--world", action="store_true",
                    help="with --box2d: Box2D's manifolds also turned into world values")
    ap.add_argument("--new", help="revision of the new headers (default: the working tree)")
    ap.add_argument("--pairs", choices=["all", "apart", "contact"], default="all",
                    help="replay all pairs, or only those contact() finds apart, or in contact")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--reps", type=int, default=200)
    ap.add_argument("--bodies", type=int, default=2000)
    args = ap.parse_args()
    if (args.old is None) == (not args.box2d):
        ap.error("give either OLD or --box2d")
    if args.world and not args.box2d:
        ap.error("--world needs --box2d")
    cxx = os.environ.get("CXX", "g++")
    with tempfile.TemporaryDirectory(prefix="collide-compare-") as tmp:
        new_inc = os.path.join(ROOT, "lib", "include")
        if args.new:
            new_inc = headers_of(args.new, os.path.join(tmp, "new"))
        sides = [(new_inc, "new")]
        if not args.box2d:
            sides.insert(0, (headers_of(args.old, os.path.join(tmp, "old")), "old"))
        objs = [os.path.join(tmp, side + ".o") for _, side in sides]
        jobs = [compile_side(cxx, inc, side, obj) for (inc, side), obj in zip(sides, objs)]
        if any(j.wait() != 0 for j in jobs):
            sys.exit("compare_headers: a side did not compile")
        exe = os.path.join(tmp, "compare")
        driver = (["-DCOMPARE_BOX2D"] if args.box2d else []) + (["-DCOMPARE_WORLD"] if args.world else [])
        libs = ["-lbox2d", "-lbenchmark", "-lpthread"]
        subprocess.run([cxx, *driver, os.path.join(HERE, "main.cpp"), *objs, *libs, "-o", exe], check=True)
        new_name = args.new or "working tree"
        if args.box2d:
            against = "Box2D 2.4.1" + (" with world manifolds" if args.world else "")
        else:
            against = "old: " + args.old
        print("%s, new: %s; %d bodies, %s pairs, best of %d passes" %
              (against, new_name, args.bodies, args.pairs, args.reps))
        failed = False
        for run in range(args.runs):
            print("\nrun %d" % (run + 1), flush=True)
            failed |= subprocess.run([exe, str(args.bodies), str(args.reps), args.pairs]).returncode != 0
        if failed:
            sys.exit("compare_headers: the two sides replayed different pairs")


if __name__ == "__main__":
    if shutil.which(os.environ.get("CXX", "g++")) is None:
        sys.exit("compare_headers: no C++ compiler")
    main()
