#!/usr/bin/python3
"""bench_mesh.py - cost of a mesh contact against a particle-particle contact.

    bench_mesh.py [--n SIDE] [--tri-side Q] [--steps S] [--repeat R]

A square monolayer of SIDE x SIDE spheres (diameter 1, spacing 0.98: every
sphere overlaps its 4 neighbours) rests in a floor of Q x Q/2 quads = Q^2
triangles (default 100: 10^4 triangles), overlapping it by 0.02: every sphere
has one mesh contact (on a face, an edge or a vertex; counted once). Nothing
moves (no integrator), so the contact sets are fixed and every step evaluates
the same contacts: run A has the pair style (hertz/mindlin) and the mesh
wall (fix wall/pair mesh, the same law), B the pair style only, C neither
(pair_style none). Per step and contact, medians of R interleaved runs:
    mesh contact  = (A - B) / mesh contacts
    pair contact  = (B - C) / pair contacts
(loop times of `run S`). --law hooke/history uses LAMMPS's gran/hooke/history
with fix wall/gran hooke/history ... mesh instead (no impulse solver). Prints
a table for doc/benchmark.md."""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GRAVEL = os.path.join(ROOT, "bin", "gravel")


def floor_stl(path, lo, hi, q):
    """Q x Q/2 rectangles of 2 triangles over [lo, hi]^2 at z = 0 (normal +z)."""
    nx, ny = q, q // 2
    with open(path, "w") as f:
        f.write("solid floor\n")
        for j in range(ny):
            for i in range(nx):
                x0 = lo + (hi - lo) * i / nx
                x1 = lo + (hi - lo) * (i + 1) / nx
                y0 = lo + (hi - lo) * j / ny
                y1 = lo + (hi - lo) * (j + 1) / ny
                for t in (((x0, y0), (x1, y0), (x1, y1)), ((x0, y0), (x1, y1), (x0, y1))):
                    f.write(" facet normal 0 0 1\n  outer loop\n")
                    for v in t:
                        f.write("   vertex %.12g %.12g 0\n" % v)
                    f.write("  endloop\n endfacet\n")
        f.write("endsolid floor\n")
    return 2 * nx * ny


LAWS = {
    # law: (pair_style line, wall fix line)
    "hertz/mindlin": ("pair_style hertz/mindlin 1e6 0.3 0.5 0.5",
                      "fix w all wall/pair mesh n_meshes 1 meshes m"),
    "hooke/history": ("pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1",
                      "fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 1 mesh "
                      "n_meshes 1 meshes m"),
}


def deck(n, mode, steps, law="hertz/mindlin"):
    a = 0.98
    L = n * a
    pl, wl = LAWS[law]
    pair = "pair_style none" if mode == "C" else pl + "\npair_coeff * *"
    wall = ("fix m all mesh/surface file floor.stl type 1\n" + wl + "\n") if mode == "A" else ""
    return """units lj
atom_style sphere
boundary p p f
lattice sc 1.0 spacing %g %g 1 origin 0.5 0.5 0
region b block 0 %g 0 %g -1 2 units box
create_box 1 b
region layer block 0 %g 0 %g 0.47 0.49 units box
lattice sc 1.0 spacing %g %g 1 origin 0.5 0.5 0.48
create_atoms 1 region layer
set type 1 diameter 1.0 density 1.0
%s
neighbor 0.1 bin
neigh_modify every 1 delay 0 check yes
timestep 0.0001
%sthermo %d
thermo_style custom step atoms
run %d
""" % (a, a, L, L, L, L, a, a, pair, wall, steps, steps)


def run(d, text):
    with open(os.path.join(d, "in.deck"), "w") as f:
        f.write(text)
    r = subprocess.run([GRAVEL, "-in", "in.deck", "-log", "none", "-echo", "none"], cwd=d,
                       capture_output=True, text=True, timeout=1200)
    if r.returncode:
        sys.exit("gravel failed:\n" + r.stdout[-2000:] + r.stderr[-2000:])
    out = r.stdout
    loop = float(re.search(r"Loop time of ([0-9.eE+-]+)", out).group(1))
    m = re.search(r"Contacts = (\d+)", out)
    return loop, int(m.group(1)) if m else 0, out


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--n", type=int, default=316)
    p.add_argument("--tri-side", type=int, default=100)
    p.add_argument("--steps", type=int, default=100)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--law", choices=sorted(LAWS), default="hertz/mindlin")
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as d:
        L = a.n * 0.98
        ntri = floor_stl(os.path.join(d, "floor.stl"), -0.5, L + 0.5, a.tri_side)
        t = {"A": [], "B": [], "C": []}
        npair = 0
        for k in range(a.repeat):
            for mode in "ABC":
                loop, nc, out = run(d, deck(a.n, mode, a.steps, a.law))
                t[mode].append(loop)
                if mode == "B":
                    npair = nc
        natoms = a.n * a.n
        mA, mB, mC = (statistics.median(t[m]) for m in "ABC")
        mesh_c = natoms          # every sphere touches the floor once
        per_mesh = (mA - mB) / (mesh_c * a.steps)
        per_pair = (mB - mC) / (npair * a.steps)
        print("law %s" % a.law)
        print("spheres %d, triangles %d, mesh contacts %d, pair contacts %d, steps %d, repeats %d"
              % (natoms, ntri, mesh_c, npair, a.steps, a.repeat))
        print("loop times (s): A %s  B %s  C %s" % (t["A"], t["B"], t["C"]))
        print("| run | loop time (median) |\n|---|---|")
        print("| A pair + mesh wall | %.3f s |\n| B pair only | %.3f s |\n| C neither | %.3f s |"
              % (mA, mB, mC))
        print("mesh contact: %.1f ns per contact-step; pair contact: %.1f ns per contact-step; "
              "ratio mesh/pair %.2f" % (1e9 * per_mesh, 1e9 * per_pair, per_mesh / per_pair))


if __name__ == "__main__":
    main()
