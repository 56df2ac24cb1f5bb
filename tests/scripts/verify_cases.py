#!/usr/bin/python3
"""verify_cases.py - the drop test (003 sec. 6.1) and the oblique impact with
rotation, two verification decks of inputs/verification/ beyond those of
seeds_verify.py, checked with its machinery (run_deck, check, verify).

drop_test: a glass bead of 003 fig. 5.24 falls onto a sheet (hertz/mindlin on
fix wall/pair); the ratio of successive bounce heights returns e^2. The
reference restitution is that of the continuous force law (GSL rk8pd of the
same law, tools/seeds_ode.c, gravity neglected during the microsecond contact).

oblique_impact: the bead hits the wall at 1 m/s normal, 0.3 m/s tangential,
against a GSL rk8pd solution of the same law with the tangential spring, its
damping, the Coulomb limit and rotation (tools/verify_ode.c); run through
seeds_verify.verify at t_col/8 ... /128 in both precisions.

trapezoidal: fix drag `update trapezoidal` (000 eq. 3.8-3.9) on the drag case.

Usage: verify_cases.py [drop_test|oblique_impact|trapezoidal ...]   (default: all)"""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seeds_verify as sv  # noqa: E402

ROOT = sv.ROOT
M_PI = math.pi


class Glass:
    """003 fig. 5.24 glass bead: hertz/mindlin coefficients as the style packs them."""
    G, nu, e, rho, d, mu = 26e9, 0.23, 0.66, 2500.0, 0.003, 0.154

    def __init__(self):
        self.E = 2 * self.G * (1 + self.nu)
        self.Es = self.E / (2 * (1 - self.nu ** 2))
        self.Gs = self.E / (2 * (1 + self.nu)) / (2 * (2 - self.nu))
        self.kn = 4.0 / 3.0 * self.Es
        self.kt = 8.0 * self.Gs
        l = math.log(self.e)
        self.cd = 2 * math.sqrt(5.0 / 6.0) * (-l / math.sqrt(l * l + M_PI ** 2))
        self.m = sv.sphere_mass(self.d, self.rho)
        self.r = self.d / 2

    def tcol_wall(self, v):
        """Hertz contact duration against a wall (m* = m, R* = r) at speed v."""
        return 2.87 * (self.m ** 2 / (self.r * self.Es ** 2 * abs(v))) ** 0.2

    def e_law_wall(self, v):
        """Restitution of the continuous law for a head-on wall impact at v."""
        tc = self.tcol_wall(v)
        times = [tc * k / 1000.0 for k in range(1, 2001)]
        x0 = self.r
        args = [sv.ode_tool()] + ["%.17g" % q for q in (self.kn, self.cd, self.m, self.r, self.r,
                                                        x0, -abs(v))]
        p = subprocess.run(args, input="\n".join("%.17g" % t for t in times), capture_output=True,
                           text=True, check=True)
        return float(p.stdout.splitlines()[-1].split()[2]) / abs(v)


_VODE = None


def verify_ode_tool():
    """Build tools/verify_ode.c (oblique-impact reference) once."""
    global _VODE
    if _VODE is None:
        d = tempfile.mkdtemp(prefix="verify_ode")
        exe = os.path.join(d, "verify_ode")
        subprocess.run(["cc", "-O2", "-o", exe, os.path.join(ROOT, "tools", "verify_ode.c"),
                        "-lgsl", "-lgslcblas", "-lm"], check=True)
        _VODE = exe
    return _VODE


class ObliqueImpact(Glass):
    """Oblique wall impact with rotation vs the GSL reference of the same law.
    Errors: max over the run of |dx|,|dz| / max overlap and of |dvx|, |dvz|,
    r |dw_y| / |u0| (|u0| = impact speed)."""
    name = "oblique_impact"
    deck = "oblique_impact.in"
    vn, vt = 1.0, 0.3
    nsubs = (8, 16, 32, 64, 128)
    # first order: the slip-stick transitions are sampled by the step
    bound32 = {"x": 1e-2, "v": 1e-2}
    min_order = {"x": 0.9, "v": 0.9}
    xnorm, vnorm = "max overlap", "|u0|"
    restitution = True

    def __init__(self):
        Glass.__init__(self)
        self.u0 = math.hypot(self.vn, self.vt)
        self.tcol = self.tcol_wall(self.vn)
        self.z0 = self.r
        ref = self.reference([self.tcol * k / 1000.0 for k in range(1, 1501)])
        self.dmax = max(self.r - q[2] for q in ref)
        self.e_law = ref[-1][4] / self.vn
        self.ref_end = ref[-1]

    def reference(self, times):
        args = [verify_ode_tool()] + ["%.17g" % q for q in (self.kn, self.kt, self.cd, self.mu, self.m,
                                                            self.r, 0.0, self.z0, self.vt, -self.vn, 0.0)]
        p = subprocess.run(args, input="\n".join("%.17g" % t for t in times), capture_output=True,
                           text=True, check=True)
        return [tuple(float(w) for w in line.split()) for line in p.stdout.splitlines()]

    def vars(self, nsub):
        return {"nsub": nsub, "vn": self.vn, "vt": self.vt, "mu": self.mu}

    def errors(self, rows):
        ref = self.reference([r["Time"] for r in rows])
        ex = ev = 0.0
        for r, q in zip(rows, ref):
            ex = max(ex, abs(r["v_px"] - q[1]) / self.dmax, abs(r["v_pz"] - q[2]) / self.dmax)
            ev = max(ev, abs(r["v_vx"] - q[3]) / self.u0, abs(r["v_vz"] - q[4]) / self.u0,
                     self.r * abs(r["c_wy"] - q[5]) / self.u0)
        return {"x": ex, "v": ev, "e": rows[-1]["v_vz"] / self.vn}


class CohesiveCollision:
    """000 sec. 3.3.4, table 5.4: cohesive normal collision (A.2 piecewise closed form), u0 = -8 m/s rebounds.
    linear/restitution + cohesion through hybrid/overlay against the analytic
    solution of tests/scripts/cohesion.py (trajectory, analytic): incoming
    under cohesion only, body contact, outgoing under cohesion, free flight at
    the escape speed. Errors: max over the run of |dx| / d_b and |dv| / |u0|."""
    name = "cohesive_collision"
    deck = "cohesive_collision.in"
    u0, kc, tend = -8.0, 100.0, 0.02
    nsubs = (8, 16, 32, 64, 128)
    xnorm, vnorm = "d_b", "|u0|"
    restitution = False

    def __init__(self):
        import cohesion   # noqa: E402 (tests/scripts, on sys.path above)
        self.co = cohesion
        self.exact = cohesion.trajectory(self.u0, self.kc)
        self.an = cohesion.analytic(self.u0, self.kc)
        self.sy = cohesion.stickiness(self.u0, self.kc)

    def vars(self, nsub):
        return {"nsub": nsub, "u0": self.u0, "kc": self.kc, "tend": self.tend}

    def errors(self, rows):
        ex = ev = 0.0
        for r in rows:
            x, v = self.exact(r["Time"])
            ex = max(ex, abs(r["v_px"] - x) / self.co.DB)
            ev = max(ev, abs(r["v_vx"] - v) / abs(self.u0))
        return {"x": ex, "v": ev, "uout": abs(rows[-1]["v_vx"] - self.an["uout"]) / self.an["uout"]}


def bounce_heights(rows, r, g):
    """Apex heights (lowest point above the sheet) of the successive flights:
    h = z - r + vz^2/(2 g) from the free-flight samples (exact for velocity
    Verlet under constant gravity; the mean over the flight's samples). A new
    flight starts where vz turned from downwards to upwards between two
    free-flight samples (a bounce happened in between)."""
    flights, prev = [], None
    for row in rows:
        z, vz = row["v_pz"], row["v_vz"]
        if z <= r:
            continue
        h = z - r + vz * vz / (2 * g)
        if not flights or (prev is not None and prev < 0 < vz):
            flights.append([])
        flights[-1].append(h)
        prev = vz
    return [sum(f) / len(f) for f in flights]


class DropTest(Glass):
    """003 sec. 6.1: restitution from successive bounce heights."""
    name = "drop_test"
    deck = "drop_test.in"
    g = 9.81

    def __init__(self, h0=2e-4, nbounce=2):
        Glass.__init__(self)
        self.h0, self.nbounce = h0, nbounce
        self.v1 = math.sqrt(2 * self.g * h0)
        self.e_law = self.e_law_wall(self.v1)

    def vars(self, nsub):
        return {"nsub": nsub, "h0": self.h0, "nbounce": self.nbounce, "every": 10}

    def restitutions(self, rows):
        h = bounce_heights(rows, self.r, self.g)
        return [math.sqrt(h[k + 1] / h[k]) for k in range(len(h) - 1)], h


def drop_test():
    case = DropTest()
    print("# drop_test: glass bead from h0 = %g m, restitution of the law at %.3f m/s: %.5f "
          "(003 fig. 6.1 measured 0.659 0.658 0.657)" % (case.h0, case.v1, case.e_law))
    check = sv.check
    check("drop_test continuous-law restitution within 1%% of e = %g" % case.e,
          abs(case.e_law - case.e) < 0.01 * case.e, "%.5f" % case.e_law)
    for prec, nsub in (("double", 32), ("single", 16)):
        rows = sv.run_deck(case.deck, prec, case.vars(nsub))
        es, h = case.restitutions(rows)
        print("#   %-6s t_col/%-3d heights %s  e %s" % (prec, nsub, " ".join("%.4e" % x for x in h),
                                                       " ".join("%.5f" % x for x in es)))
        check("drop_test %s t_col/%d %d bounces seen" % (prec, nsub, case.nbounce),
              len(es) >= case.nbounce, "%d flights" % len(h))
        if not es:
            continue
        tol = 0.02 if nsub == 16 else 0.01
        worst = max(abs(x - case.e_law) / case.e_law for x in es)
        check("drop_test %s t_col/%d bounce-height restitution within %g%% of %.4f" %
              (prec, nsub, tol * 100, case.e_law), worst <= tol, " ".join("%.5f" % x for x in es))
        check("drop_test %s t_col/%d restitution below 1 at every bounce" % (prec, nsub), max(es) < 1.0)
        check("drop_test %s t_col/%d first drop height %g kept (1e-6 double, 1e-4 single)" % (prec, nsub, case.h0),
              abs(h[0] - case.h0) < (1e-6 if prec == "double" else 1e-4) * case.h0, "%.9e" % h[0])
        vx = max(abs(row["v_vx"]) for row in rows)
        check("drop_test %s t_col/%d no tangential motion (003: no motion in x-z)" % (prec, nsub),
              vx == 0.0, "max |vx| %g" % vx)


def oblique_impact():
    case = ObliqueImpact()
    q = case.ref_end
    print("# oblique_impact reference (GSL): out vx %.5f vz %.5f w_y r %.5f (in vt %.2f vn %.2f)" %
          (q[3], q[4], q[5] * case.r, case.vt, case.vn))
    # Physical sanity of the reference itself: friction slows the slip and
    # spins the sphere; angular momentum about the contact point is conserved
    # (m vx + I w / r constant for a force acting at the contact point).
    sv.check("oblique_impact reference spins the sphere (w_y r > 0) and slows vx",
             q[5] > 0 and q[3] < case.vt, "vx %.4f w r %.4f" % (q[3], q[5] * case.r))
    L0 = case.m * case.vt * case.r
    L1 = case.m * q[3] * case.r + 0.4 * case.m * case.r ** 2 * q[5]
    sv.check("oblique_impact reference conserves angular momentum about the contact point",
             abs(L1 - L0) < 1e-6 * abs(L0), "%.3e vs %.3e" % (L1, L0))
    sv.verify(case)


def trapezoidal():
    """fix drag update trapezoidal = 000 eq. 3.8-3.9 on the drag case (table
    5.1): gravel's trajectory equals the scheme's own recurrence
      v_{n+1} = (v_n + (dt/tau) u_f) / (1 + dt/tau),  x_{n+1} = x_n + dt (v_n + v_{n+1})/2
    to round-off; against the analytic solution it is first order (the
    backward-Euler velocity limits it), with about twice the error of the
    default `implicit` update (backward Euler on each velocity-Verlet half kick)."""
    base = sv.DragImplicit()
    errs = {}
    for upd in ("trapezoidal", "implicit"):
        c = sv.DragImplicit()
        c.update = upd
        for prec in ("double", "single"):
            for n in (8, 32, 128):
                if prec == "single" and upd == "implicit":
                    continue
                rows = sv.run_deck(c.deck, prec, c.vars(n))
                errs[upd, prec, n] = c.errors(rows)
                if upd != "trapezoidal":
                    continue
                dt = base.tau / n
                a = dt / base.tau
                x = v = 0.0
                worst = 0.0
                for k, r in enumerate(rows):
                    worst = max(worst, abs(r["v_px"] - x) / (base.uf * base.tau), abs(r["v_vx"] - v) / base.uf)
                    vn = (v + a * base.uf) / (1 + a)
                    x += dt * (v + vn) / 2
                    v = vn
                tol = 1e-12 if prec == "double" else 2e-6
                sv.check("trapezoidal %s tau/%d follows 000 eq. 3.8-3.9 exactly (< %g)" % (prec, n, tol),
                         worst < tol, "%.2e" % worst)
    print("# drag case, max error x/(u_f tau), v/u_f (double):")
    for upd in ("trapezoidal", "implicit"):
        print("#   %-11s %s" % (upd, "  ".join("tau/%d x %.2e v %.2e" % (n, errs[upd, "double", n]["x"],
                                                                          errs[upd, "double", n]["v"])
                                             for n in (8, 32, 128))))
    for q in ("x", "v"):
        o = sv.order([errs["trapezoidal", "double", n][q] for n in (8, 32, 128)], (8, 32, 128))
        sv.check("trapezoidal %s observed order 0.9..1.1 (first order)" % q, 0.9 <= o <= 1.1, "%.2f" % o)
        ratios = [errs["trapezoidal", "double", n][q] / errs["implicit", "double", n][q] for n in (8, 32, 128)]
        sv.check("trapezoidal %s error 1.5..2.5 x that of update implicit at every dt" % q,
                 all(1.5 <= r <= 2.5 for r in ratios), " ".join("%.2f" % r for r in ratios))


def main():
    names = sys.argv[1:]
    for name, fn in (("drop_test", drop_test), ("oblique_impact", oblique_impact), ("trapezoidal", trapezoidal)):
        if names and name not in names:
            continue
        try:
            fn()
        except (RuntimeError, subprocess.TimeoutExpired, subprocess.CalledProcessError) as exc:
            sv.check(name + " runs", False, str(exc))
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
