#!/usr/bin/python3
"""lammps_granular_mdr.py - today's LAMMPS `pair_coeff ... mdr E nu Y gamma
psi_b eta_n0 damping mdr dtype` (doc/styles/pair_granular_normal.md, "mdr"),
with the per-atom bookkeeping of its fix granular/mdr
(styles/fix/fix_granular_mdr.c, styles/pair/gran_mdr.c). Checked here:

- check_gravel: each of LAMMPS's argument errors (coeffs_to_local, the
  damping models' init) comes first, with LAMMPS's words, naming the script
  line; mdr on fix wall/gran is refused (LAMMPS's fix granular/mdr words),
  a wall/gran/region mdr wall whose material differs from the pair's is
  refused as LAMMPS refuses it (mdr walls on other regions than planes:
  tests/scripts/lammps_mdr_region_walls.py); two
  different mdr models in one pair style are refused as LAMMPS's fix
  refuses them; a valid line creates fix MDR (granular/mdr) and runs.
- check_walls: a sphere against a plane region wall (fix wall/gran/region
  granular mdr) against the reference's WallContact, stepped in LAMMPS's
  order: elastic, plastic, damped (types 1 and 2), adhesive wall (the
  wall's own surface energy), a sphere resting on the wall under gravity
  (bulk response off) and a moving plane that presses it: the height,
  velocity and apparent radius every 500 steps.
- check_collisions: gravel against the reference (tests/reference/mdr/mdr_model.py,
  an independent Python statement of the model and its bookkeeping for two
  spheres, stepped here in LAMMPS's velocity-Verlet order): free head-on
  collisions of two spheres of the LAMMPS example's material
  (in.triaxial.compaction.12: E 1e9, nu 0.3, Y 50e6, psi_b 0.5), elastic
  and plastic, damping mdr 1 and 2, adhesive (gamma > 0), equal and unequal
  radii: the centre distance and the apparent radii every 500 steps and the
  final velocities must agree to 1e-9 relative (measured: 1e-13 or better).
  The apparent radius grows in the plastic collisions (the bookkeeping acts).
- check_pair_local: compute pair/local p13 (the contact area) and force
  during a plastic collision against the reference.
- check_trio: three mutually overlapping spheres (contact penalty up to
  0.95, bulk response with psi_b 0.99) against the reference stepped the
  same way; they start in a plastic overlap, which LAMMPS's warning names
  once (the collisions, which start apart, give none).
- check_order: 64 overlapping spheres in a periodic box give the same bits
  with and without re-sorting the atoms in memory at every rebuild.
- check_restart: a run split by write_restart / read_restart continues the
  per-atom state and the contact history exactly (16 digits).
- check_reference: the reference's own physics (Hertz limit, yield onset,
  plastic unloading, energy balance, the bookkeeping's effect).
- check_triaxial: LAMMPS's in.triaxial.compaction.12 (six moving plane
  walls; tests/reference/mdr, the deck's edits named there) against the
  thermo of LAMMPS 4 Feb 2025's log of it, every sampled row to 1e-7."""
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "reference", "mdr"))
from physics_lammps import GRAVEL  # noqa: E402
import mdr_model as mm  # noqa: E402

HEAD = """units si
atom_style sphere
region box block -4 4 -4 4 -4 4
create_box 1 box
pair_style granular
"""
OK = "mdr 1e9 0.3 50e6 0 0.5 0.2 damping mdr 1 tangential linear_history 1.4e8 0 0.5"
ONE = "create_atoms 1 single 0 0 0\nset atom 1 diameter 1 density 1000\n"
# (name, command, the error it must give): LAMMPS's checks, then gravel's refusals
CASES = (
    ("E", "pair_coeff * * mdr 0 0.3 50e6 0 0.5 0.2 damping mdr 1 tangential linear_history 1 0 0.5",
     "Illegal MDR normal model, Young's modulus must be greater than 0"),
    ("nu", "pair_coeff * * mdr 1e9 0.6 50e6 0 0.5 0.2 damping mdr 1 tangential linear_history 1 0 0.5",
     "Illegal MDR normal model, Poisson's ratio must be between 0 and 0.5"),
    ("Y", "pair_coeff * * mdr 1e9 0.3 -1 0 0.5 0.2 damping mdr 1 tangential linear_history 1 0 0.5",
     "Illegal MDR normal model, yield stress must be greater than or equal to 0"),
    ("gamma", "pair_coeff * * mdr 1e9 0.3 50e6 -1 0.5 0.2 damping mdr 1 tangential linear_history "
     "1 0 0.5", "effective surface energy must be greater than or equal to 0"),
    ("psi_b", "pair_coeff * * mdr 1e9 0.3 50e6 0 1.5 0.2 damping mdr 1 tangential linear_history "
     "1 0 0.5", "Illegal MDR normal model, psi_b must be between 0 and 1.0"),
    ("eta", "pair_coeff * * mdr 1e9 0.3 50e6 0 0.5 -1 damping mdr 1 tangential linear_history 1 0 0.5",
     "damping coefficent must be greater than or equal to 0"),
    ("dtype", "pair_coeff * * mdr 1e9 0.3 50e6 0 0.5 0.2 damping mdr 3 tangential linear_history "
     "1 0 0.5", "Illegal MDR damping model, damping type must an integer equal to 1 or 2"),
    ("no_damping_mdr", "pair_coeff * * mdr 1e9 0.3 50e6 0 0.5 0.2 tangential linear_history 1 0 0.5",
     "Only damping mdr may be used with the mdr normal model"),
    ("other_damping", "pair_coeff * * mdr 1e9 0.3 50e6 0 0.5 0.2 damping tsuji tangential "
     "linear_history 1 0 0.5", "Only damping mdr may be used with the mdr normal model"),
    ("damping_without", "pair_coeff * * hertz/material 1e9 0.2 0.3 damping mdr 1 tangential "
     "linear_history 1 0 0.5", "Damping mdr can only be used with mdr normal model"),
    ("refused_wall", "fix w all wall/gran granular " + OK + " zplane 0 NULL",
     "MDR model currently only supports fix wall/gran/region, not fix wall/gran"),
    ("wall_E", "pair_coeff * * " + OK + "\nregion r plane 0 0 -3 0 0 1\nfix w all "
     "wall/gran/region granular " + OK.replace("1e9", "2e9") + " region r\n" + ONE + "run 0",
     "Young's modulus in pair style, 1e+09, does not agree with value 2e+09 in fix w"),
    ("wall_psi_b", "pair_coeff * * " + OK + "\nregion r plane 0 0 -3 0 0 1\nfix w all "
     "wall/gran/region granular " + OK.replace(" 0.5 0.2", " 0.6 0.2") + " region r\n" + ONE +
     "run 0", "Bulk response trigger in pair style, 0.5, does not agree with value 0.6"),
)
TWO_MODELS = HEAD.replace("create_box 1", "create_box 2") + """pair_coeff 1 1 OKA
pair_coeff 2 2 OKB
create_atoms 1 single 0 0 0
create_atoms 2 single 1.5 0 0
set atom * diameter 1 density 1000
run 0
""".replace("OKA", OK).replace("OKB", OK.replace("50e6", "60e6"))


def report(name, ok, note=""):
    if note:
        print(f"  {name}: {note}")
    print(f"{'PASS' if ok else 'FAIL'} granular_mdr_{name}")
    return 0 if ok else 1


def check_gravel():
    bad = 0
    for name, cmd, want in CASES:
        r = subprocess.run([GRAVEL, "-log", "none"], input=HEAD + cmd + "\n",
                           capture_output=True, text=True, timeout=120)
        out = r.stdout + r.stderr
        err = [w for w in out.splitlines() if "ERROR" in w]
        # the message and the script line (stdin:6) it names
        line = "(stdin:%d)" % (6 + cmd.count("\n"))
        ok = r.returncode != 0 and any(want in w and line in w for w in err)
        bad += report("refuses_" + name, ok, err[0][err[0].index("ERROR"):] if err else "accepted")
    r = subprocess.run([GRAVEL, "-log", "none"], input=TWO_MODELS, capture_output=True,
                       text=True, timeout=120)
    out = r.stdout + r.stderr
    ok = r.returncode != 0 and "Cannot currently define multiple MDR normal models" in out
    bad += report("refuses_two_models", ok, next((w for w in out.splitlines() if "ERROR" in w),
                                                 "accepted"))
    r = subprocess.run([GRAVEL, "-log", "none"], input=HEAD + "pair_coeff * * " + OK +
                       "\nfix_modify MDR energy no\nprint \"fix MDR exists\"\n",
                       capture_output=True, text=True, timeout=120)
    bad += report("creates_fix_mdr", r.returncode == 0 and "fix MDR exists" in r.stdout,
                  (r.stdout + r.stderr).strip().splitlines()[-1])
    # a fix granular/mdr of the script's own: pair_coeff makes no second one
    r = subprocess.run([GRAVEL, "-log", "none"], input=HEAD + "fix keep all granular/mdr\n"
                       "pair_coeff * * " + OK + "\nfix_modify MDR energy no\n",
                       capture_output=True, text=True, timeout=120)
    err = [w for w in (r.stdout + r.stderr).splitlines() if "ERROR" in w]
    bad += report("own_fix_mdr", r.returncode != 0 and any("MDR" in w for w in err),
                  err[0] if err else "fix MDR was made beside the script's own")
    return bad


def check_reference():
    bad = 0
    R = 0.5
    m = mm.Material(1e9, 0.3, 50e6, 0.0, 0.5, 0.2, 1)
    # the elastic branch: Hertz's sphere on a rigid flat, 4/3 Es sqrt(R) d^1.5, at small d
    worst = max(abs(mm.f_flat(x * R, 4 * R, 2 * R, m.Es) /
                    (4 / 3 * m.Es * math.sqrt(R) * (x * R) ** 1.5) - 1) for x in (1e-6, 1e-5, 1e-4))
    bad += report("elastic_is_hertz", worst < 1e-4, f"worst relative difference {worst:.2e}")

    # a driven compression of two equal spheres to a total overlap 0.2 R and back
    N, dt = 4000, 1e-6
    dpeak = 0.2 * R
    gaps = [2 * R - dpeak * (n if n <= N // 2 else N - n) / (N // 2) for n in range(N + 1)]
    full = mm.drive(m, R, R, gaps, 1.0, dt)
    alone = mm.drive(m, R, R, gaps, 1.0, dt, bookkeeping=False)
    dY = m.delta_yield(R)
    # before yield (each side d = dtot/2 < dY) the force is the flat's force of one side
    pre = [(d, F) for d, F, _, _ in full[1:N // 2] if 0 < d / 2 < 0.95 * dY]
    worst = max(abs(F / mm.f_flat(d / 2, 4 * R, 2 * R, m.Es) - 1) for d, F in pre)
    # (1e-7: the first step's overlap, 1e-4 R, loses digits in arccos(1 - x) - ...)
    bad += report("elastic_loading", worst < 1e-7 and len(pre) > 100,
                  f"{len(pre)} steps before yield, worst relative difference {worst:.1e}")
    # yield: the radius starts to grow within one step's overlap of 2 dY
    first = next(n for n, (_, _, ra, _) in enumerate(full) if ra > R)
    step = dpeak / (N // 2)
    dfirst = full[first - 1][0]
    bad += report("yield_onset", abs(dfirst - 2 * dY) <= 2 * step,
                  f"yield at total overlap {dfirst:.6g}, 2 d_Y = {2 * dY:.6g} "
                  f"(d_Y/R = {dY / R:.6f})")
    # unloading: below the loading force at the same overlap, zero at a plastic rest overlap
    load = {round(g, 12): F for g, (_, F, _, _) in zip(gaps[:N // 2], full[:N // 2])}
    below = all(F < load.get(round(g, 12), math.inf) for g, (_, F, _, _) in
                zip(gaps[N // 2 + 1:], full[N // 2 + 1:]) if F > 0)
    rest = next(d for d, F, _, _ in full[N // 2:] if F == 0)
    bad += report("plastic_unloading", below and rest > 0.3 * dpeak,
                  f"unloading below loading, force zero at total overlap {rest:.5g} "
                  f"(peak {dpeak:.5g})")
    # the bookkeeping's effect on one plastic contact
    Rend = full[-1][2]
    peak = max(b[1] for b in alone)
    diff = max(abs(a[1] - b[1]) for a, b in zip(full, alone)) / peak
    top = full[N // 2][1] / alone[N // 2][1] - 1
    bad += report("bookkeeping_matters", diff > 5e-3,
                  f"apparent radius {R} -> {Rend:.7g}; the force with the radius update differs "
                  f"from the law alone by up to {100 * diff:.2f} % of the peak force "
                  f"({100 * top:.2f} % at the peak)")

    # free collisions: energy balance and restitution
    for name, Y, eta, dtype, v0, want in (("elastic", 1e12, 0.0, 1, 5.0, "e1"),
                                          ("elastic_damped", 1e12, 0.2, 1, 5.0, "lt1"),
                                          ("plastic", 50e6, 0.0, 1, 40.0, "lt1"),
                                          ("plastic_damped", 50e6, 0.2, 1, 40.0, "lt1"),
                                          ("plastic_dtype2", 50e6, 0.2, 2, 40.0, "lt1")):
        mat = mm.Material(1e9, 0.3, Y, 0.0, 0.5, eta, dtype)
        e, wd, we, loss = mm.collide(mat, R, 1000.0, v0, 2e-6)
        bal = abs(loss + wd + we) / (0.5 * (1000 * 4 / 3 * math.pi * R ** 3) / 2 * (2 * v0) ** 2)
        ok = bal < 1e-6 and (abs(e - 1) < 1e-6 if want == "e1" else e < 0.99)
        bad += report("collision_" + name, ok,
                      f"e = {e:.6f}, kinetic loss {loss:.6g} = damping {-wd:.6g} + "
                      f"elastic-plastic {-we:.6g} (imbalance {bal:.1e} of the kinetic energy)")
    return bad


WARN_PLASTIC = "pre-existing overlaps that have caused immediate plastic deformation"
DECK = """units si
atom_style sphere
boundary f f f
region box block -4 4 -4 4 -4 4
create_box 1 box
create_atoms 1 single {x1!r} 0 0
create_atoms 1 single {x2!r} 0 0
set atom 1 diameter {d1!r} density {rho!r}
set atom 2 diameter {d2!r} density {rho!r}
pair_style granular
pair_coeff * * mdr {E!r} {nu!r} {Y!r} {gamma!r} {psi_b!r} {eta!r} damping mdr {dtype} &
  tangential linear_history 1.4e8 0 0.5
set atom 1 vx {v1!r}
set atom 2 vx {v2!r}
fix 1 all nve/sphere
timestep {dt!r}
variable dx equal x[2]-x[1]
variable v1 equal vx[1]
variable v2 equal vx[2]
variable r1 equal radius[1]
variable r2 equal radius[2]
thermo_style custom step v_dx v_v1 v_v2 v_r1 v_r2
thermo_modify format float %.17g
thermo {every}
"""


def thermo_rows(out, ncol=6):
    """{step: [values]} of the thermo table(s) (ncol columns) in gravel's output"""
    rows, on = {}, False
    for line in out.splitlines():
        w = line.split()
        if w[:1] == ["Step"]:
            on = True
            continue
        if on and w and w[0].isdigit() and len(w) == ncol:
            rows[int(w[0])] = [float(v) for v in w[1:]]
        else:
            on = False
    return rows


def reference_collision(m, Ra, Rb, rho, x1, x2, v1, v2, dt, nsteps, every):
    """The reference model stepped as LAMMPS's velocity Verlet with
    nve/sphere and fix granular/mdr: each step the opening kick and drift,
    the atoms' update (fix granular/mdr pre_force), the mean surface
    displacement, the contact's force, the closing kick. {step: [x2 - x1,
    vx1, vx2, R1, R2, the contact's mean area, its normal force at the
    velocities of the step's end (LAMMPS's Pair::single)]}."""
    a, b = mm.Atom(1, Ra), mm.Atom(2, Rb)
    m1, m2 = rho * 4 / 3 * math.pi * Ra ** 3, rho * 4 / 3 * math.pi * Rb ** 3
    meff = m1 * m2 / (m1 + m2)
    c = mm.Contact(m, a, b)
    f = fe = 0.0  # the force on atom 2 along +x (atom 1 gets -f); its elastic part
    out = {0: [x2 - x1, v1, v2, a.R, b.R, 0.0, 0.0]}
    for n in range(1, nsteps + 1):
        v1 -= 0.5 * dt * f / m1
        v2 += 0.5 * dt * f / m2
        x1 += dt * v1
        x2 += dt * v2
        for at in (a, b):
            at.update(m.psi_b)
            at.ddelta_bar = 0.0
            at.zero_sums()
        dtot = a.R + b.R - (x2 - x1)
        if dtot > 0:
            c.mean_surf_disp(dtot)
            f, fe = c.force(dtot, v2 - v1, meff)
        else:
            c = mm.Contact(m, a, b)
            f = fe = 0.0
        v1 -= 0.5 * dt * f / m1
        v2 += 0.5 * dt * f / m2
        if n % every == 0:
            pref = m.eta * c.dscale if m.dtype == 1 else (m.eta if c.dscale != 0 else 0.0)
            area = 0.5 * (c.sides[0].Ac + c.sides[1].Ac) if dtot > 0 else 0.0
            out[n] = [x2 - x1, v1, v2, a.R, b.R, area,
                      fe - pref * (v2 - v1) if dtot > 0 else 0.0]
    return out


# (name, E, nu, Y, gamma, psi_b, eta, dtype, Ra, Rb, v0, steps): v0 the closing
# speed of each sphere in the centre-of-mass frame for equal masses
COLLISIONS = (
    ("elastic", 1e9, 0.3, 1e12, 0.0, 0.5, 0.0, 1, 0.5, 0.5, 5.0, 10000),
    ("plastic", 1e9, 0.3, 50e6, 0.0, 0.5, 0.0, 1, 0.5, 0.5, 20.0, 8000),
    ("plastic_damped", 1e9, 0.3, 50e6, 0.0, 0.5, 0.2, 1, 0.5, 0.5, 40.0, 8000),
    ("plastic_dtype2", 1e9, 0.3, 50e6, 0.0, 0.5, 5e4, 2, 0.5, 0.5, 40.0, 8000),
    ("adhesive", 1e9, 0.3, 50e6, 2e4, 0.5, 0.2, 1, 0.5, 0.5, 40.0, 8000),
    ("unequal_radii", 1e9, 0.3, 50e6, 0.0, 0.5, 0.2, 1, 0.4, 0.6, 20.0, 10000),
)


def check_collisions():
    bad = 0
    rho, dt, every, gap = 1000.0, 1e-6, 500, 1e-4
    for name, E, nu, Y, gamma, psi_b, eta, dtype, Ra, Rb, v0, steps in COLLISIONS:
        m1, m2 = rho * 4 / 3 * math.pi * Ra ** 3, rho * 4 / 3 * math.pi * Rb ** 3
        v1, v2 = 2 * v0 * m2 / (m1 + m2), -2 * v0 * m1 / (m1 + m2)  # momentum zero
        x1, x2 = -Ra - gap, Rb + gap
        deck = DECK.format(x1=x1, x2=x2, d1=2 * Ra, d2=2 * Rb, rho=rho, E=E, nu=nu, Y=Y,
                           gamma=gamma, psi_b=psi_b, eta=eta, dtype=dtype, v1=v1, v2=v2,
                           dt=dt, every=every) + "run %d\n" % steps
        r = subprocess.run([GRAVEL, "-log", "none"], input=deck, capture_output=True,
                           text=True, timeout=300)
        got = thermo_rows(r.stdout)
        mat = mm.Material(E, nu, Y, gamma, psi_b, eta, dtype)
        want = reference_collision(mat, Ra, Rb, rho, x1, x2, v1, v2, dt, steps, every)
        if r.returncode != 0 or set(got) != set(want):
            bad += report("collision_" + name, False, (r.stdout + r.stderr)[-400:])
            continue
        worst = 0.0
        for n in want:
            for k in range(5):  # (the area and force: check_pair_local)
                scale = 2 * v0 if k in (1, 2) else 1.0
                worst = max(worst, abs(got[n][k] - want[n][k]) / scale)
        e = (got[steps][2] - got[steps][1]) / (2 * v0 * 2) * 2
        grow = max(got[steps][3] / Ra, got[steps][4] / Rb) - 1
        ok = worst < 1e-9 and (grow > 1e-6) == (Y < 1e11) and WARN_PLASTIC not in r.stdout + \
            r.stderr
        bad += report("collision_" + name, ok,
                      f"restitution {e:.10f}, apparent radius growth {grow:.3e}; worst "
                      f"difference from the reference {worst:.1e} (relative)")
    return bad


WALL_DECK = """units si
atom_style sphere
boundary f f f
region box block -4 4 -4 4 -4 4
create_box 1 box
create_atoms 1 single 0 0 {z0!r}
set atom 1 diameter {d!r} density {rho!r}
pair_style granular
pair_coeff * * mdr {E!r} {nu!r} {Y!r} 0 {psi_b!r} {eta!r} damping mdr {dtype} &
  tangential linear_history 1.4e8 0 0.5
variable zw equal {vw!r}*elapsed*dt
region floor plane 0 0 0 0 0 1 side in move NULL NULL v_zw
fix w all wall/gran/region granular mdr {E!r} {nu!r} {Y!r} {gw!r} {psi_b!r} {eta!r} &
  damping mdr {dtype} tangential linear_history 1.4e8 0 0.5 region floor
set atom 1 vz {v0!r}
fix 1 all nve/sphere
{grav}
timestep {dt!r}
variable z equal z[1]
variable vz equal vz[1]
variable r equal radius[1]
thermo_style custom step v_z v_vz v_r
thermo_modify format float %.17g
thermo {every}
run {steps}
"""


def reference_wall(m, R, rho, z0, v0, g, vw, dt, nsteps, every):
    """The reference sphere against the plane z = vw t (velocity Verlet with
    nve/sphere, gravity g along -z, fix granular/mdr's pre_force, the wall's
    force): {step: [z, vz, R]}"""
    a = mm.Atom(1, R)
    mass = rho * 4 / 3 * math.pi * R ** 3
    c = mm.WallContact(m, a)
    z, v, f = z0, v0, -mass * g
    out = {0: [z, v, a.R]}
    for n in range(1, nsteps + 1):
        v += 0.5 * dt * f / mass
        z += dt * v
        a.update(m.psi_b)
        a.ddelta_bar = 0.0
        a.zero_sums()
        zw = vw * n * dt
        delta = a.R - (z - zw)
        if 0 < delta and z >= zw:
            c.mean_surf_disp(delta)
            fw, _ = c.force(delta, v - vw, mass)
        else:
            c = mm.WallContact(m, a)
            fw = 0.0
        f = fw - mass * g
        v += 0.5 * dt * f / mass
        if n % every == 0:
            out[n] = [z, v, a.R]
    return out


# (name, E, nu, Y, gamma of the wall, psi_b, eta, dtype, v0, gravity, wall speed, steps)
WALLS = (
    ("elastic", 1e9, 0.3, 1e12, 0.0, 0.5, 0.0, 1, -5.0, 0.0, 0.0, 8000),
    ("plastic", 1e9, 0.3, 50e6, 0.0, 0.5, 0.0, 1, -20.0, 0.0, 0.0, 8000),
    ("plastic_damped", 1e9, 0.3, 50e6, 0.0, 0.5, 0.2, 1, -40.0, 0.0, 0.0, 8000),
    ("plastic_dtype2", 1e9, 0.3, 50e6, 0.0, 0.5, 5e4, 2, -40.0, 0.0, 0.0, 8000),
    ("adhesive", 1e9, 0.3, 50e6, 2e4, 0.5, 0.2, 1, -40.0, 0.0, 0.0, 8000),
    ("resting_gravity", 1e7, 0.3, 1e5, 0.0, 0.0, 0.2, 1, 0.0, 9.81, 0.0, 20000),
    ("pressed", 1e9, 0.3, 50e6, 0.0, 0.5, 0.2, 1, 0.0, 0.0, 5.0, 8000),
)


def check_walls():
    bad = 0
    R, rho, dt, every = 0.5, 1000.0, 1e-6, 500
    for name, E, nu, Y, gw, psi_b, eta, dtype, v0, g, vw, steps in WALLS:
        z0 = R + 1e-4 if v0 < 0 else R + 1e-6
        grav = "fix g all gravity %r vector 0 0 -1" % g if g else ""
        deck = WALL_DECK.format(z0=z0, d=2 * R, rho=rho, E=E, nu=nu, Y=Y, psi_b=psi_b, eta=eta,
                                dtype=dtype, gw=gw, v0=v0, vw=vw, grav=grav, dt=dt,
                                every=every, steps=steps)
        r = subprocess.run([GRAVEL, "-log", "none"], input=deck, capture_output=True,
                           text=True, timeout=300)
        got = thermo_rows(r.stdout, 4)
        mat = mm.Material(E, nu, Y, gw, psi_b, eta, dtype)
        want = reference_wall(mat, R, rho, z0, v0, g, vw, dt, steps, every)
        if r.returncode != 0 or set(got) != set(want):
            bad += report("wall_" + name, False, (r.stdout + r.stderr)[-400:])
            continue
        vs = max(abs(v0), abs(vw), 1.0)
        worst = max(max(abs(got[n][0] - want[n][0]) / R, abs(got[n][1] - want[n][1]) / vs,
                        abs(got[n][2] - want[n][2]) / R) for n in want)
        zmin = min(want[n][0] for n in want)
        grow = want[steps][2] / R - 1
        ok = worst < 1e-12
        bad += report("wall_" + name, ok,
                      f"deepest centre height {zmin:.6f} (R {R}), final vz {got[steps][1]:.6g}, "
                      f"apparent radius growth {grow:.3e}; worst difference from the reference "
                      f"{worst:.1e} (relative)")
    return bad


def check_triaxial():
    """LAMMPS's in.triaxial.compaction.12 (12 spheres pressed by six moving
    plane walls, mdr pairs and walls, tangential friction) against its log
    from LAMMPS 4 Feb 2025 (tests/reference/mdr/triaxial12_lammps_4Feb25.txt):
    KinEng and the rotational energy at every logged row to 1e-7 relative
    (the log's 8 digits)."""
    ref = os.path.join(HERE, "..", "reference", "mdr")
    want = {}
    with open(os.path.join(ref, "triaxial12_lammps_4Feb25.txt")) as fh:
        for line in fh:
            if line.strip() and not line.startswith("#"):
                w = line.split()
                want[int(w[0])] = [float(w[1]), float(w[2])]
    with tempfile.TemporaryDirectory() as d:
        for f in ("in.triaxial.compaction.12", "spheres12.data"):
            with open(os.path.join(ref, f)) as src, open(os.path.join(d, f), "w") as dst:
                dst.write(src.read())
        r = subprocess.run([GRAVEL, "-log", "none", "-in", "in.triaxial.compaction.12"], cwd=d,
                           capture_output=True, text=True, timeout=600)
    rows = {}
    for line in r.stdout.splitlines():
        w = line.split()
        if len(w) == 6 and w[0] == "1e-06" and w[1].isdigit():
            rows[int(w[1])] = [float(w[3]), float(w[4])]  # the last run's rows win
    worst, where = 0.0, 0
    for n, (ke, rot) in want.items():
        if n not in rows:
            return report("triaxial_compaction_12", False, f"no row {n}: " +
                          (r.stdout + r.stderr)[-300:])
        for k, v in enumerate((ke, rot)):
            d = abs(rows[n][k] - v) / max(abs(v), 1e-3)
            if d > worst:
                worst, where = d, n
    return report("triaxial_compaction_12", r.returncode == 0 and worst < 1e-7,
                  f"{len(want)} rows of LAMMPS 4Feb2025's log, worst relative difference "
                  f"{worst:.1e} (step {where}); final KinEng {rows[49900][0]:.8g}")


TRIO = """units si
atom_style sphere
boundary f f f
region box block -4 4 -4 4 -4 4
create_box 1 box
create_atoms 1 single -0.46 0 0
create_atoms 1 single 0.46 0 0
create_atoms 1 single 0 0.38 0
set atom 1*2 diameter 1.0 density 1000
set atom 3 diameter 0.24 density 1000
set atom 1 vx VX1
set atom 2 vx VX2
set atom 3 vy VY3
pair_style granular
pair_coeff * * mdr 1e9 0.3 50e6 0 0.99 0.2 damping mdr 1 tangential linear_history 1.4e8 0 0
fix 1 all nve/sphere
timestep 1e-6
variable x1 equal x[1]
variable y1 equal y[1]
variable x2 equal x[2]
variable y3 equal y[3]
variable r1 equal radius[1]
variable r3 equal radius[3]
thermo_style custom step v_x1 v_y1 v_x2 v_y3 v_r1 v_r3
thermo_modify format float %.17g
thermo 100
run 3000
"""


def reference_trio(m, pos, vel, rad, rho, dt, nsteps, every):
    """Three spheres in the plane z = 0 (frictionless: mu 0), stepped
    as reference_collision with fix granular/mdr's contact penalty of the
    triple (when its three pairs overlap, r <= r_i + r_j, the pair across
    the longest side gets the increment of the angle at the third atom).
    Contacts in (lower tag, higher tag) order. Returns {step: [x1, y1, x2,
    y3, R1, R3]} and the largest penalty and bulk overlap met."""
    at = [mm.Atom(t + 1, rad[t]) for t in range(3)]
    mass = [rho * 4 / 3 * math.pi * r ** 3 for r in rad]
    x = [list(p) for p in pos]
    v = [list(u) for u in vel]
    f = [[0.0, 0.0] for _ in range(3)]
    pairs = ((0, 1), (0, 2), (1, 2))
    con = {p: mm.Contact(m, at[p[0]], at[p[1]]) for p in pairs}

    def kick():
        for a in range(3):
            for q in range(2):
                v[a][q] += 0.5 * dt * f[a][q] / mass[a]

    def geo(i, j):  # x_j - x_i and its length
        d = [x[j][0] - x[i][0], x[j][1] - x[i][1]]
        return d, math.hypot(d[0], d[1])

    out, seen = {}, {"penalty": 0.0, "bulk": 0.0}
    for n in range(nsteps + 1):
        if n > 0:
            kick()
            for a in range(3):
                for q in range(2):
                    x[a][q] += dt * v[a][q]
            for a in at:
                a.update(m.psi_b)
                a.ddelta_bar = 0.0
                a.zero_sums()
            for c in con.values():
                c.penalty = 0.0
            (dij, rij), (dik, rik), (djk, rjk) = geo(0, 1), geo(0, 2), geo(1, 2)
            R = [a.R for a in at]
            if rij <= R[0] + R[1] and rik <= R[0] + R[2] and rjk <= R[1] + R[2]:
                rmax = max(rij, rik, rjk)
                if rij == rmax:    # atom 3 in the middle: 1-2 screened
                    c0 = sum((-dik[q] / rik) * (-djk[q] / rjk) for q in range(2))
                    con[(0, 1)].penalty += mm.penalty_increment(math.acos(c0))
                elif rik == rmax:  # atom 2 in the middle: 1-3 screened
                    c0 = sum((-dij[q] / rij) * (djk[q] / rjk) for q in range(2))
                    con[(0, 2)].penalty += mm.penalty_increment(math.acos(c0))
                else:              # atom 1 in the middle: 2-3 screened
                    c0 = sum((dij[q] / rij) * (dik[q] / rik) for q in range(2))
                    con[(1, 2)].penalty += mm.penalty_increment(math.acos(c0))
            for (i, j) in pairs:
                d, r = geo(i, j)
                dtot = at[i].R + at[j].R - r
                if dtot > 0:
                    con[(i, j)].mean_surf_disp(dtot)
                seen["penalty"] = max(seen["penalty"], con[(i, j)].penalty)
        for a in range(3):
            f[a] = [0.0, 0.0]
        for (i, j) in pairs:
            d, r = geo(i, j)
            dtot = at[i].R + at[j].R - r
            if dtot <= 0:
                con[(i, j)] = mm.Contact(m, at[i], at[j])
                continue
            nrm = [-d[0] / r, -d[1] / r]  # from j to i
            vn = sum((v[i][q] - v[j][q]) * nrm[q] for q in range(2))
            meff = mass[i] * mass[j] / (mass[i] + mass[j])
            F, _ = con[(i, j)].force(dtot, vn, meff, update=n > 0)
            for q in range(2):
                f[i][q] += F * nrm[q]
                f[j][q] -= F * nrm[q]
            seen["bulk"] = max([seen["bulk"]] + [h.dbulk for h in con[(i, j)].sides])
        if n > 0:
            kick()
        if n % every == 0:
            out[n] = [x[0][0], x[0][1], x[1][0], x[2][1], at[0].R, at[2].R]
    return out, seen


def check_pair_local():
    """compute pair/local p13 (the mdr contact area, LAMMPS's svector value)
    and force (the normal force at output time) during a plastic collision,
    against the reference every 500 steps (1e-9 relative)"""
    name, E, nu, Y, gamma, psi_b, eta, dtype, Ra, Rb, v0, steps = COLLISIONS[2]
    rho, dt = 1000.0, 1e-6
    deck = DECK.format(x1=-Ra - 1e-4, x2=Rb + 1e-4, d1=2 * Ra, d2=2 * Rb, rho=rho, E=E, nu=nu,
                       Y=Y, gamma=gamma, psi_b=psi_b, eta=eta, dtype=dtype, v1=v0, v2=-v0,
                       dt=dt, every=500)
    deck = deck.replace("thermo_style custom step v_dx v_v1 v_v2 v_r1 v_r2", """compute pl all pair/local p13 force cutoff radius
compute ac all reduce sum c_pl[1]
compute fn all reduce sum c_pl[2]
thermo_style custom step c_ac c_fn""") + "run 3000\n"
    r = subprocess.run([GRAVEL, "-log", "none"], input=deck, capture_output=True, text=True,
                       timeout=300)
    got = thermo_rows(r.stdout, 3)
    mat = mm.Material(E, nu, Y, gamma, psi_b, eta, dtype)
    want = reference_collision(mat, Ra, Rb, rho, -Ra - 1e-4, Rb + 1e-4, v0, -v0, dt, 3000, 500)
    if r.returncode != 0 or set(got) != set(want):
        return report("pair_local_p13", False, (r.stdout + r.stderr)[-400:])
    worst = max(max(abs(got[n][0] - want[n][5]) / 0.1, abs(got[n][1] - want[n][6]) / 1e7)
                for n in want)
    return report("pair_local_p13", worst < 1e-9 and want[1500][5] > 0,
                  f"area {got[1500][0]:.10g} and force {got[1500][1]:.10g} at step 1500; worst "
                  f"difference from the reference {worst:.1e} (relative to 0.1 and 1e7)")


def check_trio():
    """three mutually overlapping spheres: the contact penalty and the bulk
    response (psi_b 0.99) against the reference, positions and radii every
    100 steps to 1e-9 relative"""
    vx1, vy3 = 5.0, -3.0
    deck = TRIO.replace("VX1", repr(vx1)).replace("VX2", repr(-vx1)).replace("VY3", repr(vy3))
    r = subprocess.run([GRAVEL, "-log", "none"], input=deck, capture_output=True, text=True,
                       timeout=300)
    got = thermo_rows(r.stdout, 7)
    mat = mm.Material(1e9, 0.3, 50e6, 0.0, 0.99, 0.2, 1)
    want, seen = reference_trio(mat, ((-0.46, 0.0), (0.46, 0.0), (0.0, 0.38)),
                                ((vx1, 0.0), (-vx1, 0.0), (0.0, vy3)), (0.5, 0.5, 0.12),
                               1000.0, 1e-6, 3000, 100)
    if r.returncode != 0 or set(got) != set(want):
        return report("trio_penalty_bulk", False, (r.stdout + r.stderr)[-400:])
    worst = max(abs(got[n][k] - want[n][k]) for n in want for k in range(6))
    # the spheres start in a plastic overlap: LAMMPS's warning, once
    warned = (r.stdout + r.stderr).count(WARN_PLASTIC) == 1
    ok = worst < 1e-9 and seen["penalty"] > 0.5 and seen["bulk"] > 0 and warned
    return report("trio_penalty_bulk", ok,
                  f"worst difference from the reference {worst:.1e} (positions and radii, "
                  f"length units); largest penalty {seen['penalty']:.4f}, largest bulk "
                  f"overlap {seen['bulk']:.3e}; y3 {want[3000][3]:.10f} at step 3000; "
                  f"plastic-overlap warning once: {warned}")


PACK = """atom_modify sort SORT 0
units si
atom_style sphere
boundary p p p
lattice sc 1.0
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
set atom * diameter 1.0 density 1000
set atom 7*20 diameter 1.1
velocity all create 20 4928459 loop geom
pair_style granular
pair_coeff * * mdr 1e9 0.3 50e6 0 0.5 0.2 damping mdr 1 tangential linear_history 1.4e8 0 0.5
neighbor 0.3 bin
neigh_modify every 1 delay 0 check no
fix 1 all nve/sphere
timestep 1e-6
compute rs all reduce max radius
thermo_style custom step ke c_rs press
thermo_modify format float %.17g
thermo 500
run 3000
"""


def check_order():
    """64 spheres overlapping in a periodic box (many contacts, growing
    radii): the thermo table is the same bits whether the atoms are
    re-sorted in memory at every rebuild or never (atom_modify sort 1 / 0)"""
    rows = []
    for sort in ("0", "1"):
        r = subprocess.run([GRAVEL, "-log", "none"], input=PACK.replace("SORT", sort),
                           capture_output=True, text=True, timeout=300)
        rows.append(thermo_rows(r.stdout, 4) if r.returncode == 0 else {})
    a, b = rows
    ok = len(a) == 7 and a == b and a[3000][1] > 0.55
    return report("memory_order", ok, f"{len(a)} thermo rows identical: {a == b}; largest "
                  f"radius {a.get(3000, [0, 0])[1]!r} (0.55 at the start)")


def check_restart():
    """run 8000 = run 4000, write_restart, read_restart, run 4000 (mid-collision;
    pair granular's coefficients are given again, as LAMMPS's restart keeps
    them but gravel's does not: that pair_coeff makes fix MDR again, which
    takes its state from the file)"""
    name, E, nu, Y, gamma, psi_b, eta, dtype, Ra, Rb, v0, steps = COLLISIONS[5]
    rho, dt = 1000.0, 1e-6
    m1, m2 = rho * 4 / 3 * math.pi * Ra ** 3, rho * 4 / 3 * math.pi * Rb ** 3
    v1, v2 = 2 * v0 * m2 / (m1 + m2), -2 * v0 * m1 / (m1 + m2)
    deck = DECK.format(x1=-Ra - 1e-4, x2=Rb + 1e-4, d1=2 * Ra, d2=2 * Rb, rho=rho, E=E, nu=nu,
                       Y=Y, gamma=gamma, psi_b=psi_b, eta=eta, dtype=dtype, v1=v1, v2=v2,
                       dt=dt, every=500)
    tail = "".join(l + "\n" for l in deck.replace("&\n", "").splitlines()
                   if l.startswith(("pair_", "variable", "thermo")))
    with tempfile.TemporaryDirectory() as tmp:
        whole = subprocess.run([GRAVEL, "-log", "none"], input=deck + "run 4000\nrun 4000\n",
                               capture_output=True, text=True, timeout=300, cwd=tmp)
        first = subprocess.run([GRAVEL, "-log", "none"], input=deck + "run 4000\n"
                               "write_restart mdr.restart\n", capture_output=True, text=True,
                               timeout=300, cwd=tmp)
        second = subprocess.run([GRAVEL, "-log", "none"], input="read_restart mdr.restart\n"
                                "fix 1 all nve/sphere\n" + tail + "run 4000\n",
                                capture_output=True, text=True, timeout=300, cwd=tmp)
    a, b = thermo_rows(whole.stdout), thermo_rows(second.stdout)
    ok = first.returncode == 0 and second.returncode == 0 and 8000 in a and a.get(8000) == \
        b.get(8000)
    note = f"step 8000: {a.get(8000)} vs {b.get(8000)}" if not ok else \
        f"step 8000 identical: dx {a[8000][0]!r}, radii {a[8000][3]!r} {a[8000][4]!r}"
    if second.returncode:
        note += " " + (second.stdout + second.stderr)[-300:]
    return report("restart_exact", ok, note)


def check_wall_restart():
    """a sphere pressed plastically into an mdr plane wall: run 2000,
    write_restart mid-contact (the deepest point), read_restart, run 2000
    gives the uninterrupted run 4000's bits (the walls' mdr contact state is in
    the restart file; without it the restarted contact started afresh and
    ended 1.4 % lower)"""
    R, rho, dt = 0.5, 1000.0, 1e-6
    deck = WALL_DECK.format(z0=R + 1e-4, d=2 * R, rho=rho, E=1e9, nu=0.3, Y=50e6, psi_b=0.5,
                            eta=0.2, dtype=1, gw=0.0, v0=-40.0, vw=0.0, grav="", dt=dt,
                            every=250, steps=4000)
    lines = deck.replace("&\n", "").splitlines()
    head = "".join(l + "\n" for l in lines if not l.startswith("run"))
    again = "".join(l + "\n" for l in lines if l.startswith(
        ("pair_", "variable", "region floor", "fix", "thermo")))
    with tempfile.TemporaryDirectory() as tmp:
        whole = subprocess.run([GRAVEL, "-log", "none"], input=head + "run 4000\n",
                               capture_output=True, text=True, timeout=300, cwd=tmp)
        first = subprocess.run([GRAVEL, "-log", "none"], input=head + "run 2000\n"
                               "write_restart w.restart\n", capture_output=True, text=True,
                               timeout=300, cwd=tmp)
        second = subprocess.run([GRAVEL, "-log", "none"], input="read_restart w.restart\n" +
                                again + "run 2000\n", capture_output=True, text=True,
                                timeout=300, cwd=tmp)
    a, b = thermo_rows(whole.stdout, 4), thermo_rows(second.stdout, 4)
    ok = first.returncode == 0 and second.returncode == 0 and 4000 in a and \
        a.get(4000) == b.get(4000) and a.get(2000, [1])[0] < 0.45
    note = f"step 4000: {a.get(4000)} vs {b.get(4000)}" if not ok else \
        f"step 4000 identical: z {a[4000][0]!r}, radius {a[4000][2]!r} (z {a[2000][0]!r} at the restart)"
    if second.returncode:
        note += " " + (second.stdout + second.stderr)[-300:]
    return report("wall_restart_exact", ok, note)


def main():
    if sys.argv[1:] == ["walls"]:
        return 1 if check_walls() + check_triaxial() else 0
    bad = check_gravel() + check_collisions() + check_pair_local() + check_trio() + \
        check_order() + check_restart() + check_wall_restart() + check_walls() + check_triaxial() + \
        check_reference()
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
