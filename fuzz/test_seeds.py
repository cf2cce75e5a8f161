#!/usr/bin/env python3
"""ctest fuzz.seed_archives: the seed archives and the working corpus of fuzz/run.py.

Against the stand-in fuzzers of test_run_interrupt.py (an input "adds coverage" when its bytes are
new), in a scratch tree, it checks:
- fuzz/seeds.py writes one set of inputs as the same bytes whatever the order it is given in,
  entries named by their SHA-1, in name order, with the fixed timestamp;
- --export-seeds from a working corpus writes the archive; a second export, nothing new found,
  leaves it byte for byte as it was and says so;
- a run with an empty working corpus unpacks the archive into it first, fuzzes and merges into
  it; the export after it adds the new inputs, and the one after that changes nothing;
  --reminimise rewrites the archive, into the same bytes for the same inputs;
- a seed archive with a path for an entry name, or that is no zip, stops the run with status 2
  and a message naming the archive, and nothing is written outside the corpus.
"""
import hashlib
import pathlib
import subprocess
import sys
import tempfile
import zipfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from seeds import FIXED_TIME, read_seeds, write_seeds  # noqa: E402

TARGET = "alpha"


class Check:
    def __init__(self):
        self.failures = 0

    def that(self, ok, what):
        print(f"{'ok  ' if ok else 'FAIL'} {what}")
        self.failures += 0 if ok else 1


def main():
    check = Check()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)

        # The archive format alone.
        inputs = [b"one", b"two", b"three", b""]
        write_seeds(tmp / "a.zip", inputs)
        write_seeds(tmp / "b.zip", reversed(inputs))
        check.that((tmp / "a.zip").read_bytes() == (tmp / "b.zip").read_bytes(),
                   "the same inputs in another order give the same archive bytes")
        with zipfile.ZipFile(tmp / "a.zip") as z:
            names = z.namelist()
            check.that(names == sorted(hashlib.sha1(d).hexdigest() for d in inputs),
                       "entries are named by their SHA-1, in name order")
            check.that(all(i.date_time == FIXED_TIME for i in z.infolist()), "every entry has the fixed timestamp")
        check.that(sorted(read_seeds(tmp / "a.zip").values()) == sorted(inputs), "the archive reads back as written")

        # run.py against a stand-in fuzzer.
        bins, seeds, corpus, runs = (tmp / d for d in ("bin", "seeds", "corpus", "runs"))
        bins.mkdir()
        exe = bins / TARGET
        exe.write_text(f"#!/bin/sh\nexec '{sys.executable}' '{HERE / 'test_run_interrupt.py'}' --stand-in {TARGET} "
                       "\"$@\"\n")
        exe.chmod(0o755)
        ledger = tmp / "ledger"
        ledger.touch()
        common = [sys.executable, str(HERE / "run.py"), "--fuzzer-dir", str(bins), "--seeds-dir", str(seeds),
                  "--corpus-dir", str(corpus), "--runs-dir", str(runs), "--regressions-dir", str(tmp / "regressions"),
                  "--reports-dir", str(tmp / "reports")]
        env = {"STAND_IN_LEDGER": str(ledger), "PATH": "/usr/bin:/bin"}

        def run(*extra):
            r = subprocess.run(common + list(extra), capture_output=True, text=True, env=env, timeout=120)
            print("\n".join("    | " + ln for ln in (r.stdout + r.stderr).splitlines()))
            return r

        archive = seeds / f"{TARGET}_seed_corpus.zip"
        (corpus / TARGET).mkdir(parents=True)
        for i in range(3):
            (corpus / TARGET / f"input-{i}").write_bytes(f"input {i}".encode())
        (corpus / TARGET / "again").write_bytes(b"input 1")  # same bytes: one seed
        r = run("--export-seeds")
        check.that(r.returncode == 0 and archive.exists(), "--export-seeds writes the archive")
        first = archive.read_bytes() if archive.exists() else b""
        check.that(archive.exists() and sorted(read_seeds(archive).values()) == [b"input 0", b"input 1", b"input 2"],
                   "the archive holds each distinct input of the working corpus once")
        r = run("--export-seeds")
        check.that(r.returncode == 0 and archive.read_bytes() == first and "unchanged" in r.stdout,
                   "a second export with nothing new leaves the archive byte for byte as it was")

        # A fresh working corpus: unpacked, fuzzed, merged; the export takes the new inputs.
        subprocess.run(["rm", "-rf", str(corpus)], check=True)
        r = run("--minutes", "0.05")
        unpacked = "unpacked 3 of the 3 seeds" in r.stdout
        held = {f.read_bytes() for f in (corpus / TARGET).iterdir()} if (corpus / TARGET).is_dir() else set()
        written = len(ledger.read_text().splitlines())
        check.that(unpacked and {b"input 0", b"input 1", b"input 2"} <= held,
                   "a run with no working corpus unpacks the seeds into it first")
        check.that(written > 0 and len(held) == 3 + written,
                   f"the run merges the {written} new inputs into the working corpus (holds {len(held)})")
        r = run("--export-seeds")
        grown = read_seeds(archive) if archive.exists() else {}
        check.that(r.returncode == 0 and len(grown) == 3 + written and "rewrote" in r.stdout,
                   f"the export after the run adds the new inputs ({len(grown)} seeds)")
        second = archive.read_bytes()
        r = run("--export-seeds")
        check.that(r.returncode == 0 and archive.read_bytes() == second, "and the next export changes nothing")
        r = run("--export-seeds", "--reminimise")
        check.that(r.returncode == 0 and "rewrote" in r.stdout and archive.read_bytes() == second,
                   "--reminimise minimises again, into the same bytes for the same inputs")
        r = run("--reminimise")
        check.that(r.returncode == 2 and archive.read_bytes() == second, "--reminimise alone is a usage error")

        # Archives that are not seed archives.
        for what, make in (("a path for an entry name", lambda z: z.writestr("../escaped", b"x")),
                           ("no zip", None)):
            subprocess.run(["rm", "-rf", str(corpus)], check=True)
            if make:
                with zipfile.ZipFile(archive, "w") as z:
                    make(z)
            else:
                archive.write_bytes(b"not a zip file")
            r = run("--minutes", "0.05")
            check.that(r.returncode == 2 and str(archive) in r.stdout,
                       f"an archive with {what} stops the run with status 2, naming it")
            check.that(not (tmp / "escaped").exists() and not (corpus / "escaped").exists(),
                       f"an archive with {what} writes nothing outside the corpus")
    print(f"seed archive test: {check.failures} failures")
    return 1 if check.failures else 0


if __name__ == "__main__":
    sys.exit(main())
