#!/usr/bin/env python3
"""liggghts_buoyancy.py - fix buoyancy against LIGGGHTS 3.8.

1. tests/reference/liggghts_buoyancy/buoyancy.in (400 particles of density
   2500 streaming through a planar face, falling into a fluid of density
   1000 below z = 0.3 and settling on the floor) runs in gravel; the thermo
   rows `liggghts` printed for it are committed (buoyancy.liggghts.log;
   --update rewrites it): every row (step, atoms, KinEng, the buoyancy force
   f_b[1] and f_b[3]) equal to LIGGGHTS's printed digits (the partly
   immersed caps of the particles crossing the surface included).
2. Archimedes: at the end f_b[3] equals rho_fluid g times the immersed
   volume of every sphere, computed from the dumped positions with the cap
   formula pi h^2 (3r - h) / 3 (the particles still above the surface or
   crossing it included), to 1e-7.
3. On 2 MPI ranks the rows equal one process's.
4. Errors as LIGGGHTS's: no dim, no density, level <= 0, gravity across dim,
   two fix gravity; region is refused (not supported).

Usage: liggghts_buoyancy.py [--update]. One PASS/FAIL line per case."""
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, check_bad_decks, report, thermo  # noqa: E402
from liggghts_stream import run_gravel as run_deck, run_gravel_ranks  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_buoyancy")
FACE = os.path.join(ROOT, "tests", "reference", "liggghts_planar", "face8.stl")
DECK = open(os.path.join(REF, "buoyancy.in")).read()
NCOL = 5


def stage(tmp, text=DECK):
    shutil.copy(FACE, tmp)
    open(os.path.join(tmp, "in.deck"), "w").write(text)


def rows(text):
    return [r for r in thermo(text) if len(r) == NCOL]


def update():
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp)
        out = subprocess.run(["liggghts", "-in", "in.deck"], cwd=tmp, capture_output=True,
                             text=True, timeout=600)
        open(os.path.join(REF, "buoyancy.liggghts.log"), "w").write(out.stdout)
        print("updated", REF)


def main():
    if "--update" in sys.argv:
        update()
        return
    ref = rows(open(os.path.join(REF, "buoyancy.liggghts.log")).read())
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp, DECK + "write_dump      all custom end.dump id radius z modify format float %.17g\n")
        out = run_deck(tmp, "in.deck")
        got = rows(out.stdout) if out.returncode == 0 else []
        bad = [(a[0], k, a[k], b[k]) for a, b in zip(got, ref) for k in range(NCOL)
               if abs(float(a[k]) - float(b[k])) > 1e-7 * max(abs(float(b[k])), 1e-300)]
        report(out.returncode == 0 and len(got) == len(ref) == 34 and not bad,
               "buoyancy_thermo_equal_liggghts",
               "%d/%d rows, %s %s" % (len(got), len(ref), bad[:4], out.stdout[-300:]))
        # Archimedes at the end: rho g times the immersed volume of every sphere,
        # from the dumped positions with the cap formula pi h^2 (3r - h) / 3
        vol, partial = 0.0, 0
        if out.returncode == 0:
            lines = open(os.path.join(tmp, "end.dump")).read().split("ITEM: ATOMS")[1].split("\n")[1:]
            for ln in lines:
                if ln.strip():
                    _, r, z = map(float, ln.split())
                    wet = min(max(0.3 - (z - r), 0.0), 2 * r)  # immersed height
                    vol += math.pi * wet * wet * (3 * r - wet) / 3
                    partial += 0 < wet < 2 * r
        want = 1000 * 9.81 * vol
        fz = float(got[-1][4]) if got else 0.0
        report(abs(fz - want) <= 1e-7 * want, "buoyancy_archimedes",
               "f_b[3] %.10g against rho g V %.10g" % (fz, want))
        mdir = os.path.join(tmp, "mpi")
        os.mkdir(mdir)
        stage(mdir)
        o = run_gravel_ranks(mdir, "in.deck")
        if o is None:
            report(False, "buoyancy_2_ranks", "mpirun or bin/gravel-mpi missing")
        else:
            report(o.returncode == 0 and rows(o.stdout) == got, "buoyancy_2_ranks",
                   o.stdout[-400:])
    head = DECK.split("fix             b all buoyancy")[0]
    bad = [
        ("no_dim", "fix b all buoyancy density 1000 level 0.3\n", "you have to specify 'dim'", 1),
        ("no_density", "fix b all buoyancy level 0.3 dim z\n", "you have to specify 'density'",
         1),
        ("level", "fix b all buoyancy density 1000 level 0 dim z\n", "'level' > 0 required", 1),
        ("across", "fix b all buoyancy density 1000 level 0.3 dim x\nrun 1\n",
         "fix gravity direction is not equal to 'dim'", 2),
        ("two_gravity", "fix g2 all gravity 1.0 vector 0 0 -1\n"
         "fix b all buoyancy density 1000 level 0.3 dim z\nrun 1\n", "need exactly one fix gravity",
         3),
        ("region", "fix b all buoyancy density 1000 level 0.3 dim z region reg\n",
         "'region' is not supported", 1),
    ]
    check_bad_decks(head, bad, "buoyancy_error_", lambda t: stage(t, ""))
    sys.exit(1 if FAILURES else 0)


main()
