/* pair_colloid.c - `pair_style colloid cutoff` (LAMMPS pair colloid;
 * evaluator and energies in kernels/pair_colloid.cl).
 *
 * pair_coeff I J A sigma d1 d2 [cutoff]: Hamaker constant A (energy), LJ
 * size sigma of the small particles, colloid diameters d1 (of type I) and d2
 * (of type J; 0 = a point LJ particle), and the pair's cut-off (default the
 * pair_style one). The form follows LAMMPS's init_one: d1 = d2 = 0 small-small
 * (LJ with eps = A/144), one of them 0 colloid-small, both > 0 colloid-colloid;
 * I = J requires d1 = d2. Unset I != J pairs mix from I I and J J as LAMMPS
 * (pair_modify mix geometric, the default: A = sqrt(A_I A_J), sigma, d1, d2
 * and cutoff geometric means; arithmetic: A geometric, the lengths
 * arithmetic means). pair_modify shift yes subtracts the energy at the
 * cut-off. The particles' own radii play no part: the neighbor list reaches
 * each type pair's cut-off plus the skin (pair_style type_cut). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "coeff_check.h"
#include "error.h"
#include "pair.h"

enum { C_A12, C_SIGMA, C_D1, C_D2, C_CUT, C_N };

struct col {
    int nt;
    double *c;          /* C_N per (I-1) nt + (J-1), I <= J meaningful */
    signed char *set;   /* explicit pair_coeff of I J (I <= J) */
    int *cut_given;     /* the pair's own cut-off was given */
};

static void destroy(struct pair *p)
{
    struct col *c = p->data;
    if (c) {
        free(c->c);
        free(c->set);
        free(c->cut_given);
        free(c);
    }
    p->data = NULL;
}

static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, "pair style colloid expects one argument, the global cut-off, got %d", argc);
    p->coef[0] = arg_positive(g, argv[0], "colloid cut-off");
}

static struct col *tables(struct gravel *g, struct pair *p)
{
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    struct col *c = p->data;
    if (c && c->nt == nt)
        return c;
    if (c)
        destroy(p);
    c = gr_calloc(g, 1, sizeof *c);
    c->nt = nt;
    c->c = gr_calloc(g, (size_t)nt * nt * C_N, sizeof(double));
    c->set = gr_calloc(g, (size_t)nt * nt, 1);
    c->cut_given = gr_calloc(g, (size_t)nt * nt, sizeof(int));
    p->data = c;
    return c;
}

static double *at(const struct col *c, int i, int j)
{
    return c->c + ((size_t)(i - 1) * c->nt + (j - 1)) * C_N;
}

/* pair_coeff I J A sigma d1 d2 [cutoff] */
static void coeff(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi,
                  int argc, char **argv)
{
    if (argc < 4 || argc > 5)
        gr_error(g, "pair style colloid expects pair_coeff I J A sigma d1 d2 [cutoff], got %d "
                    "values after the types", argc);
    double a12 = coeff_arg(g, NULL, argv[0], "Hamaker constant A", CR_FINITE);
    double sigma = coeff_arg(g, NULL, argv[1], "sigma", CR_POSITIVE);
    double d1 = arg_double(g, argv[2], "d1");
    double d2 = arg_double(g, argv[3], "d2");
    int given = argc == 5;
    double cut = given ? coeff_arg(g, NULL, argv[4], "cut-off", CR_POSITIVE) : p->coef[0];
    if (d1 < 0 || d2 < 0)
        gr_error(g, "invalid d1 or d2 value for pair colloid coeff (%g %g: diameters are >= 0)",
                 d1, d2);
    struct col *c = tables(g, p);
    for (int i = ilo; i <= ihi; i++)
        for (int j = jlo > i ? jlo : i; j <= jhi; j++) {
            if (i == j && d1 != d2)
                gr_error(g, "invalid d1 or d2 value for pair colloid coeff: pair_coeff %d %d "
                            "needs d1 = d2 (got %g %g)", i, j, d1, d2);
            double *v = at(c, i, j);
            v[C_A12] = a12;
            v[C_SIGMA] = sigma;
            v[C_D1] = d1;
            v[C_D2] = d2;
            v[C_CUT] = cut;
            c->set[(size_t)(i - 1) * c->nt + (j - 1)] = 1;
            c->cut_given[(size_t)(i - 1) * c->nt + (j - 1)] = given;
        }
    p->coeff_set = 1;
}

static double mix_distance(const struct pair *p, double a, double b)
{
    return p->mix_arithmetic ? 0.5 * (a + b) : sqrt(a * b);
}

/* LAMMPS init_one for every I <= J: mix what is unset, copy to J I. */
static void init(struct gravel *g, struct pair *p)
{
    struct col *c = p->data;
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    if (!c || c->nt != nt)
        gr_error(g, "pair style colloid: pair_coeff must be given for the %d atom type(s) of "
                    "the box", nt);
    for (int i = 1; i <= nt; i++)
        if (!c->set[(size_t)(i - 1) * nt + (i - 1)])
            gr_error(g, "all pair coeffs are not set: no pair_coeff for types %d %d of pair "
                        "style colloid", i, i);
    for (int i = 1; i <= nt; i++)
        for (int j = i; j <= nt; j++) {
            double *v = at(c, i, j);
            size_t k = (size_t)(i - 1) * nt + (j - 1);
            /* a pair without its own cut-off follows the current pair_style one */
            if (c->set[k] && !c->cut_given[k])
                v[C_CUT] = p->coef[0];
            if (!c->set[k]) {
                const double *a = at(c, i, i), *b = at(c, j, j);
                v[C_A12] = sqrt(a[C_A12] * b[C_A12]); /* mix_energy: geometric or arithmetic */
                v[C_SIGMA] = mix_distance(p, a[C_SIGMA], b[C_SIGMA]);
                v[C_D1] = mix_distance(p, a[C_D1], b[C_D1]);
                v[C_D2] = mix_distance(p, a[C_D2], b[C_D2]);
                v[C_CUT] = mix_distance(p, a[C_CUT], b[C_CUT]);
            }
            memcpy(at(c, j, i), v, C_N * sizeof(double));
        }
}

static double colloid_energy(const double *p, double rsq);

/* The packed parameters of the (itype, jtype) pair, the owner of type itype. */
static void pack(const struct pair *p, int itype, int jtype, double *param)
{
    const struct col *c = p->data;
    int lo = itype < jtype ? itype : jtype, hi = itype < jtype ? jtype : itype;
    const double *v = at(c, lo, hi);
    double d1 = v[C_D1], d2 = v[C_D2];
    int form = d1 == 0 && d2 == 0 ? COL_SS : d1 == 0 || d2 == 0 ? COL_SL : COL_LL;
    double sigma3 = v[C_SIGMA] * v[C_SIGMA] * v[C_SIGMA];
    double sigma6 = sigma3 * sigma3;
    memset(param, 0, COL_NPARAM * sizeof(double));
    param[COL_FORM] = form;
    param[COL_CUTSQ] = v[C_CUT] * v[C_CUT];
    param[COL_A12] = v[C_A12];
    param[COL_SIGMA3] = sigma3;
    param[COL_SIGMA6] = sigma6;
    if (form == COL_SL) {
        param[COL_A2] = d1 > 0 ? 0.5 * d1 : 0.5 * d2;
    } else if (form == COL_LL) {
        /* LAMMPS: a1 = d1/2, a2 = d2/2 for I J (I <= J), swapped for J I */
        param[COL_A1] = itype <= jtype ? 0.5 * d1 : 0.5 * d2;
        param[COL_A2] = itype <= jtype ? 0.5 * d2 : 0.5 * d1;
    }
    double eps = v[C_A12] / 144.0;
    param[COL_LJ1] = 48.0 * eps * sigma6 * sigma6;
    param[COL_LJ2] = 24.0 * eps * sigma6;
    param[COL_LJ3] = 4.0 * eps * sigma6 * sigma6;
    param[COL_LJ4] = 4.0 * eps * sigma6;
    if (p->shift && v[C_CUT] > 0)
        param[COL_OFFSET] = colloid_energy(param, v[C_CUT] * v[C_CUT]);
}

/* The energy of packed parameters at rsq, the kernel's arithmetic in
 * double (for the shift offset). */
static double colloid_energy(const double *p, double rsq)
{
    int form = (int)p[COL_FORM];
    if (form == COL_SS) {
        double r2inv = 1.0 / rsq, r6inv = r2inv * r2inv * r2inv;
        return r6inv * (r6inv * p[COL_LJ3] - p[COL_LJ4]) - p[COL_OFFSET];
    }
    if (form == COL_SL) {
        double c2 = p[COL_A2], k1 = c2 * c2, k2 = rsq, k4 = rsq * rsq, k3 = k1 - k2;
        k3 *= k3 * k3;
        double k6 = k3 * k3;
        double fR = p[COL_SIGMA3] * p[COL_A12] * c2 * k1 / k3;
        return 2.0 / 9.0 * fR *
                   (1.0 - (k1 * (k1 * (k1 / 3.0 + 3.0 * k2) + 4.2 * k4) + k2 * k4) *
                              p[COL_SIGMA6] / k6) -
               p[COL_OFFSET];
    }
    double r = sqrt(rsq), c1 = p[COL_A1], c2 = p[COL_A2];
    double K0 = c1 * c2, K1 = c1 + c2, K2 = c1 - c2;
    double K3 = K1 + r, K4 = K1 - r, K5 = K2 + r, K6 = K2 - r;
    double K7 = 1.0 / (K3 * K4), K8 = 1.0 / (K5 * K6);
    double K[4] = {K3, K4, K5, K6}, gg[4];
    for (int q = 0; q < 4; q++) {
        double x2 = K[q] * K[q], x3 = K[q] * x2, x4 = x2 * x2;
        gg[q] = 1.0 / (x3 * x4);
    }
    double h0 = ((K3 + 5.0 * K1) * K3 + 30.0 * K0) * gg[0];
    double h1 = ((K4 + 5.0 * K1) * K4 + 30.0 * K0) * gg[1];
    double h2 = ((K5 + 5.0 * K2) * K5 - 30.0 * K0) * gg[2];
    double h3 = ((K6 + 5.0 * K2) * K6 - 30.0 * K0) * gg[3];
    double a12 = p[COL_A12];
    double fR = a12 * p[COL_SIGMA6] / r / 37800.0;
    double e = fR * (h0 - h1 - h2 + h3);
    e += a12 / 6.0 * (2.0 * K0 * (K7 + K8) - log(K8 / K7)) - p[COL_OFFSET];
    return e;
}

static double type_cut(const struct pair *p, int itype, int jtype)
{
    const struct col *c = p->data; /* after init: every pair set or mixed */
    if (!c || itype > c->nt || jtype > c->nt)
        return 0.0;
    return at(c, itype, jtype)[C_CUT];
}

/* a potential: acts on every listed pair within its type pair's cut-off,
 * has an energy and no contact collision */
static void describe(const struct pair *p, struct pair_caps *c)
{
    pair_caps_source(c, "pair_colloid.cl");
    c->eval = "colloid_eval";
    c->sym_torque = 1; /* no torque */
    c->energy = "colloid_energy";
    c->beyond = 1;
    c->cut_of = p;
    c->type_cut = type_cut;
    c->nonfinite_cause = "pair colloid stops on overlapping particles (LAMMPS: \"Overlapping "
                         "small/large in pair colloid\", \"Overlapping large/large in pair "
                         "colloid\"): a point particle came within a colloid's radius or two "
                         "colloids touched, and the force there is undefined";
}

const struct pair_style pair_style_colloid = {
    .name = "colloid",
    .nparam = COL_NPARAM,
    .settings = settings,
    .pack = pack,
    .describe = describe,
    .coeff = coeff,
    .init = init,
    .destroy = destroy,
};
