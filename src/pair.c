/* pair.c - the pair registry (PAIR rows of styles/styles.def) and the
 * `pair_style` and `pair_coeff` commands. */
#include "pair.h"

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

void pair_free(struct gravel *g)
{
    if (g->styles.pair)
        pair_release(g->styles.pair);
    free(g->styles.pair);
    g->styles.pair = NULL;
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
    /* LAMMPS: redefining the same style keeps the coefficients (per-type
     * tables in data included; hybrid/overlay starts afresh) */
    if (g->styles.pair && g->styles.pair->style == st && !st->source_n) {
        tmp.coeff_set = g->styles.pair->coeff_set;
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

/* pair_coeff * *  (granular styles take no per-type coefficients) */
void cmd_pair_coeff(struct gravel *g, int argc, char **argv)
{
    if (!g->styles.pair)
        gr_error(g, "pair_coeff command before pair_style is defined");
    int ilo, ihi, jlo, jhi;
    arg_type_range(g, argv[0], g->atoms.ntypes, &ilo, &ihi);
    arg_type_range(g, argv[1], g->atoms.ntypes, &jlo, &jhi);
    if (g->styles.pair->style->coeff) {
        g->styles.pair->style->coeff(g, g->styles.pair, ilo, ihi, jlo, jhi, argc - 2, argv + 2);
        return;
    }
    if (argc > 2)
        gr_error(g, "pair style %s takes no coefficients after the two types, got '%.64s'",
                 g->styles.pair->style->name, argv[2]);
    if (ilo != 1 || jlo != 1 || ihi != g->atoms.ntypes || jhi != g->atoms.ntypes)
        gr_error(g, "pair style %s requires pair_coeff * * (all type pairs share the "
                    "pair_style coefficients)", g->styles.pair->style->name);
    g->styles.pair->coeff_set = 1;
}

/* ---- composition helpers: a plain style is one term; hybrid/overlay
 * (styles/pair_hybrid_overlay.c) answers through its source_n/defines hooks
 * and exposes its terms through pair_hybrid_terms(). ---- */

static int terms_of(const struct pair *p, const struct pair **t)
{
    if (p->style->source_n)
        return pair_hybrid_terms(p, t);
    t[0] = p;
    return 1;
}

int pair_needs_rotation(const struct pair *p)
{
    const struct pair *t[PAIR_MAXTERMS];
    int n = terms_of(p, t), r = 0;
    for (int k = 0; k < n; k++)
        r |= t[k]->style->rotation;
    return r;
}

int pair_needs_history(const struct pair *p)
{
    const struct pair *t[PAIR_MAXTERMS];
    int n = terms_of(p, t), r = 0;
    for (int k = 0; k < n; k++)
        r |= t[k]->style->history;
    return r;
}

int pair_has_cohesion(const struct pair *p)
{
    const struct pair *t[PAIR_MAXTERMS];
    int n = terms_of(p, t), r = 0;
    for (int k = 0; k < n; k++)
        r |= t[k]->style->beyond_contact;
    return r;
}

double pair_reach(const struct gravel *g, double radsum)
{
    const struct pair *p = g->styles.pair;
    double reach = radsum;
    if (!p)
        return reach;
    const struct pair *t[PAIR_MAXTERMS];
    int n = terms_of(p, t);
    for (int k = 0; k < n; k++)
        if (t[k]->style->beyond_contact && t[k]->style->reach) {
            double r = t[k]->style->reach(t[k], radsum);
            if (r > reach)
                reach = r;
        }
    return reach;
}

const char *pair_source(const struct pair *p, int k)
{
    if (p->style->source_n)
        return p->style->source_n(p, k);
    return k == 0 ? p->style->source : NULL;
}

int pair_cohesion_defines(const struct pair *p, char *buf, size_t len)
{
    const struct pair *t[PAIR_MAXTERMS];
    int n = terms_of(p, t);
    double a = 0, b = 0;
    int any = 0;
    for (int k = 0; k < n; k++)
        if (t[k]->style->beyond_contact && t[k]->style->reach) {
            double a0 = t[k]->style->reach(t[k], 0.0);
            double b0 = t[k]->style->reach(t[k], 1.0) - a0;
            a = a0 > a ? a0 : a;
            b = b0 > b ? b0 : b;
            any = 1;
        }
    if (!any)
        return 0;
    return snprintf(buf, len, " -D HAS_COHESION -D COH_REACH_A=%.17g -D COH_REACH_B=%.17g", a,
                    b);
}

int pair_defines(const struct pair *p, char *buf, size_t len)
{
    if (p->style->defines)
        return p->style->defines(p, buf, len);
    int n = snprintf(buf, len, " -D PAIR_EVAL=%s", p->style->eval);
    if (n >= 0 && (size_t)n < len)
        n += pair_cohesion_defines(p, buf + n, len - (size_t)n);
    return n;
}

void pair_prepare(struct gravel *g)
{
    struct pair *p = g->styles.pair;
    if (p && p->style->init)
        p->style->init(g, p);
}
