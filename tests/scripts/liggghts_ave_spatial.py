#!/usr/bin/env python3
"""liggghts_ave_spatial.py - fix ave/spatial (LIGGGHTS 3.8's, the LAMMPS 2013
command that fix ave/chunk replaced) against liggghts.

1. tests/reference/liggghts_ave_spatial/spatial.in (a stream of 400
   particles through a planar face onto a floor) runs in gravel; the three
   files `liggghts` wrote for it are committed (spatial.a1.txt .. a3.txt;
   --update rewrites them): z layers with vx vz density/mass, x-y pencils
   with norm sample and ave running, centred z layers inside a region with
   ave window 3, write_ts no and title1. gravel's files equal them byte for
   byte (LIGGGHTS's heads, step lines without the total count, %g rows).
2. On 2 MPI ranks the files equal one process's.
3. unfix removes the fix's own chunk compute (ID_spatial); the errors: ave
   running with a shrink-wrapped box (LIGGGHTS's "settings invalid with
   changing box size"), the std keyword, no dimension, unknown keywords.

Usage: liggghts_ave_spatial.py [--update]. One PASS/FAIL line per case."""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, check_bad_decks, report  # noqa: E402
from liggghts_stream import run_gravel as run_deck, run_gravel_ranks  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_ave_spatial")
FACE = os.path.join(ROOT, "tests", "reference", "liggghts_planar", "face8.stl")
DECK = open(os.path.join(REF, "spatial.in")).read()
FILES = ("a1", "a2", "a3")


def stage(tmp, text=DECK):
    shutil.copy(FACE, tmp)
    open(os.path.join(tmp, "in.deck"), "w").write(text)


def read(path):
    return open(path).read() if os.path.exists(path) else None


def update():
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp)
        subprocess.run(["liggghts", "-in", "in.deck"], cwd=tmp, capture_output=True, text=True,
                       timeout=600)
        for f in FILES:
            shutil.copy(os.path.join(tmp, f + ".txt"), os.path.join(REF, "spatial.%s.txt" % f))
        print("updated", REF)


def main():
    if "--update" in sys.argv:
        update()
        return
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp)
        out = run_deck(tmp, "in.deck")
        for f in FILES:
            mine, ref = read(os.path.join(tmp, f + ".txt")), read(os.path.join(REF, "spatial.%s.txt" % f))
            diff = next(((a, b) for a, b in zip((mine or "").split("\n"), ref.split("\n"))
                         if a != b), None)
            report(out.returncode == 0 and mine == ref and ref.count("\n") > 300,
                   "ave_spatial_%s_equal_liggghts" % f,
                   "first differing line: %s %s" % (diff, out.stdout[-300:]))
        mdir = os.path.join(tmp, "mpi")
        os.mkdir(mdir)
        stage(mdir)
        o = run_gravel_ranks(mdir, "in.deck")
        if o is None:
            report(False, "ave_spatial_2_ranks", "mpirun or bin/gravel-mpi missing")
        else:
            same = all(read(os.path.join(mdir, f + ".txt")) == read(os.path.join(tmp, f + ".txt"))
                       for f in FILES)
            report(o.returncode == 0 and same, "ave_spatial_2_ranks", o.stdout[-400:])
        # unfix takes the fix's chunk compute along: a new compute of that ID is accepted
        udir = os.path.join(tmp, "unfix")
        os.mkdir(udir)
        stage(udir, DECK.replace("run             1\nrun             30000\n",
                                 "run             1\nunfix           a1\n"
                                 "compute         a1_spatial all ke\nrun             10\n"))
        o = run_deck(udir, "in.deck")
        report(o.returncode == 0, "ave_spatial_unfix_drops_its_compute", o.stdout[-400:])
    head = DECK.split("fix             a1 all")[0]
    bad = [
        ("changing_box", "fix a all ave/spatial 100 5 1000 z lower 0.1 vz units box ave running\n"
         "run 1\n", "settings invalid with changing box size", 2),
        ("std", "fix a all ave/spatial 100 5 1000 z lower 0.1 vz std 1 2 s.txt\n",
         "keyword 'std' is not supported", 1),
        ("no_dim", "fix a all ave/spatial 100 5 1000 vz\n", "expects Nevery", 1),
        ("unknown", "fix a all ave/spatial 100 5 1000 z lower 0.1 vz bogus\n",
         "unknown value or keyword 'bogus'", 1),
    ]
    check_bad_decks(head.replace("boundary        f f f", "boundary        m m m"), bad,
                    "ave_spatial_error_", lambda t: stage(t, ""))
    sys.exit(1 if FAILURES else 0)


main()
