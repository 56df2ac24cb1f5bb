/* host_pairs.c - pairs within a distance, on the host (host_pairs.h).
 *
 * Method: the candidate atoms are binned into cells of width >= cut over
 * the box (periodic dimensions) or the atoms' extent; each atom scans the
 * 27 neighbouring cells (a periodic dimension with fewer than 3 cells is
 * one cell, so no pair is seen twice) and keeps partners of higher tag.
 * The result is sorted by (tag_i, tag_j). O(N) for bounded density. */
#include "host_pairs.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "fix.h"
#include "neighbor.h"
#include "pair.h"

static double minimg(double d, double L)
{
    if (L > 0 && (d > 0.5 * L || d < -0.5 * L))
        d -= L * floor(d / L + 0.5);
    return d;
}

static const int64_t *sort_tags;

static int cmp_pair(const void *pa, const void *pb)
{
    const struct host_pair *a = pa, *b = pb;
    int64_t ai = sort_tags[a->i], bi = sort_tags[b->i];
    if (ai != bi)
        return ai < bi ? -1 : 1;
    int64_t aj = sort_tags[a->j], bj = sort_tags[b->j];
    return aj < bj ? -1 : aj > bj;
}

void host_pairs_scan(struct gravel *g, const int *idx, int m, double cut,
                     void (*visit)(struct gravel *g, int k, int kk, void *ctx), void *ctx)
{
    host_pairs_scan_x(g, g->atoms.x, idx, m, cut, visit, ctx);
}

void host_pairs_scan_x(struct gravel *g, const double *x, const int *idx, int m, double cut,
                       void (*visit)(struct gravel *g, int k, int kk, void *ctx), void *ctx)
{
    if (m < 2)
        return;
    double L[3], lo[3], hi[3];
    for (int q = 0; q < 3; q++) {
        L[q] = g->dom.periodic[q] ? g->dom.hi[q] - g->dom.lo[q] : 0.0;
        lo[q] = INFINITY;
        hi[q] = -INFINITY;
    }
    for (int k = 0; k < m; k++)
        for (int q = 0; q < 3; q++) {
            lo[q] = fmin(lo[q], x[3 * idx[k] + q]);
            hi[q] = fmax(hi[q], x[3 * idx[k] + q]);
        }
    int nc[3];
    for (int q = 0; q < 3; q++) {
        if (L[q] > 0) {
            lo[q] = g->dom.lo[q];
            hi[q] = g->dom.hi[q];
        }
        double n = floor((hi[q] - lo[q]) / cut);
        nc[q] = n < 1 ? 1 : n > 1024 ? 1024 : (int)n;
        if (L[q] > 0 && nc[q] < 3)
            nc[q] = 1; /* a stencil that wraps onto itself: one cell, all pairs */
    }
    long total; /* a sparse scene: fewer cells than atoms x 8 */
    while ((total = (long)nc[0] * nc[1] * nc[2]) > 8L * m + 64) {
        int q = nc[0] >= nc[1] && nc[0] >= nc[2] ? 0 : nc[1] >= nc[2] ? 1 : 2;
        nc[q] = nc[q] / 2 > 0 ? nc[q] / 2 : 1;
        if (L[q] > 0 && nc[q] < 3)
            nc[q] = 1;
    }
    int *cell = gr_malloc(g, (size_t)m * sizeof *cell);
    int *start = gr_calloc(g, (size_t)total + 1, sizeof *start);
    int *sorted = gr_malloc(g, (size_t)m * sizeof *sorted);
    for (int k = 0; k < m; k++) {
        int ci[3];
        for (int q = 0; q < 3; q++) {
            double w = hi[q] - lo[q];
            double s = (x[3 * idx[k] + q] - lo[q]) / (w > 0 ? w : 1);
            if (L[q] > 0)
                s -= floor(s);
            ci[q] = (int)(s * nc[q]);
            ci[q] = ci[q] < 0 ? 0 : ci[q] >= nc[q] ? nc[q] - 1 : ci[q];
        }
        cell[k] = (ci[2] * nc[1] + ci[1]) * nc[0] + ci[0];
        start[cell[k] + 1]++;
    }
    for (long c = 0; c < total; c++)
        start[c + 1] += start[c];
    int *cur = gr_malloc(g, (size_t)total * sizeof *cur);
    memcpy(cur, start, (size_t)total * sizeof *cur);
    for (int k = 0; k < m; k++)
        sorted[cur[cell[k]]++] = k;
    free(cur);
    for (int k = 0; k < m; k++) {
        const int c0 = cell[k];
        const int ci[3] = {c0 % nc[0], (c0 / nc[0]) % nc[1], c0 / (nc[0] * nc[1])};
        int lst[3][3], ns[3];
        for (int q = 0; q < 3; q++) {
            ns[q] = 0;
            for (int dd = -1; dd <= 1; dd++) {
                int v = ci[q] + dd;
                if (L[q] > 0)
                    v = (v + nc[q]) % nc[q];
                else if (v < 0 || v >= nc[q])
                    continue;
                int dup = 0;
                for (int t = 0; t < ns[q]; t++)
                    dup |= lst[q][t] == v;
                if (!dup)
                    lst[q][ns[q]++] = v;
            }
        }
        for (int a = 0; a < ns[2]; a++)
            for (int b = 0; b < ns[1]; b++)
                for (int d = 0; d < ns[0]; d++) {
                    int cc = (lst[2][a] * nc[1] + lst[1][b]) * nc[0] + lst[0][d];
                    for (int s = start[cc]; s < start[cc + 1]; s++)
                        if (sorted[s] > k)
                            visit(g, k, sorted[s], ctx);
                }
    }
    free(cell);
    free(start);
    free(sorted);
}

struct find_ctx {
    const int *idx;
    unsigned bits_a, bits_b;
    double cutsq, L[3];
    int np, cap;
    struct host_pair *p;
};

/* One candidate of host_pairs_find: oriented lower tag first, kept when the
 * groups match and it is closer than the cut. */
static void find_visit(struct gravel *g, int k, int kk, void *vctx)
{
    struct find_ctx *c = vctx;
    const struct atoms *at = &g->atoms;
    int i = c->idx[k], j = c->idx[kk];
    if (at->tag[j] < at->tag[i]) {
        int t = i;
        i = j;
        j = t;
    }
    unsigned mi = at->mask[i], mj = at->mask[j];
    if (!((mi & c->bits_a) && (mj & c->bits_b)) && !((mi & c->bits_b) && (mj & c->bits_a)))
        return;
    double del[3], rsq = 0;
    for (int q = 0; q < 3; q++) {
        del[q] = minimg(at->x[3 * i + q] - at->x[3 * j + q], c->L[q]);
        rsq += del[q] * del[q];
    }
    if (rsq >= c->cutsq)
        return;
    if (c->np == c->cap) {
        c->cap = c->cap ? 2 * c->cap : 256;
        c->p = gr_realloc(g, c->p, (size_t)c->cap * sizeof *c->p);
    }
    struct host_pair *p = c->p + c->np++;
    p->i = i;
    p->j = j;
    memcpy(p->del, del, sizeof del);
    p->rsq = rsq;
}

int host_pairs_find(struct gravel *g, double cut, unsigned bits_a, unsigned bits_b,
                    struct host_pair **out, const char *who)
{
    const struct atoms *at = &g->atoms;
    *out = NULL;
    if (g->dom.triclinic || g->dom.xy != 0.0 || g->dom.xz != 0.0 || g->dom.yz != 0.0)
        gr_error(g, "%s: triclinic boxes are not supported", who);
    if (!(cut > 0) || !isfinite(cut))
        gr_error(g, "%s: the pair cut-off must be positive", who);
    struct find_ctx c = {.bits_a = bits_a, .bits_b = bits_b, .cutsq = cut * cut};
    for (int q = 0; q < 3; q++)
        c.L[q] = g->dom.periodic[q] ? g->dom.hi[q] - g->dom.lo[q] : 0.0;
    int m = 0;
    int *idx = gr_malloc(g, (size_t)(at->n > 0 ? at->n : 1) * sizeof *idx);
    for (int i = 0; i < at->n; i++)
        if (at->mask[i] & (bits_a | bits_b))
            idx[m++] = i;
    c.idx = idx;
    host_pairs_scan(g, idx, m, cut, find_visit, &c);
    free(idx);
    if (c.np > 1) {
        sort_tags = at->tag;
        qsort(c.p, (size_t)c.np, sizeof *c.p, cmp_pair);
    }
    *out = c.p;
    return c.np;
}

/* LAMMPS 2021 init_one's cut-off for types with largest radii ri, rj */
static double type_cut(const struct pair *p, const struct pair_caps *caps, int i, int j,
                       double ri, double rj)
{
    if (p && caps->lammps2021_cut)
        return caps->lammps2021_cut(caps->cut2021_of, i, j, ri, rj);
    return ri + rj;
}

/* LAMMPS 2021 init_one's cut-off of every type pair, cut[i (nt + 1) + j]
 * (malloc'd), from the largest radii of each type's dynamic and frozen (fix
 * freeze) atoms present now, frozen-frozen excluded; *cmax their largest. */
static double *type_cuts(struct gravel *g, const char *who, double *cmax)
{
    const struct atoms *a = &g->atoms;
    int nt = a->ntypes > 0 ? a->ntypes : 1;
    const struct pair *p = g->styles.pair;
    if (!p)
        gr_error(g, "%s: cutoff type needs a pair style (or use cutoff radius)", who);
    double *dyn = gr_calloc(g, (size_t)(2 * nt + 2), sizeof *dyn), *fro = dyn + nt + 1;
    unsigned frozen = fix_frozen_groupbit(g);
    for (int k = 0; k < a->n; k++) {
        double *m = (a->mask[k] & frozen) ? fro : dyn;
        if (a->radius[k] > m[a->type[k]])
            m[a->type[k]] = a->radius[k];
    }
    struct pair_caps caps;
    pair_describe(p, &caps);
    double *cut = gr_calloc(g, (size_t)(nt + 1) * (nt + 1), sizeof *cut);
    *cmax = 0;
    for (int i = 1; i <= nt; i++)
        for (int j = 1; j <= nt; j++) {
            double c = type_cut(p, &caps, i, j, dyn[i], dyn[j]);
            c = fmax(c, type_cut(p, &caps, i, j, fro[i], dyn[j]));
            c = fmax(c, type_cut(p, &caps, i, j, dyn[i], fro[j]));
            cut[i * (nt + 1) + j] = c;
            *cmax = fmax(*cmax, c);
        }
    free(dyn);
    return cut;
}

double host_pairs_cutforce(struct gravel *g, const char *who)
{
    double cmax;
    free(type_cuts(g, who, &cmax));
    return cmax;
}

int host_pairs_excluded(const struct gravel *g, int i, int j)
{
    const struct atoms *a = &g->atoms;
    const struct neigh_settings *ns = &g->neigh;
    unsigned mi = a->mask[i], mj = a->mask[j];
    for (int k = 0; k < ns->nexclude_type; k++) {
        int t1 = ns->exclude_type[k][0], t2 = ns->exclude_type[k][1];
        if ((a->type[i] == t1 && a->type[j] == t2) || (a->type[i] == t2 && a->type[j] == t1))
            return 1;
    }
    for (int k = 0; k < ns->nexclude; k++) {
        unsigned b1 = 1u << ns->exclude_group[k][0], b2 = 1u << ns->exclude_group[k][1];
        if (((mi & b1) && (mj & b2)) || ((mi & b2) && (mj & b1)))
            return 1;
    }
    for (int k = 0; k < ns->nexclude_mol && a->mol; k++) {
        unsigned b = 1u << ns->exclude_mol[k][0];
        if ((mi & b) && (mj & b) && ((a->mol[i] == a->mol[j]) == (ns->exclude_mol[k][1] != 0)))
            return 1;
    }
    return 0;
}

int host_pairs_local(struct gravel *g, unsigned groupbit, int radius, struct host_pair **out,
                     const char *who)
{
    const struct atoms *a = &g->atoms;
    int nt = a->ntypes > 0 ? a->ntypes : 1;
    double rmax = 0;
    for (int k = 0; k < a->n; k++)
        rmax = fmax(rmax, a->radius[k]);
    double *cut = NULL, cmax = 2 * rmax;
    if (!radius)
        cut = type_cuts(g, who, &cmax);
    *out = NULL;
    if (!(cmax > 0)) {
        free(cut);
        return 0;
    }
    struct host_pair *p;
    int np = host_pairs_find(g, cmax * (1 + 1e-12), groupbit, groupbit, &p, who);
    int m = 0;
    for (int k = 0; k < np; k++) {
        int i = p[k].i, j = p[k].j;
        double c = radius ? a->radius[i] + a->radius[j] : cut[a->type[i] * (nt + 1) + a->type[j]];
        if (p[k].rsq < c * c && !host_pairs_excluded(g, i, j))
            p[m++] = p[k];
    }
    free(cut);
    if (m == 0) {
        free(p);
        p = NULL;
    }
    *out = p;
    return m;
}

_Static_assert(HOST_PAIRS_HIST_MAX == GR_HIST_MAX, "history width bound");

int host_pairs_history(struct gravel *g, const struct host_pair *p, int np, double *hist)
{
    struct nbr_state st;
    if (!nbr_export(g, &st))
        return 0;
    int hw = st.history;
    if (hw <= 0 || hw > GR_HIST_MAX || st.n != g->atoms.n) {
        nbr_state_free(&st);
        return 0;
    }
    for (int k = 0; k < np; k++) {
        double *h = hist + (size_t)k * hw;
        memset(h, 0, (size_t)hw * sizeof *h);
        int i = p[k].i;
        for (int q = 0; q < st.ncount[i]; q++)
            if (st.nlist[(size_t)i * st.maxn + q] == p[k].j) {
                memcpy(h, st.shear + (size_t)hw * ((size_t)i * st.maxn + q),
                       (size_t)hw * sizeof *h);
                break;
            }
    }
    nbr_state_free(&st);
    return hw;
}
