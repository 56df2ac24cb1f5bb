/* pair_hertz_mindlin.c - `pair_style hertz/mindlin E nu e mu [rolling mu_r]`:
 * Hertz-Mindlin contact with the restitution-derived (Tsuji-type) damping of
 * Hromnik, "A GPGPU implementation of the DEM ... tumbling mill" (source
 * document 003) sec. 4.3, torque on both particles (sec. 4.4) and optional
 * rolling resistance (sec. 4.5); evaluator in kernels/pair_hertz_mindlin.cl.
 *
 * All particles share one material: Young's modulus E, Poisson ratio nu. With
 * R* = r_i r_j / (r_i + r_j) (r_i for a wall), m* the reduced mass, delta the
 * overlap and beta = -ln e / sqrt(ln^2 e + pi^2):
 *   E* = E / (2 (1 - nu^2)),  G = E / (2 (1 + nu)),  G* = G / (2 (2 - nu))
 *   F_n = 4/3 E* sqrt(R*) delta^1.5 - 2 sqrt(5/6) beta sqrt(S_n m*) v_n,
 *         S_n = 2 E* sqrt(R* delta)  (applied as the two-body impulse of
 *         kernels/contact_normal.cl)
 *   F_t = -S_t s - 2 sqrt(5/6) beta sqrt(S_t m*) v_t,  S_t = 8 G* sqrt(R* delta),
 *         |F_t| <= mu max(F_n, 0) (Coulomb; s is the accumulated tangential
 *         displacement, kept per contact and rescaled when sliding)
 *   rolling: tau_i = -mu_r R* max(F_n, 0) w/|w|,  w = omega_i - omega_j
 * 003 writes the tangential spring as c_t sqrt(delta) V_t dt (a displacement
 * of one time step) and G* with 1 - nu^2; we keep the Mindlin history and the
 * standard G* (Di Renzo & Di Maio 2004), because the one-step displacement
 * makes the tangential stiffness vanish as dt -> 0 (the same flaw 000 sec.
 * 3.2.2 shows). 003's rolling torque min(|F_n|, omega_rel) mixes units; the
 * form above is that of Zhou et al. 1999 it cites. */
#include <math.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "pair.h"
#include "pair_seeds.h"

enum { C_E, C_NU, C_REST, C_MU, C_MUR };

static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    if (argc != 4 && argc != 6)
        gr_error(g, "pair_style hertz/mindlin expects E nu e mu [rolling mu_r], got %d "
                    "argument(s)", argc);
    double E = arg_positive(g, argv[0], "Young's modulus E");
    double nu = arg_double(g, argv[1], "Poisson ratio nu");
    if (!(nu > -1.0 && nu < 0.5))
        gr_error(g, "Poisson ratio nu must be in (-1, 0.5), got %g", nu);
    double e = arg_double(g, argv[2], "restitution coefficient e");
    if (!(e > 0.0 && e <= 1.0))
        gr_error(g, "restitution coefficient e must be in (0, 1], got %g", e);
    double mu = arg_nonneg(g, argv[3], "friction coefficient mu");
    double mur = 0.0;
    if (argc == 6) {
        if (strcmp(argv[4], "rolling"))
            gr_error(g, "unknown pair_style hertz/mindlin keyword '%.64s' (expected rolling)",
                     argv[4]);
        mur = arg_nonneg(g, argv[5], "rolling friction coefficient mu_r");
    }
    p->coef[C_E] = E;
    p->coef[C_NU] = nu;
    p->coef[C_REST] = e;
    p->coef[C_MU] = mu;
    p->coef[C_MUR] = mur;
}

static double estar(const struct pair *p)
{
    double nu = p->coef[C_NU];
    return p->coef[C_E] / (2.0 * (1.0 - nu * nu));
}

static double gstar(const struct pair *p)
{
    double nu = p->coef[C_NU];
    double G = p->coef[C_E] / (2.0 * (1.0 + nu));
    return G / (2.0 * (2.0 - nu));
}

static void pack(const struct pair *p, int itype, int jtype, double *param)
{
    (void)itype;
    (void)jtype;
    double l = log(p->coef[C_REST]);
    param[HM_KN] = 4.0 / 3.0 * estar(p);
    param[HM_KT] = 8.0 * gstar(p);
    param[HM_CDAMP] = 2.0 * sqrt(5.0 / 6.0) * (-l / sqrt(l * l + M_PI * M_PI));
    param[HM_MU] = p->coef[C_MU];
    param[HM_MUR] = p->coef[C_MUR];
}

/* Hertz contact duration of two equal spheres (m* = m/2, R* = r/2) at impact
 * speed vn: 2.87 (m*^2 / (R* E*^2 vn))^(1/5). Without a speed, use 1e-3 of
 * the elastic wave speed sqrt(E/rho) as a typical impact speed. */
/* e = 1 (no dashpot), mu = 0 (no tangential force), mu_r = 0 (no rolling torque) */
static int conservative(const struct pair *p)
{
    return p->coef[C_REST] == 1.0 && p->coef[C_MU] == 0.0 && p->coef[C_MUR] == 0.0;
}

/* U = 0.4 kn sqrt(R*) delta^2.5, kn = 4/3 E* (F = kn sqrt(R*) delta^1.5) */
static double contact_energy(const struct pair *p, double delta, double reff)
{
    return 0.4 * (4.0 / 3.0) * estar(p) * sqrt(reff) * delta * delta * sqrt(delta);
}

static double collision_time(const struct pair *p, double m, double r, double vn)
{
    double es = estar(p), ms = 0.5 * m, rs = 0.5 * r;
    if (!(vn > 0)) {
        double rho = m / (4.0 / 3.0 * M_PI * r * r * r);
        vn = 1e-3 * sqrt(p->coef[C_E] / rho);
    }
    return 2.87 * pow(ms * ms / (rs * es * es * vn), 0.2);
}

const struct pair_style pair_style_hertz_mindlin = {
    .name = "hertz/mindlin",
    .source = "pair_hertz_mindlin.cl",
    .eval = "hertz_mindlin_eval",
    .history = 1,
    .rotation = 1,
    .nparam = HM_NPARAM,
    .settings = settings,
    .pack = pack,
    .collision_time = collision_time,
    .conservative = conservative,
    .contact_energy = contact_energy,
};
