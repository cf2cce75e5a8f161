#!/usr/bin/env python3
"""Writes generated seeds into the working corpora <corpus>/<target>/ in the input format of
collide/fuzz/decode.hpp (<corpus>: build/corpus, or $COLLIDE_CORPUS_DIR). `./harness fuzz
--export-seeds` then minimises them into the committed archives fuzz/seeds/<target>_seed_corpus.zip.

The kinds, their stored fields (with roles), sample shapes and byte forms are read from the build
(collide_describe, which prints the codecs of oracles/laws/include/collide/laws/codec.hpp), so a
kind added to the registry and its codec gets seeds here without an edit. Seeds are small and
deterministic: every unordered pair of kinds in float and double, overlapping, touching (for the
kinds whose samples 2 apart touch exactly) and separated; every kind with valid values, special
values (NaN, infinities, huge, subnormal) and values aimed at its rules; a few broadphase scripts.
Some seeds place their shapes by transforms (pair flags bit 6: a transform after each shape, a
quarter turn or a rounded rotation; compounds whose children carry child transforms, count byte
bit 7; shapes_from_bytes flags bit 1: a transform after the shape).

usage: fuzz/make_corpus.py [--build-dir build/ci] [--out <corpus>] [--drop-failing]
(replaces the seed files it writes, s-*.bin). With --drop-failing, every seed is run through
the build's fuzz/fuzz_replay_<target> and seeds that fail are left out and listed: a seed corpus
must pass (ctest replays the archives); failures belong in tests/regressions/ as cases.
"""
import argparse
import itertools
import os
import pathlib
import struct
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
import collide_tools  # noqa: E402


# Bits of the byte format of collide/fuzz/decode.hpp.
PLACED_BIT = 0x40          # pair flags: a transform (px py qx qy) follows each shape
CHILD_TRANSFORMS = 0x80    # compound count byte: each child is followed by its transform
SHAPE_TRANSFORM_BIT = 0x02  # shapes_from_bytes flags: a transform follows the shape


def scalar(v, dbl):
    return struct.pack("<d" if dbl else "<f", v)


def scalars(values, dbl):
    return b"".join(scalar(v, dbl) for v in values)


class Codecs:
    """The build's codecs: kind -> layout, fields, sample, byte prefix."""

    def __init__(self, described):
        self.kinds = {k["name"]: k for k in described["kinds"]}
        self.names = [k["name"] for k in described["kinds"]]

    def placed(self, kind, cx, cy, size):
        """The sample values of `kind` scaled by size and moved to (cx, cy), by the fields' roles."""
        k = self.kinds[kind]
        fields = k["fields"]
        out = []
        for i, v in enumerate(k["sample"]):
            role = fields[i % len(fields)]["role"]
            out.append(cx + size * v if role == "x" else cy + size * v if role == "y" else
                       size * v if role == "size" else v)
        return out

    def encode(self, kind, values, dbl, children=(), child_transforms=False):
        """Kind byte, byte prefix, count byte (vertices, children), then the values or children
        (each child followed by its transform when child_transforms)."""
        k = self.kinds[kind]
        out = bytes([k["index"]]) + bytes(k["byte_prefix"])
        if k["layout"] == "vertices":
            out += bytes([len(values) // len(k["fields"])])
        if k["layout"] == "children":
            return out + bytes([len(children) | (CHILD_TRANSFORMS if child_transforms else 0)]) + b"".join(children)
        return out + scalars(values, dbl)

    def shape(self, kind, cx, cy, size, dbl, child_transforms=False):
        """A shape of `kind` around (cx, cy); a compound of the first two kinds side by side, with
        child_transforms each child stored around its own origin and placed there by a quarter
        turn (the same point set: the samples are symmetric under it)."""
        if self.kinds[kind]["layout"] == "children":
            first, second = [n for n in self.names if self.kinds[n]["layout"] != "children"][:2]
            if child_transforms:
                kids = (self.shape(first, 0, 0, size / 2, dbl) + transform(cx - size / 2, cy, 0.0, 1.0, dbl),
                        self.shape(second, 0, 0, size / 2, dbl) + transform(cx + size / 2, cy, 0.0, -1.0, dbl))
            else:
                kids = (self.shape(first, cx - size / 2, cy, size / 2, dbl),
                        self.shape(second, cx + size / 2, cy, size / 2, dbl))
            return self.encode(kind, [], dbl, kids, child_transforms)
        return self.encode(kind, self.placed(kind, cx, cy, size), dbl)

    def first_value_offset(self, kind):
        """Offset of the first scalar after the kind byte."""
        k = self.kinds[kind]
        return 1 + len(k["byte_prefix"]) + (0 if k["layout"] == "fixed" else 1)


def transform(px, py, qx, qy, dbl):
    """A transform's stored values px py qx qy (its codec, through make_with_rotation)."""
    return scalars([px, py, qx, qy], dbl)


# Both shapes of a placed seed by one transform (the pair keeps its relation): a quarter turn
# (exact images) or a rotation by (0.6, 0.8) rounded to the scalar.
PLACEMENTS = (("quarter", (3.0, -2.0, 0.0, 1.0)), ("turned", (-1.5, 0.5, 0.6, 0.8)))


def pair_inputs(codecs, extra=None, flags_extra=0, placed=False):
    """(name, bytes) for every unordered pair of kinds, both scalars, three placements; placed:
    both shapes placed by each of PLACEMENTS (flags bit 6), compounds with child transforms."""
    out = []
    for a, b in itertools.combinations_with_replacement(codecs.names, 2):
        for dbl in (False, True):
            for place, dx in (("overlap", 0.75), ("touch", 2.0), ("apart", 3.5)):
                scalar_tag = "double" if dbl else "float"
                tail = extra(dbl) if extra else b""
                if not placed:
                    data = (bytes([int(dbl) | flags_extra]) + codecs.shape(a, 0, 0, 1, dbl)
                            + codecs.shape(b, dx, 0.25 if place == "apart" else 0, 1, dbl))
                    out.append((f"{a}_{b}-{scalar_tag}-{place}", data + tail))
                    continue
                for name, xf in PLACEMENTS:
                    data = (bytes([int(dbl) | flags_extra | PLACED_BIT]) + codecs.shape(a, 0, 0, 1, dbl, True)
                            + transform(*xf, dbl)
                            + codecs.shape(b, dx, 0.25 if place == "apart" else 0, 1, dbl, True) + transform(*xf, dbl))
                    out.append((f"{a}_{b}-{scalar_tag}-{place}-{name}", data + tail))
    return out


def chain_inputs(codecs):
    """(name, bytes) of the target chain: a floor segment from (2, 0) to (-2, 0) (front up; shape a,
    a capsule of radius 0) against every kind, both scalars, sunk into it, touching it and above
    it, over its middle and beside its end b, where the floor goes on flat or turns down (a convex
    corner the segment owns); the segment owning its start or not, with and without a speculative
    distance, and some with b placed by a transform."""
    out = []
    for kind in codecs.names:
        for dbl in (False, True):
            segment = codecs.encode("capsule", [2.0, 0.0, -2.0, 0.0, 0.0], dbl)
            for place, (cx, cy) in (("sunk", (0.0, 0.75)), ("touch", (0.0, 1.0)), ("above", (0.5, 1.5)),
                                    ("corner", (-2.5, 0.5))):
                for after, (ax, ay) in (("flat", (-3.0, 0.0)), ("down", (-3.0, -1.0))):
                    for option, (owns, spec) in (("", (0, 0.0)), ("-start-spec", (1, 0.75))):
                        tail = scalars([3.0, 0.0, ax, ay], dbl) + bytes([owns]) + scalar(spec, dbl)
                        b = codecs.shape(kind, cx, cy, 1, dbl)
                        tag = f"{kind}-{'double' if dbl else 'float'}-{place}-{after}{option}"
                        out.append((tag, bytes([int(dbl)]) + segment + b + tail))
            for name, xf in PLACEMENTS:
                tail = scalars([3.0, 0.0, -3.0, -1.0], dbl) + bytes([0]) + scalar(0.0, dbl)
                data = (bytes([int(dbl) | PLACED_BIT]) + segment + transform(0.0, 0.0, 1.0, 0.0, dbl)
                        + codecs.shape(kind, 0, 0, 1, dbl, True) + transform(*xf, dbl))
                out.append((f"{kind}-{'double' if dbl else 'float'}-placed-{name}", data + tail))
    return out


def ray(dbl):
    return scalars([-4.0, 0.125, 1.0, 0.0, 16.0], dbl)


def rejected_values(codecs, kind):
    """(name, values) aimed at a kind's rules, derived from the fields' roles: a negative size, the
    first two x values exchanged (min > max where they are a box's corners), all 'other' values
    zero (a zero axis); for vertices, two points (too few) and three on a line (collinear)."""
    k = codecs.kinds[kind]
    base = codecs.placed(kind, 1, -2, 1.5)
    roles = [k["fields"][i % len(k["fields"])]["role"] for i in range(len(base))]
    out = []
    for i, role in enumerate(roles):
        if role == "size":
            out.append((f"negative-{k['fields'][i % len(k['fields'])]['name']}", base[:i] + [-1.0] + base[i + 1:]))
    xs = [i for i, role in enumerate(roles) if role == "x"]
    if k["layout"] == "fixed" and len(xs) >= 2 and base[xs[0]] != base[xs[1]]:
        v = list(base)
        v[xs[0]], v[xs[1]] = v[xs[1]], v[xs[0]]
        out.append(("x-exchanged", v))
    if "other" in roles:
        out.append(("other-zero", [0.0 if role == "other" else v for v, role in zip(base, roles)]))
    if k["layout"] == "vertices":
        out.append(("two", [0, 0, 1, 1]))
        out.append(("collinear", [0, 0, 1, 1, 2, 2]))
    return out


def shapes_from_bytes_inputs(codecs):
    out = []
    specials = [float("nan"), float("inf"), -float("inf"), 1e38, -1e38, 5e-324, 1e-45, 0.0, -0.0, 2.0 ** 126]
    for dbl in (False, True):
        tag = "double" if dbl else "float"
        flags = bytes([int(dbl)])
        for kind in codecs.names:
            out.append((f"{kind}-{tag}-valid", flags + codecs.shape(kind, 1, -2, 1.5, dbl)))
            for name, values in rejected_values(codecs, kind):
                out.append((f"{kind}-{tag}-{name}", flags + codecs.encode(kind, values, dbl)))
            if codecs.kinds[kind]["layout"] == "children":
                out.append((f"{kind}-{tag}-empty", flags + codecs.encode(kind, [], dbl)))
        for n, v in enumerate(specials):
            if not dbl and v == 5e-324:
                continue
            kind = codecs.names[n % len(codecs.names)]
            base = bytearray(flags + codecs.shape(kind, 1, -2, 1.5, dbl))
            w = 8 if dbl else 4
            pos = 1 + codecs.first_value_offset(kind)
            if codecs.kinds[kind]["layout"] == "children":
                pos += 1  # the first child's kind byte
            base[pos:pos + w] = scalar(v, dbl)
            out.append((f"{kind}-{tag}-special{n}", bytes(base)))
        # A transform after the shape: valid (kept, or normalised), a zero rotation, NaN.
        placed = bytes([int(dbl) | SHAPE_TRANSFORM_BIT])
        for name, xf in (("unit", (1, -2, 0.6, 0.8)), ("normalised", (0, 0, 3, 4)), ("zero", (1, 1, 0, 0)),
                         ("nan", (float("nan"), 0, 1, 0))):
            for kind in codecs.names:
                out.append((f"{kind}-{tag}-transform-{name}",
                            placed + codecs.shape(kind, 1, -2, 1.5, dbl, True) + transform(*xf, dbl)))
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
            bad = (bytes([flags]) + scalar(param, dbl) + bytes([0]) + scalars([1, 0, 0, 1], dbl) + bytes([4])
                   + scalars([0, 0, float("nan"), 0, 1], dbl))
            out.append((f"{['tree', 'sweep', 'grid'][structure]}-{tag}-invalid", bad))
    return out


TARGETS = ["overlap_oracle", "resolve", "contact_raycast", "shapes_from_bytes", "broadphase", "chain"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build-dir", default="build/ci")
    ap.add_argument("--out", default=os.environ.get("COLLIDE_CORPUS_DIR") or str(ROOT / "build/corpus"),
                    help="working corpus root (default $COLLIDE_CORPUS_DIR, else build/corpus)")
    ap.add_argument("--drop-failing", action="store_true", help="leave out seeds that fail this build's replay")
    args = ap.parse_args()
    build = collide_tools.build_dir(args.build_dir)
    codecs = Codecs(collide_tools.describe(build))
    if args.drop_failing:
        collide_tools.build_targets(build, [f"fuzz_replay_{t}" for t in TARGETS], quiet=True)

    def passes(target, data):
        if not args.drop_failing:
            return True
        exe = build / "fuzz" / f"fuzz_replay_{target}"
        with tempfile.NamedTemporaryFile() as f:
            f.write(data)
            f.flush()
            return subprocess.run([str(exe), f.name], capture_output=True).returncode == 0

    sets = {
        "overlap_oracle": pair_inputs(codecs) + pair_inputs(codecs, placed=True),
        "resolve": (pair_inputs(codecs, flags_extra=2) + pair_inputs(codecs)[::7]
                    + pair_inputs(codecs, flags_extra=2, placed=True)[::3]),
        "contact_raycast": pair_inputs(codecs, extra=ray) + pair_inputs(codecs, extra=ray, placed=True)[::2],
        "shapes_from_bytes": shapes_from_bytes_inputs(codecs),
        "broadphase": broadphase_inputs(),
        "chain": chain_inputs(codecs),
    }
    assert sorted(sets) == sorted(TARGETS)
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
