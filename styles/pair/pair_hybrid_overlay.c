/* pair_hybrid_overlay.c - `pair_style hybrid/overlay STYLE1 args STYLE2 args
 * ...`: several pair styles acting on every pair at once (LAMMPS
 * hybrid/overlay), e.g. a contact law plus cohesion; and `pair_style hybrid
 * STYLE1 args ...`: each type pair acts through the one sub-style its
 * pair_coeff names (or none), LAMMPS hybrid.
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
 * Every term needs its pair_coeff before `run`.
 *
 * hybrid: the same fused loop with PAIR_EVAL=hybrid_eval; each type pair's
 * block starts with the index of its sub-style (-1: none), the terms' blocks
 * follow. `pair_coeff I J STYLE args` maps the pairs to STYLE (a later
 * pair_coeff re-maps them), `pair_coeff I J none` to no interaction. A cross
 * pair I J never named takes the sub-style of I I and J J when they have the
 * same one (that style mixes its own coefficients), else it is an error, as
 * LAMMPS's "All pair coeffs are not set". Several sub-styles may keep contact
 * history (a pair uses one). A sub-style with per-type coefficients of its
 * own (cohesion) checks them for every type pair, mapped to it or not. */
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
    int pick;                   /* 1: hybrid (one term per type pair) */
    int nt;                     /* hybrid: map[(i-1) nt + j-1] = term, -1 none, */
    signed char *map;           /* -2 not named */
};

#define MAP_NONE (-1)
#define MAP_UNSET (-2)

static int terms(const struct pair *p, const struct pair **terms)
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
    if (h) {
        for (int k = 0; k < h->n; k++)
            pair_release(&h->term[k]);
        free(h->map);
    }
    free(h);
    p->data = NULL;
}

/* A style with a 3-vector evaluator (not pair granular's history row): its
 * record before any coefficient says so. */
static int law_evaluator(const struct pair_style *st)
{
    struct pair tmp;
    memset(&tmp, 0, sizeof tmp);
    tmp.style = st;
    struct pair_caps c;
    pair_describe(&tmp, &c);
    return c.eval != NULL;
}

/* Split `A args B args ...` at the registered style names. */
static void parse_terms(struct gravel *g, struct pair *p, int argc, char **argv, int pick)
{
    const char *me = pick ? "hybrid" : "hybrid/overlay";
    if (argc < 1)
        gr_error(g, "%s expects one or more sub-styles with their arguments, e.g. %s "
                    "gran/hooke 4000 NULL 100 NULL 0.5 1", me, me);
    /* parsed on the stack (term settings allocate nothing), kept on success:
     * an argument error leaks nothing */
    struct hybrid loc, *h = &loc;
    memset(&loc, 0, sizeof loc);
    loc.pick = pick;
    int nhist = 0, off = pick ? 1 : 0;
    int i = 0;
    while (i < argc) {
        const struct pair_style *st = pair_style_find(argv[i]);
        if (!st || st->terms || !law_evaluator(st))
            gr_error(g, "%s: '%.64s' is not a pair style that can be composed (argument %d)",
                     me, argv[i], i + 1);
        int e = i + 1;
        while (e < argc && !pair_style_find(argv[e]))
            e++;
        for (int k = 0; k < h->n; k++)
            if (h->term[k].style == st)
                gr_error(g, "%s: sub-style %s given twice (gravel keeps one instance of "
                            "each)", me, st->name);
        if (h->n == PAIR_MAXTERMS)
            gr_error(g, "%s: at most %d sub-styles", me, PAIR_MAXTERMS);
        if (st->nparam > PAIR_MAXPARAM)
            gr_error(g, "%s: sub-style %s has too many parameters", me, st->name);
        pair_create(g, &h->term[h->n], st, e - i - 1, argv + i + 1);
        h->off[h->n] = off;
        off += st->nparam;
        struct pair_caps tc;
        pair_describe(&h->term[h->n], &tc);
        nhist += tc.history;
        h->n++;
        i = e;
    }
    if (nhist > 1 && !pick)
        gr_error(g, "hybrid/overlay: at most one sub-style may keep contact history");
    p->data = gr_calloc(g, 1, sizeof loc);
    memcpy(p->data, &loc, sizeof loc);
}

static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    parse_terms(g, p, argc, argv, 0);
}

static void settings_hybrid(struct gravel *g, struct pair *p, int argc, char **argv)
{
    parse_terms(g, p, argc, argv, 1);
}

/* hybrid: map the pairs (and mirrors) to term t (or MAP_NONE) */
static void map_pairs(struct gravel *g, struct hybrid *h, int ilo, int ihi, int jlo, int jhi,
                      int t)
{
    int nt = g->atoms.ntypes;
    if (!h->map || h->nt != nt) {
        free(h->map);
        h->map = gr_malloc(g, (size_t)nt * nt);
        memset(h->map, MAP_UNSET, (size_t)nt * nt);
        h->nt = nt;
    }
    for (int i = ilo; i <= ihi; i++)
        for (int j = jlo > i ? jlo : i; j <= jhi; j++)
            h->map[(size_t)(i - 1) * nt + (j - 1)] = h->map[(size_t)(j - 1) * nt + (i - 1)] =
                (signed char)t;
}

/* pair_coeff I J STYLE args */
static void coeff(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi,
                  int argc, char **argv)
{
    struct hybrid *h = p->data;
    const char *me = p->style->name;
    char known[256] = "";
    for (int k = 0; k < h->n; k++) {
        strncat(known, k ? ", " : "", sizeof known - strlen(known) - 1);
        strncat(known, h->term[k].style->name, sizeof known - strlen(known) - 1);
    }
    if (h->pick)
        strncat(known, ", none", sizeof known - strlen(known) - 1);
    if (argc < 1)
        gr_error(g, "pair style %s expects a sub-style name after the types (one of: %s)", me,
                 known);
    if (h->pick && !strcmp(argv[0], "none")) {
        if (argc > 1)
            gr_error(g, "pair_coeff ... none takes no further arguments, got '%.64s'", argv[1]);
        map_pairs(g, h, ilo, ihi, jlo, jhi, MAP_NONE);
        p->coeff_set = 1;
        return;
    }
    struct pair *t = NULL;
    int tk = -1;
    for (int k = 0; k < h->n; k++)
        if (!strcmp(h->term[k].style->name, argv[0])) {
            t = &h->term[k];
            tk = k;
        }
    if (!t)
        gr_error(g, "'%.64s' is not a sub-style of this pair_style %s (one of: %s)", argv[0], me,
                 known);
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
    if (h->pick)
        map_pairs(g, h, ilo, ihi, jlo, jhi, tk);
}

/* hybrid at run: every pair mapped (cross pairs from equal diagonals) */
static void init_map(struct gravel *g, struct hybrid *h)
{
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    if (!h->map || h->nt != nt)
        gr_error(g, "pair_style hybrid: pair_coeff must be given for every type pair (after "
                    "the box defines %d atom type(s))", nt);
    for (int i = 1; i <= nt; i++)
        for (int j = i; j <= nt; j++) {
            signed char *m = &h->map[(size_t)(i - 1) * nt + (j - 1)];
            if (*m != MAP_UNSET)
                continue;
            signed char a = h->map[(size_t)(i - 1) * nt + (i - 1)];
            signed char b = h->map[(size_t)(j - 1) * nt + (j - 1)];
            if (i == j || a != b || a < 0)
                gr_error(g, "pair_style hybrid: no pair_coeff for types %d %d (All pair coeffs "
                            "are not set: a cross pair is mixed only when %d %d and %d %d use "
                            "the same sub-style)", i, j, i, i, j, j);
            *m = h->map[(size_t)(j - 1) * nt + (i - 1)] = a;
        }
}

static void init(struct gravel *g, struct pair *p)
{
    struct hybrid *h = p->data;
    if (!h)
        gr_error(g, "pair_style %s has no sub-styles (restart files do not keep them: "
                    "re-issue pair_style and pair_coeff after read_restart)", p->style->name);
    if (h->pick)
        init_map(g, h);
    for (int k = 0; k < h->n; k++) {
        struct pair *t = &h->term[k];
        if (!t->coeff_set && h->pick) /* LAMMPS: a sub-style no pair uses */
            gr_error(g, "pair_style hybrid: sub-style %s is not used by any pair_coeff",
                     t->style->name);
        if (!t->coeff_set)
            gr_error(g, "pair_coeff is missing for hybrid/overlay sub-style %s (e.g. "
                        "pair_coeff * * %s ...)", t->style->name, t->style->name);
        if (!t->style->coeff && t->setflag && !h->pick) {
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
    if (h->pick)
        param[0] = h->map[(size_t)(itype - 1) * h->nt + (jtype - 1)];
    for (int k = 0; k < h->n; k++)
        h->term[k].style->pack(&h->term[k], itype, jtype, param + h->off[k]);
}

/* The terms' records merged: their sources, then the fused loop's; state
 * and reach are the union; the collision time and energy are the first
 * term's that has one (the contact law). A composed loop takes no
 * approach or potential-energy path (PAIR_APPROACH, PAIR_ENERGY). */
static void describe(const struct pair *p, struct pair_caps *c)
{
    const struct hybrid *h = p->data;
    if (!h) /* after read_restart, before pair_style is re-issued (init refuses) */
        return;
    pair_caps_define(c, "PAIR_TERMS", "%d", h->n);
    c->sym_torque = 1; /* every term's */
    for (int k = 0; k < h->n; k++) {
        const struct pair *t = &h->term[k];
        struct pair_caps tc;
        pair_describe(t, &tc);
        c->sym_torque &= tc.sym_torque;
        for (int q = 0; q < tc.nsources; q++)
            pair_caps_source(c, tc.sources[q]);
        char nm[32];
        snprintf(nm, sizeof nm, "PAIR_TERM%d", k);
        pair_caps_define(c, nm, "%s", tc.eval);
        snprintf(nm, sizeof nm, "PAIR_TERM%d_OFF", k);
        pair_caps_define(c, nm, "%d", h->off[k]);
        snprintf(nm, sizeof nm, "PAIR_TERM%d_CONTACT", k);
        pair_caps_define(c, nm, "%d", !tc.beyond);
        snprintf(nm, sizeof nm, "PAIR_TERM%d_HIST", k);
        pair_caps_define(c, nm, "%d", tc.history);
        c->rotation |= tc.rotation;
        if (tc.history) {
            c->history = 1;
            if (tc.hist_n != 3)
                c->hist_n = -1; /* every term takes a 3-REAL history (pair_setup) */
        }
        c->beyond |= tc.beyond;
        for (int q = 0; q < tc.nreach; q++)
            pair_caps_reach(c, tc.reach_a[q], tc.reach_b[q]);
        if (tc.type_cut && !c->type_cut) {
            c->cut_of = tc.cut_of;
            c->type_cut = tc.type_cut;
        }
        if (tc.collision_time && !c->collision_time) {
            c->tcol_of = tc.tcol_of;
            c->collision_time = tc.collision_time;
        }
    }
    pair_caps_source(c, "pair_hybrid_overlay.cl");
    c->eval = h->pick ? "hybrid_eval" : "hybrid_overlay_eval";
}

const struct pair_style pair_style_hybrid_overlay = {
    .name = "hybrid/overlay",
    .nparam = PAIR_MAXTERMS * PAIR_MAXPARAM,
    .settings = settings,
    .pack = pack,
    .coeff = coeff,
    .init = init,
    .describe = describe,
    .terms = terms,
    .destroy = destroy,
};

const struct pair_style pair_style_hybrid = {
    .name = "hybrid",
    .nparam = 1 + PAIR_MAXTERMS * PAIR_MAXPARAM,
    .settings = settings_hybrid,
    .pack = pack,
    .coeff = coeff,
    .init = init,
    .describe = describe,
    .terms = terms,
    .destroy = destroy,
};
