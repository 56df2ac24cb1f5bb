/* pair_cohesion.c - `pair_style cohesion kc`: linear cohesion between the
 * *effect surfaces* of two particles (Andrews 2018, source document 000,
 * eq. 2.6 and appendix A.2; evaluator in kernels/pair_cohesion.cl).
 *
 *   F_c = -kc delta_e n   on i,   delta_e = (e_i + e_j) - r > 0,   n = (x_i - x_j)/r
 *
 * e_i is the effect radius of particle i in this type pair: either half an
 * effect diameter given per type (pair_coeff I I d_e) or a ratio of the body
 * radius (pair_coeff I I ratio R: e_i = R r_i). The force keeps acting in full
 * body contact (A.2.2) and is meant to be composed with a contact law through
 * `pair_style hybrid/overlay` (styles/pair/pair_hybrid_overlay.c).
 *
 * Coefficients (pair_coeff I J):
 *   d_e [kc K]        effect diameter of the I-J pair (centre distance at which
 *                     the effect surfaces touch); for I = J the type's own d_e
 *   ratio R [kc K]    effect diameter = R x body diameter, R >= 1
 * Type ranges follow LAMMPS (pair_coeff * 2 sets 1-1 1-2 2-2, each with its
 * mirror). Unset I != J pairs mix from I I and J J: each side keeps its own type's
 * effect radius (d_e/2 or R r), kc = sqrt(kc_I kc_J) (pair_modify mix
 * geometric, the default) or (kc_I + kc_J)/2 (mix arithmetic). The kc keyword
 * overrides the pair_style stiffness for that pair.
 *
 * With fix drag active, run setup logs the Stokes number (000 eq. 6.4) and
 * the Stickiness number (eq. 6.5) of the scene. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "coeff_check.h"
#include "error.h"
#include "fix.h"
#include "pair.h"
#include "pair_cohesion_numbers.h"
#include "pair_cohesion.h"

/* Per-type-pair tables, row-major (I-1) nt + (J-1), for the I side. */
struct coh {
    int nt;
    double *a;          /* effect radius offset of the I particle (d_e / 2) */
    double *b;          /* effect radius per body radius of the I particle (R) */
    double *kc;         /* stiffness of the pair */
    signed char *set;   /* 1 = explicit pair_coeff, 2 = mixed at init */
    signed char *kcset; /* kc given explicitly for this pair */
};

static void destroy(struct pair *p)
{
    struct coh *c = p->data;
    if (c) {
        free(c->a);
        free(c->b);
        free(c->kc);
        free(c->set);
        free(c->kcset);
        free(c);
    }
    p->data = NULL;
}

static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, "cohesion expects one argument, the cohesion stiffness kc "
                    "(force/distance), got %d", argc);
    p->coef[0] = coeff_arg(g, NULL, argv[0], "cohesion stiffness kc", CR_NONNEG);
}

static struct coh *tables(struct gravel *g, struct pair *p)
{
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    struct coh *c = p->data;
    if (c && c->nt == nt)
        return c;
    if (c)
        destroy(p);
    c = gr_calloc(g, 1, sizeof *c);
    c->nt = nt;
    size_t m = (size_t)nt * nt;
    c->a = gr_calloc(g, m, sizeof *c->a);
    c->b = gr_calloc(g, m, sizeof *c->b);
    c->kc = gr_calloc(g, m, sizeof *c->kc);
    c->set = gr_calloc(g, m, 1);
    c->kcset = gr_calloc(g, m, 1);
    p->data = c;
    return c;
}

/* pair_coeff I J d_e [kc K] | ratio R [kc K] */
static void coeff(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi,
                  int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "pair style cohesion expects pair_coeff I J d_e [kc K] or pair_coeff I J "
                    "ratio R [kc K]");
    double a = 0, b = 0;
    int i = 0;
    if (!strcmp(argv[0], "ratio")) {
        arg_need(g, argc, 0, 1, "ratio");
        b = arg_double(g, argv[1], "effect/body diameter ratio");
        if (!(b >= 1.0) || !isfinite(b))
            gr_error(g, "effect/body diameter ratio must be >= 1 (the effect surface encloses "
                        "the body), got %g", b);
        i = 2;
    } else {
        a = 0.5 * coeff_arg(g, NULL, argv[0], "effect diameter d_e", CR_POSITIVE);
        i = 1;
    }
    double kc = p->coef[0];
    int kcset = 0;
    for (; i < argc; i += 2) {
        if (strcmp(argv[i], "kc"))
            gr_error(g, "unknown pair_coeff keyword '%.64s' for pair style cohesion (expected "
                        "kc)", argv[i]);
        arg_need(g, argc, i, 1, "kc");
        kc = coeff_arg(g, NULL, argv[i + 1], "cohesion stiffness kc", CR_NONNEG);
        kcset = 1;
    }
    struct coh *c = tables(g, p);
    for (int I = ilo; I <= ihi; I++)
        for (int J = jlo > I ? jlo : I; J <= jhi; J++) { /* LAMMPS: J >= I */
            for (int s = 0; s < 2; s++) { /* the pair and its mirror J I */
                size_t k = s ? (size_t)(J - 1) * c->nt + (I - 1) : (size_t)(I - 1) * c->nt + (J - 1);
                c->a[k] = a;
                c->b[k] = b;
                c->kc[k] = kc;
                c->set[k] = 1;
                c->kcset[k] = (signed char)kcset;
            }
        }
    p->coeff_set = 1;
}

/* Mix unset cross pairs from the diagonal; every pair must end up set. */
static void init(struct gravel *g, struct pair *p)
{
    struct coh *c = p->data;
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    if (!c || c->nt != nt)
        gr_error(g, "pair style cohesion: pair_coeff must be given (after the box defines %d "
                    "atom type(s); restart files do not keep cohesion coefficients)", nt);
    for (int I = 1; I <= nt; I++)
        if (c->set[(size_t)(I - 1) * nt + (I - 1)] != 1) {
            /* a diagonal may be skipped only when every pair with I is explicit */
            for (int J = 1; J <= nt; J++)
                if (!c->set[(size_t)(I - 1) * nt + (J - 1)])
                    gr_error(g, "pair style cohesion: no pair_coeff for types %d %d (give "
                                "pair_coeff %d %d d_e or ratio R)", I, J, I, I);
        }
    /* pairs without their own kc follow the current pair_style kc (a
     * redefined pair_style cohesion keeps the pair_coeff settings) */
    for (size_t k = 0; k < (size_t)nt * nt; k++)
        if (c->set[k] == 1 && !c->kcset[k])
            c->kc[k] = p->coef[0];
    for (int I = 1; I <= nt; I++)
        for (int J = 1; J <= nt; J++) {
            size_t k = (size_t)(I - 1) * nt + (J - 1);
            if (c->set[k] == 1)
                continue;
            size_t ii = (size_t)(I - 1) * nt + (I - 1), jj = (size_t)(J - 1) * nt + (J - 1);
            c->a[k] = c->a[ii];
            c->b[k] = c->b[ii];
            c->kc[k] = p->mix_arithmetic ? 0.5 * (c->kc[ii] + c->kc[jj])
                                         : sqrt(c->kc[ii] * c->kc[jj]);
            c->set[k] = 2;
        }
    pair_cohesion_overlap_check(g, p);
    pair_cohesion_dimensionless(g, p);
}

static void pack(const struct pair *p, int itype, int jtype, double *param)
{
    const struct coh *c = p->data;
    size_t ij = (size_t)(itype - 1) * c->nt + (jtype - 1);
    size_t ji = (size_t)(jtype - 1) * c->nt + (itype - 1);
    param[COH_KC] = c->kc[ij];
    param[COH_AI] = c->a[ij];
    param[COH_BI] = c->b[ij];
    param[COH_AJ] = c->a[ji];
    param[COH_BJ] = c->b[ji];
}

/* Affine bound A + B radsum over all type pairs of the effect distance
 * (left alone before pair_coeff). */
static void reach_bound(const struct pair *p, double *ra, double *rb)
{
    const struct coh *c = p->data;
    if (!c)
        return;
    double a = 0, b = 0;
    int nt = c->nt;
    for (int I = 0; I < nt; I++)
        for (int J = 0; J < nt; J++) {
            double s = c->a[(size_t)I * nt + J] + c->a[(size_t)J * nt + I];
            a = s > a ? s : a;
            b = c->b[(size_t)I * nt + J] > b ? c->b[(size_t)I * nt + J] : b;
        }
    *ra = a;
    *rb = b;
}

double pair_cohesion_effect_distance(const struct pair *p, int itype, int jtype, double radi,
                                     double radj, double *kc)
{
    const struct coh *c = p->data;
    size_t ij = (size_t)(itype - 1) * c->nt + (jtype - 1);
    size_t ji = (size_t)(jtype - 1) * c->nt + (itype - 1);
    if (kc)
        *kc = c->kc[ij];
    return (c->a[ij] + c->b[ij] * radi) + (c->a[ji] + c->b[ji] * radj);
}

/* acts beyond contact up to its effect distance; no collision of its own */
static void describe(const struct pair *p, struct pair_caps *c)
{
    pair_caps_source(c, "pair_cohesion.cl");
    c->eval = "cohesion_eval";
    c->sym_torque = 1; /* no torque */
    c->beyond = 1;
    double a = 0, b = 1; /* no tables yet: the contact distance */
    reach_bound(p, &a, &b);
    pair_caps_reach(c, a, b);
}

const struct pair_style pair_style_cohesion = {
    .name = "cohesion",
    .nparam = COH_NPARAM,
    .settings = settings,
    .pack = pack,
    .describe = describe,
    .coeff = coeff,
    .init = init,
    .destroy = destroy,
};
