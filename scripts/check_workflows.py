#!/usr/bin/env python3
"""ctest fuzz.workflows: the GitHub workflows parse and name only what exists.

For every .github/workflows/*.yml (PyYAML, Debian's python3-yaml):
- it parses, has a name, triggers and jobs; every job has runs-on and steps; every step either
  runs a command or uses an action, remote actions pinned to a ref;
- every repository path it names exists: words of `run:` commands that are paths in the tree
  (`./harness`, `.ci/run`, `fuzz/...`; `build/...` is output the harness makes), `with: path:`,
  local actions, and the literal part of `paths:` filters; a file run as a command is executable;
- every CMake preset it names (`cmake --preset P`, COLLIDE_PRESET, a matrix of presets) is a
  configure preset of CMakePresets.json; cron schedules have five fields;
- ClusterFuzzLite: its actions need .clusterfuzzlite/{Dockerfile, build.sh, project.yaml}; the
  language matches project.yaml; modes and sanitizers are ones ClusterFuzzLite knows; coverage
  runs use a coverage build.
Then what the project promises of its workflows: code-change fuzzing of pull requests with the
address and undefined sanitizers, scheduled batch fuzzing, pruning and coverage, all with a
storage repository; a CI job that runs .ci/run in a debian:12 container, and the sanitizer
presets. The seeds ClusterFuzzLite starts from: every fuzz target has its committed archive
fuzz/seeds/<target>_seed_corpus.zip, and every tree path .clusterfuzzlite/build.sh names exists.
Last, .clusterfuzzlite/Dockerfile's pinned versions meet the minimums configure checks
(oracles/exact/CMakeLists.txt) and its header states those same minimums.
"""
import json
import os
import pathlib
import re
import shlex
import sys

import yaml

ROOT = pathlib.Path(__file__).resolve().parent.parent
WORKFLOWS = ROOT / ".github/workflows"
OUTPUT_ROOTS = ("build/",)  # made by the harness during the run
CFLITE = "google/clusterfuzzlite/actions/"
CFLITE_MODES = {"code-change", "batch", "prune", "coverage"}
CFLITE_SANITIZERS = {"address", "undefined", "memory", "coverage"}


class Problems(list):
    def add(self, where, what):
        self.append(f"{where}: {what}")


def version_tuple(v):
    return tuple(int(x) for x in v.split("."))


def top_level_names():
    return {p.name for p in ROOT.iterdir()}


def repo_words(command):
    """The words of a shell command that name paths in the tree."""
    try:
        words = shlex.split(command, comments=True)
    except ValueError:
        words = command.split()
    tops = top_level_names()
    for w in words:
        if w.startswith("-") or "$" in w or "://" in w or "=" in w or w.startswith("/"):
            continue
        w = w.rstrip(";&|")
        path = w[2:] if w.startswith("./") else w
        if not path:
            continue
        first = path.split("/")[0]
        if w.startswith("./") or ("/" in path and (first in tops or path.startswith(OUTPUT_ROOTS))):
            yield path


def check_path(problems, where, path):
    if path.startswith(OUTPUT_ROOTS):
        return
    if not (ROOT / path).exists():
        problems.add(where, f"names {path}, which does not exist")


def presets():
    doc = json.loads((ROOT / "CMakePresets.json").read_text())
    return {p["name"] for p in doc.get("configurePresets", [])}


def triggers(doc):
    # YAML 1.1 reads the key `on` as the boolean true.
    on = doc.get("on", doc.get(True))
    if isinstance(on, str):
        return {on: None}
    if isinstance(on, list):
        return {k: None for k in on}
    return on or {}


def check_workflow(problems, path, known_presets, project_language, seen):
    where = path.relative_to(ROOT)
    try:
        doc = yaml.safe_load(path.read_text())
    except yaml.YAMLError as e:
        problems.add(where, f"does not parse: {e}")
        return
    if not isinstance(doc, dict):
        problems.add(where, "is not a mapping")
        return
    if not doc.get("name"):
        problems.add(where, "has no name")
    on = triggers(doc)
    if not on:
        problems.add(where, "has no triggers (on:)")
    for sched in (on.get("schedule") or []):
        if len(str(sched.get("cron", "")).split()) != 5:
            problems.add(where, f"cron '{sched.get('cron')}' does not have five fields")
    for event in ("pull_request", "push"):
        spec = on.get(event) or {}
        for pattern in (spec.get("paths") or []) if isinstance(spec, dict) else []:
            literal = re.split(r"[*?\[]", pattern)[0].rstrip("/")
            if literal:
                check_path(problems, f"{where} on.{event}.paths", literal)
    jobs = doc.get("jobs") or {}
    if not jobs:
        problems.add(where, "has no jobs")
    for job_name, job in jobs.items():
        jw = f"{where} job {job_name}"
        if "runs-on" not in job:
            problems.add(jw, "has no runs-on")
        steps = job.get("steps") or []
        if not steps:
            problems.add(jw, "has no steps")
        matrix = ((job.get("strategy") or {}).get("matrix") or {})
        for p in matrix.get("preset", []):
            if p not in known_presets:
                problems.add(jw, f"matrix preset '{p}' is not a configure preset in CMakePresets.json")
        cflite_steps = []
        for i, step in enumerate(steps):
            sw = f"{jw} step {step.get('name', i + 1)}"
            if ("uses" in step) == ("run" in step):
                problems.add(sw, "must either run a command or use an action")
                continue
            env = {**(doc.get("env") or {}), **(job.get("env") or {}), **(step.get("env") or {})}
            preset = str(env.get("COLLIDE_PRESET", ""))
            if preset and "${{" not in preset and preset not in known_presets:
                problems.add(sw, f"COLLIDE_PRESET={preset} is not a configure preset")
            if "${{ matrix.preset }}" in preset and not matrix.get("preset"):
                problems.add(sw, "COLLIDE_PRESET comes from a matrix without presets")
            if "run" in step:
                command = str(step["run"])
                for word in repo_words(command):
                    check_path(problems, sw, word)
                for line in command.splitlines():  # a file run as a command must be executable
                    first = (line.split() or [""])[0]
                    program = ROOT / (first[2:] if first.startswith("./") else first)
                    if "/" in first and program.is_file() and not os.access(program, os.X_OK):
                        problems.add(sw, f"runs {first}, which is not executable")
                for p in re.findall(r"--preset[ =](\S+)", command):
                    if p not in known_presets:
                        problems.add(sw, f"cmake --preset {p}: no such configure preset")
                if ".ci/run" in command:
                    seen["ci_run"].append((job.get("container"), jw))
                if preset:
                    seen["presets"].update(matrix.get("preset", []) if "matrix" in preset else [preset])
                continue
            uses = str(step["uses"])
            if uses.startswith("./"):
                check_path(problems, sw, uses[2:])
            elif "@" not in uses:
                problems.add(sw, f"action {uses} is not pinned to a ref")
            with_ = step.get("with") or {}
            if "path" in with_:
                for p in str(with_["path"]).split():
                    check_path(problems, sw, p.rstrip("/"))
            if uses.startswith(CFLITE):
                cflite_steps.append((sw, uses, with_))
        check_cflite_job(problems, jw, cflite_steps, matrix, project_language, on, seen)


def expand(value, matrix):
    """The values an input takes over the job's matrix."""
    m = re.fullmatch(r"\$\{\{\s*matrix\.(\w+)\s*\}\}", str(value))
    return [str(v) for v in matrix.get(m.group(1), [])] if m else [str(value)]


def check_cflite_job(problems, jw, steps, matrix, project_language, on, seen):
    if not steps:
        return
    for f in ("Dockerfile", "build.sh", "project.yaml"):
        check_path(problems, f"{jw} (ClusterFuzzLite)", f".clusterfuzzlite/{f}")
    build_sanitizers = set()
    for sw, uses, with_ in steps:
        sanitizers = expand(with_.get("sanitizer", "address"), matrix)
        for s in sanitizers:
            if s not in CFLITE_SANITIZERS:
                problems.add(sw, f"sanitizer '{s}' is not one ClusterFuzzLite builds")
        if uses.startswith(CFLITE + "build_fuzzers"):
            build_sanitizers.update(sanitizers)
            lang = with_.get("language", "c++")
            if lang != project_language:
                problems.add(sw, f"language {lang} differs from project.yaml's {project_language}")
        if uses.startswith(CFLITE + "run_fuzzers"):
            mode = str(with_.get("mode", "code-change"))
            if mode not in CFLITE_MODES:
                problems.add(sw, f"mode '{mode}' is not a ClusterFuzzLite mode")
            if set(sanitizers) - build_sanitizers:
                problems.add(sw, f"runs sanitizers {sorted(set(sanitizers) - build_sanitizers)} it did not build")
            if (mode == "coverage") != (sanitizers == ["coverage"]):
                problems.add(sw, "coverage mode and the coverage sanitizer go together")
            if "fuzz-seconds" not in with_:
                problems.add(sw, "no fuzz-seconds")
            storage = "storage-repo" in with_
            seen["modes"].setdefault(mode, []).append({"sanitizers": set(sanitizers), "storage": storage,
                                                       "schedule": "schedule" in on,
                                                       "pull_request": "pull_request" in on})


def check_promises(problems, seen):
    modes = seen["modes"]
    pr = [m for m in modes.get("code-change", []) if m["pull_request"]]
    if not pr or not any({"address", "undefined"} <= m["sanitizers"] for m in pr):
        problems.add("workflows", "no code-change fuzzing of pull requests with the address and undefined sanitizers")
    for mode in ("batch", "prune", "coverage"):
        runs = [m for m in modes.get(mode, []) if m["schedule"]]
        if not runs:
            problems.add("workflows", f"no scheduled ClusterFuzzLite {mode} run")
        elif not all(m["storage"] for m in runs):
            problems.add("workflows", f"a {mode} run keeps no storage repository")
    if not any(container == "debian:12" for container, _ in seen["ci_run"]):
        problems.add("workflows", "no job runs .ci/run in a debian:12 container")
    sanitizer_presets = {p for p in seen["presets"] if p in ("asan", "fuzz", "tsan")}
    if not sanitizer_presets:
        problems.add("workflows", "no job runs a sanitizer preset")


def check_image_pins(problems):
    cmake = (ROOT / "oracles/exact/CMakeLists.txt").read_text()
    docker = (ROOT / ".clusterfuzzlite/Dockerfile").read_text()
    minimums = dict(re.findall(r"set\(COLLIDE_MIN_(\w+)_VERSION ([\d.]+)\)", cmake))
    stated = {k.upper(): v for k, v in re.findall(r"#\s+(CGAL|Eigen|Boost)\s+>=\s+([\d.]+)", docker)}
    pinned = dict(re.findall(r"ARG (\w+)_VERSION=([\d.]+)", docker))
    for dep in ("CGAL", "BOOST", "EIGEN"):
        if dep not in minimums:
            problems.add("oracles/exact/CMakeLists.txt", f"no COLLIDE_MIN_{dep}_VERSION")
            continue
        if stated.get(dep) != minimums[dep]:
            problems.add(".clusterfuzzlite/Dockerfile", f"states {dep} >= {stated.get(dep)}, configure needs "
                                                        f">= {minimums[dep]}")
        if dep in pinned and version_tuple(pinned[dep]) < version_tuple(minimums[dep]):
            problems.add(".clusterfuzzlite/Dockerfile", f"pins {dep} {pinned[dep]} below {minimums[dep]}")
    for dep in ("CGAL", "EIGEN"):  # not Ubuntu 20.04's: the image installs them
        if dep not in pinned:
            problems.add(".clusterfuzzlite/Dockerfile", f"pins no {dep} version (Ubuntu 20.04's is too old)")
    for src in re.findall(r"^COPY (\S+) ", docker, re.M):
        if src != ".":
            check_path(problems, ".clusterfuzzlite/Dockerfile COPY", src)


def fuzz_targets():
    """collide's fuzz targets and the judge's (judge/fuzz): build.sh copies the seeds of both."""
    return sorted(p.stem for d in ("fuzz/targets", "judge/fuzz/targets") for p in (ROOT / d).glob("*.cpp"))


def check_seeds(problems):
    """Seed archives of every target, and the tree paths build.sh reads ($ROOT/...; a ${t} in one
    stands for each target)."""
    for t in fuzz_targets():
        check_path(problems, f"fuzz target {t}", f"fuzz/seeds/{t}_seed_corpus.zip")
    build_sh = (ROOT / ".clusterfuzzlite/build.sh").read_text()
    for path in sorted(set(re.findall(r'\$ROOT/([\w./${}-]+)', build_sh))):
        for t in (fuzz_targets() if "${t}" in path else [None]):
            concrete = path.replace("${t}", t) if t else path
            if "$" not in concrete:
                check_path(problems, ".clusterfuzzlite/build.sh", concrete)


# Faults planted in an otherwise sound workflow: each must be reported.
SOUND = """name: planted
on:
  schedule:
    - cron: '0 1 * * *'
jobs:
  j:
    runs-on: ubuntu-latest
    container: debian:12
    steps:
      - uses: actions/checkout@v4
      - run: .ci/run
"""
PLANTED = {
    "a missing file": SOUND.replace(".ci/run", ".ci/walk"),
    "an unknown preset": SOUND.replace("run: .ci/run", "run: cmake --preset nosuch"),
    "a command that is not executable": SOUND.replace(".ci/run", "fuzz/run.py"),
    "an unpinned action": SOUND.replace("actions/checkout@v4", "actions/checkout"),
    "a four-field cron": SOUND.replace("'0 1 * * *'", "'0 1 * *'"),
    "a step with neither run nor uses": SOUND.replace("      - run: .ci/run", "      - name: nothing"),
    "YAML that does not parse": SOUND.replace("jobs:", "jobs: [", 1),
    "a coverage run of an address build": SOUND.replace(
        "      - run: .ci/run", """      - uses: google/clusterfuzzlite/actions/build_fuzzers@v1
        with: {language: c++}
      - uses: google/clusterfuzzlite/actions/run_fuzzers@v1
        with: {mode: coverage, fuzz-seconds: 60}"""),
}


def check_planted(known, language):
    """Names of the planted faults that went unreported."""
    missed = []
    scratch = ROOT / "build" / "planted-workflow.yml"
    scratch.parent.mkdir(exist_ok=True)
    sound = Problems()
    scratch.write_text(SOUND)
    check_workflow(sound, scratch, known, language, {"modes": {}, "ci_run": [], "presets": set()})
    if sound:
        missed.append(f"the sound workflow is reported: {sound}")
    for fault, text in PLANTED.items():
        found = Problems()
        scratch.write_text(text)
        check_workflow(found, scratch, known, language, {"modes": {}, "ci_run": [], "presets": set()})
        if not found:
            missed.append(fault)
    scratch.unlink()
    return missed


def main():
    problems = Problems()
    files = sorted(WORKFLOWS.glob("*.yml")) + sorted(WORKFLOWS.glob("*.yaml"))
    if not files:
        problems.add(".github/workflows", "no workflows")
    project = yaml.safe_load((ROOT / ".clusterfuzzlite/project.yaml").read_text()) or {}
    seen = {"modes": {}, "ci_run": [], "presets": set()}
    known = presets()
    for f in files:
        check_workflow(problems, f, known, project.get("language"), seen)
    check_promises(problems, seen)
    check_image_pins(problems)
    check_seeds(problems)
    for fault in check_planted(known, project.get("language")):
        problems.add("planted faults", f"{fault} went unreported")
    for p in problems:
        print(f"FAIL {p}")
    print(f"workflows: {len(files)} files ({', '.join(f.name for f in files)}), {len(PLANTED)} planted faults checked, "
          f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
