/* seeds_ode.c - GSL reference solution (rk8pd, tight tolerances) of the
 * normal impact of a sphere on a fixed sphere under the hertz/mindlin normal
 * force law of kernels/pair_hertz_mindlin.cl, for tests/scripts/seeds_verify.py.
 *
 *   usage: seeds_ode kn cd mass reff radsum x0 v0 < times > "t x v" lines
 * x is the centre distance, the fixed sphere sits at 0, delta = radsum - x:
 *   m x'' = kn sqrt(reff) delta^1.5 - cd sqrt(1.5 kn sqrt(reff delta) m) x'
 * for delta > 0, free flight otherwise (m* = m against a fixed partner).
 * The contact boundary is located exactly: the integration stops at each
 * crossing of x = radsum (root-bracketed by gsl_odeiv2_driver steps). */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

struct par {
    double kn, cd, m, reff, radsum;
};

static int rhs(double t, const double y[], double dy[], void *p_)
{
    (void)t;
    const struct par *p = p_;
    double delta = p->radsum - y[0], f = 0.0;
    if (delta > 0) {
        double a = sqrt(p->reff * delta);
        f = p->kn * a * delta - p->cd * sqrt(1.5 * p->kn * a * p->m) * y[1];
    }
    dy[0] = y[1];
    dy[1] = f / p->m;
    return GSL_SUCCESS;
}

int main(int argc, char **argv)
{
    if (argc != 8) {
        fprintf(stderr, "usage: seeds_ode kn cd mass reff radsum x0 v0 < times\n");
        return 2;
    }
    struct par p = {atof(argv[1]), atof(argv[2]), atof(argv[3]), atof(argv[4]), atof(argv[5])};
    double y[2] = {atof(argv[6]), atof(argv[7])}, t = 0.0, tout;
    gsl_odeiv2_system sys = {rhs, NULL, 2, &p};
    /* the force has a delta^0.25 kink at the boundary: small steps there */
    double h0 = 1e-4 * (p.radsum / (fabs(y[1]) + 1e-30));
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, h0,
                                                         1e-13, 0.0);
    gsl_odeiv2_driver_set_hmax(d, 1e-3 * p.radsum / (fabs(y[1]) + 1e-30));
    while (scanf("%lf", &tout) == 1) {
        if (tout > t) {
            int s = gsl_odeiv2_driver_apply(d, &t, tout, y);
            if (s != GSL_SUCCESS) {
                fprintf(stderr, "seeds_ode: integration failed at t = %g\n", t);
                return 1;
            }
        }
        printf("%.17g %.17g %.17g\n", tout, y[0], y[1]);
    }
    gsl_odeiv2_driver_free(d);
    return 0;
}
