#!/usr/bin/env python3
"""Seeds of the fuzz target `cast`, built from the seeds of contact_raycast (the inputs of
fuzz/seeds/contact_raycast_seed_corpus.zip, in name order), written into the working corpus
<corpus>/cast/ (build/corpus, or $COLLIDE_CORPUS_DIR), from where `./harness fuzz --export-seeds`
minimises them into fuzz/seeds/cast_seed_corpus.zip.

A contact_raycast input is a pair followed by a ray (origin x y, direction x y, max_t); read by
`cast`, the same five scalars are va, vb and max_t: every ray seed is a motion seed. Each chosen
seed is written three ways: as it is, with the grazing bit (flags bit 2: a moved back along the
tangent of its contact so that the pair passes within touching at max_t / 2), with the two
turns of time_of_impact appended (a quarter turn of a, half a turn back of b), and with the turns
and a transform for each shape (flags bits 3 and 4: a placed by a quarter turn, b by a rounded
rotation), once plainly and once grazing.

usage: fuzz/make_cast_corpus.py [--count N] [--out <corpus>]   (writes <corpus>/cast/c-*.bin)
"""

import argparse
import hashlib
import os
import pathlib
import struct
import sys

from seeds import SeedError, read_seeds

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--count", type=int, default=40)
    ap.add_argument("--out", default=os.environ.get("COLLIDE_CORPUS_DIR") or str(ROOT / "build/corpus"),
                    help="working corpus root (default $COLLIDE_CORPUS_DIR, else build/corpus)")
    args = ap.parse_args()
    try:
        seeds = read_seeds(ROOT / "fuzz/seeds/contact_raycast_seed_corpus.zip")
    except SeedError as e:
        print(f"make_cast_corpus: {e}", file=sys.stderr)
        return 2
    out = pathlib.Path(args.out) / "cast"
    out.mkdir(parents=True, exist_ok=True)
    written = 0
    for name in sorted(seeds)[: args.count]:
        data = seeds[name]
        if not data:
            continue
        fmt = "<d" if data[0] & 1 else "<f"
        turns = struct.pack(fmt, 1.5707963267948966) + struct.pack(fmt, -3.141592653589793)
        xa = b"".join(struct.pack(fmt, v) for v in (0.5, -0.25, 0.0, 1.0))
        xb = b"".join(struct.pack(fmt, v) for v in (-1.0, 2.0, 0.6, 0.8))
        placed = data[1:] + turns + xa + xb
        for variant in (data, bytes([data[0] | 4]) + data[1:], data + turns, bytes([data[0] | 24]) + placed,
                        bytes([data[0] | 28]) + placed):
            name = "c-" + hashlib.sha1(variant).hexdigest()[:16] + ".bin"
            (out / name).write_bytes(variant)
            written += 1
    print(f"make_cast_corpus: {written} seeds in {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
