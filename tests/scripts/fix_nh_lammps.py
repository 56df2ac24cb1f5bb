#!/usr/bin/env python3
"""fix_nh_lammps.py - the Nose-Hoover fixes agree with LAMMPS 29Sep2021.

Each tests/reference/fix_nh/*.in deck runs unchanged in gravel and its thermo
(%.15g) must match the log LAMMPS wrote (<deck>.log) row by row, every column
to 1e-8 relative (1e-9 absolute near zero):
  nvt_lj           fix nvt, LJ liquid (pair colloid small-small), ramped
                   target, 3-chain, tloop 2, drag;
  npt_aniso_lj     fix npt aniso, MTK terms, barostat chain, ploop 2, ramped
                   pressure;
  nph_xyz_lj       fix nph x y z couple xy: deviatoric targets, nreset,
                   fixedpoint, mtk no, pchain 1;
  nph_sphere_gas   fix nph/sphere iso: a granular gas (gran/hooke/history)
                   compressed to its target, rotation integrated;
  npt_sphere_gas   fix npt/sphere, tchain 2, pchain 0;
  nvt_sphere_gas   fix nvt/sphere, a ramped target, tchain 4;
  nph_sphere_disc  fix nph/sphere aniso disc in 2d with enforce2d, drag.
Then bad fix commands stop with an error naming the script line.

Usage: fix_nh_lammps.py [--update] [deck ...]   (--update: remake the
references with lmp)"""
import glob
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seeds_verify as sv  # noqa: E402

REFDIR = os.path.join(sv.ROOT, "tests", "reference", "fix_nh")
REL, ABS = 1e-8, 1e-9


def update(deck):
    with tempfile.TemporaryDirectory() as tmp:
        r = subprocess.run(["lmp", "-in", deck, "-log", "log.out", "-screen", "none"], cwd=tmp,
                           capture_output=True, text=True, timeout=600)
        if r.returncode != 0:
            raise RuntimeError("lmp failed on %s" % deck)
        shutil.copy(os.path.join(tmp, "log.out"), deck[:-3] + ".log")
    print("wrote", os.path.relpath(deck[:-3] + ".log", sv.ROOT))


def check(deck):
    name = os.path.basename(deck)[:-3]
    ref = sv.thermo_rows(open(deck[:-3] + ".log").read())
    with tempfile.TemporaryDirectory() as tmp:
        r = subprocess.run([sv.GRAVEL, "-in", deck, "-log", "none"], cwd=tmp,
                           capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        sv.check("%s runs" % name, False, (r.stdout + r.stderr)[-400:])
        return
    rows = sv.thermo_rows(r.stdout)
    worst, where = 0.0, ""
    for p, q in zip(ref, rows):
        for c in p:
            if c == "Step" or c not in q:
                continue
            err = abs(q[c] - p[c]) / max(abs(p[c]), ABS / REL)
            if not err <= worst:
                worst, where = err, "%s step %d: %.15g vs %.15g" % (c, p["Step"], q[c], p[c])
    same = len(rows) == len(ref) and len(ref) > 2 and set(ref[0]) <= set(rows[0])
    sv.check("%s: thermo within %g of lmp (%d rows)" % (name, REL, len(ref)),
             same and worst <= REL, "worst %.3g %s" % (worst, where))


GAS = ("units lj\natom_style sphere\n%sregion b block 0 10 0 10 %s\ncreate_box 1 b\n"
       "create_atoms 1 random 20 123 NULL\n")
BAD = [
    ("", "-1 1", "fix 1 all nvt iso 1 1 1", "temperature control must be used"),
    ("", "-1 1", "fix 1 all npt temp 1 1 1", "pressure control must be used"),
    ("", "-1 1", "fix 1 all nph temp 1 1 1 iso 1 1 1", "temperature control can not be used"),
    ("", "-1 1", "fix 1 all nvt temp 1 1 1 iso 1 1 1", "pressure control can not be used"),
    ("dimension 2\n", "-0.5 0.5", "fix 1 all nph z 1 1 1", "z is invalid for a 2d"),
    ("boundary p p f\n", "-1 1", "fix 1 all nph iso 1 1 1", "non-periodic dimension (z)"),
    ("", "-1 1", "fix 1 all npt temp 1 1 1 tri 1 1 1", "controls the box lengths only"),
    ("", "-1 1", "fix 1 all nvt temp 1 1 1 disc", "keyword of the /sphere styles"),
    ("", "-1 1", "fix 1 all nvt/sphere temp 1 1 1 disc", "requires a 2d simulation"),
    ("", "-1 1", "fix 1 all nvt temp 1 1 1 tchain 0", "tchain must be 1 to"),
    ("", "-1 1", "fix 1 all nph x 1 1 1 y 2 2 1 couple xy", "coupled dimensions differ"),
    ("", "-1 1", "fix 1 all nvt temp 1 1 0", "damping parameters must be > 0.0"),
    ("", "-1 1", "fix 1 all nvt temp 0 1 1", "can not be 0.0"),
    ("", "-1 1", "fix 1 all nph iso 1 1 1 dilate nogroup", "dilate group 'nogroup'"),
    ("", "-1 1", "fix 1 all nvt temp 1 1 1 bogus 3", "unknown keyword 'bogus'"),
]


def check_errors():
    for pre, zr, line, want in BAD:
        deck = GAS % (pre, zr) + line + "\n"
        lineno = deck.count("\n")
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "in.bad"), "w").write(deck)
            r = subprocess.run([sv.GRAVEL, "-in", "in.bad", "-log", "none"], cwd=tmp,
                               capture_output=True, text=True, timeout=60)
        err = [ln for ln in (r.stdout + r.stderr).splitlines() if ln.startswith("ERROR")]
        sv.check("'%s' is refused naming the line" % line,
                 r.returncode != 0 and bool(err) and want in err[0] and
                 ("in.bad:%d" % lineno) in err[0], err[0][:170] if err else "rc %d" % r.returncode)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    decks = sorted(glob.glob(os.path.join(REFDIR, "*.in")))
    if args:
        decks = [d for d in decks if os.path.basename(d)[:-3] in args]
    sv.check("fix nh reference decks exist", len(decks) >= (len(args) or 7), str(len(decks)))
    for deck in decks:
        if "--update" in sys.argv:
            update(deck)
        check(deck)
    if not args:
        check_errors()
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
