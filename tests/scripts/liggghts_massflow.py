#!/usr/bin/env python3
"""liggghts_massflow.py - fix massflow/mesh against LIGGGHTS 3.8.

1. tests/reference/liggghts_massflow/massflow.in (the insert/stream deck of
   liggghts_planar: 400 particles through a planar face at z = 0.6, falling
   through an outlet face at z = 0.3 onto a floor, some rebounding up
   through it) runs in gravel; what `liggghts` wrote for the same deck is
   committed (massflow.liggghts.log, massflow.liggghts.txt; --update
   rewrites them):
   - every thermo row: step, atoms and the massflow columns (mass and count
     through the face, the mass and particle rates since the last output,
     count multiple downwards, count multiple upwards: a rebound crosses the
     face the other way) equal to LIGGGHTS's printed digits; KinEng to 1e-6
     relative up to step 40000 (before the floor's chaos);
   - the file of counted particles (ID, time, diameter, position, half-step
     velocity, LIGGGHTS's %4.4g) line for line, sorted by ID (LIGGGHTS
     writes a step's particles in its list order).
2. The same deck written to a restart file at step 30001 and continued from
   it (every fix again: an exact continuation) prints the uninterrupted
   run's rows, every column (but the rates of the first row after the
   split, whose window the extra output at 30001 restarted), and the same
   file (the sums, the rate's clock and every particle's counter are in the
   restart file).
3. On 2 MPI ranks (bin/gravel-mpi), over the first 25000 steps (the ranks
   gather every atom every step: slow), the thermo rows and the file equal
   one process's.
4. Errors as LIGGGHTS's: vec_side in the face's plane, a face that is not
   planar, a missing mesh or vec_side, unknown keywords; delete_atoms yes
   and point_at_outlet are refused (not supported).

Usage: liggghts_massflow.py [--update]. One PASS/FAIL line per case."""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, check_bad_decks, report, thermo  # noqa: E402
from liggghts_stream import run_gravel as run_deck, run_gravel_ranks  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_massflow")
FACE = os.path.join(ROOT, "tests", "reference", "liggghts_planar", "face8.stl")
WEDGE = os.path.join(ROOT, "tests", "reference", "liggghts_stream", "wedge.stl")
DECK = open(os.path.join(REF, "massflow.in")).read()
NCOL = 10
# the deck after its restart file: every fix again, in the same order (an
# exact continuation), the box, atoms and groups from the file
DROP = ("atom_style", "boundary", "units", "region", "create_box", "group", "run")
REST = "".join(ln + "\n" for ln in DECK.split("\n")
               if ln and not ln.startswith("#") and not ln.startswith(DROP)).replace(
    "communicate     single vel yes\n", "communicate     single vel yes\n"
    "read_restart    mf.restart\n").replace("file mf.txt", "append mf.txt") + "run 30000\n"


def stage(tmp, text=DECK):
    shutil.copy(FACE, tmp)
    shutil.copy(WEDGE, tmp)
    open(os.path.join(tmp, "in.deck"), "w").write(text)


def rows(text):
    return [r for r in thermo(text) if len(r) == NCOL]


def sorted_lines(path):
    with open(path) as fh:
        return sorted((ln for ln in fh if not ln.startswith("#")),
                      key=lambda ln: int(ln.split()[0]))


def close(a, b, rel):
    return abs(float(a) - float(b)) <= rel * max(abs(float(a)), abs(float(b)), 1e-300)


def update():
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp)
        out = subprocess.run(["liggghts", "-in", "in.deck"], cwd=tmp, capture_output=True,
                             text=True, timeout=600)
        open(os.path.join(REF, "massflow.liggghts.log"), "w").write(out.stdout)
        shutil.copy(os.path.join(tmp, "mf.txt"), os.path.join(REF, "massflow.liggghts.txt"))
        print("updated", REF)


def main():
    if "--update" in sys.argv:
        update()
        return
    ref = rows(open(os.path.join(REF, "massflow.liggghts.log")).read())
    ref_lines = sorted_lines(os.path.join(REF, "massflow.liggghts.txt"))
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp)
        out = run_deck(tmp, "in.deck")
        got = rows(out.stdout) if out.returncode == 0 else []
        bad = [(a[0], k, a[k], b[k]) for a, b in zip(got, ref) for k in (0, 1, 3, 4, 5, 6, 7, 8, 9)
               if not close(a[k], b[k], 1e-7)]
        bad += [(a[0], "ke", a[2], b[2]) for a, b in zip(got, ref)
                if int(a[0]) <= 40000 and not close(a[2], b[2], 1e-6)]
        report(out.returncode == 0 and len(got) == len(ref) == 64 and not bad,
               "massflow_thermo_equal_liggghts",
               "%d/%d rows, %s %s" % (len(got), len(ref), bad[:4], out.stderr[-300:]))
        last = got[-1] if got else []
        report(len(last) == NCOL and last[4] == "347" and last[7] == "347" and last[8] == "7",
               "massflow_counts", "last row %s" % last)
        mine = sorted_lines(os.path.join(tmp, "mf.txt")) if out.returncode == 0 else []
        report(mine == ref_lines and len(mine) == 347, "massflow_file_equal_liggghts",
               "%d/%d lines, first differing: %s" % (
                   len(mine), len(ref_lines),
                   next(((a, b) for a, b in zip(mine, ref_lines) if a != b), None)))
        # a restart at 30001 continues the uninterrupted run
        half = DECK.replace("run             60000", "run             30000\n"
                            "write_restart   mf.restart")
        rdir = os.path.join(tmp, "restart")
        os.mkdir(rdir)
        stage(rdir, half)
        o1 = run_deck(rdir, "in.deck")
        open(os.path.join(rdir, "in.rest"), "w").write(REST)
        o2 = run_deck(rdir, "in.rest")
        r2 = rows(o2.stdout) if o2.returncode == 0 else []
        # the uninterrupted run's rows, all but the rates of the first row after
        # 30001 (the split run printed 30001 too, which starts a rate window)
        want = [r for r in got if int(r[0]) > 30001]
        bad = [(a, b) for a, b in zip(r2[1:], want)
               if (a != b if a[0] != "31000" else a[:5] + a[7:] != b[:5] + b[7:])]
        report(o1.returncode == 0 and o2.returncode == 0 and len(r2) == 32 and
               len(want) == 31 and not bad and
               sorted_lines(os.path.join(rdir, "mf.txt")) == mine,
               "massflow_restart_continues",
               "%d rows, %s %s %s" % (len(r2), bad[:2], o1.stdout[-200:], o2.stdout[-400:]))
        # 2 MPI ranks
        # the ranks gather every atom every step (slow): the first 25000 steps
        mdir = os.path.join(tmp, "mpi")
        os.mkdir(mdir)
        stage(mdir, DECK.replace("run             60000", "run             25000"))
        o = run_gravel_ranks(mdir, "in.deck")
        if o is None:
            report(False, "massflow_2_ranks", "mpirun or bin/gravel-mpi missing")
        else:
            rm = rows(o.stdout) if o.returncode == 0 else []
            first = [r[:2] + r[3:] for r in got if int(r[0]) <= 25000]
            lines = sorted_lines(os.path.join(mdir, "mf.txt"))
            # the file: the counted particles of one process's run up to step 25001
            ok = (o.returncode == 0 and len(first) == 28 and
                  [r[:2] + r[3:] for r in rm if int(r[0]) <= 25000] == first and
                  set(lines) <= set(mine) and len(lines) == int(rm[-1][4]))
            report(ok, "massflow_2_ranks", "%d rows, %d lines of %d: %s" % (
                len(rm), len(lines), len(mine), o.stdout[-400:]))
    head = DECK.split("fix             mf all")[0]
    bad = [
        ("in_plane", "fix m all massflow/mesh mesh outlet vec_side 1 0 0\n",
         "need to change 'vec_side'", 1),
        ("not_planar", "fix w all mesh/surface file wedge.stl type 1 scale 0.01\n"
         "fix m all massflow/mesh mesh w vec_side 0 0 1\nrun 1\n", "not planar", 3),
        ("no_mesh", "fix m all massflow/mesh vec_side 0 0 1\n", "expecting keyword 'mesh'", 1),
        ("no_side", "fix m all massflow/mesh mesh outlet\n", "expecting keyword 'vec_side'", 1),
        ("unknown", "fix m all massflow/mesh mesh outlet vec_side 0 0 1 bogus 1\n",
         "unknown keyword", 1),
        ("delete", "fix m all massflow/mesh mesh outlet vec_side 0 0 1 delete_atoms yes\n",
         "delete_atoms yes is not supported", 1),
        ("outlet", "fix m all massflow/mesh mesh outlet point_at_outlet 0 0 0\n",
         "is not supported", 1),
    ]
    check_bad_decks(head, bad, "massflow_error_", lambda t: stage(t, ""))
    sys.exit(1 if FAILURES else 0)


main()
