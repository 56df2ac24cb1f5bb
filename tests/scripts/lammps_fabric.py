#!/usr/bin/env python3
"""lammps_fabric.py - compute fabric as LAMMPS's (lmp 2021, GRANULAR), and
compute property/chunk beside it.

A compressed cube of 125 spheres (diameter 1.04 on a unit lattice, jiggled)
in a non-periodic box springs apart for 200 steps. compute fabric's scalar
(the contact count) and every element of its tensors (contact, branch,
force/normal, force/tangential) are printed by thermo every 100 steps in
lmp and gravel: equal to 1e-10 relative (or 1e-13 absolute: the tensors are
deviators, near zero) with gran/hertz/history (cutoff radius), pair
granular (cutoff type; contact, branch, force/normal), and with two atom
types and type/include. compute property/chunk (count coord1 of a
bin/1d chunk/atom) written by fix ave/time: equal files' numbers. On 2
MPI ranks the fabric's file is byte-identical to one process's. (In a
periodic box lmp evaluates pairs across the boundary with its ghosts'
half-step velocities, as for compute pair/local: the force tensors then
differ by the damping's share; the geometry tensors do not.) Then gravel's
errors. One line PASS/FAIL per case; without `lmp` the comparisons FAIL
naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_same_on_ranks, close, expect_errors,  # noqa: E402
                  folders, run, thermo_rows)

HEAD = """units lj
atom_style sphere
comm_modify vel yes
boundary f f f
lattice sc 1.0 origin 0.5 0.5 0.5
region box block -2 7 -2 7 -2 7
region fill block 0 5 0 5 0 5
create_box 2 box
create_atoms 1 region fill
set group all diameter 1.04 density 1.0
set type 1 type/fraction 2 0.4 4321
displace_atoms all random 0.02 0.02 0.02 4125 units box
velocity all create 0.01 87287 loop geom
"""
TAIL = """fix 1 all nve/sphere
timestep 0.001
compute bins all chunk/atom bin/1d z lower 0.75 units box
compute pc all property/chunk bins count coord1
fix a all ave/time 100 1 100 c_pc[*] mode vector file pc.txt format " %.15g"
fix b all ave/time 100 1 100 c_f c_f[*] file f.txt format " %.17g"
thermo_style custom step c_f {cols}
thermo_modify format float %.15g
thermo 100
run 200
"""
CASES = {
    "hertz_history_all_tensors": (
        "pair_style gran/hertz/history 2000.0 NULL 50.0 NULL 0.5 1\npair_coeff * *\n",
        "compute f all fabric radius contact branch force/normal force/tangential\n", 24),
    "granular_cutoff_type": (
        "pair_style granular\n"
        "pair_coeff * * hertz 1000 50 tangential linear_history 300 1 0.5\n",
        "compute f all fabric type contact branch force/normal\n", 18),
    "type_include": (
        "pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1\npair_coeff * *\n",
        "compute f all fabric radius force/tangential contact type/include 1 1*2\n", 12),
    "type_include_cross_only": (
        "pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1\npair_coeff * *\n",
        "compute f all fabric radius contact branch type/include 1 2\n", 12),
}


def numbers(path):
    return [float(w) for line in open(path) if not line.startswith("#") for w in line.split()]


def compare(name, parent):
    pair, comp, n = CASES[name]
    deck = HEAD + pair + comp + TAIL.format(cols=" ".join("c_f[%d]" % i for i in range(1, n + 1)))
    g, lm = folders(parent, name + "_g", name + "_l")
    rc, out = run([GRAVEL], deck, g)
    got = thermo_rows(out, n + 2) if rc == 0 else []
    if shutil.which("lmp") is None:
        check(name, False, "lmp (Debian package lammps) is not installed")
        return
    _, lout = run(["lmp"], deck, lm)
    ref = thermo_rows(lout, n + 2)
    worst = max((abs(a - b) / max(abs(b), 1e-300) for r, s in zip(got, ref)
                 for a, b in zip(r, s) if not close(a, b, 0, 1e-13)), default=0.0)
    ok = len(ref) == 3 and len(got) == 3 and all(
        close(a, b, 1e-10, 1e-13) for r, s in zip(got, ref) for a, b in zip(r, s))
    check("fabric_" + name, ok and ref[0][1] > 0,
          "rows %d/%d, worst rel %g: %s" % (len(got), len(ref), worst, out[-300:]))
    if name == "hertz_history_all_tensors":
        ranks = os.path.join(parent, "ranks")
        os.mkdir(ranks)
        check_same_on_ranks("fabric_same_on_2_ranks", 2, deck, ranks, g, ["f.txt"])
        a, b = numbers(os.path.join(g, "pc.txt")), numbers(os.path.join(lm, "pc.txt"))
        check("property_chunk_file_equals_lmp", len(a) == len(b) > 10 and
              all(close(x, y, 1e-12, 1e-12) for x, y in zip(a, b)), "%s %s" % (a[:8], b[:8]))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name in CASES:
            compare(name, tmp)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        gran = ("pair_style granular\npair_coeff * * hertz 1000 50 tangential linear_history "
                "300 1 0.5\nfix 1 all nve/sphere\nthermo_style custom step c_f[1]\n")
        expect_errors({
            "fabric_err_cutoff_style": ("compute f all fabric sphere contact\n",
                                        "cutoff style must be type or radius"),
            "fabric_err_unknown": ("compute f all fabric radius contact stress\n",
                                   "unknown tensor or keyword 'stress'"),
            "fabric_err_type_range": ("compute f all fabric radius contact type/include 1 3\n",
                                      "atom type range '3' is outside 1..2"),
            "fabric_err_tangential_granular": (
                "compute f all fabric radius force/tangential\n" + gran + "run 0\n",
                "does not calculate tangential forces"),
            "fabric_err_no_pair": ("compute f all fabric radius contact\n"
                                   "thermo_style custom step c_f[1]\nrun 0\n",
                                   "no pair style is defined for compute fabric"),
        }, HEAD, err)


main()
