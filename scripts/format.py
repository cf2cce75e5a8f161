#!/usr/bin/env python3
"""The C++ style of the tree (.clang-format), applied or checked with clang-format 14 (Debian:
clang-format-14).

    scripts/format.py            rewrites every C++ source and header of the tree in place
    scripts/format.py --check    changes nothing; lists the files that drift and exits 1 if any does

The files are the repository's C++ sources and headers (*.cpp, *.hpp, *.h) as git lists them,
or, outside a git checkout, as found under the source folders; the law table (*.inc, an X-macro
list) is kept as written.
"""

import argparse
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
SUFFIXES = (".cpp", ".hpp", ".h")
FOLDERS = ("lib", "oracles", "properties", "fuzz", "tests", "bench", "examples", "judge")


def sources():
    git = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True)
    if git.returncode == 0 and git.stdout:
        names = [n for n in git.stdout.decode().split("\0") if n]
        files = [ROOT / n for n in names]
    else:
        files = [p for d in FOLDERS for p in (ROOT / d).rglob("*")]
    return sorted(p for p in files if p.suffix in SUFFIXES and p.is_file())


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="list drifting files, change nothing")
    ap.add_argument("--clang-format", default="clang-format-14")
    args = ap.parse_args()
    exe = shutil.which(args.clang_format)
    if exe is None:
        print(f"format.py: {args.clang_format} not found (Debian package clang-format-14)", file=sys.stderr)
        return 2
    files = sources()
    if not args.check:
        subprocess.run([exe, "-i", "--style=file", *map(str, files)], cwd=ROOT, check=True)
        print(f"format.py: {len(files)} files formatted")
        return 0
    drifting = []
    for f in files:
        formatted = subprocess.run([exe, "--style=file", str(f)], cwd=ROOT, capture_output=True, check=True).stdout
        if formatted != f.read_bytes():
            drifting.append(f.relative_to(ROOT))
    for f in drifting:
        print(f"format drift: {f}")
    print(f"format.py: {len(drifting)} of {len(files)} files drift from .clang-format"
          + (" (./harness format rewrites them)" if drifting else ""))
    return 1 if drifting else 0


if __name__ == "__main__":
    sys.exit(main())
