#!/usr/bin/env python3
"""viscous_nonlinear.py - fix viscous/nonlinear (LAMMPS 2026 Schiller-Naumann drag).

1. LAMMPS's own unit cases, as gravel decks (tests/reference/lammps_unittest):
   dem09-viscous-nonlinear-3d-si (LAMMPS 4 Jul 2026) and dem06-nonlinear-3d
   (LAMMPS 30 Mar 2026). Positions and velocities after each run segment must
   match LAMMPS's reference values (the .ref files, copied from the YAML
   cases' run_pos and run_vel) to 1e-8 relative: |a - b| <= 1e-8 max(|b|, s),
   s the largest |value| of that quantity (a zero component is compared to the
   vector's scale; a periodic coordinate to the box, 4).
2. Analytic decay: a sphere launched at v0 through still gas without gravity
   slows as m dv/dt = -1/2 Cd(Re) rho pi r^2 v^2 (Cd = 24/Re (1 + 0.15
   Re^0.687)); gravel's velocity and distance at t = 2 match a fine RK4
   solution of that ODE to 1e-3 relative, and the error is first order in
   the time step (LAMMPS's velocity Verlet takes the drag of the half-step
   velocity): halving dt halves it (ratio 1.8 .. 2.2). With a moving gas
   (velocity keyword) the sphere relaxes to the gas velocity the same way.
3. Terminal velocity: dem09's sphere reaches the v_t of m g = F(v_t) to
   0.5 % (LAMMPS's analytic_tol for that case).
4. Bad input: clear errors."""
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REF = os.path.join(ROOT, "tests", "reference", "lammps_unittest")
sys.path.insert(0, os.path.dirname(__file__))
from physics_lammps import read_dump  # noqa: E402


def check(ok, name, detail=""):
    print(f"{'PASS' if ok else 'FAIL'} {name}{(': ' + detail) if detail else ''}")
    return ok


def read_ref(path):
    rows = {}
    for line in open(path):
        if line.strip() and not line.startswith("#"):
            w = line.split()
            rows[int(w[0])] = [float(v) for v in w[2:]]
    return rows


def start(deck_path, tmp, text=None):
    if text is not None:
        deck_path = os.path.join(tmp, "in.deck")
        with open(deck_path, "w") as f:
            f.write(text)
    return subprocess.Popen([GRAVEL, "-in", deck_path, "-log", "none", "-echo", "none"],
                            cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def drag(v, r, rho, mu):
    """|F| of the Schiller-Naumann drag at speed v"""
    if v == 0:
        return 0.0
    re = rho * v * 2 * r / mu
    cd = 24 / re * (1 + 0.15 * re ** 0.687)
    return 0.5 * cd * rho * math.pi * r * r * v * v


def rk4(v0, m, r, rho, mu, t, n=200000):
    """v(t), x(t) of m dv/dt = -F(v) (v > 0)"""
    h, v, x = t / n, v0, 0.0
    f = lambda u: -drag(u, r, rho, mu) / m  # noqa: E731
    for _ in range(n):
        k1 = f(v)
        k2 = f(v + h / 2 * k1)
        k3 = f(v + h / 2 * k2)
        k4 = f(v + h * k3)
        x += h * v + h * h / 6 * (k1 + k2 + k3)
        v += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return v, x


DECAY = """units lj
atom_style sphere
boundary f f f
region box block -1 200 -5 5 -5 5 units box
create_box 1 box
create_atoms 1 single 0 0 0 units box
set group all diameter 1.0 density 1.0
velocity all set {vx} 0 0 units box
fix integr all nve/sphere
fix drag all viscous/nonlinear 1.0 0.01{extra}
timestep {dt}
dump d all custom {n} out.dump id x y z vx vy vz
dump_modify d format float %.17g
run {n}
"""


def main():
    ok = True
    tmps = [tempfile.TemporaryDirectory() for _ in range(6)]
    t1, t2, t3, t4, t5, t6 = (t.name for t in tmps)
    if True:
        cases = {"dem09_viscous_nonlinear": t1, "dem06_nonlinear": t2}
        procs = {n: start(os.path.join(REF, n + ".in"), t) for n, t in cases.items()}
        procs["decay"] = start(None, t3, DECAY.format(vx=3.0, extra="", dt=0.001, n=2000))
        procs["gas"] = start(None, t4, DECAY.format(vx=0.0, extra=" velocity 2.0 0.0 0.0",
                                                     dt=0.001, n=2000))
        procs["decay_half"] = start(None, t5, DECAY.format(vx=3.0, extra="", dt=0.0005, n=4000))
        procs["gas_half"] = start(None, t6, DECAY.format(vx=0.0, extra=" velocity 2.0 0.0 0.0",
                                                          dt=0.0005, n=4000))
        out = {n: p.communicate(timeout=600)[0] for n, p in procs.items()}
        for name, tmp in cases.items():
            if procs[name].returncode != 0:
                ok &= check(False, f"lammps_unittest_{name}", out[name][-600:])
                continue
            got, ref = read_dump(os.path.join(tmp, "out.dump")), read_ref(
                os.path.join(REF, name + ".ref"))
            worst, where = 0.0, ""
            for step, vals in ref.items():
                if step not in got:
                    worst, where = math.inf, f"step {step} missing"
                    break
                g = got[step][1]
                for k in range(6):
                    scale = max(abs(vals[3 * (k // 3) + q]) for q in range(3))
                    if name == "dem06_nonlinear" and k < 3:
                        scale = max(scale, 4.0)  # the periodic box length
                    err = abs(g[k] - vals[k]) / max(scale, 1e-300)
                    if err > worst:
                        worst, where = err, f"step {step} column {k}"
            ok &= check(worst <= 1e-8, f"lammps_unittest_{name}",
                        f"worst relative difference {worst:.2e} ({where})")
            if name == "dem09_viscous_nonlinear":
                r, m, g0 = 5e-5, 2000.0 * 4 / 3 * math.pi * 5e-5 ** 3, 9.81
                lo, hi = 0.0, 10.0
                for _ in range(200):
                    mid = 0.5 * (lo + hi)
                    lo, hi = (mid, hi) if drag(mid, r, 1.2, 1.8e-5) < m * g0 else (lo, mid)
                vt = 0.5 * (lo + hi)
                vz = -got[6000][1][5]
                ok &= check(abs(vz - vt) / vt < 0.005, "viscous_nonlinear_terminal_velocity",
                            f"v = {vz:.6g}, analytic v_t = {vt:.6g}")
        m = math.pi / 6
        for name, tmp, th, v0, vg in (("decay", t3, t5, 3.0, 0.0), ("gas", t4, t6, 0.0, 2.0)):
            if procs[name].returncode != 0 or procs[name + "_half"].returncode != 0:
                ok &= check(False, f"viscous_nonlinear_{name}", out[name][-600:])
                continue
            row = read_dump(os.path.join(tmp, "out.dump"))[2000][1]
            half = read_dump(os.path.join(th, "out.dump"))[4000][1]
            # relative to the gas: u = v - vg decays from v0 - vg
            u0 = v0 - vg
            u, s = rk4(abs(u0), m, 0.5, 1.0, 0.01, 2.0)
            u, s = math.copysign(u, u0), math.copysign(s, u0)
            ev = abs(row[3] - vg - u) / abs(u0)
            ex = abs(row[0] - (s + vg * 2.0)) / abs(s + vg * 2.0)
            ratio = ev / max(abs(half[3] - vg - u) / abs(u0), 1e-300)
            ok &= check(ev < 1e-3 and ex < 1e-3 and 1.8 < ratio < 2.2 and row[4] == 0 and
                        row[5] == 0, f"viscous_nonlinear_analytic_{name}",
                        f"v {row[3]:.12g} vs {u + vg:.12g} (rel {ev:.1e}, {ratio:.2f}x smaller "
                        f"at dt/2), x rel {ex:.1e}")
    for t in tmps:
        t.cleanup()
    # bad input
    bad = [("fix d all viscous/nonlinear 1.2", "expects rho_gas mu_gas"),
           ("fix d all viscous/nonlinear 0 1.8e-5", "gas density"),
           ("fix d all viscous/nonlinear 1.2 -1", "gas viscosity"),
           ("fix d all viscous/nonlinear 1.2 1e-5 velocity 1 2", "velocity"),
           ("fix d all viscous/nonlinear 1.2 1e-5 speed 1 2 3", "unknown keyword 'speed'")]
    head = ("units si\natom_style sphere\nregion b block 0 1 0 1 0 1\ncreate_box 1 b\n")
    for line, want in bad:
        with tempfile.TemporaryDirectory() as tmp:
            p = start(None, tmp, head + line + "\n")
            txt = p.communicate(timeout=120)[0]
            err = [ln for ln in txt.splitlines() if ln.startswith("ERROR")]
            ok &= check(p.returncode != 0 and bool(err) and want in err[0] and ":5)" in err[0],
                        f"viscous_nonlinear_error {line.split(' all ')[1][:40]}",
                        err[0] if err else txt.strip()[-160:])
    return 0


if __name__ == "__main__":
    sys.exit(main())
