#!/usr/bin/python3
"""agglo_resume.py - the agglomeration sweep (tools/agglomeration/sweep.sh, `make
reproduce-agglomeration`) survives an interruption: killed in the middle of a
grid point and run again, it keeps the finished point, resumes the interrupted
one from its newer restart file and ends with the same numbers as a sweep that
was never interrupted.

A tiny sweep (27 particles, Sy 1.5, Stk 0.1 and 10, 10 s = 22272 steps per
point, 8 checkpoints) runs once uninterrupted (A) and once (B) killed with
SIGKILL (the whole process group, as a batch system's wall-time limit does)
as soon as the second point's first restart file exists, then run again.
Checks: B's second invocation keeps point 1 and resumes point 2 from a step
0 < S < 22272; every thermo row of both logs (after average.py merges the
resumed table) is identical, digit for digit, to A's, and so is the averaged
table.dat; the resumed histogram goes to a .from<S>.hist file.

A new machine (C): B's state at the kill is parked (tools/agglomeration/park.sh,
as a session whose files do not survive commits it) and a sweep in an empty
run directory takes both points from there, resumes point 2 at the same step
and ends with A's rows, digit for digit.

Two points at once (D, AGGLO_JOBS=2): a sweep in an empty run directory
starts both points (the second once the first has written the initial
state), is killed when both have a restart file, and run again with
AGGLO_JOBS=2; the unfinished points resume (a point may have finished
before the kill: it is kept) and both end with A's rows, digit for digit.
An AGGLO_JOBS that is not a positive integer is refused.

The benchmark's late state (inputs/bench/agglo_late.restart.gz, `make bench`'s
agglate: seed 12345's Sy 1.5 / Stk 1 at step 1285977) still reads as an exact
continuation: its first row is the sweep's row at that step, digit for digit."""
import gzip
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SWEEP = os.path.join(ROOT, "tools", "agglomeration", "sweep.sh")
PARK = os.path.join(ROOT, "tools", "agglomeration", "park.sh")
sys.path.insert(0, os.path.join(ROOT, "tools", "agglomeration"))
import average  # noqa: E402

NSTEPS = 22272          # round(10 / 0.000449)
failures = 0


def check(name, ok, detail):
    global failures
    print("  %s: %s" % (name, detail))
    print(("PASS " if ok else "FAIL ") + name)
    failures += not ok


def env(out, parked, jobs=1):
    e = dict(os.environ)
    e.update(AGGLO_JOBS=str(jobs))
    e.update(AGGLO_PARKED=parked, AGGLO_N="27", AGGLO_TEND="10", AGGLO_NOUT="40", AGGLO_SY="1.5",
             AGGLO_ST="0.1 10.0", AGGLO_CHECKPOINTS="8", AGGLO_OUT=out,
             AGGLO_DOC=os.path.join(out, "doc"), AGGLO_PLOT="0", AGGLO_TAG="resume")
    return e


def sweep(out, parked, jobs=1):
    return subprocess.run(["sh", SWEEP], env=env(out, parked, jobs), capture_output=True,
                          text=True, timeout=600)


def sweep_killed(out, parked, checkpoints, jobs=1):
    """Start a sweep in `out` and kill its whole process group (SIGKILL, as a
    batch system's wall-time limit does) once every file in `checkpoints`
    exists; True when it was still running then."""
    os.makedirs(out)
    p = subprocess.Popen(["sh", SWEEP], env=env(out, parked, jobs), stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL, start_new_session=True)
    t0 = time.time()
    while not all(map(os.path.exists, checkpoints)) and p.poll() is None \
            and time.time() - t0 < 300:
        time.sleep(0.01)
    killed = p.poll() is None
    if killed:
        os.killpg(p.pid, signal.SIGKILL)
    p.wait()
    return killed


def rows_if(run_dir, name):
    """rows() of a log that may be missing: ([], False) then."""
    path = os.path.join(run_dir, name)
    return rows(path) if os.path.isfile(path) else ([], False)


def rows(path):
    info = average.parse_log(path)
    return info["rows"], info["completed"]


# the sweep's row at step 1285977 (runs/agglomeration: seed 12345, Sy 1.5, Stk 1)
LATE_ROW = "1285977 577.40367 542 18.450185 44.641709 403 0.39479059 4143.907"


def check_bench_late(tmp):
    """the benchmark's late restart resumes exactly (run 0 upto its step)"""
    d = os.path.join(tmp, "late")
    os.makedirs(d)
    with gzip.open(os.path.join(ROOT, "inputs", "bench", "agglo_late.restart.gz"), "rb") as src, \
            open(os.path.join(d, "agglo_late.restart"), "wb") as dst:
        shutil.copyfileobj(src, dst)
    r = subprocess.run([os.path.join(ROOT, "bin", "gravel"), "-in",
                        os.path.join(ROOT, "inputs", "published", "agglomeration", "agglomeration.in"),
                        "-var", "Sy", "1.5", "-var", "St", "1.0", "-var", "N", "10000",
                        "-var", "resume", "1", "-var", "rfile", "agglo_late.restart",
                        "-var", "tend", "%.6f" % (1285977 * 0.000449), "-var", "nout", "2",
                        "-var", "logfile", "none", "-log", "none"],
                       cwd=d, capture_output=True, text=True)
    lines = [" ".join(l.split()) for l in r.stdout.splitlines()]
    check("bench_late_restart_exact", r.returncode == 0 and LATE_ROW in lines and
          "Restart: exact continuation of step 1285977" in r.stdout,
          "row at the restart's step %s" % ([l for l in lines if l.startswith("1285977 ")][:1]
                                            or (r.stdout + r.stderr)[-300:]))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        a_dir, b_dir = os.path.join(tmp, "A"), os.path.join(tmp, "B")
        c_dir, parked = os.path.join(tmp, "C"), os.path.join(tmp, "parked")
        a = sweep(a_dir, parked)
        if a.returncode:
            check("uninterrupted_sweep", False, (a.stdout + a.stderr)[-400:])
            return 1
        # B: kill the sweep once the second point has written a checkpoint
        killed = sweep_killed(b_dir, parked, [os.path.join(b_dir, "agglo_Sy1.5_St10.0.restart.a")])
        log2 = os.path.join(b_dir, "agglo_Sy1.5_St10.0.log")
        done2 = "agglomeration grid point done" in open(log2).read()
        check("interrupted", killed and not done2,
              "sweep killed after point 2's first checkpoint: %s; point 2 finished before the "
              "kill: %s" % (killed, done2))
        pk = subprocess.run(["sh", PARK, b_dir, "resume"], env=env(b_dir, parked),
                            capture_output=True, text=True)
        names = sorted(os.listdir(os.path.join(parked, "resume"))) if pk.returncode == 0 else []
        check("parked", pk.returncode == 0 and "agglo_Sy1.5_St10.0.restart.gz" in names
              and "agglo_Sy1.5_St0.1.restart.gz" not in names and "settings" in names,
              "park.sh: %s" % (names or (pk.stdout + pk.stderr)[-300:]))
        b = sweep(b_dir, parked)
        kept = re.search(r"grid point Sy 1.5 St 0.1: finished earlier, kept", b.stdout)
        m = re.search(r"grid point Sy 1.5 St 10.0 starts at step (\d+)", b.stdout)
        step = int(m.group(1)) if m else -1
        exact = "Restart: exact continuation of step %d" % step in open(log2).read()
        check("resumed", b.returncode == 0 and kept is not None and 0 < step < NSTEPS and exact,
              "rerun: point 1 kept: %s; point 2 resumed at step %d of %d, log says exact "
              "continuation: %s%s" % (kept is not None, step, NSTEPS, exact,
                "" if b.returncode == 0 else "; " + (b.stdout + b.stderr)[-300:]))
        for st in ("0.1", "10.0"):
            name = "agglo_Sy1.5_St%s.log" % st
            ra, ca = rows(os.path.join(a_dir, name))
            rb, cb = rows(os.path.join(b_dir, name))
            diff = [x[0] for x, y in zip(ra, rb) if x != y]
            check("rows_equal_St" + st, ca and cb and len(ra) == len(rb) and len(ra) > 40
                  and not diff, "%d rows uninterrupted, %d interrupted+resumed, completed %s/%s;"
                  " differing steps %s" % (len(ra), len(rb), ca, cb, diff[:5]))
        c = sweep(c_dir, parked)
        mc = re.search(r"grid point Sy 1.5 St 10.0 starts at step (\d+)", c.stdout)
        seeded = c.stdout.count("from the parked run")
        check("resumed_from_parked", c.returncode == 0 and seeded == 2 and mc is not None
              and int(mc.group(1)) == step and "grid point Sy 1.5 St 0.1: finished earlier, kept"
              in c.stdout, "empty run directory: %d grid points from the parked run, point 2 "
              "resumed at step %s (B: %d)%s" % (seeded, mc.group(1) if mc else "?", step,
                "" if c.returncode == 0 else "; " + (c.stdout + c.stderr)[-300:]))
        for st in ("0.1", "10.0"):
            name = "agglo_Sy1.5_St%s.log" % st
            ra, _ = rows(os.path.join(a_dir, name))
            rc_, cc = rows_if(c_dir, name)
            check("parked_rows_equal_St" + st, cc and ra == rc_ and len(ra) > 40,
                  "%d rows uninterrupted, %d parked+resumed" % (len(ra), len(rc_)))
        ta = open(os.path.join(a_dir, "table.dat")).read()
        tb = open(os.path.join(b_dir, "table.dat")).read()
        check("table_equal", ta == tb and ta.count("\n") == 3,
              "table.dat identical: %s (%s)" % (ta == tb, tb.strip().splitlines()[-1]))
        hist = os.path.join(b_dir, "agglo_Sy1.5_St10.0.from%d.hist" % step)
        check("resumed_histogram", os.path.isfile(hist), hist)
        # D: two points at once, killed while both run, then resumed two at once
        d_dir = os.path.join(tmp, "D")
        killed = sweep_killed(d_dir, parked + "-none", [
            os.path.join(d_dir, "agglo_Sy1.5_St%s.restart.a" % st) for st in ("0.1", "10.0")], 2)
        d = sweep(d_dir, parked + "-none", 2)
        steps = [int(x) for x in re.findall(r"grid point Sy 1.5 St [0-9.]+ starts at step (\d+)",
                                            d.stdout)]
        kept2 = d.stdout.count("finished earlier, kept")
        both = [os.path.isfile(os.path.join(d_dir, "screen_Sy1.5_St%s.txt" % st))
                for st in ("0.1", "10.0")]
        check("jobs2_resumed", killed and d.returncode == 0 and len(steps) >= 1 and all(both)
              and "2 grid points at once" in d.stdout
              and len(steps) + kept2 == 2 and all(0 < x < NSTEPS for x in steps),
              "killed while running: %s; rerun with AGGLO_JOBS=2 resumed at steps %s, kept %d "
              "finished point(s)%s" % (killed, steps, kept2,
                                      "" if d.returncode == 0 else "; " + (d.stdout + d.stderr)[-300:]))
        for st in ("0.1", "10.0"):
            name = "agglo_Sy1.5_St%s.log" % st
            ra, _ = rows(os.path.join(a_dir, name))
            rd, cd = rows_if(d_dir, name)
            check("jobs2_rows_equal_St" + st, cd and ra == rd and len(ra) > 40,
                  "%d rows one at a time, %d two at once (interrupted, resumed)"
                  % (len(ra), len(rd)))
        bad = sweep(os.path.join(tmp, "E"), parked + "-none", "two")
        check("jobs_refused", bad.returncode != 0 and "AGGLO_JOBS must be a positive integer"
              in bad.stdout, (bad.stdout + bad.stderr).strip()[-200:])
        check_bench_late(tmp)
    print("%d failure(s)" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
