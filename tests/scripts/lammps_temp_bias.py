#!/usr/bin/env python3
"""lammps_temp_bias.py - compute temp/com, temp/partial and temp/region as
LAMMPS's (lmp 2021), as thermo's temperature and as fix temp/rescale's.

The falling bed of tests/scripts/lib/peer.py (96 spheres on a wall/gran
floor, gran/hooke/history) given a bulk velocity along x, run unchanged by
`lmp` (one process) and bin/gravel:
1. thermo prints each temperature and its kinetic-energy tensor (six
   elements), temp/partial with the y component left out, temp/region of a
   block the bed falls through (its atom count changes), and compute_modify
   extra/dof and dynamic/dof on them: equal to 1e-9 relative over 1500 steps;
2. thermo_modify temp on temp/com: temp, press and its tensor, ke (LAMMPS's
   ke is the temperature's), to 1e-9;
3. fix temp/rescale with fix_modify temp on each: the rescaling keeps the
   bias (the centre-of-mass motion, the y component, the atoms outside the
   region): thermo and the fix's energy to 1e-9;
4. velocity create and scale with `temp ID` and `bias yes` on them (with
   sum yes, loop local and geom): every velocity equal to lmp's to 1e-12;
5. compute temp/sphere with `bias` on temp/com, temp/partial (group all) and
   temp/region, dof all and rotate: scalars and tensor elements to 1e-9.
On 2 MPI ranks the three temperatures' file is byte-identical to one
process's, and each temp/rescale case's and the temp/sphere bias case's
thermo rows equal one process's to 17 digits. Then gravel's errors (temp/sphere's bias too). One line PASS/FAIL per case; without `lmp` the
comparisons FAIL naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check, check_same_on_ranks, check_thermo_same_on_ranks, close,  # noqa: E402
                  dump_steps, expect_errors, falling_bed, thermo_against_lmp)

HEAD = falling_bed() + """velocity all set 2.0 0.0 0.0 sum yes units box
region mid block INF INF INF INF 1 4 units box
compute tc all temp/com
compute tp top temp/partial 1 0 1
compute tr all temp/region mid
"""
CASES = {
    "computes": ("compute_modify tp extra/dof 1\ncompute_modify tr dynamic/dof yes\n"
                 "thermo_style custom step temp c_tc c_tc[1] c_tc[4] c_tc[6] c_tp c_tp[1] "
                 "c_tp[2] c_tp[5] c_tr c_tr[3] c_tr[4]\n"
                 "fix t all ave/time 100 1 100 c_tc c_tc[*] c_tp c_tp[*] c_tr c_tr[*] file t.txt "
                 "format \" %.17g\"\n", 13),
    "thermo_temp_com": ("thermo_style custom step temp press pxx pzz pxz ke\n"
                        "thermo_modify temp tc\n", 7),
    "sphere_bias": ("compute pa all temp/partial 1 0 1\n"
                    "compute sc all temp/sphere bias tc\ncompute sp all temp/sphere bias pa\n"
                    "compute sr all temp/sphere bias tr\n"
                    "compute spr all temp/sphere bias pa dof rotate\n"
                    "compute srr all temp/sphere bias tr dof rotate\n"
                    "thermo_style custom step c_sc c_sp c_sr c_spr c_srr c_sc[1] c_sp[2] c_sr[3] "
                    "c_sr[4]\n", 10),
    "rescale_com": ("fix r all temp/rescale 50 1.0 1.0 0.02 0.5\nfix_modify r temp tc\n"
                    "thermo_style custom step temp c_tc f_r\n", 4),
    "rescale_partial": ("fix r top temp/rescale 50 0.5 0.5 0.02 1.0\nfix_modify r temp tp\n"
                        "thermo_style custom step temp c_tp f_r\n", 4),
    "rescale_region": ("fix r all temp/rescale 50 0.5 0.5 0.02 1.0\nfix_modify r temp tr\n"
                       "thermo_style custom step temp c_tr f_r\n", 4),
}
TAIL = "thermo_modify format float %.15g\nthermo 100\nrun 1500\n"
VELOCITY = {  # velocity create / scale with `temp ID` and `bias yes`, after HEAD
    "velocity_create_temp_com_bias": "velocity all create 0.7 4411 temp tc bias yes loop geom\n",
    "velocity_create_temp_partial_bias_sum": "velocity top create 0.4 98 temp tp bias yes "
                                             "sum yes loop local\n",
    "velocity_create_temp_id": "velocity all create 0.9 5 temp tc dist gaussian\n",
    "velocity_scale_region_bias": "velocity all scale 0.25 temp tr bias yes\n",
    "velocity_scale_temp_partial": "velocity top scale 2.0 temp tp\n",
}
VTAIL = """thermo_style custom step ke c_tc c_tp c_tr
thermo_modify format float %.15g
dump d all custom 1 v.dump id vx vy vz
dump_modify d sort id format float %.15g
run 0
"""


def compare(name, parent):
    body, ncol = CASES[name]
    deck = HEAD + body + TAIL
    _, _, _, g, _ = thermo_against_lmp("temp_bias_" + name, deck, ncol, 16, parent, 1e-9, 1e-12)
    if name == "computes":
        ranks = os.path.join(parent, "ranks")
        os.mkdir(ranks)
        check_same_on_ranks("temp_bias_same_on_2_ranks", 2, deck, ranks, g, ["t.txt"])
    if name.startswith("rescale") or name == "sphere_bias":
        ranks = os.path.join(parent, "ranks_" + name)
        os.mkdir(ranks)
        check_thermo_same_on_ranks("temp_bias_%s_2_ranks" % name, 2,
                                   deck.replace("%.15g", "%.17g"), ncol, ranks)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name in CASES:
            compare(name, tmp)
        for name, cmd in VELOCITY.items():
            ok, _, _, g, lm = thermo_against_lmp(name, HEAD + cmd + VTAIL, 5, 1, tmp, 1e-12,
                                                 1e-14)
            if ok:
                a, b = dump_steps(os.path.join(g, "v.dump")), dump_steps(os.path.join(lm, "v.dump"))
                bad = [i for i in a[0] if any(not close(x, y, 1e-12, 1e-14)
                                              for x, y in zip(a[0][i], b[0][i]))]
                check(name + "_velocities", a.keys() == b.keys() and not bad, str(bad[:5]))
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        expect_errors({
            "err_com_args": ("compute c all temp/com 1\n", "takes no arguments"),
            "err_partial_args": ("compute c all temp/partial 1 0\n", "expects xflag yflag zflag"),
            "err_partial_flag": ("compute c all temp/partial 1 2 0\n", "flags must be 0 or 1"),
            "err_region_missing": ("compute c all temp/region nowhere\n", "nowhere"),
            "err_region_args": ("compute c all temp/region\n", "expects a region ID"),
            "err_bias_without_temp": ("velocity all create 1.0 5 bias yes\n",
                                      "velocity bias command without temp keyword"),
            "err_bias_plain_temp": ("compute t all temp\nvelocity all scale 1.0 temp t bias "
                                    "yes\n", "does not compute a velocity bias"),
            "err_sphere_bias_plain": ("compute t all temp\ncompute s all temp/sphere bias t\n"
                                      "thermo_style custom step c_s\nrun 0\n",
                                      "bias compute t does not calculate a velocity bias"),
            "err_sphere_bias_group": ("compute t top temp/com\ncompute s all temp/sphere bias t"
                                      "\nthermo_style custom step c_s\nrun 0\n",
                                      "bias compute t's group does not match its group"),
            "err_sphere_bias_missing": ("compute s all temp/sphere bias\n",
                                        "bias needs a compute ID"),
        }, falling_bed(), err)


main()
