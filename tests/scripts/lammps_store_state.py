#!/usr/bin/env python3
"""lammps_store_state.py - fix store/state as LAMMPS's, and per-atom fix
outputs inside atom-style variables.

The falling bed of the lmp comparisons (96 spheres onto a wall/gran floor),
1500 steps, run unchanged by `lmp` (LAMMPS 2021, one process) and
bin/gravel: store/state 0 of xu yu zu vx type on all (kept from the fix's
definition), store/state 300 of zu (from the group's centre of mass: `com
yes`), fz, compute ke/atom and an atom-style variable on the upper half,
and an atom-style variable z - f_s0[3] (the fall since the start) reading
the first. A dump every 300 steps of them agrees with lmp's to 1e-8 of each
column's largest value. A run continued from a restart file at step 750
equals the uninterrupted one. On 2 and 3 MPI ranks (bin/gravel-mpi) the dump
(17 digits) is byte-identical to one process's. Then the errors. One line PASS/FAIL per case;
without `lmp` the comparison FAILs naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_restart_continues, check_same_on_ranks,  # noqa: E402
                  dump_steps, expect_errors, falling_bed, folders, run)

REL = 1e-8
HEAD = falling_bed()
FIXES = """compute k all ke/atom
variable sp atom sqrt(vx*vx+vy*vy+vz*vz)
fix s0 all store/state 0 xu yu zu vx type
fix s1 top store/state 300 zu fz c_k v_sp com yes
variable dz atom z-f_s0[3]
"""
DUMP = """dump 1 all custom 300 out.dump id f_s0[1] f_s0[3] f_s0[4] f_s0[5] f_s1[1] f_s1[2] &
     f_s1[3] f_s1[4] v_dz
dump_modify 1 sort id format float %.15g
"""
DECK = HEAD + FIXES + DUMP + "run 1500\n"


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir, edir = folders(tmp, "g", "l", "errors")
        rc, gout = run([GRAVEL], DECK, gdir)
        gs = dump_steps(os.path.join(gdir, "out.dump")) if rc == 0 else {}
        check("store_state_run", rc == 0 and sorted(gs) == [0, 300, 600, 900, 1200, 1500],
              "exit %d: %s" % (rc, gout[-600:]))
        if shutil.which("lmp") is None:
            check("store_state_match_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            ls = dump_steps(os.path.join(ldir, "out.dump")) if rc == 0 else {}
            bad = []
            for st, atoms in ls.items():
                ncol = len(next(iter(atoms.values())))
                scale = [max(abs(r[k]) for r in atoms.values()) for k in range(ncol)]
                for i, row in atoms.items():
                    got = gs.get(st, {}).get(i, [float("nan")] * ncol)
                    bad += [(st, i, k, a, b) for k, (a, b) in enumerate(zip(got, row))
                            if not abs(a - b) <= REL * scale[k]]
            check("store_state_match_lammps", rc == 0 and sorted(ls) == sorted(gs) and not bad,
                  "lmp exit %d, differences %s" % (rc, bad[:3]))
        # a restart at step 750 continues exactly
        check_restart_continues("store_state_restart_continues", tmp, HEAD + FIXES,
                                HEAD[HEAD.index("fix 1"):] + FIXES,
                                DUMP.replace("300", "%d").replace("%.15g", "%%.15g"), 750)
        # on MPI ranks: every atom's stored values on every rank
        exact = DECK.replace("%.15g", "%.17g")
        one, = folders(tmp, "ranks_one")
        run([GRAVEL], exact, one)
        for np in (2, 3):
            d, = folders(tmp, "ranks%d" % np)
            check_same_on_ranks("store_state_%d_ranks" % np, np, exact, d, one, ["out.dump"])
        expect_errors({
            "store_state_args": ("fix s all store/state 0\n", "ERROR: fix: fix store/state needs N "
                                 "and at least one input"),
            "store_state_n": ("fix s all store/state -1 x\n", "fix store/state: N must be >= 0"),
            "store_state_input": ("fix s all store/state 0 q\n", "fix store/state: invalid value "
                                  "'q'"),
            "store_state_com": ("fix s all store/state 0 xu com maybe\n", "com"),
            "store_state_variable": ("variable e equal 1\nfix s all store/state 0 v_e\nrun 0\n",
                                     "fix store/state s: variable 'e' is not atom-style"),
        }, HEAD, edir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
