#!/usr/bin/env python3
"""lammps_group_group.py - compute group/group as LAMMPS's (lmp 2021): the
pair force one group exerts on another and their pair energy.

The falling bed (96 spheres, gran/hooke/history) in a walled box (boundary
f f f, wall/gran planes on every side), run unchanged by `lmp` and
bin/gravel for 1500 steps: group/group of the upper half on the rest, the
reverse, and all on all (its two orientations cancel: zero force), printed
by thermo (extensive: divided by the atom count, lj's thermo_modify norm
yes) at every 250 steps; the same with thermo_modify norm no and molecule
inter / intra on a bed whose atoms carry molecule IDs. Every row equals
lmp's to 1e-9 (the granular styles' Pair::single: the normal contact force
only, energy 0). Newton's third law: group A on B is minus B on A at every
row, exactly. In a box periodic in x and y, one process and 2 MPI ranks
print the same rows (LAMMPS differs there by its ghost atoms' velocities:
see doc/styles/compute_group_group.md). Then the errors. One line
PASS/FAIL per case; without `lmp` the comparisons FAIL naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check, check_thermo_same_on_ranks, expect_errors, falling_bed,  # noqa: E402
                  thermo_against_lmp)

WALLS = ("fix wx all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 xplane 0.0 4.0\n"
         "fix wy all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 yplane 0.0 4.0\n")
TAIL = """group bottom subtract all top
compute gg top group/group bottom
compute gb bottom group/group top
compute ga all group/group all
thermo_style custom step c_gg c_gg[1] c_gg[2] c_gg[3] c_gb[1] c_gb[2] c_gb[3] c_ga[3]
thermo_modify format float %.17g
thermo 250
run 1500
"""
PERIODIC = falling_bed() + TAIL
WALLED = PERIODIC.replace("boundary p p f", "boundary f f f").replace(
    "fix g all gravity", WALLS + "fix g all gravity")
MOL = WALLED.replace("group bottom subtract all top\n", """group bottom subtract all top
set atom 1*40 mol 1
set atom 41*70 mol 2
set atom 71*96 mol 3
thermo_modify norm no
""").replace("atom_style sphere", "atom_style hybrid sphere molecular").replace(
    "compute gb bottom group/group top", "compute gb bottom group/group top molecule intra").replace(
    "compute gg top group/group bottom", "compute gg top group/group bottom molecule inter")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        ok, got, _, _, _ = thermo_against_lmp("group_group_equal_lmp", WALLED, 9, 7, tmp,
                                              1e-9, 1e-14)
        nz = sum(1 for r in got if r[4] != 0)
        newton = all(r[2 + d] == -r[5 + d] for r in got for d in range(3))
        check("group_group_newton_third_law", len(got) == 7 and nz >= 5 and newton and
              all(r[8] == 0 for r in got), "rows %s" % got[:3])
        thermo_against_lmp("group_group_molecule_equal_lmp", MOL, 9, 7, tmp, 1e-9, 1e-14)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_thermo_same_on_ranks("group_group_2_ranks", 2, PERIODIC, 9, err)
        head = falling_bed()
        expect_errors({
            "err_group": ("compute c all group/group nope\n", "group 'nope' does not exist"),
            "err_kspace": ("compute c all group/group top kspace yes\n", "kspace yes"),
            "err_molecule": ("compute c all group/group top molecule inter\n",
                             "needs molecule IDs"),
            "err_keyword": ("compute c all group/group top bogus 1\n", "unknown keyword"),
            "err_nopair": ("pair_style none\ncompute c all group/group top\n"
                           "thermo_style custom step c_c\nrun 0\n", "needs a pair style"),
        }, head, err)


main()
