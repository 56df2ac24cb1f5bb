#!/usr/bin/env python3
"""lammps_random.py - gravel draws LAMMPS's random numbers, bit for bit.

Each case is a small deck run unchanged by both `lmp` (LAMMPS 2021, one
process) and bin/gravel. It builds atoms with create_atoms (lattice, random N
seed NULL or region, interior and `side out`), changes types with set type/fraction,
type/ratio and type/subset, and gives velocities with velocity create in
every loop mode (all, local, geom), both distributions, mom and rot, sum, on
a subgroup, in lj and si units. Both write one snapshot (write_dump custom id
type x y z vx vy vz, %.17g). The test compares per atom ID: same atom count,
same IDs and types, and every value within 1e-12 relative
(|a - b| <= 1e-12 max(1e-300, |b|) + 1e-300); in practice they are
identical. A last case prints random()/normal() of equal-style variables
(LAMMPS's RanMars) and compares the printed numbers the same way (LAMMPS
2021 passes v_name through a %.15g string inside formulas, so the %.17g
line agrees to ~1e-15, not to the bit). LAMMPS 2021 has no create_atoms
overlap/maxtry (gravel's follow later LAMMPS), so no case uses them.

One line PASS/FAIL per case. When `lmp` is missing the cases FAIL naming it
(tools/deps.sh installs the Debian package lammps)."""
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REL = 1e-12

HEAD = """units {units}
atom_style sphere
boundary {bnd}
lattice sc {lat}
region box block 0 6 0 5 0 4
create_box 3 box
"""
TAIL = "write_dump all custom d.out id type x y z vx vy vz modify format float %.17g\n"

CASES = {
    # loop all (LAMMPS's default), uniform, lattice + random atoms of 2 sizes
    "loop_all_uniform": """create_atoms 1 box
create_atoms 2 random 25 4567 NULL
set type 2 diameter 0.7 density 2.5
velocity all create 1.5 87287
""",
    "loop_all_gaussian_rot": """create_atoms 1 box
create_atoms 2 random 17 991 NULL
set type 2 mass 3.25
velocity all create 0.8 12345 dist gaussian rot yes
""",
    "loop_local": """create_atoms 1 box
create_atoms 2 random 30 77 NULL
velocity all create 2.0 4711 loop local dist gaussian
""",
    "loop_geom": """create_atoms 1 box
set atom 10*40 diameter 0.6 density 3
velocity all create 1.0 87287 loop geom
""",
    "loop_geom_gaussian_mom_no": """create_atoms 1 box
velocity all create 3.0 5 loop geom dist gaussian mom no
""",
    "subgroup_sum": """create_atoms 1 box
region half block 0 3 INF INF INF INF
group left region half
velocity all set 0.25 -0.5 1.0
velocity left create 1.2 31415 sum yes rot yes
""",
    "random_region": """region ball sphere 3 2.5 2 1.9
create_atoms 1 random 60 8765 ball
region cyl cylinder z 3 2.5 1.0 0.5 3.5 side out
create_atoms 2 random 40 2020 cyl
velocity all create 1.0 99 loop all dist gaussian
""",
    "set_type_random": """create_atoms 1 box
set type 1 type/fraction 2 0.3 1234
set type 1 type/ratio 3 0.25 4321
set group all type/subset 1 17 999
velocity all create 1.0 2468 loop geom
""",
    "si_units": """create_atoms 1 box
set type 1 diameter 0.004 density 2500
velocity all create 300.0 13579 dist gaussian
""",
}
PARAMS = {"units": "lj", "bnd": "p p f", "lat": "1.0"}
SPECIAL = {"si_units": {"units": "si", "bnd": "p p p", "lat": "0.005"},
           "random_region": {"units": "lj", "bnd": "f f f", "lat": "1.0"}}

VARDECK = """variable a equal random(-2.5,7.0,271828)
variable b equal normal(1.0,0.3,5)
variable c equal random(0,1,17)
print "R ${a} ${b} ${c} ${a} ${b} ${c}"
print "R $(v_a:%.17g) $(v_b:%.17g) $(v_c:%.17g)"
"""


def read_dump(path):
    """{id: [type, x, y, z, vx, vy, vz]} of a one-frame LAMMPS dump."""
    lines = open(path).read().split("\n")
    n = int(lines[3])
    j = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    rows = {}
    for line in lines[j + 1:j + 1 + n]:
        w = line.split()
        rows[int(w[0])] = [int(w[1])] + [float(x) for x in w[2:]]
    return rows


def close(a, b):
    return abs(a - b) <= REL * max(1e-300, abs(b)) + 1e-300


def run(cmd, cwd):
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=120)


def compare_dumps(name, tmp, deck):
    out = {}
    for engine, cmd in (("lmp", ["lmp", "-in", "in.deck", "-log", "none"]),
                        ("gravel", [GRAVEL, "-in", "in.deck", "-log", "none"])):
        d = os.path.join(tmp, name + "_" + engine)
        os.makedirs(d)
        open(os.path.join(d, "in.deck"), "w").write(deck)
        r = run(cmd, d)
        if r.returncode != 0 or not os.path.exists(os.path.join(d, "d.out")):
            return "%s failed: %s" % (engine, (r.stdout + r.stderr).strip()[-300:])
        out[engine] = read_dump(os.path.join(d, "d.out"))
    l, g = out["lmp"], out["gravel"]
    if sorted(l) != sorted(g):
        return "atom IDs differ: lmp %d atoms, gravel %d" % (len(l), len(g))
    worst, nval = 0.0, 0
    for i in l:
        if l[i][0] != g[i][0]:
            return "atom %d: type %d in lmp, %d in gravel" % (i, l[i][0], g[i][0])
        for k in range(1, 7):
            nval += 1
            if not close(g[i][k], l[i][k]):
                return "atom %d column %d: lmp %.17g gravel %.17g" % (i, k, l[i][k], g[i][k])
            if l[i][k] != 0:
                worst = max(worst, abs(g[i][k] - l[i][k]) / abs(l[i][k]))
    return (len(l), nval, worst)


def main():
    if not os.access(GRAVEL, os.X_OK):
        print("FAIL lammps_random (bin/gravel missing: run make)")
        return 1
    if not shutil.which("lmp"):
        print("FAIL lammps_random (lmp not found: apt-get install -y lammps)")
        return 1
    fails = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, body in CASES.items():
            p = dict(PARAMS, **SPECIAL.get(name, {}))
            res = compare_dumps(name, tmp, HEAD.format(**p) + body + TAIL)
            if isinstance(res, str):
                print("FAIL lammps_random_%s (%s)" % (name, res))
                fails += 1
            else:
                print("PASS lammps_random_%s (%d atoms, %d values, max rel diff %.1e)"
                      % ((name,) + res))
        # equal-style random()/normal(): LAMMPS's RanMars
        got = {}
        for engine, cmd in (("lmp", ["lmp", "-in", "in.var", "-log", "none"]),
                            ("gravel", [GRAVEL, "-in", "in.var", "-log", "none"])):
            d = os.path.join(tmp, "var_" + engine)
            os.makedirs(d)
            open(os.path.join(d, "in.var"), "w").write(VARDECK)
            r = run(cmd, d)
            got[engine] = [l.split()[1:] for l in r.stdout.split("\n") if l.startswith("R ")]
        l, g = got["lmp"], got["gravel"]
        ok = len(l) == 2 and len(g) == 2 and all(
            len(a) == len(b) and all(close(float(x), float(y)) for x, y in zip(a, b))
            for a, b in zip(g, l))
        print("%s lammps_random_variables (lmp %s, gravel %s)"
              % ("PASS" if ok else "FAIL", l, g))
        fails += not ok
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
