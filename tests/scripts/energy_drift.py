#!/usr/bin/python3
"""energy_drift.py - the run footer reports the energy drift per collision
time where energy is conserved (issue 13 item 6): an elastic pair style
without friction (linear/restitution e = 1 mu = 0, hertz/mindlin e = 1 mu = 0
mu_r = 0, gran/* gamman = 0 xmu = 0) and only nve, nve/sphere or freeze fixes.
Energy = kinetic (with rotation) + elastic energy of the contacts (src/io/output.c).

- two spheres overlapping at rest across a periodic boundary: the footer's
  starting energy is the contact's elastic energy (linear 1/2 ke delta^2,
  Hertz 0.4 kn sqrt(R*) delta^2.5), and the two-body normal impulse returns
  it to O((w dt)^2) (its discrete energy, exactly conserved, differs from the
  continuous one by that at a start from rest);
- a dense elastic gas (1000 spheres, 15 steps per collision): the line is
  there and small;
- no line with damping (e < 1), friction, or gravity.

`energy_drift.py --table` prints drift against the time step for make verify."""
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seeds_verify as sv  # noqa: E402

GRAVEL = sv.GRAVEL
check = sv.check
LINE = re.compile(r"Energy drift \(energy-conserving run\) = (\S+) per collision time "
                  r"\(kinetic \+ contact energy (\S+) -> (\S+) over (\S+) collision times of (\S+)\)")


def run(text, prec="double"):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.drift")
        with open(path, "w") as f:
            f.write(text)
        p = subprocess.run([GRAVEL, "-in", path, "-precision", prec, "-log", "none"], cwd=tmp,
                           capture_output=True, text=True, timeout=300)
    out = p.stdout + p.stderr
    m = LINE.search(out)
    return p.returncode, out, (tuple(float(x) for x in m.groups()) if m else None)


def pair_deck(pair, d=0.001, overlap=2e-5):
    # centres 0.5 mm inside either face of a 10 mm periodic box: they touch
    # through the boundary only (nearest image)
    return """units si
atom_style sphere
boundary p p p
region box block 0 0.01 0 0.01 0 0.01
create_box 1 box
create_atoms 1 single %.17g 0.005 0.005
create_atoms 1 single %.17g 0.005 0.005
set atom * diameter %g density 2500
%s
pair_coeff * *
timestep 2e-7
fix 1 all nve/sphere
thermo 1000
run 3000
""" % (0.5 * (d - overlap), 0.01 - 0.5 * (d - overlap), d, pair)


GAS = """units si
atom_style sphere
boundary p p p
lattice sc 0.00105
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 box
set atom * diameter 0.001 density 2500
velocity all create 1e15 4928459 dist gaussian
%s
pair_coeff * *
variable m equal PI/6*0.001^3*2500
variable tcol equal sqrt(0.5*${m}/1e3)*PI
timestep $(v_tcol/%g)
fix 1 all nve/sphere
%s
thermo 500
run %d
"""


def gas(pair, nsub=15, extra="", nsteps=2000, prec="double"):
    return run(GAS % (pair, nsub, extra, nsteps), prec)


def two_body():
    d, ov, ke = 0.001, 2e-5, 1e3
    rc, out, m = run(pair_deck("pair_style linear/restitution %g 1 0" % ke, d, ov))
    want = 0.5 * ke * ov * ov
    # the scheme conserves its discrete energy exactly; from rest it differs
    # from 1/2 ke delta^2 by O((w dt)^2) = 6e-5 here, once, not as a drift
    check("drift footer: linear pair overlapping through a periodic face, E0 = 1/2 ke delta^2, "
          "E1 within (w dt)^2", rc == 0 and m is not None and abs(m[1] / want - 1) < 1e-9
          and abs(m[2] / m[1] - 1) < 5e-5,
          "%s (want E0 %.10g)" % (m, want))
    E, nu = 1e7, 0.3
    rc, out, m = run(pair_deck("pair_style hertz/mindlin %g %g 1 0" % (E, nu), d, ov))
    es = E / (2 * (1 - nu * nu))
    want = 0.4 * (4.0 / 3.0) * es * math.sqrt(d / 4) * ov ** 2.5
    check("drift footer: Hertz pair, E0 = 0.4 kn sqrt(R*) delta^2.5, E1 within (w dt)^2",
          rc == 0 and m is not None and abs(m[1] / want - 1) < 1e-9 and abs(m[2] / m[1] - 1) < 5e-5,
          "%s (want E0 %.10g)" % (m, want))


def dense_gas():
    for pair in ("pair_style linear/restitution 1e3 1 0", "pair_style hertz/mindlin 1e7 0.3 1 0",
                 "pair_style gran/hooke 1e3 NULL 0 NULL 0 0"):
        rc, out, m = gas(pair)
        ok = rc == 0 and m is not None and abs(m[0]) < 2e-5 and m[3] > 50
        check("drift footer: dense elastic gas (%s), 15 steps per collision: |drift| < 2e-5 per "
              "collision time" % pair.split()[1], ok, "%s" % (m,))
    for pair, extra, why in (("pair_style linear/restitution 1e3 0.9 0", "", "e = 0.9"),
                             ("pair_style linear/restitution 1e3 1 0.3", "", "friction"),
                             ("pair_style hertz/mindlin 1e7 0.3 1 0 rolling 0.1", "", "rolling resistance"),
                             ("pair_style gran/hooke 1e3 NULL 10 NULL 0 0", "", "gran damping"),
                             ("pair_style linear/restitution 1e3 1 0", "fix 2 all gravity 1 vector 0 0 -1",
                              "gravity")):
        rc, out, m = gas(pair, extra=extra, nsteps=100)
        check("drift footer: no line with %s" % why, rc == 0 and m is None and "Loop time" in out,
              out.strip().splitlines()[-1][:120] if out.strip() else "")


def table():
    rows = ["| pair style | precision | t_col/8 | t_col/15 | t_col/32 |", "|---|---|---|---|---|"]
    for pair in ("pair_style linear/restitution 1e3 1 0", "pair_style hertz/mindlin 1e7 0.3 1 0",
                 "pair_style gran/hooke 1e3 NULL 0 NULL 0 0"):
        for prec in ("double", "single"):
            cells = []
            for nsub in (8, 15, 32):
                rc, out, m = gas(pair, nsub=nsub, nsteps=int(round(2000 * nsub / 15.0)), prec=prec)
                cells.append("%+.2e" % m[0] if m else "-")
            rows.append("| %s | %s | %s |" % (pair.split()[1], prec, " | ".join(cells)))
    return rows


def main():
    if "--table" in sys.argv:
        print("\n".join(table()))
        return 0
    two_body()
    dense_gas()
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
