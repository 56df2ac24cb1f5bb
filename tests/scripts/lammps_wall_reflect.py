#!/usr/bin/env python3
"""lammps_wall_reflect.py - fix wall/reflect as LAMMPS's.

125 spheres launched at temperature 5 in a closed box (boundary f f f),
gran/hooke/history, reflected by six walls: x at EDGE, y at numbers in box
units, z from 0 and at an equal-style variable that oscillates, 2000
steps, run unchanged by `lmp` (LAMMPS 2021, one process) and bin/gravel. A
dump every 250 steps of every atom's position and velocity agrees with
lmp's to 1e-8 of the snapshot's largest value (the trajectories to ~1e-10),
and no atom is ever beyond a wall (each dump's coordinates within the
walls). On 2 and 3 MPI ranks the dump is byte-identical to one process's.
Then the errors. One line PASS/FAIL per case; without `lmp` the comparison
FAILs naming it."""
import math
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_same_on_ranks, dump_steps, expect_errors,  # noqa: E402
                  folders, run)

REL = 1e-8
HEAD = """units lj
atom_style sphere
atom_modify map array
comm_modify vel yes
boundary f f f
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 5 0 5 0 5
create_box 1 box
create_atoms 1 box
set group all diameter 0.8 density 1.0
velocity all create 5.0 4928 loop geom
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
timestep 0.001
"""
DECK = HEAD + """variable zt equal 4.6-0.3*sin(2*PI*step*dt)
fix r all wall/reflect xlo EDGE xhi EDGE ylo 0.0 yhi 5.0 units box zlo 0.0 zhi v_zt
dump 1 all custom 250 out.dump id x y z vx vy vz
dump_modify 1 sort id format float %.15g
run 2000
"""


def inside(snaps):
    """every dumped position within the walls of its step"""
    for st, atoms in snaps.items():
        zt = 4.6 - 0.3 * math.sin(2 * math.pi * st * 0.001)
        for row in atoms.values():
            if not (0 <= row[0] <= 5 and 0 <= row[1] <= 5 and 0 <= row[2] <= zt):
                return False
    return bool(snaps)


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir, m2, m3, edir = folders(tmp, "g", "l", "m2", "m3", "errors")
        rc, gout = run([GRAVEL], DECK, gdir)
        gs = dump_steps(os.path.join(gdir, "out.dump")) if rc == 0 else {}
        check("wall_reflect_run", rc == 0 and len(gs) == 9 and inside(gs),
              "exit %d: %s" % (rc, gout[-600:]))
        if shutil.which("lmp") is None:
            check("wall_reflect_match_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            ls = dump_steps(os.path.join(ldir, "out.dump")) if rc == 0 else {}
            bad = []
            for st, atoms in ls.items():
                scale = max(abs(v) for row in atoms.values() for v in row)
                bad += [(st, i, a, b) for i, row in atoms.items()
                        for a, b in zip(gs.get(st, {}).get(i, [float("nan")] * 6), row)
                        if not abs(a - b) <= REL * scale]
            check("wall_reflect_match_lammps", rc == 0 and sorted(ls) == sorted(gs) and not bad,
                  "lmp exit %d, differences %s" % (rc, bad[:3]))
        for np, mdir in ((2, m2), (3, m3)):
            check_same_on_ranks("wall_reflect_np%d_same_dump" % np, np, DECK, mdir, gdir,
                                ["out.dump"])
        expect_errors({
            "wall_reflect_needs_wall": ("fix r all wall/reflect\n", "ERROR: fix: fix wall/reflect "
                                        "needs a face (xlo xhi ylo yhi zlo zhi) and its position"),
            "wall_reflect_twice": ("fix r all wall/reflect xlo EDGE xlo 1.0\n", "fix "
                                   "wall/reflect: wall xlo defined twice"),
            "wall_reflect_keyword": ("fix r all wall/reflect xlo EDGE side in\n", "fix "
                                     "wall/reflect: unknown keyword 'side'"),
            "wall_reflect_units": ("fix r all wall/reflect xlo EDGE units metal\n", "fix "
                                   "wall/reflect: units must be box or lattice, got 'metal'"),
            "wall_reflect_variable": ("fix r all wall/reflect xlo v_nope\nrun 1\n", "fix "
                                      "wall/reflect r: variable 'nope' does not exist"),
        }, HEAD, edir)
        expect_errors({
            "wall_reflect_periodic": ("fix r all wall/reflect xlo EDGE\n", "fix wall/reflect: "
                                      "cannot use a wall in the periodic dimension x"),
        }, HEAD.replace("boundary f f f", "boundary p f f"), edir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
