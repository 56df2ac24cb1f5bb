#!/usr/bin/python3
"""create_atoms_mesh.py - create_atoms ... mesh ID d skips the sites closer
than d to a mesh.

A closed cube mesh (12 STL triangles, side 4, centred at c) and an sc
lattice of spacing 0.5 in a larger box. For create_atoms box and region
(lattice hcp and sc) the created atoms are exactly the lattice sites whose
distance to the cube's surface is >= d (counted here by brute force from
the exact point-box distance), none closer; create_atoms random with the
keyword leaves every atom >= d from the surface and still places N atoms.
The cube is moved first by fix move/mesh linear during a run: the test uses
the mesh's current pose. Prints PASS/FAIL lines."""
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
failures = 0


def report(name, ok, detail=""):
    global failures
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else "  " + detail))
    if not ok:
        failures += 1


def cube_stl(path):
    q = [((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)), ((0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)),
         ((0, 0, 0), (0, 1, 0), (0, 1, 1), (0, 0, 1)), ((1, 0, 0), (1, 0, 1), (1, 1, 1), (1, 1, 0)),
         ((0, 0, 0), (0, 0, 1), (1, 0, 1), (1, 0, 0)), ((0, 1, 0), (1, 1, 0), (1, 1, 1), (0, 1, 1))]
    with open(path, "w") as f:
        f.write("solid cube\n")
        for a, b, c, d in q:
            for tri in ((a, b, c), (a, c, d)):
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for v in tri:
                    f.write("   vertex %g %g %g\n" % tuple(4 * x - 2 for x in v))
                f.write("  endloop\n endfacet\n")
        f.write("endsolid cube\n")


def surf_dist(p, c):
    """Distance from p to the surface of the cube [c-2, c+2]^3."""
    e = [abs(p[k] - c[k]) - 2.0 for k in range(3)]
    if max(e) <= 0:
        return -max(e)
    return math.sqrt(sum(max(x, 0.0) ** 2 for x in e))


def atoms(path):
    rows = []
    lines = open(path).read().splitlines()
    i = lines.index("ITEM: ATOMS id x y z") + 1
    for l in lines[i:]:
        if l.startswith("ITEM"):
            break
        rows.append(tuple(float(v) for v in l.split()[1:4]))
    return rows


HEAD = """units lj
atom_style sphere
boundary f f f
region b block -4 4 -4 4 -4 4
create_box 1 b
fix m all mesh/surface file cube.stl type 1
fix mv all move/mesh mesh m linear 0.1 -0.05 0.2
timestep 0.01
run 10
"""
SHIFT = (0.01, -0.005, 0.02)   # v * 10 steps * 0.01


def run(d, body):
    with open(os.path.join(d, "in.deck"), "w") as f:
        f.write(HEAD + body + "write_dump all custom out.dump id x y z modify sort id format float %.17g\n")
    r = subprocess.run([GRAVEL, "-in", "in.deck", "-log", "none", "-echo", "none"], cwd=d,
                       capture_output=True, text=True, timeout=120)
    return r


def main():
    with tempfile.TemporaryDirectory() as d:
        cube_stl(os.path.join(d, "cube.stl"))
        dist = 0.35
        # lattice sites of sc 0.5 (lj: spacing (1/rho)^(1/3) -> rho = 8)
        r = run(d, "lattice sc 8.0\ncreate_atoms 1 box mesh m %g units box\n" % dist)
        report("create_atoms box mesh runs", r.returncode == 0, (r.stdout + r.stderr)[-400:])
        if r.returncode == 0:
            got = atoms(os.path.join(d, "out.dump"))
            sites = [(-4 + 0.5 * i, -4 + 0.5 * j, -4 + 0.5 * k)
                     for k in range(16) for j in range(16) for i in range(16)]
            keep = [p for p in sites if surf_dist(p, SHIFT) >= dist]
            near = min(surf_dist(p, SHIFT) for p in got)
            report("box: %d atoms = %d sites at >= %g from the moved cube (of %d)"
                   % (len(got), len(keep), dist, len(sites)), len(got) == len(keep))
            report("box: nearest atom %.4f >= %g from the surface" % (near, dist), near >= dist)
            skipped = "  %d sites skipped" % (len(sites) - len(keep))
            report("box: log counts the skipped sites", skipped in r.stdout, r.stdout[-300:])
        r = run(d, "lattice hcp 1.0\nregion in block -1.9 1.9 -1.9 1.9 -1.9 1.9 units box\n"
                   "create_atoms 1 region in mesh m 0.5\n")
        report("create_atoms region (hcp) mesh runs", r.returncode == 0, (r.stdout + r.stderr)[-400:])
        if r.returncode == 0:
            got = atoms(os.path.join(d, "out.dump"))
            # lj hcp 1.0: a = (sqrt 2 / rho)^(1/3); cell a, sqrt3 a, sqrt(8/3) a; LAMMPS's basis
            xl = math.sqrt(2.0) ** (1.0 / 3.0)
            prim = (xl, math.sqrt(3.0) * xl, math.sqrt(8.0 / 3.0) * xl)
            basis = ((0, 0, 0), (0.5, 0.5, 0), (0.5, 5.0 / 6.0, 0.5), (0, 1.0 / 3.0, 0.5))
            want = 0
            for i in range(-4, 5):
                for j in range(-3, 4):
                    for k in range(-3, 4):
                        for b in basis:
                            p = ((i + b[0]) * prim[0], (j + b[1]) * prim[1], (k + b[2]) * prim[2])
                            if all(-1.9 <= x <= 1.9 for x in p) and surf_dist(p, SHIFT) >= 0.5 * xl:
                                want += 1
            near = min(surf_dist(p, SHIFT) for p in got) if got else -1
            report("hcp region: %d atoms = %d hcp sites in the region at >= 0.5 xlattice, nearest %.4f"
                   % (len(got), want, near), len(got) == want and near >= 0.5 * xl)
        r = run(d, "create_atoms 1 random 300 4711 NULL mesh m 0.4 units box overlap 0.3\n")
        report("create_atoms random mesh runs", r.returncode == 0, (r.stdout + r.stderr)[-400:])
        if r.returncode == 0:
            got = atoms(os.path.join(d, "out.dump"))
            near = min(surf_dist(p, SHIFT) for p in got)
            report("random: 300 atoms placed, nearest %.4f >= 0.4 from the surface" % near,
                   len(got) == 300 and near >= 0.4)
        r = run(d, "create_atoms 1 single 0 0 0 mesh m 0.3\n")
        report("error: mesh with style single", r.returncode != 0 and
               "mesh applies only to styles box, region and random" in r.stdout + r.stderr)
        r = run(d, "create_atoms 1 box mesh nosuch 0.3\n")
        report("error: unknown mesh", r.returncode != 0 and "nosuch" in r.stdout + r.stderr,
               (r.stdout + r.stderr)[-300:])
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
