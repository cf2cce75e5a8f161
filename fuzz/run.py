#!/usr/bin/env python3
"""Long fuzzing runs of collide's libFuzzer targets (the backend of `./harness fuzz`).

  fuzz/run.py [--build-dir D] [--target T ...] [--minutes M | --hours H] [--jobs J]
              [--no-sanitizers] [--no-merge]

- Configures and builds the `fuzz` preset (clang, ASan + UBSan, -fsanitize=fuzzer) if needed.
  D is used when it is such a build; otherwise (e.g. the g++ build the harness passes) the fuzz
  build goes to build/fuzz beside it. --no-sanitizers builds build/fuzz-nosan instead (speed).
- Runs the targets one after another, sharing the time budget (M minutes in total), each in
  libFuzzer's fork mode with J workers, so a failure is recorded and the run goes on. Prints a
  progress line each minute: elapsed, executions, exec/s, corpus size, coverage, failures.
- At the end merges the new inputs that add coverage into fuzz/corpus/<target>/ (-merge=1),
  groups the failing inputs by what failed (law, scalar and wording of the account, or the
  sanitizer's summary), minimises the smallest input of each group, and turns it into a
  regression case under tests/regressions/: a .case file + .svg (the property suite's format)
  when a law broke, else the raw input (<target>-<hash>.input) with the crash report beside it
  (.txt).
- Writes build/reports/fuzz.md and build/reports/fuzz.json.

Exit status: 0 when no target failed, 1 when failures were found, 2 on a build or usage error.
"""
import argparse
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import threading
import time

from cmake_cache import cache_value

ROOT = pathlib.Path(__file__).resolve().parent.parent
STATS_RE = re.compile(r"#(\d+):?\s.*?cov: (\d+).*?ft: (\d+).*?corp: (\d+).*?exec/s:? (\d+)")
CASE_RE = re.compile(r"case file: (\S+)")
RAW_RE = re.compile(r"regression input: (\S+)")


def log(msg):
    print(msg, flush=True)




def choose_build_dir(arg, no_sanitizers):
    if arg and not no_sanitizers:
        d = pathlib.Path(arg)
        d = d if d.is_absolute() else ROOT / d
        if cache_value(d, "COLLIDE_FUZZ_ENGINE"):
            return d
    return ROOT / "build" / ("fuzz-nosan" if no_sanitizers else "fuzz")


def configure_and_build(build, targets, jobs, no_sanitizers):
    if not cache_value(build, "COLLIDE_FUZZ_ENGINE"):
        cmd = ["cmake", "--preset", "fuzz", "-B", str(build)]
        if no_sanitizers:
            cmd.append("-DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link -fno-omit-frame-pointer")
        log("configure: " + " ".join(cmd))
        if subprocess.run(cmd, cwd=ROOT).returncode != 0:
            return None
    else:
        subprocess.run(["cmake", str(build)], cwd=ROOT, stdout=subprocess.DEVNULL)
    available = (cache_value(build, "COLLIDE_FUZZ_TARGETS") or "").split(";")
    available = [t for t in available if t]
    if not available:
        log("fuzz/run.py: no fuzz targets configured (is collide::laws built?)")
        return None
    chosen = targets or available
    unknown = [t for t in chosen if t not in available]
    if unknown:
        log(f"fuzz/run.py: unknown target(s) {unknown}; available: {available}")
        return None
    cmd = ["cmake", "--build", str(build), "-j", str(jobs), "--target"] + [f"fuzz_{t}" for t in chosen]
    log("build: " + " ".join(cmd))
    if subprocess.run(cmd, cwd=ROOT).returncode != 0:
        return None
    return chosen


def failures_in(d):
    return sorted(p for p in d.glob("*") if p.name.split("-")[0] in ("crash", "timeout", "oom", "leak", "slow"))


class Stats:
    def __init__(self):
        self.execs = self.cov = self.ft = self.corp = self.eps = 0
        self.lock = threading.Lock()

    def feed(self, line):
        m = STATS_RE.search(line)
        if m:
            with self.lock:
                self.execs, self.cov, self.ft, self.corp, self.eps = (int(x) for x in m.groups())


def fmt_count(n):
    for unit, div in (("G", 1e9), ("M", 1e6), ("k", 1e3)):
        if n >= div:
            return f"{n / div:.1f}{unit}"
    return str(n)


def run_target(binary, target, seconds, jobs, work):
    """One fork-mode run; returns its statistics."""
    seeds = ROOT / "fuzz/corpus" / target
    new = work / "new"
    crashes = work / "crashes"
    shutil.rmtree(work, ignore_errors=True)
    new.mkdir(parents=True)
    crashes.mkdir()
    logfile = work / "libfuzzer.log"
    cmd = [str(binary), f"-fork={max(1, jobs)}", "-ignore_crashes=1", "-ignore_timeouts=1", "-ignore_ooms=1",
           f"-max_total_time={seconds}", f"-artifact_prefix={crashes}/", "-max_len=4096", "-timeout=20",
           "-rss_limit_mb=2560", "-print_final_stats=1", str(new), str(seeds)]
    stats = Stats()
    start = time.time()
    with open(logfile, "w") as lf:
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace",
                                cwd=work)

        def pump():
            for line in proc.stdout:
                lf.write(line)
                stats.feed(line)

        reader = threading.Thread(target=pump, daemon=True)
        reader.start()
        next_report = start + 60
        while proc.poll() is None:
            time.sleep(1)
            now = time.time()
            if now >= next_report:
                next_report += 60
                with stats.lock:
                    log(f"  [{target} {int(now - start) // 60}:{int(now - start) % 60:02d}] "
                        f"execs {fmt_count(stats.execs)}, {fmt_count(stats.eps)} exec/s, corpus {stats.corp}, "
                        f"cov {stats.cov} (ft {stats.ft}), failures {len(failures_in(crashes))}")
        reader.join(timeout=10)
    elapsed = time.time() - start
    return {
        "target": target,
        "seconds": round(elapsed, 1),
        "executions": stats.execs,
        "exec_per_s": round(stats.execs / elapsed) if elapsed > 0 else 0,
        "coverage_edges": stats.cov,
        "features": stats.ft,
        "corpus": stats.corp,
        "exit_code": proc.returncode,
        "log": str(logfile.relative_to(ROOT)) if logfile.is_relative_to(ROOT) else str(logfile),
        "artifacts": [str(p) for p in failures_in(crashes)],
    }


def merge(binary, target, work):
    seeds = ROOT / "fuzz/corpus" / target
    before = {p.name for p in seeds.iterdir()}
    r = subprocess.run([str(binary), "-merge=1", "-max_len=4096", "-timeout=20", "-rss_limit_mb=2560", str(seeds),
                        str(work / "new")], cwd=work, capture_output=True, text=True, errors="replace")
    after = {p.name for p in seeds.iterdir()}
    if r.returncode != 0:
        log(f"  merge of {target} exited with {r.returncode} (corpus kept as merged so far)")
    return len(after - before), len(after)


def signature(binary, artifact, work):
    """What a failure is, for grouping: the law, the scalar and the words of its account, or the
    sanitizer's summary line. One night can write thousands of artifacts of one bug; each bug is
    minimised and promoted once."""
    r = subprocess.run([str(binary), "-timeout=20", "-rss_limit_mb=2560", str(artifact)], cwd=work,
                       capture_output=True, text=True, errors="replace")
    lines = r.stderr.splitlines()
    head = next((ln for ln in lines if ln.startswith("== collide fuzz target")), None)
    if head:
        # The law, the scalar and the wording of what was expected and got, numbers left out.
        said = [re.sub(r"\(0x[^)]*\)|[-+]?\d[\d.]*(e[-+]?\d+)?", "#", ln.strip()) for ln in lines
                if ln.strip().startswith(("expected:", "got:"))]
        return " | ".join([head.strip()] + [" ".join(x.split()[:8]) for x in said])
    summary = next((ln for ln in lines if "SUMMARY:" in ln), None)
    if summary:
        return re.sub(r"0x[0-9a-f]+", "", summary.strip())
    return f"{pathlib.Path(artifact).name.split('-')[0]} (exit {r.returncode})"


def distinct_failures(binary, artifacts, work):
    """[(smallest artifact, how many artifacts share its signature, signature)]."""
    groups = {}
    for art in artifacts:
        groups.setdefault(signature(binary, art, work), []).append(art)
    return [(min(arts, key=lambda a: pathlib.Path(a).stat().st_size), len(arts), sig)
            for sig, arts in groups.items()]


def to_regression(binary, target, artifact, work):
    """Minimises a failure and stores it as a regression case; returns a description."""
    art = pathlib.Path(artifact)
    kind = art.name.split("-")[0]
    minimized = work / f"min-{art.name}"
    if kind == "crash":
        subprocess.run([str(binary), "-minimize_crash=1", "-runs=3000", "-max_total_time=120",
                        f"-exact_artifact_path={minimized}", str(art)], cwd=work, capture_output=True)
    # libFuzzer's minimiser keeps any failing input, and a shorter input often fails another law:
    # keep the minimised input only when it still fails the same way.
    if minimized.exists() and signature(binary, minimized, work) != signature(binary, art, work):
        minimized.unlink()
    if not minimized.exists():
        shutil.copy(art, minimized)
    regressions = ROOT / "tests/regressions"
    regressions.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, COLLIDE_FUZZ_CASE_DIR=str(regressions))
    r = subprocess.run([str(binary), "-timeout=20", "-rss_limit_mb=2560", str(minimized)], cwd=work, env=env,
                       capture_output=True, text=True, errors="replace")
    report = r.stderr
    entry = {"artifact": str(art), "kind": kind, "bytes": minimized.stat().st_size}
    m = CASE_RE.search(report) or RAW_RE.search(report)
    if m:
        path = pathlib.Path(m.group(1))
        entry["case_file"] = str(path.relative_to(ROOT)) if path.is_relative_to(ROOT) else str(path)
        svg = path.with_suffix(".svg")
        if svg.exists():
            entry["svg"] = str(svg.relative_to(ROOT)) if svg.is_relative_to(ROOT) else str(svg)
    else:
        # A sanitizer report, a timeout or an out-of-memory: keep the raw input and the report.
        data = minimized.read_bytes()
        h = 2166136261
        for b in data:
            h = ((h ^ b) * 16777619) & 0xFFFFFFFF
        stem = regressions / f"{target}-{h:08x}"
        stem.with_suffix(".input").write_bytes(data)
        stem.with_suffix(".txt").write_text(f"fuzz target {target} ({kind})\n" + report[-6000:])
        entry["case_file"] = str(stem.with_suffix(".input").relative_to(ROOT))
    summary = [ln.strip() for ln in report.splitlines()
               if ln.startswith("==") or "SUMMARY" in ln or ln.strip().startswith(("expected:", "got:"))]
    entry["summary"] = " | ".join(summary[:4])[:600]
    return entry


def write_reports(results, args, build):
    reports = ROOT / "build/reports"
    reports.mkdir(parents=True, exist_ok=True)
    doc = {"build_dir": str(build), "sanitizers": not args.no_sanitizers, "jobs": args.jobs, "targets": results,
           "failures": sum(len(r["failures"]) for r in results)}
    (reports / "fuzz.json").write_text(json.dumps(doc, indent=2) + "\n")
    lines = ["# Fuzzing report", "",
             f"Build: `{build.relative_to(ROOT) if build.is_relative_to(ROOT) else build}` "
             f"({'ASan + UBSan' if not args.no_sanitizers else 'no sanitizers'}), fork workers per target: {args.jobs}.",
             "", "| target | time (s) | executions | exec/s | coverage (edges / features) | corpus | new inputs | failures |",
             "|---|---:|---:|---:|---|---:|---:|---:|"]
    for r in results:
        lines.append(f"| {r['target']} | {r['seconds']} | {r['executions']} | {r['exec_per_s']} | "
                     f"{r['coverage_edges']} / {r['features']} | {r.get('corpus_after', r['corpus'])} | "
                     f"{r.get('new_inputs', 0)} | {len(r['failures'])} |")
    for r in results:
        if r["failures"]:
            lines += ["", f"## Failures of {r['target']}", ""]
            for f in r["failures"]:
                link = f.get("case_file", "")
                svg = f" ([picture]({f['svg']}))" if f.get("svg") else ""
                lines.append(f"- {f['kind']} ({f['inputs']} failing inputs alike): [{link}]({link}){svg} — "
                             f"{f.get('summary', '')}")
    (reports / "fuzz.md").write_text("\n".join(lines) + "\n")
    return reports


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--build-dir", help="a fuzz-preset build to use (others: build/fuzz is used)")
    ap.add_argument("--target", action="append", help="target to run (repeatable; default: all)")
    budget = ap.add_mutually_exclusive_group()
    budget.add_argument("--minutes", type=float, help="total time budget in minutes (default 10)")
    budget.add_argument("--hours", type=float, help="total time budget in hours")
    ap.add_argument("--jobs", type=int, default=2, help="fork workers per target and build parallelism (default 2)")
    ap.add_argument("--no-sanitizers", action="store_true", help="build and run without ASan/UBSan (speed)")
    ap.add_argument("--no-merge", action="store_true", help="leave fuzz/corpus/ unchanged")
    args = ap.parse_args()
    total = (args.hours * 3600 if args.hours else (args.minutes if args.minutes is not None else 10) * 60)

    build = choose_build_dir(args.build_dir, args.no_sanitizers)
    targets = configure_and_build(build, args.target, args.jobs, args.no_sanitizers)
    if targets is None:
        return 2
    per_target = max(10, int(total / len(targets)))
    log(f"fuzzing {', '.join(targets)}: {per_target} s each, {args.jobs} fork workers")
    results = []
    for t in targets:
        binary = build / "fuzz/bin" / t
        work = ROOT / "build/fuzz-runs" / t
        log(f"== {t}")
        res = run_target(binary, t, per_target, args.jobs, work)
        if not args.no_merge:
            res["new_inputs"], res["corpus_after"] = merge(binary, t, work)
        artifacts = res.pop("artifacts")
        res["failure_inputs"] = len(artifacts)
        res["failures"] = []
        for art, count, sig in distinct_failures(binary, artifacts, work):
            entry = to_regression(binary, t, art, work)
            entry.update({"inputs": count, "signature": sig})
            res["failures"].append(entry)
        log(f"  {t}: {res['executions']} executions, {res['exec_per_s']} exec/s, cov {res['coverage_edges']}, "
            f"{res.get('new_inputs', 0)} new inputs, {len(res['failures'])} distinct failures "
            f"({res['failure_inputs']} failing inputs)")
        for f in res["failures"]:
            log(f"    {f['kind']} x{f['inputs']}: {f.get('case_file')}  {f.get('summary', '')[:200]}")
        results.append(res)
    reports = write_reports(results, args, build)
    log(f"reports: {reports / 'fuzz.md'}, {reports / 'fuzz.json'}")
    return 1 if any(r["failures"] for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
