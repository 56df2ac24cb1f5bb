#!/usr/bin/env python3
"""lammps_nve_limit_lineforce.py - fix nve/limit, nve/noforce, lineforce and
planeforce as LAMMPS's (lmp 2021).

Each deck runs unchanged in `lmp` (one process) and bin/gravel; every thermo
row agrees to 1e-9 relative:
1. nve/limit: 120 spheres dropped at random into a periodic box, heavily
   overlapping (gran/hooke/history), relaxed with xmax 0.002: ke to 1e-9 and
   the fix's count of capped kicks f_lim (extensive: divided by the atoms
   under lj's norm yes) within 6 kicks of lmp's 22,000 and more, over two
   runs (the count starts again at each run); a velocity capped to the limit
   sits on it, so whether the next kick caps it again is decided by the last
   bit of its speed, which the two codes' force sums round apart;
2. nve/noforce: three spheres of the falling bed of tests/scripts/lib/peer.py
   driven at a set velocity through the others (nve/sphere): ke, the
   rotational energy and the probe group's centre of mass;
3. lineforce 1 0.5 -1 and 4. planeforce 0 1 0 on the falling bed (after
   gravity and the wall): ke, the rotational energy and the bed's centre of
   mass (planeforce: y fixed);
5. spring tether (a NULL component, R0 0.5, fix_modify energy yes: pe) and
   spring couple (the top half to three probe spheres) on the falling bed:
   the probe's centre of mass, the spring's energy f_sp and its force vector
   f_sp[1..4], over 1000 steps (the falling bed is chaotic:
   by step 1400 the codes part at 1e-8).
On 2 MPI ranks each deck prints the rows of one process to 17 digits. Then
the errors. One line PASS/FAIL per case; without `lmp` the comparisons FAIL
naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_thermo_same_on_ranks, close, expect_errors,  # noqa: E402
                  falling_bed, folders, run, thermo_against_lmp, thermo_rows)

PACK = """units lj
atom_style sphere
atom_modify map array
comm_modify vel yes
boundary p p p
region box block 0 5 0 5 0 5
create_box 1 box
create_atoms 1 random 120 4567 box
set group all diameter 1.0 density 1.0
pair_style gran/hooke/history 20000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix lim all nve/limit 0.002
timestep 0.001
thermo_style custom step ke f_lim
thermo_modify format float %.15g
thermo 100
run 600
run 400
"""
TAIL = """compute rot all erotate/sphere
variable cx equal xcm(%s,x)
variable cy equal xcm(%s,y)
variable cz equal xcm(%s,z)
thermo_style custom step ke c_rot v_cx v_cy v_cz
thermo_modify format float %%.15g
thermo 100
run 1000
"""
CASES = {
    "nve_noforce": (falling_bed(extra="group probe id 1 2 3\ngroup rest subtract all probe\n") +
                    "unfix 1\nfix 1 rest nve/sphere\nfix 2 probe nve/noforce\n"
                    "velocity probe set 0.5 0.0 0.2 units box\n" + TAIL % (("probe",) * 3),
                    6, 11),
    "lineforce": (falling_bed() + "fix lf all lineforce 1 0.5 -1\n" + TAIL % (("all",) * 3), 6, 11),
    "planeforce": (falling_bed() + "fix pf all planeforce 0 1 0\n" + TAIL % (("all",) * 3), 6, 11),
    "spring_tether": (falling_bed(extra="group probe id 1 2 3\n") +
                      "fix sp probe spring tether 20.0 2.0 NULL 4.0 0.5\n"
                      "fix_modify sp energy yes\n" +
                      TAIL.replace("v_cz", "v_cz f_sp f_sp[1] f_sp[2] f_sp[3] f_sp[4] pe") %
                      (("probe",) * 3), 12, 11),
    "spring_couple": (falling_bed(extra="group probe id 1 2 3\n") +
                      "fix sp top spring couple probe 15.0 0.5 -0.3 NULL 0.0\n" +
                      TAIL.replace("v_cz", "v_cz f_sp f_sp[1] f_sp[2] f_sp[3] f_sp[4]") %
                      (("probe",) * 3), 11, 11),
}


def main():
    with tempfile.TemporaryDirectory() as tmp:
        gd, ld = folders(tmp, "limit_g", "limit_l")
        rc, out = run([GRAVEL], PACK, gd)
        got = thermo_rows(out, 3) if rc == 0 else []
        _, lout = run(["lmp"], PACK, ld)
        ref = thermo_rows(lout, 3)
        bad = [(r[0], a, b) for r, t in zip(got, ref) for c, (a, b) in enumerate(zip(r, t))
               if not (close(a, b, 1e-9, 1e-14) if c < 2 else abs(a - b) <= 6 / 120)]
        check("nve_limit", len(got) == 12 and len(ref) == 12 and not bad,
              "rows %d/%d, differ %s: %s" % (len(got), len(ref), bad[:3], out[-300:]))
        check("nve_limit_caps_and_restarts", len(got) == 12 and got[6][2] > 100 and
              got[7][2] == 0, "rows %s" % got[5:8])
        for name, (deck, ncol, nrows) in CASES.items():
            thermo_against_lmp(name, deck, ncol, nrows, tmp, 1e-9, 1e-12)
        ok, got, _, _, _ = thermo_against_lmp("planeforce_keeps_y", CASES["planeforce"][0], 6,
                                              11, tmp, 1e-9, 1e-12)
        check("planeforce_y_fixed", ok and max(abs(r[4] - got[0][4]) for r in got) < 1e-12,
              "centre of mass y %s" % [r[4] for r in got[:3]])
        e = os.path.join(tmp, "err")
        os.mkdir(e)
        expect_errors({
            "err_limit_args": ("fix l all nve/limit\n", "fix nve/limit expects xmax, got 0"),
            "err_noforce_args": ("fix n all nve/noforce 1\n", "takes no arguments, got '1'"),
            "err_lineforce_args": ("fix l all lineforce 1 0\n", "fix lineforce expects x y z"),
            "err_planeforce_zero": ("fix p all planeforce 0 0 0\n", "has no length"),
            "err_spring_style": ("fix s all spring pull 1 0 0 0 0\n", "expected tether or couple"),
            "err_spring_group": ("fix s all spring couple nogroup 1 0 0 0 0\n",
                                 "group 'nogroup' does not exist"),
            "err_spring_args": ("fix s all spring tether 1 0 0 0\n",
                                "tether expects K x y z R0, got 4"),
        }, falling_bed(), e)
        decks = [("nve_limit", PACK.replace("%.15g", "%.17g"), 3)] + \
            [(n, d.replace("%.15g", "%.17g"), c) for n, (d, c, _) in CASES.items()]
        for name, deck, ncol in decks:
            check_thermo_same_on_ranks("%s_2_ranks" % name, 2, deck, ncol, e)


main()
