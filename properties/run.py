#!/usr/bin/env python3
"""Runs the property suite within a budget and reports law x pair x scalar.

usage: properties/run.py [--build-dir D] [--cases N] [--seed S] [--pair P] [--law L] [--minutes M]
                         [--jobs J]

--cases N    RapidCheck cases per (law, pair, scalar) test (RC_PARAMS max_success; max_size stays
             at 100). Without it, --minutes picks N from a short calibration run (default 100).
--seed S     RapidCheck seed (default: chosen here and printed, so a run can be repeated).
--pair P     one pair, e.g. circle_obb (either order), or a kind for the single-shape laws.
--law L      one law of the build's law table (collide_describe --laws).
--minutes M  time budget for the whole run (default 3).

Prints a table (cases, relation distribution, answers within the tolerance band (a measurement:
each law judges them exactly), status) and writes it as JSON to build/reports/properties.json, and
keeps every run as build/reports/properties-runs/properties-<time>-seed<S>.json (+ latest.json). A
counterexample is written by the suite itself as a case file (+ SVG) under tests/regressions/; the
paths are listed here. Exit status 1 if any test failed.
"""

from __future__ import annotations

import argparse
import json
import os
import pathlib
import random
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
import collide_tools  # noqa: E402

RELATIONS = ["separated", "touching", "overlapping", "contained"]


def canonical_pair(p: str, kinds: list[str]) -> str:
    if p in kinds:
        return p
    for i, a in enumerate(kinds):
        for b in kinds[i:]:
            if p in (f"{a}_{b}", f"{b}_{a}"):
                return f"{a}_{b}"
    sys.exit(f"run.py: unknown pair '{p}'")


def gtest_filter(laws: list[str], pair: str | None) -> str:
    name = f"{pair}_*" if pair else "*"
    return ":".join(f"{law}.{name}" for law in laws)


def run_suite(exe: pathlib.Path, laws: list[str], pair: str | None, cases: int, seed: int, jobs: int,
              report: pathlib.Path, cases_dir: pathlib.Path | None = None) -> tuple[int, str, list[str]]:
    """Runs the laws split over `jobs` processes; returns (worst exit status, combined output,
    failed tests from GoogleTest's JSON reports). Counterexamples go to cases_dir (default: the
    suite's own, tests/regressions)."""
    groups = [laws[i::jobs] for i in range(jobs)] if len(laws) >= jobs else [laws]
    env = dict(os.environ)
    env["RC_PARAMS"] = f"max_success={cases} max_size=100 seed={seed}"
    env["COLLIDE_PROPS_REPORT"] = str(report)
    if cases_dir is not None:
        env["COLLIDE_CASES_DIR"] = str(cases_dir)
    procs = []
    with tempfile.TemporaryDirectory() as tmp:
        for n, g in enumerate(g for g in groups if g):
            json_out = pathlib.Path(tmp) / f"gtest-{n}.json"
            procs.append((json_out, subprocess.Popen([str(exe), f"--gtest_filter={gtest_filter(g, pair)}",
                                                      f"--gtest_output=json:{json_out}"], env=env,
                                                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)))
        status, output, failed = 0, [], []
        for json_out, p in procs:
            out, _ = p.communicate()
            output.append(out)
            status = max(status, p.returncode)
            if json_out.exists():
                failed += collide_tools.gtest_failures(json.loads(json_out.read_text()))
    return status, "\n".join(output), failed


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", default="build/ci")
    ap.add_argument("--cases", type=int)
    ap.add_argument("--seed", type=int)
    ap.add_argument("--pair")
    ap.add_argument("--law")
    ap.add_argument("--minutes", type=float, default=3.0)
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    build = collide_tools.build_dir(args.build_dir)
    exe = build / "properties" / "collide_properties"
    collide_tools.build_targets(build, ["collide_properties"], quiet=True)
    described = collide_tools.describe(build)
    # The static suite's laws (collide_properties); the placed and moving suites run in ctest.
    all_laws = [law["name"] for law in described["laws"] if law["suite"] == "static"]
    relation_laws = {law["name"] for law in described["laws"] if law["inputs"] == "pair"}
    if args.law and args.law not in all_laws:
        ap.error(f"--law: unknown law '{args.law}' (the law table: {', '.join(all_laws)})")
    seed = args.seed if args.seed is not None else random.randrange(1, 2**31)
    laws = [args.law] if args.law else all_laws
    pair = canonical_pair(args.pair, collide_tools.kind_names(build)) if args.pair else None

    with tempfile.TemporaryDirectory() as tmp:
        cases = args.cases
        if cases is None:
            # Calibrate: 20 cases per test, then fill ~80% of the budget (at most 2000 per test).
            cal_report = pathlib.Path(tmp) / "calibration.jsonl"
            t0 = time.monotonic()
            # Its counterexamples are not kept: the measured run finds them again and announces them.
            run_suite(exe, laws, pair, 20, seed, args.jobs, cal_report, pathlib.Path(tmp) / "calibration-cases")
            per_case = max(time.monotonic() - t0, 0.05) / 20
            cases = int(max(20, min(2000, 0.8 * args.minutes * 60 / per_case)))
            print(f"calibration: {per_case * 1000:.1f} ms per case-round; {cases} cases per test "
                  f"for a {args.minutes:g} minute budget")
        report = pathlib.Path(tmp) / "report.jsonl"
        t0 = time.monotonic()
        status, output, failed_tests = run_suite(exe, laws, pair, cases, seed, args.jobs, report)
        seconds = time.monotonic() - t0
        records = [json.loads(line) for line in report.read_text().splitlines()] if report.exists() else []

    rows = []
    for r in records:
        name = f"{r['law']}.{r['pair']}_{r['scalar']}"
        dist = {k: r.get(k, 0) for k in RELATIONS}
        failed = r["failed"] or name in failed_tests
        rows.append({"name": name, "law": r["law"], "pair": r["pair"], "scalar": r["scalar"],
                     "cases": r["cases"], "distribution": dist, "disagreements": r["disagreements"],
                     "status": "fail" if failed else "pass",
                     "reason": ("law broken" if r["failed"] else "too few cases of a relation") if failed else "",
                     "case_file": r.get("case_file", "")})
    total = sum(r["cases"] for r in rows)
    table = []
    for r in rows:
        d = r["distribution"]
        n = max(r["cases"], 1)
        pct = [f"{100 * d[k] / n:.0f}%" if r["law"] in relation_laws else "-" for k in RELATIONS]
        table.append([r["law"], r["pair"], r["scalar"], r["cases"], *pct,
                      r["disagreements"], f"{r['status'].upper()} {r['reason']}"])
    print()
    collide_tools.print_table(["law", "pair", "scalar", "cases", "sep", "tch", "ovl", "cnt",
                               "in band, judged exactly", "status"], table,
                              right={3, 4, 5, 6, 7, 8})
    cases_per_second = total / seconds if seconds > 0 else 0.0
    disagreements = sum(r["disagreements"] for r in rows)
    n_failed = sum(r["status"] == "fail" for r in rows) + (1 if status and not rows else 0)
    print(f"\n{len(rows)} tests, {total} cases in {seconds:.1f} s ({cases_per_second:.0f} cases/s), seed {seed}, "
          f"{disagreements} answers within the tolerance band (each judged exactly on the library's own shapes), "
          f"{n_failed} failing")
    saved = [r["case_file"] for r in rows if r["case_file"]]
    for path in saved:
        print(f"counterexample kept: {path}")
    if status and not rows:
        print(output[-4000:])

    reports = ROOT / "build" / "reports"
    runs = reports / "properties-runs"
    runs.mkdir(parents=True, exist_ok=True)
    summary = {"status": "fail" if n_failed or status else "pass", "seed": seed, "cases_per_test": cases,
               "cases": total, "seconds": round(seconds, 2), "cases_per_second": round(cases_per_second, 1),
               "disagreements": disagreements, "failures": n_failed, "counterexamples": saved,
               "rc_params": f"max_success={cases} max_size=100 seed={seed}", "properties": rows}
    # Each run is kept (timestamped); properties.json and properties-runs/latest.json are this one.
    stamp = time.strftime("%Y%m%d-%H%M%S")
    collide_tools.write_report("properties", summary, runs / f"properties-{stamp}-seed{seed}.json",
                               runs / "latest.json", reports / "properties.json")
    print(f"report: {reports / 'properties.json'} (kept as {runs / f'properties-{stamp}-seed{seed}.json'})")
    return 1 if (n_failed or status) else 0


if __name__ == "__main__":
    sys.exit(main())
