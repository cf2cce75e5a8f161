#!/usr/bin/env python3
"""Prints the one verdict table of `./harness verify`.

Combines the status of the harness's own steps (given as --step NAME=EXIT_STATUS) with the
records of build/reports/properties.json and build/reports/fuzz.json. Exits 1 if any step or
record failed or a report is missing or unreadable, else 0.

The reports are read tolerantly, since their writers own their exact layout:
- the records are the top-level list, or the first list found under one of RECORD_KEYS, or a
  mapping name -> record under one of those keys (or at the top level);
- a record's name is its first present NAME_KEYS field; its verdict is a STATUS_KEYS string, else
  a boolean under BOOL_KEYS, else a failure count under FAILURE_KEYS;
- a few well-known figures (DETAIL_KEYS) are shown when present.
A top-level status field, if present, must also be passing.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import sys
from typing import Any

RECORD_KEYS = ("properties", "laws", "targets", "fuzzers", "results", "records", "tests", "entries", "items")
NAME_KEYS = ("name", "property", "law", "target", "fuzzer", "id", "test")
STATUS_KEYS = ("status", "verdict", "result", "outcome")
BOOL_KEYS = ("passed", "ok", "success", "pass")
FAILURE_KEYS = ("failures", "failed", "crashes", "mismatches", "counterexamples")
DETAIL_KEYS = (
    ("cases", "cases"), ("tests", "cases"), ("runs", "runs"), ("execs", "execs"),
    ("executions", "execs"), ("exec_per_sec", "exec/s"), ("execs_per_sec", "exec/s"),
    ("exec_per_s", "exec/s"), ("corpus_after", "corpus"), ("corpus_size", "corpus"),
    ("coverage", "cov"), ("coverage_edges", "edges"), ("seconds", "s"),
    ("corpus", "corpus"), ("time_s", "s"), ("duration_s", "s"), ("seed", "seed"), ("disagreements", "disagreements"),
    ("message", ""), ("reason", ""),
)
GROUP_KEYS = ("law", "group", "family")
GROUP_ABOVE = 30  # records beyond which a grouped report is summarised per group
PASS_WORDS = {"pass", "passed", "ok", "success", "succeeded", "green", "clean"}
FAIL_WORDS = {"fail", "failed", "failure", "error", "crash", "crashed", "mismatch", "timeout", "red"}


def verdict_of(record: dict[str, Any]) -> str:
    """PASS, FAIL or ? for one record (or a whole report's top level)."""
    for key in STATUS_KEYS:
        value = record.get(key)
        if isinstance(value, str):
            word = value.strip().lower()
            if word in PASS_WORDS:
                return "PASS"
            if word in FAIL_WORDS:
                return "FAIL"
            return value.upper()[:12]
        if isinstance(value, bool):
            return "PASS" if value else "FAIL"
    for key in BOOL_KEYS:
        if isinstance(record.get(key), bool):
            return "PASS" if record[key] else "FAIL"
    for key in FAILURE_KEYS:
        value = record.get(key)
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return "PASS" if value == 0 else "FAIL"
        if isinstance(value, list):
            return "PASS" if not value else "FAIL"
    return "?"


def detail_of(record: dict[str, Any]) -> str:
    parts = []
    used = set()
    for key, label in DETAIL_KEYS:
        value = record.get(key)
        if value is None or isinstance(value, (dict, list)) or (label and label in used):
            continue
        used.add(label)
        if isinstance(value, float):
            value = f"{value:.0f}" if abs(value) >= 1000 else f"{value:.3g}"
        parts.append(f"{label} {value}".strip() if label else str(value))
    for key in FAILURE_KEYS:
        value = record.get(key)
        if isinstance(value, (int, float)) and not isinstance(value, bool) and value:
            parts.append(f"{key} {value}")
        elif isinstance(value, list) and value:
            parts.append(f"{key} {len(value)}")
    return ", ".join(parts)


def records_of(report: Any) -> list[tuple[str, dict[str, Any]]]:
    def from_container(container: Any) -> list[tuple[str, dict[str, Any]]] | None:
        if isinstance(container, list):
            out = []
            for i, item in enumerate(container):
                if isinstance(item, dict):
                    name = next((str(item[k]) for k in NAME_KEYS if k in item), f"#{i}")
                    out.append((name, item))
            return out
        if isinstance(container, dict) and container and all(isinstance(v, dict) for v in container.values()):
            return [(str(k), v) for k, v in container.items()]
        return None

    if isinstance(report, dict):
        for key in RECORD_KEYS:
            if key in report:
                found = from_container(report[key])
                if found is not None:
                    return found
    found = from_container(report)
    return found or []


def summarise(section: str, records: list[tuple[str, dict[str, Any]]]) -> list[tuple[str, str, str, str]]:
    """One row per record; long reports whose records carry a group (e.g. the law of a
    law x pair x scalar test) get one row per group, plus one row per record that did not pass."""
    if len(records) <= GROUP_ABOVE or not all(any(k in r for k in GROUP_KEYS) for _, r in records):
        return [(section, name, verdict_of(r), detail_of(r)) for name, r in records]
    groups: dict[str, list[tuple[str, dict[str, Any]]]] = {}
    for name, r in records:
        groups.setdefault(str(next(r[k] for k in GROUP_KEYS if k in r)), []).append((name, r))
    rows = []
    for group, members in groups.items():
        verdicts = [verdict_of(r) for _, r in members]
        passed = verdicts.count("PASS")
        cases = sum(r.get("cases", 0) for _, r in members if isinstance(r.get("cases"), int))
        detail = f"{passed}/{len(members)} tests passed" + (f", {cases} cases" if cases else "")
        rows.append((section, group, "PASS" if passed == len(members) else "FAIL", detail))
        rows.extend((section, "  " + name, v, detail_of(r))
                    for (name, r), v in zip(members, verdicts) if v != "PASS")
    return rows


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reports", default="build/reports", help="folder holding the JSON reports")
    parser.add_argument("--step", action="append", default=[], metavar="NAME=STATUS",
                        help="a harness step and its exit status (0 = passed)")
    args = parser.parse_args()

    rows: list[tuple[str, str, str, str]] = []  # (section, item, verdict, detail)
    for step in args.step:
        name, _, status = step.rpartition("=")
        code = int(status) if status.lstrip("-").isdigit() else 1
        if code == 0:
            rows.append(("harness", name, "PASS", ""))
        elif code == 2 and not name.startswith("build"):
            rows.append(("harness", name, "FAIL", "script missing or refused its arguments (exit 2)"))
        else:
            rows.append(("harness", name, "FAIL", f"exit status {code}"))

    reports_dir = pathlib.Path(args.reports)
    for section, file_name in (("properties", "properties.json"), ("fuzz", "fuzz.json")):
        path = reports_dir / file_name
        if not path.is_file():
            rows.append((section, file_name, "MISSING", f"{path} was not written"))
            continue
        try:
            report = json.loads(path.read_text())
        except (OSError, json.JSONDecodeError) as err:
            rows.append((section, file_name, "FAIL", f"unreadable: {err}"))
            continue
        if isinstance(report, dict):
            overall = verdict_of(report)
            if overall != "?":
                rows.append((section, "(overall)", overall, detail_of(report)))
        records = records_of(report)
        if not records:
            rows.append((section, file_name, "FAIL", "no records found in the report"))
        rows.extend(summarise(section, records))

    headers = ("section", "item", "verdict", "detail")
    widths = [max(len(headers[i]), *(len(r[i]) for r in rows)) for i in range(3)]
    line = f"{headers[0]:<{widths[0]}}  {headers[1]:<{widths[1]}}  {headers[2]:<{widths[2]}}  {headers[3]}"
    print(line)
    print("-" * min(len(line) + 20, 120))
    for section, item, verdict, detail in rows:
        print(f"{section:<{widths[0]}}  {item:<{widths[1]}}  {verdict:<{widths[2]}}  {detail}")

    bad = [r for r in rows if r[2] != "PASS"]
    passed = len(rows) - len(bad)
    print(f"\n{passed} of {len(rows)} rows passed" + ("" if not bad else f"; not passing: {', '.join(r[0] + '/' + r[1].strip() for r in bad)}"))
    return 0 if not bad else 1


if __name__ == "__main__":
    sys.exit(main())
