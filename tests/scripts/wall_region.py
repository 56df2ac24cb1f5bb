#!/usr/bin/env python3
"""wall_region.py - fix wall/gran/region, region move/rotate/open and
pair_style hybrid: what the reference decks (tests/reference/wall_gran_region/wall_region_*,
pair_hybrid, compared with LAMMPS dumps by physics_lammps.py) do not cover.

1. A single sphere at rest on the floor of a block container (hooke, no
   friction, no damping) rests at the overlap m g / kn: its height is
   zlo + r - m g / kn to 1e-9 after 4000 steps.
2. A sphere in a rotating block (rotate v_theta about z): the region's
   surface velocity is its angular velocity times the axis (LAMMPS
   Region::set_velocity): a sphere that does not spin (fix nve) on the floor
   of a block turning at w about z, with friction (mu g > w^2 r), is carried
   round at the floor's speed w r (to 2 %).
3. A moving region (move v_x NULL NULL with x = A sin wt) used by group
   region and create_atoms matches in its displaced frame at the current
   step.
4. Restart: a rotating region wall continues exactly: run 60 equals run 30 +
   write_restart + read_restart in a fresh process + run 30 (the per-atom
   wall history travels with the atoms; the region's previous angle is kept
   in the fix's restart state as LAMMPS keeps it): the step-60 kinetic
   energy agrees in all 15 printed digits.
5. Bad input stops with a message naming the line: an unknown region, a
   region that cannot be a wall (union of a union), open on a sphere, open
   face 4 of a cylinder, move on a union, a deleted region at run, a missing
   rotate variable, wiggle on wall/gran/region, pair_style hybrid with an
   unknown sub-style in pair_coeff and an unset cross pair of two sub-styles.
One PASS/FAIL line per check."""
import math
import os
import re
import subprocess
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")

HEAD = """units lj
atom_style sphere
boundary f f f
region box block -10 10 -10 10 -10 10 units box
create_box 2 box
"""


def run(deck, tmp):
    path = os.path.join(tmp, "in.deck")
    with open(path, "w") as f:
        f.write(deck)
    return subprocess.run([GRAVEL, "-in", path, "-log", "none"], cwd=tmp, capture_output=True,
                          text=True, timeout=120)


def check(name, ok, detail):
    print(f"  {name}: {detail}")
    print(f"{'PASS' if ok else 'FAIL'} {name}")


def last_dump(tmp):
    rows = {}
    lines = open(os.path.join(tmp, "out.dump")).read().split("\n")
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    for l in lines[start + 1:]:
        w = l.split()
        if w:
            rows[int(w[0])] = [float(v) for v in w[1:]]
    return rows


def resting(tmp):
    kn, r, rho, g = 1.0e5, 0.5, 1.0, 1.0
    m = rho * 4.0 / 3.0 * math.pi * r ** 3
    deck = HEAD + f"""create_atoms 1 single 0 0 -5.4 units box
set type 1 diameter {2 * r} density {rho}
pair_style gran/hooke {kn} NULL 0 NULL 0 0
pair_coeff * *
region cup block -6 6 -6 6 -6 6 units box
fix w all wall/gran/region hooke {kn} NULL 500.0 NULL 0 1 region cup
fix 1 all nve/sphere
fix 2 all gravity {g} vector 0 0 -1
timestep 0.002
dump d all custom 1500 out.dump id z vz
dump_modify d format float %.15g
run 1500
"""
    res = run(deck, tmp)
    if res.returncode != 0:
        return check("wall_region_resting_overlap", False, res.stdout[-400:] + res.stderr[-400:])
    z = last_dump(tmp)[1][0]
    want = -6 + r - m * g / kn
    check("wall_region_resting_overlap", abs(z - want) < 1e-9,
          f"z = {z:.12f}, zlo + r - m g / kn = {want:.12f}")


def carried(tmp):
    w = 0.3
    deck = HEAD + f"""create_atoms 1 single 3 0 -5.45 units box
set type 1 diameter 1.0 density 1.0
pair_style gran/hooke/history 1e5 NULL 50 NULL 0.5 1
pair_coeff * *
variable theta equal step*dt*{w}
region cup block -6 6 -6 6 -6 6 units box rotate v_theta 0 0 0 0 0 1
fix w all wall/gran/region hooke/history 1e5 NULL 50 NULL 0.8 1 region cup
fix 1 all nve
fix 2 all gravity 1.0 vector 0 0 -1
timestep 0.002
dump d all custom 2500 out.dump id x y z vx vy vz
dump_modify d format float %.15g
run 2500
"""
    res = run(deck, tmp)
    if res.returncode != 0:
        return check("wall_region_rotating_floor", False, res.stdout[-400:] + res.stderr[-400:])
    x, y, z, vx, vy, vz = last_dump(tmp)[1]
    rad = math.hypot(x, y)
    speed = math.hypot(vx, vy)
    check("wall_region_rotating_floor", abs(speed - w * rad) < 0.02 * w * rad,
          f"speed {speed:.5f} vs w r = {w * rad:.5f} (r = {rad:.4f}, vz = {vz:.2e})")


def moving_match(tmp):
    deck = HEAD + """variable dx equal 4.0*sin(0.25*PI)
region slab block -1 1 -10 10 -10 10 units box move v_dx NULL NULL
create_atoms 1 single 2.9 0 0 units box
create_atoms 1 single 0 1 0 units box
group moved region slab
create_atoms 2 random 200 12345 slab
variable n equal count(moved)
print "MOVED ${n}"
write_dump all custom out.dump id type x
"""
    res = run(deck, tmp)
    if res.returncode != 0:
        return check("region_move_match", False, res.stdout[-400:] + res.stderr[-400:])
    m = re.search(r"MOVED (\d+)", res.stdout)
    rows = last_dump(tmp)
    lo, hi = 4 * math.sin(math.pi / 4) - 1, 4 * math.sin(math.pi / 4) + 1
    inside = all(lo <= v[1] <= hi for k, v in rows.items() if v[0] == 2)
    n2 = sum(1 for v in rows.values() if v[0] == 2)
    ok = m is not None and m.group(1) == "1" and inside and n2 == 200
    check("region_move_match", ok, f"group count {m.group(1) if m else None} (want 1), "
          f"{n2} random atoms all in x [{lo:.3f}, {hi:.3f}]: {inside}")


RS_SETUP = """variable theta equal step*(4.0*PI/300)
region cup block -3 3 -3 3 -3 3 units box rotate v_theta 0 0 0 0 0 1
fix w all wall/gran/region hooke/history 4000.0 NULL 100.0 NULL 0.5 1 region cup
fix 1 all nve/sphere
fix 2 all gravity 1.0 vector 0 0 -1
timestep 0.005
thermo 30
thermo_style custom step ke
thermo_modify format float %20.15g
"""


def restart(tmp):
    make = HEAD + """region inner block -2 2 -2 2 -2 2 units box
lattice sc 0.5
create_atoms 1 region inner
set type 1 diameter 1.0 density 1.0
velocity all create 1.0 4928 loop geom
pair_style gran/hooke/history 4000.0 NULL 100.0 NULL 0.5 1
pair_coeff * *
""" + RS_SETUP
    full = run(make + "run 60\n", tmp)
    half = run(make + "run 30\nwrite_restart rs.bin\n", tmp)
    rest = run("read_restart rs.bin\npair_style gran/hooke/history 4000.0 NULL 100.0 NULL 0.5 1\n"
               "pair_coeff * *\n" + RS_SETUP + "run 30\n", tmp)

    def ke60(res):
        m = re.search(r"^\s*60\s+(\S+)\s*$", res.stdout, re.M)
        return m.group(1) if m else None

    a, b = ke60(full), ke60(rest)
    ok = half.returncode == 0 and a is not None and a == b
    check("wall_region_restart_exact", ok, f"run 60: {a}, run 30 + restart + run 30: {b}")


ERRORS = [
    ("unknown_region", "fix w all wall/gran/region hooke 1e5 NULL 0 NULL 0 0 region nope\n",
     "unknown region 'nope'"),
    ("nested_union", """region a sphere 0 0 0 2
region b sphere 1 0 0 2
region c sphere 5 0 0 1
region ab union 2 a b
region abc union 2 ab c
fix w all wall/gran/region hooke 1e5 NULL 0 NULL 0 0 region abc
run 1
""", "cannot be a wall"),
    ("open_sphere", "region s sphere 0 0 0 2 open 1\n", "has no faces to open"),
    ("open_cyl_face4", "region c cylinder z 0 0 2 -1 1 open 4\n", "cannot open face 4"),
    ("move_union", """variable x equal 1
region a sphere 0 0 0 2
region b sphere 1 0 0 2
region ab union 2 a b move v_x NULL NULL
""", "cannot move or rotate"),
    ("deleted_region", """region cup block -6 6 -6 6 -6 6
fix w all wall/gran/region hooke 1e5 NULL 0 NULL 0 0 region cup
region cup delete
run 1
""", "does not exist"),
    ("missing_variable", """region cup block -6 6 -6 6 -6 6 rotate v_th 0 0 0 0 0 1
fix w all wall/gran/region hooke 1e5 NULL 0 NULL 0 0 region cup
run 1
""", "variable 'th'"),
    ("region_wiggle", """region cup block -6 6 -6 6 -6 6
fix w all wall/gran/region hooke 1e5 NULL 0 NULL 0 0 region cup wiggle z 1 1
""", "no wiggle or shear"),
    ("hybrid_unknown_sub", """pair_style hybrid gran/hooke 1e5 NULL 0 NULL 0 0
pair_coeff * * gran/hertz/history
""", "is not a sub-style"),
    ("hybrid_cross_unset", """pair_style hybrid gran/hooke 1e5 NULL 0 NULL 0 0 gran/hooke/history 1e5 NULL 0 NULL 0 0
pair_coeff 1 1 gran/hooke
pair_coeff 2 2 gran/hooke/history
run 1
""", "no pair_coeff for types 1 2"),
]


def errors(tmp):
    pre = HEAD + "create_atoms 1 single 0 0 0 units box\nset type 1 diameter 1 density 1\n"
    pre_pair = "pair_style gran/hooke 1e5 NULL 0 NULL 0 0\npair_coeff * *\nfix 1 all nve/sphere\n"
    for name, body, want in ERRORS:
        deck = pre + ("" if body.startswith("pair_style") else pre_pair) + body
        if body.startswith("pair_style"):
            deck += "fix 1 all nve/sphere\n"
        res = run(deck, tmp)
        out = res.stdout + res.stderr
        line = re.search(r"ERROR: .*in\.deck:(\d+)\)", out)
        ok = res.returncode != 0 and want in out and line is not None
        msg = out.strip().split("\n")
        msg = [l for l in msg if "ERROR" in l]
        check(f"wall_region_error_{name}", ok, msg[0] if msg else out[-300:])


def main():
    with tempfile.TemporaryDirectory() as tmp:
        resting(tmp)
        carried(tmp)
        moving_match(tmp)
        restart(tmp)
        errors(tmp)


if __name__ == "__main__":
    main()
