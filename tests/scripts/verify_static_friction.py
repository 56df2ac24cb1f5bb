#!/usr/bin/python3
"""verify_static_friction.py - pair granular's tangential linear_history/static
and mindlin/static (today's LAMMPS, GranSubModTangential*Static; kernels/
pair_granular.cl grt_static) against the block-on-an-incline limit, through a
fix wall/gran granular plane and through a pair contact (a sphere on a
frozen sphere of radius 1e4), with both models.

The sphere is integrated by fix nve (no rotation: it slides as a block) on a
plane under gravity tilted to tan(theta), mu_s = 0.6, mu_d = 0.3:
- at rest at tan(theta) = 0.5 < mu_s it stays (|vx| < 1e-9 after settling);
- sliding (first at tan(theta) = 0.8 > mu_s, then tilted back to 0.5) it keeps
  sliding at the dynamic-friction acceleration g (sin - mu_d cos) (relative
  error below 1e-6 wall, 2e-3 pair: the frozen sphere's curvature) in
  both phases: the hysteresis of the static/dynamic switch;
- linear_history with mu = mu_s = 0.6, same history, stops in the second
  phase (the reference without the switch: |vx| < 1e-3 of its speed at the tilt).
Errors: a missing dynamic coefficient, mindlin/static's NULL kt without
material properties, linear_history/static's NULL kt, twisting marshall."""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from physics_lammps import GRAVEL  # noqa: E402

DT = 0.0002
END = 7500
MUS, MUD = 0.6, 0.3

HEAD = """units lj
atom_style sphere
boundary f f f
timestep 0.0002
variable vx equal vx[1]
thermo_style custom step v_vx
thermo_modify format float %.17g
thermo 1250
"""

WALL = HEAD + """region box block -50 50 -5 5 -1 5 units box
create_box 1 box
create_atoms 1 single 0.0 0.0 0.49991 units box
set type 1 diameter 1.0 density 1.9098593171027443
fix 1 all nve
fix w all wall/gran granular {normal} damping velocity tangential {tang} zplane 0.0 NULL
"""

PAIR = HEAD + """region box block -50 50 -5 5 -20001 5 units box
create_box 2 box
create_atoms 1 single 0.0 0.0 0.49991 units box
create_atoms 2 single 0.0 0.0 -10000.0 units box
set type 1 diameter 1.0 density 1.9098593171027443
set type 2 diameter 20000.0 density 1.0
group mover type 1
fix 1 mover nve
pair_style granular
pair_coeff * * {normal} damping velocity tangential {tang}
neighbor 0.3 bin
"""

GRAVITY = "fix g mover gravity 1.0 vector {t} 0.0 -1.0\n"

MODELS = (
    ("linear_history/static", "hooke 10000 100",
     f"linear_history/static 4000 1.5 {MUS} {MUD}", f"linear_history 4000 1.5 {MUS}"),
    ("mindlin/static", "hertz/material 1e6 100 0.3",
     f"mindlin/static NULL 1.5 {MUS} {MUD}", f"mindlin NULL 1.5 {MUS}"),
)


def run(deck):
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "in.s"), "w") as f:
            f.write(deck)
        r = subprocess.run([GRAVEL, "-in", "in.s", "-log", "none"], cwd=tmp,
                           capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        return None, r.stdout[-500:] + r.stderr[-500:]
    rows = {}
    for line in r.stdout.splitlines():
        w = line.split()
        if len(w) == 2 and w[0].isdigit():
            rows[int(w[0])] = float(w[1])
    return rows, ""


def accel(t):
    n = math.hypot(t, 1.0)
    return t / n - MUD / n


def deck(base, normal, tang, t1, t2):
    d = base.format(normal=normal, tang=tang)
    if base is WALL:
        d = d.replace("fix 1 all nve", "group mover type 1\nfix 1 mover nve")
    d += GRAVITY.format(t=t1) + "run 2500\nunfix g\n" + GRAVITY.format(t=t2) + "run 5000\n"
    return d


def main():
    failed = 0

    def report(ok, name, text):
        nonlocal failed
        print(f"  {name}: {text}")
        print(f"{'PASS' if ok else 'FAIL'} static_friction_{name}")
        failed += not ok

    for label, base, tol in (("wall", WALL, 1e-6), ("pair", PAIR, 2e-3)):
        for name, normal, tang, plain in MODELS:
            tag = f"{label}_{name.replace('/', '_')}"
            rows, err = run(deck(base, normal, tang, 0.5, 0.5))
            ok = rows is not None and abs(rows[END]) < 1e-9
            report(ok, f"{tag}_holds", f"at rest, tan 0.5 < mu_s: vx = "
                   f"{rows[END] if rows else err}")
            rows, err = run(deck(base, normal, tang, 0.8, 0.5))
            if rows is None:
                report(False, f"{tag}_slides", err)
                continue
            a1 = (rows[2500] - rows[1250]) / (1250 * DT)
            a2 = (rows[END] - rows[END - 1250]) / (1250 * DT)
            e1 = abs(a1 / accel(0.8) - 1)
            e2 = abs(a2 / accel(0.5) - 1)
            report(e1 < tol and e2 < tol, f"{tag}_slides",
                   f"sliding at tan 0.8 then 0.5: a = {a1:.9f}, {a2:.9f}, g (sin - mu_d cos) = "
                   f"{accel(0.8):.9f}, {accel(0.5):.9f} (relative {e1:.1e}, {e2:.1e})")
            rows, err = run(deck(base, normal, plain, 0.8, 0.5))
            ok = rows is not None and abs(rows[END]) < 1e-3 * abs(rows[2500])
            report(ok, f"{tag}_reference_stops", f"{plain.split()[0]} mu = mu_s, same "
                   f"history: vx = {rows[2500] if rows else err} at the tilt, "
                   f"{rows[END] if rows else ''} at the end")
    bad = (
        ("missing_mud", "hooke 10000 100", "linear_history/static 4000 1.5 0.6",
         "expected a number for dynamic friction coefficient, got 'zplane'"),
        ("null_kt_hooke", "hooke 10000 100", "mindlin/static NULL 1.5 0.6 0.3",
         "NULL setting for Mindlin tangential stiffness requires"),
        ("null_kt_linear", "hertz/material 1e6 100 0.3", "linear_history/static NULL 1.5 0.6 0.3",
         "expected a number for tangential stiffness kt, got 'NULL'"),
        ("marshall", "hooke 10000 100", "linear_history/static 4000 1.5 0.6 0.3 twisting marshall",
         "twisting marshall takes its friction"),
    )
    for name, normal, tang, want in bad:
        rows, err = run(WALL.format(normal=normal, tang=tang) + "run 1\n")
        ok = rows is None and want in err
        msg = [w for w in err.splitlines() if "ERROR" in w]
        report(ok, f"error_{name}", msg[0][msg[0].index("ERROR"):] if msg else "ran")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
