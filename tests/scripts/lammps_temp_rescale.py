#!/usr/bin/env python3
"""lammps_temp_rescale.py - fix temp/rescale and fix temp/berendsen as LAMMPS's.

125 spheres launched at temperature 5 in a periodic box, gran/hooke/history,
2000 steps, run unchanged by `lmp` (LAMMPS 2021, one process) and
bin/gravel, with two rescalings: every 50 steps the whole gas toward a
target ramped from 5 to 1 (window 0.2, fraction 0.5), and every 100 steps
the lower half held at 2 (window 0.05, fraction 1) through a temperature
compute given by `fix_modify temp`. Every thermo row (temp, ke, that
compute, both fixes' energies, ecouple (their sum, not divided by the
atoms under lj's norm yes, as LAMMPS) and econserve) agrees with lmp's to 1e-7 relative (the
gas is chaotic: the trajectories part at 1e-9 by the end). The same gas
under fix temp/berendsen twice (the whole gas toward an equal-style
variable's target, Tdamp 0.2; the lower half through `fix_modify temp` from 2
to 1.5, Tdamp 0.05): temp, ke, both fixes' energies, ecouple and econserve to
1e-7; on 2 MPI ranks the rows of one process to 17 digits. Then the errors.
One line PASS/FAIL per case; without `lmp` the comparison FAILs naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_thermo_same_on_ranks, close, expect_errors,  # noqa: E402
                  folders, run, thermo_against_lmp, thermo_rows)

REL = 1e-7
HEAD = """units lj
atom_style sphere
atom_modify map array
comm_modify vel yes
boundary p p p
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 5 0 5 0 5
create_box 1 box
create_atoms 1 box
set group all diameter 0.8 density 1.0
velocity all create 5.0 4928 loop geom
region half block INF INF INF INF 0 2.5 units box
group half region half
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
timestep 0.001
"""
DECK = HEAD + """compute th half temp
fix tr all temp/rescale 50 5.0 1.0 0.2 0.5
fix tr2 half temp/rescale 100 2.0 2.0 0.05 1.0
fix_modify tr2 temp th
thermo_style custom step temp ke c_th f_tr f_tr2 ecouple econserve
thermo_modify format float %.15g
thermo 200
run 2000
"""
BERENDSEN = HEAD + """compute th half temp
variable tt equal 5.0-0.002*step
fix tb all temp/berendsen v_tt 1.0 0.2
fix tb2 half temp/berendsen 2.0 1.5 0.05
fix_modify tb2 temp th
thermo_style custom step temp ke c_th f_tb f_tb2 ecouple econserve
thermo_modify format float %.15g
thermo 200
run 2000
"""


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir, edir = folders(tmp, "g", "l", "errors")
        rc, gout = run([GRAVEL], DECK, gdir)
        g = thermo_rows(gout, 8)
        check("temp_rescale_run", rc == 0 and len(g) == 11 and g[-1][1] < 2.0 and g[-1][4] < 0 and
              abs(g[-1][6] - 125 * (g[-1][4] + g[-1][5])) <= 1e-9 * abs(g[-1][6]),
              "exit %d: %s" % (rc, gout[-600:]))
        if shutil.which("lmp") is None:
            check("temp_rescale_match_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            lm = thermo_rows(lout, 8)
            bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
                   if not close(a, b, REL, 1e-12)]
            check("temp_rescale_match_lammps", rc == 0 and len(lm) == len(g) and not bad,
                  "lmp exit %d, differences %s" % (rc, bad[:3]))
        ok, b, _, _, _ = thermo_against_lmp("temp_berendsen_match_lammps", BERENDSEN, 8, 11, tmp,
                                            REL, 1e-12)
        check("temp_berendsen_acts", ok and b[-1][1] < 1.5 and b[-1][4] != 0 and b[-1][5] != 0,
              "rows %s" % b[-2:])
        check_thermo_same_on_ranks("temp_berendsen_2_ranks", 2,
                                   BERENDSEN.replace("%.15g", "%.17g"), 8, edir)
        expect_errors({
            "temp_berendsen_args": ("fix t all temp/berendsen 1 1\n", "fix temp/berendsen "
                                    "expects Tstart Tstop Tdamp, got 2 arguments"),
            "temp_berendsen_damp": ("fix t all temp/berendsen 1 1 0\n", "Tdamp must be > 0"),
            "temp_rescale_args": ("fix t all temp/rescale 10 1 1 0.1\n", "ERROR: fix: fix "
                                  "temp/rescale expects N Tstart Tstop window fraction, got 4"),
            "temp_rescale_n": ("fix t all temp/rescale 0 1 1 0.1 1\n", "fix temp/rescale: N must "
                               "be > 0"),
            "temp_rescale_variable": ("fix t all temp/rescale 10 v_nope 1 0.1 1\nrun 1\n",
                                      "fix temp/rescale t: variable 'nope' does not exist"),
            "temp_rescale_modify": ("compute k all ke\nfix t all temp/rescale 10 1 1 0.1 1\n"
                                    "fix_modify t temp k\n", "fix temp/rescale t: compute k (ke) "
                                    "is not a temperature"),
        }, HEAD, edir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
