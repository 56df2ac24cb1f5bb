#!/usr/bin/python3
"""verify_coeff_restitution.py - pair granular's `damping coeff_restitution`
(LAMMPS 2024, GranSubModDampingCoeffRestitution; styles/pair/pair_granular.c,
kernels/pair_granular.cl) against its analytic restitution, for pairs and for
its wall forms (fix wall/gran granular zplane, fix wall/gran/region granular,
fix wall/gran granular mesh).

The model puts the restitution coefficient e in the normal model's damping
slot and damps with eta_n = damp sqrt(m* Fne / delta):
- hooke: damp = -2 ln e / sqrt(pi^2 + ln^2 e), i.e. the linear
  spring-dashpot's damping ratio for e; its contact ends after half a damped
  period with exactly -e times the closing speed.
- hertz, hertz/material: damp = -sqrt(3/2) 2 sqrt(5/6) ln e / sqrt(pi^2 +
  ln^2 e), the Tsuji-type coefficient LAMMPS documents as reproducing e for
  monodisperse and polydisperse pairs, whatever the impact speed (an RK4
  solution of its ODE with 10^4 steps per collision gives e to 1e-6).

Checks, for an equal pair, an unequal pair (m*, R* differ), two types mixed as
LAMMPS 2024 mixes (e_IJ = sqrt(e_I e_J); hertz/material's E* of the two
materials) and the three walls (m* = m), at e = 0.1, 0.5, 0.9:
- gravel is the law: e_out equals a 1-d velocity-Verlet replica of the
  analytic force law (this file, `replica`) to 1e-12 at every time step run;
- the law gives e: the replica at t_col/10^5 rebounds at e within 2e-5;
- the integrator's precision: |e_out - e| <= 1e-3 at t_col/800, worst over
  four entry phases of the contact within a step, and the error falls as dt
  (observed order >= 0.8: velocity Verlet with a contact that starts and ends
  inside a step);
- the Hertz restitution is the same at impact speeds 0.25 and 4;
- single precision gives the double-precision e_out within 1e-5;
- errors: with dmt or jkr (LAMMPS: "Cannot use coeff_restitution model with a
  cohesive normal model") and for e outside (0, 1].

LAMMPS 2021 (`lmp`, Debian) has no coeff_restitution ("unrecognized damping
model"), so no lmp peer: the reference is the analytic restitution."""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seeds_verify as sv  # noqa: E402

GRAVEL = sv.GRAVEL
NPHASE = 4
ES = (0.1, 0.5, 0.9)
NSUBS = (50, 200, 800)
BOUND = 1e-3  # |e_out - e| at t_col / 800, worst over the entry phases
REPLICA = 1e-12  # |e_out (gravel) - e_out (replica)|
FINE, FINE_BOUND = 100000, 2e-5  # the replica's own time step t_col / FINE: |e_out - e|
D, RHO, KN = 0.01, 2500.0, 1.0e4
E_MAT, NU = 1.0e7, 0.3


def mass(d, rho=RHO):
    return math.pi / 6 * d ** 3 * rho


def kn_of(kind, wall=False, E=E_MAT, nu=NU):
    """the normal stiffness gravel keeps: hooke's kn; 4/3 E* (pair and,
    today's LAMMPS, wall: E* = E / (2 (1 - nu^2)))"""
    if kind == "hooke":
        return KN
    return 4.0 / 3.0 * E / (2 * (1 - nu * nu))


def damp_of(kind, e):
    """LAMMPS 2024 GranSubModDampingCoeffRestitution::init"""
    l = math.log(e)
    if kind == "hooke":
        return -2 * l / math.sqrt(math.pi ** 2 + l * l)
    return -math.sqrt(1.5) * 2 * math.sqrt(5.0 / 6.0) * l / math.sqrt(math.pi ** 2 + l * l)


def tcol(kind, kn, reff, meff, e, v):
    """half a damped period (hooke); the elastic Hertz duration 2.9432 delta_max / v"""
    if kind == "hooke":
        return math.pi * math.sqrt(meff / kn) * math.sqrt(1 + (math.log(e) / math.pi) ** 2)
    es = 0.75 * kn
    dmax = (15 * meff * v * v / (16 * es * math.sqrt(reff))) ** 0.4
    return 2.9432 * dmax / v


def normal(kind, e, E=E_MAT, nu=NU):
    if kind == "hooke":
        return "hooke %.17g %.17g" % (KN, e)
    if kind == "hertz":
        return "hertz %.17g %.17g" % (kn_of("hertz"), e)
    return "hertz/material %.17g %.17g %.17g" % (E, e, nu)


def model(kind, e, **kw):
    return "%s tangential linear_nohistory 0 0 damping coeff_restitution" % normal(kind, e, **kw)


def run(lines, prec="double"):
    with tempfile.TemporaryDirectory() as tmp:
        stl = os.path.join(tmp, "floor.stl")
        with open(stl, "w") as f:
            f.write("solid floor\n")
            for tri in (((-1, -1, 0), (1, -1, 0), (1, 1, 0)), ((-1, -1, 0), (1, 1, 0), (-1, 1, 0))):
                f.write("facet normal 0 0 1\nouter loop\n")
                for v in tri:
                    f.write("vertex %g %g %g\n" % v)
                f.write("endloop\nendfacet\n")
            f.write("endsolid floor\n")
        path = os.path.join(tmp, "in.cr")
        with open(path, "w") as f:
            f.write("\n".join(lines).replace("@STL@", stl) + "\n")
        return subprocess.run([GRAVEL, "-in", path, "-log", "none", "-precision", prec], cwd=tmp,
                              capture_output=True, text=True, timeout=600)


class Case:
    """One collision set-up. source pair: sphere 1 (type 1: D, RHO) moving at
    +u0/2 meets sphere 2 (type 2: d2, rho2) moving at -u0/2 along x, e_out =
    -(v2 - v1)_out / u0; types = pair_coeff lines (default `* *` of kind at
    e), with kn, e the law they make for 1-2. Walls (plane, region, mesh): a
    sphere falling at u0 on z = 0 (m* = m, R* = its radius), e_out = vz_out /
    u0. The contact starts at NPHASE phases of the second step."""

    def __init__(self, kind, e, source="pair", d2=D, rho2=RHO, types=None, kn=None, u0=1.0):
        self.kind, self.e, self.source, self.types, self.u0 = kind, e, source, types, u0
        self.wall = source != "pair"
        self.d2, self.rho2 = d2, rho2
        self.m1, self.m2 = mass(D), mass(d2, rho2)
        self.meff = self.m1 if self.wall else self.m1 * self.m2 / (self.m1 + self.m2)
        self.reff = D / 2 if self.wall else (D / 2) * (d2 / 2) / (D / 2 + d2 / 2)
        self.kn = kn if kn is not None else kn_of(kind, self.wall)
        self.damp = damp_of(kind, e)
        self.tc = tcol(kind, self.kn, self.reff, self.meff, e, u0)

    def gap(self, j, dt):
        return (1 + j / NPHASE) * self.u0 * dt

    def gravel(self, nsub, prec="double"):
        dt, u0 = self.tc / nsub, self.u0
        box = 3 * D * NPHASE + 3 * D
        lines = ["units si", "atom_style sphere", "boundary f f f", "comm_modify vel yes",
                 "region box block %g %g %g %g %g %g" % (-4 * D, 4 * D, -3 * D, box, -2 * D, 4 * D),
                 "create_box 2 box"]
        atoms = []
        for j in range(NPHASE):
            y = 3 * D * j
            if self.wall:
                lines.append("create_atoms 1 single 0 %.17g %.17g" % (y, D / 2 + self.gap(j, dt)))
                atoms.append((j + 1,))
            else:
                x2 = (D + self.d2) / 2 + self.gap(j, dt)
                lines.append("create_atoms 1 single 0 %.17g 0" % y)
                lines.append("create_atoms 2 single %.17g %.17g 0" % (x2, y))
                atoms.append((2 * j + 1, 2 * j + 2))
        lines += ["set type 1 diameter %g density %g" % (D, RHO),
                  "set type 2 diameter %.17g density %.17g" % (self.d2, self.rho2),
                  "timestep %.17g" % dt, "pair_style granular"]
        lines += self.types or ["pair_coeff * * " + model(self.kind, self.e)]
        lines += ["neighbor %g bin" % (0.2 * D), "fix integ all nve/sphere"]
        if self.wall:
            wm = model(self.kind, self.e)
            lines.append("velocity all set 0 0 %g" % -u0)
            if self.source == "plane":
                lines.append("fix floor all wall/gran granular %s zplane 0 NULL" % wm)
            elif self.source == "region":
                lines += ["region floor block -1 1 -1 1 0 1 side in units box",
                          "fix floor all wall/gran/region granular %s region floor" % wm]
            else:
                lines += ["fix m all mesh/surface file @STL@ type 1",
                          "fix floor all wall/gran granular %s mesh n_meshes 1 meshes m" % wm]
            for j, (i,) in enumerate(atoms):
                lines.append("variable v%d equal vz[%d]" % (j, i))
        else:
            lines += ["group one type 1", "group two type 2",
                      "velocity one set %g 0 0" % (u0 / 2), "velocity two set %g 0 0" % (-u0 / 2)]
            for j, (i, k) in enumerate(atoms):
                lines.append("variable v%d equal vx[%d]-vx[%d]" % (j, k, i))
        nsteps = 4 * nsub + 2
        lines += ["thermo_style custom step %s" % " ".join("v_v%d" % j for j in range(NPHASE)),
                  "thermo_modify format float %.16g", "thermo %d" % nsteps, "run %d" % nsteps]
        r = run(lines, prec)
        if r.returncode != 0:
            raise RuntimeError("%s %s e=%g t_col/%d failed: %s"
                               % (self.kind, self.source, self.e, nsub,
                                  (r.stdout + r.stderr)[-800:]))
        last = sv.thermo_rows(r.stdout)[-1]
        return [last["v_v%d" % j] / u0 for j in range(NPHASE)]

    def force(self, delta, vclose):
        """the normal force pushing the bodies apart at overlap delta and
        closing speed vclose (LAMMPS granular: Fne + damp sqrt(m* Fne/delta)
        vclose, zero out of touch)"""
        if delta <= 0:
            return 0.0
        if self.kind == "hooke":
            fne = self.kn * delta
        else:
            fne = self.kn * math.sqrt(delta * self.reff) * delta
        return fne + self.damp * math.sqrt(max(0.0, self.meff * fne / delta)) * vclose

    def replica(self, nsub, phases=None):
        """e_out of LAMMPS's velocity Verlet (half kick, drift, force at the
        drifted positions and half-kicked velocities, half kick) in 1-d"""
        dt, u0 = self.tc / nsub, self.u0
        out = []
        for j in (range(NPHASE) if phases is None else phases):
            if self.wall:
                x, v, f = [D / 2 + self.gap(j, dt)], [-u0], [0.0]
                m = [self.m1]
            else:
                x = [0.0, (D + self.d2) / 2 + self.gap(j, dt)]
                v, f, m = [u0 / 2, -u0 / 2], [0.0, 0.0], [self.m1, self.m2]
            for _ in range(4 * nsub + 2 if phases is None else 8 * nsub):
                for k in range(len(x)):
                    v[k] += 0.5 * dt * f[k] / m[k]
                    x[k] += dt * v[k]
                if self.wall:
                    f[0] = self.force(D / 2 - x[0], -v[0])
                else:
                    fn = self.force((D + self.d2) / 2 - (x[1] - x[0]), v[0] - v[1])
                    f[0], f[1] = -fn, fn
                for k in range(len(x)):
                    v[k] += 0.5 * dt * f[k] / m[k]
            out.append((v[0] if self.wall else v[1] - v[0]) / u0)
        return out


def worst(v, e):
    return max((x - e for x in v), key=abs)


def contract(name, case, e_expect=None):
    e = case.e if e_expect is None else e_expect
    errs, gaps = [], []
    for nsub in NSUBS:
        g = case.gravel(nsub)
        r = case.replica(nsub)
        errs.append(worst(g, e))
        gaps.append(max(abs(a - b) for a, b in zip(g, r)))
    sv.check("coeff_restitution %s e=%g: gravel = the velocity-Verlet replica of the law within "
             "%g at t_col/%s" % (name, e, REPLICA, "/".join(str(n) for n in NSUBS)),
             max(gaps) <= REPLICA, "worst %.2e" % max(gaps))
    sv.check("coeff_restitution %s e=%g: |e_out - e| at t_col/%d <= %g" % (name, e, NSUBS[-1],
                                                                           BOUND),
             all(math.isfinite(x) for x in errs) and abs(errs[-1]) <= BOUND,
             "t_col/%s: %s" % ("/".join(str(n) for n in NSUBS),
                               " ".join("%+.2e" % x for x in errs)))
    if abs(errs[0]) > 1e-6:
        order = math.log(abs(errs[0]) / max(abs(errs[-1]), 1e-300)) / math.log(
            NSUBS[-1] / NSUBS[0])
        sv.check("coeff_restitution %s e=%g: the error falls as dt (observed order >= 0.8)"
                 % (name, e), order >= 0.8,
                 "order %.2f: %s" % (order, " -> ".join("%.2e" % abs(x) for x in errs)))


def analytic(name, case, e_expect=None):
    """the law itself: the replica at t_col / FINE, one entry phase"""
    e = case.e if e_expect is None else e_expect
    x = case.replica(FINE, phases=[0])[0]
    sv.check("coeff_restitution %s e=%g: the law rebounds at e (replica at t_col/%d) within %g"
             % (name, e, FINE, FINE_BOUND), abs(x - e) <= FINE_BOUND, "%+.2e" % (x - e))


def error_case(line, expect):
    lines = ["atom_style sphere", "region box block -1 1 -1 1 -1 1", "create_box 1 box",
             "create_atoms 1 single 0 0 0", "pair_style granular", line]
    r = run(lines)
    out = r.stdout + r.stderr
    sv.check("coeff_restitution error: '%s' -> '%s'" % (line[:60], expect),
             r.returncode != 0 and expect in out, out.strip().splitlines()[-1] if out else "")


def main():
    quick = "--quick" in sys.argv
    es = (0.5,) if quick else ES
    for e in es:
        cases = [("hooke pair", Case("hooke", e)),
                 ("hooke unequal pair (d 2:1, rho 1:3)",
                  Case("hooke", e, d2=2 * D, rho2=RHO / 3)),
                 ("hertz pair", Case("hertz", e)),
                 ("hertz/material pair", Case("hertz/material", e)),
                 ("hertz/material unequal pair (d 2:1, rho 1:3)",
                  Case("hertz/material", e, d2=2 * D, rho2=RHO / 3))]
        cases += [("hooke wall/gran %s" % s, Case("hooke", e, source=s))
                  for s in ("plane", "region", "mesh")]
        cases += [("hertz/material wall/gran %s" % s, Case("hertz/material", e, source=s))
                  for s in ("plane", "region", "mesh")]
        for name, c in cases:
            contract(name, c)
        analytic("hooke", Case("hooke", e))
        analytic("hertz/material", Case("hertz/material", e))
        analytic("hertz/material unequal pair", Case("hertz/material", e, d2=2 * D,
                                                     rho2=RHO / 3))
    # the Hertz restitution does not depend on the impact speed
    for e in es:
        a = Case("hertz/material", e, u0=0.25).gravel(NSUBS[-1])
        b = Case("hertz/material", e, u0=4.0).gravel(NSUBS[-1])
        sv.check("coeff_restitution hertz/material e=%g: e_out the same at impact speeds "
                 "0.25 and 4 (and = e) within %g" % (e, BOUND),
                 abs(worst(a, e)) <= BOUND and abs(worst(b, e)) <= BOUND,
                 "%+.2e, %+.2e" % (worst(a, e), worst(b, e)))
    # single precision: the same collisions to float round-off
    for name, c in (("hertz/material pair", Case("hertz/material", 0.5)),
                    ("hooke wall/gran plane", Case("hooke", 0.5, source="plane"))):
        d, f = c.gravel(NSUBS[1]), c.gravel(NSUBS[1], "single")
        gap = max(abs(a - b) for a, b in zip(d, f))
        sv.check("coeff_restitution %s e=0.5 t_col/%d: single precision = double within 1e-5"
                 % (name, NSUBS[1]), gap <= 1e-5, "worst %.2e" % gap)
    # LAMMPS 2024 mixing: types 1 (e1) and 2 (e2) collide at sqrt(e1 e2); hooke kn
    # geometric, hertz/material kn = 4/3 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)
    e1, e2 = 0.3, 0.8
    em = math.sqrt(e1 * e2)
    mix = ["pair_coeff 1 1 " + model("hooke", e1), "pair_coeff 2 2 " + model("hooke", e2)]
    contract("hooke mixed types (e %g, %g)" % (e1, e2), Case("hooke", em, types=mix))
    E2, nu2 = 4e7, 0.25
    mix = ["pair_coeff 1 1 " + model("hertz/material", e1),
           "pair_coeff 2 2 " + model("hertz/material", e2, E=E2, nu=nu2)]
    kn = 4.0 / 3.0 / ((1 - NU * NU) / E_MAT + (1 - nu2 * nu2) / E2)
    contract("hertz/material mixed types (e %g, %g; E %g, %g)" % (e1, e2, E_MAT, E2),
             Case("hertz/material", em, types=mix, kn=kn))
    error_case("pair_coeff * * dmt 1e7 0.5 0.3 0.1 tangential linear_nohistory 0 0 damping "
               "coeff_restitution", "Cannot use coeff_restitution model with a cohesive normal "
               "model, dmt")
    error_case("pair_coeff * * damping coeff_restitution jkr 1e7 0.5 0.3 0.1 tangential "
               "linear_nohistory 0 0", "cohesive normal model, jkr")
    error_case("pair_coeff * * hooke 1e4 0 tangential linear_nohistory 0 0 damping "
               "coeff_restitution", "must be in (0, 1], got 0")
    error_case("pair_coeff * * hooke 1e4 1.5 tangential linear_nohistory 0 0 damping "
               "coeff_restitution", "must be in (0, 1], got 1.5")
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
