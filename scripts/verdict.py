#!/usr/bin/env python3
"""Prints the one verdict table of `./harness verify`.

Combines the status of the harness's own steps (given as --step NAME=EXIT_STATUS) with the reports
this repository writes, each read and checked against the schema its writer checks it against
before writing (collide_tools.REPORT_SCHEMAS):
- build/reports/properties.json (properties/run.py): one row per law, plus one per failing test;
- build/reports/fuzz.json (fuzz/run.py): one row per target;
- build/reports/mutation.json (scripts/mutate.py), with --mutation: the kill matrix's verdict.
A missing or unreadable report, or one that does not follow its schema, is a failing row (named).
Exit status 1 if any row failed, else 0.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import sys
from typing import Any

import collide_tools

Row = tuple[str, str, str, str]  # section, item, verdict, detail


def properties_rows(doc: dict[str, Any]) -> list[Row]:
    by_law: dict[str, list[dict[str, Any]]] = {}
    for t in doc["properties"]:
        by_law.setdefault(t["law"], []).append(t)
    rows: list[Row] = [("properties", "(overall)", "PASS" if doc["status"] == "pass" else "FAIL",
                        f"seed {doc['seed']}, {doc['cases']} cases, "
                        f"{doc['disagreements']} disagreements allowed (within the tolerance band)")]
    for law, members in by_law.items():
        failing = [t for t in members if t["status"] != "pass"]
        cases = sum(t["cases"] for t in members)
        band = sum(t["disagreements"] for t in members)
        rows.append(("properties", law, "FAIL" if failing else "PASS",
                     f"{len(members) - len(failing)}/{len(members)} tests passed, {cases} cases, "
                     f"{band} allowed (within the tolerance band)"))
        for t in failing:
            detail = ", ".join(x for x in (t["reason"], t["case_file"]) if x)
            rows.append(("properties", "  " + t["name"], "FAIL", detail))
    return rows


def fuzz_rows(doc: dict[str, Any]) -> list[Row]:
    rows: list[Row] = []
    for t in doc["targets"]:
        failures = t["failures"]
        detail = f"{t['seconds']} s, {t['executions']} executions, {t['exec_per_s']} exec/s"
        if failures:
            detail += "; " + "; ".join(str(f.get("case_file", f.get("summary", ""))) for f in failures[:3])
        rows.append(("fuzz", t["target"], "FAIL" if failures else "PASS", detail))
    if not rows:
        raise collide_tools.ReportError("fuzz.json: no targets")
    return rows


def mutation_rows(doc: dict[str, Any]) -> list[Row]:
    n = doc["mutants"]
    met = doc["killed_by_properties_or_replays_within_goal"]
    return [("mutation", "kill matrix", "PASS" if doc["status"] == "pass" else "FAIL",
             f"{met}/{n} killed by properties or replays within {doc['goal_seconds']} s; per layer "
             + ", ".join(f"{k} {v}/{n}" for k, v in doc["killed_per_layer"].items()))]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reports", default="build/reports", help="folder holding the JSON reports")
    parser.add_argument("--step", action="append", default=[], metavar="NAME=STATUS",
                        help="a harness step and its exit status (0 = passed)")
    parser.add_argument("--mutation", action="store_true", help="also judge build/reports/mutation.json")
    args = parser.parse_args()

    rows: list[Row] = []
    for step in args.step:
        name, _, status = step.rpartition("=")
        code = int(status) if status.lstrip("-").isdigit() else 1
        rows.append(("harness", name, "PASS" if code == 0 else "FAIL", "" if code == 0 else f"exit status {code}"))

    reports_dir = pathlib.Path(args.reports)
    for section, reader, required in (("properties", properties_rows, True), ("fuzz", fuzz_rows, True),
                                      ("mutation", mutation_rows, args.mutation)):
        path = reports_dir / f"{section}.json"
        if not required:
            continue
        if not path.is_file():
            rows.append((section, path.name, "MISSING", f"{path} was not written"))
            continue
        try:
            rows.extend(reader(collide_tools.read_report(section, path)))
        except (OSError, json.JSONDecodeError, collide_tools.ReportError) as err:
            rows.append((section, path.name, "FAIL", f"unreadable: {err}"))

    collide_tools.print_table(["section", "item", "verdict", "detail"], [list(r) for r in rows])
    bad = [r for r in rows if r[2] != "PASS"]
    print(f"\n{len(rows) - len(bad)} of {len(rows)} rows passed"
          + ("" if not bad else f"; not passing: {', '.join(r[0] + '/' + r[1].strip() for r in bad)}"))
    return 0 if not bad else 1


if __name__ == "__main__":
    sys.exit(main())
