#!/usr/bin/env python3
"""lammps_stress_atom.py - compute stress/atom as LAMMPS's.

Two decks, each run unchanged by `lmp` (LAMMPS 2021, one process) and
bin/gravel:
  wall    96 spheres launched at temperature 3 in a box periodic in x and y
          falling onto a wall/gran floor, 1500 steps: stress/atom with every
          term on all, the pair term only on the upper half (group top, its
          temp-ID thermo_temp), the kinetic term only on all;
  deform  125 spheres in a periodic box that fix deform stretches in x and
          squeezes in y (remap x), 1200 steps: the per-atom virial of the
          forces, taken before the box change moves the atoms.
Thermo prints the reductions (sums) every 250 / 200 steps and a dump custom
every 500 / 400 steps each atom's six components. Thermo values agree to
1e-8 relative (1e-10 absolute); each dump value to 1e-8 of the largest
component of its snapshot (a contact that barely touches has a tiny force
whose relative value follows the 1e-12 differences of the trajectories).
gravel alone: -(sum of s_xx + s_yy + s_zz) / (3 V) is the thermo pressure
(a variable of the raw sums; thermo normalizes the printed c_ columns by
the atom count, as LAMMPS's `thermo_modify norm yes` in lj units). Then
gravel's errors, and the refusal on 2 MPI ranks. One line PASS/FAIL per case; without `lmp` the
comparisons FAIL naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_refused_on_ranks, close, dump_steps,  # noqa: E402
                  expect_errors, falling_bed, folders, run, thermo_rows)

REL, ABS, DUMP_REL = 1e-8, 1e-10, 1e-8

WALL = falling_bed()
WALL_RUN = WALL + """compute s all stress/atom NULL
compute p top stress/atom thermo_temp pair
compute k all stress/atom NULL ke
compute ss all reduce sum c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6]
compute ps top reduce sum c_p[1] c_p[6]
compute ks all reduce sum c_k[1] c_k[4]
variable pr equal -(c_ss[1]+c_ss[2]+c_ss[3])/(3*vol)
thermo_style custom step press v_pr c_ss[4] c_ps[1] c_ps[2] c_ks[1] c_ks[2]
thermo_modify format float %.15g
thermo 250
dump 1 all custom 500 out.dump id c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6] c_p[1] c_p[4] &
     c_k[2] c_k[5]
dump_modify 1 sort id format float %.15g
run 1500
"""
DEFORM_RUN = """units lj
atom_style sphere
boundary p p p
comm_modify vel yes
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 5 0 5 0 5
create_box 1 box
create_atoms 1 box
set group all diameter 1.05 density 1.0
velocity all create 2.0 4928 loop geom
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
fix d all deform 1 x erate 0.05 y erate -0.05 remap x
timestep 0.001
compute s all stress/atom NULL
compute ss all reduce sum c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6]
variable pr equal -(c_ss[1]+c_ss[2]+c_ss[3])/(3*vol)
thermo_style custom step press v_pr c_ss[1] c_ss[4] c_ss[6]
thermo_modify format float %.15g
thermo 200
dump 1 all custom 400 out.dump id c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6]
dump_modify 1 sort id format float %.15g
run 1200
"""
DECKS = {"wall": (WALL_RUN, 8, [0, 500, 1000, 1500]),
         "deform": (DEFORM_RUN, 6, [0, 400, 800, 1200])}


def dump_differences(mine, ref):
    """(step, id, mine, ref) where a value is off by more than DUMP_REL of its
    snapshot's largest |value|"""
    bad = []
    for st, atoms in ref.items():
        scale = max((abs(v) for row in atoms.values() for v in row), default=0)
        for i, row in atoms.items():
            for a, b in zip(mine.get(st, {}).get(i, [float("nan")] * len(row)), row):
                if not abs(a - b) <= DUMP_REL * scale:
                    bad.append((st, i, a, b))
    return bad


def check_deck(name, tmp):
    deck, ncol, steps = DECKS[name]
    gdir, ldir = folders(tmp, name + "_g", name + "_l")
    rc, gout = run([GRAVEL], deck, gdir)
    g = thermo_rows(gout, ncol)
    gs = dump_steps(os.path.join(gdir, "out.dump")) if rc == 0 else {}
    nonzero = any(v != 0 for s in gs.values() for row in s.values() for v in row)
    check("stress_atom_%s_run" % name, rc == 0 and len(g) == steps[-1] // (steps[1] // 2) + 1
          and sorted(gs) == steps and nonzero, "exit %d: %s" % (rc, gout[-600:]))
    # -(s_xx + s_yy + s_zz) summed / (3 V) is the pressure, to the last digits
    off = [(r[0], r[1], r[2]) for r in g if abs(r[1] - r[2]) > 1e-12 * abs(r[1])]
    check("stress_atom_%s_sum_is_pressure" % name, g and not off, str(off[:3]))
    if shutil.which("lmp") is None:
        check("stress_atom_%s_match_lammps" % name, False, "lmp not found (apt-get install lammps)")
        return
    rc, lout = run(["lmp"], deck, ldir)
    lm = thermo_rows(lout, ncol)
    ls = dump_steps(os.path.join(ldir, "out.dump")) if rc == 0 else {}
    bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
           if not close(a, b, REL, ABS)]
    bad += dump_differences(gs, ls)
    same_atoms = all(sorted(gs.get(st, {})) == sorted(ls[st]) for st in ls)
    check("stress_atom_%s_match_lammps" % name, rc == 0 and len(lm) == len(g) and same_atoms
          and sorted(ls) == sorted(gs) and not bad, "lmp exit %d, differences %s" % (rc, bad[:3]))


def main():
    tmp = tempfile.mkdtemp()
    try:
        for name in DECKS:
            check_deck(name, tmp)
        edir, = folders(tmp, "errors")
        expect_errors({
            "stress_atom_needs_temp_id": ("compute s all stress/atom\n",
                                          "ERROR: compute: compute stress/atom needs a "
                                          "temperature compute ID (or NULL)"),
            "stress_atom_unknown_keyword": ("compute s all stress/atom NULL pressure\n",
                                            "ERROR: compute: compute stress/atom: unknown "
                                            "keyword 'pressure'"),
            "stress_atom_temp_not_temperature": (
                "compute e all ke\ncompute s all stress/atom e\n"
                "dump 1 all custom 10 out.dump id c_s[1]\nrun 0\n",
                "compute stress/atom: compute e (ke) is not a temperature"),
        }, WALL, edir)
        # several ranks: refused at the run's setup, naming the compute
        check_refused_on_ranks("stress_atom_two_ranks_refused", WALL + "compute s all stress/atom "
                               "NULL\nrun 10\n", edir, "compute s (stress/atom)")
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
