#!/usr/bin/env python3
"""pair_colloid_lammps.py - pair colloid agrees with LAMMPS 29Sep2021.

Each tests/reference/colloid/pair_colloid_*.in deck (a few particles: small-
small LJ with pair_modify shift yes; colloid-small with the colloid's
diameter given as d2 and as d1; colloid-colloid of two diameters; cross
pairs mixed from the diagonal) runs unchanged in gravel for 20 nve steps.
Every frame of its force dump (fx fy fz, %.17g) must match LAMMPS's dump
(<deck>.dump) to 1e-10 relative to the frame's largest force component,
and every thermo row (pe: the pair energy, press: kinetic part plus the
pair virial; %.17g) LAMMPS's log (<deck>.log) to 1e-10 relative.

Then bad coefficients stop with an error naming the script line, as LAMMPS
refuses them: d1 != d2 for I = I, a negative diameter, a wrong count.

Usage: pair_colloid_lammps.py [--update]   (--update: remake the references
with lmp)"""
import glob
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seeds_verify as sv  # noqa: E402
from physics_lammps import read_dump  # noqa: E402

REFDIR = os.path.join(sv.ROOT, "tests", "reference", "colloid")
TOL = 1e-10


def run(cmd, deck, tmp):
    return subprocess.run(cmd + ["-in", deck, "-log", "log.out", "-screen", "none"]
                          if cmd[0] == "lmp" else cmd + ["-in", deck, "-log", "none"],
                          cwd=tmp, capture_output=True, text=True, timeout=300)


def update(deck):
    name = deck[:-3]
    with tempfile.TemporaryDirectory() as tmp:
        r = run(["lmp"], deck, tmp)
        if r.returncode != 0:
            raise RuntimeError("lmp failed on %s" % deck)
        shutil.copy(os.path.join(tmp, "out.dump"), name + ".dump")
        shutil.copy(os.path.join(tmp, "log.out"), name + ".log")
    print("wrote", os.path.relpath(name + ".dump", sv.ROOT), os.path.relpath(name + ".log", sv.ROOT))


def check(deck):
    name = os.path.basename(deck)[:-3]
    ref = read_dump(deck[:-3] + ".dump")
    ref_rows = sv.thermo_rows(open(deck[:-3] + ".log").read())
    with tempfile.TemporaryDirectory() as tmp:
        r = run([sv.GRAVEL], deck, tmp)
        if r.returncode != 0:
            sv.check("%s runs" % name, False, (r.stdout + r.stderr)[-400:])
            return
        got = read_dump(os.path.join(tmp, "out.dump"))
        rows = sv.thermo_rows(r.stdout)
    worst, where = 0.0, ""
    ok = sorted(got) == sorted(ref) and len(ref) > 1
    for step, frame in ref.items():
        scale = max(abs(v) for vals in frame.values() for v in vals)
        for tag, vals in frame.items():
            for k, (a, b) in enumerate(zip(got.get(step, {}).get(tag, [float("nan")] * 3), vals)):
                err = abs(a - b) / max(scale, 1e-300)
                if not err <= worst:
                    worst, where = err, "step %d atom %d f%s" % (step, tag, "xyz"[k])
    sv.check("%s: forces within %g of lmp (%d frames)" % (name, TOL, len(ref)),
             ok and worst <= TOL, "worst %.3g %s" % (worst, where))
    tworst, twhere = 0.0, ""
    same = len(rows) == len(ref_rows) and len(rows) > 1
    for q, p in zip(rows, ref_rows):
        for c in ("PotEng", "Press"):
            err = abs(q[c] - p[c]) / max(abs(p[c]), 1e-300)
            if not err <= tworst:
                tworst, twhere = err, "%s step %d: %.17g vs %.17g" % (c, p["Step"], q[c], p[c])
    sv.check("%s: pe and press within %g of lmp" % (name, TOL), same and tworst <= TOL,
             "worst %.3g %s" % (tworst, twhere))


BAD = [
    ("pair_coeff 1 1 39.5 1.0 10.0 6.0", "needs d1 = d2"),
    ("pair_coeff 1 2 39.5 1.0 -1.0 6.0", "invalid d1 or d2"),
    ("pair_coeff 1 1 39.5 1.0 10.0", "expects pair_coeff I J A sigma d1 d2"),
    ("pair_coeff 1 1 39.5 1.0 10.0 10.0 2.0 7", "expects pair_coeff I J A sigma d1 d2"),
]


def check_errors():
    for line, want in BAD:
        deck = ("units lj\natom_style sphere\nregion b block 0 50 0 50 0 50\n"
                "create_box 2 b\npair_style colloid 20.0\n%s\n" % line)
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "in.bad"), "w").write(deck)
            r = run([sv.GRAVEL], "in.bad", tmp)
        err = [ln for ln in (r.stdout + r.stderr).splitlines() if ln.startswith("ERROR")]
        sv.check("pair colloid refuses '%s' naming the line" % line,
                 r.returncode != 0 and bool(err) and want in err[0] and "in.bad:6" in err[0],
                 err[0][:160] if err else "rc %d" % r.returncode)


def main():
    decks = sorted(glob.glob(os.path.join(REFDIR, "pair_colloid_*.in")))
    sv.check("pair colloid reference decks exist", len(decks) >= 4, str(len(decks)))
    for deck in decks:
        if "--update" in sys.argv:
            update(deck)
        check(deck)
    check_errors()
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
