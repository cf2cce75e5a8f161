#!/usr/bin/env python3
"""Speed of the overlap_oracle fuzz target against its goals (part of `./harness bench`).

  fuzz/speed.py [--build-dir D] [--seconds S] [--repeat R] [--jobs J]

Two input classes, generated deterministically (seed 1) in the format of collide/fuzz/decode.hpp,
2,000 inputs each, float and double, a third each separated, overlapping and exactly touching or
within a few ulps of it:
  round    circle-circle, circle-AABB, AABB-circle, AABB-AABB;
  polygon  convex polygons of 3 to 8 vertices.
Each class is measured two ways:
  engine   libFuzzer, one process, no sanitizers (build/fuzz-nosan), S seconds starting from the
           class's inputs: executions per second from its final statistics. This is everything a
           fuzzing hour pays for: mutation (the custom mutator), coverage bookkeeping, the target.
  target   the replay executable of D (no engine, no instrumentation) over the same inputs R times:
           the target's own cost per input (decode, library both orders, exact oracle).
Goals (issue "Fuzzing"): overlap_oracle >= 500k exec/s on circle/AABB inputs, >= 100k on polygon
pairs, one process, no sanitizers. Writes build/reports/fuzz-speed.json and fuzz-speed.md.

Exit status: 0 when measured (goals met or not: this is a benchmark), 1 when the engine run
found a failure (its input is kept in build/fuzz-speed/), 2 on a build error.
"""
import argparse
import struct
import json
import math
import pathlib
import random
import re
import shutil
import subprocess
import sys
import time

from make_corpus import Codecs
from run import configure_and_build

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
import collide_tools  # noqa: E402
GOALS = {"round": 500_000, "polygon": 100_000}
COUNT = 2000


def f32(v):
    """v rounded to float, so that placements computed here stay exact in float inputs."""
    return struct.unpack("<f", struct.pack("<f", v))[0]


def round_shape(codecs, rng, kind, cx, cy, size, dbl):
    if kind == "circle":
        return codecs.encode("circle", [cx, cy, size], dbl)
    w = size * rng.uniform(0.5, 1.0)
    return codecs.encode("aabb", [cx - size, cy - w, cx + size, cy + w], dbl)


def polygon_shape(codecs, rng, cx, cy, size, dbl):
    n = rng.randint(3, 8)
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    pts = [v for a in angles for v in (cx + size * math.cos(a), cy + size * math.sin(a))]
    return codecs.encode("polygon", pts, dbl)


def placement(rng, reach):
    """Centre distance for a pair whose touching distance is about `reach`."""
    mode = rng.randrange(3)
    if mode == 0:
        return reach * rng.uniform(1.05, 2.0)  # separated
    if mode == 1:
        return reach * rng.uniform(0.2, 0.95)  # overlapping
    return reach  # touching (exactly for circle and box pairs on an axis), else within rounding


def inputs(codecs, cls, rng):
    out = []
    for _ in range(COUNT):
        dbl = rng.random() < 0.5
        cx, cy = (rng.uniform(-100, 100) for _ in range(2))
        s1, s2 = rng.choice([0.5, 1.0, 2.0, 4.0]), rng.choice([0.5, 1.0, 2.0, 4.0])
        d = placement(rng, s1 + s2)
        if cls == "round":
            a, b = rng.choice(["circle", "aabb"]), rng.choice(["circle", "aabb"])
            cx, cy = f32(cx), f32(cy)
            if a == b == "circle" and rng.random() < 0.5:
                ang = rng.uniform(0, 2 * math.pi)
                dx, dy = d * math.cos(ang), d * math.sin(ang)
            else:
                dx, dy = d, 0.0
            data = round_shape(codecs, rng, a, cx, cy, s1, dbl) + round_shape(codecs, rng, b, cx + dx, cy + dy, s2, dbl)
        else:
            ang = rng.uniform(0, 2 * math.pi)
            data = (polygon_shape(codecs, rng, cx, cy, s1, dbl) +
                    polygon_shape(codecs, rng, cx + d * math.cos(ang), cy + d * math.sin(ang), s2, dbl))
        out.append(bytes([int(dbl)]) + data)
    return out


def engine_rate(binary, corpus, seconds, work):
    scratch = work / "engine"
    shutil.rmtree(scratch, ignore_errors=True)
    shutil.copytree(corpus, scratch)
    start = time.time()
    r = subprocess.run([str(binary), f"-max_total_time={seconds}", "-seed=1", "-print_final_stats=1",
                        "-max_len=4096", str(scratch)], capture_output=True, text=True, errors="replace", cwd=work)
    wall = time.time() - start
    m = re.search(r"stat::number_of_executed_units: (\d+)", r.stderr)
    if r.returncode != 0 or not m:
        # A failure found while measuring is a finding: keep the input and say how to promote it.
        print(r.stderr[-3000:])
        for art in sorted(work.glob("crash-*")) + sorted(work.glob("timeout-*")):
            print(f"failure input kept: {art}\n  promote it: COLLIDE_FUZZ_CASE_DIR=tests/regressions "
                  f"build/ci/fuzz/fuzz_replay_overlap_oracle {art}")
        return None
    runs = int(m.group(1))
    return {"executions": runs, "seconds": round(wall, 1), "exec_per_s": round(runs / wall)}


def target_rate(binary, corpus, repeat):
    r = subprocess.run([str(binary), "--repeat", str(repeat), str(corpus)], capture_output=True, text=True)
    m = re.search(r"([\d.]+) inputs/s", r.stdout)
    if r.returncode != 0 or not m:
        print(r.stdout[-2000:], r.stderr[-2000:])
        return None
    return round(float(m.group(1)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--build-dir", default="build/ci", help="build with the replay executables (default build/ci)")
    ap.add_argument("--seconds", type=int, default=30, help="engine run per class (default 30)")
    ap.add_argument("--repeat", type=int, default=50, help="replays of each class's inputs (default 50)")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    build = collide_tools.build_dir(args.build_dir)
    codecs = Codecs(collide_tools.describe(build))
    collide_tools.build_targets(build, ["fuzz_replay_overlap_oracle"], args.jobs)
    nosan = ROOT / "build/fuzz-nosan"
    if configure_and_build(nosan, ["overlap_oracle"], args.jobs, True) is None:
        return 2

    work = ROOT / "build/fuzz-speed"
    results = []
    for cls in ("round", "polygon"):
        corpus = work / cls
        shutil.rmtree(corpus, ignore_errors=True)
        corpus.mkdir(parents=True)
        for i, data in enumerate(inputs(codecs, cls, random.Random(f"{cls}-1"))):
            (corpus / f"{i:04d}.bin").write_bytes(data)
        target = target_rate(build / "fuzz/fuzz_replay_overlap_oracle", corpus, args.repeat)
        if target is None:
            return 1
        engine = engine_rate(nosan / "fuzz/bin/overlap_oracle", corpus, args.seconds, work)
        if engine is None:
            return 1
        res = {"class": cls, "goal_exec_per_s": GOALS[cls], "target_inputs_per_s": target, "engine": engine}
        results.append(res)
        print(f"overlap_oracle {cls}: target alone {target:,} inputs/s; libFuzzer {engine['exec_per_s']:,} exec/s "
              f"({engine['executions']:,} in {engine['seconds']} s); goal {GOALS[cls]:,} exec/s", flush=True)

    reports = ROOT / "build/reports"
    reports.mkdir(parents=True, exist_ok=True)
    doc = {"target": "overlap_oracle", "classes": results}
    (reports / "fuzz-speed.json").write_text(json.dumps(doc, indent=2) + "\n")
    lines = ["# overlap_oracle speed", "",
             "| inputs | target alone (inputs/s) | libFuzzer, no sanitizers (exec/s) | goal (exec/s) | target / goal "
             "| libFuzzer / goal |",
             "|---|---:|---:|---:|---:|---:|"]
    for r in results:
        g = r["goal_exec_per_s"]
        lines.append(f"| {r['class']} | {r['target_inputs_per_s']:,} | {r['engine']['exec_per_s']:,} | {g:,} | "
                     f"{r['target_inputs_per_s'] / g:.2f} | {r['engine']['exec_per_s'] / g:.3f} |")
    (reports / "fuzz-speed.md").write_text("\n".join(lines) + "\n")
    print(f"reports: {reports / 'fuzz-speed.md'}, {reports / 'fuzz-speed.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
