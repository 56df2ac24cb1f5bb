#!/usr/bin/python3
"""hm_pair_material.py - hertz/mindlin's per-type-pair material
(pair_coeff I J E nu e mu).

Bead 1 bounces obliquely on a floor of two triangles (fix mesh/surface type 2,
fix wall/pair mesh); beads 2 and 3 collide head-on and obliquely in the air.
Deck B: pair_style with material P (glass, 003 fig. 5.24 pp), pair_coeff 1 2
with material S (the shell's ps values). Deck A: S as the pair_style
material. Deck C: P everywhere. Bead 1 of B equals bead 1 of A bit for bit
(the mesh sees pair (1, 2)); beads 2 and 3 of B equal C bit for bit (pair
(1, 1) keeps P); bead 1 of A and C differ (the materials matter). Errors:
a missing I I, a malformed material."""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
failures = 0

P = "63.96e9 0.23 0.66 0.154"
S = "0.8804e9 0.42 0.55 0.32"

FLOOR = """solid floor
 facet normal 0 0 1
  outer loop
   vertex -0.05 -0.05 0
   vertex 0.05 -0.05 0
   vertex 0.05 0.05 0
  endloop
 endfacet
 facet normal 0 0 1
  outer loop
   vertex -0.05 -0.05 0
   vertex 0.05 0.05 0
   vertex -0.05 0.05 0
  endloop
 endfacet
endsolid floor
"""


def report(name, ok, detail=""):
    global failures
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else "  " + detail))
    if not ok:
        failures += 1


def deck(style, coeffs):
    return """units si
atom_style sphere
boundary f f f
region b block -0.05 0.05 -0.05 0.05 -0.01 0.09
create_box 2 b
create_atoms 1 single 0 0 0.0016 units box
create_atoms 1 single 0.02 0.02 0.05 units box
create_atoms 1 single 0.02 0.0208 0.0531 units box
set type 1 diameter 0.003 density 2500
velocity all set 0 0 0 units box
set atom 1 vx 0.3 vz -0.5
set atom 3 vz -0.8
pair_style hertz/mindlin %s
%s
neighbor 0.0005 bin
timestep 1e-7
fix m all mesh/surface file floor.stl type 2
fix w all wall/pair mesh n_meshes 1 meshes m
fix 1 all nve/sphere
run 5000
write_dump all custom out.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %%.17g
""" % (style, coeffs)


def atoms(d):
    lines = open(os.path.join(d, "out.dump")).read().splitlines()
    i = [k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS")][0]
    return {int(l.split()[0]): l.split()[1:] for l in lines[i + 1:]}


def run(d, text):
    with open(os.path.join(d, "in.deck"), "w") as f:
        f.write(text)
    return subprocess.run([GRAVEL, "-in", "in.deck", "-log", "none", "-echo", "none"], cwd=d,
                          capture_output=True, text=True, timeout=120)


def main():
    res = {}
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "floor.stl"), "w") as f:
            f.write(FLOOR)
        for name, style, coeffs in (("A", S, "pair_coeff * *"),
                                    ("B", P, "pair_coeff 1 1\npair_coeff 2 2\npair_coeff 1 2 " + S),
                                    ("C", P, "pair_coeff * *")):
            r = run(d, deck(style, coeffs))
            report("deck %s runs" % name, r.returncode == 0, (r.stdout + r.stderr)[-300:])
            if r.returncode == 0:
                res[name] = atoms(d)
        if len(res) == 3:
            A, B, C = res["A"], res["B"], res["C"]
            report("bead on the type-2 mesh: pair_coeff 1 2 material = pair_style material (bitwise)",
                   B[1] == A[1], "%s vs %s" % (B[1][:4], A[1][:4]))
            report("bead-bead (1 1) keeps the pair_style material (bitwise)",
                   B[2] == C[2] and B[3] == C[3])
            report("the two materials give different bounces (vz %s vs %s)" % (A[1][5], C[1][5]),
                   A[1] != C[1])
            report("the beads touched (bead 3 vz changed from -0.8)", float(B[3][5]) != -0.8)
        r = run(d, deck(P, "pair_coeff 1 1\npair_coeff 1 2 " + S))
        report("error: pair_coeff 2 2 missing", r.returncode != 0 and "no pair_coeff for types 2 2 of pair style hertz/mindlin"
               in r.stdout + r.stderr, (r.stdout + r.stderr)[-300:])
        r = run(d, deck(P, "pair_coeff * *\npair_coeff 1 2 1e9 0.3 0.5"))
        report("error: material with three numbers", r.returncode != 0 and
               "expects E nu e mu" in r.stdout + r.stderr and "in.deck:15" in r.stdout + r.stderr,
               (r.stdout + r.stderr)[-300:])
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
