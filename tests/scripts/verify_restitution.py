#!/usr/bin/python3
"""verify_restitution.py - the restitution contract of the two source-document
contact laws (issue 13 item 1): a head-on collision of a sphere with a frozen
one (linear/restitution as inputs/verification/normal_collision.in,
hertz/mindlin as hertz_collision.in) must rebound at the nominal e to within
5 % at t_col/8 and 1 % at t_col/32, worst over the phase at which contact
starts within a step, for e from 0.01 to 1 (kernels/contact_normal.cl).

Each gravel run holds NPHASE independent pairs, far apart in y, whose gaps
put the start of contact at phases 0, 1/NPHASE, ... of the second step (a
contact that starts in the run's first drift is seen by a half kick of the
setup forces: LAMMPS' Verlet); e_eff of a pair is -v_out/v_in of its moving
sphere after the run. The Hertz law with the Tsuji-type damping of
hertz/mindlin rebounds at e itself (a fine-step solution of its ODE agrees to
1e-6), so both laws are checked against e.

linear/restitution integrates the two-body collision exactly (its pre-contact
kick, contact_normal_linear), so it is also held to round-off: 1e-10 in double
(the worst is 4.5e-12, at e = 0.01) and 1e-5 in single precision, for pairs and
for a sphere dropped on a `fix wall/pair zplane` (the mesh floor of
tests/unit/test_mesh.c follows that plane to 1e-10).

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
# linear/restitution is exact to round-off (pairs and walls)
ROUNDOFF = {"double": 1e-10, "single": 1e-5}

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


def sweep(law, e, nsub, prec="double", wall=False):
    """e_eff of the NPHASE pairs (list, phase order); wall: NPHASE spheres
    dropped on a fix wall/pair zplane at z = 0 instead (m* = m, as a frozen
    partner, so t_col is the same)."""
    p = LAWS[law]
    d, u0 = p["d"], p["u0"]
    m = math.pi / 6 * d ** 3 * p["rho"]
    dt = p["tcol"](m, e) / nsub
    lines = ["units si", "atom_style sphere", "boundary f f f",
             "region box block -%g %g -%g %g -%g %g" % (10 * d, 10 * d, 3 * d, 3 * d * NPHASE + 3 * d,
                                                         3 * d, 10 * d),
             "create_box 1 box"]
    for j in range(NPHASE):
        y = 3 * d * j
        gap = (1 + j / NPHASE) * u0 * dt
        if wall:
            lines.append("create_atoms 1 single 0 %.17g %.17g" % (y, d / 2 + gap))
        else:
            lines.append("create_atoms 1 single 0 %.17g 0" % y)
            lines.append("create_atoms 1 single %.17g %.17g 0" % (d + gap, y))
    mobile = [j + 1 for j in range(NPHASE)] if wall else [2 * j + 2 for j in range(NPHASE)]
    lines += ["set atom * diameter %g density %g" % (d, p["rho"]),
              "group mobile id %s" % " ".join(str(i) for i in mobile),
              "velocity mobile set %s" % ("0 0 %g" % -u0 if wall else "%g 0 0" % -u0),
              "timestep %.17g" % dt,
              p["pair"].format(e=e), "pair_coeff * *",
              "neighbor %g bin" % (0.1 * d), "fix integ all nve/sphere"]
    if wall:
        lines.append("fix floor all wall/pair zplane 0 NULL")
    else:
        lines += ["group fixed id %s" % " ".join(str(2 * j + 1) for j in range(NPHASE)),
                  "fix hold fixed freeze"]
    for j, i in enumerate(mobile):
        lines.append("variable v%d equal %s[%d]" % (j, "vz" if wall else "vx", i))
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


def measure_linear_roundoff():
    """{(what, prec, nsub, e): [e_eff per phase]} for linear/restitution:
    pairs in single precision and the wall in both (the pairs in double are
    measure()'s)."""
    res = {}
    for nsub in NSUBS:
        for e in ES:
            res[("pair", "single", nsub, e)] = sweep("linear/restitution", e, nsub, "single")
            for prec in ("double", "single"):
                res[("wall", prec, nsub, e)] = sweep("linear/restitution", e, nsub, prec, wall=True)
    return res


def table(res):
    out = ["| law | e | t_col/8: e_eff over entry phases | worst | t_col/32: e_eff over entry phases | worst |",
           "|---|---|---|---|---|---|"]
    for law in LAWS:
        for e in ES:
            cells = []
            for nsub in NSUBS:
                v = res[(law, nsub, e)]
                w = max((x / e - 1 for x in v), key=abs)
                cells.append("%.5g .. %.5g | %s" % (min(v), max(v), "%+.2f %%" % (100 * w)
                                                    if abs(w) >= 1e-5 else "%+.1e" % w))
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
        bound = CONTRACT[nsub]
        if law == "linear/restitution":
            bound = ROUNDOFF["double"]
        sv.check("restitution %s e=%g t_col/%d, %d entry phases: worst |e_eff/e - 1| <= %g"
                 % (law, e, nsub, NPHASE, bound), finite and worst <= bound,
                 "e_eff %.6g .. %.6g, worst %+.3g" % (min(v), max(v), max(
                     (x / e - 1 for x in v), key=abs)))
    for (what, prec, nsub, e), v in sorted(measure_linear_roundoff().items()):
        worst = max(abs(x / e - 1) for x in v)
        finite = all(math.isfinite(x) for x in v)
        sv.check("restitution linear/restitution %s %s e=%g t_col/%d, %d entry phases: "
                 "worst |e_eff/e - 1| <= %g (exact two-body collision)"
                 % (what, prec, e, nsub, NPHASE, ROUNDOFF[prec]),
                 finite and worst <= ROUNDOFF[prec],
                 "e_eff %.6g .. %.6g, worst %+.3g" % (min(v), max(v), max(
                     (x / e - 1 for x in v), key=abs)))
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
