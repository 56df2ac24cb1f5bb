#!/usr/bin/env python3
"""lammps_group_functions.py - the group functions of equal-style variables
that LAMMPS has beside count, mass, xcm, vcm and bound: ke(group),
fcm(group,dim), gyration(group), angmom(group,dim), torque(group,dim),
inertia(group,dimdim), omega(group,dim).

The falling bed of peer.py, its upper and lower halves (groups top, bot)
and all, 1000 steps: each function as a thermo column every 100 steps, run
unchanged by `lmp` (2021, one process) and bin/gravel: every value equal
to 1e-9 relative (1e-10 absolute: the x force on all cancels to round-off).
On 2 MPI ranks the rows are one process's to 17 digits. Then the errors: a
wrong argument count, an inertia component that is not xx yy zz xy yz xz.
One line PASS/FAIL per case; without `lmp` the comparison FAILs naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check_thermo_same_on_ranks, expect_errors, falling_bed,  # noqa: E402
                  thermo_against_lmp)

HEAD = falling_bed(extra="group bot subtract all top\n")
DECK = HEAD + """variable kt equal ke(top)
variable fz equal fcm(bot,z)
variable fx equal fcm(all,x)
variable rg equal gyration(top)
variable ly equal angmom(top,y)
variable tz equal torque(bot,z)
variable ixx equal inertia(top,xx)
variable ixy equal inertia(top,xy)
variable iyz equal inertia(all,yz)
variable wx equal omega(top,x)
thermo_style custom step v_kt v_fz v_fx v_rg v_ly v_tz v_ixx v_ixy v_iyz v_wx
thermo_modify format float %.15g
thermo 100
run 1000
"""


def main():
    with tempfile.TemporaryDirectory() as tmp:
        thermo_against_lmp("group_functions", DECK, 11, 11, tmp, 1e-9, 1e-10)
        check_thermo_same_on_ranks("group_functions_2_ranks", 2, DECK.replace("%.15g", "%.17g"),
                                   11, tmp)
        expect_errors({
            "ke_arguments": ("variable a equal ke(top,x)\nprint $a\n",
                             "ke() takes 1 argument, got 2"),
            "inertia_component": ("variable a equal inertia(top,xz2)\nprint $a\n",
                                  "inertia() component must be xx yy zz xy yz xz, got 'xz2'"),
        }, HEAD, tmp)


if __name__ == "__main__":
    sys.exit(main())
