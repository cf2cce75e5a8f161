#!/usr/bin/env python3
"""ctest fuzz.run_interrupted: fuzz/run.py stopped by SIGTERM and by SIGINT mid-run, then resumed,
loses nothing a fuzzer found.

The fuzzers are stand-ins (this file, run with --stand-in as each target's executable): they speak
the part of libFuzzer's command line run.py uses, write a new input every 50 ms into the corpus
directory and a ledger line for each, write failing inputs of two kinds into the artifact prefix,
and start a worker process of their own, as fork mode does. So the test needs no clang build and
takes seconds. It checks, after each stop: every input written is in the corpus, one regression
input per kind of failure, the reports say the run was interrupted and which targets are left,
the worker is gone; after the last resume: the run is complete and reported as a whole.
"""
import json
import os
import pathlib
import signal
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
TARGETS = ("alpha", "beta")
FAILING = {5: b"crash A", 8: b"crash B", 12: b"crash A"}  # write step -> failing input


def stand_in(target, argv):
    """A fuzzer executable as far as run.py uses one."""
    flags = {a.split("=", 1)[0]: a.split("=", 1)[1] if "=" in a else "" for a in argv if a.startswith("-")}
    paths = [pathlib.Path(a) for a in argv if not a.startswith("-")]
    if "-merge" in flags:  # -merge=1 OUT IN...: an input "adds coverage" when its bytes are new to OUT
        out, *others = paths
        held = {f.read_bytes() for f in out.iterdir()}
        for d in others:
            for f in sorted(d.iterdir()):
                data = f.read_bytes()
                if data not in held and not (out / f.name).exists():
                    (out / f.name).write_bytes(data)
                    held.add(data)
        return 0
    if flags.get("-runs") == "0":  # load the corpus once: "coverage" is the count of distinct inputs
        distinct = {f.read_bytes() for d in paths for f in d.iterdir()}
        sys.stderr.write(f"#{len(distinct)} INITED cov: {len(distinct)} ft: {len(distinct)} corp: {len(distinct)}\n")
        return 0
    if "-minimize_crash" in flags:
        pathlib.Path(flags["-exact_artifact_path"]).write_bytes(paths[0].read_bytes())
        return 0
    if "-fork" not in flags:  # replay of single inputs
        for p in paths:
            data = p.read_bytes()
            if data.startswith(b"crash"):
                sys.stderr.write(f"==1==ERROR: stand-in failure\nSUMMARY: stand-in: {data.decode()}\n")
                return 1
        return 0
    # Fork mode: NEW SEEDS; runs until -max_total_time or SIGINT.
    new = paths[0]
    prefix = flags["-artifact_prefix"]
    ledger = pathlib.Path(os.environ["STAND_IN_LEDGER"])
    worker = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(600)"])
    ledger.with_name("workers").open("a").write(f"{worker.pid}\n")
    stop = []
    signal.signal(signal.SIGINT, lambda *_: stop.append(1))
    start = time.time()
    step = 0
    while not stop and time.time() - start < float(flags["-max_total_time"]):
        step += 1
        name = f"input-{os.getpid()}-{step}"
        (new / name).write_bytes(name.encode())
        with ledger.open("a") as lf:
            lf.write(f"{target} {name}\n")
        if step in FAILING:
            pathlib.Path(f"{prefix}crash-{os.getpid()}-{step}").write_bytes(FAILING[step])
        print(f"#{step * 1000}: cov: {step} ft: {step} corp: {step} exec/s: 20000 oom/timeout/crash: 0/0/0",
              flush=True)
        time.sleep(0.05)
    worker.terminate()
    worker.wait()
    return 72 if stop else 0


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # A zombie is not alive either.
    stat = pathlib.Path(f"/proc/{pid}/stat")
    return stat.exists() and stat.read_text().split()[2] != "Z"


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
        bins, corpus, regressions, runs, reports = (tmp / d for d in ("bin", "corpus", "regressions", "runs",
                                                                      "reports"))
        bins.mkdir()
        for t in TARGETS:
            exe = bins / t
            exe.write_text(f"#!/bin/sh\nexec '{sys.executable}' '{__file__}' --stand-in {t} \"$@\"\n")
            exe.chmod(0o755)
            (corpus / t).mkdir(parents=True)
            (corpus / t / "seed").write_bytes(b"seed")
        ledger = tmp / "ledger"
        ledger.touch()
        env = dict(os.environ, STAND_IN_LEDGER=str(ledger))
        common = [sys.executable, str(HERE / "run.py"), "--fuzzer-dir", str(bins), "--corpus-dir", str(corpus),
                  "--seeds-dir", str(tmp / "seeds"), "--regressions-dir", str(regressions), "--runs-dir", str(runs),
                  "--reports-dir", str(reports), "--progress-seconds", "0.5"]

        def run(extra, stop_when, sig):
            """Starts run.py, sends sig once stop_when(output so far) holds; returns (status, output)."""
            out = tmp / "out.txt"
            with out.open("w") as f:
                p = subprocess.Popen(common + extra, stdout=f, stderr=subprocess.STDOUT, env=env)
                deadline = time.time() + 60
                while p.poll() is None and time.time() < deadline:
                    if sig and stop_when(out.read_text()):
                        p.send_signal(sig)
                        sig = None
                    time.sleep(0.05)
                if p.poll() is None:
                    p.kill()
                    check.that(False, "run.py exits within 60 s")
                p.wait()
            text = out.read_text()
            print("\n".join("    | " + ln for ln in text.splitlines()))
            return p.returncode, text

        def nothing_lost(when, ran):
            written = [ln.split() for ln in ledger.read_text().splitlines()]
            missing = [f"{t}/{n}" for t, n in written if not (corpus / t / n).exists()]
            check.that(written and not missing,
                       f"{when}: all {len(written)} inputs the fuzzers wrote are in the corpus "
                       f"(missing: {missing[:5]})")
            kinds = sorted((p.name.split("-")[0], p.read_bytes()) for p in regressions.glob("*.input"))
            expected = sorted((t, k) for t in ran for k in (b"crash A", b"crash B"))
            check.that(kinds == expected, f"{when}: one regression input per target and kind of failure "
                                          f"(found {kinds})")
            workers = [int(x) for x in (tmp / "workers").read_text().split()]
            check.that(not any(alive(w) for w in workers), f"{when}: the fuzzers' workers are gone")

        def crash_b_written(target):
            crashes = runs / target / "crashes"
            return crashes.exists() and any(p.read_bytes() == b"crash B" for p in crashes.glob("crash-*"))

        # 1. SIGTERM while the first target runs.
        status, text = run(["--minutes", "0.34"], lambda s: crash_b_written("alpha"), signal.SIGTERM)
        check.that(status == 1, f"stopped run exits 1 (failures found), got {status}")
        check.that("SIGTERM: stopping the fuzzer" in text, "the stop is announced")
        check.that("] alpha (1/2): execs" in text, "progress lines are printed while a target runs")
        doc = json.loads((reports / "fuzz.json").read_text())
        check.that(doc["interrupted"] and doc["unfinished_targets"] == ["alpha", "beta"],
                   f"fuzz.json: interrupted, alpha and beta left (got {doc['unfinished_targets']})")
        check.that("Interrupted" in (reports / "fuzz.md").read_text(), "fuzz.md says the run was interrupted")
        state = json.loads((runs / "state.json").read_text())
        check.that("alpha" in state["partial"] and not state["done"], "the plan keeps alpha as partly run")
        nothing_lost("after SIGTERM", ["alpha"])

        # 2. Resume; SIGINT while the second target runs.
        status, text = run(["--resume"], lambda s: "] beta (2/2)" in s and crash_b_written("beta"),
                           signal.SIGINT)
        check.that("alpha" in text.split("== beta")[0] and "resumed" in text, "the resume finishes alpha first")
        state = json.loads((runs / "state.json").read_text())
        check.that(list(state["done"]) == ["alpha"] and "beta" in state["partial"],
                   "after SIGINT: alpha done, beta partly run")
        alpha = state["done"]["alpha"]
        check.that(9 <= alpha["seconds"] <= 15, f"alpha's two parts add up to its 10 s (got {alpha['seconds']})")
        check.that(len(alpha["failures"]) == 2, f"alpha reports 2 distinct failures (got {len(alpha['failures'])})")
        nothing_lost("after SIGINT", TARGETS)

        # 3. Resume to the end.
        status, text = run(["--resume"], None, None)
        check.that(status == 1, f"the complete run exits 1 (failures found), got {status}")
        doc = json.loads((reports / "fuzz.json").read_text())
        check.that(not doc["interrupted"] and [r["target"] for r in doc["targets"]] == ["alpha", "beta"],
                   "fuzz.json: complete, both targets reported")
        check.that(not (runs / "state.json").exists(), "the plan is removed when the run is complete")
        nothing_lost("at the end", TARGETS)
        status, text = run(["--resume"], None, None)
        check.that(status == 2 and "nothing to resume" in text, "--resume after a complete run says so")
    print(f"interrupted-run test: {check.failures} failures")
    return 1 if check.failures else 0


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--stand-in":
        sys.exit(stand_in(sys.argv[2], sys.argv[3:]))
    sys.exit(main())
