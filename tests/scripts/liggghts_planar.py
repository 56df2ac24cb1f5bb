#!/usr/bin/env python3
"""liggghts_planar.py - fix mesh/surface/planar and fix insert/stream ... all_in
yes against LIGGGHTS 3.8.

1. tests/reference/liggghts_planar/all_in.in (a stream of 400 particles of
   two radii through a planar face of 8 triangles, all_in yes, onto a zplane
   wall) runs in gravel; what `liggghts` wrote for the same deck is committed
   (all_in.liggghts.log, out.STEP.liggghts.dump.gz; --update rewrites them).
   all_in yes redraws a face point closer than the particle's radius to one of
   the stored nearest active edges of its triangle (LIGGGHTS's
   TriMeshPlanar lists, src/state/mesh_planar.c), from the face mesh's
   stream, so the comparison is exact:
   - the insertion INFO lines (count, mass, step), as text;
   - every thermo row (step, atoms, KinEng, rotational energy, Volume) to REL
     of the 8 printed digits (measured: all digits equal to step 40000,
     bounces on the floor included);
   - the dumped atoms (id, type, radius, x, v, omega printed to 17 digits) at
     steps 5000 and 20000 (before the floor) to EXACT; at 40000 (after the
     stream hit the floor: round-off grows) to CHAOS.
2. all_in matters: at step 5000 the centres whose x lies within their radius
   of the face's border |x| = 0.2 (they fly straight down in x until they
   reach the floor) number the same in gravel as in liggghts (1: LIGGGHTS's
   lists keep six edges per triangle, so a point may pass), and the same deck
   with all_in no gives at least ten times as many (liggghts: 31).
3. Errors as LIGGGHTS's: a mesh/surface/planar that is not planar, all_in yes
   on a plain mesh/surface.

Usage: liggghts_planar.py [--update]. One PASS/FAIL line per case."""
import gzip
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, check_bad_decks, infos, report, thermo  # noqa: E402
from liggghts_stream import run_gravel as run_deck  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_planar")
WEDGE = os.path.join(ROOT, "tests", "reference", "liggghts_stream", "wedge.stl")
REL = 1e-6              # thermo columns, relative (8 digits printed)
EXACT, CHAOS = 1e-12, 1e-3
STEPS = (5000, 20000, 40000)
HALF = 0.2              # the face: |x|, |y| <= 0.2

def stage(tmp, text):
    shutil.copy(os.path.join(REF, "face8.stl"), tmp)
    shutil.copy(WEDGE, tmp)
    open(os.path.join(tmp, "in.deck"), "w").write(text)


def run_gravel(cwd):
    return run_deck(cwd, "in.deck")


def dump_atoms(path):
    """LAMMPS text dump: {id: [type, radius, x, y, z, vx, vy, vz, wx, wy, wz]}."""
    op = gzip.open if path.endswith(".gz") else open
    lines = op(path, "rt").read().split("\n")
    at = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    return {int(l.split()[0]): [float(v) for v in l.split()[1:]]
            for l in lines[at + 1:] if l.strip()}


def near_border(atoms):
    return sum(1 for a in atoms.values() if HALF - abs(a[2]) < a[1])


def check_deck():
    deck = open(os.path.join(REF, "all_in.in")).read()
    reflog = open(os.path.join(REF, "all_in.liggghts.log")).read()
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp, deck)
        out = run_gravel(tmp)
        if out.returncode:
            report(False, "liggghts_planar_all_in_runs", (out.stdout + out.stderr)[-1500:])
            return
        text = open(os.path.join(tmp, "log.gravel")).read()
        ins, ref_ins = infos(text), infos(reflog)
        report(ins == ref_ins and len(ins) == 2, "liggghts_planar_all_in_insertions",
               "gravel %s\n  liggghts %s" % (ins, ref_ins))
        print("  insertions (count, mass, step): %s" % ins)
        rows, ref_rows = thermo(text), thermo(reflog)
        bad, worst = [], 0.
        if len(rows) != len(ref_rows) or len(rows) < 40:
            bad.append("%d thermo rows, liggghts %d" % (len(rows), len(ref_rows)))
        for r, q in zip(rows, ref_rows):
            if r[:2] != q[:2]:
                bad.append("step/atoms %s vs %s" % (r[:2], q[:2]))
                continue
            for c in range(2, len(q)):
                u, w = float(r[c]), float(q[c])
                d = abs(u - w) / abs(w) if w else abs(u)
                worst = max(worst, d)
                if d > REL:
                    bad.append("step %s column %d: %s vs %s" % (r[0], c, r[c], q[c]))
        report(not bad, "liggghts_planar_all_in_thermo", "; ".join(bad[:5]))
        print("  %d thermo rows, last %s; largest relative difference %.2g" %
              (len(rows), " ".join(rows[-1]) if rows else "-", worst))
        for step in STEPS:
            mine = dump_atoms(os.path.join(tmp, "out.%d.dump" % step))
            ref = dump_atoms(os.path.join(REF, "out.%d.liggghts.dump.gz" % step))
            tol = EXACT if step < 40000 else CHAOS
            name = "liggghts_planar_all_in_dump_%d" % step
            if sorted(mine) != sorted(ref):
                report(False, name, "ids differ: %d atoms vs liggghts %d" % (len(mine), len(ref)))
                continue
            wrong = [i for i in ref if mine[i][:2] != ref[i][:2]]
            dmax = max(abs(u - w) for i in ref for u, w in zip(mine[i][2:], ref[i][2:]))
            report(not wrong and dmax <= tol, name,
                   "type/radius differ for ids %s; largest difference %.3g > %g" %
                   (wrong[:5], dmax, tol))
            print("  step %d: %d atoms, largest |dx|, |dv|, |domega| %.2g (tolerance %g)" %
                  (step, len(ref), dmax, tol))
            if step == 5000:
                check_all_in(tmp, deck, near_border(mine), near_border(ref))


def check_all_in(tmp, deck, mine, ref):
    """Centres within their radius of the face's border at step 5000."""
    text, n = re.subn(r"overlapcheck yes all_in yes", "overlapcheck yes all_in no", deck)
    text, m = re.subn(r"(?m)^run +40000$", "run 5000", text)
    assert n == 1 and m == 1
    with tempfile.TemporaryDirectory() as tmp2:
        stage(tmp2, text)
        out = run_gravel(tmp2)
        without = near_border(dump_atoms(os.path.join(tmp2, "out.5000.dump"))) \
            if out.returncode == 0 else -1
    report(mine == ref and without >= 10 * max(ref, 1), "liggghts_planar_all_in_border",
           "near the border: gravel %d, liggghts %d, all_in no %d" % (mine, ref, without))
    print("  centres within r of the face's border at step 5000: all_in yes %d (liggghts %d), "
          "all_in no %d" % (mine, ref, without))


HEAD = """units si
atom_style granular
boundary m m m
region reg block -0.5 0.5 -0.5 0.5 0.0 1.0 units box
create_box 1 reg
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m4 all property/global coefficientFriction peratomtypepair 1 0.05
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.00001
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.015
fix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0
"""
STREAM = ("fix ins all insert/stream seed 32452867 distributiontemplate pdd1 nparticles 10 vel "
          "constant 0 0 -2 particlerate 1000 all_in yes insertion_face face extrude_length 0.3\n"
          "run 1\n")
# (name, body, LIGGGHTS's message, line of the error counted from the body's first)
BAD = [("not_planar", "fix face all mesh/surface/planar file wedge.stl type 1 scale 0.01\n",
        "Face defined as planar face is in fact not planar", 1),
       ("all_in_not_planar", "fix face all mesh/surface file face8.stl type 1\n" + STREAM,
        "using all_in yes requires you to use a fix mesh/surface/planar", 3),
       ("curvature", "fix face all mesh/surface/planar file face8.stl type 1 curvature 70\n",
        "0 < curvature <= 60 degrees required", 1)]


def update():
    deck = open(os.path.join(REF, "all_in.in")).read()
    fmt = '"%d %d' + " %.17g" * 10 + '"'
    deck = deck.replace("format float %.17g", "format " + fmt)
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp, deck)
        out = subprocess.run(["stdbuf", "-o0", "liggghts", "-in", "in.deck"], cwd=tmp,
                             capture_output=True, text=True, timeout=600)
        if out.returncode:
            sys.exit("liggghts failed:\n" + out.stdout[-2000:])
        open(os.path.join(REF, "all_in.liggghts.log"), "w").write(
            "".join(l for l in out.stdout.splitlines(True) if not l.startswith("Created")))
        for step in STEPS:
            src = os.path.join(tmp, "out.%d.dump" % step)
            dst = os.path.join(REF, "out.%d.liggghts.dump.gz" % step)
            with open(src, "rb") as fi, gzip.GzipFile(dst, "wb", mtime=0) as fo:
                fo.write(fi.read())
    print("references written to", REF)


def main():
    if "--update" in sys.argv:
        update()
        return 0
    check_deck()
    check_bad_decks(HEAD, BAD, "liggghts_planar_error_",
                    lambda tmp: stage(tmp, ""))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
