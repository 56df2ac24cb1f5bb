#!/usr/bin/python3
"""accuracy_map.py - `gravel -check deck` and `run N accuracy` (issue 13
item 7; src/contact/accuracy_map.c, doc/accuracy_map.md) on two decks of inputs/:

- inputs/examples/settle.in (gran/hooke/history, kn 1e5, gamma_n 100, m 1):
  the converged reference replay equals the damped linear oscillator of two
  free spheres (m* = 1/2): restitution exp(-gamma_n t_c / 2), contact time
  pi / omega_d and the largest overlap (1e-3); the rows are dt x 0.5, 1, 2
  (steps per collision in ratio 2, cost 2, 1, 0.5); the errors grow with dt;
  the run itself is not performed; the PNG is written where gnuplot exists.
- inputs/verification/hertz_collision.in (hertz/mindlin, e = 0.66): the
  reference rebounds at e (1e-3) and lasts the contact time of two free beads
  under the damped law (RK4 of its ODE, 1 %); at the scene's dt (t_col/32 of the frozen-partner collision, 24
  steps for two free beads) the restitution error is within the 1 % contract.
- `run 20 accuracy` on an inline deck prints the map and then runs."""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seeds_verify as sv  # noqa: E402
import verify_chung_ooi as vco  # noqa: E402

check = sv.check
ROOT = sv.ROOT


def check_map(deck, extra=()):
    with tempfile.TemporaryDirectory() as tmp:
        p = subprocess.run([sv.GRAVEL, "-check", deck, "-log", "none"] + list(extra), cwd=tmp,
                           capture_output=True, text=True, timeout=600)
        png = os.path.exists(os.path.join(tmp, "accuracy_map.png"))
    return p.returncode, p.stdout + p.stderr, png


ROW = re.compile(r"^(\S+)\s+(\S+)\s+(\S+)\s+(\S+)%\s+(\S+)\s+(\S+)%\s+(\S+) %\s+(\S+)")


def parse(out):
    ref = re.search(r"^(\S+)\s+(\S+)\s+(\S+)\s+reference\s+(\S+)\s+(\S+)$", out, re.M)
    rows = [ROW.match(x) for x in out.splitlines()]
    rows = [[float(g) for g in m.groups()] for m in rows if m]
    return (None if not ref else [float(g) for g in ref.groups()]), rows


def common(name, rc, out, rows, png):
    ok = rc == 0 and len(rows) == 3 and "Loop time" not in out and "-check: run" in out
    ok = ok and all(abs(rows[k][1] / rows[k + 1][1] - 2) < 0.02 for k in range(2))
    ok = ok and [r[7] for r in rows] == [2.0, 1.0, 0.5] and "<- the scene's time step" in out
    ok = ok and abs(rows[0][3]) <= abs(rows[2][3]) and abs(rows[0][6]) <= abs(rows[1][6]) <= abs(rows[2][6])
    check("accuracy map %s: rows dt x 0.5, 1, 2 (steps ratio 2, cost 2 1 0.5), errors grow with dt, "
          "run not performed" % name, ok, out[-400:] if not ok else "")
    if shutil.which("gnuplot"):
        check("accuracy map %s: accuracy_map.png written (gnuplot present)" % name,
              png and "accuracy_map.png" in out)


def settle():
    rc, out, png = check_map(os.path.join(ROOT, "inputs", "examples", "settle.in"))
    ref, rows = parse(out)
    kn, gam, meff, V = 1e5, 100.0, 0.5, math.sqrt(2 * 10.0 * 18.0)
    wd = math.sqrt(kn / meff - 0.25 * gam * gam)
    tc = math.pi / wd
    e = math.exp(-0.5 * gam * tc)
    ts = math.atan2(wd, 0.5 * gam) / wd
    xmax = V / wd * math.exp(-0.5 * gam * ts) * math.sin(wd * ts)
    ok = ref is not None and abs(ref[2] / e - 1) < 1e-3 and abs(ref[3] / (xmax / 0.5) - 1) < 1e-3 \
        and abs(ref[1] * ref[0] / tc - 1) < 1e-3 and "free fall over the box" in out
    check("accuracy map settle.in: reference e %.6f (exact %.6f), overlap/r %.5g (%.5g), t_col "
          "%.5g (%.5g)" % (ref[2] if ref else -1, e, ref[3] if ref else -1, xmax / 0.5,
                           ref[1] * ref[0] if ref else -1, tc), ok)
    common("settle.in", rc, out, rows, png)


def hertz():
    rc, out, png = check_map(os.path.join(ROOT, "inputs", "verification", "hertz_collision.in"))
    ref, rows = parse(out)
    G, nu, d, rho = 26e9, 0.23, 0.003, 2500.0
    E = 2 * G * (1 + nu)
    es = E / (2 * (1 - nu * nu))
    m = math.pi / 6 * d ** 3 * rho
    # two free beads (m* = m/2, R* = d/4) at V = 2 |u0| = 2: the damped law's duration (RK4)
    tc = vco.normal_ode("hertz/mindlin", es, d / 4, m / 2, 2.0, vco.tsuji_cd(0.66))[2]
    ok = ref is not None and abs(ref[2] / 0.66 - 1) < 1e-3 and abs(ref[1] * ref[0] / tc - 1) < 0.01 \
        and rows and abs(rows[1][3]) < 1.0
    check("accuracy map hertz_collision.in: reference e %.5f (0.66), t_col %.4g (law %.4g), "
          "restitution error at the scene's dt %+.3f %% (< 1 %%)"
          % (ref[2] if ref else -1, ref[1] * ref[0] if ref else -1, tc, rows[1][3] if rows else 99), ok)
    common("hertz_collision.in", rc, out, rows, png)


def keyword():
    deck = """units si
atom_style sphere
boundary f f f
region box block -1 1 -1 1 -1 1
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 0.2 0 0
set atom * diameter 0.1 density 1000
velocity all set 0.5 0 0
pair_style linear/restitution 1e5 0.5 0.3
pair_coeff * *
fix integ all nve/sphere
timestep 1e-4
run 20 accuracy
"""
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "in.k"), "w") as f:
            f.write(deck)
        p = subprocess.run([sv.GRAVEL, "-in", "in.k", "-log", "none"], cwd=tmp, capture_output=True,
                           text=True, timeout=600)
    out = p.stdout + p.stderr
    ref, rows = parse(out)
    check("run 20 accuracy: the map (reference e %.5f = 0.5) and then the run" % (ref[2] if ref else -1),
          p.returncode == 0 and ref is not None and abs(ref[2] / 0.5 - 1) < 1e-3 and len(rows) == 3
          and "Loop time of" in out and out.index("Accuracy map") < out.index("Loop time of"))


def main():
    for fn in (settle, hertz, keyword):
        try:
            fn()
        except (subprocess.TimeoutExpired, IndexError, TypeError, ValueError) as exc:
            check("accuracy map %s runs" % fn.__name__, False, str(exc)[-300:])
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
