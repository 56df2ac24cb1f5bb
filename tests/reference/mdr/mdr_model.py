#!/usr/bin/python3
"""mdr_model.py - an independent Python statement of today's LAMMPS `mdr`
normal model of pair granular with `damping mdr` and the per-atom
bookkeeping of its fix granular/mdr, for two spheres in head-on contact
(Zunker and Kamrin 2024 I, II; Zunker et al. 2025; LAMMPS
gran_sub_mod_normal.cpp GranSubModNormalMDR, gran_sub_mod_damping.cpp
GranSubModDampingMDR, fix_granular_mdr.cpp as of 2025-2026, see
doc/styles/pair_granular_normal.md): the reference gravel's mdr must meet
(tests/scripts/lammps_granular_mdr.py); the apparent-radius growth of the
fix changes the force of even one plastic contact.

Scope: pair contacts and a sphere against a flat wall (WallContact, with
its wall force magnifier); the bulk response and the mean surface
displacement are kept; a contact's penalty
(it needs three mutually overlapping particles) is its attribute `penalty`,
set by the caller from `penalty_increment` (fix granular/mdr's contact
screening), 0 for two atoms.

Units are the caller's; E, nu, Y, gamma, psi_b, eta_n0 as in `pair_coeff *
* mdr E nu Y gamma psi_b eta_n0 damping mdr dtype`."""
import math

OVERLAP_LIMIT = 0.95
NR_MAX, NR_EPS1, NR_EPS2, EPS3 = 100, 1e-10, 1e-16, 1e-20
A_FAC = 0.99          # the adhesive contact radius stays below 0.99 a_max
N_WINDOW = 10.0       # the running mean of the radius increments


def csqrt(x):
    """C's sqrt: NaN below 0 (LAMMPS's Newton-Raphson can step to a negative
    radius; its NaN then runs the loop out to a = 0)"""
    return math.sqrt(x) if x >= 0 else float("nan")


def f_flat(d, A, B, Es):
    """The MDR force of an elliptical indenter of height A and width B pushed
    d into an elastic half space of plane-strain modulus Es (Part I, the
    sphere on a rigid flat: A = 4R, B = 2R)."""
    x = d / A
    return 0.25 * Es * A * B * (math.acos(1 - 2 * x) - (2 - 4 * x) * math.sqrt(x - x * x))


def penalty_increment(alpha):
    """the penalty a contact gets from one third particle that overlaps both
    of its atoms, alpha the angle at that third particle between the
    directions to the contact's two atoms (Zunker et al. 2025): a sigmoid
    that is ~1 when the third particle sits between them (alpha > pi/2)"""
    return 1.0 / (1.0 + math.exp(-50.0 * (alpha / math.pi - 0.5)))


class Material:
    def __init__(self, E, nu, Y, gamma, psi_b, eta, dtype):
        self.E, self.nu, self.Y, self.gamma, self.psi_b, self.eta, self.dtype = \
            E, nu, Y, gamma, psi_b, eta, dtype
        self.G = E / (2 * (1 + nu))
        self.kappa = E / (3 * (1 - 2 * nu))
        self.Es = E / (1 - nu * nu)

    def p_yield(self, dmax, R):
        """mean pressure on the yield surface at the largest MDR overlap"""
        return self.Y * (1.75 * math.exp(-4.4 * dmax / R) + 1)

    def p_hertz(self, d, R):
        return 4 * self.Es * math.sqrt(d) / (3 * math.pi * math.sqrt(R))

    def delta_yield(self, R):
        """the MDR overlap of one side where p_hertz reaches p_yield (bisection)"""
        lo, hi = 0.0, R
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if self.p_hertz(mid, R) > self.p_yield(mid, R):
                hi = mid
            else:
                lo = mid
        return hi


class Atom:
    def __init__(self, tag, R):
        self.tag, self.R, self.Ro = tag, R, R
        self.Vo = 4 / 3 * math.pi * R ** 3
        self.Vgeo = self.Velas = self.Vo
        self.Acon0 = self.Acon1 = 0.0
        self.psi, self.ddelta_bar, self.dRavg = 1.0, 0.0, 0.0
        self.zero_sums()

    def zero_sums(self):
        self.Vcaps = self.eps_bar = self.dRnum = self.dRden = 0.0
        self.Acon1 = self.Atot_sum = 0.0

    def update(self, psi_b, radius_update=True):
        """fix granular/mdr's pre_force for one atom (outside setup)"""
        Rsq = self.R * self.R
        self.Vgeo = min(4 / 3 * math.pi * Rsq * self.R - self.Vcaps, self.Vo)
        self.Velas = self.Vo * (1 + self.eps_bar)
        Atot = 4 * math.pi * Rsq + self.Atot_sum
        self.psi = (Atot - self.Acon1) / Atot
        if psi_b < self.psi and radius_update:
            w = 1 / (1 + math.exp(-75 * (self.psi - 0.2))) if self.psi > 0.1 else 0.0
            dR = max(self.dRnum / (self.dRden - 4 * math.pi * Rsq) * w, 0.0)
            if dR > 0:
                self.dRavg += (dR - self.dRavg) / N_WINDOW
            if self.R + dR < 1.5 * self.Ro and dR > 0:
                self.R += self.dRavg
        self.Acon0 = self.Acon1


class Side:
    """the history of one side of the contact (the flat's view of one sphere)"""
    def __init__(self):
        self.delta = self.deltao = self.dmdr = self.dbulk = self.dmax_mdr = 0.0
        self.yflag, self.deltaY, self.cA, self.aadh, self.Ac, self.eps = 0, 0.0, 0.0, 0.0, 0.0, 0.0
        self.deltap = 0.0


def side_deltas(dtot, dmax, deltap, Ra, Rb):
    """the overlap of each side (a: the higher tag, b: the lower) from the
    total overlap dtot: the largest total overlap dmax splits where the two
    apparent spheres' caps meet (capped at 0.95 R), then each side moves
    linearly toward its plastic rest overlap deltap[side]"""
    out = []
    for s, (ri, rj) in enumerate(((Ra, Rb), (Rb, Ra))):
        den = 1 / (2 * (dmax - ri - rj))
        o1, o2 = dmax * (dmax - 2 * rj) * den, dmax * (dmax - 2 * ri) * den
        geo, alt = (max(o1, o2), min(o1, o2)) if ri < rj else (min(o1, o2), max(o1, o2))
        if geo / ri > OVERLAP_LIMIT:
            geo = ri * OVERLAP_LIMIT
        elif alt / rj > OVERLAP_LIMIT:
            geo = dmax - rj * OVERLAP_LIMIT
        dp = deltap[0] + deltap[1]
        out.append(geo + (deltap[s] - geo) * (dtot - dmax) / (dp - dmax))
    return out


def adhesive_force(m, de, A, B, a_na, aadh, at_max, h, amax):
    """cases 1-3 of the adhesive MDR force; updates h.aadh; returns (F, aAdh)"""
    Es, g = m.Es, m.gamma
    if aadh > A_FAC * amax:
        aadh = A_FAC * amax
    if at_max or a_na >= aadh:              # 1: compressive only
        F = f_flat(de, A, B, Es) if de > 0 else 0.0
        h.aadh = A_FAC * a_na
        return F, aadh

    def g_of(a):
        v = A / 2 - A / B * math.sqrt(B * B / 4 - a * a)
        return 0.0 if -EPS3 < v < 0 else v

    lmax = math.sqrt(2 * math.pi * aadh * g / Es)
    if de + lmax - g_of(aadh) >= 0:          # 2: the springs hold
        ga = g_of(aadh)
        return f_flat(ga, A, B, Es) + 2 * Es * (de - ga) * aadh, aadh
    # 3: the springs at their critical length: Newton-Raphson on aAdh
    A2, B2 = A * A, B * B
    t = 27 * A2 * A2 * B2 * B2 * g / Es - 2 * B ** 6 * g ** 3 * math.pi ** 2 / Es ** 3
    t += math.sqrt(27) * A2 * B2 * B2 * math.sqrt(
        27 * A2 * A2 * Es * Es * g * g - 4 * B2 * g ** 4 * math.pi ** 2) / Es ** 2
    t = t ** (1 / 3)
    acrit = (-B2 * g * math.pi / (A2 * Es) + 2 ** (1 / 3) * B2 * B2 * g * g * math.pi ** (5 / 3)
             / (A2 * Es * Es * t) + (math.pi / 2) ** (1 / 3) * t / A2) / 6
    F = 0.0
    if aadh < acrit:
        aadh = 0.0
    else:
        a = aadh
        for it in range(NR_MAX):
            base = de - A / 2 + A * csqrt(B2 / 4 - a * a) / B
            fa = base + csqrt(2 * math.pi * a * g / Es)
            if abs(fa) < NR_EPS1:
                break
            df = -a * A / (B * csqrt(B2 / 4 - a * a)) + g * csqrt(math.pi / 2) / \
                csqrt(a * g * Es)
            a -= fa / df
            if abs(fa - (base + csqrt(2 * math.pi * a * g / Es))) < NR_EPS2:
                break
            if it == NR_MAX - 1:
                a = 0.0
        aadh = a
        if aadh < acrit:
            aadh = 0.0
        else:
            ga = g_of(aadh)
            F = f_flat(ga, A, B, Es) + 2 * Es * (de - ga) * aadh
    h.aadh = aadh
    return F, aadh


def side_force(m, at, h, delta, w, update):
    """one side of a contact: the flat pushed delta into atom at, h the
    side's history, w the penalty weight; with update the history and the
    atom's sums advance. Returns (the side's force F_MDR + F_BULK, its
    damping contact radius)."""
    R, Ro = at.R, at.Ro
    dd = delta - h.delta
    deltao = delta - (R - Ro)
    ddo = deltao - h.deltao
    if update:
        h.delta, h.deltao = delta, deltao
    if at.psi < m.psi_b:
        dmdr, dbulk = min(dd - at.ddelta_bar, delta - h.dmdr), at.ddelta_bar
    else:
        dmdr, dbulk = dd, 0.0
    d_mdr = h.dmdr + dmdr
    d_bulk = max(0.0, h.dbulk + dbulk)
    if update:
        h.dmdr, h.dbulk = d_mdr, d_bulk
    if d_mdr > h.dmax_mdr:
        h.dmax_mdr = d_mdr
    dm = h.dmax_mdr
    pY = m.p_yield(dm, R)
    if h.yflag == 0 and d_mdr >= dm and update and m.p_hertz(d_mdr, R) > pY:
        h.yflag, h.deltaY = 1, d_mdr
        h.cA = math.pi * (d_mdr * d_mdr - d_mdr * R)
    if h.yflag == 0:
        A, B, de, amax = 4 * R, 2 * R, d_mdr, math.sqrt(dm * R)
    else:
        amax = math.sqrt(2 * dm * R - dm * dm + h.cA / math.pi)
        A, B = 4 * pY / m.Es * amax, 2 * amax
        demax = A / 2
        Fmax = m.Es * A * B / 4 * math.acos(0.0)
        zR = R - (dm - demax)
        rt = math.sqrt(amax * amax + zR * zR)
        dR = 2 * amax * amax * (m.nu - 1) - (2 * m.nu - 1) * zR * (-zR + rt)
        dR *= Fmax / (2 * math.pi * amax * amax * m.G * rt)
        de = (d_mdr - dm + demax + dR) / (1 + dR / demax)
        if update:
            h.deltap = dm - (demax + dR)
    a_na = B * math.sqrt(A - de) * math.sqrt(de) / A if de >= 0 else 0.0
    if m.gamma <= 0:
        F = f_flat(de, A, B, m.Es) if de > 0 else 0.0
        if update:
            h.aadh = a_na
        aadh = h.aadh
    else:
        saved = h.aadh
        F, aadh = adhesive_force(m, de, A, B, a_na, h.aadh, d_mdr == dm, h, amax)
        if not update:
            h.aadh = saved
    Ac = math.pi * delta * R if h.yflag == 0 else \
        math.pi * (2 * delta * R - delta * delta) + h.cA
    Ac = max(Ac, 0.0)
    Fb = 0.0 if d_bulk <= 0 else at.Acon0 * d_bulk * m.kappa * Ac / at.Vgeo
    eps = w * (F + Fb) * (-(Ro - deltao)) / (3 * m.kappa * at.Velas)
    if update:
        at.Atot_sum += w * (Ac - 2 * math.pi * R * (dm + d_bulk))
        at.Acon1 += w * Ac
        h.Ac = w * Ac
        at.Vcaps += math.pi / 3 * delta * delta * (3 * R - delta)
        at.eps_bar += eps
        if d_mdr == dm and h.yflag and F > 0:
            at.dRnum -= at.Vo * (eps - h.eps)
            at.dRnum -= w * math.pi * ddo * (2 * deltao * Ro - deltao ** 2 + R * R -
                                             Ro * Ro)
            at.dRden += w * 2 * math.pi * R * (deltao + R - Ro)
        h.eps = eps
    return F + Fb, (aadh if m.gamma > 0 else a_na)


class Contact:
    def __init__(self, m, a, b):
        """a, b: the two atoms; side 0 is the higher tag's"""
        self.m = m
        self.atoms = (a, b) if a.tag > b.tag else (b, a)
        self.sides = (Side(), Side())
        self.dmax = 0.0
        self.penalty = 0.0
        self.dscale = 0.0  # the damping scale of the last update (LAMMPS's DAMP_SCALE)

    def force(self, dtot, vnnr, meff, update=True):
        """the normal force (elastic + damping) at total overlap dtot and
        normal rate vnnr (< 0 approaching); with update the history and the
        atoms' sums advance (LAMMPS's history_update)"""
        m = self.m
        w = max(1.0 - self.penalty, 0.0)
        if dtot >= self.dmax:
            self.dmax = dtot
        A0, A1 = self.atoms
        ds = side_deltas(dtot, self.dmax, (self.sides[0].deltap, self.sides[1].deltap),
                         A0.R, A1.R)
        Fs, a_damp = [0.0, 0.0], 0.0
        for s in (0, 1):
            Fs[s], ad = side_force(m, self.atoms[s], self.sides[s], ds[s], w, update)
            a_damp += ad
        Fe = w * 0.5 * (Fs[0] + Fs[1])
        if update:  # without update (a run's setup) the damping reads the stored scale
            self.dscale = math.sqrt(meff * 2 * m.Es * a_damp) if a_damp > 0 else 0.0
        scale = self.dscale
        pref = m.eta * scale if m.dtype == 1 else (m.eta if scale != 0 else 0.0)
        return Fe - pref * vnnr, Fe

    def mean_surf_disp(self, dtot):
        """fix granular/mdr's mean surface displacement increment (after the
        radius update, before the force)"""
        A0, A1 = self.atoms
        dmax = max(self.dmax, dtot)
        ds = side_deltas(dtot, dmax, (self.sides[0].deltap, self.sides[1].deltap), A0.R, A1.R)
        for s in (0, 1):
            at, h = self.atoms[s], self.sides[s]
            if at.Acon0 != 0:
                at.ddelta_bar += h.Ac / at.Acon0 * (ds[s] - h.delta)


class WallContact:
    """a sphere against a flat wall (LAMMPS's fix wall/gran/region with the
    mdr model): one side only, the flat at the wall, the whole overlap the
    sphere's, no penalty. The side's force is magnified by exp(10.7 deltao /
    Ro - 10) + 1 (deltao the overlap from the initial sphere); damping mdr's
    scale is sqrt(meff E* a / 2), a the side's damping contact radius and
    meff the sphere's mass."""
    def __init__(self, m, atom):
        self.m, self.atom, self.side = m, atom, Side()
        self.dscale = 0.0

    def force(self, delta, vnnr, meff, update=True):
        """(total normal force, its elastic-plastic part) at overlap delta and
        normal rate vnnr (< 0 approaching the wall)"""
        m = self.m
        F0, ad = side_force(m, self.atom, self.side, delta, 1.0, update)
        Fe = F0 * (math.exp(10.7 * self.side.deltao / self.atom.Ro - 10) + 1)
        if update:
            self.dscale = math.sqrt(meff * m.Es * ad / 2) if ad > 0 else 0.0
        pref = m.eta * self.dscale if m.dtype == 1 else (m.eta if self.dscale != 0 else 0.0)
        return Fe - pref * vnnr, Fe

    def mean_surf_disp(self, delta):
        """the wall contact's share of the sphere's mean surface displacement"""
        at, h = self.atom, self.side
        if at.Acon0 != 0:
            at.ddelta_bar += h.Ac / at.Acon0 * (delta - h.delta)


def drive(m, Ra, Rb, gaps, meff, dt, bookkeeping=True):
    """Two spheres (tags 1: radius Ra, 2: Rb) whose centre distance follows
    gaps[n] (n = 0 the setup): each step runs fix granular/mdr's pre_force,
    then the force. Returns [(total overlap, elastic force, radius a, radius
    b)] per step. bookkeeping False leaves the radii as they are (the law
    alone)."""
    a, b = Atom(1, Ra), Atom(2, Rb)
    c = Contact(m, a, b)
    out = []
    for n, r in enumerate(gaps):
        if n > 0:
            for at in (a, b):
                at.update(m.psi_b, bookkeeping)
                at.ddelta_bar = 0.0
                at.zero_sums()
        dtot = a.R + b.R - r
        if n > 0 and dtot > 0:
            c.mean_surf_disp(dtot)
        if dtot > 0:
            vn = (r - gaps[n - 1]) / dt if n > 0 else 0.0
            _, Fe = c.force(dtot, vn, meff, update=n > 0)
        else:
            c = Contact(m, a, b)
            Fe = 0.0
        out.append((dtot, Fe, a.R, b.R))
    return out


def collide(m, R, rho, v0, dt):
    """A free head-on collision of two equal spheres of radius R, density
    rho, approaching at v0 each (velocity Verlet, LAMMPS's order); returns
    (restitution, damping work, elastic-plastic work, kinetic energy loss)."""
    mass = rho * 4 / 3 * math.pi * R ** 3
    meff = mass / 2
    a, b = Atom(1, R), Atom(2, R)
    c = Contact(m, a, b)
    x, v, f, fe = 2 * R, -2 * v0, 0.0, 0.0  # centre distance, its rate, forces on the pair
    wd = we = 0.0                          # the work of the damping and elastic-plastic forces
    ke0 = 0.5 * meff * v * v
    for _ in range(10 ** 7):
        v += 0.5 * dt * f / meff
        xo = x
        x += dt * v
        for at in (a, b):
            at.update(m.psi_b)
            at.ddelta_bar = 0.0
            at.zero_sums()
        dtot = a.R + b.R - x
        fo, feo = f, fe
        if dtot > 0:
            c.mean_surf_disp(dtot)
            f, fe = c.force(dtot, v, meff)
        else:
            f = fe = 0.0
        wd += 0.5 * ((f - fe) + (fo - feo)) * (x - xo)   # trapezoids
        we += 0.5 * (fe + feo) * (x - xo)
        if dtot <= 0:
            if v > 0 and xo > 0 and c.dmax > 0:
                break
            c = Contact(m, a, b)
        v += 0.5 * dt * f / meff
    return abs(v) / (2 * v0), wd, we, ke0 - 0.5 * meff * v * v
