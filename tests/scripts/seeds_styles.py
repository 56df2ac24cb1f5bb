#!/usr/bin/python3
"""seeds_styles.py - behaviour and error checks of the source-document styles
(pair linear/restitution, pair hertz/mindlin, fix drag, fix wall/pair) on
small decks with closed-form expectations. One PASS/FAIL line per check."""
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
failures = 0


def check(name, ok, detail=""):
    global failures
    print(("PASS " if ok else "FAIL ") + name + (" (" + detail + ")" if detail else ""))
    if not ok:
        failures += 1


def run(text, precision="double"):
    """Run a script; return (rc, stdout+stderr, last thermo row as dict)."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.test")
        with open(path, "w") as f:
            f.write(text)
        p = subprocess.run([GRAVEL, "-in", path, "-log", "none", "-precision", precision],
                           cwd=tmp, capture_output=True, text=True, timeout=120)
    out = p.stdout + p.stderr
    header, last = None, None
    for line in p.stdout.splitlines():
        w = line.split()
        if w and w[0] == "Step":
            header = w
        elif header and len(w) == len(header):
            try:
                last = {h: float(x) for h, x in zip(header, w)}
            except ValueError:
                pass
    return p.returncode, out, last


BOX = """units si
atom_style sphere
boundary f f f
region box block -1 1 -1 1 -1 1
create_box 1 box
"""


def error_case(name, body, expect):
    rc, out, _ = run(BOX + body)
    ok = rc != 0 and expect in out and "ERROR" in out
    check("error: " + name, ok, out.strip().splitlines()[-1][:160] if out.strip() else "no output")


def errors():
    error_case("restitution above 1", "pair_style linear/restitution 1e5 1.2 0.5\n",
               "restitution coefficient e must be in (0, 1]")
    error_case("restitution zero", "pair_style linear/restitution 1e5 0 0.5\n",
               "restitution coefficient e must be in (0, 1]")
    error_case("zero stiffness", "pair_style linear/restitution 0 0.8 0.5\n", "stiffness ke")
    error_case("unknown linear keyword", "pair_style linear/restitution 1e5 0.8 0.5 kt 3\n",
               "unknown pair_style linear/restitution keyword 'kt'")
    error_case("linear too few", "pair_style linear/restitution 1e5 0.8\n", "expects ke e mu")
    error_case("hertz poisson", "pair_style hertz/mindlin 1e9 0.6 0.8 0.3\n",
               "Poisson ratio nu must be in (-1, 0.5]")
    error_case("hertz rolling keyword", "pair_style hertz/mindlin 1e9 0.3 0.8 0.3 rollin 0.1\n",
               "expected rolling")
    error_case("hertz negative rolling", "pair_style hertz/mindlin 1e9 0.3 0.8 0.3 rolling -1\n",
               "mu_r")
    error_case("drag flow", "fix d all drag 1e-3 couette 1\n", "unknown fix drag flow 'couette'")
    error_case("drag viscosity", "fix d all drag 0 uniform 1 0 0\n", "fluid viscosity mu")
    error_case("drag update", "fix d all drag 1e-3 uniform 1 0 0 update crank\n",
               "fix drag update must be explicit, implicit or exact")
    error_case("drag uniform arity", "fix d all drag 1e-3 uniform 1 0\n", "uniform")
    error_case("taylor_green wave number", "fix d all drag 1e-3 taylor_green 1 0\n",
               "wave number a")
    error_case("wall/pair style", "fix w all wall/pair zcylinder 1 2\n",
               "unknown fix wall/pair wall style 'zcylinder'")
    error_case("wall/pair null faces", "fix w all wall/pair zplane NULL NULL\n", "both NULL")
    error_case("wall/pair without pair style",
               "create_atoms 1 single 0 0 0\nset atom * diameter 0.1 density 10\n"
               "fix i all nve/sphere\nfix w all wall/pair zplane -0.5 NULL\nrun 1\n",
               "needs a pair style")


def taylor_green():
    """Explicit drag force at setup = 3 pi mu d u_f(x0) for a particle at rest,
    in the vortex of eq. 6.1-6.3 and in source 000's code's variant
    (taylor_green/demoranges: w with cos(a X) for sin(a X))."""
    A, a, mu, d = 0.7, 2.0, 0.01, 0.1
    x0 = (0.13, -0.21, 0.37)
    for flow in ("taylor_green", "taylor_green/demoranges"):
        rc, out, row = run(BOX + """create_atoms 1 single %g %g %g
set atom * diameter %g density 10
fix i all nve/sphere
fix d all drag %g %s %g %g update explicit
variable fx equal fx[1]
variable fy equal fy[1]
variable fz equal fz[1]
thermo_style custom step v_fx v_fy v_fz
thermo_modify format float %%.16g
run 0
""" % (x0 + (d, mu, flow, A, a)))
        sh = math.pi / (2 * a)
        X, Y, Z = (a * (c + sh) for c in x0)
        wx = math.cos(X) if flow.endswith("demoranges") else math.sin(X)
        uf = (A * math.cos(X) * math.sin(Y) * math.sin(Z),
              A * math.sin(X) * math.cos(Y) * math.sin(Z), -2 * A * wx * math.sin(Y) * math.cos(Z))
        beta = 3 * math.pi * mu * d
        if row is None:
            check("%s explicit force at setup" % flow, False, out[-300:])
            continue
        got = (row["v_fx"], row["v_fy"], row["v_fz"])
        err = max(abs(g - beta * u) for g, u in zip(got, uf))
        check("%s explicit force at setup = 3 pi mu d u_f(x) (eq. 6.1-6.3%s)"
              % (flow, "; w with cos(a X)" if flow.endswith("demoranges") else ""),
              err < 1e-12 * beta * A, "max diff %.2e of %.3e" % (err, beta * A))


def terminal_velocity():
    """Implicit/exact drag with gravity (drag defined last): the velocity
    relaxes to the terminal velocity g tau exactly (steady state of the update)."""
    mu, d, rho, g = 0.05, 0.01, 2500.0, 9.81
    tau = rho * d * d / (18 * mu)
    for upd in ("implicit", "exact"):
        rc, out, row = run(BOX.replace("-1 1 -1 1 -1 1", "-1 1 -1 1 -100 1") + """create_atoms 1 single 0 0 0
set atom * diameter %g density %g
fix i all nve/sphere
fix g all gravity %g vector 0 0 -1
fix d all drag %g uniform 0 0 0 update %s
timestep %.17g
variable vz equal vz[1]
thermo_style custom step v_vz
thermo_modify format float %%.16g
run 400
""" % (d, rho, g, mu, upd, tau / 8))
        want = -g * tau
        ok = row is not None and abs(row["v_vz"] - want) < 1e-9 * abs(want)
        check("drag %s terminal velocity = -g tau (drag defined after gravity)" % upd, ok,
              "%s vs %.10g" % (row and row["v_vz"], want))
    rc, out, _ = run(BOX + """create_atoms 1 single 0 0 0
set atom * diameter 0.01 density 2500
fix i all nve/sphere
fix d all drag 0.05 uniform 0 0 0
fix g all gravity 9.81 vector 0 0 -1
run 1
""")
    check("drag warns when a force fix follows it", rc == 0 and "WARNING" in out and
          "treats it explicitly" in out, out.strip().splitlines()[-1][:120] if out else "")


def drag_resort():
    """fix drag exact with many particles of different sizes moving through
    neighbor rebuilds and re-sorts: the per-atom effective drag follows its
    atom, so every particle keeps the exact solution v = u_f + (v0 - u_f)
    exp(-t/tau_i) to round-off."""
    mu, rho, uf, dt, nsteps = 0.01, 10.0, 1.0, 0.01, 300
    parts = []
    lines = []
    for k in range(8):
        d = 0.05 + 0.01 * k
        v0 = (-1.5, 2.0, 0.3, -0.7, 1.2, -2.2, 0.0, 0.9)[k]
        y = -1.75 + 0.5 * k
        parts.append((d, v0))
        lines.append("create_atoms 1 single 0 %g 0\nset atom %d diameter %g density %g vx %g"
                     % (y, k + 1, d, rho, v0))
    text = """units si
atom_style sphere
boundary f f f
region box block -20 20 -2 2 -1 1
create_box 1 box
%s
pair_style linear/restitution 1e5 0.8 0.5
pair_coeff * *
neighbor 0.002 bin
neigh_modify every 1 delay 0 check yes
fix i all nve/sphere
fix d all drag %g uniform %g 0 0 update exact
timestep %g
%s
thermo_style custom step time %s
thermo_modify format float %%.16g
thermo 100
# the particles never touch: dt need not resolve a collision (verify: run ... force yes)
run %d force yes
""" % ("\n".join(lines), mu, uf, dt,
       "\n".join("variable v%d equal vx[%d]" % (k + 1, k + 1) for k in range(8)),
       " ".join("v_v%d" % (k + 1) for k in range(8)), nsteps)
    rc, out, row = run(text)
    if row is None:
        check("drag re-sort runs", False, out[-300:])
        return
    builds = 0
    for line in out.splitlines():
        if line.startswith("Neighbor list builds"):
            builds = int(line.split()[-1])
    t = row["Time"]
    worst = 0.0
    for k, (d, v0) in enumerate(parts):
        tau = rho * d * d / (18 * mu)
        want = uf + (v0 - uf) * math.exp(-t / tau)
        worst = max(worst, abs(row["v_v%d" % (k + 1)] - want))
    check("drag exact: 8 particles through %d neighbor rebuilds keep the exact velocity" % builds,
          builds > 5 and worst < 1e-12, "max error %.2e" % worst)


def slide_to_roll():
    """linear/restitution torque yes: a sliding sphere on a wall ends rolling at
    5/7 of its initial speed (solid sphere, I = 2/5 m r^2)."""
    ke, e, mu, d, rho, g, u0 = 1e5, 0.8, 0.3, 0.1, 10.0, 9.81, 1.0
    m = math.pi / 6 * d ** 3 * rho
    for torque, want in (("yes", 5.0 / 7.0 * u0), ("no", 0.0)):
        rc, out, row = run(BOX + """create_atoms 1 single 0 0 %.17g
set atom * diameter %g density %g
velocity all set %g 0 0
pair_style linear/restitution %g %g %g torque %s
pair_coeff * *
fix i all nve/sphere
fix g all gravity %g vector 0 0 -1
fix w all wall/pair zplane 0 NULL
timestep 2e-5
variable vx equal vx[1]
compute rot all erotate/sphere
thermo_style custom step v_vx c_rot
thermo_modify format float %%.16g
run 20000
""" % (d / 2 - m * g / ke, d, rho, u0, ke, e, mu, torque, g))
        if row is None:
            check("slide-to-roll torque %s runs" % torque, False, out[-300:])
            continue
        wr = math.sqrt(5 * row["c_rot"] / m)     # E_rot = 0.2 m (omega r)^2
        if torque == "yes":
            ok = abs(row["v_vx"] - want) < 0.01 * u0 and abs(wr - row["v_vx"]) < 0.01 * u0
            check("linear/restitution torque yes: sliding sphere rolls at 5/7 u0", ok,
                  "v %.5f omega r %.5f want %.5f" % (row["v_vx"], wr, want))
        else:
            ok = abs(row["v_vx"]) < 1e-3 and row["c_rot"] == 0.0
            check("linear/restitution torque no: sphere stops without spinning (000 model)", ok,
                  "v %.3g omega r %.3g" % (row["v_vx"], wr))


def rolling_resistance():
    """hertz/mindlin rolling mu_r on a wall: a rolling sphere decelerates at
    mu_r g / 1.4 (torque mu_r R* m g, R* = r, I + m r^2 = 1.4 m r^2); without
    rolling resistance it keeps its speed."""
    E, nu, e, mu, d, rho, g, v0, T = 1e8, 0.3, 0.5, 0.5, 0.01, 2500.0, 9.81, 0.5, 0.1
    m = math.pi / 6 * d ** 3 * rho
    r = d / 2
    Es = E / (2 * (1 - nu * nu))
    delta0 = (m * g / (4.0 / 3.0 * Es * math.sqrt(r))) ** (2.0 / 3.0)
    for mur in (0.0, 0.05):
        extra = " rolling %g" % mur if mur > 0 else ""
        rc, out, row = run(BOX + """create_atoms 1 single 0 0 %.17g
set atom * diameter %g density %g
velocity all set %g 0 0
set atom 1 omega 0 %.17g 0
pair_style hertz/mindlin %g %g %g %g%s
pair_coeff * *
fix i all nve/sphere
fix g all gravity %g vector 0 0 -1
fix w all wall/pair zplane 0 NULL
timestep 1e-5
variable vx equal vx[1]
thermo_style custom step time v_vx
thermo_modify format float %%.16g
run %d
""" % (r - delta0, d, rho, v0, v0 / r, E, nu, e, mu, extra, g, int(round(T / 1e-5))))
        if row is None:
            check("rolling mu_r %g runs" % mur, False, out[-300:])
            continue
        want = v0 - mur * g / 1.4 * T
        check("hertz/mindlin rolling mu_r=%g: v(T) = v0 - mu_r g T / 1.4" % mur,
              abs(row["v_vx"] - want) < 0.01 * v0, "v %.5f want %.5f" % (row["v_vx"], want))


def wall_bounce():
    """hertz/mindlin against fix wall/pair (history kept per atom): a glass bead
    hitting the wall head on at 1 m/s and obliquely rebounds with e_n = e within
    2 % at ~t_col/32 (the continuous law returns e; sec. 4.3 damping with m* = m,
    R* = r for a wall); the oblique hit spins the bead."""
    G, nu, e, rho, d = 26e9, 0.23, 0.66, 2500.0, 0.003
    E = 2 * G * (1 + nu)
    m = math.pi / 6 * d ** 3 * rho
    Es = E / (2 * (1 - nu * nu))
    tcol = 2.87 * (m * m / (d / 2 * Es * Es * 1.0)) ** 0.2
    for vx in (0.0, 0.5):
        rc, out, row = run("""units si
atom_style sphere
boundary f f f
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 box
create_atoms 1 single 0 0 %.17g
set atom * diameter %g density %g
velocity all set %g 0 -1
pair_style hertz/mindlin %g %g %g 0.154
pair_coeff * *
fix i all nve/sphere
fix w all wall/pair zplane 0 NULL
timestep %.17g
variable vz equal vz[1]
compute rot all erotate/sphere
thermo_style custom step v_vz c_rot
thermo_modify format float %%.16g
run 80
""" % (d / 2 * (1 - 1e-6), d, rho, vx, E, nu, e, tcol / 32))
        if row is None:
            check("wall bounce vx=%g runs" % vx, False, out[-300:])
            continue
        check("hertz/mindlin on wall/pair vx=%g: normal restitution %.4f within 2%% of %g" % (vx, row["v_vz"], e),
              abs(row["v_vz"] - e) <= 0.02 * e)
        if vx > 0:
            check("hertz/mindlin on wall/pair oblique hit spins the bead", row["c_rot"] > 0,
                  "E_rot %.3g" % row["c_rot"])


def oblique_pair():
    """Oblique impact of two equal free spheres: momentum is conserved to
    round-off (the evaluators are exactly antisymmetric) and both spheres get
    the same spin (torque on both, 003 sec. 4.4)."""
    styles = (("hertz/mindlin", "hertz/mindlin 6.4e10 0.23 0.66 0.154 rolling 0.01", 400),
              ("linear/restitution", "linear/restitution 1e5 0.8 0.5 torque yes", 700))
    for name, pair, nsteps in styles:
        for prec, tol in (("double", 1e-12), ("single", 1e-5)):
            rc, out, row = run("""units si
atom_style sphere
boundary f f f
region box block -0.05 0.05 -0.05 0.05 -0.05 0.05
create_box 1 box
create_atoms 1 single -0.00265 0 0
create_atoms 1 single 0 0.0015 0
set atom * diameter 0.003 density 2500
velocity all set 0 0 0
set atom 1 vx 1.0 vy 0.3
pair_style %s
pair_coeff * *
neighbor 0.001 bin
fix i all nve/sphere
timestep 2e-7
variable px equal vx[1]*mass[1]+vx[2]*mass[2]
variable py equal vy[1]*mass[1]+vy[2]*mass[2]
variable p0 equal 1.0*mass[1]
group a1 id 1
group a2 id 2
compute r1 a1 erotate/sphere
compute r2 a2 erotate/sphere
thermo_style custom step v_px v_py v_p0 c_r1 c_r2
thermo_modify format float %%.16g
run %d
""" % (pair, nsteps), prec)
            if row is None:
                check("%s oblique pair %s runs" % (name, prec), False, out[-300:])
                continue
            p0 = row["v_p0"]
            ok = abs(row["v_px"] - p0) < tol * p0 * 10 and abs(row["v_py"] - 0.3 * p0) < tol * p0 * 10
            check("%s %s oblique impact conserves momentum" % (name, prec), ok,
                  "px %.10g py %.10g p0 %.10g" % (row["v_px"], row["v_py"], p0))
            w1, w2 = row["c_r1"], row["c_r2"]
            check("%s %s oblique impact spins both spheres equally" % (name, prec),
                  w1 > 0 and abs(w1 - w2) <= 1e-4 * w1, "E_rot %.6g %.6g" % (w1, w2))


def drag_explicit_limit():
    """fix drag update explicit warns at setup when dt >= 2 tau_p of the
    smallest particle of its group (forward Euler on the velocity: stable
    below), naming the fix, dt, tau_p and the atom, with the run's line; at
    1.9 tau_p it stays silent and the particle relaxes to the flow."""
    mu, rho = 0.05, 2500.0
    dsmall, dbig = 0.01, 0.02
    tau = rho * dsmall ** 2 / (18 * mu)
    for ratio, warn in ((1.9, False), (2.0, True), (3.0, True)):
        body = ("create_atoms 1 single 0 0 0\ncreate_atoms 1 single 0.5 0 0\n"
                "set atom 1 diameter %g density %g\nset atom 2 diameter %g density %g\n"
                "velocity all set 1 0 0\ntimestep %.17g\nfix i all nve/sphere\n"
                "fix slow all drag %g uniform 0 0 0 update explicit\n"
                "variable v2 equal vx[2]\nthermo_style custom step v_v2\nrun 40\n"
                % (dbig, rho, dsmall, rho, ratio * tau, mu))
        rc, out, last = run(BOX + body)
        nline = (BOX + body).count("\n")          # the run command is the last line
        warned = [l for l in out.splitlines() if l.startswith("WARNING") and "drag" in l]
        if warn:
            w = warned[0] if warned else ""
            # past the limit the particle may leave the box: the warning came first
            ok = (len(warned) == 1 and "fix slow drag update explicit" in w
                  and ("timestep %g" % (ratio * tau)) in w and ("tau_p = %g" % tau) in w
                  and "atom 2" in w and "update implicit or exact" in w and w.endswith("in.test:%d)" % nline))
            check("drag explicit at dt = %.1f tau_p: setup warning names fix, dt, tau_p, atom, line"
                  % ratio, ok, w[:200] or out.strip()[-200:])
        else:
            ok = (rc == 0 and not warned and last is not None
                  and abs(float(last["v_v2"])) < 0.05)
            check("drag explicit at dt = 1.9 tau_p: no warning, stable", ok,
                  "%s %s" % (warned[:1], last))


def main():
    errors()
    taylor_green()
    terminal_velocity()
    drag_resort()
    slide_to_roll()
    rolling_resistance()
    oblique_pair()
    wall_bounce()
    drag_explicit_limit()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
