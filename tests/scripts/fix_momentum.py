#!/usr/bin/env python3
"""fix_momentum.py - fix momentum (LAMMPS and LIGGGHTS) against LAMMPS.

1. tests/reference/momentum/mom.in: a gas of 512 spheres with a net drift in
   x and y between two granular walls, `fix momentum 50 linear 1 1 0 angular
   rescale`; runs unchanged in lmp (committed mom.lammps.log, LAMMPS 29 Sep
   2021). Every thermo row (every 50 steps, right after each removal): the
   kinetic energy within REL_KE of LAMMPS's, vcm_z within ABS_VZ of LAMMPS's
   (the z drift is kept: flag 0), and vcm_x, vcm_y below ABS_ZERO (removed;
   LAMMPS's are round-off of the same size).
2. Bad commands stop with an error naming the line: no N, N <= 0, a linear
   flag that is not 0 or 1, an unknown keyword, neither linear nor angular.
One PASS/FAIL line per check."""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REF = os.path.join(ROOT, "tests", "reference", "momentum")
REL_KE = 1e-10     # measured 2e-15 (sums in tag order against LAMMPS's memory order)
ABS_VZ = 1e-12     # measured 4e-16
ABS_ZERO = 1e-13   # removed components: round-off (measured 1e-14)
failures = 0


def check(name, ok, detail=""):
    global failures
    print("%s %s%s" % ("PASS" if ok else "FAIL", name, "" if ok else " (" + detail + ")"))
    failures += not ok


def rows(text):
    return [[float(v) for v in l.split()] for l in text.splitlines()
            if re.match(r"^\s+\d+\s+[-\d.eE+]+(\s+[-\d.eE+]+){3}\s*$", l)]


def run(tmp, text):
    open(os.path.join(tmp, "in.deck"), "w").write(text)
    r = subprocess.run([GRAVEL, "-in", "in.deck", "-log", "none"], cwd=tmp, capture_output=True,
                       text=True, timeout=300)
    return r.returncode, r.stdout + r.stderr


def main():
    deck = open(os.path.join(REF, "mom.in")).read()
    ref = rows(open(os.path.join(REF, "mom.lammps.log")).read())
    with tempfile.TemporaryDirectory() as tmp:
        rc, out = run(tmp, deck)
        got = rows(out)
        ok = rc == 0 and len(got) == len(ref) == 11
        ke = max((abs(a[1] - b[1]) / abs(b[1]) for a, b in zip(got, ref)), default=-1)
        vz = max((abs(a[4] - b[4]) for a, b in zip(got, ref)), default=-1)
        zero = max((abs(v) for a in got[1:] for v in a[2:4]), default=-1)
        check("momentum_lammps_rows", ok and 0 <= ke <= REL_KE and 0 <= vz <= ABS_VZ and
              0 <= zero <= ABS_ZERO, "%d rows (lammps %d), ke %g, vz %g, removed %g\n%s" %
              (len(got), len(ref), ke, vz, zero, out[-300:]))
        print("  fix momentum: ke within %.1e of LAMMPS's, vcm_z within %.1e, vcm_x, vcm_y "
              "at most %.1e after each removal" % (ke, vz, zero))
        head = deck.split("fix             3")[0]
        for name, line, msg in (
                ("no_n", "fix 3 all momentum", "expected N"),
                ("n_zero", "fix 3 all momentum 0 linear 1 1 1", "N must be > 0"),
                ("flag", "fix 3 all momentum 10 linear 1 2 1", "linear flags are 0 or 1"),
                ("keyword", "fix 3 all momentum 10 linear 1 1 1 spin", "unknown keyword 'spin'"),
                ("neither", "fix 3 all momentum 10 rescale", "give linear and/or angular")):
            rc, out = run(tmp, head + line + "\nrun 10\n")
            lineno = head.count("\n") + 1
            check("momentum_error_" + name, rc != 0 and msg in out and
                  "(in.deck:%d)" % lineno in out, out[-300:])
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
