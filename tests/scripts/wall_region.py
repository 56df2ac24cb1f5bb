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
6. Region walls run in sets (one launch for up to 4 walls of one law in a
   row): nine walls of two laws (rotating, moving, a group, a union,
   `contacts`, a run of five cut 4 + 1) and two conducting walls give the
   bits of one launch per wall (GRAVEL_FUSE=0) in both precisions, with
   fewer launches per step.
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


def run(deck, tmp, env=None, args=()):
    path = os.path.join(tmp, "in.deck")
    with open(path, "w") as f:
        f.write(deck)
    return subprocess.run([GRAVEL, "-in", path, "-log", "none", *args], cwd=tmp,
                          capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, **(env or {})))


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


GRANW = ("wall/gran/region granular hertz/material {E} 0.1 0.3 tangential mindlin NULL 1.0 {mu} "
         "damping tsuji region {reg}")
SETS = HEAD + """region fill block -4.5 4.5 -4.5 4.5 -3 6 units box
lattice sc 1.3
create_atoms 1 region fill
set type 1 type/fraction 2 0.5 4821
set group all diameter 1.0 density 1.0
velocity all create 4.0 8731 loop geom
group g1 type 1
pair_style granular
pair_coeff * * hertz/material 1e5 0.2 0.3 tangential mindlin NULL 1.0 0.5 damping tsuji
variable theta equal 2*PI*elapsed/4000
variable zf equal -5+0.5*sin(2*PI*elapsed/1000)
region cyl cylinder z 0 0 6 -6 8 side in rotate v_theta 0 0 0 0 0 1 units box
region floor plane 0 0 0 0 0 1 side in move NULL NULL v_zf units box
region ball sphere 0 0 0 1.5 side out units box
region post cylinder z 3 0 0.7 -6 8 side out units box
region lid plane 0 0 7 0 0 -1 side in units box
region u1 sphere 2 2 2 1.0 side out units box
region u2 sphere -2 -2 2 1.0 side out units box
region u union 2 u1 u2
region b1 block -3.5 -2.5 2 3 -6 8 side out units box
region b2 block 2.5 3.5 -3 -2 -6 8 side out units box
region b3 cone z -3 3 0.5 1.0 -5 0 side out units box
fix 1 all nve/sphere
fix w1 all {w1}
fix w2 all {w2} contacts
fix w3 g1 {w3}
fix w4 all wall/gran/region hooke/history 2000 NULL 50 NULL 0.5 1 region post
fix w5 all {w5}
fix w6 all {w6}
fix w7 all {w7}
fix w8 all {w8}
fix w9 all {w9}
fix grav all gravity 10 vector 0 0 -1
compute ke all ke
thermo_style custom step atoms c_ke
thermo_modify format float %.17g
thermo 500
timestep 0.0005
dump d all custom 500 out.dump id x y z vx vy vz fx fy fz omegax omegay omegaz f_w2[1] f_w2[2] f_w2[5]
dump_modify d sort id format float %.17g
run 2000
""".format(w1=GRANW.format(E="1e5", mu="0.5", reg="cyl"),
           w2=GRANW.format(E="1e5", mu="0.5", reg="floor"),
           w3=GRANW.format(E="1e5", mu="0.5", reg="ball"),
           w5=GRANW.format(E="1e5", mu="0.5", reg="lid"),
           w6=GRANW.format(E="2e5", mu="0.4", reg="u"),
           w7=GRANW.format(E="1e5", mu="0.5", reg="b1"),
           w8=GRANW.format(E="1e5", mu="0.5", reg="b2"),
           w9=GRANW.format(E="1e5", mu="0.3", reg="b3"))

HEATW = ("wall/gran/region granular hooke 1000.0 0.0 tangential linear_history 100.0 0.0 0.5 "
         "heat radius 2.0 region {reg} temperature {T}")
SETS_HEAT = """units lj
atom_style sphere
boundary f f f
region box block -2 2 -2 2 -2 2 units box
create_box 1 box
create_atoms 1 single 0 0 -1.51 units box
create_atoms 1 single 1.41 0 0 units box
set group all diameter 1.0 density 1.0
fix prop all property/atom temperature heatflow
set group all temperature 0.25
pair_style granular
pair_coeff * * hooke 1000.0 0.0 tangential linear_history 100.0 0.0 0.5
region floor block -1.9 1.9 -1.9 1.9 -2 2 units box
region side plane 1.9 0 0 -1 0 0 side in units box
variable Tw equal 2.0+0.001*step
fix wf all {wf}
fix ws all {ws}
fix hf all heat/flow constant 2.0
timestep 0.001
dump d all custom 100 out.dump id x z temperature heatflow
dump_modify d sort id format float %.17g
run 500
""".format(wf=HEATW.format(reg="floor", T="1.5"), ws=HEATW.format(reg="side", T="v_Tw"))


def launches(out):
    m = re.findall(r"kernel launches per step = (\S+)", out)
    return float(m[-1]) if m else None


def sets(tmp):
    """Region walls of one law whose post_force calls follow each other run in
    one launch, up to RS_MAXWALL (4) each (src/contact/wall_region.c): nine
    walls (two sets of the granular law around a hooke/history wall, a rotating
    cylinder, a moving plane, a wall of group g1, a union, `contacts`, the
    second run of five cut into 4 + 1) and two conducting walls at their own
    temperatures (one a variable) give the bits of one launch per wall
    (GRAVEL_FUSE=0), in both precisions, with fewer launches per step."""
    for name, deck, precs in (("granular", SETS, ("double", "single")),
                              ("heat", SETS_HEAT, ("double",))):
        for prec in precs:
            out = {}
            for mode, env in (("sets", None), ("one_each", {"GRAVEL_FUSE": "0"})):
                res = run(deck, tmp, env, ("-precision", prec))
                dump = open(os.path.join(tmp, "out.dump")).read() if res.returncode == 0 else ""
                out[mode] = (res.returncode, dump, res.stdout, launches(res.stdout))
            a, b = out["sets"], out["one_each"]
            rows = [re.findall(r"^\s+\d+\s+.*$", o[2], re.M) for o in (a, b)]
            ok = a[0] == 0 and b[0] == 0 and a[1] == b[1] and rows[0] == rows[1] and a[1]
            check(f"wall_region_sets_{name}_{prec}_equal_one_launch_each", ok,
                  f"exit {a[0]} / {b[0]}, dumps {'equal' if a[1] == b[1] else 'differ'}, "
                  f"{len(rows[0])} thermo rows")
            # the sets save 5 launches (9 walls in 4) and 1 (2 in 1); GRAVEL_FUSE=0
            # also unfuses the other fixes
            fewer = 5 if name == "granular" else 1
            ok = a[3] is not None and b[3] is not None and b[3] - a[3] > fewer - 0.01
            check(f"wall_region_sets_{name}_{prec}_launches", ok,
                  f"{a[3]} launches per step with sets, {b[3]} one each "
                  f"(at least {fewer} fewer)")
    # the scenes do what they are for: contacts recorded, heat conducted
    last = last_dump(tmp)
    warm = [r[2] for r in last.values()]
    ok = len(warm) == 2 and all(t > 0.26 for t in warm)
    check("wall_region_sets_heat_conducted", ok, f"temperatures {warm} (from 0.25)")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        resting(tmp)
        carried(tmp)
        moving_match(tmp)
        restart(tmp)
        errors(tmp)
        sets(tmp)


if __name__ == "__main__":
    main()
