/* pair_linear_restitution.c - `pair_style linear/restitution ke e mu [kf K]
 * [torque yes|no]`: the linear spring-dashpot of Andrews (2018), "GPU
 * enabled analysis of agglomeration" (source document 000), with the damping
 * derived from the restitution coefficient and its "complex" friction model
 * (evaluator in kernels/pair_linear_restitution.cl).
 *
 *   F_n = ke delta n - eta u_n                             (000 eq. 2.1)
 *         (applied as the two-body impulse of kernels/contact_normal.cl)
 *   eta = -2 ln(e) sqrt(m* ke / (pi^2 + ln(e)^2))           (000 eq. 2.17)
 *   t_col = sqrt(m_eff / ke) sqrt(pi^2 + ln(e)^2)                (000 eq. 2.15)
 *   F_t = -t min(kf |u_t| t_col, mu |F_n|)                  (000 eq. 2.2, 2.4, 2.5)
 * with m* = m_i m_j / (m_i + m_j) the reduced mass of the pair (eq. 2.14; a
 * frozen partner or a wall counts as infinitely heavy: m* = m_i). The static
 * friction uses the estimate zeta = |u_t| t_col of sec. 3.2.2 with the pair's
 * own collision time, so no contact history is kept.
 *
 * The host precomputes the two pair-independent factors, so the kernel only
 * takes sqrt(m*): eta = ceta sqrt(m*), t_col = ctcol sqrt(m*). */
#include <math.h>
#include <string.h>

#include "args.h"
#include "coeff_check.h"
#include "collision_time.h"
#include "error.h"
#include "pair.h"
#include "pair_seeds.h"

/* coef[] layout on the host (the script's values). */
enum { C_KE, C_E, C_MU, C_KF, C_TORQUE };

static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "pair_style linear/restitution expects ke e mu [kf K] [torque yes|no], "
                    "got %d argument(s)", argc);
    double ke = coeff_arg(g, NULL, argv[0], "stiffness ke", CR_POSITIVE);
    double e = coeff_arg(g, NULL, argv[1], "restitution coefficient e", CR_RESTITUTION);
    double mu = coeff_arg(g, NULL, argv[2], "friction coefficient mu", CR_NONNEG);
    double kf = ke;
    int torque = 0;
    for (int i = 3; i < argc; i += 2) {
        if (!strcmp(argv[i], "kf")) {
            arg_need(g, argc, i, 1, "kf");
            kf = coeff_arg(g, NULL, argv[i + 1], "friction stiffness kf", CR_NONNEG);
        } else if (!strcmp(argv[i], "torque")) {
            arg_need(g, argc, i, 1, "torque");
            torque = arg_yesno(g, argv[i + 1], "torque");
        } else {
            gr_error(g, "unknown pair_style linear/restitution keyword '%.64s' (expected kf or "
                        "torque)", argv[i]);
        }
    }
    p->coef[C_KE] = ke;
    p->coef[C_E] = e;
    p->coef[C_MU] = mu;
    p->coef[C_KF] = kf;
    p->coef[C_TORQUE] = torque;
}

double seeds_restitution_damping_factor(double e)
{
    double l = log(e);
    return -2.0 * l / sqrt(M_PI * M_PI + l * l);
}

double seeds_linear_collision_time(double ke, double e, double meff)
{
    return tcol_restitution(ke, e, meff);
}

static void pack(const struct pair *p, int itype, int jtype, double *param)
{
    (void)itype;
    (void)jtype;
    double ke = p->coef[C_KE], e = p->coef[C_E];
    param[LR_KE] = ke;
    param[LR_KF] = p->coef[C_KF];
    param[LR_MU] = p->coef[C_MU];
    param[LR_CETA] = seeds_restitution_damping_factor(e) * sqrt(ke);
    param[LR_CTCOL] = seeds_linear_collision_time(ke, e, 1.0);
    param[LR_TORQUE] = p->coef[C_TORQUE];
}

/* Collision time (eq. 2.15) of two equal particles of mass m: m* = m/2. */
/* e = 1 and mu = 0: spring only (kf acts only under the Coulomb cap mu |F_n|) */
static int conservative(const struct pair *p)
{
    return p->coef[C_E] == 1.0 && p->coef[C_MU] == 0.0;
}

static double contact_energy(const struct pair *p, double delta, double reff)
{
    (void)reff;
    return 0.5 * p->coef[C_KE] * delta * delta;
}

static double collision_time(const struct pair *p, double m, double r, double vn)
{
    (void)r;
    (void)vn;
    return seeds_linear_collision_time(p->coef[C_KE], p->coef[C_E], 0.5 * m);
}

static void describe(const struct pair *p, struct pair_caps *c)
{
    pair_caps_source(c, "pair_linear_restitution.cl");
    c->eval = "linear_restitution_eval";
    c->sym_torque = 1; /* tr = 0 */
    c->approach = 1;
    c->tcol_of = p;
    c->collision_time = collision_time;
    c->conservative = conservative(p);
    c->energy_of = p;
    c->contact_energy = contact_energy;
}

const struct pair_style pair_style_linear_restitution = {
    .name = "linear/restitution",
    .nparam = LR_NPARAM,
    .settings = settings,
    .pack = pack,
    .describe = describe,
};
