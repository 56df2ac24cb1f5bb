#!/usr/bin/python3
"""verify_restitution.py - the restitution contract of the two source-document
contact laws (issue 13 item 1): a head-on collision of a sphere with a frozen
one (linear/restitution as inputs/verification/normal_collision.in,
hertz/mindlin as hertz_collision.in) must rebound at the nominal e to within
5 % at t_col/8 and 1 % at t_col/32, worst over the phase at which contact
starts within a step, for e from 0.01 to 1 (kernels/contact_normal.cl).

Each gravel run holds NPHASE independent pairs, far apart in y, whose gaps
put the start of contact at phases 0, 1/NPHASE, ... of a step; e_eff of a
pair is -v_out/v_in of its moving sphere after the run. The Hertz law with
the Tsuji-type damping of hertz/mindlin rebounds at e itself (a fine-step
solution of its ODE agrees to 1e-6), so both laws are checked against e.

Known limit (asserted as measured, not as the contract): the linear law at
t_col/8 and e < 0.1. There one step of free flight, u0 t_col/8, is longer
than the deepest overlap the collision reaches (1.7 times at e = 0.01, 1.17
at e = 0.05, 0.97 at e = 0.1), so for entry phases near a step the first
kick sees an overlap no real collision at that speed has: to a history-free
kick that state is the same as a harder collision's, and it rebounds as one.

`verify_restitution.py --table` prints the markdown table that
tools/verify_doc.py puts in doc/verification.md."""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seeds_verify as sv  # noqa: E402

GRAVEL = sv.GRAVEL
NPHASE = 8
NCOL = 4   # collision durations run: heavily damped Hertz contacts outlast the elastic t_col
ES = (0.01, 0.05, 0.1, 0.3, 0.5, 0.8, 1.0)
NSUBS = (8, 32)
CONTRACT = {8: 0.05, 32: 0.01}
# measured worst |e_eff/e - 1| where the contract is out of reach (see above),
# with a margin: a regression there still fails
KNOWN_LIMIT = {("linear/restitution", 8, 0.01): 1.10, ("linear/restitution", 8, 0.05): 0.09}

LAWS = {
    # name: (diameter, density, impact speed, pair_style line with {e}, collision time(m, e))
    "linear/restitution": dict(
        d=0.1, rho=10.0, u0=2.0, pair="pair_style linear/restitution 1e5 {e} 0.0",
        tcol=lambda m, e: math.sqrt(m / 1e5) * math.sqrt(math.pi ** 2 + math.log(e) ** 2)),
    "hertz/mindlin": dict(
        d=0.003, rho=2500.0, u0=1.0, pair="pair_style hertz/mindlin 63.96e9 0.23 {e} 0.154",
        # elastic Hertz duration at u0: m* = m (frozen partner), R* = d/4
        tcol=lambda m, e: 2.87 * (m * m / (0.003 / 4 * (63.96e9 / (2 * (1 - 0.23 ** 2))) ** 2
                                           * 1.0)) ** 0.2),
}


def sweep(law, e, nsub, prec="double"):
    """e_eff of the NPHASE pairs (list, phase order)."""
    p = LAWS[law]
    d, u0 = p["d"], p["u0"]
    m = math.pi / 6 * d ** 3 * p["rho"]
    dt = p["tcol"](m, e) / nsub
    lines = ["units si", "atom_style sphere", "boundary f f f",
             "region box block -%g %g -%g %g -%g %g" % (10 * d, 10 * d, 3 * d, 3 * d * NPHASE + 3 * d,
                                                         3 * d, 3 * d),
             "create_box 1 box"]
    for j in range(NPHASE):
        y = 3 * d * j
        gap = (1 + j / NPHASE) * u0 * dt
        lines.append("create_atoms 1 single 0 %.17g 0" % y)
        lines.append("create_atoms 1 single %.17g %.17g 0" % (d + gap, y))
    lines += ["set atom * diameter %g density %g" % (d, p["rho"]),
              "group fixed id %s" % " ".join(str(2 * j + 1) for j in range(NPHASE)),
              "group mobile id %s" % " ".join(str(2 * j + 2) for j in range(NPHASE)),
              "velocity mobile set %g 0 0" % -u0,
              "timestep %.17g" % dt,
              p["pair"].format(e=e), "pair_coeff * *",
              "neighbor %g bin" % (0.1 * d), "fix integ all nve/sphere", "fix hold fixed freeze"]
    for j in range(NPHASE):
        lines.append("variable v%d equal vx[%d]" % (j, 2 * j + 2))
    nsteps = int(round(NCOL * nsub + 2))
    lines += ["thermo_style custom step %s" % " ".join("v_v%d" % j for j in range(NPHASE)),
              "thermo_modify format float %.16g", "thermo %d" % nsteps,
              "run %d force yes" % nsteps]
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.rest")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        r = subprocess.run([GRAVEL, "-in", path, "-precision", prec, "-log", "none"], cwd=tmp,
                           capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        raise RuntimeError("%s e=%g t_col/%d failed: %s" % (law, e, nsub, (r.stdout + r.stderr)[-600:]))
    rows = sv.thermo_rows(r.stdout)
    last = rows[-1]
    return [last["v_v%d" % j] / u0 for j in range(NPHASE)]


def measure():
    """{(law, nsub, e): [e_eff per phase]}"""
    return {(law, nsub, e): sweep(law, e, nsub) for law in LAWS for nsub in NSUBS for e in ES}


def table(res):
    out = ["| law | e | t_col/8: e_eff over entry phases | worst | t_col/32: e_eff over entry phases | worst |",
           "|---|---|---|---|---|---|"]
    for law in LAWS:
        for e in ES:
            cells = []
            for nsub in NSUBS:
                v = res[(law, nsub, e)]
                cells.append("%.5g .. %.5g | %+.2f %%" % (min(v), max(v),
                                                          100 * max((x / e - 1 for x in v), key=abs)))
            out.append("| %s | %g | %s | %s |" % (law, e, cells[0], cells[1]))
    return out


def main():
    res = measure()
    if "--table" in sys.argv:
        print("\n".join(table(res)))
        return 0
    for (law, nsub, e), v in sorted(res.items()):
        worst = max(abs(x / e - 1) for x in v)
        finite = all(math.isfinite(x) for x in v)
        bound = KNOWN_LIMIT.get((law, nsub, e), CONTRACT[nsub])
        what = "known limit" if (law, nsub, e) in KNOWN_LIMIT else "contract"
        sv.check("restitution %s e=%g t_col/%d, %d entry phases: worst |e_eff/e - 1| <= %g (%s)"
                 % (law, e, nsub, NPHASE, bound, what), finite and worst <= bound,
                 "e_eff %.6g .. %.6g, worst %+.3f %%" % (min(v), max(v), 100 * max(
                     (x / e - 1 for x in v), key=abs)))
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
