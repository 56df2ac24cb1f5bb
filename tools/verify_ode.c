/* verify_ode.c - GSL reference for the oblique-impact verification case
 * (inputs/verification/oblique_impact.in, tests/scripts/verify_cases.py):
 * a sphere hits a flat wall (fix wall/pair, z = 0, normal +z) obliquely under
 * the hertz/mindlin law of kernels/pair_hertz_mindlin.cl, with the tangential
 * spring, its damping, the Coulomb limit and rotation about y.
 *
 *   verify_ode kn kt cd mu mass r x0 z0 vx0 vz0 wy0 < times
 *     > "t x z vx vz wy s" lines
 *
 * The wall is particle j: R* = r, m* = m, I = 2/5 m r^2, delta = r - z,
 * a = sqrt(r delta), v_t = vx - r wy (contact-point slip along x),
 *   F_n  = kn a delta - cd sqrt(1.5 kn a m) vz
 *   s'   = v_t                                     (stick)
 *   F_t  = -kt a s - cd sqrt(kt a m) v_t, |F_t| <= mu max(F_n, 0)
 *   torque_y = -r F_t   (n x F_t = F_t e_y for n = e_z)
 * In slip the kernel holds the spring at s = -F_t/(kt a): the spring alone
 * carries the Coulomb force. The reference does the same: rk8pd with steps of at
 * most 1e-4 of the contact duration, the spring mapped back onto the Coulomb
 * limit after every accepted step, so the remaining difference to the exact
 * differential inclusion is O(1e-4) of the contact, far below what the DEM
 * time steps (t_col/8 ... /128) are checked for. Out of contact s = 0. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

struct par {
    double kn, kt, cd, mu, m, r;
};

/* Contact forces at state y (x z vx vz wy s): normal fn, tangential ft
 * (clamped), and the spring value consistent with the clamp in *s_map. */
static void forces(const struct par *p, const double y[], double *fn, double *ft, double *s_map)
{
    double delta = p->r - y[1];
    *fn = *ft = 0.0;
    *s_map = 0.0;
    if (delta <= 0)
        return;
    double a = sqrt(p->r * delta);
    double vt = y[2] - p->r * y[4];
    *fn = p->kn * a * delta - p->cd * sqrt(1.5 * p->kn * a * p->m) * y[3];
    double st = p->kt * a, dtc = p->cd * sqrt(st * p->m);
    double f = -st * y[5] - dtc * vt, flim = p->mu * fmax(*fn, 0.0);
    *s_map = y[5];
    if (fabs(f) > flim) {
        f = f > 0 ? flim : -flim;
        *s_map = -f / st;
    }
    *ft = f;
}

static int rhs(double t, const double y[], double dy[], void *p_)
{
    (void)t;
    const struct par *p = p_;
    double fn, ft, sm;
    forces(p, y, &fn, &ft, &sm);
    double inertia = 0.4 * p->m * p->r * p->r;
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = ft / p->m;
    dy[3] = fn / p->m;
    dy[4] = -p->r * ft / inertia;
    dy[5] = p->r - y[1] > 0 ? y[2] - p->r * y[4] : 0.0;
    return GSL_SUCCESS;
}

int main(int argc, char **argv)
{
    if (argc != 12) {
        fprintf(stderr, "usage: verify_ode kn kt cd mu mass r x0 z0 vx0 vz0 wy0 < times\n");
        return 2;
    }
    struct par p = {atof(argv[1]), atof(argv[2]), atof(argv[3]),
                    atof(argv[4]), atof(argv[5]), atof(argv[6])};
    double y[6] = {atof(argv[7]), atof(argv[8]), atof(argv[9]), atof(argv[10]), atof(argv[11]), 0};
    /* contact duration scale: Hertz 2.87 (m^2/(R E*^2 v))^(1/5), E* = 3 kn / 4 */
    double es = 0.75 * p.kn, v = fabs(y[3]) + 1e-30;
    double tc = 2.87 * pow(p.m * p.m / (p.r * es * es * v), 0.2);
    const char *hs = getenv("VERIFY_ODE_HMAX");  /* fraction of the contact duration */
    double hmax = (hs ? atof(hs) : 1e-4) * tc, t = 0.0, tout;
    gsl_odeiv2_system sys = {rhs, NULL, 6, &p};
    gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 6);
    gsl_odeiv2_control *c = gsl_odeiv2_control_y_new(1e-13, 1e-13);
    gsl_odeiv2_evolve *ev = gsl_odeiv2_evolve_alloc(6);
    while (scanf("%lf", &tout) == 1) {
        while (t < tout) {
            double h = fmin(hmax, tout - t);
            if (gsl_odeiv2_evolve_apply(ev, c, st, &sys, &t, tout, &h, y) != GSL_SUCCESS) {
                fprintf(stderr, "verify_ode: integration failed at t = %g\n", t);
                return 1;
            }
            double fn, ft, sm;
            forces(&p, y, &fn, &ft, &sm);
            y[5] = sm;      /* return mapping onto the Coulomb limit; 0 out of contact */
            gsl_odeiv2_evolve_reset(ev);
        }
        printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", tout, y[0], y[1], y[2], y[3], y[4],
               y[5]);
    }
    gsl_odeiv2_evolve_free(ev);
    gsl_odeiv2_control_free(c);
    gsl_odeiv2_step_free(st);
    return 0;
}
