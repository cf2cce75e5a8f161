#!/usr/bin/env python3
"""Writes the seed corpora fuzz/corpus/<target>/ in the input format of collide/fuzz/decode.hpp.

The kinds and their order are read from the registry (lib/include/collide/registry.hpp, enum
ShapeKind), so a kind added there without an encoder here stops this script instead of silently
shifting every kind byte. Seeds are small and deterministic: every unordered pair of kinds in
float and double, overlapping, touching (for the kinds where unit shapes 2 apart touch exactly)
and separated; every factory form with valid and invalid values; a few broadphase scripts.

usage: fuzz/make_corpus.py [--out fuzz/corpus] [--drop-failing BUILD_DIR]
(replaces the seed files it writes, s-*.bin). With --drop-failing, every seed is run through
BUILD_DIR/fuzz/fuzz_replay_<target> and seeds that fail are left out and listed: a seed corpus
must pass (ctest replays it); failures belong in tests/regressions/ as cases.
"""
import argparse
import itertools
import math
import pathlib
import re
import struct
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def registry_kinds():
    text = (ROOT / "lib/include/collide/registry.hpp").read_text()
    m = re.search(r"enum class ShapeKind\s*:\s*std::uint8_t\s*\{([^}]*)\}", text)
    if not m:
        sys.exit("make_corpus: cannot find enum ShapeKind in registry.hpp")
    return [k.strip().lower() for k in m.group(1).split(",") if k.strip()]


KINDS = registry_kinds()
PRIMITIVES = [k for k in KINDS if k != "compound"]


def scalar(v, dbl):
    return struct.pack("<d" if dbl else "<f", v)


def scalars(values, dbl):
    return b"".join(scalar(v, dbl) for v in values)


def kind_byte(kind, among=None):
    return bytes([(among or KINDS).index(kind)])


def payload(kind, cx, cy, size, dbl, form=0):
    """Values of one shape of `kind` centred near (cx, cy) with radius-like size."""
    s = size
    if kind == "circle":
        return scalars([cx, cy, s], dbl)
    if kind == "aabb":
        return scalars([cx - s, cy - s, cx + s, cy + s], dbl)
    if kind == "obb":
        if form == 0:
            return bytes([0]) + scalars([cx, cy, s, s / 2, 0.5], dbl)
        if form == 1:
            return bytes([1]) + scalars([cx, cy, s, s / 2, 3.0, 4.0], dbl)
        # A square with dyadic corners: sides (s, s/2) and (-s/2, s).
        h = s / 2
        pts = [(cx - h, cy - h), (cx - h + s, cy - h + h), (cx - h + s - h, cy - h + h + s), (cx - h - h, cy - h + s)]
        return bytes([2]) + scalars([c for p in pts for c in p], dbl)
    if kind == "capsule":
        return scalars([cx - s / 2, cy, cx + s / 2, cy, s / 2], dbl)
    if kind == "polygon":
        n = 5 + form * 4  # 5 or 9 vertices (9 leaves the inline storage)
        pts = []
        for i in range(n):
            a = 2 * math.pi * i / n
            pts += [cx + s * round(math.cos(a) * 64) / 64, cy + s * round(math.sin(a) * 64) / 64]
        head = n | (0x80 if form == 2 else 0)
        return bytes([head]) + scalars(pts, dbl)
    if kind == "compound":
        kids = kind_byte("circle", PRIMITIVES) + payload("circle", cx - s / 2, cy, s / 2, dbl)
        kids += kind_byte("aabb", PRIMITIVES) + payload("aabb", cx + s / 2, cy, s / 2, dbl)
        return bytes([2]) + kids
    sys.exit(f"make_corpus: no encoder for kind '{kind}' (added to the registry?)")


def shape(kind, cx, cy, size, dbl, form=0):
    return kind_byte(kind) + payload(kind, cx, cy, size, dbl, form)


def pair_inputs(extra=b"", flags_extra=0):
    """(name, bytes) for every unordered pair of kinds, both scalars, three placements."""
    out = []
    for i, j in itertools.combinations_with_replacement(range(len(KINDS)), 2):
        a, b = KINDS[i], KINDS[j]
        for dbl in (False, True):
            for place, dx in (("overlap", 0.75), ("touch", 2.0), ("apart", 3.5)):
                form = (i + j) % 3
                data = bytes([int(dbl) | flags_extra]) + shape(a, 0, 0, 1, dbl, form) + shape(b, dx, 0.25 if place == "apart" else 0, 1, dbl, form)
                out.append((f"{a}_{b}-{'double' if dbl else 'float'}-{place}", data + extra(dbl) if callable(extra) else data))
    return out


def ray(dbl):
    return scalars([-4.0, 0.125, 1.0, 0.0, 16.0], dbl)


def shapes_from_bytes_inputs():
    out = []
    specials = [float("nan"), float("inf"), -float("inf"), 1e38, -1e38, 5e-324, 1e-45, 0.0, -0.0, 2.0 ** 126]
    for dbl in (False, True):
        tag = "double" if dbl else "float"
        for kind in KINDS:
            forms = (0, 1, 2) if kind in ("obb", "polygon") else (0,)
            for form in forms:
                out.append((f"{kind}{form}-{tag}-valid", bytes([int(dbl)]) + shape(kind, 1, -2, 1.5, dbl, form)))
        for k, v in enumerate(specials):
            if not dbl and v == 5e-324:
                continue
            kind = KINDS[k % len(KINDS)]
            base = bytearray(bytes([int(dbl)]) + shape(kind, 1, -2, 1.5, dbl))
            w = 8 if dbl else 4
            pos = 2 + (1 if kind in ("obb", "polygon", "compound") else 0) + (1 if kind == "compound" else 0)
            base[pos:pos + w] = scalar(v, dbl)
            out.append((f"{kind}-{tag}-special{k}", bytes(base)))
        # Rejections by name: negative radius, min > max, too few vertices, collinear, empty compound.
        out.append((f"circle-{tag}-negative", bytes([int(dbl)]) + kind_byte("circle") + scalars([0, 0, -1], dbl)))
        out.append((f"aabb-{tag}-inverted", bytes([int(dbl)]) + kind_byte("aabb") + scalars([1, 0, 0, 1], dbl)))
        out.append((f"polygon-{tag}-two", bytes([int(dbl)]) + kind_byte("polygon") + bytes([2]) + scalars([0, 0, 1, 1], dbl)))
        out.append((f"polygon-{tag}-collinear", bytes([int(dbl)]) + kind_byte("polygon") + bytes([3]) + scalars([0, 0, 1, 1, 2, 2], dbl)))
        out.append((f"polygon-{tag}-reflex", bytes([int(dbl)]) + kind_byte("polygon") + bytes([4]) + scalars([0, 0, 2, 0, 1, 0.5, 1, 2], dbl)))
        out.append((f"compound-{tag}-empty", bytes([int(dbl)]) + kind_byte("compound") + bytes([0])))
        out.append((f"obb-{tag}-zeroaxis", bytes([int(dbl)]) + kind_byte("obb") + bytes([1]) + scalars([0, 0, 1, 1, 0, 0], dbl)))
    return out


def broadphase_inputs():
    out = []
    for dbl in (False, True):
        tag = "double" if dbl else "float"
        for structure, param in ((0, 0.1), (1, 0.0), (2, 1.0)):
            ops = b""
            boxes = [(0, 0, 1, 1), (1, 0, 2, 1), (0.5, 0.5, 3, 3), (-2, -2, -1, -1), (5, 5, 5, 5)]
            for bx in boxes:
                ops += bytes([0]) + scalars(bx, dbl)
            ops += bytes([5])  # pairs sorted
            ops += bytes([1, 1]) + scalars([2, 2, 4, 4], dbl)  # move
            ops += bytes([3]) + scalars([1, 1, 2, 2], dbl)  # query
            ops += bytes([4]) + scalars([-1, 0.5, 1, 0, 10], dbl)  # raycast
            ops += bytes([2, 0]) + bytes([2, 0])  # remove, then the stale handle again
            ops += bytes([0]) + scalars([0, 0, 1, 1], dbl)  # reuse the slot
            ops += bytes([1, 0]) + scalars([0, 0, 1, 1], dbl)  # move through the stale handle
            ops += bytes([6])  # pairs any
            flags = int(dbl) | (structure << 1)
            out.append((f"{['tree', 'sweep', 'grid'][structure]}-{tag}", bytes([flags]) + scalar(param, dbl) + ops))
            bad = bytes([flags]) + scalar(param, dbl) + bytes([0]) + scalars([1, 0, 0, 1], dbl) + bytes([4]) + scalars([0, 0, float("nan"), 0, 1], dbl)
            out.append((f"{['tree', 'sweep', 'grid'][structure]}-{tag}-invalid", bad))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(ROOT / "fuzz/corpus"))
    ap.add_argument("--drop-failing", metavar="BUILD_DIR", help="leave out seeds that fail this build's replay")
    args = ap.parse_args()

    def passes(target, data):
        if not args.drop_failing:
            return True
        exe = pathlib.Path(args.drop_failing) / "fuzz" / f"fuzz_replay_{target}"
        with tempfile.NamedTemporaryFile() as f:
            f.write(data)
            f.flush()
            return subprocess.run([str(exe), f.name], capture_output=True).returncode == 0

    sets = {
        "overlap_oracle": pair_inputs(),
        "resolve": pair_inputs(flags_extra=2) + pair_inputs()[::7],
        "contact_raycast": pair_inputs(extra=ray),
        "shapes_from_bytes": shapes_from_bytes_inputs(),
        "broadphase": broadphase_inputs(),
    }
    for target, items in sets.items():
        d = pathlib.Path(args.out) / target
        d.mkdir(parents=True, exist_ok=True)
        for old in d.glob("s-*.bin"):
            old.unlink()
        names = set()
        for name, data in items:
            if name in names:
                name += "-b"
            names.add(name)
            if not passes(target, data):
                print(f"  {target}: seed {name} fails the replay: left out")
                continue
            (d / f"s-{name}.bin").write_bytes(data)
        print(f"{target}: {len(list(d.glob('s-*.bin')))} seeds")


if __name__ == "__main__":
    main()
