/* gran_mdr.c - the mdr contact model's physics (gran_mdr.h): LAMMPS's
 * GranSubModNormalMDR::calculate_forces for a pair contact and fix
 * granular/mdr's per-atom update, in LAMMPS's order of operations (so that
 * the sums round as LAMMPS's do). Units are the script's. */
#include "gran_mdr.h"

#include <math.h>

#include "param_layout.h"

#define MDR_OVERLAP_LIMIT 0.95
#define MDR_MAX_IT 100
#define MDR_EPS1 1e-10  /* Newton-Raphson: |f(a)| small enough */
#define MDR_EPS2 1e-16  /* Newton-Raphson: f stopped changing */
#define MDR_EPS3 1e-20  /* g(a) in (-EPS3, 0) is 0 (rounding) */
#define A_FAC 0.99      /* the adhesive contact radius stays below 0.99 a_max */
#define N_WINDOW 10.0   /* the running mean of the radius increments */

#define PI_ M_PI
#define PIINV 0.318309886183790671538
#define PISQ 9.86960440108935861883
#define CBRT2 1.25992104989487316476
#define PITOFIVETHIRDS 6.73880859551872223106 /* pi^(5/3) */
#define CBRTHALFPI 1.16244735150962652526      /* (pi/2)^(1/3) */
#define SQRTHALFPI 1.25331413731550025121      /* sqrt(pi/2) */
#define THIRD (1.0 / 3.0)
#define FOURTHIRDS (4.0 / 3.0)

static double sq(double x) { return x * x; }
static double cube(double x) { return x * x * x; }

void mdr_mat_set(struct mdr_mat *m, double E, double nu, double Y, double gamma, double psi_b)
{
    m->E = E;
    m->nu = nu;
    m->Y = Y;
    m->gamma = gamma;
    m->psi_b = psi_b;
    m->G = E / (2.0 * (1.0 + nu));
    m->kappa = E / (3.0 * (1.0 - 2.0 * nu));
    m->Eeff = E / (1.0 - sq(nu));
}

void mdr_atom_init(struct mdr_atom *a, double R)
{
    a->Ro = R;
    a->Acon0 = a->Acon1 = 0.0;
    a->Vcaps = a->eps_bar = 0.0;
    a->dRnum = a->dRden = 0.0;
    a->Atot_sum = 0.0;
    a->ddelta_bar = 0.0;
    a->sigma[0] = a->sigma[1] = a->sigma[2] = 0.0;
    a->ready = 1;
}

void mdr_atom_update(const struct mdr_mat *m, struct mdr_atom *a, double *Rp)
{
    const double R = *Rp, Rsq = R * R;
    const double Vo = 4.0 / 3.0 * PI_ * cube(a->Ro);
    const double Vgeoi = 4.0 / 3.0 * PI_ * Rsq * R - a->Vcaps;
    a->Vgeo = fmin(Vgeoi, Vo);
    a->Velas = Vo * (1.0 + a->eps_bar);
    a->Atot = 4.0 * PI_ * Rsq + a->Atot_sum;
    a->psi = (a->Atot - a->Acon1) / a->Atot;
    if (m->psi_b < a->psi) {
        /* the confinement weight: growth fades out as the free surface closes */
        const double w = a->psi > 0.1 ? 1.0 / (1.0 + exp(-75.0 * (a->psi - 0.2))) : 0.0;
        const double dR = fmax(a->dRnum / (a->dRden - 4.0 * PI_ * Rsq) * w, 0.0);
        if (dR > 0.0)
            a->dRavg += (dR - a->dRavg) / N_WINDOW;
        if (R + dR < 1.5 * a->Ro && dR > 0.0)
            *Rp = R + a->dRavg;
    }
    a->Acon0 = a->Acon1;
}

void mdr_atom_zero_sums(struct mdr_atom *a)
{
    a->Vcaps = a->eps_bar = 0.0;
    a->dRnum = a->dRden = 0.0;
    a->Acon1 = a->Atot_sum = 0.0;
    a->sigma[0] = a->sigma[1] = a->sigma[2] = 0.0;
}

void mdr_side_deltas(double dmax, double dp0, double dp1, double delta, double R0, double R1,
                     int force_form, double out[2])
{
    const double dp = dp0 + dp1;
    if (force_form) { /* calculate_forces: each side with its own radii */
        for (int s = 0; s < 2; s++) {
            const double ri = s ? R1 : R0, rj = s ? R0 : R1;
            const double denom = 1.0 / (2.0 * (dmax - ri - rj));
            const double o1 = dmax * (dmax - 2.0 * rj) * denom;
            const double o2 = dmax * (dmax - 2.0 * ri) * denom;
            double geo = ri < rj ? fmax(o1, o2) : fmin(o1, o2);
            const double alt = ri < rj ? fmin(o1, o2) : fmax(o1, o2);
            if (geo / ri > MDR_OVERLAP_LIMIT)
                geo = ri * MDR_OVERLAP_LIMIT;
            else if (alt / rj > MDR_OVERLAP_LIMIT)
                geo = dmax - rj * MDR_OVERLAP_LIMIT;
            out[s] = geo + ((s ? dp1 : dp0) - geo) * (delta - dmax) / (dp - dmax);
        }
        return;
    }
    /* mean_surf_disp */
    const double o1 = dmax * (dmax - 2.0 * R1) / (2.0 * (dmax - R0 - R1));
    const double o2 = dmax * (dmax - 2.0 * R0) / (2.0 * (dmax - R0 - R1));
    double g0 = R0 < R1 ? fmax(o1, o2) : fmin(o1, o2);
    double g1 = R0 < R1 ? fmin(o1, o2) : fmax(o1, o2);
    if (g0 / R0 > MDR_OVERLAP_LIMIT) {
        g0 = R0 * MDR_OVERLAP_LIMIT;
        g1 = dmax - g0;
    } else if (g1 / R1 > MDR_OVERLAP_LIMIT) {
        g1 = R1 * MDR_OVERLAP_LIMIT;
        g0 = dmax - g1;
    }
    out[0] = g0 + (dp0 - g0) / (dp - dmax) * (delta - dmax);
    out[1] = g1 + (dp1 - g1) / (dp - dmax) * (delta - dmax);
}

/* The force of an elliptical indenter of height A and width B pushed de
 * into an elastic half space (MDR, Part I): E* A B / 4 (acos(1 - 2x) -
 * (2 - 4x) sqrt(x - x^2)), x = de / A. */
static double f_na(double de, double Ainv, double Eeff, double A, double B)
{
    double F = acos(1.0 - 2.0 * de * Ainv);
    F -= (2 - 4 * de * Ainv) * sqrt(de * Ainv - sq(de * Ainv));
    return F * (0.25 * Eeff * A * B);
}

static double round_neg_eps(double v) { return v < 0.0 && v > -MDR_EPS3 ? 0.0 : v; }

/* The adhesive force of one side (gamma > 0): case 1 compressive only,
 * case 2 the tensile springs hold, case 3 they are at their critical
 * length (aAdh by Newton-Raphson, 0 below the critical radius). *aAdh is
 * the side's adhesive radius (capped), *hA its history slot. */
static double adhesive(const struct mdr_mat *m, double de, double A, double Ainv, double B,
                       double a_na, int at_max, double *aAdh, double *hA, int update)
{
    const double Eeff = m->Eeff, Eeffinv = 1.0 / Eeff, gamma = m->gamma;
    if (at_max || a_na >= *aAdh) {
        if (update)
            *hA = A_FAC * a_na;
        return de <= 0.0 ? 0.0 : f_na(de, Ainv, Eeff, A, B);
    }
    const double Ainvsq = Ainv * Ainv, Asq = A * A, A4 = Asq * Asq;
    const double Binv = 1.0 / B, Bsq = B * B, B4 = Bsq * Bsq;
    const double gammasq = gamma * gamma, gamma3 = gammasq * gamma, gamma4 = gammasq * gammasq;
    const double Eeffsq = Eeff * Eeff, Eeffsqinv = Eeffinv * Eeffinv;
    const double lmax = sqrt(2.0 * PI_ * *aAdh * gamma * Eeffinv);
    double g_a = round_neg_eps(A * 0.5 - A * Binv * sqrt(Bsq * 0.25 - sq(*aAdh)));
    double tmp = 27 * A4 * B4 * gamma * Eeffinv;
    tmp -= 2 * (Bsq * B4) * gamma3 * PISQ * cube(Eeffinv);
    tmp += sqrt(27) * Asq * B4 * sqrt(27 * A4 * Eeffsq * gammasq - 4 * Bsq * gamma4 * PISQ) *
           Eeffsqinv;
    tmp = cbrt(tmp);
    double acrit = -Bsq * gamma * PI_ * Ainvsq * Eeffinv;
    acrit += CBRT2 * B4 * gammasq * PITOFIVETHIRDS / (Asq * Eeffsq * tmp);
    acrit += CBRTHALFPI * tmp * Ainvsq;
    acrit /= 6;
    if (de + lmax - g_a >= 0.0) /* case 2 */
        return f_na(g_a, Ainv, Eeff, A, B) + 2.0 * Eeff * (de - g_a) * *aAdh;
    double F = 0.0; /* case 3 */
    if (*aAdh < acrit) {
        *aAdh = 0.0;
    } else {
        double a = *aAdh;
        for (int it = 0; it < MDR_MAX_IT; ++it) {
            const double fa_tmp = de - A * 0.5 + A * sqrt(Bsq * 0.25 - sq(a)) * Binv;
            const double fa = fa_tmp + sqrt(2.0 * PI_ * a * gamma * Eeffinv);
            if (fabs(fa) < MDR_EPS1)
                break;
            double dfda = -a * A / (B * sqrt(-sq(a) + Bsq * 0.25));
            dfda += gamma * SQRTHALFPI / sqrt(a * gamma * Eeff);
            a = a - fa / dfda;
            const double fa2 = fa_tmp + sqrt(2.0 * PI_ * a * gamma * Eeffinv);
            if (fabs(fa - fa2) < MDR_EPS2)
                break;
            if (it == MDR_MAX_IT - 1)
                a = 0.0;
        }
        *aAdh = a;
        if (*aAdh < acrit) {
            *aAdh = 0.0;
        } else {
            g_a = round_neg_eps(A * 0.5 - A * Binv * sqrt(Bsq * 0.25 - sq(*aAdh)));
            F = f_na(g_a, Ainv, Eeff, A, B) + 2.0 * Eeff * (de - g_a) * *aAdh;
        }
    }
    if (update)
        *hA = *aAdh;
    return F;
}

/* One side of a contact (LAMMPS's loop body over contactSide): the side's
 * overlap dl of atom at (apparent radius R), its history slots s of h.
 * Gathers the atom's sums with update; returns the side's force (F_MDR +
 * F_BULK, no weight), adds its weighted area to *Acsum and its damping
 * radius to *a_damp. */
static double mdr_side_force(const struct mdr_mat *m, double *h, int s, double dl,
                             struct mdr_atom *at, double R, const double n[3], double wij,
                             double dmax_before, int update, int *yield_new, double *Acsum,
                             double *a_damp)
{
    const double Eeff = m->Eeff, Eeffinv = 1.0 / Eeff;
    const double Ro = at->Ro;
    const double ddelta = dl - h[MH_DELTA_0 + s];
    if (update)
        h[MH_DELTA_0 + s] = dl;
    const double deltao = dl - (R - Ro);
    const double ddeltao = deltao - h[MH_DELTAO_0 + s];
    if (update)
        h[MH_DELTAO_0 + s] = deltao;
    double dd_mdr, dd_bulk;
    if (at->psi < m->psi_b) { /* the bulk response takes the mean surface motion */
        dd_mdr = fmin(ddelta - at->ddelta_bar, dl - h[MH_DELTA_MDR_0 + s]);
        dd_bulk = at->ddelta_bar;
    } else {
        dd_bulk = 0.0;
        dd_mdr = ddelta;
    }
    const double d_mdr = h[MH_DELTA_MDR_0 + s] + dd_mdr;
    if (update)
        h[MH_DELTA_MDR_0 + s] = d_mdr;
    const double d_bulk = fmax(0.0, h[MH_DELTA_BULK_0 + s] + dd_bulk);
    if (update)
        h[MH_DELTA_BULK_0 + s] = d_bulk;
    if (d_mdr > h[MH_DELTAMAX_MDR_0 + s])
        h[MH_DELTAMAX_MDR_0 + s] = d_mdr;
    const double dm = h[MH_DELTAMAX_MDR_0 + s];
    const double pY = m->Y * (1.75 * exp(-4.4 * dm / R) + 1.0); /* mean yield pressure */
    if (h[MH_YFLAG_0 + s] == 0.0 && d_mdr >= dm) {
        const double phertz = 4 * Eeff * sqrt(d_mdr) / (3 * PI_ * sqrt(R));
        if (!update && dmax_before == 0.0 && phertz > pY)
            *yield_new = 1;
        if (update && phertz > pY) {
            h[MH_YFLAG_0 + s] = 1.0;
            h[MH_DELTAY_0 + s] = d_mdr;
            h[MH_CA_0 + s] = PI_ * (sq(d_mdr) - d_mdr * R);
        }
    }
    const double cA = h[MH_CA_0 + s];
    double A, Ainv, B, de, amax;
    if (h[MH_YFLAG_0 + s] == 0.0) { /* elastic: the sphere itself */
        A = 4.0 * R;
        Ainv = 1.0 / A;
        B = 2.0 * R;
        de = d_mdr;
        amax = sqrt(dm * R);
    } else { /* plastic: the elliptical indenter of the yielded cap */
        amax = sqrt(2.0 * dm * R - sq(dm) + cA * PIINV);
        const double amaxsq = amax * amax;
        A = 4.0 * pY * Eeffinv * amax;
        Ainv = 1.0 / A;
        B = 2.0 * amax;
        const double demax = A * 0.5;
        double Fmax = Eeff * (A * B * 0.25) * acos(1 - 2 * demax * Ainv);
        Fmax -= (2 - 4 * demax * Ainv) * sqrt(demax * Ainv - sq(demax * Ainv));
        const double zR = R - (dm - demax); /* depth of the particle centre */
        double dR = 2 * amaxsq * (-1 + m->nu) -
                    (-1 + 2 * m->nu) * zR * (-zR + sqrt(amaxsq + sq(zR)));
        dR *= Fmax / (2.0 * PI_ * amaxsq * m->G * sqrt(amaxsq + sq(zR)));
        de = (d_mdr - dm + demax + dR) / (1 + dR / demax);
        if (update)
            h[MH_DELTAP_0 + s] = dm - (demax + dR);
    }
    const double a_na = de >= 0.0 ? B * sqrt(A - de) * sqrt(de) * Ainv : 0.0;
    double aAdh = h[MH_AADH_0 + s];
    if (aAdh > A_FAC * amax)
        aAdh = A_FAC * amax;
    double F_mdr;
    if (m->gamma <= 0.0) {
        F_mdr = de <= 0.0 ? 0.0 : f_na(de, Ainv, Eeff, A, B);
        if (update)
            h[MH_AADH_0 + s] = a_na;
    } else {
        F_mdr = adhesive(m, de, A, Ainv, B, a_na, d_mdr == dm, &aAdh, &h[MH_AADH_0 + s], update);
    }
    double Ac = h[MH_YFLAG_0 + s] == 0.0 ? PI_ * dl * R : PI_ * (2.0 * dl * R - sq(dl)) + cA;
    if (Ac < 0.0)
        Ac = 0.0;
    if (update) {
        at->Atot_sum += wij * (Ac - 2.0 * PI_ * R * (dm + d_bulk));
        at->Acon1 += wij * Ac;
    }
    *Acsum += wij * Ac;
    *a_damp += m->gamma > 0.0 ? aAdh : a_na;
    const double F_bulk = d_bulk <= 0.0 ? 0.0
                                        : (1.0 / at->Vgeo) * at->Acon0 * d_bulk * m->kappa * Ac;
    if (update) {
        h[MH_AC_0 + s] = wij * Ac;
        at->Vcaps += PI_ * THIRD * sq(dl) * (3.0 * R - dl);
    }
    /* the contact's share of the atom's mean strain: f . b / (3 kappa V) */
    const double Fn = wij * (F_mdr + F_bulk);
    const double fx = Fn * n[0], fy = Fn * n[1], fz = Fn * n[2];
    const double bx = -(Ro - deltao) * n[0], by = -(Ro - deltao) * n[1],
                 bz = -(Ro - deltao) * n[2];
    const double eps_c = (fx * bx + fy * by + fz * bz) / (3 * m->kappa * at->Velas);
    if (update)
        at->eps_bar += eps_c;
    if (update && d_mdr == dm && h[MH_YFLAG_0 + s] > 0.0 && F_mdr > 0.0) {
        const double Vo = FOURTHIRDS * PI_ * cube(Ro);
        at->dRnum -= Vo * (eps_c - h[MH_EPS_BAR_0 + s]);
        at->dRnum -= wij * PI_ * ddeltao * (2 * deltao * Ro - sq(deltao) + sq(R) - sq(Ro));
        at->dRden += wij * 2.0 * PI_ * R * (deltao + R - Ro);
    }
    if (update) {
        h[MH_EPS_BAR_0 + s] = eps_c;
        at->sigma[0] += fx * bx / at->Velas;
        at->sigma[1] += fy * by / at->Velas;
        at->sigma[2] += fz * bz / at->Velas;
    }
    return F_mdr + F_bulk;
}

double mdr_pair_force(const struct mdr_mat *m, double *h, double delta, struct mdr_atom *a[2],
                      const double R2[2], const double n[3], double meff, int update,
                      int *yield_new)
{
    const double Eeff = m->Eeff;
    const double dmax_before = h[MH_DELTA_MAX];
    /* deltamax follows the overlap even in setup (LAMMPS: an atom created
     * with an overlap) */
    if (delta >= h[MH_DELTA_MAX])
        h[MH_DELTA_MAX] = delta;
    const double dmax = h[MH_DELTA_MAX];
    double ds[2];
    mdr_side_deltas(dmax, h[MH_DELTAP_0], h[MH_DELTAP_1], delta, R2[0], R2[1], 1, ds);
    const double wij = fmax(1.0 - h[MH_PENALTY], 0.0);
    double Fs[2], Acsum = 0.0, a_damp = 0.0;
    for (int s = 0; s < 2; s++)
        Fs[s] = mdr_side_force(m, h, s, ds[s], a[s], R2[s], n, wij, dmax_before, update,
                               yield_new, &Acsum, &a_damp);
    const double damp_scale = sqrt(meff * 2.0 * Eeff * a_damp);
    const double F = wij * (Fs[0] + Fs[1]) * 0.5;
    if (update)
        h[MH_DAMP_SCALE] = a_damp <= 0.0 ? 0.0 : damp_scale;
    h[MH_FN] = F;
    h[MH_AC_AVG] = Acsum * 0.5;
    return F;
}

double mdr_wall_force(const struct mdr_mat *m, double *h, double delta, struct mdr_atom *a,
                      double R, const double n[3], double meff, int update, int *yield_new)
{
    const double dmax_before = h[MH_DELTA_MAX];
    if (delta >= h[MH_DELTA_MAX])
        h[MH_DELTA_MAX] = delta;
    const double wij = fmax(1.0 - h[MH_PENALTY], 0.0); /* no penalty on a wall: 1 */
    double Acsum = 0.0, a_damp = 0.0;
    const double F0 = mdr_side_force(m, h, 0, delta, a, R, n, wij, dmax_before, update,
                                     yield_new, &Acsum, &a_damp);
    a_damp = a_damp / 2.0;
    const double damp_scale = sqrt(meff * 2.0 * (0.5 * m->Eeff) * a_damp);
    /* the wall force magnifier of the side's (stored) overlap from the initial sphere */
    const double wfm = exp(10.7 * h[MH_DELTAO_0] / a->Ro - 10.0) + 1.0;
    const double F = wij * F0 * wfm;
    if (update)
        h[MH_DAMP_SCALE] = a_damp <= 0.0 ? 0.0 : damp_scale;
    h[MH_FN] = F;
    h[MH_AC_AVG] = Acsum * 0.5;
    return F;
}

double mdr_penalty(double alpha) { return 1.0 / (1.0 + exp(-50.0 * (alpha / PI_ - 0.5))); }
