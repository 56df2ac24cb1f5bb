#!/usr/bin/env python3
"""lammps_fix_rigid.py - fix rigid (LAMMPS's, not rigid/small) as lmp 2021.

Three clumps of overlapping spheres (molecule IDs 1..3: three, two and
four spheres) and four free spheres thrown onto a wall/gran floor with gran/hooke/history,
intra-clump pairs excluded, run unchanged by `lmp` and bin/gravel for 3000
steps with fix rigid in each body style: `molecule`, `single` (one clump's
atoms as the fix's group), `group 2 ...` (two clumps by group), and
`molecule` with `force`/`torque` flags holding components of some bodies.
thermo prints ke, the fix's scalar (the bodies' temperature) and elements
of its array (xcm, vcm, fcm, torque, image of two bodies): equal to 1e-8
relative (1e-10 absolute) every 250 steps; on 2 MPI ranks every case's rows
equal one process's to 17 digits. Then the errors. One line
PASS/FAIL per case; without `lmp` the comparisons FAIL naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import check_thermo_same_on_ranks, expect_errors, thermo_against_lmp  # noqa: E402

HEAD = """units lj
atom_style sphere
atom_modify map array
comm_modify vel yes
boundary p p f
region box block 0 10 0 10 0 12
create_box 1 box
fix pm all property/atom mol
create_atoms 1 single 2.0 2.0 3.0 units box
create_atoms 1 single 2.7 2.0 3.0 units box
create_atoms 1 single 2.3 2.6 3.2 units box
create_atoms 1 single 6.0 5.0 5.0 units box
create_atoms 1 single 6.0 5.8 5.0 units box
create_atoms 1 single 4.0 7.0 7.0 units box
create_atoms 1 single 4.7 7.0 7.0 units box
create_atoms 1 single 4.0 7.7 7.2 units box
create_atoms 1 single 4.3 7.3 7.8 units box
create_atoms 1 single 8.0 2.0 2.0 units box
create_atoms 1 single 8.0 8.0 4.0 units box
create_atoms 1 single 1.0 8.0 6.0 units box
create_atoms 1 single 8.5 5.0 8.0 units box
set atom 1*3 mol 1
set atom 4*5 mol 2
set atom 6*9 mol 3
set group all diameter 1.0 density 1.0
group c1 molecule 1
group c2 molecule 2
group c3 molecule 3
group c23 union c2 c3
group bodies union c1 c2 c3
group free id 10:13
velocity all set 0.3 -0.2 -1.0 units box
neigh_modify exclude molecule/intra all
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 NULL
fix g all gravity 1.0 vector 0 0 -1
timestep 0.001
"""
TAIL = """thermo_style custom step ke f_rb f_rb[1][3] f_rb[1][4] f_rb[1][9] f_rb[1][12] {more}
thermo_modify format float %.15g norm no
thermo 250
run 3000
"""
CASES = {
    "molecule": ("fix rb bodies rigid molecule\nfix n free nve/sphere\n",
                 "f_rb[3][1] f_rb[3][5] f_rb[3][10] f_rb[3][15]"),
    "single": ("fix rb c1 rigid single\nfix n c23 nve/sphere\nfix n2 free nve/sphere\n",
               "f_rb[1][14]"),
    "group": ("fix rb c23 rigid group 2 c2 c3\nfix n c1 nve/sphere\nfix n2 free nve/sphere\n",
              "f_rb[2][1] f_rb[2][6] f_rb[2][11]"),
    "force_torque_flags": ("fix rb bodies rigid molecule force 1 off on on torque 2*3 on off "
                           "on force 3 on on on\nfix n free nve/sphere\n",
                           "f_rb[2][4] f_rb[3][11] f_rb[3][12]"),
}


def compare(name, parent):
    fix, more = CASES[name]
    deck = HEAD + fix + TAIL.format(more=more)
    thermo_against_lmp("rigid_" + name, deck, 7 + len(more.split()), 13, parent, 1e-8, 1e-10)
    ranks = os.path.join(parent, "ranks_" + name)
    os.mkdir(ranks)
    check_thermo_same_on_ranks("rigid_%s_2_ranks" % name, 2, deck.replace("%.15g", "%.17g"),
                               7 + len(more.split()), ranks)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name in CASES:
            compare(name, tmp)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        expect_errors({
            "err_style": ("fix rb all rigid clump\n", "unknown fix rigid body style 'clump'"),
            "err_group_twice": ("fix rb all rigid group 2 c1 bodies\n",
                                "one or more atoms belong to multiple rigid bodies"),
            "err_group_missing": ("fix rb all rigid group 1 nope\n",
                                  "could not find fix rigid group ID nope"),
            "err_body_range": ("fix rb bodies rigid molecule force 4 on on on\n",
                               "fix rigid body range '4' is outside 1..3"),
            "err_keyword": ("fix rb all rigid molecule langevin 1 1 1 1\n",
                            "fix rigid keyword 'langevin' is not supported"),
        }, HEAD, err)


main()
