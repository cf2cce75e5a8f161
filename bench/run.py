#!/usr/bin/env python3
"""Builds collide_bench (Release), runs it with repetitions, prints the collide/Box2D ratio table
and writes build/reports/bench.json. Every ratio comes from one run of one binary.

Usage: bench/run.py [--build-dir D] [--repetitions R] [--min-time S] [--filter REGEX] [--scale]
Figures are medians over the repetitions of CPU time per pair (or per box); on a shared 2-core
machine they are noisy (+-20% or worse while others compile).
"""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import collide_tools  # noqa: E402


def build(build_dir):
    if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        # build/ci -> preset ci (Release, -Werror); anything else -> preset default (Release).
        preset = "ci" if os.path.basename(build_dir.rstrip("/")) == "ci" else "default"
        subprocess.run(["cmake", "--preset", preset, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                        "-DCOLLIDE_BUILD_BENCH=ON"], cwd=ROOT, check=True)
    collide_tools.build_targets(build_dir, ["collide_bench"])
    for cand in (os.path.join(build_dir, "bench", "collide_bench"), os.path.join(build_dir, "collide_bench")):
        if os.path.exists(cand):
            return cand
    sys.exit("collide_bench not found under " + build_dir)


def run(exe, repetitions, min_time, flt, raw_path):
    cmd = [exe, "--benchmark_format=json", "--benchmark_out=" + raw_path, "--benchmark_out_format=json",
           "--benchmark_min_time=%g" % min_time, "--benchmark_repetitions=%d" % repetitions]
    if repetitions > 1:
        cmd.append("--benchmark_report_aggregates_only=true")
    if flt:
        cmd.append("--benchmark_filter=" + flt)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    sys.stderr.write(proc.stderr)
    checks = [ln for ln in proc.stderr.splitlines() + proc.stdout.splitlines() if ln.startswith("check ")]
    if proc.returncode != 0:
        sys.stdout.write(proc.stdout[:4000])
        sys.exit("collide_bench failed (exit %d): cross-check or run error; no figures written" % proc.returncode)
    with open(raw_path) as f:
        return json.load(f), checks


def chosen_runs(raw, repetitions):
    """(name, result) of each benchmark: its median aggregate, or its single run."""
    for b in raw["benchmarks"]:
        if repetitions > 1 and b.get("aggregate_name") != "median":
            continue
        if repetitions <= 1 and b.get("run_type") == "aggregate":
            continue
        yield b.get("run_name", b["name"]), b


def medians(raw, repetitions):
    """name -> ns per unit (per pair or per box), from the median aggregate (or the single run)."""
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
    out = {}
    for name, b in chosen_runs(raw, repetitions):
        per = b.get("pairs") or b.get("boxes") or 1.0
        out[name] = b["cpu_time"] * scale[b.get("time_unit", "ns")] / per
    return out


def counters(raw, repetitions):
    """The game loop's per-frame counters (*_ms) of each run, "game_loop/IMPL/N" -> {counter: ms},
    from the median aggregate (or the single run)."""
    return {"/".join(name.split("/")[:3]): {k: v for k, v in b.items() if k.endswith("_ms")}
            for name, b in chosen_runs(raw, repetitions) if name.startswith("game_loop/")}


def ratio(a, b):
    return round(a / b, 3) if a is not None and b else None


# The game loop's phases as its counters name them, and the goals on collide / Box2D per frame.
LOOP_PHASES = ("transforms", "update", "broadphase", "narrowphase", "frame")
LOOP_GOALS = (("narrowphase", "narrowphase <= Box2D's", 1.0), ("transforms", "shape update <= Box2D's", 1.0),
              ("update", "boxes moved (the World's move()) <= Box2D's", 1.0),
              ("frame", "whole frame <= 0.5x Box2D's", 0.5))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", default=os.path.join(ROOT, "build", "bench"))
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--min-time", type=float, default=0.05, help="seconds per repetition per benchmark")
    ap.add_argument("--filter", default="", help="benchmark name regex (default: all)")
    ap.add_argument("--scale", action="store_true",
                    help="only the broadphase scale and bad-load program (1M boxes; 10k all overlapping)")
    args = ap.parse_args()
    if args.scale:
        collide_tools.build_targets(os.path.abspath(args.build_dir), ["collide_broadphase_scale"])
        exe = os.path.join(os.path.abspath(args.build_dir), "bench", "collide_broadphase_scale")
        sys.exit(subprocess.run([exe]).returncode)
    build_dir = os.path.abspath(args.build_dir)
    exe = build(build_dir)
    reports = os.path.join(ROOT, "build", "reports")
    os.makedirs(reports, exist_ok=True)
    raw, checks = run(exe, args.repetitions, args.min_time, args.filter, os.path.join(reports, "bench_raw.json"))
    m = medians(raw, args.repetitions)
    loop_counters = counters(raw, args.repetitions)

    pairs, broad = [], []
    for name in sorted(m):
        parts = name.split("/")
        if parts[0] == "overlap" and parts[3] == "collide":
            pair, placement = parts[1], parts[2]

            def get(impl, kind="overlap"):
                return m.get("%s/%s/%s/%s" % (kind, pair, placement, impl))
            row = {"pair": pair, "set": placement, "collide_ns": get("collide"),
                   "box2d_test_overlap_ns": get("box2d_test_overlap"), "box2d_manifold_ns": get("box2d_manifold"),
                   "naive_ns": get("naive"), "collide_contact_ns": get("collide", "contact")}
            # Box2D's manifold function is timed twice on these pairs, for the overlap table and
            # for the contacts (the same calls, the manifold kept whole); the contacts are measured
            # against the faster, so that a slow moment of the machine during one cannot meet a goal.
            b2_manifold = [t for t in (get("box2d_manifold", "contact"), row["box2d_manifold_ns"]) if t is not None]
            row["box2d_manifold_contact_ns"] = min(b2_manifold) if b2_manifold else None
            row["ratio_vs_test_overlap"] = ratio(row["collide_ns"], row["box2d_test_overlap_ns"])
            row["ratio_vs_manifold"] = ratio(row["collide_ns"], row["box2d_manifold_ns"])
            row["ratio_vs_naive"] = ratio(row["collide_ns"], row["naive_ns"])
            row["contact_ratio_vs_manifold"] = ratio(row["collide_contact_ns"], row["box2d_manifold_contact_ns"])
            # The floor of a world-space contact (the same fields, no exact decision), where one is written.
            row["naive_contact_ns"] = get("naive", "contact")
            row["naive_contact_ratio_vs_manifold"] = ratio(row["naive_contact_ns"], row["box2d_manifold_contact_ns"])
            pairs.append(row)
    # Distances: closest_points() and distance() against b2Distance of the same pair (distance,
    # pointA, pointB); signed_distance() and contains() of points against b2Distance from a
    # one-vertex proxy and b2Shape::TestPoint.
    distances = []
    for name in sorted(m):
        parts = name.split("/")
        if parts[0] == "distance" and parts[3] == "closest_points":
            key = "distance/%s/%s/" % (parts[1], parts[2])
            row = {"pair": parts[1], "set": parts[2], "closest_points_ns": m[name],
                   "distance_ns": m.get(key + "distance"), "box2d_distance_ns": m.get(key + "box2d_distance")}
            row["closest_points_ratio"] = ratio(row["closest_points_ns"], row["box2d_distance_ns"])
            row["distance_ratio"] = ratio(row["distance_ns"], row["box2d_distance_ns"])
            distances.append(row)
    points = []
    for name in sorted(m):
        parts = name.split("/")
        if parts[0] == "point" and parts[3] == "signed_distance":
            key = "point/%s/%s/" % (parts[1], parts[2])
            row = {"kind": parts[1], "set": parts[2], "signed_distance_ns": m[name],
                   "contains_ns": m.get(key + "contains"), "box2d_distance_ns": m.get(key + "box2d_distance"),
                   "box2d_test_point_ns": m.get(key + "box2d_test_point")}
            row["signed_distance_ratio"] = ratio(row["signed_distance_ns"], row["box2d_distance_ns"])
            row["contains_ratio"] = ratio(row["contains_ns"], row["box2d_test_point_ns"])
            points.append(row)
    # Chains: contact(segment, shape) against Box2D's one-sided edge with ghost vertices and its
    # world manifold, per pair of the same terrain.
    chains = []
    for name in sorted(m):
        parts = name.split("/")
        if parts[0] == "chain" and parts[2] == "collide":
            b2 = m.get("chain/%s/box2d" % parts[1])
            chains.append({"kind": parts[1], "collide_ns": m[name], "box2d_ns": b2, "ratio": ratio(m[name], b2)})
    sizes = sorted({int(n.split("/")[3]) for n in m if n.startswith("broadphase/")})
    for n in sizes:
        for op in ("build", "pairs", "move10"):
            row = {"n": n, "op": op}
            for impl in ("tree", "sweep", "grid", "box2d_tree", "brute", "tree_batch"):
                row[impl + "_ns_per_box"] = m.get("broadphase/%s/%s/%d" % (op, impl, n))
            b2 = row["box2d_tree_ns_per_box"]
            for impl in ("tree", "sweep", "grid", "tree_batch"):
                row["box2d_over_" + impl] = ratio(b2, row[impl + "_ns_per_box"])
            broad.append(row)
    # Pair events per frame (every box moves): collide's PairTracker over each structure against
    # Box2D's b2BroadPhase (MoveProxy + UpdatePairs); ratio = collide / Box2D, < 1 is faster.
    events = []
    for n in sizes:
        b2 = m.get("broadphase/events/box2d_broadphase/%d" % n)
        if b2 is None:
            continue
        row = {"n": n, "box2d_broadphase_ns_per_box": b2}
        for impl in ("tree", "sweep", "grid"):
            row[impl + "_ns_per_box"] = m.get("broadphase/events/%s/%d" % (impl, n))
            row[impl + "_over_box2d"] = ratio(row[impl + "_ns_per_box"], b2)
        events.append(row)

    # The game loop: collide's loop on each broadphase structure against Box2D's, per frame.
    loops = []
    for n in sorted({int(k.split("/")[2]) for k in loop_counters}):
        b2 = loop_counters.get("game_loop/box2d/%d" % n)
        for impl, structure in (("collide", "tree"), ("collide_sweep", "sweep"), ("collide_world", "world")):
            c = loop_counters.get("game_loop/%s/%d" % (impl, n))
            if b2 is None or c is None:
                continue
            row = {"n": n, "structure": structure}
            for phase in LOOP_PHASES:
                row[phase + "_ms"] = c.get(phase + "_ms")
                row["box2d_" + phase + "_ms"] = b2.get(phase + "_ms")
                row[phase + "_ratio"] = ratio(row[phase + "_ms"], row["box2d_" + phase + "_ms"])
            # Box2D's manifolds turned into world points, normal and separations (what contact()
            # returns), timed outside its frame: the same outputs, not the goal's measure.
            row["box2d_narrowphase_world_ms"] = b2.get("narrowphase_world_ms")
            row["narrowphase_world_ratio"] = ratio(row["narrowphase_ms"], row["box2d_narrowphase_world_ms"])
            # The World's step finds the pairs and computes the contacts: Box2D's pair finding (its
            # broadphase less its update) plus its narrowphase.
            row["step_ms"] = c.get("step_ms")
            b2_step = None
            if None not in (b2.get("broadphase_ms"), b2.get("update_ms"), b2.get("narrowphase_ms")):
                b2_step = b2["broadphase_ms"] - b2["update_ms"] + b2["narrowphase_ms"]
            row["box2d_step_ms"] = b2_step
            row["step_ratio"] = ratio(row["step_ms"], b2_step)
            loops.append(row)

    def fmt(x):
        return "%.2f" % x if isinstance(x, (int, float)) else "-"

    print("\nPer pair (ns, medians of %d repetitions; ratio = collide / peer, < 1 is faster; contact against the"
          " faster of Box2D's two timings of its manifold function)" % args.repetitions)
    collide_tools.print_table(
        ["pair", "set", "collide", "b2Test", "b2Manif", "naive", "/Test", "/Manif", "/naive", "contact", "b2Manif",
         "ratio"],
        [[r["pair"], r["set"]] + [fmt(r[k]) for k in (
            "collide_ns", "box2d_test_overlap_ns", "box2d_manifold_ns", "naive_ns", "ratio_vs_test_overlap",
            "ratio_vs_manifold", "ratio_vs_naive", "collide_contact_ns", "box2d_manifold_contact_ns",
            "contact_ratio_vs_manifold")] for r in pairs], right=set(range(2, 12)))
    floors = [r for r in pairs if r["naive_contact_ns"] is not None]
    if floors:
        print("\nContact floor: a naive world-space contact with contact()'s fields and no exact decision, against"
              " the same Box2D timing (ns; ratio = / Box2D manifold function)")
        collide_tools.print_table(
            ["pair", "set", "naive", "contact", "b2Manif", "naive/", "contact/"],
            [[r["pair"], r["set"]] + [fmt(r[k]) for k in (
                "naive_contact_ns", "collide_contact_ns", "box2d_manifold_contact_ns",
                "naive_contact_ratio_vs_manifold", "contact_ratio_vs_manifold")] for r in floors],
            right=set(range(2, 7)))
    if distances:
        print("\nDistances (ns per pair; ratio = collide / Box2D b2Distance with its witness points, < 1 is faster)")
        collide_tools.print_table(
            ["pair", "set", "closest_points", "distance", "b2Distance", "closest/", "distance/"],
            [[r["pair"], r["set"]] + [fmt(r[k]) for k in (
                "closest_points_ns", "distance_ns", "box2d_distance_ns", "closest_points_ratio", "distance_ratio")]
             for r in distances], right=set(range(2, 7)))
    if points:
        print("\nPoints (ns per point; signed_distance / Box2D b2Distance from a one-vertex proxy, unsigned;"
              " contains / b2Shape::TestPoint)")
        collide_tools.print_table(
            ["kind", "set", "signed", "b2Distance", "ratio", "contains", "TestPoint", "ratio"],
            [[r["kind"], r["set"]] + [fmt(r[k]) for k in (
                "signed_distance_ns", "box2d_distance_ns", "signed_distance_ratio", "contains_ns",
                "box2d_test_point_ns", "contains_ratio")] for r in points], right=set(range(2, 8)))
    if chains:
        print("\nChains (ns per pair; ratio = collide contact(segment, shape) / Box2D b2CollideEdgeAnd* with"
              " b2WorldManifold, one-sided edges with ghost vertices)")
        collide_tools.print_table(["shape", "collide", "box2d", "ratio"],
                                  [[r["kind"]] + [fmt(r[k]) for k in ("collide_ns", "box2d_ns", "ratio")]
                                   for r in chains], right={1, 2, 3})
    print("\nBroadphase (ns per box; speedup = Box2D tree / collide, > 1 is faster; batch = tree add_batch)")
    collide_tools.print_table(
        ["N", "op", "tree", "sweep", "grid", "box2dTree", "brute", "xTree", "xSweep", "xGrid", "batch", "xBatch"],
        [[r["n"], r["op"]] + [fmt(r[k]) for k in (
            "tree_ns_per_box", "sweep_ns_per_box", "grid_ns_per_box", "box2d_tree_ns_per_box", "brute_ns_per_box",
            "box2d_over_tree", "box2d_over_sweep", "box2d_over_grid", "tree_batch_ns_per_box",
            "box2d_over_tree_batch")] for r in broad], right={0} | set(range(2, 12)))
    if events:
        print("\nPair events per frame, every box moving (ns per box; ratio = collide / Box2D b2BroadPhase)")
        collide_tools.print_table(
            ["N", "tree", "sweep", "grid", "b2BroadPh", "/tree", "/sweep", "/grid"],
            [[r["n"]] + [fmt(r[k]) for k in (
                "tree_ns_per_box", "sweep_ns_per_box", "grid_ns_per_box", "box2d_broadphase_ns_per_box",
                "tree_over_box2d", "sweep_over_box2d", "grid_over_box2d")] for r in events], right=set(range(8)))

    if loops:
        print("\nGame loop (ms per frame, collide / Box2D 2.4.1 in the same run; ratio < 1 is faster; /world:"
              " narrowphase / Box2D's b2Collide* plus b2WorldManifold, the same outputs, timed outside its frame)")
        collide_tools.print_table(
            ["N", "collide", "transforms", "update", "broadphase", "narrowphase", "frame", "/transf", "/update",
             "/broad", "/narrow", "/frame", "/world", "/step"],
            [[r["n"], r["structure"]] + ["%.3f / %.3f" % (r[p + "_ms"], r["box2d_" + p + "_ms"])
                                         if r[p + "_ms"] is not None and r["box2d_" + p + "_ms"] is not None else "-"
                                         for p in LOOP_PHASES] + [fmt(r[p + "_ratio"]) for p in LOOP_PHASES]
             + [fmt(r["narrowphase_world_ratio"]), fmt(r["step_ratio"])] for r in loops],
            right={0} | set(range(2, 14)))
        print("(world: the documented World loop; its broadphase is its move() alone, its step (pairs and"
              " contacts) is /step against Box2D's pair finding plus its narrowphase)")

    goals = []
    for r in pairs:
        # Every set with a Box2D manifold function has a contact goal (circle-circle, circle-box,
        # circle-polygon, box-box, polygon-polygon); a capsule pair has none in Box2D 2.4.1.
        if r["contact_ratio_vs_manifold"] is not None:
            goals.append({"goal": "%s/%s contact() <= Box2D manifold function" % (r["pair"], r["set"]),
                          "value": r["contact_ratio_vs_manifold"], "met": r["contact_ratio_vs_manifold"] <= 1.0})
        # The yes/no question never costs more than the whole answer on the same pairs.
        if r["collide_ns"] is not None and r["collide_contact_ns"] is not None:
            value = r["collide_ns"] / r["collide_contact_ns"]
            goals.append({"goal": "%s/%s overlaps() <= contact()" % (r["pair"], r["set"]),
                          "value": round(value, 2), "met": value <= 1.0})
    for r in chains:
        if r["ratio"] is not None:
            goals.append({"goal": "chain/%s contact() <= Box2D edge manifold" % r["kind"], "value": r["ratio"],
                          "met": r["ratio"] <= 1.0})
    for r in loops:
        for phase, what, limit in LOOP_GOALS:
            if r[phase + "_ratio"] is not None:
                goals.append({"goal": "game loop %d (%s): %s" % (r["n"], r["structure"], what),
                              "value": r[phase + "_ratio"], "met": r[phase + "_ratio"] <= limit})
    for r in pairs:
        for peer in ("ratio_vs_test_overlap", "ratio_vs_manifold"):
            if r[peer] is not None:
                goals.append({"goal": "%s/%s faster than Box2D %s" % (r["pair"], r["set"], peer[9:]),
                              "value": r[peer], "met": r[peer] < 1})
        if r["pair"] in ("obb_obb", "polygon_polygon") and r["set"] == "near" and r["collide_ns"] is not None:
            goals.append({"goal": "%s/near <= 25 ns" % r["pair"], "value": r["collide_ns"],
                          "met": r["collide_ns"] <= 25})
        if r["ratio_vs_naive"] is not None:
            goals.append({"goal": "%s/%s within 1.5x of naive" % (r["pair"], r["set"]), "value": r["ratio_vs_naive"],
                          "met": r["ratio_vs_naive"] <= 1.5})
    for r in broad:
        if r["n"] == 100000 and r["op"] == "pairs":
            best = max(v for v in (r["box2d_over_tree"], r["box2d_over_sweep"], r["box2d_over_grid"]) if v is not None)
            goals.append({"goal": "broadphase all-pairs at 100k >= 5x faster per box than Box2D tree queries",
                          "value": best, "met": best >= 5})
    for r in events:
        best = min(v for v in (r["tree_over_box2d"], r["sweep_over_box2d"], r["grid_over_box2d"]) if v is not None)
        goals.append({"goal": "pair-event update at %d moving boxes <= 0.5x Box2D b2BroadPhase" % r["n"],
                      "value": best, "met": best <= 0.5})
    for r in broad:
        if r["op"] == "build" and r["n"] >= 10000 and r["box2d_over_tree"] is not None:
            goals.append({"goal": "tree build (add one by one) at %d >= 1.0x Box2D tree's speed" % r["n"],
                          "value": r["box2d_over_tree"], "met": r["box2d_over_tree"] >= 1.0})
            if r["box2d_over_tree_batch"] is not None:
                goals.append({"goal": "tree build (add_batch) at %d >= 1.0x Box2D tree's speed" % r["n"],
                              "value": r["box2d_over_tree_batch"], "met": r["box2d_over_tree_batch"] >= 1.0})
    print("\nGoals:")
    for g in goals:
        print("  [%s] %s: %s" % ("met" if g["met"] else "MISSED", g["goal"], g["value"]))
    out = {"repetitions": args.repetitions, "min_time_s": args.min_time, "statistic": "median",
           "note": "shared 2-core machine: figures are noisy; ratios come from the same run",
           "context": raw.get("context", {}), "cross_checks": checks, "pairs": pairs, "broadphase": broad,
           "broadphase_events": events, "game_loop": loops, "distances": distances, "points": points, "chains": chains,
           "goals": goals}
    path = os.path.join(reports, "bench.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=2)
    print("\nwrote " + path)


if __name__ == "__main__":
    main()
