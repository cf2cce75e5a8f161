#!/usr/bin/env python3
"""Checks the documentation as a reader meets it.

  check_docs.py snippets PAGE.md OUT.cpp   one C++ program from every ```cpp block of PAGE.md
  check_docs.py readme README.md           README.md is short and says what is true now

Snippets (built and run by ctest, label docs; see docs/verification.md, "Code in the docs"):
- Each ```cpp block is the body of a function returning int, run in the page's order; a non-zero
  return or an escaping exception fails the page. A block that defines `int main(` is a whole
  program instead: its main() is run the same way.
- `#include` lines of any block go to the top of the program.
- An HTML comment opening with `<!-- prelude` holds C++ that the blocks after it need but the
  reader does not (a using-declaration, a helper); it is placed at namespace scope before the
  next block, and stays in effect for the rest of the page.
- Other fences (```sh, ```cmake, ```text) are not compiled.
"""

import argparse
import re
import sys
from pathlib import Path

FENCE = re.compile(r"^```(\S*)\s*$")
PRELUDE_OPEN = "<!-- prelude"
PRELUDE_CLOSE = "-->"
MAIN = re.compile(r"\bint\s+main\s*\(\s*\)")

README_MAX_LINES = 400
README_MAX_DATES = 5
CLOCK_TIME = re.compile(r"\b\d{1,2}:\d{2}(?:[–-]\d{1,2}:\d{2})?\s*UTC\b")
ISO_DATE = re.compile(r"\b\d{4}-\d{2}-\d{2}\b")


class Block:
    """One piece of C++ taken from a page: a cpp block or a prelude."""

    def __init__(self, kind, line, text):
        self.kind = kind  # "cpp" or "prelude"
        self.line = line  # 1-based line of the first code line in the page
        self.text = text


def read_blocks(page):
    """The cpp blocks and preludes of a page, in order, with their first lines."""
    lines = page.read_text(encoding="utf-8").splitlines()
    blocks = []
    i = 0
    while i < len(lines):
        line = lines[i]
        fence = FENCE.match(line)
        if line.strip().startswith(PRELUDE_OPEN):
            start = i + 1
            body = []
            first = line.strip()[len(PRELUDE_OPEN):]
            if first.strip():
                raise SystemExit(f"{page}:{i + 1}: the prelude's code starts on the next line")
            i += 1
            while i < len(lines) and lines[i].strip() != PRELUDE_CLOSE:
                body.append(lines[i])
                i += 1
            if i == len(lines):
                raise SystemExit(f"{page}:{start}: prelude without its closing '-->' line")
            blocks.append(Block("prelude", start + 1, body))
        elif fence and fence.group(1):
            lang, start = fence.group(1), i + 1
            body = []
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            if i == len(lines):
                raise SystemExit(f"{page}:{start}: code block without its closing fence")
            if lang == "cpp":
                blocks.append(Block("cpp", start + 1, body))
        i += 1
    return blocks


def split_includes(text):
    """(the #include lines, the other lines with the includes blanked to keep line numbers)."""
    includes, rest = [], []
    for line in text:
        if line.lstrip().startswith("#include"):
            includes.append(line.strip())
            rest.append("")
        else:
            rest.append(line)
    return includes, rest


def program(page, shown_as):
    """The C++ program of one page: includes, preludes and blocks as functions, and a main()."""
    blocks = read_blocks(page)
    includes = ["#include <collide/collide.hpp>", "#include <collide/broadphase.hpp>", "#include <cstdio>",
                "#include <exception>"]
    body = []
    runs = []
    for b in blocks:
        found, rest = split_includes(b.text)
        includes += [i for i in found if i not in includes]
        if b.kind == "prelude":
            body += [f'#line {b.line} "{shown_as}"', *rest, ""]
            continue
        name = f"block_{len(runs) + 1}"
        runs.append((name, b.line))
        if any(MAIN.search(line) for line in rest):
            rest = [MAIN.sub("int run()", line) for line in rest]
            body += [f"namespace {name} {{", f'#line {b.line} "{shown_as}"', *rest, f"}}  // namespace {name}", ""]
        else:
            body += [f"namespace {name} {{", "int run() {", f'#line {b.line} "{shown_as}"', *rest,
                     "  return 0;", "}", f"}}  // namespace {name}", ""]
    if not runs:
        raise SystemExit(f"{page}: no ```cpp block to check")
    main = ["int main() {", "  int failed = 0;"]
    for name, line in runs:
        where = f"{shown_as}:{line}"
        main += [
            "  try {",
            f"    if (const int status = {name}::run(); status != 0) {{",
            f'      std::fprintf(stderr, "{where}: the block returned %d\\n", status);',
            "      ++failed;",
            "    }",
            "  } catch (const std::exception& e) {",
            f'    std::fprintf(stderr, "{where}: the block threw: %s\\n", e.what());',
            "    ++failed;",
            "  }",
        ]
    main += [f'  std::printf("{shown_as}: %d of {len(runs)} blocks passed\\n", {len(runs)} - failed);',
             "  return failed == 0 ? 0 : 1;", "}"]
    header = ["// Generated by scripts/check_docs.py from " + shown_as + ": edit the page, not this file."]
    return "\n".join(header + includes + [""] + body + main) + "\n"


def check_readme(path):
    """The README's rules: its length, no clock times, a handful of dates. Returns the problems."""
    lines = path.read_text(encoding="utf-8").splitlines()
    problems = []
    if len(lines) > README_MAX_LINES:
        problems.append(f"{path}: {len(lines)} lines, more than {README_MAX_LINES}: move detail to docs/")
    for n, line in enumerate(lines, 1):
        for m in CLOCK_TIME.finditer(line):
            problems.append(f"{path}:{n}: a clock time ({m.group(0)}): dated records go to docs/measurements.md")
    dates = [(n, m.group(0)) for n, line in enumerate(lines, 1) for m in ISO_DATE.finditer(line)]
    if len(dates) > README_MAX_DATES:
        listed = ", ".join(f"line {n}: {d}" for n, d in dates)
        problems.append(f"{path}: {len(dates)} dates, more than {README_MAX_DATES} ({listed}): "
                        "the README says what is true now; dated records go to docs/measurements.md")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    snippets = sub.add_parser("snippets", help="write the C++ program of a page's cpp blocks")
    snippets.add_argument("page", type=Path)
    snippets.add_argument("out", type=Path)
    snippets.add_argument("--shown-as", help="the page's name in messages (default: the path given)")
    readme = sub.add_parser("readme", help="check README.md's length, clock times and dates")
    readme.add_argument("path", type=Path)
    args = parser.parse_args()

    if args.command == "snippets":
        text = program(args.page, args.shown_as or str(args.page))
        # Rewritten only when changed, so an edit elsewhere in the tree rebuilds nothing here.
        if not args.out.exists() or args.out.read_text(encoding="utf-8") != text:
            args.out.parent.mkdir(parents=True, exist_ok=True)
            args.out.write_text(text, encoding="utf-8")
        return 0
    problems = check_readme(args.path)
    for p in problems:
        print(p, file=sys.stderr)
    if not problems:
        print(f"{args.path}: within {README_MAX_LINES} lines, no clock time, at most {README_MAX_DATES} dates")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
