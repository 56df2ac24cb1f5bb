#!/usr/bin/python3
"""mill_resume.py - the mill's sensitivity study (tools/mill/sensitivity.sh,
`make mill-sensitivity`) survives an interruption in the middle of its
averaging: killed and run again, the variant resumes from its newer restart
file and ends with the same windows as a run that was never interrupted.

The base variant, shortened (0.05 revolutions of settling, 0.15 averaged in
windows of 0.05 revolution, restart files every window), runs once
uninterrupted (A) and once (B) killed with SIGKILL (the process group, as a
batch system's wall-time limit does) as soon as its first averaging restart
file exists, then run again. Checks: B's rerun says it resumed the
averaging and the log says exact continuation; every ave/chunk epoch of the
2R grid (B's file holds the first part and the appended rest) and every
thermo row of the averaging run are identical, digit for digit, to A's; the
sensitivity table rows agree but for the timing columns."""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
STUDY = os.path.join(ROOT, "tools", "mill", "sensitivity.sh")
sys.path.insert(0, os.path.join(ROOT, "tools", "mill"))
import sensitivity  # noqa: E402

failures = 0


def check(name, ok, detail):
    global failures
    print("  %s: %s" % (name, detail))
    print(("PASS " if ok else "FAIL ") + name)
    failures += not ok


def env(out):
    e = dict(os.environ)
    e.update(MILLS_DIR=out, MILLS_DOC=os.path.join(out, "mill.md"), MILLS_ONLY="base",
             MILLS_SETTLE="0.05", MILLS_AVE="0.15", MILLS_WIN="0.05", MILLS_CHECKPOINT="400")
    return e


def study(out):
    return subprocess.run(["sh", STUDY], env=env(out), capture_output=True, text=True,
                          timeout=900)


def base_row(out):
    """The table row of the base run without its timing columns."""
    for l in open(os.path.join(out, "mill.md")):
        if l.startswith("| base |"):
            return l.split("|")[1:-3]
    return None


def main():
    with tempfile.TemporaryDirectory() as tmp:
        a_dir, b_dir = os.path.join(tmp, "A"), os.path.join(tmp, "B")
        a = study(a_dir)
        if a.returncode:
            check("uninterrupted_run", False, (a.stdout + a.stderr)[-400:])
            return 1
        os.makedirs(b_dir)
        p = subprocess.Popen(["sh", STUDY], env=env(b_dir), stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL, start_new_session=True)
        cp = os.path.join(b_dir, "base", "base.ave.a")
        t0 = time.time()
        while not os.path.exists(cp) and p.poll() is None and time.time() - t0 < 600:
            time.sleep(0.01)
        killed = p.poll() is None
        if killed:
            os.killpg(p.pid, signal.SIGKILL)
        p.wait()
        done = os.path.exists(os.path.join(b_dir, "base", "done"))
        check("interrupted", killed and not done,
              "killed after the first averaging restart file: %s; finished before: %s"
              % (killed, done))
        b = study(b_dir)
        m = re.search(r"averaging resumed from (base\.ave\.[ab])", b.stdout)
        log_b = open(os.path.join(b_dir, "base", "base.log")).read()
        step = re.findall(r"Reading restart file base\.ave\.[ab] \(written by \S+ \S+ at step (\d+)\)",
                          open(os.path.join(b_dir, "base", "run.out")).read())
        exact = bool(step) and "Restart: exact continuation of step %s" % step[-1] in log_b
        check("resumed", b.returncode == 0 and m is not None and exact,
              "rerun resumed the averaging: %s, at step %s, exact continuation: %s%s"
              % (m is not None, step[-1] if step else "?", exact,
                 "" if b.returncode == 0 else "; " + (b.stdout + b.stderr)[-300:]))
        ea = sensitivity.epochs(os.path.join(a_dir, "base", "base_2R.txt"))
        eb = sensitivity.epochs(os.path.join(b_dir, "base", "base_2R.txt"))
        check("epochs_equal", len(ea) == 3 and ea == eb,
              "2R epochs uninterrupted at steps %s, interrupted+resumed %s, identical: %s"
              % (sorted(ea), sorted(eb), ea == eb))
        ra = sensitivity.averaging_rows(os.path.join(a_dir, "base", "base.log"))
        rb = sensitivity.averaging_rows(os.path.join(b_dir, "base", "base.log"))
        diff = [s for s in ra if ra[s] != rb.get(s)]
        check("rows_equal", len(ra) > 50 and sorted(ra) == sorted(rb) and not diff,
              "%d averaging rows uninterrupted, %d resumed; differing steps %s"
              % (len(ra), len(rb), diff[:5]))
        ta, tb = base_row(a_dir), base_row(b_dir)
        check("table_equal", ta is not None and ta == tb,
              "table row %s" % ("|".join(tb) if tb else None))
    print("%d failure(s)" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
