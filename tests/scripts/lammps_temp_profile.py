#!/usr/bin/env python3
"""lammps_temp_profile.py - compute temp/profile as LAMMPS's (lmp 2021): the
temperature about each spatial bin's mean velocity (a profile-unbiased
temperature), its kinetic-energy tensor, its per-bin array (out bin), and
its bias taken out and put back by a thermostat (fix temp/rescale with
fix_modify temp).

The falling bed (96 spheres on a wall/gran floor) run unchanged by `lmp`
and bin/gravel: temp/profile of all atoms about 4 z layers (all three
components), of the upper group about 2 x 2 xy pencils (x and z
components), and 3 z layers with out bin (count and temperature per bin,
dof = dim count - extra/dof) through fix ave/time; then a second run with
fix temp/rescale thermostatting the profile temperature (its bias kept).
The thermo columns and the file equal lmp's to 1e-9 over the first 1000
steps (the dof: dim N - dim Nbins - extra/dof, LAMMPS's Evans-Morriss
count), and to 1e-6 under the thermostat (the rescaled step reads the
target exactly); on 2 MPI ranks the thermo rows equal one process's. Then
the errors. One line PASS/FAIL per case; without `lmp` the comparison
FAILs naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)) + "/lib")
from peer import (check, check_thermo_same_on_ranks, close, expect_errors, falling_bed,  # noqa: E402
                  file_numbers, run_with_lmp, thermo_rows)

DECK = falling_bed() + """compute tp all temp/profile 1 1 1 z 4
compute tq top temp/profile 1 0 1 xy 2 2
compute tb all temp/profile 1 1 0 z 3 out bin
fix a all ave/time 250 1 250 c_tb[*] mode vector file tb.txt format " %.15g"
thermo_style custom step c_tp c_tp[1] c_tp[4] c_tq c_tq[3]
thermo_modify format float %.17g
thermo 250
run 1000
fix r all temp/rescale 100 1.0 0.5 0.05 1.0
fix_modify r temp tp
run 1000
"""


def main():
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, lout, g, lm = run_with_lmp(DECK, tmp, "profile")
        ta = thermo_rows(out, 6) if rc == 0 else []
        if lout is None:
            check("temp_profile_equal_lmp", False, "lmp (Debian package lammps) is not installed")
        else:
            tb = thermo_rows(lout, 6)
            bad = [(r[0], x, y) for r, s in zip(ta, tb) for x, y in zip(r, s)
                   if not close(x, y, 1e-9 if r[0] <= 1000 else 1e-6, 1e-12)]
            fa = file_numbers(os.path.join(g, "tb.txt")) if rc == 0 else []
            fb = file_numbers(os.path.join(lm, "tb.txt"))
            n1 = len(fb) // 2  # the first run's samples (steps 0..1000) of 2 runs
            bad += [("tb", x, y) for k, (x, y) in enumerate(zip(fa, fb))
                    if not close(x, y, 1e-9 if k < n1 else 1e-6, 1e-12)]
            check("temp_profile_equal_lmp", rc == 0 and len(ta) == len(tb) == 10 and
                  len(fa) == len(fb) > 0 and not bad,
                  "%d/%d rows, %s: %s" % (len(ta), len(tb), bad[:4], (out if rc else lout)[-300:]))
        # the thermostat holds the profile temperature at its rescale steps
        check("temp_profile_thermostat", len(ta) == 10 and abs(ta[7][1] - 0.75) < 1e-12 and
          abs(ta[9][1] - 0.5) < 1e-12,
              "rows %s" % ta[6:])
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_thermo_same_on_ranks("temp_profile_2_ranks", 2, DECK, 6, err)
        head = falling_bed()
        expect_errors({
            "err_flag": ("compute t all temp/profile 2 1 1 x 4\n", "flags must be 0 or 1"),
            "err_style": ("compute t all temp/profile 1 1 1 q 4\n", "binstyle must be"),
            "err_counts": ("compute t all temp/profile 1 1 1 xy 4\n", "expects 2 bin counts"),
            "err_out": ("compute t all temp/profile 1 1 1 x 4 out both\n",
                        "out must be tensor or bin"),
            "err_nbin": ("compute t all temp/profile 1 1 1 x 0\n", "bin count"),
        }, head, err)


main()
