#!/usr/bin/python3
"""hm_tangential_thesis.py - pair_style hertz/mindlin ... tangential thesis
(source document 003 sec. 4.3: the tangential displacement is V_t dt afresh
each step, c_t = 8 G sqrt(R*), no static friction) against the closed form.

Two 3 mm glass beads (003 fig. 5.24) overlap by delta = 1e-5 m; bead 2 slides
past bead 1 at v = 0.01 m/s (no spin), mu = 10 (no Coulomb cap).
1. `run 0`: bead 1's tangential force is
     thesis:  F_y = (8 G a dt + cd sqrt(8 G a m*)) v
     mindlin: F_y = cd sqrt(8 G* a m*) v   (no spring yet at setup)
   a = sqrt(R* delta), R* = R/2, m* = m/2, cd = 2 sqrt(5/6) beta; at dt =
   1e-8 and 4e-8 s (the thesis force depends on dt, Mindlin's does not).
2. No static friction: after 200 steps of sliding both beads are stopped
   (velocity and spin zero) and `run 0` evaluates again: the thesis gives no
   tangential force at all (F_y = F_z = 0 exactly), Mindlin's stored spring
   still pulls (|F_y| > 0).
3. `tangential` with a bad model or an odd keyword count is an error."""
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
E, NU, EPS, MU = 63.96e9, 0.23, 0.66, 10.0
R, RHO, DELTA, V = 1.5e-3, 2500.0, 1e-5, 0.01
failures = 0


def report(name, ok, detail):
    global failures
    print("  %s: %s" % (name, detail))
    print(("PASS " if ok else "FAIL ") + name)
    failures += not ok


def deck(model, dt, slide):
    tail = "run 0\n"
    if slide:
        tail = ("run %d\nvelocity all set 0 0 0 units box\nset atom * omega 0 0 0\nrun 0\n"
                % slide)
    return """units si
atom_style sphere
boundary f f f
region b block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 b
create_atoms 1 single 0 0 0 units box
create_atoms 1 single %.17g 0 0 units box
set type 1 diameter %.17g density %.17g
velocity all set 0 0 0 units box
set atom 2 vy %.17g
pair_style hertz/mindlin %.17g %g %g %g tangential %s
pair_coeff * *
neighbor 0.0005 bin
timestep %g
fix 1 all nve/sphere
%sprint "F1 $(fx[1]:%%.17g) $(fy[1]:%%.17g) $(fz[1]:%%.17g)"
print "D $(x[1]-x[2]:%%.17g) $(y[1]-y[2]:%%.17g) $(z[1]-z[2]:%%.17g)"
""" % (2 * R - DELTA, 2 * R, RHO, V, E, NU, EPS, MU, model, dt, tail)


def run(text, tmp):
    path = os.path.join(tmp, "in.hm")
    with open(path, "w") as f:
        f.write(text)
    return subprocess.run([GRAVEL, "-in", path, "-log", "none"], cwd=tmp, capture_output=True,
                          text=True, timeout=120)


def force(text, tmp):
    """bead 1's force and its part in the contact's tangent plane"""
    r = run(text, tmp)
    m = re.findall(r"^F1 (\S+) (\S+) (\S+)$", r.stdout, re.M)
    d = re.findall(r"^D (\S+) (\S+) (\S+)$", r.stdout, re.M)
    if r.returncode or not m or not d:
        return None, None, (r.stderr + r.stdout).strip()[-300:]
    f = [float(x) for x in m[-1]]
    d = [float(x) for x in d[-1]]
    n = [x / math.sqrt(sum(y * y for y in d)) for x in d]
    fn = sum(a * b for a, b in zip(f, n))
    return f, [a - fn * b for a, b in zip(f, n)], ""


def main():
    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    mstar, rstar = m / 2, R / 2
    a = math.sqrt(rstar * DELTA)
    lne = math.log(EPS)
    cd = 2 * math.sqrt(5.0 / 6.0) * (-lne / math.sqrt(lne * lne + math.pi ** 2))
    G = E / (2 * (1 + NU))
    Gs = G / (2 * (2 - NU))
    with tempfile.TemporaryDirectory() as tmp:
        for dt in (1e-8, 4e-8):
            want = {"thesis": (8 * G * a * dt + cd * math.sqrt(8 * G * a * mstar)) * V,
                    "mindlin": cd * math.sqrt(8 * Gs * a * mstar) * V}
            for model, w in want.items():
                f, _, err = force(deck(model, dt, 0), tmp)
                if f is None:
                    report("setup_%s_dt%g" % (model, dt), False, "run failed: " + err)
                    continue
                rel = abs(f[1] - w) / w
                report("setup_%s_dt%g" % (model, dt), rel < 1e-9,
                       "F_y on bead 1 %.10g N, closed form %.10g N (relative %.1e, limit 1e-9)"
                       % (f[1], w, rel))
        f_t, t_t, err_t = force(deck("thesis", 1e-8, 200), tmp)
        f_m, t_m, err_m = force(deck("mindlin", 1e-8, 200), tmp)
        ok = f_t is not None and f_m is not None
        if ok:
            tt, tm, fn = (math.sqrt(sum(x * x for x in v)) for v in (t_t, t_m, f_t))
            report("no_static_friction", tt < 1e-14 * fn and tm > 1e-3 * fn,
                   "stopped after 200 sliding steps: tangential force thesis %.3g N, mindlin "
                   "%.3g N (normal %.4g N; limits: thesis < 1e-14 of it, mindlin > 1e-3 of it)"
                   % (tt, tm, fn))
        else:
            report("no_static_friction", False, "run failed: " + (err_t or err_m or ""))
        for bad, msg in (("tangential history", "unknown tangential model 'history'"),
                         ("tangential", "expects E nu e mu")):
            text = deck("thesis", 1e-8, 0).replace("tangential thesis", bad)
            r = run(text, tmp)
            out = r.stderr + r.stdout
            err = [l for l in out.splitlines() if "ERROR" in l]
            report("error_" + bad.replace(" ", "_"), r.returncode != 0 and msg in out
                   and "in.hm:11" in out, err[0] if err else out.strip()[-200:])
    print("%d failure(s)" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
