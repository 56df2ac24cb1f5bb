#!/usr/bin/env python3
"""lammps_fix_indent.py - fix indent as LAMMPS's (lmp 2021).

The falling bed of tests/scripts/lib/peer.py (96 spheres on a wall/gran
floor, gran/hooke/history), run unchanged by `lmp` (one process) and
bin/gravel with an indenter pressed into it: a sphere whose centre descends
(an equal-style variable of the step), across the periodic x boundary (its
centre remapped, the distances minimum images), in lattice units; a
cylinder along y with `units box` and a growing radius; a plane from above
(`plane z ... hi`); a sphere with `side in` holding the bed inside it. thermo
prints ke, the indenter's energy f_ID and force f_ID[1..3], and pe with
`fix_modify energy yes`: equal to 1e-9 relative (1e-12 absolute) every 100
steps over 1500. On 2 MPI ranks every case's rows equal one process's to
17 digits (the plane presses every atom into one rank's half: a rank
without atoms still takes part in the sums). Then gravel's errors. One line PASS/FAIL per case;
without `lmp` the comparisons FAIL naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check, check_thermo_same_on_ranks, expect_errors, falling_bed,  # noqa: E402
                  thermo_against_lmp)

CASES = {
    "sphere_moving_periodic": "variable zc equal 7.0-0.003*step\n"
                              "fix ind all indent 200.0 sphere 0.2 2.0 v_zc 2.5\n",
    "cylinder_growing_box": "variable rc equal 0.5+0.001*step\n"
                            "fix ind all indent 300.0 cylinder y 2.0 3.0 v_rc units box\n",
    "plane_from_above": "variable zp equal 7.0-0.003*step\n"
                        "fix ind all indent 500.0 plane z v_zp hi units box\n",
    "sphere_side_in": "fix ind all indent 100.0 sphere 2.0 2.0 3.0 2.6 side in units box\n",
}
TAIL = """fix_modify ind energy yes
thermo_style custom step ke pe f_ind f_ind[1] f_ind[2] f_ind[3]
thermo_modify format float %.15g norm no
thermo 100
run 1500
"""


def compare(name, parent):
    deck = falling_bed() + CASES[name] + TAIL
    ok, got, _, _, _ = thermo_against_lmp("indent_" + name, deck, 7, 16, parent, 1e-9, 1e-12)
    if ok:
        check("indent_" + name + "_touches", any(abs(r[3]) > 1e-6 for r in got), str(got[-1:]))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name in CASES:
            compare(name, tmp)
        ranks = os.path.join(tmp, "ranks")
        os.mkdir(ranks)
        for name, fix in CASES.items():
            check_thermo_same_on_ranks("indent_%s_2_ranks" % name, 2, falling_bed() + fix +
                                       TAIL.replace("%.15g", "%.17g"), 7, ranks)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        expect_errors({
            "err_no_indenter": ("fix ind all indent 10.0\n", "no indenter given"),
            "err_dim": ("fix ind all indent 10.0 cylinder w 1 1 1\n", "dim must be x, y or z"),
            "err_side": ("fix ind all indent 10.0 sphere 1 1 1 1 side up\n",
                         "side must be in or out"),
            "err_plane_side": ("fix ind all indent 10.0 plane z 1 mid\n",
                               "plane side must be lo or hi"),
            "err_keyword": ("fix ind all indent 10.0 sphere 1 1 1 1 wall yes\n",
                            "unknown keyword 'wall'"),
            "err_variable": ("fix ind all indent 10.0 sphere 1 1 v_nope 1\nrun 0\n",
                             "variable nope does not exist"),
            "err_negative_radius": ("variable r equal -1\n"
                                    "fix ind all indent 10.0 sphere 1 1 1 v_r\nrun 0\n",
                                    "radius -1 < 0"),
        }, falling_bed(), err)


main()
