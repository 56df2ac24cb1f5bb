#!/usr/bin/env python3
"""bench_neighbor_multi.py - neighbor bin vs multi on polydisperse beds.

Small spheres (diameter 0.2) on a simple-cubic lattice of spacing 0.2 (each
touches six) fill a box around large spheres, the small ones nearest a large
one touching it: size ratio 10, eight of diameter 2 in an 8^3 box (60000
atoms); ratio 50, one of diameter 10 in an 11^3 box (100000 atoms).
`neigh_modify every 1 delay 0 check no` rebuilds the list every step for
`run N`. Prints, per style: atoms, neighbors (the list total),
builds, Neigh seconds and seconds per build.
Usage: tools/bench_neighbor_multi.py [steps [styles]]  (default 1, "bin,multi")
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GRAVEL = os.path.join(ROOT, "bin", "gravel")


def deck(ratio, style, steps):
    big = 0.2 * ratio
    if ratio == 10:
        L = 8.0
        centers = [(2 + 4 * i, 2 + 4 * j, 2 + 4 * k) for i in range(2) for j in range(2)
                   for k in range(2)]
    else:
        L = 11.0
        centers = [(5.5, 5.5, 5.5)]
    lines = ["units lj", "atom_style sphere", "boundary f f f",
             "region box block 0 %g 0 %g 0 %g units box" % (L, L, L), "create_box 2 box"]
    excl = []
    for n, (x, y, z) in enumerate(centers):
        lines.append("create_atoms 2 single %g %g %g units box" % (x, y, z))
        lines.append("region e%d sphere %g %g %g %g side out units box"
                     % (n, x, y, z, big / 2 + 0.1))
        excl.append("e%d" % n)
    lines += ["lattice sc 125.0",
              "region blk block 0.1 %g 0.1 %g 0.1 %g units box" % (L - 0.1, L - 0.1, L - 0.1),
              "region fill intersect %d blk %s" % (len(excl) + 1, " ".join(excl)),
              "create_atoms 1 region fill",
              "set type 1 diameter 0.2 density 1.0",
              "set type 2 diameter %g density 1.0" % big,
              "velocity all create 0.1 8811 loop geom",
              "pair_style gran/hooke/history 20000.0 NULL 50.0 NULL 0.5 1",
              "pair_coeff * *", "fix move all nve/sphere",
              "neighbor 0.02 %s" % style, "neigh_modify every 1 delay 0 check no",
              "timestep 0.0001", "thermo_style custom step atoms ke", "run %d" % steps]
    return "\n".join(lines) + "\n"


def main():
    steps = int(sys.argv[1]) if len(sys.argv) > 1 else 1
    styles = sys.argv[2].split(",") if len(sys.argv) > 2 else ["bin", "multi"]
    print("ratio style   atoms  neighbors builds  Neigh_s  s/build")
    for ratio in (10, 50):
        for style in styles:
            with tempfile.TemporaryDirectory() as d:
                with open(os.path.join(d, "in.deck"), "w") as f:
                    f.write(deck(ratio, style, steps))
                p = subprocess.run([GRAVEL, "-in", "in.deck", "-log", "none"], cwd=d,
                                   capture_output=True, text=True)
                out = p.stdout + p.stderr
                if p.returncode:
                    print(out[-600:])
                    return 1
                atoms = int(re.search(r"with (\d+) atoms", out).group(1))
                tot = int(re.search(r"Total # of neighbors = (\d+)", out).group(1))
                bld = int(re.search(r"Neighbor list builds = (\d+)", out).group(1))
                neigh = float(re.search(r"^Neigh\s+\|\s+(\S+)", out, re.M).group(1))
                print("%5d %-6s %6d %10d %6d %8.3f %8.4f" % (ratio, style, atoms, tot, bld,
                                                           neigh, neigh / max(bld, 1)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
