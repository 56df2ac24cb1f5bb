/* contact_ref.h - independent reference solutions of the LAMMPS granular contact
 * laws (pair gran/hooke, gran/hooke/history, gran/hertz/history and the same
 * models in fix wall/gran against a flat z wall), for the contact tests.
 *
 * The reference integrates the continuous-time equations of motion of one or
 * two spheres (position, velocity, spin, and for the history models the
 * tangential spring displacement s) with GSL's rk8pd at a relative and absolute
 * tolerance of 1e-12, and with closed forms where they exist (damped linear
 * spring head-on: contact time pi/wd and restitution exp(-gamman pi / (2 wd));
 * undamped Hertz head-on: contact time from the Beta function). It shares no
 * code with the engine: the force law is re-derived here from the LAMMPS
 * documentation (pair_gran, fix wall/gran):
 *
 *   del = x_i - x_j, r = |del|, n = del/r, overlap d = radsum - r > 0
 *   vr = v_i - v_j, vn = (vr.n) n, vt = vr - vn
 *   vtr = vt + n x (rad_i w_i + rad_j w_j)            relative surface velocity
 *   Fn  = P (kn d - meff gamman (vr.n))  n            P = 1 (Hooke) or sqrt(d reff) (Hertz)
 *   hooke:     Ft = -min(mu |Fn|, meff gammat |vtr|) vtr/|vtr|
 *   history:   Ft = -P (kt s + meff gammat vtr),  ds/dt = vtr - n (s . dn/dt),
 *              dn/dt = vt / r for two spheres, 0 for a flat wall (the
 *              continuous limit of LAMMPS' "add vtr dt, then project s onto
 *              the tangent plane")
 *   F_i = Fn + Ft = -F_j,  T_i = -rad_i n x Ft,  T_j = -rad_j n x Ft
 *   sphere: I = 0.4 m rad^2
 *
 * Sliding with history: for gammat = 0 (dampflag 0) the Coulomb limit is
 * |s| <= S = mu |kn d - meff gamman vn| / kt (the Hertz factor P cancels), and
 * the continuous limit of LAMMPS' rescaling keeps |s| = S while the free
 * evolution pushes outwards: ds/dt = f - s^ (s^.f - dS/dt), f the free rate.
 * With gammat > 0 the reference covers sticking contacts only: cref_solve()
 * reports the largest |Ft| / (mu |Fn|) so a test can assert that premise.
 * The wall is the plane z = wall_z (particle above it), moving with velocity
 * wall_v (fix wall/gran shear); it is body j with rad_j = 0, w_j = 0, meff = m_i,
 * reff = rad_i. */
#ifndef CONTACT_REF_H
#define CONTACT_REF_H

#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_gamma.h>

enum cref_model { CREF_HOOKE, CREF_HOOKE_HISTORY, CREF_HERTZ_HISTORY };

struct cref_body {
    double x[3], v[3], w[3];
    double rad, m;
};

struct cref_system {
    enum cref_model model;
    double kn, kt, gamman, gammat, xmu;  /* as LAMMPS after NULL/dampflag handling */
    int nbody;                           /* 2: sphere-sphere; 1: sphere-wall */
    struct cref_body b[2];
    double wall_z, wall_v[3];            /* nbody == 1: the plane z = wall_z */
    double grav[3];                      /* acceleration on every body */
    double s[3];                         /* tangential displacement (history models) */
    double max_slip_ratio;               /* largest |Ft| / (mu |Fn|) seen (history) */
    int ncontact_steps;                  /* RHS calls in contact (sanity) */
    int slip;                            /* history, gammat = 0: sliding mode */
    double phi, psi;                     /* |s| - S and the outward push minus dS/dt */
};

/* Contact between a (index i) and b (j, or the wall). Adds force/torque to
 * the outputs, and writes ds/dt. Returns 1 when in contact. */
static int cref_contact(struct cref_system *sy, const double *y, double fi[3], double ti[3],
                        double tj[3], double dsdt[3])
{
    const double *xi = y, *vi = y + 3, *wi = y + 6;
    double xj[3], vj[3], wj[3] = {0, 0, 0};
    double radi = sy->b[0].rad, radj, meff, reff;
    if (sy->nbody == 2) {
        for (int k = 0; k < 3; k++) {
            xj[k] = y[9 + k];
            vj[k] = y[12 + k];
            wj[k] = y[15 + k];
        }
        radj = sy->b[1].rad;
        meff = sy->b[0].m * sy->b[1].m / (sy->b[0].m + sy->b[1].m);
        reff = radi * radj / (radi + radj);
    } else {
        xj[0] = xi[0];
        xj[1] = xi[1];
        xj[2] = sy->wall_z;
        for (int k = 0; k < 3; k++) vj[k] = sy->wall_v[k];
        radj = 0.0;
        meff = sy->b[0].m;
        reff = radi;
    }
    double del[3], vr[3], n[3];
    for (int k = 0; k < 3; k++) {
        del[k] = xi[k] - xj[k];
        vr[k] = vi[k] - vj[k];
    }
    double r = sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
    double radsum = radi + radj;
    dsdt[0] = dsdt[1] = dsdt[2] = 0.0;
    if (r >= radsum) return 0;
    for (int k = 0; k < 3; k++) n[k] = del[k] / r;
    double d = radsum - r;
    double vnn = vr[0] * n[0] + vr[1] * n[1] + vr[2] * n[2];
    double vt[3], rw[3], vtr[3];
    for (int k = 0; k < 3; k++) {
        vt[k] = vr[k] - vnn * n[k];
        rw[k] = radi * wi[k] + radj * wj[k];
    }
    vtr[0] = vt[0] + (n[1] * rw[2] - n[2] * rw[1]);
    vtr[1] = vt[1] + (n[2] * rw[0] - n[0] * rw[2]);
    vtr[2] = vt[2] + (n[0] * rw[1] - n[1] * rw[0]);
    double P = sy->model == CREF_HERTZ_HISTORY ? sqrt(d * reff) : 1.0;
    double g = sy->kn * d - meff * sy->gamman * vnn;     /* normal force / P */
    double fnmag = P * g;                                /* signed, along n */
    double fn_lim = sy->xmu * fabs(fnmag);
    double ft[3], se[3] = {0, 0, 0}, smag = 0.0, smag0 = 0.0, S = 0.0;
    if (sy->model == CREF_HOOKE) {
        double vrel = sqrt(vtr[0] * vtr[0] + vtr[1] * vtr[1] + vtr[2] * vtr[2]);
        double fs = meff * sy->gammat * vrel;
        double f = vrel != 0.0 ? fmin(fn_lim, fs) / vrel : 0.0;
        for (int k = 0; k < 3; k++) ft[k] = -f * vtr[k];
    } else {
        const double *s = y + 9 * sy->nbody; /* s follows the bodies */
        smag = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
        /* gammat = 0: the Coulomb limit is |s| <= S; clip drift beyond it */
        S = sy->kt > 0.0 ? sy->xmu * fabs(g) / sy->kt : 0.0;
        double scale = (sy->gammat == 0.0 && smag > S) ? S / smag : 1.0;
        for (int k = 0; k < 3; k++) {
            se[k] = s[k] * scale;
            ft[k] = -P * (sy->kt * se[k] + meff * sy->gammat * vtr[k]);
        }
        smag0 = smag;
        smag *= scale;
        double ftm = sqrt(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2]);
        if (fn_lim > 0 && ftm / fn_lim > sy->max_slip_ratio) sy->max_slip_ratio = ftm / fn_lim;
    }
    if (sy->model != CREF_HOOKE) {
        /* ds/dt: free evolution keeps s in the tangent plane as n turns;
         * sliding (gammat = 0, |s| at S and pushing outwards) keeps |s| = S. */
        /* s . dn/dt; dn/dt = vt/r for two spheres, 0 for the flat wall (its
         * contact point slides with the sphere, n stays the wall normal) */
        double sdn = sy->nbody == 2 ? (se[0] * vt[0] + se[1] * vt[1] + se[2] * vt[2]) / r : 0.0;
        double fr[3];
        for (int k = 0; k < 3; k++) fr[k] = vtr[k] - n[k] * sdn;
        for (int k = 0; k < 3; k++) dsdt[k] = fr[k];
        sy->phi = smag0 - S;
        sy->psi = 1.0;
        if (sy->gammat == 0.0 && smag > 0.0) {
            double F[3], ar[3], vt2 = 0.0, an = 0.0;
            for (int k = 0; k < 3; k++) {
                F[k] = fnmag * n[k] + ft[k];
                ar[k] = sy->nbody == 2 ? F[k] / sy->b[0].m + F[k] / sy->b[1].m : F[k] / sy->b[0].m;
                vt2 += vt[k] * vt[k];
            }
            if (sy->nbody == 1) ar[2] += sy->grav[2], ar[0] += sy->grav[0], ar[1] += sy->grav[1];
            for (int k = 0; k < 3; k++) an += ar[k] * n[k];
            double vnndot = an + (sy->nbody == 2 ? vt2 / r : 0.0);
            double gdot = -sy->kn * vnn - meff * sy->gamman * vnndot;
            double Sdot = sy->xmu * (g >= 0.0 ? gdot : -gdot) / sy->kt;
            double out = (se[0] * fr[0] + se[1] * fr[1] + se[2] * fr[2]) / smag;
            sy->psi = out - Sdot;
            /* sliding (mode set by cref_solve at the located switch): |s|/S
             * stays constant (1), the direction turns with the free rate */
            if (sy->slip && S > 0.0)
                for (int k = 0; k < 3; k++)
                    dsdt[k] = fr[k] - out * se[k] / smag + Sdot / S * y[9 * sy->nbody + k];
        }
    }
    for (int k = 0; k < 3; k++) fi[k] += fnmag * n[k] + ft[k];
    double tor[3] = {n[1] * ft[2] - n[2] * ft[1], n[2] * ft[0] - n[0] * ft[2],
                     n[0] * ft[1] - n[1] * ft[0]};
    for (int k = 0; k < 3; k++) {
        ti[k] -= radi * tor[k];
        tj[k] -= radj * tor[k];
    }
    sy->ncontact_steps++;
    return 1;
}

/* y layout: per body x v w (9 doubles), then s (3). */
static int cref_rhs(double t, const double *y, double *dy, void *par)
{
    (void)t;
    struct cref_system *sy = par;
    double fi[3] = {0, 0, 0}, ti[3] = {0, 0, 0}, tj[3] = {0, 0, 0}, ds[3];
    cref_contact(sy, y, fi, ti, tj, ds);
    for (int b = 0; b < sy->nbody; b++) {
        const double *yb = y + 9 * b;
        double *db = dy + 9 * b;
        double m = sy->b[b].m, inertia = 0.4 * m * sy->b[b].rad * sy->b[b].rad;
        for (int k = 0; k < 3; k++) {
            double f = b == 0 ? fi[k] : -fi[k];
            double tq = b == 0 ? ti[k] : tj[k];
            db[k] = yb[3 + k];
            db[3 + k] = f / m + sy->grav[k];
            db[6 + k] = tq / inertia;
        }
    }
    for (int k = 0; k < 3; k++) dy[9 * sy->nbody + k] = ds[k];
    return GSL_SUCCESS;
}

/* 1 when the state y calls for a switch of the sliding mode: sticking and
 * |s| > S, or sliding and the free evolution no longer pushes outwards. */
static int cref_switch_due(struct cref_system *sy, const double *y)
{
    if (sy->model == CREF_HOOKE || sy->gammat != 0.0)
        return 0;
    double f[3] = {0, 0, 0}, a[3] = {0, 0, 0}, c[3] = {0, 0, 0}, ds[3];
    if (!cref_contact(sy, y, f, a, c, ds))
        return 0;
    return sy->slip ? sy->psi <= 0.0 : sy->phi > 0.0;
}

/* Advance the system by time t with adaptive rk8pd steps. Stick/slip
 * switches are located by bisection to ~1e-15 of the step and the mode is
 * changed there (entering the slide, s is put exactly on |s| = S), so the
 * integrator never steps across a discontinuity of ds/dt. s is cleared
 * whenever the bodies are apart, as LAMMPS does when a contact ends.
 * `piece` bounds the step. Returns 0 on success. */
static int cref_solve(struct cref_system *sy, double t, double piece)
{
    double y[21], y0[21], yt[21], yerr[21];
    int n = 9 * sy->nbody + 3;
    for (int b = 0; b < sy->nbody; b++)
        for (int k = 0; k < 3; k++) {
            y[9 * b + k] = sy->b[b].x[k];
            y[9 * b + 3 + k] = sy->b[b].v[k];
            y[9 * b + 6 + k] = sy->b[b].w[k];
        }
    for (int k = 0; k < 3; k++) y[9 * sy->nbody + k] = sy->s[k];
    gsl_odeiv2_system sys = {cref_rhs, NULL, (size_t)n, sy};
    gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, (size_t)n);
    gsl_odeiv2_control *ctl = gsl_odeiv2_control_standard_new(1e-12, 1e-12, 1.0, 0.0);
    gsl_odeiv2_evolve *ev = gsl_odeiv2_evolve_alloc((size_t)n);
    double tt = 0.0, h = 1e-7;
    int rc = 0;
    while (tt < t && rc == 0) {
        double t0 = tt;
        memcpy(y0, y, sizeof(double) * (size_t)n);
        rc = gsl_odeiv2_evolve_apply(ev, ctl, st, &sys, &tt, fmin(t, t0 + piece), &h, y);
        if (rc)
            break;
        if (cref_switch_due(sy, y)) {
            double lo = 0.0, hi = tt - t0;
            memcpy(yt, y, sizeof(double) * (size_t)n);
            for (int it = 0; it < 60 && hi - lo > 1e-15 * (t0 + 1.0); it++) {
                double mid = 0.5 * (lo + hi);
                double ym[21];
                memcpy(ym, y0, sizeof(double) * (size_t)n);
                gsl_odeiv2_step_reset(st);
                if (gsl_odeiv2_step_apply(st, t0, mid, ym, yerr, NULL, NULL, &sys) != 0)
                    break;
                if (cref_switch_due(sy, ym)) {
                    hi = mid;
                    memcpy(yt, ym, sizeof(double) * (size_t)n);
                } else {
                    lo = mid;
                }
            }
            memcpy(y, yt, sizeof(double) * (size_t)n);
            tt = t0 + hi;
            if (!sy->slip) {
                /* onto the Coulomb limit exactly: |s| = S */
                double *s = y + 9 * sy->nbody;
                double sm = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
                cref_switch_due(sy, y); /* refresh phi */
                double S = sm - sy->phi;
                for (int k = 0; k < 3; k++) s[k] *= S / sm;
            }
            sy->slip = !sy->slip;
            gsl_odeiv2_evolve_reset(ev);
            gsl_odeiv2_step_reset(st);
        }
        double f[3] = {0, 0, 0}, a[3] = {0, 0, 0}, c[3] = {0, 0, 0}, ds[3];
        if (!cref_contact(sy, y, f, a, c, ds)) {
            sy->slip = 0;
            for (int k = 0; k < 3; k++) y[9 * sy->nbody + k] = 0.0;
        }
    }
    gsl_odeiv2_evolve_free(ev);
    gsl_odeiv2_control_free(ctl);
    gsl_odeiv2_step_free(st);
    for (int b = 0; b < sy->nbody; b++)
        for (int k = 0; k < 3; k++) {
            sy->b[b].x[k] = y[9 * b + k];
            sy->b[b].v[k] = y[9 * b + 3 + k];
            sy->b[b].w[k] = y[9 * b + 6 + k];
        }
    for (int k = 0; k < 3; k++) sy->s[k] = y[9 * sy->nbody + k];
    return rc;
}

/* ---- closed forms, head-on, no gravity ------------------------------------ */

/* Linear spring-dashpot (gran/hooke*): d'' + gamman d' + (kn/meff) d = 0 from
 * d = 0, d' = v0. Contact lasts pi/wd; the normal relative velocity is
 * reversed and scaled by e = exp(-gamman pi / (2 wd)). */
static inline double cref_hooke_contact_time(double kn, double gamman, double meff)
{
    double wd = sqrt(kn / meff - 0.25 * gamman * gamman);
    return M_PI / wd;
}
static inline double cref_hooke_restitution(double kn, double gamman, double meff)
{
    return exp(-0.5 * gamman * cref_hooke_contact_time(kn, gamman, meff));
}
/* Overlap during the contact (t in [0, tc]). */
static inline double cref_hooke_overlap(double kn, double gamman, double meff, double v0, double t)
{
    double wd = sqrt(kn / meff - 0.25 * gamman * gamman);
    return v0 / wd * exp(-0.5 * gamman * t) * sin(wd * t);
}

/* Undamped Hertz (gran/hertz/history, gamman = 0): meff d'' = -kn sqrt(reff) d^1.5.
 * Maximum overlap dmax = (5 meff v0^2 / (4 kn sqrt(reff)))^(2/5); contact time
 * 2 (dmax/v0) (2/5) B(2/5, 1/2). */
static inline double cref_hertz_contact_time(double kn, double reff, double meff, double v0)
{
    double K = kn * sqrt(reff);
    double dmax = pow(5.0 * meff * v0 * v0 / (4.0 * K), 0.4);
    return 2.0 * dmax / v0 * 0.4 * gsl_sf_beta(0.4, 0.5);
}

#endif
