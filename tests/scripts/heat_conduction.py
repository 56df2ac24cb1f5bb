#!/usr/bin/env python3
"""heat_conduction.py - heat as LAMMPS (2023+) does it: fix property/atom
temperature heatflow, set temperature, pair granular and fix wall/gran
granular `heat area|radius`, fix heat/flow, temperature and heatflow in dump
custom and compute property/atom (through compute reduce).

1. Two touching spheres held still (no integrator), T = 1 and 0, pair
   granular hooke with heat area h: each step's heat flow is h pi a^2 dT
   (a = sqrt(delta R*), the hooke contact radius) into the colder sphere and
   exactly its negative into the hotter; fix heat/flow's explicit Euler gives
   dT_n = dT_0 (1 - 2 G dt / (m cp))^n, checked to 1e-12 every 100 steps;
   the analytic exponential dT_0 exp(-lambda t), lambda = 2 G / (m cp), within
   the explicit step's error 0.6 lambda^2 dt t dT; the sum of the
   temperatures (compute reduce sum of compute property/atom temperature,
   thermo) is conserved to 1e-14.
2. The same with heat radius k (G = 2 k a), two atom types of different k
   (mixed geometrically, as LAMMPS's mix_coeffs) and cp by type (then
   lambda = G (1/(m cp1) + 1/(m cp2)) and sum m cp T is conserved, from the
   dump).
3. A sphere resting on a zplane wall/gran granular wall with heat radius k at
   temperature Tw: T_n from the recurrence T += dt G (Tw - T) / (m cp), 1e-12;
   the same sphere in a wall/gran/region block (its floor): the same numbers.
   `temperature v_Tw` with an equal-style variable: evaluated at every step
   as LAMMPS's post_force does (a ramp Tw = 1.5 + 0.001 step follows the
   recurrence with Tw of the step, 1e-12; a constant variable gives the
   number's dump byte for byte).
4. Restart: run 600 = run 300 + write_restart + read_restart + run 300, the
   temperatures bit for bit.
5. Order independence: 64 pressed spheres settling on a hot wall (pair and
   wall conduction, temperatures set by an atom-style variable) gives
   bit-identical temperatures and heat flows with the cell sort every step or
   never and one work-item per work-group (GRAVEL_WORKGROUP=1): the heat flow
   is gathered in partner order, like the forces.
6. Bad input: clear errors (heat without the properties, wall heat without
   its temperature, negative temperature, dumping an absent property)."""
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
sys.path.insert(0, os.path.dirname(__file__))
from physics_lammps import read_dump  # noqa: E402


def check(ok, name, detail=""):
    print(f"{'PASS' if ok else 'FAIL'} {name}{(': ' + detail) if detail else ''}")
    return ok


def start(tmp, text):
    with open(os.path.join(tmp, "in.deck"), "w") as f:
        f.write(text)
    return subprocess.Popen([GRAVEL, "-in", "in.deck", "-log", "log.txt", "-echo", "none"],
                            cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


HEAD = """units lj
atom_style sphere
boundary f f f
region box block -2 2 -2 2 -2 2 units box
create_box 2 box
"""

PAIR = HEAD + """create_atoms 1 single -0.495 0 0 units box
create_atoms {t2} single 0.495 0 0 units box
set group all diameter 1.0 density 1.0
fix prop all property/atom temperature heatflow
set atom 1 temperature 1.0
set atom 2 temperature 0.0
pair_style granular
pair_coeff 1 1 hooke 1000.0 0.0 tangential linear_history 100.0 0.0 0.5 heat {model} {k1}
pair_coeff 2 2 hooke 1000.0 0.0 tangential linear_history 100.0 0.0 0.5 heat {model} {k2}
fix hf all heat/flow {cp}
compute T all property/atom temperature
compute Tsum all reduce sum c_T
thermo_style custom step c_Tsum
thermo_modify norm no format float %.17g
thermo 100
timestep 0.001
dump d all custom 100 out.dump id temperature heatflow
dump_modify d format float %.17g
run {n}
"""

WALL = HEAD + """create_atoms 1 single 0 0 -1.51 units box
set group all diameter 1.0 density 1.0
fix prop all property/atom temperature heatflow
set group all temperature 0.25
pair_style granular
pair_coeff * * hooke 1000.0 0.0 tangential linear_history 100.0 0.0 0.5
fix w all wall/gran granular hooke 1000.0 0.0 tangential linear_history 100.0 0.0 0.5 &
    heat radius 2.0 zplane -2.0 NULL temperature 1.5
fix hf all heat/flow constant 2.0
timestep 0.001
dump d all custom 100 out.dump id temperature heatflow
dump_modify d format float %.17g
run 1000
"""

WALLVAR = WALL.replace("temperature 1.5", "temperature v_Tw").replace(
    "fix hf all", "variable Tw equal 1.5+0.001*step\nfix hf all")
WALLCONST = WALL.replace("temperature 1.5", "temperature v_Tw").replace(
    "fix hf all", "variable Tw equal 1.5\nfix hf all")

WALLREG = WALL.replace("zplane -2.0 NULL", "region floor").replace(
    "fix w all", "region floor block -1.9 1.9 -1.9 1.9 -2 2 units box\nfix w all").replace(
    "wall/gran granular", "wall/gran/region granular")

RESTART_A = PAIR.format(t2=2, model="area", k1=3.0, k2=3.0, cp="constant 2.0", n=300).replace(
    "run 300", "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\n"
    "fix prop all property/atom temperature heatflow\nfix hf all heat/flow constant 2.0\n"
    "pair_coeff * * hooke 1000.0 0.0 tangential linear_history 100.0 0.0 0.5 heat area 3.0\n"
    "dump d all custom 100 out2.dump id temperature heatflow\n"
    "dump_modify d format float %.17g\nrun 300")


BED = """units lj
atom_style sphere
boundary p p f
region box block 0 4 0 4 0 8 units box
create_box 1 box
lattice sc 1.0
region fill block 0 4 0 4 0.6 4.5 units box
create_atoms 1 region fill
set group all diameter 1.02 density 1.0
fix prop all property/atom temperature heatflow
variable t atom 0.1*id
set group all temperature v_t
pair_style granular
pair_coeff * * hertz 2000.0 20.0 tangential linear_history 500.0 0.5 0.5 heat area 5.0
fix w all wall/gran granular hertz 2000.0 20.0 tangential linear_history 500.0 0.5 0.5 &
    heat radius 3.0 zplane 0.5 NULL temperature 10.0
fix g all gravity 1.0 vector 0 0 -1
fix nve all nve/sphere
fix hf all heat/flow constant 1.0
atom_modify sort {sort} 1.0
timestep 0.001
dump d all custom 300 out.dump id temperature heatflow
dump_modify d format float %.17g sort id
run 300
"""


def thermo(tmp):
    rows, on = [], False
    for line in open(os.path.join(tmp, "log.txt")):
        w = line.split()
        if w[:2] == ["Step", "c_Tsum"]:
            on = True
        elif on and len(w) == 2 and w[0].isdigit():
            rows.append(float(w[1]))
        elif on and w and w[0] == "Loop":
            on = False
    return rows


def pair_check(tmp, name, G, m, cp, ok_proc, txt):
    if not ok_proc:
        return check(False, name, txt[-600:])
    frames = read_dump(os.path.join(tmp, "out.dump"))
    ok, worst, wq, wc, we = True, 0.0, 0.0, 0.0, 0.0
    dt, d0 = 0.001, 1.0
    lam = G * (1 / (m * cp[0]) + 1 / (m * cp[1]))
    fac = 1 - lam * dt
    e0 = cp[0] * 1.0
    for step, rows in sorted(frames.items()):
        dT = d0 * fac ** step
        got = rows[1][0] - rows[2][0]
        worst = max(worst, abs(got - dT))
        if step > 0:  # the step's heat flow: from the temperatures it started with
            q = G * d0 * fac ** (step - 1)
            wq = max(wq, abs(rows[2][1] - q) / q, abs(rows[1][1] + q) / q)
            if rows[1][1] != -rows[2][1]:
                wq = math.inf
        cont = d0 * math.exp(-lam * step * dt)
        wc = max(wc, abs(got - cont) / (0.6 * lam * lam * dt * max(step, 1) * dt * d0))
        we = max(we, abs(cp[0] * rows[1][0] + cp[1] * rows[2][0] - e0))
    ts = thermo(tmp)
    cons = max(abs(t - 1.0) for t in ts) if ts else math.inf
    if cp[0] != cp[1]:  # the thermo sum is not conserved, the heat is
        cons, ts = we, list(frames)
    ok &= check(worst < 1e-12 and len(frames) > 5, f"{name}_euler", f"max |dT - recurrence| {worst:.1e}")
    ok &= check(wq < 1e-12, f"{name}_heatflow", f"max relative error of Q = G dT: {wq:.1e}")
    ok &= check(wc < 1, f"{name}_exponential",
                f"max |dT - exp| / (0.6 lambda^2 dt t) {wc:.2f}")
    ok &= check(cons < 1e-14 and len(ts) > 5, f"{name}_conserved",
                f"max |sum {'T' if cp[0] == cp[1] else 'cp T'} - initial| {cons:.1e} over "
                f"{len(ts)} rows")
    return ok


def main():
    m = math.pi / 6  # unit sphere of density 1
    a = math.sqrt(0.01 * 0.25)  # hooke contact radius: sqrt(delta R*)
    tmps = [tempfile.TemporaryDirectory() for _ in range(4)]
    t = [x.name for x in tmps]
    runs = [start(t[0], PAIR.format(t2=2, model="area", k1=3.0, k2=3.0, cp="constant 2.0",
                                    n=1000)),
            start(t[1], PAIR.format(t2=2, model="radius", k1=1.5, k2=6.0, cp="type 2.0 3.0",
                                    n=1000)),
            start(t[2], WALL),
            start(t[3], RESTART_A)]
    treg = tempfile.TemporaryDirectory()
    runs.append(start(treg.name, WALLREG))
    tvar = [tempfile.TemporaryDirectory() for _ in range(2)]
    runs.append(start(tvar[0].name, WALLVAR))
    runs.append(start(tvar[1].name, WALLCONST))
    beds = [tempfile.TemporaryDirectory() for _ in range(3)]
    nfirst = len(runs)
    for k, (sort, wg) in enumerate(((1, None), (0, None), (1, "1"))):
        with open(os.path.join(beds[k].name, "in.deck"), "w") as fh:
            fh.write(BED.format(sort=sort))
        env = dict(os.environ)
        if wg:
            env["GRAVEL_WORKGROUP"] = wg
        runs.append(subprocess.Popen([GRAVEL, "-in", "in.deck", "-log", "none", "-echo", "none"],
                                     cwd=beds[k].name, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, text=True, env=env))
    outs = [p.communicate(timeout=600)[0] for p in runs]
    rcs = [p.returncode == 0 for p in runs]
    pair_check(t[0], "heat_area", 3.0 * math.pi * a * a, m, (2.0, 2.0), rcs[0], outs[0])
    pair_check(t[1], "heat_radius_mixed", 2 * math.sqrt(1.5 * 6.0) * a, m, (2.0, 3.0), rcs[1],
               outs[1])
    # the wall
    if rcs[2]:
        frames = read_dump(os.path.join(t[2], "out.dump"))
        aw = math.sqrt(0.01 * 0.5)
        G, T, worst = 2 * 2.0 * aw, 0.25, 0.0
        for n in range(1, 1001):
            T += 0.001 * G * (1.5 - T) / (m * 2.0)
            if n % 100 == 0:
                worst = max(worst, abs(frames[n][1][0] - T))
        check(worst < 1e-12 and frames[1000][1][0] > 0.3, "heat_wall_radius",
              f"T {frames[1000][1][0]:.15g}, recurrence {T:.15g}")
    else:
        check(False, "heat_wall_radius", outs[2][-600:])
    # restart round trip
    if rcs[3]:
        one = read_dump(os.path.join(t[0], "out.dump"))
        two = read_dump(os.path.join(t[3], "out2.dump"))
        same = all(one[300 + s][i][0] == two[300 + s][i][0] for s in (100, 200, 300)
                   for i in (1, 2))
        check(same, "heat_restart", "temperatures after run 300 + restart + run 300 vs run 600"
              if same else f"{one[600]} vs {two[600]}")
    else:
        check(False, "heat_restart", outs[3][-600:])
    # the region wall: the plane wall's numbers
    if rcs[4] and rcs[2]:
        a_, b_ = (read_dump(os.path.join(d, "out.dump")) for d in (t[2], treg.name))
        check(all(a_[s][1][:2] == b_[s][1][:2] for s in a_), "heat_wall_region",
              f"T {b_[1000][1][0]:.15g} as the plane wall's")
    else:
        check(False, "heat_wall_region", outs[4][-600:])
    treg.cleanup()
    # a variable wall temperature
    if rcs[5] and rcs[6] and rcs[2]:
        frames = read_dump(os.path.join(tvar[0].name, "out.dump"))
        aw = math.sqrt(0.01 * 0.5)
        G, T, worst = 2 * 2.0 * aw, 0.25, 0.0
        for n in range(1, 1001):
            T += 0.001 * G * (1.5 + 0.001 * n - T) / (m * 2.0)
            if n % 100 == 0:
                worst = max(worst, abs(frames[n][1][0] - T))
        check(worst < 1e-12, "heat_wall_variable_temperature",
              f"T {frames[1000][1][0]:.15g}, recurrence with Tw(step) {T:.15g}")
        same = open(os.path.join(t[2], "out.dump")).read() == \
            open(os.path.join(tvar[1].name, "out.dump")).read()
        check(same, "heat_wall_variable_constant", "temperature v_Tw (Tw equal 1.5) dumps as "
              "temperature 1.5" if same else "dumps differ")
    else:
        check(False, "heat_wall_variable_temperature",
              next(o for o, r in zip(outs[5:7], rcs[5:7]) if not r)[-600:]
              if not (rcs[5] and rcs[6]) else outs[2][-600:])
    for x in tvar:
        x.cleanup()
    # order independence
    rcs, outs = rcs[nfirst:], outs[nfirst:]
    if all(rcs):
        txt = [open(os.path.join(b.name, "out.dump")).read() for b in beds]
        heated = read_dump(os.path.join(beds[0].name, "out.dump"))[300]
        moved = sum(1 for i, r in heated.items() if abs(r[0] - 0.1 * i) > 1e-6)
        check(txt[0] == txt[1] == txt[2] and moved > 10, "heat_order_independent",
              f"{moved} of 64 temperatures changed; dumps identical with sort 1, sort 0, "
              f"GRAVEL_WORKGROUP=1" if txt[0] == txt[1] == txt[2] else "dumps differ")
    else:
        check(False, "heat_order_independent", next(o for o, r in zip(outs, rcs) if not r)[-600:])
    for x in tmps + beds:
        x.cleanup()
    # bad input
    one = HEAD + "create_atoms 1 single 0 0 0 units box\n"
    bad = [
        (one + "set group all temperature 1.0\n", "fix property/atom temperature first"),
        (one + "fix p all property/atom temperature heatflow\nset group all temperature -1\n",
         "invalid temperature -1"),
        (one + "fix p all property/atom temperature heatflow\nset group all heatflow 1\n",
         "'heatflow' is not settable"),
        (one + "fix p all property/atom temperature\nfix q all property/atom temperature\n",
         "vector temperature already exists"),
        (one + "dump d all custom 1 x.dump id temperature\n", "(temperature) that isn't allocated"),
        (one + "compute c all property/atom heatflow\n", "atom property heatflow is not allocated"),
        (one + "fix h all heat/flow constant 0\n", "specific heat cp must be positive"),
        (one + "fix h all heat/flow type 1.0\n", "one specific heat per atom type (2), got 1"),
        (one + "fix h all heat/flow linear 1.0\n", "unknown style 'linear'"),
        (one + "pair_style granular\npair_coeff * * hooke 1 0 tangential linear_nohistory 0 0 "
               "heat area -1\n", "heat transfer coefficient (heat area) must be"),
        (one + "pair_style granular\npair_coeff * * hooke 1 0 tangential linear_nohistory 0 0 "
               "heat conduction 1\n", "unknown heat model 'conduction'"),
        (one + "pair_style granular\npair_coeff * * hooke 1 0 tangential linear_nohistory 0 0 "
               "heat area 1\nrun 0\n", "requires atom style with temperature property"),
        (one + "fix h all heat/flow constant 1\nrun 0\n", "requires atoms store temperature"),
        (one + "fix w all wall/gran granular hooke 1 0 tangential linear_nohistory 0 0 heat "
               "area 1 zplane -2 NULL\n", "Must define wall temperature with heat model"),
        (one + "fix w all wall/gran granular hooke 1 0 tangential linear_nohistory 0 0 "
               "zplane -2 NULL temperature 1\n", "Must define wall temperature with heat model"),
        (one + "fix p all property/atom temperature heatflow\nfix w all wall/gran granular "
               "hooke 1 0 tangential linear_nohistory 0 0 heat area 1 zplane -2 NULL "
               "temperature v_nope\nrun 0\n", "Variable nope for fix wall/gran does not exist"),
        (one + "fix p all property/atom temperature heatflow\nvariable a atom x\nfix w all "
               "wall/gran granular hooke 1 0 tangential linear_nohistory 0 0 heat area 1 zplane "
               "-2 NULL temperature v_a\nrun 0\n",
         "Variable a for fix wall/gran must be an equal style variable"),
    ]
    for text, want in bad:
        with tempfile.TemporaryDirectory() as tmp:
            p = start(tmp, text)
            txt = p.communicate(timeout=120)[0]
            err = [ln for ln in txt.splitlines() if ln.startswith("ERROR")]
            last = text.strip().splitlines()[-1]
            check(p.returncode != 0 and bool(err) and want in err[0] and "in.deck:" in err[0],
                  f"heat_error {last[:60]}", err[0] if err else txt.strip()[-200:])
    return 0


if __name__ == "__main__":
    sys.exit(main())
