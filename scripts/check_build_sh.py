#!/usr/bin/env python3
"""Runs .clusterfuzzlite/build.sh with local values, as ctest tests fuzz.clusterfuzzlite_build
(--stdlib libstdc++) and fuzz.clusterfuzzlite_build_libcxx (--stdlib libc++), label slow.

Sets CXX=clang++, CXXFLAGS with ASan and -fsanitize=fuzzer-no-link, a scratch $OUT / $WORK and:
- libstdc++: LIB_FUZZING_ENGINE=-fsanitize=fuzzer, as Debian's clang links it;
- libc++: -stdlib=libc++ in CFLAGS/CXXFLAGS, as ClusterFuzzLite's image sets it. Debian's libFuzzer
  runtime is built against libstdc++, so LIB_FUZZING_ENGINE names that archive and libstdc++.so
  for libFuzzer's own use: everything collide compiles (library, oracle with CGAL and Boost, laws,
  targets) is built and linked against libc++, which the check confirms in each binary (libc++
  loaded, collide's code in std::__1, no gmpxx).
Then checks what OSS-Fuzz expects in $OUT: every target built (the judge's targets where their
library's header is installed), each with <target>_seed_corpus.zip
(the committed fuzz/seeds/<target>_seed_corpus.zip as it is) and <target>.options, and each binary
replays its unzipped seed corpus and fuzzes briefly (which runs the custom mutator) without a
failure (a judge target's short run may end on a finding in its library: a measurement).
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


# The judge's targets that need a library beyond collide's own: the library's header, as its
# Debian package installs it (judge/CMakeLists.txt builds the adapter where it is found).
JUDGE_TARGET_NEEDS = {"judge_box2d": "box2d/box2d.h", "judge_chipmunk": "chipmunk/chipmunk.h"}


def expected_targets():
    names = sorted(p.stem for p in (ROOT / "fuzz/targets").glob("*.cpp"))
    if not (ROOT / "lib/include/collide/broadphase.hpp").exists():
        names = [n for n in names if n != "broadphase"]
    for p in sorted((ROOT / "judge/fuzz/targets").glob("*.cpp")):
        header = JUDGE_TARGET_NEEDS.get(p.stem)
        if header and not any((pathlib.Path(d) / header).exists() for d in ("/usr/include", "/usr/local/include")):
            print(f"note: {p.stem} not expected: no {header} on this machine")
            continue
        names.append(p.stem)
    return names


def libfuzzer_for_libcxx(clang):
    """LIB_FUZZING_ENGINE for a -stdlib=libc++ build with Debian's libFuzzer: its archive, then the
    libstdc++ it was built against (for libFuzzer's own code only)."""
    resource = subprocess.run([clang, "-print-resource-dir"], capture_output=True, text=True).stdout.strip()
    archive = pathlib.Path(resource) / "lib/linux/libclang_rt.fuzzer-x86_64.a"
    gxx = shutil.which("g++")
    libstdcxx = subprocess.run([gxx, "-print-file-name=libstdc++.so"], capture_output=True,
                               text=True).stdout.strip() if gxx else ""
    probe = subprocess.run([clang, "-stdlib=libc++", "-x", "c++", "-std=c++20", "-fsyntax-only", "-"],
                           input="#include <vector>\n", capture_output=True, text=True)
    problems = []
    if probe.returncode != 0:
        problems.append("clang++ -stdlib=libc++ cannot compile (install libc++-14-dev and libc++abi-14-dev): "
                        + probe.stderr.strip()[-300:])
    if not archive.exists():
        problems.append(f"libFuzzer runtime {archive} missing (libclang-rt-14-dev)")
    if not libstdcxx or not pathlib.Path(libstdcxx).is_absolute():
        problems.append("libstdc++.so not found through g++ -print-file-name")
    for p in problems:
        print(f"FAIL: {p}")
    return None if problems else f"{archive} {libstdcxx}"


def libcxx_problems(binary):
    """Why binary is not a libc++ build of collide's code (empty when it is one)."""
    problems = []
    ldd = subprocess.run(["ldd", str(binary)], capture_output=True, text=True).stdout
    if "libc++.so" not in ldd:
        problems.append("does not load libc++.so")
    symbols = subprocess.run(["nm", "-C", str(binary)], capture_output=True, text=True).stdout.splitlines()
    ours = [s for s in symbols if "collide::" in s]
    if not any("std::__1::" in s for s in ours):
        problems.append("no collide symbol uses libc++'s std::__1")
    if any("std::__cxx11::" in s for s in ours):
        problems.append("collide code compiled against libstdc++ (std::__cxx11)")
    if any("__gmp_expr" in s or "mpq_class" in s for s in symbols):
        problems.append("gmpxx linked")
    return problems


def shared_gmp(binary):
    """The shared GMP/MPFR libraries binary loads (build.sh links them statically)."""
    ldd = subprocess.run(["ldd", str(binary)], capture_output=True, text=True).stdout
    return [ln.split()[0] for ln in ldd.splitlines() if "libgmp" in ln or "libmpfr" in ln]


def finding_line(target, stderr):
    return next((ln for ln in stderr.splitlines() if ln.startswith(f"== collide fuzz target {target}: finding ")), None)


def finding_only(target, stderr):
    """stderr holds a judge target's finding and no sanitizer report."""
    return finding_line(target, stderr) is not None and not any(
        s in stderr for s in ("ERROR: AddressSanitizer", "ERROR: UndefinedBehaviorSanitizer", "runtime error:"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--clang", default="clang++")
    ap.add_argument("--stdlib", choices=("libstdc++", "libc++"), default="libstdc++")
    ap.add_argument("--work", required=True, help="scratch directory (kept between runs for speed)")
    ap.add_argument("--runs", type=int, default=300, help="fuzzing iterations per target after the replay")
    args = ap.parse_args()

    work = pathlib.Path(args.work).resolve()  # build.sh changes directory
    out = work / "out"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    env = dict(os.environ)
    cc = args.clang.replace("clang++", "clang")
    flags = "-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address -fsanitize=fuzzer-no-link"
    engine = "-fsanitize=fuzzer"
    if args.stdlib == "libc++":
        flags += " -stdlib=libc++"
        engine = libfuzzer_for_libcxx(args.clang)
        if engine is None:
            return 1
    env.update({
        "CC": cc,
        "CXX": args.clang,
        "CFLAGS": flags,
        "CXXFLAGS": flags,
        "LIB_FUZZING_ENGINE": engine,
        "OUT": str(out),
        "WORK": str(work / "work"),
        "SRC": str(work / "src"),
        "COLLIDE_JOBS": env.get("COLLIDE_JOBS", "2"),
    })
    (work / "work").mkdir(parents=True, exist_ok=True)
    print(f"running .clusterfuzzlite/build.sh ({args.stdlib}): CXXFLAGS={flags} LIB_FUZZING_ENGINE={engine}",
          flush=True)
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
        committed = ROOT / "fuzz/seeds" / zipped.name
        if not committed.exists() or committed.read_bytes() != zipped.read_bytes():
            print(f"FAIL: {zipped.name} in $OUT is not the committed {committed.relative_to(ROOT)}")
            failures += 1
        if "[libfuzzer]" not in options.read_text():
            print(f"FAIL: {options.name} has no [libfuzzer] section")
            failures += 1
        if shared_gmp(binary):
            print(f"FAIL: {t}: loads {shared_gmp(binary)}; build.sh links GMP and MPFR statically")
            failures += 1
        if args.stdlib == "libc++":
            for problem in libcxx_problems(binary):
                print(f"FAIL: {t}: {problem}")
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
            # A judge target's finding is the other library's answer, a measurement (docs/judge.md):
            # its short run may end on one; anything else (a sanitizer's report) is a failure.
            if t.startswith("judge_") and fuzz.returncode != 0 and finding_only(t, fuzz.stderr):
                print(f"{t}: the short fuzzing run ended on a finding in the library: "
                      f"{finding_line(t, fuzz.stderr)}")
                fuzz = subprocess.CompletedProcess(fuzz.args, 0, fuzz.stdout, fuzz.stderr)
            for what, p in (("replay of the seed corpus", replay), ("short fuzzing run", fuzz)):
                if p.returncode != 0:
                    print(f"FAIL: {t}: {what} exited with {p.returncode}\n{p.stderr[-4000:]}")
                    failures += 1
            print(f"{t}: {len(members)} seeds replayed, {args.runs} runs fuzzed: "
                  f"{'ok' if replay.returncode == 0 and fuzz.returncode == 0 else 'FAILED'}")
    print(f"build.sh check ({args.stdlib}): {len(expected_targets())} targets, {failures} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
