#!/usr/bin/env python3
"""Runs .clusterfuzzlite/build.sh with local values, as ctest test fuzz.clusterfuzzlite_build.

Sets CXX=clang++, CXXFLAGS with ASan and -fsanitize=fuzzer-no-link (no -stdlib=libc++: Debian's
libFuzzer runtime is built against libstdc++ and does not link with it),
LIB_FUZZING_ENGINE=-fsanitize=fuzzer and a scratch $OUT / $WORK, then
checks what OSS-Fuzz expects in $OUT: every target built, each with <target>_seed_corpus.zip and
<target>.options, and each binary replays its unzipped seed corpus and fuzzes briefly (which runs
the custom mutator) without a failure.
"""
import argparse
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import zipfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def expected_targets():
    names = sorted(p.stem for p in (ROOT / "fuzz/targets").glob("*.cpp"))
    if not (ROOT / "lib/include/collide/broadphase.hpp").exists():
        names = [n for n in names if n != "broadphase"]
    return names


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--clang", default="clang++")
    ap.add_argument("--work", required=True, help="scratch directory (kept between runs for speed)")
    ap.add_argument("--runs", type=int, default=300, help="fuzzing iterations per target after the replay")
    args = ap.parse_args()

    work = pathlib.Path(args.work)
    out = work / "out"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    env = dict(os.environ)
    cc = args.clang.replace("clang++", "clang")
    env.update({
        "CC": cc,
        "CXX": args.clang,
        "CFLAGS": "-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address -fsanitize=fuzzer-no-link",
        "CXXFLAGS": "-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address -fsanitize=fuzzer-no-link",
        "LIB_FUZZING_ENGINE": "-fsanitize=fuzzer",
        "OUT": str(out),
        "WORK": str(work / "work"),
        "SRC": str(work / "src"),
        "COLLIDE_JOBS": env.get("COLLIDE_JOBS", "2"),
    })
    (work / "work").mkdir(parents=True, exist_ok=True)
    print("running .clusterfuzzlite/build.sh", flush=True)
    r = subprocess.run(["bash", str(ROOT / ".clusterfuzzlite/build.sh")], env=env)
    if r.returncode != 0:
        print(f"FAIL: build.sh exited with {r.returncode}")
        return 1

    failures = 0
    for t in expected_targets():
        binary, zipped, options = out / t, out / f"{t}_seed_corpus.zip", out / f"{t}.options"
        for f in (binary, zipped, options):
            if not f.exists():
                print(f"FAIL: {f.name} missing from $OUT")
                failures += 1
        if not binary.exists() or not zipped.exists():
            continue
        if "[libfuzzer]" not in options.read_text():
            print(f"FAIL: {options.name} has no [libfuzzer] section")
            failures += 1
        with tempfile.TemporaryDirectory() as tmp, zipfile.ZipFile(zipped) as z:
            members = [m for m in z.namelist() if not m.endswith("/")]
            if not members:
                print(f"FAIL: {zipped.name} is empty")
                failures += 1
                continue
            z.extractall(tmp)
            replay = subprocess.run([str(binary), "-runs=0", tmp], capture_output=True, text=True)
            fuzz = subprocess.run([str(binary), f"-runs={args.runs}", "-seed=1", f"-artifact_prefix={tmp}/", tmp],
                                  capture_output=True, text=True)
            for what, p in (("replay of the seed corpus", replay), ("short fuzzing run", fuzz)):
                if p.returncode != 0:
                    print(f"FAIL: {t}: {what} exited with {p.returncode}\n{p.stderr[-4000:]}")
                    failures += 1
            print(f"{t}: {len(members)} seeds replayed, {args.runs} runs fuzzed: "
                  f"{'ok' if replay.returncode == 0 and fuzz.returncode == 0 else 'FAILED'}")
    print(f"build.sh check: {len(expected_targets())} targets, {failures} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
