/* pair_hybrid_overlay.c - `pair_style hybrid/overlay STYLE1 args STYLE2 args
 * ...`: several pair styles acting on every pair at once (LAMMPS
 * hybrid/overlay), e.g. a contact law plus cohesion.
 *
 * The terms are fused into ONE neighbor loop: the program is built with
 * PAIR_EVAL=hybrid_overlay_eval (kernels/pair_hybrid_overlay.cl) and
 * PAIR_TERMS / PAIR_TERMk* options naming each term's evaluator, its offset in
 * the packed parameters, whether it is a contact law (called only while the
 * bodies touch) and whether it owns the contact history. Each type pair's
 * parameter block is the terms' own packed blocks one after another.
 *
 * `pair_coeff I J STYLE args` routes to term STYLE (its own coefficient
 * syntax, LAMMPS type ranges). A term without per-type coefficients applies
 * to every type pair, so at run each pair I <= J must have been named for
 * it (in one `pair_coeff * * STYLE` or several partial ones).
 * Every term needs its pair_coeff before `run`. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "pair.h"

struct hybrid {
    int n;
    struct pair term[PAIR_MAXTERMS];
    int off[PAIR_MAXTERMS];     /* parameter offset of each term */
};

int pair_hybrid_terms(const struct pair *p, const struct pair **terms)
{
    const struct hybrid *h = p->data;
    if (!h)
        return 0;
    for (int k = 0; k < h->n; k++)
        terms[k] = &h->term[k];
    return h->n;
}

static void destroy(struct pair *p)
{
    struct hybrid *h = p->data;
    if (h)
        for (int k = 0; k < h->n; k++)
            pair_release(&h->term[k]);
    free(h);
    p->data = NULL;
}

/* Split `A args B args ...` at the registered style names. */
static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "hybrid/overlay expects one or more sub-styles with their "
                    "arguments, e.g. hybrid/overlay linear/restitution 1e5 0.8 0.1 cohesion 100");
    /* parsed on the stack (term settings allocate nothing), kept on success:
     * an argument error leaks nothing */
    struct hybrid loc, *h = &loc;
    memset(&loc, 0, sizeof loc);
    int nhist = 0, off = 0;
    int i = 0;
    while (i < argc) {
        const struct pair_style *st = pair_style_find(argv[i]);
        if (!st || st->source_n || !st->eval)
            gr_error(g, "hybrid/overlay: '%.64s' is not a pair style that can be "
                        "composed (argument %d)", argv[i], i + 1);
        int e = i + 1;
        while (e < argc && !pair_style_find(argv[e]))
            e++;
        for (int k = 0; k < h->n; k++)
            if (h->term[k].style == st)
                gr_error(g, "hybrid/overlay: sub-style %s given twice", st->name);
        if (h->n == PAIR_MAXTERMS)
            gr_error(g, "hybrid/overlay: at most %d sub-styles", PAIR_MAXTERMS);
        if (st->nparam > PAIR_MAXPARAM)
            gr_error(g, "hybrid/overlay: sub-style %s has too many parameters",
                     st->name);
        pair_create(g, &h->term[h->n], st, e - i - 1, argv + i + 1);
        h->off[h->n] = off;
        off += st->nparam;
        nhist += st->history;
        h->n++;
        i = e;
    }
    if (nhist > 1)
        gr_error(g, "hybrid/overlay: at most one sub-style may keep contact history");
    p->data = gr_calloc(g, 1, sizeof loc);
    memcpy(p->data, &loc, sizeof loc);
}

/* pair_coeff I J STYLE args */
static void coeff(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi,
                  int argc, char **argv)
{
    struct hybrid *h = p->data;
    char known[256] = "";
    for (int k = 0; k < h->n; k++) {
        strncat(known, k ? ", " : "", sizeof known - strlen(known) - 1);
        strncat(known, h->term[k].style->name, sizeof known - strlen(known) - 1);
    }
    if (argc < 1)
        gr_error(g, "pair style hybrid/overlay expects a sub-style name after the types (one "
                    "of: %s)", known);
    struct pair *t = NULL;
    for (int k = 0; k < h->n; k++)
        if (!strcmp(h->term[k].style->name, argv[0]))
            t = &h->term[k];
    if (!t)
        gr_error(g, "'%.64s' is not a sub-style of this pair_style hybrid/overlay (one of: %s)",
                 argv[0], known);
    if (t->style->coeff) {
        t->style->coeff(g, t, ilo, ihi, jlo, jhi, argc - 1, argv + 1);
    } else {
        if (argc > 1)
            gr_error(g, "sub-style %s takes no coefficients after its name, got '%.64s'",
                     t->style->name, argv[1]);
        /* the term applies to every type pair (the fused loop has no
         * per-pair switch): record which pairs were named, check at run */
        int nt = g->atoms.ntypes;
        if (!t->setflag || t->setflag_nt != nt) {
            free(t->setflag);
            t->setflag = gr_calloc(g, (size_t)nt * nt, 1);
            t->setflag_nt = nt;
        }
        for (int i = ilo; i <= ihi; i++)
            for (int j = jlo > i ? jlo : i; j <= jhi; j++)
                t->setflag[(size_t)(i - 1) * nt + (j - 1)] =
                    t->setflag[(size_t)(j - 1) * nt + (i - 1)] = 1;
    }
    t->coeff_set = 1;
    p->coeff_set = 1;
}

static void init(struct gravel *g, struct pair *p)
{
    struct hybrid *h = p->data;
    if (!h)
        gr_error(g, "pair_style hybrid/overlay has no sub-styles (restart files do not keep "
                    "them: re-issue pair_style and pair_coeff after read_restart)");
    for (int k = 0; k < h->n; k++) {
        struct pair *t = &h->term[k];
        if (!t->coeff_set)
            gr_error(g, "pair_coeff is missing for hybrid/overlay sub-style %s (e.g. "
                        "pair_coeff * * %s ...)", t->style->name, t->style->name);
        if (!t->style->coeff && t->setflag) {
            int nt = t->setflag_nt;
            for (int i = 1; i <= nt; i++)
                for (int j = i; j <= nt; j++)
                    if (!t->setflag[(size_t)(i - 1) * nt + (j - 1)])
                        gr_error(g, "hybrid/overlay: no pair_coeff %d %d %s; gravel applies "
                                    "each overlaid sub-style to every type pair, so every "
                                    "pair needs it (e.g. pair_coeff * * %s)",
                                 i, j, t->style->name, t->style->name);
        }
        if (t->style->init)
            t->style->init(g, t);
    }
}

static void pack(const struct pair *p, int itype, int jtype, double *param)
{
    const struct hybrid *h = p->data;
    for (int k = 0; k < h->n; k++)
        h->term[k].style->pack(&h->term[k], itype, jtype, param + h->off[k]);
}

/* The first term with a collision time (the contact law). */
static double collision_time(const struct pair *p, double m, double r, double vn)
{
    const struct hybrid *h = p->data;
    for (int k = 0; k < h->n; k++)
        if (h->term[k].style->collision_time)
            return h->term[k].style->collision_time(&h->term[k], m, r, vn);
    return INFINITY;
}

static const char *source_n(const struct pair *p, int k)
{
    const struct hybrid *h = p->data;
    if (k < h->n)
        return h->term[k].style->source;
    return k == h->n ? "pair_hybrid_overlay.cl" : NULL;
}

static int defines(const struct pair *p, char *buf, size_t len)
{
    const struct hybrid *h = p->data;
    size_t n = (size_t)snprintf(buf, len, " -D PAIR_EVAL=hybrid_overlay_eval -D PAIR_TERMS=%d",
                                h->n);
    for (int k = 0; k < h->n && n < len; k++) {
        const struct pair_style *st = h->term[k].style;
        n += (size_t)snprintf(buf + n, len - n,
                              " -D PAIR_TERM%d=%s -D PAIR_TERM%d_OFF=%d -D PAIR_TERM%d_CONTACT=%d"
                              " -D PAIR_TERM%d_HIST=%d",
                              k, st->eval, k, h->off[k], k, !st->beyond_contact, k,
                              st->history);
    }
    if (n < len)
        n += (size_t)pair_cohesion_defines(p, buf + n, len - n);
    return (int)n;
}

const struct pair_style pair_style_hybrid_overlay = {
    .name = "hybrid/overlay",
    .source = "pair_hybrid_overlay.cl",
    .eval = "hybrid_overlay_eval",
    .history = 0,
    .rotation = 0,
    .nparam = PAIR_MAXTERMS * PAIR_MAXPARAM,
    .settings = settings,
    .pack = pack,
    .collision_time = collision_time,
    .coeff = coeff,
    .init = init,
    .source_n = source_n,
    .defines = defines,
    .destroy = destroy,
};
