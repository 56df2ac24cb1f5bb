/* par_restart.c - restart files on several ranks (par.h): what a decomposed
 * run leaves for write_restart, and what read_restart hands the next
 * decomposed run. The file is the one one process writes: the neighbor
 * list as rows of the host atoms by partner tag, the fixes' per-atom state
 * in host order. */
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "neighbor.h"
#include "par.h"
#include "par_restart.h"
#include "par_hist.h"

/* one history value, the device's REAL bytes <-> double */
static double real_get(const unsigned char *b, size_t rsz, int k)
{
    if (rsz == sizeof(float)) {
        float v;
        memcpy(&v, b + (size_t)k * rsz, sizeof v);
        return v;
    }
    double v;
    memcpy(&v, b + (size_t)k * rsz, sizeof v);
    return v;
}

static void real_put(unsigned char *b, size_t rsz, int k, double v)
{
    if (rsz == sizeof(float)) {
        float f = (float)v;
        memcpy(b + (size_t)k * rsz, &f, sizeof f);
    } else {
        memcpy(b + (size_t)k * rsz, &v, sizeof v);
    }
}

/* row of tag t among n tag-sorted atoms, or -1 */
static int row_of(const int64_t *tag, int n, int64_t t)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        int mid = lo + (hi - lo) / 2;
        if (tag[mid] == t)
            return mid;
        if (tag[mid] < t)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}

/* the host atoms are those the last decomposed run left, in its order */
static int as_left(const struct gravel *g)
{
    const struct par *p = g->par;
    return p && p->ended && par_tag_set_key(&g->atoms) == p->tags_at_end;
}

int par_list_export(struct gravel *g, struct nbr_state *s, int *exact)
{
    memset(s, 0, sizeof *s);
    *exact = 0;
    if (!as_left(g))
        return 0;
    struct par *p = g->par;
    struct engine *e = g->eng;
    const struct atoms *a = &g->atoms; /* tag order: the run's end sorted them */
    const struct par_hist *h = p->hist;
    int n = a->n, hw = e->history ? e->hist_n : 0;
    size_t rsz = e->rsz;
    s->n = n;
    s->history = h && h->vb ? hw : 0;
    s->ago = p->ago_end;
    s->ncount = gr_calloc(g, (size_t)n + 1, sizeof(int));
    int maxn = 1;
    for (size_t q = 0; h && q < h->cap; q++)
        if (h->key[2 * q]) {
            int i = row_of(a->tag, n, h->key[2 * q]), j = row_of(a->tag, n, h->key[2 * q + 1]);
            if (i < 0 || j < 0)
                continue;
            maxn = s->ncount[i] + 1 > maxn ? s->ncount[i] + 1 : maxn;
            maxn = s->ncount[j] + 1 > maxn ? s->ncount[j] + 1 : maxn;
            s->ncount[i]++;
            s->ncount[j]++;
        }
    s->maxn = maxn;
    memset(s->ncount, 0, ((size_t)n + 1) * sizeof(int));
    s->nlist = gr_malloc(g, ((size_t)n * maxn + 1) * sizeof(int));
    if (s->history)
        s->shear = gr_calloc(g, (size_t)s->history * n * maxn + 1, sizeof(double));
    /* the lower tag owns the contact: its side holds the history, the other its negative */
    for (size_t q = 0; h && q < h->cap; q++)
        if (h->key[2 * q]) {
            int i = row_of(a->tag, n, h->key[2 * q]), j = row_of(a->tag, n, h->key[2 * q + 1]);
            if (i < 0 || j < 0)
                continue;
            const int side[2][2] = {{i, j}, {j, i}};
            for (int k = 0; k < 2; k++) {
                int at = side[k][0];
                size_t slot = (size_t)at * maxn + (size_t)s->ncount[at]++;
                s->nlist[slot] = side[k][1];
                for (int d = 0; d < s->history; d++)
                    s->shear[(size_t)s->history * slot + d] =
                        (k ? -1.0 : 1.0) * real_get(h->val + q * h->vb, rsz, d);
            }
        }
    /* rows in partner tag order: the host's order */
    size_t w = (size_t)s->history;
    double tmp[GR_HIST_MAX];
    for (int i = 0; i < n; i++) {
        int *row = s->nlist + (size_t)i * maxn;
        double *sh = s->shear ? s->shear + w * i * maxn : NULL;
        for (int x = 1; x < s->ncount[i]; x++) {
            int v = row[x], y = x - 1;
            if (sh)
                memcpy(tmp, sh + w * x, w * sizeof(double));
            for (; y >= 0 && row[y] > v; y--) {
                row[y + 1] = row[y];
                if (sh)
                    memcpy(sh + w * (y + 1), sh + w * y, w * sizeof(double));
            }
            row[y + 1] = v;
            if (sh)
                memcpy(sh + w * (y + 1), tmp, w * sizeof(double));
        }
    }
    s->xhold = gr_malloc(g, (3 * (size_t)n + 1) * sizeof(double));
    memcpy(s->xhold, p->xhold_end, 3 * (size_t)n * sizeof(double));
    *exact = atoms_fingerprint(&g->atoms) == p->host_hash;
    return 1;
}

const unsigned char *par_fix_rows(const struct gravel *g, const struct fix *f)
{
    if (!as_left(g))
        return NULL;
    const struct par *p = g->par;
    for (int k = 0; k < p->nsaved; k++)
        if (p->saved[k].fix == f && f->peratom_bytes == p->saved[k].bytes)
            return p->saved[k].state;
    return NULL;
}

/* ---- read_restart: the next decomposed run's start --------------------------------- */

void par_adopt_begin(struct gravel *g)
{
    struct par *p = par_state(g);
    par_hist_free(p->hist);
    p->hist = NULL;
    for (int k = 0; k < p->nsaved; k++)
        free(p->saved[k].state);
    p->nsaved = 0;
    free(p->resume_ft);
    p->resume_ft = NULL;
    p->nresume = 0;
    p->tags_at_end = par_tag_set_key(&g->atoms);
}

void par_adopt_list(struct gravel *g, const struct nbr_state *s)
{
    struct par *p = g->par;
    struct engine *e = g->eng;
    const int64_t *tag = g->atoms.tag;
    size_t rsz = e->rsz, hw = e->history ? (size_t)e->hist_n : 0;
    int common = (int)hw < s->history ? (int)hw : s->history;
    unsigned char *val = gr_calloc(g, hw * rsz + 1, 1);
    p->hist = par_hist_new(g, (size_t)s->n * 4, hw * rsz);
    for (int i = 0; i < s->n; i++)
        for (int k = 0; k < s->ncount[i]; k++) {
            size_t slot = (size_t)i * s->maxn + (size_t)k;
            int j = s->nlist[slot];
            if (tag[i] > tag[j])
                continue; /* the lower tag's row holds the owner's history */
            memset(val, 0, hw * rsz);
            for (int d = 0; d < common; d++)
                real_put(val, rsz, d, s->shear[(size_t)s->history * slot + d]);
            par_hist_put(g, &p->hist, tag[i], tag[j], val);
        }
    free(val);
}

void par_adopt_fix_rows(struct gravel *g, struct fix *f, size_t bytes,
                        const unsigned char *rows)
{
    struct par *p = g->par;
    if (p->nsaved == PAR_MAXSAVED)
        gr_error(g, "more than %d fixes with per-atom state on several ranks", PAR_MAXSAVED);
    struct par_saved *sv = &p->saved[p->nsaved++];
    size_t n = (size_t)g->atoms.n;
    sv->fix = f;
    sv->bytes = bytes;
    sv->state = gr_malloc(g, n * bytes + 1);
    memcpy(sv->state, rows, n * bytes);
}

/* by tag: the first double's bits */
static int by_tag_bits(const void *x, const void *y)
{
    int64_t a, b;
    memcpy(&a, x, sizeof a);
    memcpy(&b, y, sizeof b);
    return (a > b) - (a < b);
}

void par_adopt_forces(struct gravel *g)
{
    struct par *p = g->par;
    const struct atoms *a = &g->atoms;
    int n = a->n;
    p->resume_ft = gr_malloc(g, (7 * (size_t)n + 1) * sizeof(double));
    for (int i = 0; i < n; i++) {
        double *r = p->resume_ft + 7 * (size_t)i;
        memcpy(r, &a->tag[i], sizeof(double));
        memcpy(r + 1, a->f + 3 * (size_t)i, 3 * sizeof(double));
        memcpy(r + 4, a->torque + 3 * (size_t)i, 3 * sizeof(double));
    }
    qsort(p->resume_ft, (size_t)n, 7 * sizeof(double), by_tag_bits);
    p->nresume = n;
}

void par_resume_forces(struct gravel *g)
{
    struct par *p = g->par;
    struct engine *e = g->eng;
    int n = e->a.n;
    if (!p->resume_ft || n == 0)
        return;
    int64_t *tag = gr_malloc(g, ((size_t)n + 1) * sizeof(int64_t));
    double *f = gr_malloc(g, (6 * (size_t)n + 1) * sizeof(double)), *t = f + 3 * (size_t)n;
    eng_read(g, e->a.tag, 0, (size_t)n * sizeof(int64_t), tag);
    for (int i = 0; i < n; i++) {
        double key;
        memcpy(&key, &tag[i], sizeof key);
        const double *r = bsearch(&key, p->resume_ft, (size_t)p->nresume, 7 * sizeof(double),
                                  by_tag_bits);
        if (!r)
            gr_error(g, "internal error: atom %lld has no force in the restart file",
                     (long long)tag[i]);
        memcpy(f + 3 * (size_t)i, r + 1, 3 * sizeof(double));
        memcpy(t + 3 * (size_t)i, r + 4, 3 * sizeof(double));
    }
    eng_write_reals(g, e->a.f, 3 * (size_t)n, f);
    if (e->a.torque)
        eng_write_reals(g, e->a.torque, 3 * (size_t)n, t);
    free(tag);
    free(f);
    free(p->resume_ft);
    p->resume_ft = NULL;
}
