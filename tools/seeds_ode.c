/* seeds_ode.c - GSL reference solutions (rk8pd, tight tolerances) for
 * tests/scripts/seeds_verify.py, for force laws without a closed form.
 *
 * 1) Normal impact of a sphere on a fixed sphere under the hertz/mindlin
 *    normal force law of kernels/pair_hertz_mindlin.cl:
 *      seeds_ode kn cd mass reff radsum x0 v0 < times > "t x v" lines
 *    x is the centre distance, the fixed sphere sits at 0, delta = radsum - x:
 *      m x'' = kn sqrt(reff) delta^1.5 - cd sqrt(1.5 kn sqrt(reff delta) m) x'
 *    for delta > 0, free flight otherwise (m* = m against a fixed partner).
 *    Small maximum steps resolve the delta^(1/4) kink at the contact boundary.
 * 2) A particle in the Taylor-Green vortex of 000 eq. 6.1-6.3 under Stokes
 *    drag (kernels/fix_drag.cl):
 *      seeds_ode tg A a tau x y z vx vy vz < times > "t x y z vx vy vz" lines
 *    x' = v, v' = (u_f(x) - v) / tau. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

struct tg {
    double A, a, tau;
};

static int rhs_tg(double t, const double y[], double dy[], void *p_)
{
    (void)t;
    const struct tg *p = p_;
    double sh = M_PI / (2 * p->a);
    double X = p->a * (y[0] + sh), Y = p->a * (y[1] + sh), Z = p->a * (y[2] + sh);
    double u[3] = {p->A * cos(X) * sin(Y) * sin(Z), p->A * sin(X) * cos(Y) * sin(Z),
                   -2 * p->A * sin(X) * sin(Y) * cos(Z)};
    for (int k = 0; k < 3; k++) {
        dy[k] = y[3 + k];
        dy[3 + k] = (u[k] - y[3 + k]) / p->tau;
    }
    return GSL_SUCCESS;
}

static int taylor_green(int argc, char **argv)
{
    if (argc != 11) {
        fprintf(stderr, "usage: seeds_ode tg A a tau x y z vx vy vz < times\n");
        return 2;
    }
    struct tg p = {atof(argv[2]), atof(argv[3]), atof(argv[4])};
    double y[6], t = 0.0, tout;
    for (int k = 0; k < 6; k++)
        y[k] = atof(argv[5 + k]);
    gsl_odeiv2_system sys = {rhs_tg, NULL, 6, &p};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3 * p.tau, 1e-13, 1e-13);
    while (scanf("%lf", &tout) == 1) {
        if (tout > t && gsl_odeiv2_driver_apply(d, &t, tout, y) != GSL_SUCCESS) {
            fprintf(stderr, "seeds_ode: integration failed at t = %g\n", t);
            return 1;
        }
        printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", tout, y[0], y[1], y[2], y[3], y[4],
               y[5]);
    }
    gsl_odeiv2_driver_free(d);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 1 && !strcmp(argv[1], "tg"))
        return taylor_green(argc, argv);
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
