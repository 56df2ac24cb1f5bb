#!/usr/bin/env python3
"""lammps_fix_deposit.py - fix deposit as LAMMPS's (lmp 2021).

Spheres deposited one by one onto a wall/gran floor (gran/hooke/history,
gravity), run unchanged by `lmp` (one process) and bin/gravel: thermo
prints the atom count, ke and the fix's count every 200 steps, and a dump
of every atom's ID, type, position and velocity at the end. The same RanPark
stream places the same atoms: thermo and the dump equal lmp's to 1e-8
relative (1e-10 absolute). Cases: uniform points with `near` and velocity
ranges in lattice units; `global lo hi` above the highest atom; `local lo
hi delta` with `rate`, `target` and `id next`; `gaussian` in box units;
two runs in a row (the schedule continues); `attempt 1` in a crowded
region (fewer deposits, LAMMPS's warning). A restart written mid-way and
read back continues to the same dump; the fix's scalar (today's LAMMPS;
lmp 2021 has none) counts the deposits. On 2 and 3 MPI ranks
(bin/gravel-mpi) every case's end dump is byte-identical to one process's
(each rank draws every atom; its brick's owner keeps it; `near`, `global`
and `local` look at every rank's atoms). Then the errors. One line PASS/FAIL
per case; without `lmp` the comparisons FAIL naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_restart_continues, check_same_on_ranks,  # noqa: E402
                  close, dump_steps, expect_errors, folders, run, thermo_against_lmp)

HEAD = """units lj
atom_style sphere
comm_modify vel yes
boundary p p f
lattice sc 1.0
region box block 0 6 0 6 0 12
create_box 2 box
region dep block 0 6 0 6 8 10
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
fix g all gravity 1.0 vector 0 0 -1
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 NULL
timestep 0.002
"""
TAIL = """thermo_style custom step atoms ke
thermo_modify format float %.15g norm no
thermo 200
run 2000
dump e all custom 1 end.dump id type x y z vx vy vz
dump_modify e sort id format float %.15g
run 0
"""
CASES = {
    "uniform_near_lattice": "fix d all deposit 30 1 50 12345 region dep near 1.0 vz -1.0 -0.5 "
                            "vx -0.1 0.1\n",
    "global": "fix d all deposit 30 2 150 777 region dep near 1.0 global 0.6 1.0 vz -3 -3\n",
    "local_rate_target_idnext": "fix d all deposit 25 1 150 4242 region dep near 1.0 "
                                "local 0.6 1.0 2.0 rate -0.5 target 3 3 0 vz -3 -3 id next\n",
    "gaussian_box": "fix d all deposit 20 1 80 99 region dep near 1.0 gaussian 3 3 9 1.5 "
                    "units box\n",
    "crowded_attempt1": "region tiny block 2 3 2 3 8 9\n"
                        "fix d all deposit 30 1 20 5 region tiny near 2.0 attempt 1\n",
}
TWO_RUNS = HEAD + "fix d all deposit 30 1 50 12345 region dep near 1.0 vz -1 -0.5\n" + \
    TAIL.replace("run 2000\n", "run 1100\nrun 900\n")


def compare(name, deck, nrows, parent):
    ok, got, _, g, lm = thermo_against_lmp("deposit_" + name, deck, 3, nrows, parent, 1e-8, 1e-10)
    if ok:
        a, b = dump_steps(os.path.join(g, "end.dump")), dump_steps(os.path.join(lm, "end.dump"))
        same = a.keys() == b.keys() and all(
            a[s].keys() == b[s].keys() and all(close(x, y, 1e-8, 1e-10) for i in a[s]
                                               for x, y in zip(a[s][i], b[s][i]))
            for s in a)
        n = len(next(iter(a.values()), {}))
        check("deposit_" + name + "_atoms", same and n > 0, "%d atoms" % n)
    if name == "two_runs":  # f_ID (today's LAMMPS; lmp 2021 has no scalar): the count
        rc, out = run([GRAVEL], deck.replace("step atoms ke", "step atoms ke f_d"), parent)
        rows = [line.split() for line in out.splitlines() if line.split()[:1] == ["2000"]]
        check("deposit_scalar_counts", rc == 0 and len(rows) >= 1 and
              float(rows[-1][3]) == float(rows[-1][1]) == 30, out[-300:])


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name, fix in CASES.items():
            compare(name, HEAD + fix + TAIL, 11 + 1, tmp)
        compare("two_runs", TWO_RUNS, 14, tmp)
        for name, fix in CASES.items():  # on MPI ranks: the same atoms, byte for byte
            deck = (HEAD + fix + TAIL).replace("%.15g", "%.17g")
            one, = folders(tmp, "one_" + name)
            run([GRAVEL], deck, one)
            for np in (2, 3):
                d, = folders(tmp, "np%d_%s" % (np, name))
                check_same_on_ranks("deposit_%s_%d_ranks" % (name, np), np, deck, d, one,
                                    ["end.dump"])
        check_restart_continues(
            "deposit_restart", tmp,
            HEAD + "fix d all deposit 30 1 50 12345 region dep near 1.0 vz -1 -0.5\n",
            "region dep block 0 6 0 6 8 10\npair_style gran/hooke/history 2000.0 NULL 50.0 "
            "NULL 0.5 0\npair_coeff * *\nfix 1 all nve/sphere\nfix g all gravity 1.0 vector "
            "0 0 -1\nfix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 "
            "NULL\nfix d all deposit 30 1 50 12345 region dep near 1.0 vz -1 -0.5\n"
            "timestep 0.002\n",
            "dump d all custom %d out.dump id x y z vx vy vz\n"
            "dump_modify d sort id format float %%.17g\n", 600)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        expect_errors({
            "err_no_region": ("fix d all deposit 10 1 10 5\n", "must specify a region"),
            "err_type": ("fix d all deposit 10 3 10 5 region dep\n",
                         "invalid atom type 3 in fix deposit"),
            "err_mol": ("fix d all deposit 10 1 10 5 region dep mol m\n",
                        "keyword mol is not supported"),
            "err_outside": ("region out block 0 6 0 6 10 14\n"
                            "fix d all deposit 10 1 10 5 region out\n",
                            "deposition region extends outside simulation box"),
            "err_seed": ("fix d all deposit 10 1 10 0 region dep\n", "seed must be > 0"),
        }, HEAD, err)
        rc, out = run([GRAVEL], HEAD + CASES["crowded_attempt1"] + TAIL, err)
        check("deposit_warns_unsuccessful", rc == 0 and
              "one or more particle depositions were unsuccessful" in out, out[-300:])


main()
