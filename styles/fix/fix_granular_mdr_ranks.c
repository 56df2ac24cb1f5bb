/* fix_granular_mdr_ranks.c - the gathers of fix granular/mdr on several MPI
 * ranks and the taking back of each rank's part (fix_granular_mdr_ranks.h).
 * Records are doubles: integers travel as their bytes in a double's slot,
 * so nothing is rounded on the way. Phase 1: O(N + contacts) bytes to
 * every rank each step (doc/parallel.md, "Costs of phase 1"). */
#include "fix_granular_mdr_ranks.h"

#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "error.h"
#include "par.h"
#include "state.h"

static int64_t tag_of(const double *rec)
{
    int64_t t;
    memcpy(&t, rec, sizeof t);
    return t;
}

static int by_tag(const void *a, const void *b)
{
    const int64_t ta = tag_of(a), tb = tag_of(b);
    return ta < tb ? -1 : ta > tb;
}

static int by_pair(const void *a, const void *b)
{
    const int64_t ta = tag_of(a), tb = tag_of(b);
    if (ta != tb)
        return ta < tb ? -1 : 1;
    const int64_t ua = tag_of((const double *)a + 1), ub = tag_of((const double *)b + 1);
    return ua < ub ? -1 : ua > ub;
}

/* The set index of tag, or -1 */
static int index_of(const struct mdr_ranks *r, int64_t tag)
{
    int a = 0, b = r->n - 1;
    while (a <= b) {
        const int m = a + (b - a) / 2;
        if (r->tag[m] == tag)
            return m;
        if (r->tag[m] < tag)
            a = m + 1;
        else
            b = m - 1;
    }
    return -1;
}

void mdr_ranks_atoms(struct gravel *g, struct mdr_ranks *r, int nw, const size_t *stride,
                     double *const *own, struct mdr_atoms *v)
{
    const struct atoms *A = &g->atoms;
    const int n = A->n;
    if (nw > MDR_RANKS_WALLS)
        gr_error(g, "fix granular/mdr: more than %d mdr walls", MDR_RANKS_WALLS);
    size_t w = 7; /* tag, x, radius, rmass, mask */
    r->nw = nw;
    for (int k = 0; k < nw; k++) {
        r->stride[k] = own[k] ? stride[k] : 0;
        w += r->stride[k];
    }
    double *mine = gr_malloc(g, ((size_t)n * w + 1) * sizeof(double)), *all = NULL;
    for (int i = 0; i < n; i++) {
        double *q = mine + (size_t)i * w;
        memcpy(q, &A->tag[i], sizeof(int64_t));
        memcpy(q + 1, A->x + 3 * (size_t)i, 3 * sizeof(double));
        q[4] = A->radius[i];
        q[5] = A->rmass[i];
        uint64_t m = A->mask[i];
        memcpy(q + 6, &m, sizeof m);
        q += 7;
        for (int k = 0; k < nw; k++) {
            memcpy(q, own[k] + (size_t)i * r->stride[k], r->stride[k] * sizeof(double));
            q += r->stride[k];
        }
    }
    size_t bytes = comm_allgatherv(mine, (size_t)n * w * sizeof(double), (void **)&all);
    free(mine);
    if (bytes == (size_t)-1)
        gr_error(g, "fix granular/mdr: out of memory gathering every rank's atoms");
    const int tot = (int)(bytes / (w * sizeof(double)));
    if (tot > 1)
        qsort(all, (size_t)tot, w * sizeof(double), by_tag);
    r->n = tot;
    const size_t nn = (size_t)tot + 1;
    r->tag = gr_malloc(g, nn * sizeof *r->tag);
    r->x = gr_malloc(g, 3 * nn * sizeof *r->x);
    r->radius = gr_malloc(g, nn * sizeof *r->radius);
    r->rmass = gr_malloc(g, nn * sizeof *r->rmass);
    r->mask = gr_malloc(g, nn * sizeof *r->mask);
    for (int k = 0; k < nw; k++)
        r->wall[k] = r->stride[k] ? gr_malloc(g, nn * r->stride[k] * sizeof(double)) : NULL;
    for (int i = 0; i < tot; i++) {
        const double *q = all + (size_t)i * w;
        r->tag[i] = tag_of(q);
        memcpy(r->x + 3 * (size_t)i, q + 1, 3 * sizeof(double));
        r->radius[i] = q[4];
        r->rmass[i] = q[5];
        uint64_t m;
        memcpy(&m, q + 6, sizeof m);
        r->mask[i] = (unsigned)m;
        q += 7;
        for (int k = 0; k < nw; k++) {
            if (r->stride[k])
                memcpy(r->wall[k] + (size_t)i * r->stride[k], q, r->stride[k] * sizeof(double));
            q += r->stride[k];
        }
    }
    free(all);
    r->nown = n;
    r->own = gr_malloc(g, ((size_t)n + 1) * sizeof *r->own);
    for (int i = 0; i < n; i++)
        r->own[i] = index_of(r, A->tag[i]);
    *v = (struct mdr_atoms){r->n, r->tag, r->x, r->radius, r->rmass, r->mask};
}

void mdr_ranks_radius_back(const struct mdr_ranks *r, double *radius)
{
    for (int i = 0; i < r->nown; i++)
        radius[i] = r->radius[r->own[i]];
}

void mdr_ranks_wall_back(const struct mdr_ranks *r, int k, double *own)
{
    const size_t s = r->stride[k];
    for (int i = 0; s && i < r->nown; i++)
        memcpy(own + (size_t)i * s, r->wall[k] + (size_t)r->own[i] * s, s * sizeof(double));
}

/* the gathered contact of tags lo < hi, or -1 */
static int contact_of(const struct mdr_ranks *r, int64_t lo, int64_t hi)
{
    int a = 0, b = r->nc - 1;
    while (a <= b) {
        const int m = a + (b - a) / 2;
        const int64_t tl = r->tag[r->ci[m]], th = r->tag[r->cj[m]];
        if (tl == lo && th == hi)
            return m;
        if (tl < lo || (tl == lo && th < hi))
            a = m + 1;
        else
            b = m - 1;
    }
    return -1;
}

void mdr_ranks_contacts(struct gravel *g, struct mdr_ranks *r, int nc, const int *ci,
                        const int *cj, const double *hist, int hw)
{
    const struct par *p = g->par;
    const int64_t *tb = p->tags_built; /* the tags of the slots the list indexes */
    const int nown = p->nlocal_built;
    const size_t w = 2 + (size_t)hw;
    double *mine = gr_malloc(g, ((size_t)nc * w + 1) * sizeof(double)), *all = NULL;
    int k = 0;
    for (int c = 0; c < nc; c++) {
        const int64_t a = tb[ci[c]], b = tb[cj[c]];
        const int lo_slot = a < b ? ci[c] : cj[c];
        if (lo_slot >= nown)
            continue; /* the lower tag's owner sends it */
        double *q = mine + (size_t)k++ * w;
        const int64_t lo = a < b ? a : b, hi = a < b ? b : a;
        memcpy(q, &lo, sizeof lo);
        memcpy(q + 1, &hi, sizeof hi);
        memcpy(q + 2, hist + (size_t)c * hw, (size_t)hw * sizeof(double));
    }
    size_t bytes = comm_allgatherv(mine, (size_t)k * w * sizeof(double), (void **)&all);
    free(mine);
    if (bytes == (size_t)-1)
        gr_error(g, "fix granular/mdr: out of memory gathering every rank's contacts");
    const int tot = (int)(bytes / (w * sizeof(double)));
    if (tot > 1)
        qsort(all, (size_t)tot, w * sizeof(double), by_pair);
    r->nc = tot;
    r->hw = hw;
    r->ci = gr_malloc(g, ((size_t)tot + 1) * sizeof(int));
    r->cj = gr_malloc(g, ((size_t)tot + 1) * sizeof(int));
    r->hist = gr_malloc(g, ((size_t)tot * hw + 1) * sizeof(double));
    for (int c = 0; c < tot; c++) {
        const double *q = all + (size_t)c * w;
        r->ci[c] = index_of(r, tag_of(q));
        r->cj[c] = index_of(r, tag_of(q + 1));
        if (r->ci[c] < 0 || r->cj[c] < 0)
            gr_error(g, "internal error: fix granular/mdr: the contact of atoms %lld and %lld "
                        "has an atom no rank owns", (long long)tag_of(q), (long long)tag_of(q + 1));
        memcpy(r->hist + (size_t)c * hw, q + 2, (size_t)hw * sizeof(double));
    }
    free(all);
    r->nloc = nc;
    r->loc = gr_malloc(g, ((size_t)nc + 1) * sizeof(int));
    for (int c = 0; c < nc; c++) {
        const int64_t a = tb[ci[c]], b = tb[cj[c]];
        r->loc[c] = contact_of(r, a < b ? a : b, a < b ? b : a);
    }
}

void mdr_ranks_contacts_back(const struct mdr_ranks *r, double *hist)
{
    for (int c = 0; c < r->nloc; c++)
        if (r->loc[c] >= 0)
            memcpy(hist + (size_t)c * r->hw, r->hist + (size_t)r->loc[c] * r->hw,
                   (size_t)r->hw * sizeof(double));
}

void mdr_ranks_free(struct mdr_ranks *r)
{
    free(r->tag);
    free(r->x);
    free(r->radius);
    free(r->rmass);
    free(r->mask);
    free(r->own);
    for (int k = 0; k < r->nw; k++)
        free(r->wall[k]);
    free(r->ci);
    free(r->cj);
    free(r->hist);
    free(r->loc);
    memset(r, 0, sizeof *r);
}
