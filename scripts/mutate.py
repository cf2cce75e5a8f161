#!/usr/bin/env python3
"""The project's mutation score: applies every mutant of scripts/mutants.txt to lib/ and runs each
layer of checks against it on its own.

All mutants are compiled into ONE build: a patched copy of lib/include in build/mutation/src, where
each mutant site becomes `(collide_mutant() == K ? mutated : original)` and collide_mutant() reads
COLLIDE_MUTANT once. The shipped headers are never touched. Mutant 0 (no mutant) is run first: a
check failing there is left out of the matrix (and named), so only what a mutant changes counts.

Layers, each run to its first failure (the time to it is the kill time):
  properties  the property suite at CI depth (200 cases per test, seed 1, no shrinking)
  replays     the regression cases (collide_replay_cases), every fuzz target's seed archive
              (fuzz/seeds, unpacked into build/mutation/seeds) and regression replays, and the
              adversarial boundary cases at ctest's fixed seed (200,000 cases of
              tests/adversarial, replayed identically every run)
  unit        the unit tests

Writes build/reports/mutation.{md,json} (and a timestamped copy of each under
build/reports/mutation-runs/). Exit status 0 only if every mutant is killed by the properties or
the replays within --goal seconds; 2 when the list does not apply (a mutant's original text is
missing or ambiguous), naming each such mutant.

usage: scripts/mutate.py [--build-dir build/mutation] [--only NAME...] [--jobs 2] [--check]
       scripts/mutate.py --planted --out DIR    (the build's planted faults, see below)
       scripts/mutate.py --planted --print-path

The planted faults of scripts/planted_faults.txt use the same format and checks, behind their own
switch: --planted writes the headers they touch, every fault in place, under DIR (DIR/collide/...),
which the build puts before lib/include for the planted-fault test targets; collide_planted(K)
reads the names in COLLIDE_PLANTED (comma-separated), so one planted build serves every planted
test. --print-path prints those headers' paths relative to DIR. --check checks both lists.
"""

from __future__ import annotations

import argparse
import concurrent.futures
import dataclasses
import datetime
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile

import collide_tools

ROOT = collide_tools.ROOT
LIST = ROOT / "scripts" / "mutants.txt"
PLANTED = ROOT / "scripts" / "planted_faults.txt"
LAYERS = ("properties", "replays", "unit")
PROPS_PARAMS = "max_success=200 max_size=100 seed=1 noshrink=1"
TIMEOUT = 120  # seconds per layer and mutant: beyond it the layer counts as hung (killed, flagged)

MUTANT_SWITCH = ("collide/detail/mutant_switch.hpp", "collide_mutant() == {number}")
PLANTED_SWITCH = ("collide/detail/planted_switch.hpp", "collide_planted({number})")

SWITCH_HEADER = """#pragma once
// Written by scripts/mutate.py into the mutation build only: which mutant is active, from the
// environment variable COLLIDE_MUTANT (0 or unset: none), read once.
#include <cstdlib>

inline int collide_mutant() noexcept {
  static const int id = [] {
    const char* s = std::getenv("COLLIDE_MUTANT");
    return s != nullptr ? std::atoi(s) : 0;
  }();
  return id;
}
"""

# The names of the planted faults in list order (fault K is names[K - 1]) fill in @NAMES@.
PLANTED_SWITCH_HEADER = """#pragma once
// Written by scripts/mutate.py into the planted-fault headers of the build tree only: which planted
// faults are active, from the environment variable COLLIDE_PLANTED (names of
// scripts/planted_faults.txt, comma-separated; unset: none), read once. An unknown name stops the
// program, so a misspelt fault cannot pass for one that no check catches.
#include <cstdio>
#include <cstdlib>
#include <cstring>

inline bool collide_planted(int fault) noexcept {
  static const unsigned long long active = [] {
    static const char* const names[] = {@NAMES@};
    unsigned long long bits = 0;
    const char* s = std::getenv("COLLIDE_PLANTED");
    while (s != nullptr && *s != '\\0') {
      const char* comma = std::strchr(s, ',');
      const std::size_t n = comma != nullptr ? static_cast<std::size_t>(comma - s) : std::strlen(s);
      bool known = false;
      for (std::size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
        if (std::strlen(names[k]) == n && std::strncmp(names[k], s, n) == 0) {
          bits |= 1ULL << (k + 1);
          known = true;
        }
      }
      if (!known) {
        std::fprintf(stderr, "COLLIDE_PLANTED: no planted fault named '%.*s'\\n", static_cast<int>(n), s);
        std::abort();
      }
      s = comma != nullptr ? comma + 1 : s + n;
    }
    return bits;
  }();
  return (active >> fault & 1ULL) != 0;
}
"""


class ListError(Exception):
    pass


@dataclasses.dataclass
class Mutant:
    number: int
    name: str
    path: str
    description: str
    original: str
    mutated: str
    occurrence: int | None = None
    raw: bool = False

    def replacement(self, condition: str) -> str:
        if self.raw:
            return self.mutated.replace("@ID@", str(self.number))
        return f"({condition.format(number=self.number)} ? ({self.mutated}) : ({self.original}))"


def parse_list(path: pathlib.Path) -> list[Mutant]:
    mutants: list[Mutant] = []
    header = re.compile(r"^\[([A-Za-z0-9_-]+)\]\s+(\S+)((?:\s+(?:raw|#\d+))*)\s*\|\s*(.+)$")
    current: dict | None = None
    for n, line in enumerate(path.read_text().splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        m = header.match(line)
        if m:
            current = {"name": m.group(1), "path": m.group(2), "flags": m.group(3).split(),
                       "description": m.group(4).strip(), "line": n}
            continue
        if current is None or line[:2] not in ("- ", "+ "):
            raise ListError(f"{path.name}:{n}: expected '[name] path | description', '- original' or '+ mutated'")
        current["original" if line[0] == "-" else "mutated"] = line[2:]
        if "original" in current and "mutated" in current:
            flags = current["flags"]
            occ = next((int(f[1:]) for f in flags if f.startswith("#")), None)
            if any(mu.name == current["name"] for mu in mutants):
                raise ListError(f"{path.name}:{current['line']}: duplicate mutant name {current['name']}")
            mutants.append(Mutant(len(mutants) + 1, current["name"], current["path"], current["description"],
                                  current["original"], current["mutated"], occ, "raw" in flags))
            current = None
    if current is not None:
        raise ListError(f"{path.name}:{current['line']}: mutant {current['name']} lacks its '-' or '+' line")
    return mutants


def patch_sources(mutants: list[Mutant], src: pathlib.Path, switch: tuple[str, str] = MUTANT_SWITCH) -> dict[str, str]:
    """Returns {relative path: patched text}, each site behind switch (its header, its condition);
    raises ListError naming every mutant that does not apply."""
    problems = []
    by_file: dict[str, list[tuple[int, Mutant]]] = {}
    for mu in mutants:
        path = src / mu.path
        if not path.is_file():
            problems.append(f"  [{mu.name}] {mu.path}: file not found")
            continue
        text = path.read_text()
        starts = [m.start() for m in re.finditer(re.escape(mu.original), text)]
        if mu.occurrence is None and len(starts) != 1:
            problems.append(f"  [{mu.name}] {mu.path}: original text found {len(starts)} times (need exactly 1, "
                            f"or give #N): {mu.original!r}")
            continue
        if mu.occurrence is not None and not 1 <= mu.occurrence <= len(starts):
            problems.append(f"  [{mu.name}] {mu.path}: occurrence #{mu.occurrence} of {len(starts)}: {mu.original!r}")
            continue
        by_file.setdefault(mu.path, []).append((starts[(mu.occurrence or 1) - 1], mu))
    patched = {}
    for rel, sites in by_file.items():
        text = (src / rel).read_text()
        sites.sort(key=lambda s: s[0])
        for (a, ma), (b, mb) in zip(sites, sites[1:]):
            if a + len(ma.original) > b:
                problems.append(f"  [{ma.name}] and [{mb.name}] overlap in {rel}")
        for start, mu in reversed(sites):
            text = text[:start] + mu.replacement(switch[1]) + text[start + len(mu.original):]
        if "#pragma once\n" not in text:
            problems.append(f"  {rel}: no '#pragma once' line to put the switch include after")
            continue
        text = text.replace("#pragma once\n", f'#pragma once\n#include "{switch[0]}"\n', 1)
        patched[rel] = text
    if problems:
        listed = "planted_faults.txt" if switch is PLANTED_SWITCH else "mutants.txt"
        raise ListError(f"these mutants do not apply to the current sources (edit scripts/{listed}):\n" +
                        "\n".join(problems))
    return patched


def planted_headers() -> dict[str, str]:
    """Path relative to lib/include -> text, for every header the planted faults touch (each fault
    behind collide_planted(K)) and the planted switch header."""
    faults = parse_list(PLANTED)
    if len(faults) > 63:
        raise ListError(f"{PLANTED.name}: {len(faults)} faults, but the switch holds 63")
    out = {rel.removeprefix("lib/include/"): text for rel, text in patch_sources(faults, ROOT, PLANTED_SWITCH).items()}
    names = ", ".join(f'"{mu.name}"' for mu in faults)
    out[PLANTED_SWITCH[0]] = PLANTED_SWITCH_HEADER.replace("@NAMES@", names)
    return out


def write_if_changed(path: pathlib.Path, text: str) -> None:
    if path.exists() and path.read_text() == text:
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


def prepare_tree(build: pathlib.Path, patched: dict[str, str]) -> pathlib.Path:
    """Copies the source tree (tracked and new files) into build/src, with lib/include patched."""
    src = build / "src"
    files = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"], cwd=ROOT,
                           capture_output=True, text=True, check=True).stdout.splitlines()
    for rel in files:
        if rel.startswith("build/") or not (ROOT / rel).is_file():
            continue
        text_or_bytes = patched.get(rel)
        dest = src / rel
        if text_or_bytes is not None:
            write_if_changed(dest, text_or_bytes)
        elif not dest.exists() or dest.stat().st_mtime < (ROOT / rel).stat().st_mtime or \
                dest.stat().st_size != (ROOT / rel).stat().st_size:
            dest.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / rel, dest)
    write_if_changed(src / "lib/include/collide/detail/mutant_switch.hpp", SWITCH_HEADER)
    return src


def unpack_seeds(build: pathlib.Path, target: str) -> pathlib.Path:
    """The inputs of the target's seed archive, in a fresh build/mutation/seeds/<target>/."""
    archive = ROOT / "fuzz" / "seeds" / f"{target}_seed_corpus.zip"
    out = build / "seeds" / target
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    try:
        with zipfile.ZipFile(archive) as z:
            for info in z.infolist():
                name = pathlib.PurePosixPath(info.filename).name
                if not info.is_dir() and name:
                    (out / name).write_bytes(z.read(info))
    except (OSError, zipfile.BadZipFile) as e:
        raise ListError(f"cannot read the seed archive {archive}: {e}") from e
    return out


def build_tree(build: pathlib.Path, src: pathlib.Path) -> dict[str, list[list[str]]]:
    """Configures and builds the check executables; returns the commands of each layer."""
    out = build / "build"
    env = dict(os.environ, CCACHE_BASEDIR=os.environ.get("CCACHE_BASEDIR", str(ROOT.parent)))
    if not (out / "build.ninja").exists():
        subprocess.run(["cmake", "-S", str(src), "-B", str(out), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                        "-DCMAKE_CXX_COMPILER=g++", "-DCOLLIDE_WERROR=ON", "-DCOLLIDE_BUILD_BENCH=OFF"],
                       check=True, env=env, stdout=subprocess.DEVNULL)
    # Regenerated first: a build.ninja older than the tree's globs lists targets that no longer exist.
    subprocess.run(["ninja", "-C", str(out), "build.ninja"], check=True, env=env, stdout=subprocess.DEVNULL)
    targets = subprocess.run(["ninja", "-C", str(out), "-t", "targets", "all"], capture_output=True, text=True,
                             check=True).stdout
    # Every linked program of the three layers: the property suites (properties/, the planted-fault
    # copy and the picture tool aside), the replays (regression cases, fuzz corpora) and unit tests.
    programs: dict[str, str] = {}
    for line in targets.splitlines():
        path, _, rule = line.partition(": ")
        if "EXECUTABLE_LINKER" not in rule:
            continue
        name = path.rsplit("/", 1)[-1]
        if not re.fullmatch(r"[A-Za-z0-9_-]+", name):  # side outputs of the link step (test lists)
            continue
        if path.startswith("properties/") and "planted" not in name and name != "collide_draw_cases":
            programs[path] = "properties"
        elif name == "collide_replay_cases" or name.startswith("fuzz_replay_") or name == "adversarial_exact_decisions":
            programs[path] = "replays"
        elif path.startswith("tests/unit/"):
            programs[path] = "unit"
    print(f"mutate: building {len(programs)} check programs in {out}", flush=True)
    jobs = os.environ.get("COLLIDE_JOBS", "2")
    if subprocess.run(["ninja", "-C", str(out), f"-j{jobs}", *sorted(programs)], env=env).returncode != 0:
        raise ListError(f"the mutated tree does not build (see the compiler's message above; {out})")
    regressions = str(ROOT / "tests" / "regressions")
    layers: dict[str, list[list[str]]] = {layer: [] for layer in LAYERS}
    for path, layer in sorted(programs.items(), key=lambda kv: (kv[0] != "properties/collide_properties", kv[0])):
        exe = str(out / path)
        name = path.rsplit("/", 1)[-1]
        if layer == "replays" and name.startswith("fuzz_replay_"):
            target = name[len("fuzz_replay_"):]
            layers["replays"].append([exe, str(unpack_seeds(build, target))])
            layers["replays"].append([exe, "--cases-of", regressions])
        elif name == "adversarial_exact_decisions":
            # The boundary cases ctest replays: a fixed seed and the program's default count, so the
            # same cases every run. Run first: they take under a second, the fuzz replays about 20 s.
            layers["replays"].insert(0, [exe, "--seed", "1"])
        elif layer == "replays":
            layers["replays"].insert(0, [exe, regressions])
        else:
            layers[layer].append([exe, "--gtest_fail_fast"])
    return layers


def run_layer(commands: list[list[str]], mutant: int, cases_dir: str) -> dict:
    """Runs the commands in order until one fails; returns killed, seconds, what failed."""
    env = dict(os.environ, COLLIDE_MUTANT=str(mutant), RC_PARAMS=PROPS_PARAMS, COLLIDE_CASES_DIR=cases_dir)
    env.pop("COLLIDE_PROPS_REPORT", None)
    start = time.monotonic()
    for index, cmd in enumerate(commands):
        gtest = "--gtest_fail_fast" in cmd
        try:
            if gtest:
                proc, report = collide_tools.run_gtest(cmd, env=env, capture_output=True, text=True, timeout=TIMEOUT)
            else:
                proc, report = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=TIMEOUT), {}
        except subprocess.TimeoutExpired:
            return {"killed": True, "seconds": round(time.monotonic() - start, 2),
                    "by": f"{pathlib.Path(cmd[0]).name}: no answer within {TIMEOUT} s", "index": index}
        if proc.returncode != 0:
            failed = collide_tools.gtest_failures(report)
            first_fail = re.search(r"^FAIL (\S+)", proc.stdout, re.M)
            what = failed[0] if failed else first_fail.group(1) if first_fail else f"exit status {proc.returncode}"
            return {"killed": True, "seconds": round(time.monotonic() - start, 2),
                    "by": f"{pathlib.Path(cmd[0]).name}: {what}", "failed_tests": failed, "index": index}
    return {"killed": False, "seconds": round(time.monotonic() - start, 2), "by": ""}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", default="build/mutation")
    ap.add_argument("--only", nargs="+", metavar="NAME", help="run only these mutants")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("COLLIDE_JOBS", "2")))
    ap.add_argument("--goal", type=float, default=10.0, help="seconds of checks within which each mutant must die")
    ap.add_argument("--check", action="store_true", help="only check that every mutant applies, then stop")
    ap.add_argument("--planted", action="store_true",
                    help="write the planted faults' headers (with --out) or print their paths (--print-path)")
    ap.add_argument("--out", metavar="DIR", help="with --planted: the include directory to write into")
    ap.add_argument("--print-path", action="store_true", help="with --planted: print the headers' paths in DIR")
    args = ap.parse_args()

    try:
        if args.planted:
            # The path alone does not check the text: the mutation build configures a tree whose
            # headers carry mutant switches, and never builds the planted targets.
            if args.print_path:
                paths = {mu.path.removeprefix("lib/include/") for mu in parse_list(PLANTED)}
                print("\n".join(sorted(paths | {PLANTED_SWITCH[0]})))
            elif args.out:
                for rel, text in planted_headers().items():
                    write_if_changed(pathlib.Path(args.out) / rel, text)
            else:
                raise ListError("--planted needs --out DIR or --print-path")
            return 0
        mutants = parse_list(LIST)
        patched = patch_sources(mutants, ROOT)
        planted = parse_list(PLANTED)
        planted_headers()
    except ListError as e:
        print(f"mutate: {e}", file=sys.stderr)
        return 2
    files = sorted({mu.path for mu in mutants})
    print(f"mutate: {len(mutants)} mutants over {len(files)} files of lib/; {len(planted)} planted faults apply")
    if args.check:
        return 0
    build = pathlib.Path(args.build_dir)
    build = build if build.is_absolute() else ROOT / build
    src = prepare_tree(build, patched)
    try:
        layers = build_tree(build, src)
    except ListError as e:
        print(f"mutate: {e}", file=sys.stderr)
        return 2
    chosen = [mu for mu in mutants if not args.only or mu.name in args.only]

    with tempfile.TemporaryDirectory() as cases:
        # Mutant 0: every check must pass; what fails here is left out (and named) for all mutants.
        excluded: list[str] = []
        baseline = {layer: run_layer(layers[layer], 0, cases) for layer in LAYERS}
        for layer, result in baseline.items():
            if not result["killed"]:
                continue
            cmd = layers[layer][result["index"]]
            if result.get("failed_tests"):
                # Find every failing test (fail-fast stops at the first), then filter them out.
                _, full = collide_tools.run_gtest([cmd[0]], capture_output=True, text=True,
                                                  env=dict(os.environ, COLLIDE_MUTANT="0", RC_PARAMS=PROPS_PARAMS,
                                                           COLLIDE_CASES_DIR=cases))
                bad = sorted(set(collide_tools.gtest_failures(full)))
                excluded += [f"{layer} {pathlib.Path(cmd[0]).name} {t}" for t in bad]
                cmd.append("--gtest_filter=-" + ":".join(bad))
                if run_layer([cmd], 0, cases)["killed"]:
                    print(f"mutate: {cmd[0]} fails without any mutant even without {len(bad)} failing tests",
                          file=sys.stderr)
                    return 2
            else:
                layers[layer].remove(cmd)
                excluded.append(f"{layer} {' '.join(pathlib.Path(x).name for x in cmd)}")
            if run_layer(layers[layer], 0, cases)["killed"]:
                print(f"mutate: layer {layer} still fails without any mutant; fix that first", file=sys.stderr)
                return 2
        for e in excluded:
            print(f"mutate: fails without any mutant, left out: {e}")

        def run_one(mu: Mutant) -> dict:
            row = {"number": mu.number, "name": mu.name, "file": mu.path, "description": mu.description}
            for layer in LAYERS:
                row[layer] = run_layer(layers[layer], mu.number, cases)
            return row

        started = time.monotonic()
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            rows = []
            for row in pool.map(run_one, chosen):
                rows.append(row)
                marks = "  ".join(f"{layer} {'%5.1fs' % row[layer]['seconds'] if row[layer]['killed'] else ' alive'}"
                                  for layer in LAYERS)
                print(f"  {row['number']:3} {row['name']:34} {marks}", flush=True)
        elapsed = time.monotonic() - started

    def killed_in_goal(row: dict) -> bool:
        return any(row[layer]["killed"] and row[layer]["seconds"] <= args.goal for layer in ("properties", "replays"))

    score = {layer: sum(r[layer]["killed"] for r in rows) for layer in LAYERS}
    goal_met = sum(killed_in_goal(r) for r in rows)
    when = datetime.datetime.now()
    report = {"date": when.isoformat(timespec="seconds"), "mutants": len(rows), "files": files,
              "killed_per_layer": score, "killed_by_properties_or_replays_within_goal": goal_met,
              "goal_seconds": args.goal, "status": "pass" if goal_met == len(rows) else "fail",
              "seconds": round(elapsed, 1), "properties_params": PROPS_PARAMS, "left_out_at_baseline": excluded,
              "results": rows}
    md = [f"# Mutation matrix ({when:%Y-%m-%d %H:%M})", "",
          f"{len(rows)} mutants of lib/ (scripts/mutants.txt), one build, each layer run on its own to its first "
          f"failure; time = seconds of checks until the mutant was killed. Properties: RC_PARAMS=\"{PROPS_PARAMS}\".",
          "", "| # | mutant | file | properties | replays | unit |", "|---|---|---|---|---|---|"]
    for r in rows:
        cells = [f"{r[layer]['seconds']:.1f} s ({r[layer]['by'].split(': ', 1)[-1]})" if r[layer]["killed"]
                 else "**alive**" for layer in LAYERS]
        short = r["file"].replace("lib/include/collide/", "")
        md.append(f"| {r['number']} | {r['name']}: {r['description']} | {short} | " + " | ".join(cells) + " |")
    md += ["", f"Killed: properties {score['properties']}/{len(rows)}, replays {score['replays']}/{len(rows)}, "
               f"unit {score['unit']}/{len(rows)}; by properties or replays within {args.goal:g} s: "
               f"{goal_met}/{len(rows)}."]
    if excluded:
        md += ["", "Failing without any mutant, left out of every row: " + "; ".join(excluded) + "."]
    reports = ROOT / "build" / "reports"
    runs = reports / "mutation-runs"
    runs.mkdir(parents=True, exist_ok=True)
    stamp = f"{when:%Y%m%d-%H%M%S}"
    collide_tools.write_report("mutation", report, reports / "mutation.json", runs / f"mutation-{stamp}.json")
    for path in (reports / "mutation.md", runs / f"mutation-{stamp}.md"):
        path.write_text("\n".join(md) + "\n")
    print("\n".join(md[-3:]))
    print(f"report: {reports / 'mutation.md'} (and mutation.json; this run also in {runs})")
    return 0 if goal_met == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
