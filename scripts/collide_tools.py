"""What the project's Python scripts share: building the programs they run, asking the build what
it knows (kinds, codecs, laws: collide_describe), reading GoogleTest's JSON output, printing
tables, reading the CMake cache, and the one FNV-1a of the Python side (its C++ twin is
oracles/laws/include/collide/laws/hash.hpp).

Scripts outside scripts/ import it after `sys.path.insert(0, str(ROOT / "scripts"))`.
"""

from __future__ import annotations

import json
import os
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def build_dir(path: str | os.PathLike) -> pathlib.Path:
    """A build directory given on a command line: relative paths are taken from the repository."""
    p = pathlib.Path(path)
    return p if p.is_absolute() else ROOT / p


def build_targets(build: pathlib.Path, targets: list[str], jobs: int | str = 2, quiet: bool = False) -> None:
    """Builds the targets (always: ninja does nothing when they are current, and a stale program
    would judge yesterday's code). Exits with status 2 and a message naming the targets when the
    build fails."""
    cmd = ["cmake", "--build", str(build), "-j", str(jobs), "--target", *targets]
    out = subprocess.DEVNULL if quiet else None
    if subprocess.run(cmd, cwd=ROOT, stdout=out).returncode != 0:
        print(f"cannot build {', '.join(targets)} in {build}", file=sys.stderr)
        sys.exit(2)


_DESCRIBED: dict[pathlib.Path, dict] = {}


def describe(build: pathlib.Path) -> dict:
    """The build's own account of kinds (with their codecs) and laws (collide_describe)."""
    if build not in _DESCRIBED:
        build_targets(build, ["collide_describe"], quiet=True)
        exe = build / "oracles" / "laws" / "collide_describe"
        _DESCRIBED[build] = json.loads(subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout)
    return _DESCRIBED[build]


def law_names(build: pathlib.Path) -> list[str]:
    """The law table's names, in table order."""
    return [law["name"] for law in describe(build)["laws"]]


def kind_names(build: pathlib.Path) -> list[str]:
    """The registry's kinds, in ShapeKind order."""
    return [kind["name"] for kind in describe(build)["kinds"]]


def run_gtest(cmd: list[str], **kwargs) -> tuple[subprocess.CompletedProcess, dict]:
    """Runs a GoogleTest program with --gtest_output=json; returns the process and the report
    ({} when the program wrote none: it crashed before the end)."""
    with tempfile.TemporaryDirectory() as tmp:
        report = pathlib.Path(tmp) / "gtest.json"
        proc = subprocess.run([*cmd, f"--gtest_output=json:{report}"], **kwargs)
        data = json.loads(report.read_text()) if report.exists() else {}
    return proc, data


def gtest_failures(report: dict) -> list[str]:
    """The failed tests of a GoogleTest JSON report, as Suite.name, in run order."""
    failed = []
    for suite in report.get("testsuites", []):
        for test in suite.get("testsuite", []):
            if test.get("failures"):
                failed.append(f"{suite['name']}.{test['name']}")
    return failed


def print_table(header: list[str], rows: list[list], right: set[int] | None = None) -> None:
    """Prints rows under a header, each column as wide as its widest cell; columns whose index is
    in `right` are right-aligned (numbers)."""
    right = right or set()
    cells = [[str(c) for c in header]] + [[str(c) for c in row] for row in rows]
    widths = [max(len(r[i]) for r in cells) for i in range(len(header))]
    for r in cells:
        print("  ".join(c.rjust(w) if i in right else c.ljust(w) for i, (c, w) in enumerate(zip(r, widths))).rstrip())


def cache_value(build: pathlib.Path, key: str) -> str | None:
    """A value of the build directory's CMake cache, or None."""
    cache = build / "CMakeCache.txt"
    if not cache.exists():
        return None
    for line in cache.read_text(errors="replace").splitlines():
        if line.startswith(key + ":"):
            return line.split("=", 1)[1]
    return None


def fnv1a(data: bytes) -> int:
    """FNV-1a, 32 bit (names of raw regression inputs and case files)."""
    h = 2166136261
    for b in data:
        h = ((h ^ b) * 16777619) & 0xFFFFFFFF
    return h


# The reports the harness writes and scripts/verdict.py reads: each field a report must carry and
# its type ("list of" rows give the fields of each row). Writers check before writing, readers on
# reading, so both follow this one declaration.
REPORT_SCHEMAS: dict[str, dict] = {
    "properties": {"status": str, "seed": int, "cases": int, "disagreements": int, "failures": int,
                   "counterexamples": list,
                   "properties": ("list of", {"name": str, "law": str, "pair": str, "scalar": str, "cases": int,
                                              "disagreements": int, "status": str,
                                              "reason": str, "case_file": str})},
    "fuzz": {"failures": int, "interrupted": bool,
             "targets": ("list of", {"target": str, "seconds": (int, float), "executions": int,
                                     "exec_per_s": (int, float), "failures": list})},
    "mutation": {"status": str, "mutants": int, "killed_per_layer": dict,
                 "killed_by_properties_or_replays_within_goal": int, "goal_seconds": (int, float),
                 "results": list},
}


class ReportError(Exception):
    """A report that does not follow its schema (REPORT_SCHEMAS)."""


def check_report(name: str, doc: dict, schema: dict | None = None, where: str = "") -> None:
    """Raises ReportError naming the first field of `doc` that is missing or of another type."""
    schema = REPORT_SCHEMAS[name] if schema is None else schema
    where = where or f"{name}.json"
    for key, kind in schema.items():
        if key not in doc:
            raise ReportError(f"{where}: field '{key}' missing")
        if isinstance(kind, tuple) and kind and kind[0] == "list of":
            if not isinstance(doc[key], list):
                raise ReportError(f"{where}: field '{key}' is not a list")
            for i, row in enumerate(doc[key]):
                check_report(name, row, kind[1], f"{where} {key}[{i}]")
        elif not isinstance(doc[key], kind) or (kind is int and isinstance(doc[key], bool)):
            raise ReportError(f"{where}: field '{key}' is not {kind}")


def write_report(name: str, doc: dict, *paths: pathlib.Path) -> None:
    """Checks `doc` against its schema, then writes it as JSON to every path."""
    check_report(name, doc)
    text = json.dumps(doc, indent=1) + "\n"
    for path in paths:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


def read_report(name: str, path: pathlib.Path) -> dict:
    """The report at `path`, checked against its schema (ReportError, OSError or a JSON error)."""
    doc = json.loads(path.read_text())
    check_report(name, doc)
    return doc
