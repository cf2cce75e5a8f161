#!/usr/bin/env python3
"""Long fuzzing runs of collide's libFuzzer targets (the backend of `./harness fuzz`).

  fuzz/run.py [--build-dir D] [--target T ...] [--minutes M | --hours H] [--jobs J]
              [--no-sanitizers] [--no-merge] [--resume]
  fuzz/run.py --export-seeds [--reminimise] [--build-dir D] [--target T ...]

- Configures and builds the `fuzz` preset (clang, ASan + UBSan, -fsanitize=fuzzer) if needed.
  D is used when it is such a build; otherwise (e.g. the g++ build the harness passes) the fuzz
  build goes to build/fuzz beside it. --no-sanitizers builds build/fuzz-nosan instead (speed).
- The working corpus of each target is <corpus>/<target>/, outside the tracked tree: build/corpus
  unless COLLIDE_CORPUS_DIR or --corpus-dir names another root. The committed seed archive
  fuzz/seeds/<target>_seed_corpus.zip is unpacked into it first (all of it into a missing or
  empty one; into an older one, the seeds it lacks).
- Runs the targets one after another, sharing the time budget (M minutes in total), each in
  libFuzzer's fork mode with J workers, so a failure is recorded and the run goes on. Prints a
  progress line each minute of the whole run: elapsed and total time, the current target and its
  executions, exec/s, corpus size, coverage, failures.
- SIGINT (Ctrl-C) or SIGTERM stops the current target's fuzzer and goes on to what a finished run
  does with what it has: merge, promote the failures, write the reports, exit with the usual
  status. The plan (targets, time each, what finished) is kept in build/fuzz-runs/state.json:
  --resume runs what is left of it (the interrupted target for its remaining time, from its
  inputs so far, then the targets not started) and reports the whole run.
- At the end merges the new inputs that add coverage into the working corpus (-merge=1),
  groups the failing inputs by what failed (law, scalar and wording of the account, or the
  sanitizer's summary), minimises the smallest input of each group, and turns it into a
  regression case under tests/regressions/: a .case file + .svg (the property suite's format)
  when a law broke, else the raw input (<target>-<hash>.input) with the crash report beside it
  (.txt).
- Writes build/reports/fuzz.md and build/reports/fuzz.json.
- The judge's targets judge_<adapter> (judge/fuzz, COLLIDE_JUDGE_FUZZ_TARGETS) judge other
  libraries: they run only when named (--target judge_box2d), and their failures go to
  build/reports/judge-fuzz/ (raw input and account), never to tests/regressions/.
- --export-seeds fuzzes nothing: for each target it minimises the working corpus together with the
  current seeds (-merge=1 into an empty directory) and rewrites fuzz/seeds/<target>_seed_corpus.zip
  for a commit: entries named by their SHA-1, in name order, with fixed timestamps, so the same
  inputs always give the same bytes. An archive whose inputs the working corpus adds no coverage
  to is left as it is (--reminimise rewrites it too: for an archive that was never minimised,
  or after a change to a target that alters its coverage). Prints, per target, the inputs, bytes
  and libFuzzer's cov of the archive and of the working corpus.

Exit status: 0 when no target failed, 1 when failures were found (an interrupted run too: its
report says it was interrupted), 2 on a build or usage error or a seed archive that cannot be
read or written.
"""
import argparse
import json
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "scripts"))
from collide_tools import build_targets, cache_value, fnv1a, write_report  # noqa: E402
from seeds import SeedError, entry_name, read_seeds, unpack_seeds, write_seeds  # noqa: E402


ROOT = pathlib.Path(__file__).resolve().parent.parent
INITED_RE = re.compile(r"INITED cov: (\d+) ft: (\d+)")
STATS_RE = re.compile(r"#(\d+):?\s.*?cov: (\d+).*?ft: (\d+).*?corp: (\d+).*?exec/s:? (\d+)")
CASE_RE = re.compile(r"case file: (\S+)")
RAW_RE = re.compile(r"regression input: (\S+)")
# How long a stopped fuzzer may take to exit before it is killed.
STOP_GRACE_S = 30


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
    available = [t for t in (cache_value(build, "COLLIDE_FUZZ_TARGETS") or "").split(";") if t]
    if not available:
        log(f"fuzz/run.py: {build} lists no fuzz targets (COLLIDE_FUZZ_TARGETS)")
        return None
    chosen = targets or available
    # The judge's targets (judge/fuzz) are built and run only when named.
    available += [t for t in (cache_value(build, "COLLIDE_JUDGE_FUZZ_TARGETS") or "").split(";") if t]
    unknown = [t for t in chosen if t not in available]
    if unknown:
        log(f"fuzz/run.py: unknown target(s) {unknown}; available: {available}")
        return None
    log(f"build: {', '.join(f'fuzz_{t}' for t in chosen)} in {build}")
    build_targets(build, [f"fuzz_{t}" for t in chosen], jobs)
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


def shown(path):
    """A path as reports show it: relative to the tree when inside it."""
    path = pathlib.Path(path)
    return str(path.relative_to(ROOT)) if path.is_relative_to(ROOT) else str(path)


def shielded(cmd, **kw):
    """subprocess.run in a session of its own: a Ctrl-C at the terminal reaches this script only,
    which stops the fuzzer and lets the merge and the minimisation that follow finish."""
    return subprocess.run(cmd, start_new_session=True, **kw)


class Places:
    """Where a run reads and writes: the working corpus (build/corpus, or COLLIDE_CORPUS_DIR), the
    tree's seed archives and regressions, scratch and reports unless told otherwise (the tests run
    against scratch copies)."""

    def __init__(self, args):
        def pick(value, default):
            return pathlib.Path(value).resolve() if value else ROOT / default
        self.corpus = pick(args.corpus_dir or os.environ.get("COLLIDE_CORPUS_DIR"), "build/corpus")
        self.seeds = pick(args.seeds_dir, "fuzz/seeds")
        self.regressions = pick(args.regressions_dir, "tests/regressions")
        self.runs = pick(args.runs_dir, "build/fuzz-runs")
        self.reports = pick(args.reports_dir, "build/reports")
        self.state = self.runs / "state.json"


class Stop:
    """SIGINT and SIGTERM: stop the running fuzzer (its whole process group: fork mode's workers
    too), then let the run merge, promote and report what it has."""

    def __init__(self):
        self.signal = None
        self.proc = None

    def install(self):
        for sig in (signal.SIGINT, signal.SIGTERM):
            signal.signal(sig, self.handle)

    def handle(self, signum, _frame):
        if self.signal is not None:
            log(f"{signal.Signals(signum).name}: already stopping; merging and reporting what was found")
            return
        self.signal = signum
        log(f"{signal.Signals(signum).name}: stopping the fuzzer; merging and reporting what was found "
            f"(continue later with --resume)")
        self.stop_fuzzer(signal.SIGINT)

    def stop_fuzzer(self, sig):
        proc = self.proc
        if proc is not None and proc.poll() is None:
            try:
                os.killpg(proc.pid, sig)
            except ProcessLookupError:
                pass


class Ticker:
    """One progress line per interval of the whole run (not per target)."""

    def __init__(self, total_seconds, done_before, interval):
        self.start = time.time()
        self.total = total_seconds
        self.done_before = done_before  # seconds spent by the part of the run being resumed
        self.interval = interval
        self.next = self.start + interval
        self.failures_before = 0       # failing inputs of the targets already run in this process

    def tick(self, label, stats, crashes):
        now = time.time()
        if now < self.next:
            return
        while self.next <= now:
            self.next += self.interval
        with stats.lock:
            log(f"[{clock(self.done_before + now - self.start)} of {clock(self.total)}] {label}: "
                f"execs {fmt_count(stats.execs)}, {fmt_count(stats.eps)} exec/s, corpus {stats.corp}, "
                f"cov {stats.cov} (ft {stats.ft}), failing inputs {self.failures_before + len(failures_in(crashes))}")


def clock(seconds):
    s = int(seconds)
    return f"{s // 3600}:{s % 3600 // 60:02d}:{s % 60:02d}"


def seed_archive(places, target):
    return places.seeds / f"{target}_seed_corpus.zip"


def prepare_corpus(places, target):
    """Makes sure <corpus>/<target>/ exists and holds every seed of the target's archive: a new
    one gets them all, an older one those committed since (inputs are named by their SHA-1 in
    both, so a seed already there is not written twice). Raises SeedError when the archive
    cannot be read."""
    corpus = places.corpus / target
    corpus.mkdir(parents=True, exist_ok=True)
    archive = seed_archive(places, target)
    if not archive.exists():
        if not any(corpus.iterdir()):
            log(f"  {target}: no seed archive {shown(archive)}; starting from an empty corpus")
        return corpus
    seeds = read_seeds(archive)
    missing = {name: data for name, data in seeds.items() if not (corpus / name).exists()}
    if missing:  # inputs under other names (written by make_corpus.py, say) are there already
        held = {entry_name(p.read_bytes()) for p in corpus.iterdir() if p.is_file()}
        missing = {name: data for name, data in missing.items() if name not in held}
    for name, data in missing.items():
        (corpus / name).write_bytes(data)
    if missing:
        log(f"  {target}: unpacked {len(missing)} of the {len(seeds)} seeds of {shown(archive)} into {shown(corpus)}")
    return corpus


def run_target(binary, target, seconds, jobs, work, places, stop, ticker, label, keep_inputs):
    """One fork-mode run; returns its statistics. keep_inputs: go on from the inputs an
    interrupted run of this target left in work/new."""
    seeds = places.corpus / target
    new = work / "new"
    crashes = work / "crashes"
    tmp = work / "tmp"
    if not keep_inputs:
        shutil.rmtree(work, ignore_errors=True)
    # Failing inputs of an earlier part were promoted when it stopped.
    shutil.rmtree(crashes, ignore_errors=True)
    shutil.rmtree(tmp, ignore_errors=True)
    for d in (seeds, new, crashes, tmp):
        d.mkdir(parents=True, exist_ok=True)
    logfile = work / "libfuzzer.log"
    cmd = [str(binary), f"-fork={max(1, jobs)}", "-ignore_crashes=1", "-ignore_timeouts=1", "-ignore_ooms=1",
           f"-max_total_time={seconds}", f"-artifact_prefix={crashes}/", "-max_len=4096", "-timeout=20",
           "-rss_limit_mb=2560", "-print_final_stats=1", str(new), str(seeds)]
    stats = Stats()
    start = time.time()
    # Fork mode's scratch directories go under work/, not /tmp, when a stop leaves them behind.
    env = dict(os.environ, TMPDIR=str(tmp))
    with open(logfile, "a" if keep_inputs else "w") as lf:
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace",
                                cwd=work, env=env, start_new_session=True)
        stop.proc = proc

        def pump():
            for line in proc.stdout:
                lf.write(line)
                stats.feed(line)

        reader = threading.Thread(target=pump, daemon=True)
        reader.start()
        stopped_at = None
        while proc.poll() is None:
            time.sleep(0.2)
            ticker.tick(label, stats, crashes)
            if stop.signal is not None:
                stopped_at = stopped_at or time.time()
                if time.time() - stopped_at > STOP_GRACE_S:
                    stop.stop_fuzzer(signal.SIGKILL)
        stop.proc = None
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
        "interrupted": stop.signal is not None,
        "log": shown(logfile),
        "artifacts": [str(p) for p in failures_in(crashes)],
    }


def merge(binary, target, work, places):
    seeds = places.corpus / target
    before = {p.name for p in seeds.iterdir()}
    r = shielded([str(binary), "-merge=1", "-max_len=4096", "-timeout=20", "-rss_limit_mb=2560", str(seeds),
                  str(work / "new")], cwd=work, capture_output=True, text=True, errors="replace")
    after = {p.name for p in seeds.iterdir()}
    if r.returncode != 0:
        log(f"  merge of {target} exited with {r.returncode} (corpus kept as merged so far)")
    return len(after - before), len(after)


def coverage(binary, corpus, work):
    """libFuzzer's (cov, ft) after loading every input of corpus once (-runs=0)."""
    r = shielded([str(binary), "-runs=0", "-max_len=4096", "-timeout=20", "-rss_limit_mb=2560", str(corpus)],
                 cwd=work, capture_output=True, text=True, errors="replace")
    m = INITED_RE.search(r.stderr + r.stdout)
    return (int(m.group(1)), int(m.group(2))) if m and r.returncode == 0 else None


def merged_into(binary, out, inputs, work):
    """-merge=1: the inputs of the directories `inputs` that add coverage to `out` are copied into
    it. Returns the files added, or None when the merge failed."""
    before = {p.name for p in out.iterdir()}
    r = shielded([str(binary), "-merge=1", "-max_len=4096", "-timeout=20", "-rss_limit_mb=2560", str(out)]
                 + [str(d) for d in inputs], cwd=work, capture_output=True, text=True, errors="replace")
    if r.returncode != 0:
        log(f"  merge exited with {r.returncode}:\n{r.stderr[-2000:]}")
        return None
    return sorted(p for p in out.iterdir() if p.name not in before)


def export_seeds(binary, target, places, reminimise):
    """Minimises the working corpus with the current seeds and rewrites the target's archive
    unless the corpus adds no coverage to it (reminimise: rewrites it in any case). Returns a
    report entry, or None on a failure."""
    archive = seed_archive(places, target)
    corpus = prepare_corpus(places, target)
    work = places.runs / "export" / target
    shutil.rmtree(work, ignore_errors=True)
    current, probe, minimised = work / "current", work / "probe", work / "minimised"
    for d in (current, probe, minimised):
        d.mkdir(parents=True)
    if archive.exists() and not reminimise:
        unpack_seeds(archive, current)
        unpack_seeds(archive, probe)
        added = merged_into(binary, probe, [corpus], work)
        if added is None:
            return None
        if not added:
            # Nothing new: the corpus's coverage is the archive's, one replay of the archive says it.
            cov = coverage(binary, current, work)
            return {"target": target, "archive": shown(archive), "rewritten": False,
                    "inputs": len(read_seeds(archive)), "bytes": archive.stat().st_size, "coverage": cov,
                    "corpus_coverage": cov}
    # prepare_corpus() put every current seed into the corpus: minimising it minimises both.
    if merged_into(binary, minimised, [corpus], work) is None:
        return None
    inputs = {p.read_bytes() for p in minimised.iterdir() if p.is_file()}
    if not inputs:
        log(f"  {target}: the minimised corpus is empty; {shown(archive)} left as it is")
        return None
    write_seeds(archive, inputs)
    entry = {"target": target, "archive": shown(archive), "rewritten": True, "inputs": len(inputs),
             "bytes": archive.stat().st_size}
    entry["coverage"] = coverage(binary, minimised, work)
    entry["corpus_coverage"] = coverage(binary, corpus, work)
    return entry


def export_all(bin_dir, targets, places, reminimise):
    """--export-seeds for every target; returns the exit status."""
    status = 0
    for t in targets:
        log(f"== {t}: minimising {shown(places.corpus / t)} with {shown(seed_archive(places, t))}")
        try:
            entry = export_seeds(bin_dir / t, t, places, reminimise)
        except SeedError as e:
            log(f"fuzz/run.py: {e}")
            entry = None
        if entry is None:
            status = 2
            continue

        def cov(c):
            return f"cov {c[0]} ft {c[1]}" if c else "cov unknown (the replay failed)"
        log(f"  {t}: {'rewrote' if entry['rewritten'] else 'unchanged (the working corpus adds no coverage)'} "
            f"{entry['archive']}: {entry['inputs']} inputs, {entry['bytes']} bytes, {cov(entry['coverage'])}; "
            f"working corpus: {cov(entry['corpus_coverage'])}")
    shutil.rmtree(places.runs / "export", ignore_errors=True)
    return status


def signature(binary, artifact, work):
    """What a failure is, for grouping: the law, the scalar and the words of its account, or the
    sanitizer's summary line. One night can write thousands of artifacts of one bug; each bug is
    minimised and promoted once."""
    r = shielded([str(binary), "-timeout=20", "-rss_limit_mb=2560", str(artifact)], cwd=work,
                 capture_output=True, text=True, errors="replace")
    lines = r.stderr.splitlines()
    head = next((ln for ln in lines if ln.startswith("== collide fuzz target")), None)
    if head:
        # The law, the scalar and the wording of what was expected and got, numbers left out.
        said = [re.sub(r"\(0x[^)]*\)|[-+]?\d[\d.]*(e[-+]?\d+)?", "#", ln.strip()) for ln in lines
                if ln.strip().startswith(("expected:", "got:"))]
        return " | ".join([head.strip()] + [" ".join(x.split()[:8]) for x in said])
    summary = next((ln for ln in lines if "SUMMARY:" in ln), None)
    # An assert inside an uninstrumented library (a judge target's) is only a deadly signal to
    # the sanitizer: its message tells one assert from another.
    assertion = next((re.sub(r"^\S+: ", "", ln.strip()) for ln in lines if "Assertion `" in ln), None)
    if summary:
        return " | ".join(x for x in (assertion, re.sub(r"0x[0-9a-f]+", "", summary.strip())) if x)
    return f"{pathlib.Path(artifact).name.split('-')[0]} (exit {r.returncode})"


def distinct_failures(binary, artifacts, work):
    """[(smallest artifact, how many artifacts share its signature, signature)]."""
    groups = {}
    for art in artifacts:
        groups.setdefault(signature(binary, art, work), []).append(art)
    return [(min(arts, key=lambda a: pathlib.Path(a).stat().st_size), len(arts), sig)
            for sig, arts in groups.items()]


def is_judge_target(target):
    """A target of judge/fuzz: its failures are another library's answers (docs/judge.md)."""
    return target.startswith("judge_")


def to_regression(binary, target, artifact, work, places):
    """Minimises a failure and stores it as a regression case; returns a description. A judge
    target's failure is another library's answer, never collide's regression: it is kept under
    <reports>/judge-fuzz/ instead of tests/regressions/."""
    art = pathlib.Path(artifact)
    kind = art.name.split("-")[0]
    minimized = work / f"min-{art.name}"
    if kind == "crash":
        shielded([str(binary), "-minimize_crash=1", "-runs=3000", "-max_total_time=120",
                  f"-exact_artifact_path={minimized}", str(art)], cwd=work, capture_output=True)
    # libFuzzer's minimiser keeps any failing input, and a shorter input often fails another law:
    # keep the minimised input only when it still fails the same way.
    if minimized.exists() and signature(binary, minimized, work) != signature(binary, art, work):
        minimized.unlink()
    if not minimized.exists():
        shutil.copy(art, minimized)
    regressions = places.reports / "judge-fuzz" if is_judge_target(target) else places.regressions
    regressions.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, COLLIDE_FUZZ_CASE_DIR=str(regressions))
    r = shielded([str(binary), "-timeout=20", "-rss_limit_mb=2560", str(minimized)], cwd=work, env=env,
                 capture_output=True, text=True, errors="replace")
    report = r.stderr
    entry = {"artifact": str(art), "kind": kind, "bytes": minimized.stat().st_size}
    m = CASE_RE.search(report) or RAW_RE.search(report)
    if m:
        path = pathlib.Path(m.group(1))
        entry["case_file"] = shown(path)
        svg = path.with_suffix(".svg")
        if svg.exists():
            entry["svg"] = shown(svg)
    else:
        # A sanitizer report, a timeout or an out-of-memory: keep the raw input and the report.
        data = minimized.read_bytes()
        stem = regressions / f"{target}-{fnv1a(data):08x}"
        stem.with_suffix(".input").write_bytes(data)
        stem.with_suffix(".txt").write_text(f"fuzz target {target} ({kind})\n" + report[-6000:])
        entry["case_file"] = shown(stem.with_suffix(".input"))
    summary = [ln.strip() for ln in report.splitlines()
               if ln.startswith("==") or "SUMMARY" in ln or ln.strip().startswith(("expected:", "got:"))]
    entry["summary"] = " | ".join(summary[:4])[:600]
    return entry


def write_reports(results, build, places, plan):
    reports = places.reports
    reports.mkdir(parents=True, exist_ok=True)
    unfinished = [t for t in plan["targets"] if t not in plan["done"]]
    doc = {"build_dir": str(build), "sanitizers": plan["sanitizers"], "jobs": plan["jobs"], "targets": results,
           "failures": sum(len(r["failures"]) for r in results),
           "interrupted": bool(unfinished), "unfinished_targets": unfinished}
    write_report("fuzz", doc, reports / "fuzz.json")
    flavour = ("executables as given" if plan["fuzzer_dir"] else "ASan + UBSan" if plan["sanitizers"]
               else "no sanitizers")
    lines = ["# Fuzzing report", "",
             f"Build: `{shown(build)}` "
             f"({flavour})"
             f", fork workers per target: {plan['jobs']}.",
             "", "| target | time (s) | executions | exec/s | coverage (edges / features) | corpus | new inputs "
             "| failures |",
             "|---|---:|---:|---:|---|---:|---:|---:|"]
    if unfinished:
        lines[2:2] = [f"**Interrupted**: {', '.join(unfinished)} not finished; `./harness fuzz --resume` "
                      "runs what is left.", ""]
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


def combine(before, part):
    """The result of a target run in parts (interrupted, then resumed)."""
    if before is None:
        return part
    out = dict(part)
    for key in ("seconds", "executions", "new_inputs", "failure_inputs"):
        out[key] = round(before.get(key, 0) + part.get(key, 0), 1)
    out["exec_per_s"] = round(out["executions"] / out["seconds"]) if out["seconds"] > 0 else 0
    # A failure found again after the resume is one failure, promoted once (same case file).
    seen = {f["signature"]: f for f in before["failures"]}
    for f in part["failures"]:
        if f["signature"] in seen:
            seen[f["signature"]] = dict(seen[f["signature"]], inputs=seen[f["signature"]]["inputs"] + f["inputs"])
        else:
            seen[f["signature"]] = f
    out["failures"] = list(seen.values())
    return out


def save_plan(places, plan):
    places.runs.mkdir(parents=True, exist_ok=True)
    tmp = places.state.with_suffix(".tmp")
    tmp.write_text(json.dumps(plan, indent=2) + "\n")
    tmp.replace(places.state)


def export_main(args, places):
    if args.fuzzer_dir:
        bin_dir = pathlib.Path(args.fuzzer_dir).resolve()
        targets = args.target or sorted(p.name for p in bin_dir.iterdir() if os.access(p, os.X_OK))
    else:
        build = choose_build_dir(args.build_dir, args.no_sanitizers)
        bin_dir = build / "fuzz/bin"
        targets = configure_and_build(build, args.target, args.jobs, args.no_sanitizers)
        if targets is None:
            return 2
    return export_all(bin_dir, targets, places, args.reminimise)


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
    ap.add_argument("--no-merge", action="store_true", help="leave the working corpus unchanged")
    ap.add_argument("--export-seeds", action="store_true",
                    help="fuzz nothing: minimise the working corpus with the seeds into fuzz/seeds/*.zip")
    ap.add_argument("--reminimise", action="store_true",
                    help="with --export-seeds: rewrite every archive, also where the corpus adds no coverage")
    ap.add_argument("--resume", action="store_true",
                    help="go on with an interrupted run (its targets, time and options; others are ignored)")
    ap.add_argument("--progress-seconds", type=float, default=60, help="interval of the progress line (default 60)")
    ap.add_argument("--fuzzer-dir", help="use the fuzzer executables <dir>/<target> as they are (no configure/build)")
    ap.add_argument("--corpus-dir", help="working corpus root (default $COLLIDE_CORPUS_DIR, else build/corpus)")
    ap.add_argument("--seeds-dir", help="the seed archives <target>_seed_corpus.zip (default fuzz/seeds)")
    ap.add_argument("--regressions-dir", help="where failures become cases (default tests/regressions)")
    ap.add_argument("--runs-dir", help="scratch and the resumable state (default build/fuzz-runs)")
    ap.add_argument("--reports-dir", help="fuzz.md and fuzz.json (default build/reports)")
    args = ap.parse_args()
    places = Places(args)
    if args.export_seeds and args.resume:
        ap.error("--export-seeds and --resume do not go together")
    if args.reminimise and not args.export_seeds:
        ap.error("--reminimise goes with --export-seeds")
    if args.export_seeds:
        return export_main(args, places)

    if args.resume:
        if not places.state.exists():
            log(f"fuzz/run.py: nothing to resume ({shown(places.state)} does not exist: the last run finished)")
            return 2
        plan = json.loads(places.state.read_text())
        log(f"resuming: {', '.join(t for t in plan['targets'] if t not in plan['done'])} left of "
            f"{', '.join(plan['targets'])}")
    else:
        if places.state.exists():
            log(f"note: the plan of an interrupted run ({shown(places.state)}) is replaced by this run's "
                "(--resume would have continued it)")
        total = (args.hours * 3600 if args.hours else (args.minutes if args.minutes is not None else 10) * 60)
        plan = {"targets": args.target or [], "total_seconds": total, "jobs": args.jobs,
                "sanitizers": not args.no_sanitizers, "merge": not args.no_merge,
                "fuzzer_dir": str(pathlib.Path(args.fuzzer_dir).resolve()) if args.fuzzer_dir else None,
                "build_dir": args.build_dir, "done": {}, "partial": {}}

    if plan["fuzzer_dir"]:
        build = pathlib.Path(plan["fuzzer_dir"])
        bin_dir = build
        targets = plan["targets"] or sorted(p.name for p in bin_dir.iterdir() if os.access(p, os.X_OK))
    else:
        build = choose_build_dir(plan["build_dir"], not plan["sanitizers"])
        bin_dir = build / "fuzz/bin"
        targets = configure_and_build(build, plan["targets"], plan["jobs"], not plan["sanitizers"])
        if targets is None:
            return 2
    # Every working corpus is ready before anything runs: a bad archive stops the run here.
    try:
        for t in targets:
            prepare_corpus(places, t)
    except SeedError as e:
        log(f"fuzz/run.py: {e}")
        return 2
    if not args.resume:
        plan["targets"] = targets
        plan["per_target"] = max(10, int(plan["total_seconds"] / len(targets)))
        save_plan(places, plan)
    per_target, jobs = plan["per_target"], plan["jobs"]

    stop = Stop()
    stop.install()
    spent = sum(r["seconds"] for r in plan["done"].values()) + sum(r["seconds"] for r in plan["partial"].values())
    ticker = Ticker(per_target * len(targets), spent, args.progress_seconds)
    log(f"fuzzing {', '.join(targets)}: {per_target} s each, {jobs} fork workers; "
        f"progress every {args.progress_seconds:g} s; Ctrl-C or SIGTERM stops, merges and reports")
    for i, t in enumerate(targets):
        if t in plan["done"]:
            continue
        if stop.signal is not None:
            break
        binary = bin_dir / t
        work = places.runs / t
        before = plan["partial"].get(t)
        seconds = max(1, int(per_target - (before["seconds"] if before else 0)))
        log(f"== {t} ({i + 1}/{len(targets)}, {seconds} s{', resumed' if before else ''})")
        res = run_target(binary, t, seconds, jobs, work, places, stop, ticker, f"{t} ({i + 1}/{len(targets)})",
                         keep_inputs=before is not None)
        if plan["merge"]:
            res["new_inputs"], res["corpus_after"] = merge(binary, t, work, places)
        artifacts = res.pop("artifacts")
        res["failure_inputs"] = len(artifacts)
        ticker.failures_before += len(artifacts)
        res["failures"] = []
        for art, count, sig in distinct_failures(binary, artifacts, work):
            entry = to_regression(binary, t, art, work, places)
            entry.update({"inputs": count, "signature": sig})
            res["failures"].append(entry)
        res = combine(before, res)
        log(f"  {t}: {res['executions']} executions, {res['exec_per_s']} exec/s, cov {res['coverage_edges']}, "
            f"{res.get('new_inputs', 0)} new inputs, {len(res['failures'])} distinct failures "
            f"({res['failure_inputs']} failing inputs){', interrupted' if res['interrupted'] else ''}")
        for f in res["failures"]:
            log(f"    {f['kind']} x{f['inputs']}: {f.get('case_file')}  {f.get('summary', '')[:200]}")
        if res["interrupted"]:
            plan["partial"][t] = res
        else:
            plan["partial"].pop(t, None)
            plan["done"][t] = res
        save_plan(places, plan)

    results = [plan["done"].get(t) or plan["partial"][t] for t in targets
               if t in plan["done"] or t in plan["partial"]]
    reports = write_reports(results, build, places, plan)
    log(f"reports: {reports / 'fuzz.md'}, {reports / 'fuzz.json'}")
    if stop.signal is not None:
        log(f"interrupted: resume with `./harness fuzz --resume` (plan in {shown(places.state)})")
    else:
        places.state.unlink(missing_ok=True)
    return 1 if any(r["failures"] for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
