#!/usr/bin/env python3
"""Line and branch coverage of lib/ by the fuzz seeds and corpora and the property suite
(the backend of `./harness coverage`).

  fuzz/coverage.py [--build-dir D] [--coverage-dir C] [--no-properties] [--jobs J]

Builds the fuzz replay executables and the property suite with clang's source-based coverage
(-fprofile-instr-generate -fcoverage-mapping) in C (default build/coverage; --build-dir is
accepted for the harness and only used to place C beside it), replays every seed archive
fuzz/seeds/<target>_seed_corpus.zip and the working corpus <corpus>/<target>/ where there is one
(build/corpus, or $COLLIDE_CORPUS_DIR), runs the property suite at its ctest depth, merges the profiles with
llvm-profdata and reports lib/ with llvm-cov: printed per file and in total, and written to
build/reports/coverage.json.

Exit status: 0 on success, 2 when the build or a tool fails.
"""
import argparse
import json
import os
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "scripts"))
from collide_tools import build_targets, cache_value, print_table  # noqa: E402
from seeds import SeedError, unpack_seeds  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


def tool(name):
    for cand in (name, f"{name}-14"):
        if shutil.which(cand):
            return cand
    sys.exit(f"coverage.py: {name} not found (Debian package llvm)")


def run(cmd, **kw):
    print("+ " + " ".join(str(c) for c in cmd), flush=True)
    return subprocess.run(cmd, **kw)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--build-dir", help="(accepted for the harness; the coverage build goes beside it)")
    ap.add_argument("--coverage-dir", help="coverage build directory (default build/coverage)")
    ap.add_argument("--no-properties", action="store_true", help="corpora only")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    build = pathlib.Path(args.coverage_dir) if args.coverage_dir else ROOT / "build/coverage"
    build = build if build.is_absolute() else ROOT / build
    flags = "-fprofile-instr-generate -fcoverage-mapping"
    if cache_value(build, "CMAKE_CXX_FLAGS") != flags:
        if run(["cmake", "--preset", "clang", "-B", str(build), f"-DCMAKE_CXX_FLAGS={flags}",
                "-DCOLLIDE_BUILD_BENCH=OFF"], cwd=ROOT).returncode != 0:
            return 2
    targets = [t for t in (cache_value(build, "COLLIDE_FUZZ_TARGETS") or "").split(";") if t]
    if not targets:
        print(f"coverage.py: {build} lists no fuzz targets (COLLIDE_FUZZ_TARGETS)")
        return 2
    exes = [f"fuzz_replay_{t}" for t in targets]
    with_props = not args.no_properties
    if with_props:
        exes.append("collide_properties")
    build_targets(build, exes, args.jobs)

    prof = build / "profiles"
    shutil.rmtree(prof, ignore_errors=True)
    prof.mkdir()
    env = dict(os.environ, LLVM_PROFILE_FILE=str(prof / "%p-%m.profraw"))
    binaries = []
    for t in targets:
        exe = build / "fuzz" / f"fuzz_replay_{t}"
        binaries.append(exe)
        seeds = build / "seeds" / t
        shutil.rmtree(seeds, ignore_errors=True)
        try:
            unpack_seeds(ROOT / "fuzz/seeds" / f"{t}_seed_corpus.zip", seeds)
        except SeedError as e:
            print(f"coverage.py: {e}")
            return 2
        corpus = pathlib.Path(os.environ.get("COLLIDE_CORPUS_DIR") or ROOT / "build/corpus") / t
        inputs = [seeds] + ([corpus] if corpus.is_dir() else [])
        r = run([str(exe)] + [str(d) for d in inputs], env=env, cwd=build, stdout=subprocess.DEVNULL)
        if r.returncode != 0:
            print(f"coverage.py: replay of {t}'s inputs failed ({r.returncode}); its profile still counts")
    if with_props:
        exe = build / "properties" / "collide_properties"
        binaries.append(exe)
        # ctest's depth and seed (properties/CMakeLists.txt): at other seeds the suite's check that
        # every relation class has 10 % of the cases can fail by chance, which says nothing of lib/.
        penv = dict(env, RC_PARAMS="max_success=200 max_size=100 seed=1",
                    COLLIDE_REGRESSIONS_DIR=str(build / "property-cases"))
        r = run([str(exe), "--gtest_brief=1"], env=penv, cwd=build, stdout=subprocess.DEVNULL)
        if r.returncode != 0:
            print(f"coverage.py: the property suite failed ({r.returncode}); its profile still counts")

    merged = build / "merged.profdata"
    raws = sorted(prof.glob("*.profraw"))
    merge = [tool("llvm-profdata"), "merge", "-sparse", "-o", str(merged)] + [str(p) for p in raws]
    if not raws or run(merge).returncode:
        return 2
    objects = [str(binaries[0])] + [a for b in binaries[1:] for a in ("-object", str(b))]
    lib = str(ROOT / "lib")
    exported = subprocess.run([tool("llvm-cov"), "export", "-summary-only", f"-instr-profile={merged}"] + objects +
                              [lib], capture_output=True, text=True)
    if exported.returncode != 0:
        print(exported.stderr)
        return 2
    data = json.loads(exported.stdout)["data"][0]
    files = []
    for f in data["files"]:
        s = f["summary"]
        files.append({"file": str(pathlib.Path(f["filename"]).relative_to(ROOT)),
                      "lines": s["lines"]["count"], "lines_covered": s["lines"]["covered"],
                      "branches": s["branches"]["count"], "branches_covered": s["branches"]["covered"]})
    totals = data["totals"]

    def pct(c, n):
        return round(100.0 * c / n, 1) if n else 100.0

    lt, bt = totals["lines"], totals["branches"]
    print()
    print_table(["file", "lines", "%", "branches", "%"],
                [[f["file"], f"{f['lines_covered']}/{f['lines']}", f"{pct(f['lines_covered'], f['lines']):.1f}",
                  f"{f['branches_covered']}/{f['branches']}", f"{pct(f['branches_covered'], f['branches']):.1f}"]
                 for f in sorted(files, key=lambda f: f["file"])]
                + [["total lib/", f"{lt['covered']}/{lt['count']}", f"{pct(lt['covered'], lt['count']):.1f}",
                    f"{bt['covered']}/{bt['count']}", f"{pct(bt['covered'], bt['count']):.1f}"]], right={1, 2, 3, 4})
    report = {
        "scope": "lib/",
        "sources": {"corpora": targets, "property_suite": with_props},
        "lines": {"covered": lt["covered"], "total": lt["count"], "percent": pct(lt["covered"], lt["count"])},
        "branches": {"covered": bt["covered"], "total": bt["count"], "percent": pct(bt["covered"], bt["count"])},
        "files": files,
    }
    out = ROOT / "build/reports"
    out.mkdir(parents=True, exist_ok=True)
    (out / "coverage.json").write_text(json.dumps(report, indent=2) + "\n")
    print(f"written {out / 'coverage.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
