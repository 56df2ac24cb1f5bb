#!/usr/bin/python3
"""mill_stl.py - write the ASCII STL of a tumbling mill's shell with lifters.

    mill_stl.py OUT.stl [--diameter D] [--length L] [--lifters K]
                        [--height H] [--top W] [--base B] [--arc-facets M]
                        [--overhang O] [--plates]

The shell is the inner surface of a drum of diameter D about the z axis,
from z = -O to L + O (open ends: use a periodic z of length L for an axial
slice), or closed by two end plates at z = 0 and z = L (--plates; the
overhang is then 0): fans of triangles from the axis to every profile
point, so the plates follow the lifters and have the shell's material
(the mesh's type). Its profile is K identical lifters,
evenly spaced with the first centred at the bottom (angle -90 degrees),
joined by shell arcs of M flat facets each with vertices on the circle of
radius D/2. Each lifter is a trapezoidal bar along the whole length: a base
B wide on the shell (chord), a flat top W wide at H in from the shell, and
two flank faces: the three-faces-per-lifter profile of Hromnik's pilot mill
mesh (003 fig. 5.13/5.14: 96 triangles = 48 profile segments = 12 lifters x
(3 lifter faces + 1 shell segment)). Every profile segment becomes two
triangles; normals point into the mill (towards the charge), as fix
mesh/surface expects. Defaults: the 300 mm pilot mill of 003 sec. 6.2 with
the lifters chosen in doc/mill.md (12 lifters, H = 12 mm, W = 10 mm,
B = 20 mm, 18 facets per arc: 12 x (18 + 3) = 252 profile segments, near
the 259 lines of 003's profile). Prints the triangle count."""
import argparse
import math


def profile(R, K, H, W, B, M):
    """Profile points, counterclockwise (interior on the left)."""
    pts = []
    beta = 2 * math.asin(min(1.0, B / (2 * R)))           # base chord -> angle
    gamma = 2 * math.asin(min(1.0, W / (2 * (R - H))))    # top chord at R - H
    for k in range(K):
        phi = -math.pi / 2 + 2 * math.pi * k / K
        nxt = -math.pi / 2 + 2 * math.pi * (k + 1) / K
        if K > 0 and H > 0:
            pts.append((R * math.cos(phi - beta / 2), R * math.sin(phi - beta / 2)))
            rt = R - H
            pts.append((rt * math.cos(phi - gamma / 2), rt * math.sin(phi - gamma / 2)))
            pts.append((rt * math.cos(phi + gamma / 2), rt * math.sin(phi + gamma / 2)))
            a0, a1 = phi + beta / 2, nxt - beta / 2
        else:
            a0, a1 = phi, nxt
        for m in range(M):
            a = a0 + (a1 - a0) * m / M
            pts.append((R * math.cos(a), R * math.sin(a)))
    return pts


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--diameter", type=float, default=0.3)
    p.add_argument("--length", type=float, default=0.27)
    p.add_argument("--lifters", type=int, default=12)
    p.add_argument("--height", type=float, default=0.012)
    p.add_argument("--top", type=float, default=0.010)
    p.add_argument("--base", type=float, default=0.020)
    p.add_argument("--arc-facets", type=int, default=18)
    p.add_argument("--overhang", type=float, default=0.0015)
    p.add_argument("--plates", action="store_true")
    a = p.parse_args()
    R = 0.5 * a.diameter
    if a.lifters < 0 or a.arc_facets < 1 or not (0 <= a.height < R):
        p.error("need lifters >= 0, arc-facets >= 1 and 0 <= height < D/2")
    if a.lifters > 0 and a.height > 0 and not (0 < a.top < a.base < 2 * math.pi * R / a.lifters):
        p.error("need 0 < top < base < the lifter pitch")
    K = a.lifters if a.lifters > 0 else 1
    pts = profile(R, K, a.height if a.lifters > 0 else 0.0, a.top, a.base,
                  a.arc_facets if a.lifters > 0 else a.arc_facets)
    o = 0.0 if a.plates else a.overhang
    z0, z1 = -o, a.length + o
    tris = []
    n = len(pts)
    for i in range(n):
        (x0, y0), (x1, y1) = pts[i], pts[(i + 1) % n]
        # p_i -> p_i+1 counterclockwise: (p1, p0, p0 + L, p1 + L) has the inward normal
        tris.append(((x1, y1, z0), (x0, y0, z0), (x0, y0, z1)))
        tris.append(((x1, y1, z0), (x0, y0, z1), (x1, y1, z1)))
    if a.plates:  # normals +z at z = 0 and -z at z = L: into the mill
        for i in range(n):
            (x0, y0), (x1, y1) = pts[i], pts[(i + 1) % n]
            tris.append(((0.0, 0.0, 0.0), (x0, y0, 0.0), (x1, y1, 0.0)))
            tris.append(((0.0, 0.0, a.length), (x1, y1, a.length), (x0, y0, a.length)))
    with open(a.out, "w") as fp:
        fp.write("solid mill\n")
        for t in tris:
            e1 = [t[1][k] - t[0][k] for k in range(3)]
            e2 = [t[2][k] - t[0][k] for k in range(3)]
            nv = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                  e1[0] * e2[1] - e1[1] * e2[0])
            ln = math.sqrt(sum(c * c for c in nv))
            fp.write(" facet normal %.9g %.9g %.9g\n  outer loop\n" % tuple(c / ln for c in nv))
            for v in t:
                fp.write("   vertex %.9g %.9g %.9g\n" % v)
            fp.write("  endloop\n endfacet\n")
        fp.write("endsolid mill\n")
    print("%s: %d profile segments, %d triangles" % (a.out, n, len(tris)))


if __name__ == "__main__":
    main()
