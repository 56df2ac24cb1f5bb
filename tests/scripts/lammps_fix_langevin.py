#!/usr/bin/env python3
"""lammps_fix_langevin.py - fix langevin as LAMMPS's (lmp 2021).

1. A dilute granular gas (125 spheres of two types, gran/hooke/history,
   periodic) with `atom_modify sort 0 0.0`, so that LAMMPS's one process
   meets its atoms in creation (= ID) order: fix langevin with a
   temperature ramp, `omega yes`, `zero yes`, `scale 2 2.0`, with an
   equal-style target and with an atom-style one (a target per atom): thermo ke and the rotational energy equal lmp's to
   1e-9 relative every 200 steps over 2000 (the same RanMars stream, the
   same forces).
2. Physics, gravel alone: 1000 point-like spheres that never touch, held at
   T = 1.5 (damp 0.1): the temperature averaged over the second half of the
   run is 1.5 within 3 %, and with `omega yes` the rotational temperature
   too (equipartition).
   `tally yes`: the thermostat's energy f_lg (with omega, zero and scale)
   equals lmp's to 1e-9 over two runs (LAMMPS restarts the tally at each
   run's first step).
3. On 2 and 3 MPI ranks (bin/gravel-mpi) every case of 1. prints the rows
   of one process to 17 digits (every rank draws the whole stream).
4. The errors. One line PASS/FAIL per case; without
   `lmp` the comparisons FAIL naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_thermo_same_on_ranks, expect_errors,  # noqa: E402
                  run, thermo_against_lmp, thermo_rows)

GAS = """units lj
atom_style sphere
atom_modify map array sort 0 0.0
comm_modify vel yes
boundary p p p
lattice sc 0.3
region box block 0 5 0 5 0 5
create_box 2 box
create_atoms 1 box
set group all diameter 1.0 density 1.0
set type 1 type/fraction 2 0.5 8812
velocity all create 0.5 87287 loop geom
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
fix 1 all nve/sphere
compute rot all erotate/sphere
timestep 0.001
"""
TAIL = """thermo_style custom step ke c_rot
thermo_modify format float %.15g
thermo 200
run 2000
"""
CASES = {
    "ramp_omega_zero_scale": "fix lg all langevin 1.0 2.0 0.5 48279 omega yes zero yes "
                             "scale 2 2.0\n",
    "translation_only": "fix lg all langevin 0.8 0.8 0.2 1234 zero no\n",
    "equal_variable_target": "variable tt equal 0.5+0.0005*step\n"
                             "fix lg all langevin v_tt 1.0 0.5 9999 omega yes\n",
    "atom_variable_target": "variable ta atom 0.4+0.3*type+0.02*(id%9)\n"
                            "fix lg all langevin v_ta 1.0 0.5 4242 omega yes zero yes\n",
}
# tally yes: f_lg beside ke and the rotational energy, over two runs
TALLY = ("fix lg all langevin 1.0 2.0 0.5 48279 omega yes zero yes scale 2 2.0 tally yes\n"
         "thermo_style custom step ke c_rot f_lg ecouple econserve\n"
         "thermo_modify format float %.15g\n"
         "thermo 200\n"
         "run 1000\n"
         "run 600\n")

IDEAL = """units lj
atom_style sphere
boundary p p p
lattice sc 0.05
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 box
set group all diameter 0.01 density 1000000.0
velocity all create 0.1 4711 loop geom
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
fix 1 all nve/sphere
fix lg all langevin 1.5 1.5 0.1 777 omega yes
compute tr all temp/sphere dof rotate
thermo_style custom step temp c_tr
thermo_modify format float %.10g
thermo 100
timestep 0.005
run 6000
"""


def compare(name, parent):
    thermo_against_lmp("langevin_" + name, GAS + CASES[name] + TAIL, 3, 11, parent, 1e-9, 1e-14)


def ideal(tmp):
    rc, out = run([GRAVEL], IDEAL, tmp)
    rows = [r for r in thermo_rows(out, 3) if r[0] >= 3000] if rc == 0 else []
    t = sum(r[1] for r in rows) / max(len(rows), 1)
    tr = sum(r[2] for r in rows) / max(len(rows), 1)
    check("langevin_equipartition_translation", len(rows) == 31 and abs(t / 1.5 - 1) < 0.03,
          "mean temp %g (target 1.5): %s" % (t, out[-300:]))
    check("langevin_equipartition_rotation", len(rows) == 31 and abs(tr / 1.5 - 1) < 0.03,
          "mean rotational temp %g (target 1.5)" % tr)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name in CASES:
            compare(name, tmp)
        ok, got, _, _, _ = thermo_against_lmp("langevin_tally", GAS + TALLY, 6, 10, tmp, 1e-9,
                                              1e-14)
        check("langevin_tally_energy_taken", ok and got[5][3] < -1.0 and got[6][3] == 0.0,
              "rows %s" % got[4:7])
        d = os.path.join(tmp, "ideal")
        os.mkdir(d)
        ideal(d)
        e = os.path.join(tmp, "err")
        os.mkdir(e)
        expect_errors({
            "err_args": ("fix lg all langevin 1.0 1.0 0.5\n", "expects Tstart Tstop damp seed"),
            "err_seed": ("fix lg all langevin 1.0 1.0 0.5 0\n", "seed must be in 1 .. 900000000"),
            "err_damp": ("fix lg all langevin 1.0 1.0 0.0 5\n", "damp must be > 0"),
            "err_gjf": ("fix lg all langevin 1.0 1.0 0.5 5 gjf vhalf\n",
                        "gjf vhalf is not supported yet"),
            "err_keyword": ("fix lg all langevin 1.0 1.0 0.5 5 bias yes\n",
                            "unknown keyword 'bias'"),
            "err_atom_target": ("variable t atom 1.0-id\nfix lg all langevin v_t 1.0 0.5 5\n"
                                "run 0\n", "variable t returned a negative temperature -1 for "
                                "atom 2"),
        }, GAS, e)
        decks = [(name, GAS + fix + TAIL, 3) for name, fix in CASES.items()]
        for name, deck, ncol in decks + [("tally", GAS + TALLY, 6)]:
            for np in (2, 3):
                check_thermo_same_on_ranks("langevin_%s_%d_ranks" % (name, np), np,
                                           deck.replace("%.15g", "%.17g"), ncol, e)


main()
