#!/usr/bin/env python3
"""lammps_chunk_moments.py - compute gyration/chunk (and its tensor),
inertia/chunk, angmom/chunk, torque/chunk and omega/chunk as LAMMPS's (lmp
2021).

The falling bed of tests/scripts/lib/peer.py (96 spheres on a wall/gran
floor, launched at temperature 3) binned along z (chunk/atom bin/1d, 2.0
wide: 4 chunks) and its upper half in a second group, run unchanged by `lmp`
and bin/gravel for 1000 steps: fix ave/time writes every 200 steps, in
vector mode, every chunk's values; the files' numbers agree to 1e-8 relative
(1e-10 absolute: torques of contact forces cancel). On 2 MPI ranks the file
is byte-identical to one process's. A chunk of one atom has the inertia of
the round-off between its centre of mass and the atom's position (1e-31 in
lmp) and an omega of round-off over round-off (1e15 in lmp, exactly 0 in
gravel, whose centre of mass of one atom is its position): those numbers are
not compared. Two atoms turning about their centre (a singular inertia,
solved in its principal axes) get the exact omega and angular momentum.
Then the errors. One line PASS/FAIL per
case; without `lmp` the comparison FAILs naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_same_on_ranks, close, expect_errors,  # noqa: E402
                  falling_bed, file_numbers, run, run_with_lmp)

DECK = falling_bed() + """compute bins all chunk/atom bin/1d z lower 2.0 units box
compute gy all gyration/chunk bins
compute gt all gyration/chunk bins tensor
compute in all inertia/chunk bins
compute am top angmom/chunk bins
compute tq all torque/chunk bins
compute om all omega/chunk bins
fix a all ave/time 200 1 200 c_gy c_gt[*] c_in[*] c_am[*] c_tq[*] c_om[*] &
  mode vector file moments.txt format " %.15g"
thermo 500
run 1000
"""
# two atoms 1 apart turning about their centre at 0.3 along y (omega 0.6 along
# z: the singular inertia of a pair, solved in its principal axes as today's
# LAMMPS does) and their angular momentum
TWO = """units lj
atom_style sphere
region box block -2 2 -2 2 -2 2
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 1 0 0
set group all diameter 0.5 density 1.0
set group all mass 1.0
velocity all set 0 0.3 0 units box
group a id 1
velocity a set 0 -0.3 0 units box
compute one all chunk/atom bin/1d z lower 4.0 units box
compute om all omega/chunk one
compute am all angmom/chunk one
thermo_style custom step c_om[1][1] c_om[1][2] c_om[1][3] c_am[1][1] c_am[1][2] c_am[1][3]
run 0
"""


def main():
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, lout, g, lm = run_with_lmp(DECK, tmp, "moments")
        a = file_numbers(os.path.join(g, "moments.txt")) if rc == 0 else []
        if lout is None:
            check("chunk_moments_equal_lmp", False, "lmp (Debian package lammps) is not installed")
        else:
            b = file_numbers(os.path.join(lm, "moments.txt"))
            # a one-atom chunk's omega is round-off over round-off in lmp (see the top)
            singular = [(x, y) for x, y in zip(a, b) if abs(y) > 1e6]
            bad = [(x, y) for x, y in zip(a, b) if abs(y) <= 1e6 and not close(x, y, 1e-8, 1e-10)]
            check("chunk_moments_equal_lmp", len(a) == len(b) > 400 and not bad and
                  len(singular) <= 12, "%d / %d numbers, %d differ %s, %d singular: %s" %
                  (len(a), len(b), len(bad), bad[:3], len(singular),
                   (out if rc else lout)[-300:]))
        check("chunk_moments_not_trivial", rc == 0 and sum(abs(x) > 1e-6 for x in a) > 200,
              out[-300:])
        two = os.path.join(tmp, "two")
        os.mkdir(two)
        rc, out = run([GRAVEL], TWO, two)
        rows = [ln.split() for ln in out.splitlines() if ln.split()[:1] == ["0"]]
        check("omega_chunk_two_atoms", rc == 0 and rows and
              [float(w) for w in rows[0][1:]] == [0.0, 0.0, 0.6, 0.0, 0.0, 0.3],
              "%s: %s" % (rows, out[-300:]))
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_same_on_ranks("chunk_moments_2_ranks", 2, DECK, err, g, ["moments.txt"])
        head = falling_bed() + "compute bins all chunk/atom bin/1d z lower 1.0 units box\n"
        expect_errors({
            "err_gyration_keyword": ("compute r all gyration/chunk bins tensors\n",
                                     "unknown keyword 'tensors'"),
            "err_omega_args": ("compute o all omega/chunk\n",
                               "expects the chunk/atom compute ID, got 0"),
            "err_chunk": ("compute t all torque/chunk nobins\n", "nobins"),
        }, head, err)


main()
