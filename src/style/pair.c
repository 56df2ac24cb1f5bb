/* pair.c - the pair registry (PAIR rows of styles/styles.def) and the
 * `pair_style` and `pair_coeff` commands. */
#include "pair.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"

#define FIX(k, i)
#define COMPUTE(k, i)
#define DUMP(k, i)
#define REGION(k, i)
#define PAIR(k, i) extern const struct pair_style pair_style_##i;
#include "styles.def"
#undef PAIR
#define PAIR(k, i) &pair_style_##i,
static const struct pair_style *const pair_styles[] = {
#include "styles.def"
    NULL};
#undef PAIR
#undef FIX
#undef COMPUTE
#undef DUMP
#undef REGION

static void surf_free(struct gravel *g)
{
    if (g->styles.surf)
        pair_release(g->styles.surf);
    free(g->styles.surf);
    g->styles.surf = NULL;
}

void pair_free(struct gravel *g)
{
    if (g->styles.pair)
        pair_release(g->styles.pair);
    free(g->styles.pair);
    g->styles.pair = NULL;
    surf_free(g);
    free(g->styles.pair_cmds);
    g->styles.pair_cmds = NULL;
}

/* Append `name argv...` as one line to the recorded pair commands (keep:
 * 0 = start afresh). */
static void record(struct gravel *g, const char *name, int argc, char **argv, int keep)
{
    size_t old = keep && g->styles.pair_cmds ? strlen(g->styles.pair_cmds) : 0, add = strlen(name) + 2;
    for (int i = 0; i < argc; i++)
        add += strlen(argv[i]) + 1;
    char *s = gr_malloc(g, old + add + 1);
    if (old)
        memcpy(s, g->styles.pair_cmds, old);
    char *q = s + old;
    q += sprintf(q, "%s", name);
    for (int i = 0; i < argc; i++)
        q += sprintf(q, " %s", argv[i]);
    sprintf(q, "\n");
    free(g->styles.pair_cmds);
    g->styles.pair_cmds = s;
}

/* The style line first, then the coefficient lines kept with it. */
static void record_style(struct gravel *g, int argc, char **argv, int keep_coeffs)
{
    char *coeffs = NULL;
    if (keep_coeffs && g->styles.pair_cmds) {
        char *nl = strchr(g->styles.pair_cmds, '\n');
        if (nl && nl[1])
            coeffs = strdup(nl + 1);
    }
    record(g, "pair_style", argc, argv, 0);
    if (coeffs) {
        size_t a = strlen(g->styles.pair_cmds), b = strlen(coeffs);
        char *s = gr_malloc(g, a + b + 1);
        memcpy(s, g->styles.pair_cmds, a);
        memcpy(s + a, coeffs, b + 1);
        free(g->styles.pair_cmds);
        free(coeffs);
        g->styles.pair_cmds = s;
    }
}

const struct pair_style *pair_style_find(const char *name)
{
    for (int i = 0; pair_styles[i]; i++)
        if (!strcmp(pair_styles[i]->name, name))
            return pair_styles[i];
    return NULL;
}

void pair_release(struct pair *p)
{
    free(p->setflag);
    p->setflag = NULL;
    p->setflag_nt = 0;
    free(p->none);
    p->none = NULL;
    p->none_nt = 0;
    if (p->data && p->style && p->style->destroy)
        p->style->destroy(p);
    else
        free(p->data);
    p->data = NULL;
}

void pair_create(struct gravel *g, struct pair *p, const struct pair_style *st, int argc,
                 char **argv)
{
    memset(p, 0, sizeof *p);
    p->style = st;
    st->settings(g, p, argc, argv);
}

/* pair_style hybrid ... SURF args ...: the surface sub-style (style->surface,
 * LAMMPS 4 Jul 2026's surf/granular) goes to g->styles.surf; out gets the
 * rest of the line: `hybrid` and the particle laws, or the one law alone
 * (out[0] its name) when only one is left. Returns the words in out, 0
 * when the line names no surface sub-style. */
static int split_surface(struct gravel *g, const struct pair_style *hy, int argc, char **argv,
                         char **out)
{
    int n = 0, nlaw = 0, law = -1, surf = -1, send = -1;
    for (int i = 1; i < argc; i++) {
        const struct pair_style *t = pair_style_find(argv[i]);
        if (!t)
            continue;
        if (t->surface) {
            if (surf >= 0)
                gr_error(g, "pair_style %s: one surface sub-style at most (%s given twice)",
                         hy->name, t->name);
            surf = i;
            for (send = i + 1; send < argc && !pair_style_find(argv[send]); send++)
                ;
        } else {
            nlaw++;
            law = law < 0 ? i : law;
        }
    }
    if (surf < 0)
        return 0;
    if (strcmp(hy->name, "hybrid"))
        gr_error(g, "pair_style %s: %s is a sub-style of pair_style hybrid", hy->name,
                 argv[surf]);
    if (!nlaw)
        gr_error(g, "pair_style hybrid %s needs a particle law beside it (LAMMPS: pair_style "
                    "hybrid granular %s)", argv[surf], argv[surf]);
    surf_free(g);
    struct pair *sp = g->styles.surf = gr_calloc(g, 1, sizeof *sp); /* freed with g on error */
    pair_create(g, sp, pair_style_find(argv[surf]), send - surf - 1, argv + surf + 1);
    if (nlaw > 1)
        out[n++] = argv[0];
    for (int i = nlaw > 1 ? 1 : law; i < argc; i++)
        if (i < surf || i >= send)
            out[n++] = argv[i];
    return n;
}

/* pair_style style args... */
void cmd_pair_style(struct gravel *g, int argc, char **argv)
{
    const struct pair_style *st = pair_style_find(argv[0]);
    if (!st && !strcmp(argv[0], "none")) {
        if (argc > 1)
            gr_error(g, "pair_style none takes no arguments");
        pair_free(g);
        return;
    }
    if (st && st->surface)
        gr_error(g, "pair_style %s acts only as a sub-style of pair_style hybrid (LAMMPS: "
                    "pair_style hybrid granular %s)", st->name, st->name);
    int one = 0, split = 0, argc0 = argc;
    char **argv0 = argv, *fa[256];
    if (st && st->terms) {
        if (argc > (int)(sizeof fa / sizeof *fa))
            gr_error(g, "pair_style %s: more than %d words", st->name,
                     (int)(sizeof fa / sizeof *fa));
        split = split_surface(g, st, argc, argv, fa);
        if (split) {
            argc = split;
            argv = fa;
            st = pair_style_find(argv[0]);
            one = !st->terms;
        }
    }
    if (!split)
        surf_free(g); /* a pair_style without surf/granular drops its models */
    if (!st) {
        char known[512] = "";
        for (int i = 0; pair_styles[i]; i++) {
            strncat(known, i ? ", " : "", sizeof known - strlen(known) - 1);
            strncat(known, pair_styles[i]->name, sizeof known - strlen(known) - 1);
        }
        gr_error(g, "unknown pair style '%.64s' (known: %s, none)", argv[0], known);
    }
    struct pair tmp;
    pair_create(g, &tmp, st, argc - 1, argv + 1);
    tmp.one_of_hybrid = one;
    record_style(g, argc0, argv0, g->styles.pair && g->styles.pair->style == st && !st->terms);
    /* LAMMPS: redefining the same style keeps the coefficients (per-type
     * tables in data included; hybrid/overlay starts afresh) */
    if (g->styles.pair && g->styles.pair->style == st && !st->terms) {
        tmp.coeff_set = g->styles.pair->coeff_set;
        tmp.setflag = g->styles.pair->setflag;
        tmp.setflag_nt = g->styles.pair->setflag_nt;
        g->styles.pair->setflag = NULL;
        if (!tmp.data) {
            tmp.data = g->styles.pair->data;
            g->styles.pair->data = NULL;
        }
    }
    if (g->styles.pair)
        pair_release(g->styles.pair);
    if (!g->styles.pair)
        g->styles.pair = gr_calloc(g, 1, sizeof *g->styles.pair);
    *g->styles.pair = tmp;
}

int pair_coeff_each(int ilo, int ihi, int jlo, int jhi, void (*visit)(int, int, void *),
                    void *ctx)
{
    int n = 0;
    for (int i = ilo; i <= ihi; i++)
        for (int j = jlo > i ? jlo : i; j <= jhi; j++) {
            if (visit)
                visit(i, j, ctx);
            n++;
        }
    return n;
}

static int plain_int(const char *s)
{
    if (!*s)
        return 0;
    for (; *s; s++)
        if (*s < '0' || *s > '9')
            return 0;
    return 1;
}

struct flagctx {
    unsigned char *f;
    int nt;
};

static void mark_pair(int i, int j, void *vctx)
{
    struct flagctx *c = vctx;
    c->f[(size_t)(i - 1) * c->nt + (j - 1)] = 1;
    c->f[(size_t)(j - 1) * c->nt + (i - 1)] = 1;
}

/* set the pairs of the ranges (and mirrors) in the nt x nt table *tab of
 * *tnt types, (re)made for the box's types */
static void mark_pairs(struct gravel *g, unsigned char **tab, int *tnt, int ilo, int ihi,
                       int jlo, int jhi)
{
    int nt = g->atoms.ntypes;
    if (!*tab || *tnt != nt) {
        free(*tab);
        *tab = gr_calloc(g, (size_t)nt * nt, 1);
        *tnt = nt;
    }
    struct flagctx c = {*tab, nt};
    pair_coeff_each(ilo, ihi, jlo, jhi, mark_pair, &c);
}

/* pair_coeff I J [args]: LAMMPS's type ranges (N, *, N*, *N, M*N). As in
 * LAMMPS, two plain numbers with J < I are swapped; otherwise the pairs set
 * are I in the first range and J >= I in the second (`pair_coeff * 2` with 3
 * types sets 1-1 1-2 2-2), and ranges that give no such pair are an error. */
void cmd_pair_coeff(struct gravel *g, int argc, char **argv)
{
    if (!g->styles.pair)
        gr_error(g, "pair_coeff command before pair_style is defined");
    struct pair *p = g->styles.pair;
    if (g->styles.pair_cmds)
        record(g, "pair_coeff", argc, argv, 1);
    if (plain_int(argv[0]) && plain_int(argv[1]) && atoi(argv[1]) < atoi(argv[0])) {
        char *t = argv[0];
        argv[0] = argv[1];
        argv[1] = t;
    }
    int nt = g->atoms.ntypes, ilo, ihi, jlo, jhi;
    arg_type_range(g, argv[0], nt, &ilo, &ihi);
    arg_type_range(g, argv[1], nt, &jlo, &jhi);
    if (pair_coeff_each(ilo, ihi, jlo, jhi, NULL, NULL) == 0)
        gr_error(g, "pair_coeff %s %s names no type pair I <= J (LAMMPS sets J >= I only; "
                    "write the lower types first)", argv[0], argv[1]);
    struct pair *sp = g->styles.surf;
    if (sp && argc > 2 && !strcmp(argv[2], sp->style->name)) {
        sp->style->coeff(g, sp, ilo, ihi, jlo, jhi, argc - 3, argv + 3);
        sp->coeff_set = 1;
        return;
    }
    if (p->one_of_hybrid) { /* pair_coeff I J LAW args | none */
        if (argc > 2 && !strcmp(argv[2], "none")) {
            if (argc > 3)
                gr_error(g, "pair_coeff ... none takes no further arguments, got '%.64s'",
                         argv[3]);
            mark_pairs(g, &p->none, &p->none_nt, ilo, ihi, jlo, jhi);
            return;
        }
        if (argc < 3 || strcmp(argv[2], p->style->name))
            gr_error(g, "pair_coeff of this pair_style hybrid expects a sub-style after the "
                        "types (%s, %s or none), got '%.64s'", p->style->name,
                     sp ? sp->style->name : "", argc > 2 ? argv[2] : "");
        argv[2] = argv[1]; /* drop the sub-style's name */
        argv[1] = argv[0];
        argv++;
        argc--;
    }
    if (p->style->coeff) {
        p->style->coeff(g, p, ilo, ihi, jlo, jhi, argc - 2, argv + 2);
        return;
    }
    if (argc > 2)
        gr_error(g, "pair style %s takes no coefficients after the two types, got '%.64s' "
                    "(its parameters are the pair_style arguments)",
                 p->style->name, argv[2]);
    mark_pairs(g, &p->setflag, &p->setflag_nt, ilo, ihi, jlo, jhi);
    p->coeff_set = 1;
}

/* the style has a potential energy (pair_modify shift applies) */
static int has_energy(const struct pair *p)
{
    struct pair_caps c;
    pair_describe(p, &c);
    return c.energy != NULL;
}

/* pair_modify on one style (a plain style or one hybrid/overlay term). */
static void modify_one(struct gravel *g, struct pair *p, int argc, char **argv)
{
    /* styles whose unset cross pairs are mixed from the diagonal */
    int mixes = p->style->coeff != NULL && p->style->init != NULL;
    for (int i = 0; i < argc; i++) {
        const char *k = argv[i];
        if (!strcmp(k, "mix")) {
            arg_need(g, argc, i, 1, k);
            const char *v = argv[++i];
            int arith = !strcmp(v, "arithmetic");
            if (!arith && strcmp(v, "geometric") && strcmp(v, "sixthpower"))
                gr_error(g, "mix must be geometric, arithmetic or sixthpower, got '%.32s'", v);
            if (!mixes) {
                gr_warn(g, "pair style %s has no per-type coefficients to mix: mix %s ignored",
                        p->style->name, v);
            } else if (!arith && strcmp(v, "geometric")) {
                gr_error(g, "pair style %s mixes a stiffness: mix geometric or arithmetic, "
                            "not %s", p->style->name, v);
            } else {
                p->mix_arithmetic = arith;
            }
        } else if (!strcmp(k, "shift") && has_energy(p)) {
            arg_need(g, argc, i, 1, k);
            p->shift = arg_yesno(g, argv[++i], k);
        } else if (!strcmp(k, "shift") || !strcmp(k, "tail")) {
            arg_need(g, argc, i, 1, k);
            if (arg_yesno(g, argv[++i], k))
                gr_warn(g, "%s yes ignored: contact forces end at contact, there is no "
                           "energy shift or long-range tail", k);
        } else if (!strcmp(k, "compute")) {
            arg_need(g, argc, i, 1, k);
            if (!arg_yesno(g, argv[++i], k))
                gr_error(g, "compute no is not supported (use pair_style none)");
        } else if (!strcmp(k, "table") || !strcmp(k, "table/disp") ||
                   !strcmp(k, "tabinner") || !strcmp(k, "tabinner/disp")) {
            arg_need(g, argc, i, 1, k);
            i++;
            gr_warn(g, "%s ignored: gravel's pair styles are not tabulated", k);
        } else if (!strcmp(k, "nofdotr")) {
            gr_warn(g, "nofdotr ignored");
        } else if (!strcmp(k, "special")) {
            arg_need(g, argc, i, 4, k);
            i += 4;
            gr_warn(g, "special ignored: atom_style sphere has no bonds");
        } else {
            gr_error(g, "unknown keyword '%.64s' (expected pair, mix, shift, tail, compute, "
                        "table, tabinner, nofdotr or special)", k);
        }
    }
}

/* pair_modify [pair SUBSTYLE [N]] keyword value ... (LAMMPS pair_modify).
 * mix applies where the style mixes unset cross pairs (cohesion's kc);
 * keywords that have no meaning for contact forces are accepted with a
 * warning when they ask for something (shift yes, tail yes, tables). For
 * hybrid/overlay, `pair SUBSTYLE` picks one term, otherwise all. */
void cmd_pair_modify(struct gravel *g, int argc, char **argv)
{
    struct pair *p = g->styles.pair;
    if (!p)
        gr_error(g, "pair_modify command before pair_style is defined");
    const struct pair *t[PAIR_MAXTERMS];
    int nt = 1;
    t[0] = p;
    if (p->style->terms)
        nt = p->style->terms(p, t);
    int start = 0;
    if (!strcmp(argv[0], "pair")) {
        arg_need(g, argc, 0, 1, "pair");
        const struct pair *pick = NULL;
        for (int k = 0; k < nt; k++)
            if (!strcmp(t[k]->style->name, argv[1]))
                pick = t[k];
        if (!pick || !p->style->terms)
            gr_error(g, "pair %s: not a sub-style of the current pair style %s", argv[1],
                     p->style->name);
        t[0] = pick;
        nt = 1;
        start = 2;
        if (start < argc && argv[start][0] >= '1' && argv[start][0] <= '9')
            start++; /* sub-style instance number: each style appears once */
    }
    if (start >= argc)
        gr_error(g, "pair_modify needs at least one keyword");
    for (int k = 0; k < nt; k++)
        modify_one(g, (struct pair *)t[k], argc - start, argv + start);
}

/* The first type I with no pair_coeff I I in a flag table, or 0. */
int pair_first_unset_diag(const unsigned char *flag, int nt)
{
    for (int i = 1; i <= nt; i++)
        if (!flag[(size_t)(i - 1) * nt + (i - 1)])
            return i;
    return 0;
}

/* ---- the capabilities record ---- */

void pair_caps_source(struct pair_caps *c, const char *file)
{
    for (int k = 0; k < c->nsources; k++)
        if (!strcmp(c->sources[k], file))
            return;
    if (c->nsources < PAIR_MAXTERMS + 2)
        c->sources[c->nsources++] = file;
}

void pair_caps_define(struct pair_caps *c, const char *name, const char *fmt, ...)
{
    if (c->ndef >= PAIR_MAXDEF)
        return; /* pair_setup reports the overflow */
    struct pair_def *d = &c->def[c->ndef++];
    snprintf(d->name, sizeof d->name, "%s", name);
    d->value[0] = 0;
    if (fmt) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(d->value, sizeof d->value, fmt, ap);
        va_end(ap);
    }
}

void pair_caps_reach(struct pair_caps *c, double a, double b)
{
    if (c->nreach < PAIR_MAXTERMS) {
        c->reach_a[c->nreach] = a;
        c->reach_b[c->nreach] = b;
        c->nreach++;
    }
}

void pair_describe(const struct pair *p, struct pair_caps *c)
{
    memset(c, 0, sizeof *c);
    c->nparam = p->style->nparam;
    c->hist_n = 3;
    p->style->describe(p, c);
}

int pair_type_absent(const struct pair *p, int t)
{
    int nt = p->none_nt;
    return p->one_of_hybrid && p->none && t >= 1 && t <= nt &&
           p->none[(size_t)(t - 1) * nt + (t - 1)];
}

/* one law of pair_style hybrid: `none` only for absent types (I I none),
 * which no atom may have */
static void check_absent(struct gravel *g, struct pair *p)
{
    int nt = p->none_nt;
    for (int i = 1; i <= nt; i++)
        for (int j = i + 1; j <= nt; j++)
            if (p->none[(size_t)(i - 1) * nt + (j - 1)] && !pair_type_absent(p, i) &&
                !pair_type_absent(p, j))
                gr_error(g, "pair_coeff %d %d none: gravel's pair_style hybrid with one "
                            "particle law switches off only types no particle has (pair_coeff "
                            "%d %d none, %d %d none: fix surface/local's surface types)",
                         i, j, i, i, j, j);
    for (int k = 0; k < g->atoms.n; k++)
        if (pair_type_absent(p, g->atoms.type[k]))
            gr_error(g, "atom %lld has type %d, which pair_coeff %d %d none leaves without a "
                        "particle law (gravel: such types are fix surface/local's surfaces, "
                        "not particles)", (long long)g->atoms.tag[k], g->atoms.type[k],
                     g->atoms.type[k], g->atoms.type[k]);
}

void pair_setup(struct gravel *g)
{
    struct pair *p = g->styles.pair;
    if (!p)
        return;
    if (p->one_of_hybrid)
        check_absent(g, p);
    /* LAMMPS Pair::init: every I I must have been named by a pair_coeff
     * (cross pairs of these styles share the pair_style parameters) */
    if (!p->style->coeff && p->setflag) {
        int nt = g->atoms.ntypes, i = 0;
        if (p->setflag_nt != nt)
            gr_error(g, "pair style %s: pair_coeff was given for %d atom types, the box has "
                        "%d: re-issue pair_coeff", p->style->name, p->setflag_nt, nt);
        for (int t = 1; t <= nt && !i; t++)
            if (!p->setflag[(size_t)(t - 1) * nt + (t - 1)] && !pair_type_absent(p, t))
                i = t;
        if (i)
            gr_error(g, "all pair coeffs are not set: no pair_coeff for types %d %d of pair "
                        "style %s (e.g. pair_coeff * *)", i, i, p->style->name);
    }
    if (p->style->init)
        p->style->init(g, p);
    pair_describe(p, &p->caps);
    if (p->caps.ndef >= PAIR_MAXDEF)
        gr_error(g, "pair style %s: too many build options", p->style->name);
    if (p->caps.hist_n < 0)
        gr_error(g, "pair style %s: every composed term must keep a 3-REAL contact history",
                 p->style->name);
}

double *pair_pack(struct gravel *g, int *ntypes)
{
    const struct pair *p = g->styles.pair;
    if (!p->coeff_set)
        gr_error(g, "all pair coeffs are not set (pair_coeff * * is missing for pair style %s)",
                 p->style->name);
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1, np = p->caps.nparam;
    double *par = gr_calloc(g, (size_t)nt * nt * np, sizeof(double));
    for (int i = 1; i <= nt; i++)
        for (int j = 1; j <= nt; j++)
            p->style->pack(p, i, j, par + ((size_t)(i - 1) * nt + (j - 1)) * np);
    *ntypes = nt;
    return par;
}

double pair_reach(const struct gravel *g, double radsum)
{
    const struct pair *p = g->styles.pair;
    double reach = radsum;
    if (!p)
        return reach;
    for (int k = 0; k < p->caps.nreach; k++) {
        double r = p->caps.reach_a[k] + p->caps.reach_b[k] * radsum;
        if (r > reach)
            reach = r;
    }
    return reach;
}

double pair_type_cut_max(const struct gravel *g, unsigned imask, unsigned jmask)
{
    const struct pair *p = g->styles.pair;
    double m = 0.0;
    if (!p || !p->caps.type_cut)
        return m;
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    for (int a = 1; a <= nt; a++)
        for (int b = 1; b <= nt; b++) {
            if (a <= 32 && !(imask >> (a - 1) & 1u))
                continue;
            if (b <= 32 && !(jmask >> (b - 1) & 1u))
                continue;
            double c = p->caps.type_cut(p->caps.cut_of, a, b);
            m = c > m ? c : m;
        }
    return m;
}

double pair_collision_time(const struct pair_caps *c, double m, double r, double vn)
{
    return c->collision_time ? c->collision_time(c->tcol_of, m, r, vn) : NAN;
}
