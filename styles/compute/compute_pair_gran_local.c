/* compute_pair_gran_local.c - LIGGGHTS's `compute ID group pair/gran/local
 * [keyword ...]`: one row per pair of group atoms whose surfaces intersect
 * (r < r_i + r_j), with the contact's force and torque on i as the step's
 * contact evaluation computed them (the engine's contact records, read back
 * at output time). Keywords, columns in this order whatever the order given
 * (LIGGGHTS's):
 *   pos               x_i, x_j (6)           vel    v_i, v_j (6)
 *   id                tag_i, tag_j, 1 when the pair meets across a periodic
 *                     boundary (3)
 *   force             F on i (3); force_normal, force_tangential its parts
 *                     along and across n = (x_j - x_i)/r (3 each)
 *   torque            the torque on i (3); torque_normal, torque_tangential
 *                     (3 each)
 *   history           the pair style's history row, seen from i (its width)
 *   contactArea       -pi/4 (r-ri-rj)(r+ri-rj)(r-ri+rj)(r+ri+rj)/r^2 (1)
 *   delta             ri + rj - r (1)
 *   contactPoint      (x_i rj + x_j ri)/(ri + rj) (3)
 * No keyword: pos vel id force torque history contactArea. i is the
 * contact's owner (the lower tag); rows in (tag_i, tag_j) order. A local
 * array of that many columns. LIGGGHTS re-evaluates its contact models at
 * output time with the end-of-step velocities and no history update; these
 * are the forces that acted in the step (the same wherever the law does not
 * read the velocities: doc/styles/compute_pair_gran_local.md). heatFlux and
 * ms_id are refused, verbose is accepted. One process only (the contacts'
 * records are the device's). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "compute_pair_gran_local.h"
#include "error.h"
#include "host_pairs.h"
#include "neighbor.h"
#include "pair.h"

static const char *const pgl_names[PG_N] = {
    "pos", "vel", "id", "force", "force_normal", "force_tangential", "torque",
    "torque_normal", "torque_tangential", "history", "contactArea", "delta", "contactPoint"};
extern const struct compute_style compute_style_pair_gran_local;
static const int pgl_width[PG_N] = {6, 6, 3, 3, 3, 3, 3, 3, 3, 0, 1, 1, 3};

struct pgl {
    int on[PG_N];
    int hist_w;                 /* the history row's width at the last check */
};

/* The pair style's history width (0 without history or pair style). */
static int history_width(struct gravel *g)
{
    const struct pair *p = g->styles.pair;
    if (!p)
        return 0;
    struct pair_caps caps;
    pair_describe(p, &caps);
    return caps.history ? caps.hist_n : 0;
}

static int columns(const struct pgl *pg)
{
    int n = 0;
    for (int k = 0; k < PG_N; k++)
        if (pg->on[k])
            n += k == PG_HIST ? pg->hist_w : pgl_width[k];
    return n;
}

/* The history check and the column count (at create and every init). */
static void pgl_shape(struct gravel *g, struct compute *c)
{
    struct pgl *pg = c->data;
    if (!g->styles.pair)
        gr_error(g, "compute %s: no pair style is defined for compute pair/gran/local", c->id);
    pg->hist_w = history_width(g);
    if (pg->on[PG_HIST] && pg->hist_w == 0)
        gr_error(g, "compute %s: compute pair/gran/local can not calculate history values since "
                    "pair style %s does not compute them (leave out 'history', or name the "
                    "values wanted)", c->id, g->styles.pair->style->name);
    c->size_local_cols = columns(pg);
}

static void pgl_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    struct pgl *pg = gr_calloc(g, 1, sizeof *pg);
    c->data = pg;
    int named = 0;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "verbose"))
            continue;
        if (!strcmp(argv[i], "heatFlux") || !strcmp(argv[i], "ms_id"))
            gr_error(g, "compute pair/gran/local: '%s' is not supported (pos vel id force "
                        "force_normal force_tangential torque torque_normal torque_tangential "
                        "history contactArea delta contactPoint)", argv[i]);
        int k = 0;
        while (k < PG_N && strcmp(argv[i], pgl_names[k]))
            k++;
        if (k == PG_N)
            gr_error(g, "compute pair/gran/local: illegal/unrecognized keyword '%.64s' (pos vel "
                        "id force force_normal force_tangential torque torque_normal "
                        "torque_tangential history contactArea delta contactPoint)", argv[i]);
        pg->on[k] = 1;
        named = 1;
    }
    if (!named) /* LIGGGHTS's default */
        pg->on[PG_POS] = pg->on[PG_VEL] = pg->on[PG_ID] = pg->on[PG_F] = pg->on[PG_T] =
            pg->on[PG_HIST] = pg->on[PG_AREA] = 1;
    c->local_flag = 1;
    pgl_shape(g, c);
}

static void pgl_init(struct gravel *g, struct compute *c)
{
    struct pgl *pg = c->data;
    const int cols = c->size_local_cols;
    pgl_shape(g, c);
    if (c->size_local_cols != cols && pg->on[PG_HIST])
        gr_error(g, "compute %s: the pair style's history is %d values wide now, %d when the "
                    "compute was defined: define compute pair/gran/local after the pair style",
                 c->id, pg->hist_w, cols - (columns(pg) - pg->hist_w));
}

/* A contact of the list: its atoms' tags (owner first) and its index */
struct pgl_contact {
    int64_t ti, tj;
    int c;
};

static int by_tags(const void *pa, const void *pb)
{
    const struct pgl_contact *a = pa, *b = pb;
    if (a->ti != b->ti)
        return a->ti < b->ti ? -1 : 1;
    return (a->tj > b->tj) - (a->tj < b->tj);
}

/* v's parts along the unit vector n and across it */
static void split(const double *v, const double *n, double *along, double *across)
{
    const double d = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    for (int k = 0; k < 3; k++) {
        along[k] = d * n[k];
        across[k] = v[k] - along[k];
    }
}

static void pgl_local(struct gravel *g, struct compute *c)
{
    struct pgl *pg = c->data;
    const struct atoms *a = &g->atoms;
    int *ci, *cj;
    double *fc, *tc;
    const int nc = nbr_contact_forces(g, &ci, &cj, &fc, &tc);
    if (nc < 0)
        gr_error(g, "compute %s: compute pair/gran/local reads the contacts of a run: evaluate "
                    "it during or after a run with these atoms", c->id);
    /* the contacts by (owner tag, partner tag) */
    struct pgl_contact *ct = gr_malloc(g, ((size_t)nc + 1) * sizeof *ct);
    for (int k = 0; k < nc; k++)
        ct[k] = (struct pgl_contact){a->tag[ci[k]], a->tag[cj[k]], k};
    qsort(ct, (size_t)nc, sizeof *ct, by_tags);
    /* the pairs whose surfaces intersect (i the lower tag) */
    struct host_pair *p;
    const int np = host_pairs_local(g, c->groupbit, 1, &p, "compute pair/gran/local");
    double *hist = NULL;
    int hw = 0;
    if (pg->on[PG_HIST] && np > 0) {
        hist = gr_calloc(g, (size_t)np * HOST_PAIRS_HIST_MAX, sizeof *hist);
        hw = host_pairs_history(g, p, np, hist);
    }
    const int ncol = c->size_local_cols;
    double *out = compute_local_rows(g, c, np);
    for (int k = 0; k < np; k++) {
        int i = p[k].i, j = p[k].j;
        double del[3] = {p[k].del[0], p[k].del[1], p[k].del[2]}; /* x_i - x_j */
        struct pgl_contact key = {a->tag[i], a->tag[j], 0};
        const struct pgl_contact *hit = bsearch(&key, ct, (size_t)nc, sizeof *ct, by_tags);
        double sign = 1;
        if (!hit) { /* owned by the higher tag (-compat lammps2021): i is the owner */
            struct pgl_contact rev = {a->tag[j], a->tag[i], 0};
            hit = bsearch(&rev, ct, (size_t)nc, sizeof *ct, by_tags);
            int t = i;
            i = j;
            j = t;
            for (int d = 0; d < 3; d++)
                del[d] = -del[d];
            sign = -1; /* the history was read as seen from the lower tag */
        }
        if (!hit)
            gr_error(g, "compute %s: atoms %lld and %lld touch but are not in the contact list "
                        "(compute pair/gran/local evaluated between a move and a rebuild)",
                     c->id, (long long)a->tag[i], (long long)a->tag[j]);
        const double *F = fc + 3 * (size_t)hit->c, *T = tc + 3 * (size_t)hit->c;
        const double rsq = p[k].rsq, r = sqrt(rsq), ri = a->radius[i], rj = a->radius[j];
        const double n[3] = {-del[0] / r, -del[1] / r, -del[2] / r}; /* from i to j */
        double *o = out + (size_t)k * ncol, along[3], across[3];
        for (int q = 0; q < PG_N; q++) {
            if (!pg->on[q])
                continue;
            switch (q) {
            case PG_POS:
                for (int d = 0; d < 3; d++)
                    o[d] = a->x[3 * i + d], o[3 + d] = a->x[3 * j + d];
                break;
            case PG_VEL:
                for (int d = 0; d < 3; d++)
                    o[d] = a->v[3 * i + d], o[3 + d] = a->v[3 * j + d];
                break;
            case PG_ID: {
                int across_pbc = 0;
                for (int d = 0; d < 3; d++)
                    across_pbc |= del[d] != a->x[3 * i + d] - a->x[3 * j + d];
                o[0] = (double)a->tag[i];
                o[1] = (double)a->tag[j];
                o[2] = across_pbc;
                break;
            }
            case PG_F: memcpy(o, F, 3 * sizeof *o); break;
            case PG_FN: split(F, n, o, across); break;
            case PG_FT: split(F, n, along, o); break;
            case PG_T: memcpy(o, T, 3 * sizeof *o); break;
            case PG_TN: split(T, n, o, across); break;
            case PG_TT: split(T, n, along, o); break;
            case PG_HIST:
                for (int d = 0; d < pg->hist_w; d++)
                    o[d] = hw == pg->hist_w ? sign * hist[(size_t)k * hw + d] : 0.0;
                break;
            case PG_AREA:
                o[0] = -M_PI / 4 * ((r - ri - rj) * (r + ri - rj) * (r - ri + rj) * (r + ri + rj)) /
                       rsq;
                break;
            case PG_DELTA: o[0] = ri + rj - r; break;
            case PG_CP:
                for (int d = 0; d < 3; d++)
                    o[d] = (a->x[3 * i + d] * rj + (a->x[3 * i + d] - del[d]) * ri) / (ri + rj);
                break;
            }
            o += q == PG_HIST ? pg->hist_w : pgl_width[q];
        }
    }
    free(p);
    free(hist);
    free(ct);
    free(ci);
    free(cj);
    free(fc);
    free(tc);
}

int pgl_columns(const struct compute *c, int at[PG_N])
{
    if (c->style != &compute_style_pair_gran_local)
        return 0;
    const struct pgl *pg = c->data;
    int n = 0;
    for (int k = 0; k < PG_N; k++) {
        at[k] = pg->on[k] ? n : -1;
        if (pg->on[k])
            n += k == PG_HIST ? pg->hist_w : pgl_width[k];
    }
    return 1;
}

const struct compute_style compute_style_pair_gran_local = {
    .name = "pair/gran/local",
    .ranks = COMPUTE_RANKS_NO, /* the device's contact records */
    .create = pgl_create,
    .init = pgl_init,
    .local = pgl_local,
};
