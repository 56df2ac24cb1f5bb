#!/usr/bin/python3
"""mesh_drum.py - write an ASCII STL of a drum with lifter bars, for mesh walls.

    mesh_drum.py OUT.stl [--radius R] [--length L] [--facets N] [--lifters K]
                         [--height H] [--width W]

The drum is a prism of N flat facets about the z axis from z = 0 to L, each
facet tangent to the circle of radius R at its middle (vertices at
R / cos(pi / N)); the ends are open (use a periodic z of length L, or add
walls). K lifters, evenly spaced from angle -90 degrees (the bottom), are
triangular bars along the whole length: base W wide on the shell, apex H in
from it. Each facet is split into two triangles; the normals point inwards.
"""
import argparse
import math


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--radius", type=float, default=8.0)
    p.add_argument("--length", type=float, default=6.0)
    p.add_argument("--facets", type=int, default=48)
    p.add_argument("--lifters", type=int, default=6)
    p.add_argument("--height", type=float, default=1.0)
    p.add_argument("--width", type=float, default=1.2)
    a = p.parse_args()
    R, L, n = a.radius, a.length, a.facets
    tris = []

    def quad(p0, p1, q1, q0):
        # p0 p1 at z = 0, q0 q1 at z = L; counterclockwise seen from the axis
        tris.append((p0, p1, q1))
        tris.append((p0, q1, q0))

    rv = R / math.cos(math.pi / n)
    for f in range(n):
        a0 = 2 * math.pi * (f - 0.5) / n - math.pi / 2
        a1 = 2 * math.pi * (f + 0.5) / n - math.pi / 2
        c0, c1 = (rv * math.cos(a0), rv * math.sin(a0)), (rv * math.cos(a1), rv * math.sin(a1))
        quad((*c1, 0.0), (*c0, 0.0), (*c0, L), (*c1, L))
    for k in range(a.lifters):
        phi = -math.pi / 2 + 2 * math.pi * k / max(a.lifters, 1)
        dphi = 0.5 * a.width / R
        b0 = (R * math.cos(phi - dphi), R * math.sin(phi - dphi))
        b1 = (R * math.cos(phi + dphi), R * math.sin(phi + dphi))
        top = ((R - a.height) * math.cos(phi), (R - a.height) * math.sin(phi))
        quad((*top, 0.0), (*b0, 0.0), (*b0, L), (*top, L))
        quad((*b1, 0.0), (*top, 0.0), (*top, L), (*b1, L))
    with open(a.out, "w") as fp:
        fp.write("solid drum\n")
        for t in tris:
            fp.write("  facet normal 0 0 0\n    outer loop\n")
            for v in t:
                fp.write("      vertex %.9g %.9g %.9g\n" % v)
            fp.write("    endloop\n  endfacet\n")
        fp.write("endsolid drum\n")


if __name__ == "__main__":
    main()
