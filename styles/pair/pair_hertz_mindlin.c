/* pair_hertz_mindlin.c - `pair_style hertz/mindlin E nu e mu [rolling mu_r]
 * [tangential mindlin|thesis]`:
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
 * 3.2.2 shows); `tangential thesis` gives 003's own law as an option: s = v_t dt
 * afresh each step (nothing stored) with S_t = 8 G sqrt(R* delta) (fig. 5.23's
 * ppTanForceCoeff = 8 G sqrt(R/2) dt), so F_t = 0 when v_t = 0 (no static
 * friction). 003's rolling torque min(|F_n|, omega_rel) mixes units; the
 * form above is that of Zhou et al. 1999 it cites.
 *
 * Materials per type pair (003 fig. 5.24 gives particle-particle and
 * particle-shell values): `pair_coeff I J E nu e mu [rolling mu_r]` gives the
 * pair (I, J) its own interaction properties, used in the formulas above in
 * place of the pair_style ones; `pair_coeff I J` alone uses the pair_style
 * ones. Every I I must be named before a run (LAMMPS's rule); a cross pair
 * never named uses the pair_style values. A mesh of `type T` under fix
 * wall/pair sees the coefficients of (I, T). Restart files keep the
 * pair_style values only: re-issue per-pair pair_coeff lines after
 * read_restart. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "coeff_check.h"
#include "collision_time.h"
#include "error.h"
#include "pair.h"
#include "pair_seeds.h"

enum { C_E, C_NU, C_REST, C_MU, C_MUR, C_TTHESIS };

#define HMC_N 6

/* Per type pair: set (0 none, 1 pair_style values, 2 own values) and values. */
struct hm_table {
    int nt;
    unsigned char *set;
    double *c;          /* nt x nt x HMC_N */
};

static void destroy(struct pair *p)
{
    struct hm_table *t = p->data;
    if (t) {
        free(t->set);
        free(t->c);
        free(t);
    }
    p->data = NULL;
}

/* E nu e mu [rolling mu_r] [tangential mindlin|thesis] into c[0..HMC_N); `who`
 * names the command. */
static void parse_material(struct gravel *g, int argc, char **argv, double *c, const char *who)
{
    if (argc < 4 || argc % 2)
        gr_error(g, "%s expects E nu e mu [rolling mu_r] [tangential mindlin|thesis], got %d "
                    "argument(s)", who, argc);
    double E = coeff_arg(g, NULL, argv[0], "Young's modulus E", CR_POSITIVE);
    double nu = coeff_arg(g, NULL, argv[1], "Poisson ratio nu", CR_POISSON);
    double e = coeff_arg(g, NULL, argv[2], "restitution coefficient e", CR_RESTITUTION);
    double mu = coeff_arg(g, NULL, argv[3], "friction coefficient mu", CR_NONNEG);
    double mur = 0.0, thesis = 0.0;
    for (int k = 4; k < argc; k += 2) {
        if (!strcmp(argv[k], "rolling"))
            mur = coeff_arg(g, NULL, argv[k + 1], "rolling friction coefficient mu_r",
                            CR_NONNEG);
        else if (!strcmp(argv[k], "tangential") && !strcmp(argv[k + 1], "mindlin"))
            thesis = 0.0;
        else if (!strcmp(argv[k], "tangential") && !strcmp(argv[k + 1], "thesis"))
            thesis = 1.0;
        else if (!strcmp(argv[k], "tangential"))
            gr_error(g, "%s: unknown tangential model '%.64s' (expected mindlin or thesis)", who,
                     argv[k + 1]);
        else
            gr_error(g, "unknown pair_style hertz/mindlin keyword '%.64s' (expected rolling or "
                        "tangential)", argv[k]);
    }
    c[C_E] = E;
    c[C_NU] = nu;
    c[C_REST] = e;
    c[C_MU] = mu;
    c[C_MUR] = mur;
    c[C_TTHESIS] = thesis;
}

static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    parse_material(g, argc, argv, p->coef, "pair_style hertz/mindlin");
}

/* pair_coeff I J [E nu e mu [rolling mu_r] [tangential mindlin|thesis]] */
static void coeff(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi,
                  int argc, char **argv)
{
    double c[HMC_N];
    if (argc > 0)
        parse_material(g, argc, argv, c, "pair_coeff (hertz/mindlin)");
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    struct hm_table *t = p->data;
    if (t && t->nt != nt)
        destroy(p);
    t = p->data;
    if (!t) {
        t = gr_calloc(g, 1, sizeof *t);
        p->data = t;
        t->nt = nt;
        t->set = gr_calloc(g, (size_t)nt * nt, 1);
        t->c = gr_calloc(g, (size_t)nt * nt * HMC_N, sizeof(double));
    }
    for (int I = ilo; I <= ihi; I++)
        for (int J = jlo > I ? jlo : I; J <= jhi; J++) /* LAMMPS: J >= I, and the mirror */
            for (int s = 0; s < 2; s++) {
                size_t k = s ? (size_t)(J - 1) * nt + (I - 1) : (size_t)(I - 1) * nt + (J - 1);
                t->set[k] = argc > 0 ? 2 : 1;
                if (argc > 0)
                    memcpy(t->c + k * HMC_N, c, sizeof c);
            }
    p->coeff_set = 1;
}

static void init(struct gravel *g, struct pair *p)
{
    const struct hm_table *t = p->data;
    if (!t) /* after read_restart: the pair_style material for every pair */
        return;
    if (t->nt != g->atoms.ntypes)
        gr_error(g, "pair style hertz/mindlin: pair_coeff was given for %d atom types, the box "
                    "has %d: re-issue pair_coeff", t->nt, g->atoms.ntypes);
    for (int I = 1; I <= t->nt; I++)
        if (!t->set[(size_t)(I - 1) * t->nt + (I - 1)])
            gr_error(g, "all pair coeffs are not set: no pair_coeff for types %d %d of pair "
                        "style hertz/mindlin (e.g. pair_coeff * *)", I, I);
}

/* The material of type pair (i, j): its own or the pair_style one. */
static const double *material(const struct pair *p, int itype, int jtype)
{
    const struct hm_table *t = p->data;
    if (t && itype >= 1 && jtype >= 1 && itype <= t->nt && jtype <= t->nt) {
        size_t k = (size_t)(itype - 1) * t->nt + (jtype - 1);
        if (t->set[k] == 2)
            return t->c + k * HMC_N;
    }
    return p->coef;
}

static double estar_of(const double *c)
{
    double nu = c[C_NU];
    return c[C_E] / (2.0 * (1.0 - nu * nu));
}

static double estar(const struct pair *p)
{
    return estar_of(p->coef);
}

/* G = E / (2 (1 + nu)); tangential thesis uses it as 003's c_t = 8 G sqrt(R*)
 * (sec. 4.3, fig. 5.23) */
static double g_of(const double *c)
{
    return c[C_E] / (2.0 * (1.0 + c[C_NU]));
}

static double gstar_of(const double *c)
{
    return g_of(c) / (2.0 * (2.0 - c[C_NU]));
}

static void pack(const struct pair *p, int itype, int jtype, double *param)
{
    const double *c = material(p, itype, jtype);
    double l = log(c[C_REST]);
    param[HM_KN] = 4.0 / 3.0 * estar_of(c);
    param[HM_KT] = 8.0 * (c[C_TTHESIS] != 0.0 ? g_of(c) : gstar_of(c));
    param[HM_CDAMP] = 2.0 * sqrt(5.0 / 6.0) * (-l / sqrt(l * l + M_PI * M_PI));
    param[HM_MU] = c[C_MU];
    param[HM_MUR] = c[C_MUR];
    param[HM_TTHESIS] = c[C_TTHESIS];
}

/* Hertz contact duration of two equal spheres (m* = m/2, R* = r/2) at impact
 * speed vn: 2.87 (m*^2 / (R* E*^2 vn))^(1/5). Without a speed, use 1e-3 of
 * the elastic wave speed sqrt(E/rho) as a typical impact speed. */
/* 1 when test(c) holds for the pair_style material and every pair's own */
static int every_material(const struct pair *p, int (*test)(const double *c))
{
    const struct hm_table *t = p->data;
    int nt = t ? t->nt : 0;
    for (size_t k = 0; k <= (size_t)nt * nt; k++) {
        const double *c = k == (size_t)nt * nt ? p->coef
                        : t->set[k] == 2      ? t->c + k * HMC_N
                                               : p->coef;
        if (!test(c))
            return 0;
    }
    return 1;
}

/* e = 1 (no dashpot), mu = 0 (no tangential force), mu_r = 0 (no rolling
 * torque) */
static int elastic(const double *c)
{
    return c[C_REST] == 1.0 && c[C_MU] == 0.0 && c[C_MUR] == 0.0;
}

/* mu_r = 0: no rolling torque (struct contact_force tr = 0) */
static int rolling_free(const double *c) { return c[C_MUR] == 0.0; }

/* U = 0.4 kn sqrt(R*) delta^2.5, kn = 4/3 E* (F = kn sqrt(R*) delta^1.5) */
static double contact_energy(const struct pair *p, double delta, double reff)
{
    return 0.4 * (4.0 / 3.0) * estar(p) * sqrt(reff) * delta * delta * sqrt(delta);
}

/* Run-start collision time of two equal spheres (m* = m/2, R* = r/2):
 * Johnson's Hertz time (kernels/collision_time.h) from E* */
static double collision_time(const struct pair *p, double m, double r, double vn)
{
    if (!(vn > 0)) {
        double rho = m / (4.0 / 3.0 * M_PI * r * r * r);
        vn = 1e-3 * sqrt(p->coef[C_E] / rho);
    }
    return tcol_hertz_es(estar(p), 0.5 * r, 0.5 * m, vn);
}

static void describe(const struct pair *p, struct pair_caps *c)
{
    pair_caps_source(c, "pair_hertz_mindlin.cl");
    c->eval = "hertz_mindlin_eval";
    c->rotation = 1;
    c->sym_torque = every_material(p, rolling_free);
    c->history = 1;
    c->tcol_of = p;
    c->collision_time = collision_time;
    c->conservative = every_material(p, elastic);
    c->energy_of = p;
    c->contact_energy = contact_energy;
}

const struct pair_style pair_style_hertz_mindlin = {
    .name = "hertz/mindlin",
    .nparam = HM_NPARAM,
    .settings = settings,
    .coeff = coeff,
    .init = init,
    .destroy = destroy,
    .pack = pack,
    .describe = describe,
};
