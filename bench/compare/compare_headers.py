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

Usage: bench/compare/compare_headers.py OLD [--new NEW] [--runs N] [--reps R] [--bodies B]
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
    ap.add_argument("old")
    ap.add_argument("--new", help="revision of the new headers (default: the working tree)")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--reps", type=int, default=200)
    ap.add_argument("--bodies", type=int, default=2000)
    args = ap.parse_args()
    cxx = os.environ.get("CXX", "g++")
    with tempfile.TemporaryDirectory(prefix="collide-compare-") as tmp:
        old_inc = headers_of(args.old, os.path.join(tmp, "old"))
        new_inc = os.path.join(ROOT, "lib", "include")
        if args.new:
            new_inc = headers_of(args.new, os.path.join(tmp, "new"))
        objs = [os.path.join(tmp, "old.o"), os.path.join(tmp, "new.o")]
        jobs = [compile_side(cxx, old_inc, "old", objs[0]), compile_side(cxx, new_inc, "new", objs[1])]
        if [j.wait() for j in jobs] != [0, 0]:
            sys.exit("compare_headers: a side did not compile")
        exe = os.path.join(tmp, "compare")
        subprocess.run([cxx, os.path.join(HERE, "main.cpp"), *objs, "-lbox2d", "-lbenchmark", "-lpthread", "-o", exe],
                       check=True)
        new_name = args.new or "working tree"
        print("old: %s, new: %s; %d bodies, best of %d passes" % (args.old, new_name, args.bodies, args.reps))
        failed = False
        for run in range(args.runs):
            print("\nrun %d" % (run + 1), flush=True)
            failed |= subprocess.run([exe, str(args.bodies), str(args.reps)]).returncode != 0
        if failed:
            sys.exit("compare_headers: the two sides replayed different pairs")


if __name__ == "__main__":
    if shutil.which(os.environ.get("CXX", "g++")) is None:
        sys.exit("compare_headers: no C++ compiler")
    main()
