#!/usr/bin/env python3
"""liggghts_tracer.py - fix property/atom/tracer and compute
nparticles/tracer/region against LIGGGHTS 3.8.

1. tests/reference/liggghts_tracer/tracer.in (250 spheres fall onto a floor in
   a box periodic in x; a dirac tracer marks the upper atoms at step 2000, a
   heaviside tracer every atom passing a slab from step 1000; one compute
   counts and unmarks the first tracer's atoms in the lower region, another
   counts the second's without unmarking) runs in gravel; the thermo rows
   `liggghts` printed for it are committed (tracer.liggghts.log; --update
   rewrites it): the tracers' scalars (atoms newly marked) and the counts and
   masses equal LIGGGHTS's on all 41 rows, and every column, kinetic energy
   included, to 1e-7 through step 15000 (the settling pile is chaotic after).
2. `periodic x 0` and `periodic x 1` count only the atoms of that image: the
   last row's counts equal those of the final atoms (write_dump: z, ix) in the
   region. (LIGGGHTS's image flags follow its neighbor rebuilds, gravel's every
   step: those two columns are not compared with LIGGGHTS.)
3. Restart: the markers are kept (run 10000 + write_restart + read_restart +
   the fixes and computes again + run 10000 gives the uninterrupted rows).
4. Errors: no region_mark, no mark_step, an unknown marker_style, a tracer ID
   that is not a tracer, a non-periodic `periodic` dimension; on 2 MPI ranks
   the run stops naming the fix.

Usage: liggghts_tracer.py [--update]. One PASS/FAIL line per case."""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, check_bad_decks, report, thermo  # noqa: E402
from liggghts_stream import run_gravel, run_gravel_ranks  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_tracer")
DECK = open(os.path.join(REF, "tracer.in")).read()
NCOL = 14  # step atoms ke f_tr f_th cn[1..4] ck[1] ck[2] ck[4] ck0[1] ck1[1]
LOW = 0.075  # region low: z < LOW


def rows(text):
    return [r for r in thermo(text) if len(r) == NCOL]


def update():
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "tracer.in"), "w").write(DECK)
        out = subprocess.run(["liggghts", "-in", "tracer.in"], cwd=tmp, capture_output=True,
                             text=True, timeout=600)
        open(os.path.join(REF, "tracer.liggghts.log"), "w").write(out.stdout)
    print("updated", REF)


def main():
    if "--update" in sys.argv:
        update()
        return
    ref = rows(open(os.path.join(REF, "tracer.liggghts.log")).read())
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "tracer.in"), "w").write(
            DECK + "write_dump      all custom end.dump id z ix f_th modify sort id\n")
        out = run_gravel(tmp, "tracer.in")
        got = rows(out.stdout) if out.returncode == 0 else []
        counts = [(a[0], k, a[k], b[k]) for a, b in zip(got, ref) for k in range(3, 12)
                  if float(a[k]) != float(b[k])
                  and abs(float(a[k]) - float(b[k])) > 1e-7 * abs(float(b[k]))]
        early = [(a[0], k, a[k], b[k]) for a, b in zip(got, ref) if int(a[0]) <= 15000
                 for k in range(12)
                 if abs(float(a[k]) - float(b[k])) > 1e-7 * max(abs(float(b[k])), 1e-300)]
        marked = sum(float(r[3]) + float(r[4]) for r in ref)
        report(out.returncode == 0 and len(got) == len(ref) == 41 and not counts and not early
               and marked > 0 and any(float(r[6]) > 0 for r in ref),
               "tracer_rows_equal_liggghts",
               "%d/%d rows, counts %s, early %s %s" % (len(got), len(ref), counts[:3],
                                                      early[:3], out.stdout[-300:]))
        img = {0: 0, 1: 0}
        if out.returncode == 0:
            text = open(os.path.join(tmp, "end.dump")).read()
            for line in text.split("ITEM: ATOMS")[1].strip().split("\n")[1:]:
                _, z, ix, _ = line.split()
                if float(z) < LOW and int(ix) in img:
                    img[int(ix)] += 1
        last = got[-1] if got else ["0"] * NCOL
        report(img[0] > 0 and img[1] > 0 and float(last[12]) == img[0]
               and float(last[13]) == img[1], "tracer_periodic_image_counts",
               "dump: %s, columns %s" % (img, last[12:14]))
        # restart: the markers and the tracers' state carried over
        half = DECK.replace("run             20000",
                            "run             10000\nwrite_restart   tr.restart")
        tail = [l for l in DECK.split("\n") if l.startswith(("fix", "compute", "thermo",
                                                             "neighbor", "neigh_modify",
                                                             "timestep", "pair_coeff",
                                                             "region", "group"))]
        rest = ("atom_style      granular\nread_restart    tr.restart\n" + "\n".join(tail) +
                "\nrun             10000\n")
        open(os.path.join(tmp, "half.in"), "w").write(half)
        open(os.path.join(tmp, "rest.in"), "w").write(rest)
        o1 = run_gravel(tmp, "half.in")
        o2 = run_gravel(tmp, "rest.in")
        r2 = rows(o2.stdout) if o1.returncode == 0 and o2.returncode == 0 else []
        want = [r for r in got if int(r[0]) >= 10000]
        report(len(r2) == len(want) == 21 and all(
            a[2:] == b[2:] or (a[0] == "10000" and a[2:3] + a[5:] == b[2:3] + b[5:])
            for a, b in zip(r2, want)),
               "tracer_restart_continues",
               "%d rows against %d: %s\n%s" % (len(r2), len(want),
                                               next(((a, b) for a, b in zip(r2, want)
                                                     if a[3:] != b[3:]), None),
                                               (o1.stdout + o2.stdout)[-600:]))
        mdir = os.path.join(tmp, "mpi")
        os.mkdir(mdir)
        open(os.path.join(mdir, "tracer.in"), "w").write(DECK)
        o = run_gravel_ranks(mdir, "tracer.in")
        if o is None:
            report(False, "tracer_2_ranks_refused", "mpirun or bin/gravel-mpi missing")
        else:
            report(o.returncode != 0 and "fix tr (property/atom/tracer) cannot run on 2 MPI "
                   "ranks" in o.stdout + o.stderr, "tracer_2_ranks_refused",
                   (o.stdout + o.stderr)[-400:])
    head = DECK.split("fix             tr all")[0]
    bad = [
        ("no_region", "fix t all property/atom/tracer mark_step 10\n",
         "expecting keyword 'region_mark'", 1),
        ("no_step", "fix t all property/atom/tracer region_mark up\n",
         "expecting keyword 'mark_step'", 1),
        ("style", "fix t all property/atom/tracer region_mark up mark_step 1 marker_style box\n",
         "expecting 'heaviside' or 'dirac' after keyword 'marker_style'", 1),
        ("region", "fix t all property/atom/tracer region_mark nowhere mark_step 1\n",
         "region ID 'nowhere' does not exist", 1),
        ("not_tracer", "compute c all nparticles/tracer/region region_count low tracer m1\n"
         "thermo_style custom step c_c[1]\nrun 0\n", "need a tracer fix of type fix "
         "property/atom/tracer ('m1' is another style)", 3),
        ("periodic", "fix t all property/atom/tracer region_mark up mark_step 1\n"
         "compute c all nparticles/tracer/region region_count low tracer t periodic z 0\n",
         "using 'periodic' in a dimension which is not periodic (z)", 2),
    ]
    check_bad_decks(head, bad, "tracer_error_")
    sys.exit(1 if FAILURES else 0)


main()
