#!/usr/bin/env python3
"""The floors of lib/include/collide, checked: every header on one floor, every include going to
the same floor or one below, the queries side by side, and the broadphase index structures light.

Usage: include_floors.py [INCLUDE_DIR]   (default: lib/include of this tree)

A floor is a group of headers; includes inside a floor are allowed (real dependencies chain a few
files there), includes upward are not. Prints the floors table and the file-level include depth;
exits 1 naming every broken rule.
"""

import fnmatch
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent

# Floor -> (name, header patterns relative to collide/). Every header must match exactly one.
FLOORS = {
    1: ("ground: configuration, errors, feature ids, numeric helpers, exact predicates",
        ["config.hpp", "error.hpp", "feature.hpp", "predicates.hpp", "detail/math.hpp"]),
    2: ("shapes: the kinds, boxes, rays, transforms and images, compounds, the registry",
        ["shapes.hpp", "bounds.hpp", "ray.hpp", "transform.hpp", "detail/image.hpp", "compound.hpp",
         "registry.hpp", "shape_traits.hpp", "translate.hpp"]),
    3: ("cores and the exact decisions: convex cores, the pair decisions, tolerances",
        ["detail/convex_core.hpp", "detail/exact_signs.hpp", "decide.hpp", "detail/contact_cores.hpp",
         "tolerances.hpp"]),
    4: ("the queries, side by side: overlaps, contact, resolve, distance, contains, raycast, mass",
        ["overlaps.hpp", "contact.hpp", "resolve.hpp", "distance.hpp", "contains.hpp", "raycast.hpp", "mass.hpp",
         "detail/contact_base.hpp", "detail/contact_circle.hpp", "detail/contact_hulls.hpp", "detail/contact_pairs.hpp",
         "detail/contact_local.hpp", "detail/contains_point.hpp", "detail/contains_shape.hpp",
         "detail/witness.hpp"]),
    5: ("placement: shapes and compounds posed by transforms, and the queries on them",
        ["transformed.hpp", "detail/placement.hpp"]),
    6: ("casts, chains, the world and the umbrella headers",
        ["cast.hpp", "time_of_impact.hpp", "detail/advance*.hpp", "chain.hpp", "broadphase/*.hpp", "broadphase.hpp",
         "collide.hpp", "compiled.hpp"]),
}

# The query headers of floor 4: none may reach another through its includes.
QUERIES = ["contact.hpp", "resolve.hpp", "distance.hpp", "contains.hpp", "raycast.hpp", "mass.hpp"]

# The broadphase index structures: their closure stays small and never reaches the contact engine.
BROADPHASE = ["broadphase/common.hpp", "broadphase/tree.hpp", "broadphase/grid.hpp", "broadphase/sweep.hpp",
              "broadphase/events.hpp"]
BROADPHASE_MAX_LINES = 3000
CONTACT_ENGINE = ["contact.hpp", "detail/contact_*.hpp"]

INCLUDE = re.compile(r'^\s*#\s*include\s+"collide/([^"]+)"', re.M)


def matches(rel: str, patterns: list[str]) -> bool:
    return any(fnmatch.fnmatchcase(rel, p) for p in patterns)


def floor_of(rel: str) -> list[int]:
    """Every floor whose patterns name rel (exactly one when the table is right)."""
    return [f for f, (_, patterns) in FLOORS.items() if matches(rel, patterns)]


def closure(rel: str, includes: dict[str, list[str]]) -> set[str]:
    seen, todo = set(), [rel]
    while todo:
        h = todo.pop()
        if h not in seen:
            seen.add(h)
            todo.extend(i for i in includes.get(h, []) if i in includes)
    return seen


def check(include_dir: pathlib.Path) -> list[str]:
    base = include_dir / "collide"
    if not base.is_dir():
        return [f"{base}: no such directory"]
    headers = sorted(p.relative_to(base).as_posix() for p in base.rglob("*.hpp"))
    texts = {h: (base / h).read_text() for h in headers}
    includes = {h: INCLUDE.findall(texts[h]) for h in headers}
    lines = {h: texts[h].count("\n") for h in headers}
    problems = []

    floor = {}
    for h in headers:
        fs = floor_of(h)
        if len(fs) != 1:
            problems.append(f"collide/{h}: on {'no floor' if not fs else 'floors ' + str(fs)} "
                            "(give it exactly one in FLOORS of scripts/include_floors.py)")
        else:
            floor[h] = fs[0]

    for h in headers:
        for i in includes[h]:
            if i not in texts:
                problems.append(f"collide/{h}: includes collide/{i}, which does not exist")
            elif h in floor and i in floor and floor[i] > floor[h]:
                problems.append(f"collide/{h} (floor {floor[h]}) includes collide/{i} (floor {floor[i]}): "
                                "an include must go to the same floor or a lower one")

    loop = cycle(headers, includes)
    if loop:
        problems.append("include cycle: " + " -> ".join("collide/" + h for h in loop))

    for q in QUERIES:
        if q not in texts:
            problems.append(f"collide/{q}: query header missing")
            continue
        for other in sorted(closure(q, includes) & (set(QUERIES) - {q})):
            problems.append(f"collide/{q} reaches collide/{other}: the query headers must not include each other")

    for b in BROADPHASE:
        if b not in texts:
            problems.append(f"collide/{b}: broadphase header missing")
            continue
        reach = closure(b, includes)
        total = sum(lines[h] for h in reach)
        if total > BROADPHASE_MAX_LINES:
            problems.append(f"collide/{b} pulls in {len(reach)} headers of {total} lines "
                            f"(at most {BROADPHASE_MAX_LINES})")
        engine = sorted(h for h in reach if matches(h, CONTACT_ENGINE))
        if engine:
            problems.append(f"collide/{b} reaches the contact engine: {', '.join('collide/' + h for h in engine)}")

    report(headers, floor, includes, lines)
    return problems


def depths(headers: list[str], includes: dict[str, list[str]]) -> dict[str, int]:
    """Each header's include depth (1 for a header that includes no other); an include that closes
    a cycle is not counted (the cycle is reported by check())."""
    depth: dict[str, int] = {}
    on_path: set[str] = set()

    def visit(h: str) -> int:
        if h in depth:
            return depth[h]
        on_path.add(h)
        below = [visit(i) for i in includes[h] if i in includes and i not in on_path]
        on_path.discard(h)
        depth[h] = 1 + max(below, default=0)
        return depth[h]

    for h in headers:
        visit(h)
    return depth


def cycle(headers: list[str], includes: dict[str, list[str]]) -> list[str]:
    """One include cycle as the list of its headers, or [] when there is none."""
    state: dict[str, int] = {}  # 1: on the current path, 2: done
    path: list[str] = []

    def visit(h: str) -> list[str]:
        state[h] = 1
        path.append(h)
        for i in includes[h]:
            if i not in includes:
                continue
            if state.get(i) == 1:
                return path[path.index(i):] + [i]
            if i not in state and (found := visit(i)):
                return found
        path.pop()
        state[h] = 2
        return []

    for h in headers:
        if h not in state and (found := visit(h)):
            return found
    return []


def report(headers: list[str], floor: dict[str, int], includes: dict[str, list[str]], lines: dict[str, int]) -> None:
    print("| floor | what | headers | lines |")
    print("|---:|---|---|---:|")
    for f, (name, _) in FLOORS.items():
        on = [h for h in headers if floor.get(h) == f]
        print(f"| {f} | {name} | {', '.join('`' + h + '`' for h in on)} | {sum(lines[h] for h in on)} |")

    depth = depths(headers, includes)
    deepest = max(headers, key=lambda h: depth[h])
    chain = [deepest]
    while depth[chain[-1]] > 1:
        chain.append(next(i for i in includes[chain[-1]] if depth.get(i) == depth[chain[-1]] - 1))
    print(f"\nfile-level include depth: {depth[deepest]} ({' -> '.join(chain)})")
    for b in BROADPHASE:
        if b in includes:
            reach = closure(b, includes)
            print(f"closure of {b}: {len(reach)} headers, {sum(lines[h] for h in reach)} lines")


def main() -> int:
    include_dir = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "lib" / "include"
    problems = check(include_dir)
    if problems:
        print(f"\ninclude_floors: {len(problems)} problem(s):", file=sys.stderr)
        for p in problems:
            print("  " + p, file=sys.stderr)
        return 1
    print("\ninclude_floors: every header on its floor; no include goes up")
    return 0


if __name__ == "__main__":
    sys.exit(main())
