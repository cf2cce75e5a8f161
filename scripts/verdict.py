#!/usr/bin/env python3
"""Prints the one verdict table of `./harness verify`.

Combines the status of the harness's own steps (given as --step NAME=EXIT_STATUS) with the reports
this repository writes, read by their schema:
- build/reports/properties.json (properties/run.py): {"status", "seed", "cases", "disagreements",
  "failures", "counterexamples": [path], "properties": [{"name", "law", "pair", "scalar", "cases",
  "disagreements", "disagreement_ceiling", "status": "pass"|"fail", "reason", "case_file"}]};
  one row per law, plus one per failing test;
- build/reports/fuzz.json (fuzz/run.py): {"failures", "targets": [{"target", "seconds",
  "executions", "exec_per_s", "failures": [{"case_file", "summary", ...}], ...}]}; one row per target;
- build/reports/mutation.json (scripts/mutate.py), with --mutation: {"status", "mutants",
  "killed_per_layer", "killed_by_properties_or_replays_within_goal", "results": [...]}.
A missing or unreadable report, or one that lacks these fields, is a failing row (named).
Exit status 1 if any row failed, else 0.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import sys
from typing import Any

Row = tuple[str, str, str, str]  # section, item, verdict, detail


class SchemaError(Exception):
    pass


def field(record: dict[str, Any], key: str, kind: type | tuple[type, ...], where: str) -> Any:
    if key not in record or not isinstance(record[key], kind):
        raise SchemaError(f"{where}: field '{key}' missing or not {kind}")
    return record[key]


def properties_rows(doc: dict[str, Any]) -> list[Row]:
    tests = field(doc, "properties", list, "properties.json")
    by_law: dict[str, list[dict[str, Any]]] = {}
    for t in tests:
        by_law.setdefault(field(t, "law", str, "properties.json test"), []).append(t)
    rows: list[Row] = [("properties", "(overall)", "PASS" if field(doc, "status", str, "properties.json") == "pass"
                        else "FAIL", f"seed {doc.get('seed')}, {doc.get('cases')} cases, "
                        f"{doc.get('disagreements')} disagreements allowed (within the tolerance band)")]
    for law, members in by_law.items():
        failing = [t for t in members if field(t, "status", str, f"properties.json {law}") != "pass"]
        cases = sum(field(t, "cases", int, f"properties.json {law}") for t in members)
        band = sum(t.get("disagreements", 0) for t in members)
        rows.append(("properties", law, "FAIL" if failing else "PASS",
                     f"{len(members) - len(failing)}/{len(members)} tests passed, {cases} cases, "
                     f"{band} allowed (within the tolerance band)"))
        for t in failing:
            rows.append(("properties", "  " + t.get("name", "?"), "FAIL",
                         ", ".join(x for x in (t.get("reason", ""), t.get("case_file", "")) if x)))
    return rows


def fuzz_rows(doc: dict[str, Any]) -> list[Row]:
    rows: list[Row] = []
    for t in field(doc, "targets", list, "fuzz.json"):
        failures = field(t, "failures", list, "fuzz.json target")
        detail = f"{t.get('seconds', '?')} s, {t.get('executions', '?')} executions, {t.get('exec_per_s', '?')} exec/s"
        if failures:
            detail += "; " + "; ".join(str(f.get("case_file", f.get("summary", ""))) for f in failures[:3])
        rows.append(("fuzz", field(t, "target", str, "fuzz.json target"), "FAIL" if failures else "PASS", detail))
    if not rows:
        raise SchemaError("fuzz.json: no targets")
    return rows


def mutation_rows(doc: dict[str, Any]) -> list[Row]:
    n = field(doc, "mutants", int, "mutation.json")
    met = field(doc, "killed_by_properties_or_replays_within_goal", int, "mutation.json")
    per = field(doc, "killed_per_layer", dict, "mutation.json")
    return [("mutation", "kill matrix", "PASS" if field(doc, "status", str, "mutation.json") == "pass" else "FAIL",
             f"{met}/{n} killed by properties or replays within {doc.get('goal_seconds')} s; per layer "
             + ", ".join(f"{k} {v}/{n}" for k, v in per.items()))]


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
    for section, file_name, reader, required in (("properties", "properties.json", properties_rows, True),
                                                 ("fuzz", "fuzz.json", fuzz_rows, True),
                                                 ("mutation", "mutation.json", mutation_rows, args.mutation)):
        path = reports_dir / file_name
        if not required:
            continue
        if not path.is_file():
            rows.append((section, file_name, "MISSING", f"{path} was not written"))
            continue
        try:
            rows.extend(reader(json.loads(path.read_text())))
        except (OSError, json.JSONDecodeError, SchemaError) as err:
            rows.append((section, file_name, "FAIL", f"unreadable: {err}"))

    headers = ("section", "item", "verdict", "detail")
    widths = [max(len(headers[i]), *(len(r[i]) for r in rows)) for i in range(3)]
    line = f"{headers[0]:<{widths[0]}}  {headers[1]:<{widths[1]}}  {headers[2]:<{widths[2]}}  {headers[3]}"
    print(line)
    print("-" * min(len(line) + 20, 120))
    for section, item, verdict, detail in rows:
        print(f"{section:<{widths[0]}}  {item:<{widths[1]}}  {verdict:<{widths[2]}}  {detail}")
    bad = [r for r in rows if r[2] != "PASS"]
    print(f"\n{len(rows) - len(bad)} of {len(rows)} rows passed"
          + ("" if not bad else f"; not passing: {', '.join(r[0] + '/' + r[1].strip() for r in bad)}"))
    return 0 if not bad else 1


if __name__ == "__main__":
    sys.exit(main())
