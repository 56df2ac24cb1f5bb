/* neighbor.c - host side of the device neighbor lists (kernels/neighbor.cl).
 *
 * A rebuild: wrap periodic positions and reduce the atom extent (one pass),
 * shrink-wrap the box, bin atoms into cells of size >= 2 r_max + skin
 * (atoms outside a fixed face go to a sentinel cell and are lost), scan the
 * cell counts, scatter and sort each cell by tag (deterministic), gather every
 * per-atom array into the new order, and build the full list with history
 * transfer. A list longer than the capacity grows it and builds again. */
#include "neighbor.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "domain.h"
#include "error.h"
#include "fix.h"
#include "pair.h"

#define NCHUNK_MAX 256

struct nbr {
    struct nbr_list list;
    cl_mem nlist_old, ncount_old, shear_old;
    int maxn_old;
    int old_valid;              /* old list indexes the current atom order */
    int built;                  /* a list exists for the current run */
    cl_mem xhold, cellof, perm, counts, start, cursor, sums, flags, ext, excl_type,
        excl_group, dummy;
    size_t cap_atoms, cap_cells;
    size_t rsz;
    int history;
    int ncell, nc[3];
    double cutmax, lo[3], hi[3], inv[3];
    int nexg;
    int ago;
    int lost_warned;
    cl_kernel k_check, k_wrap, k_bin, k_scan_partial, k_scan_top, k_scan_final, k_scatter,
        k_cellsort, k_reorder, k_reorder_words, k_build, k_overlap;
};

static struct nbr *get(struct gravel *g)
{
    struct engine *e = g->eng;
    if (!e->nbr)
        e->nbr = gr_calloc(g, 1, sizeof(struct nbr));
    return e->nbr;
}

static void rel(cl_mem *m)
{
    if (*m) {
        clReleaseMemObject(*m);
        *m = NULL;
    }
}

void nbr_free(struct gravel *g)
{
    if (!g->eng || !g->eng->nbr)
        return;
    struct nbr *b = g->eng->nbr;
    rel(&b->list.nlist);
    rel(&b->list.ncount);
    rel(&b->list.shear);
    rel(&b->nlist_old);
    rel(&b->ncount_old);
    rel(&b->shear_old);
    cl_mem *m[] = {&b->xhold, &b->cellof, &b->perm, &b->counts, &b->start, &b->cursor,
                   &b->sums, &b->flags, &b->ext, &b->excl_type, &b->excl_group, &b->dummy};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++)
        rel(m[i]);
    free(b);
    g->eng->nbr = NULL;
}

void nbr_invalidate(struct gravel *g)
{
    if (g->eng && g->eng->nbr)
        g->eng->nbr->old_valid = 0;
}

const struct nbr_list *nbr_list(struct gravel *g) { return &get(g)->list; }

static size_t scan_chunks(int m, int *chunk)
{
    int nch = (m + 63) / 64;
    if (nch > NCHUNK_MAX)
        nch = NCHUNK_MAX;
    if (nch < 1)
        nch = 1;
    *chunk = (m + nch - 1) / nch;
    if (*chunk < 1)
        *chunk = 1;
    return (size_t)((m + *chunk - 1) / *chunk > 0 ? (m + *chunk - 1) / *chunk : 1);
}

void nbr_scan(struct gravel *g, cl_mem in, cl_mem out, int m)
{
    struct nbr *b = get(g);
    int chunk;
    size_t nch = scan_chunks(m, &chunk);
    eng_arg_int(g, b->k_scan_partial, 0, m);
    eng_arg_int(g, b->k_scan_partial, 1, chunk);
    eng_arg_mem(g, b->k_scan_partial, 2, in);
    eng_arg_mem(g, b->k_scan_partial, 3, b->sums);
    eng_launch(g, b->k_scan_partial, nch);
    eng_arg_int(g, b->k_scan_top, 0, (int)nch);
    eng_arg_mem(g, b->k_scan_top, 1, b->sums);
    eng_launch(g, b->k_scan_top, 1);
    eng_arg_int(g, b->k_scan_final, 0, m);
    eng_arg_int(g, b->k_scan_final, 1, chunk);
    eng_arg_int(g, b->k_scan_final, 2, (int)nch);
    eng_arg_mem(g, b->k_scan_final, 3, in);
    eng_arg_mem(g, b->k_scan_final, 4, b->sums);
    eng_arg_mem(g, b->k_scan_final, 5, out);
    eng_launch(g, b->k_scan_final, nch);
}

static void grow_atoms(struct gravel *g, struct nbr *b, size_t n)
{
    size_t r = g->eng->rsz;
    rel(&b->xhold);
    rel(&b->cellof);
    rel(&b->perm);
    b->xhold = eng_alloc(g, 3 * n * r, "neighbor reference positions");
    b->cellof = eng_alloc(g, n * sizeof(cl_int), "cell of atom");
    b->perm = eng_alloc(g, n * sizeof(cl_int), "sort permutation");
    b->cap_atoms = n;
}

static void grow_cells(struct gravel *g, struct nbr *b, size_t ncell)
{
    if (ncell + 2 <= b->cap_cells && b->counts)
        return;
    size_t c = ncell + 2 + ncell / 4;
    rel(&b->counts);
    rel(&b->start);
    rel(&b->cursor);
    b->counts = eng_alloc(g, c * sizeof(cl_int), "cell counts");
    b->start = eng_alloc(g, c * sizeof(cl_int), "cell starts");
    b->cursor = eng_alloc(g, c * sizeof(cl_int), "cell cursors");
    b->cap_cells = c;
}

/* List buffers for maxn slots per atom (current list only). */
static void alloc_list(struct gravel *g, struct nbr *b, int maxn)
{
    struct engine *e = g->eng;
    size_t cap = (size_t)e->cap;
    rel(&b->list.nlist);
    rel(&b->list.shear);
    if (!b->list.ncount)
        b->list.ncount = eng_alloc(g, cap * sizeof(cl_int), "neighbor counts");
    b->list.nlist = eng_alloc(g, cap * (size_t)maxn * sizeof(cl_int), "neighbor list");
    if (e->history)
        b->list.shear = eng_alloc(g, cap * (size_t)maxn * 3 * e->rsz, "contact history");
    b->list.maxn = maxn;
}

void nbr_setup(struct gravel *g)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    b->k_check = eng_kernel(g, "nbr_check");
    b->k_wrap = eng_kernel(g, "nbr_wrap_extent");
    b->k_bin = eng_kernel(g, "nbr_bin");
    b->k_scan_partial = eng_kernel(g, "scan_partial");
    b->k_scan_top = eng_kernel(g, "scan_top");
    b->k_scan_final = eng_kernel(g, "scan_final");
    b->k_scatter = eng_kernel(g, "nbr_scatter");
    b->k_cellsort = eng_kernel(g, "nbr_cellsort");
    b->k_reorder = eng_kernel(g, "nbr_reorder");
    b->k_reorder_words = eng_kernel(g, "nbr_reorder_words");
    b->k_build = eng_kernel(g, "nbr_build");
    b->k_overlap = eng_kernel(g, "nbr_overlap");
    if (!b->flags)
        b->flags = eng_alloc(g, 4 * sizeof(cl_int), "neighbor flags");
    if (!b->sums)
        b->sums = eng_alloc(g, (NCHUNK_MAX + 1) * sizeof(cl_int), "scan sums");
    rel(&b->ext);
    b->ext = eng_alloc(g, NCHUNK_MAX * 6 * e->rsz, "extent");
    if (!b->dummy)
        b->dummy = eng_alloc(g, 64, "dummy");
    /* a different capacity, precision or feature set invalidates the kept list */
    if (b->cap_atoms != (size_t)e->cap || b->rsz != e->rsz || b->history != e->history) {
        b->old_valid = 0;
        rel(&b->nlist_old);
        rel(&b->ncount_old);
        rel(&b->shear_old);
        rel(&b->list.ncount);
        grow_atoms(g, b, (size_t)e->cap);
        alloc_list(g, b, b->list.maxn ? b->list.maxn : 16);
        b->rsz = e->rsz;
        b->history = e->history;
    }
    /* exclusions */
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    int *et = gr_calloc(g, (size_t)nt * nt, sizeof(int));
    for (int k = 0; k < g->neigh.nexclude_type; k++) {
        int a = g->neigh.exclude_type[k][0] - 1, c = g->neigh.exclude_type[k][1] - 1;
        if (a >= 0 && c >= 0 && a < nt && c < nt)
            et[a * nt + c] = et[c * nt + a] = 1;
    }
    rel(&b->excl_type);
    b->excl_type = eng_alloc(g, (size_t)nt * nt * sizeof(cl_int), "type exclusions");
    cl_int err = clEnqueueWriteBuffer(e->ocl.queue, b->excl_type, CL_TRUE, 0,
                                      (size_t)nt * nt * sizeof(cl_int), et, 0, NULL, NULL);
    free(et);
    ocl_check(g, err, "clEnqueueWriteBuffer");
    cl_uint eg[32];
    b->nexg = 0;
    for (int k = 0; k < g->neigh.nexclude && k < 16; k++) {
        eg[2 * k] = 1u << g->neigh.exclude_group[k][0];
        eg[2 * k + 1] = 1u << g->neigh.exclude_group[k][1];
        b->nexg++;
    }
    rel(&b->excl_group);
    b->excl_group = eng_alloc(g, sizeof eg, "group exclusions");
    if (b->nexg)
        eng_write(g, b->excl_group, 0, (size_t)b->nexg * 2 * sizeof(cl_uint), eg);
    /* cut-off from the largest radius */
    double rmax = 0;
    for (int i = 0; i < g->atoms.n; i++)
        if (g->atoms.radius[i] > rmax)
            rmax = g->atoms.radius[i];
    b->cutmax = 2 * rmax + g->neigh.skin;
    if (b->cutmax <= 0)
        b->cutmax = 1.0;
    b->ago = 0;
    b->built = 0;
    e->st.nbuilds = e->st.ndanger = 0;
}

static void read_flags(struct gravel *g, struct nbr *b, cl_int out[4])
{
    eng_read(g, b->flags, 0, 4 * sizeof(cl_int), out);
}

static void reset_flags(struct gravel *g, struct nbr *b)
{
    cl_int f[4] = {0, 0x7fffffff, 0, 0};
    eng_write(g, b->flags, 0, sizeof f, f);
}

/* "; probable cause: ..." comparing the time step with the collision time
 * of the contact model (for the non-finite and lost-atoms stops). */
static void probable_cause(struct gravel *g, char *cause, size_t len)
{
    const struct pair *p = g->styles.pair;
    if (p && p->style->collision_time && g->atoms.n > 0) {
        double m = 0, r = 0, vmax = 0;
        /* lightest particle of the host copy (run start) */
        for (int k = 0; k < g->atoms.n; k++) {
            if (m == 0 || g->atoms.rmass[k] < m) {
                m = g->atoms.rmass[k];
                r = g->atoms.radius[k];
            }
            for (int d = 0; d < 3; d++)
                vmax = fmax(vmax, fabs(g->atoms.v[3 * k + d]));
        }
        double tc = p->style->collision_time(p, m, r, vmax > 0 ? 2 * vmax : 0);
        snprintf(cause, len,
                 "; probable cause: the time step %g vs the estimated collision time %g of "
                 "pair style %s (%.3g steps per collision; at least ~10 are needed)",
                 g->dt, tc, p->style->name, tc / g->dt);
    } else {
        snprintf(cause, len, "; probable cause: a time step (%g) too large for the forces, or "
                             "overlapping particles in the initial configuration", g->dt);
    }
}

/* Stop on non-finite atom index i with the step, tag and the likely cause. */
static void nonfinite_error(struct gravel *g, int i)
{
    struct engine *e = g->eng;
    long long tag = 0;
    eng_read(g, e->a.tag, (size_t)i * sizeof(cl_long), sizeof(cl_long), &tag);
    char cause[400];
    probable_cause(g, cause, sizeof cause);
    gr_error(g, "non-finite position or velocity of atom %lld at step %lld%s", tag,
             (long long)g->step, cause);
}

int nbr_decide(struct gravel *g)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    int n = e->a.n;
    double trig = 0.5 * g->neigh.skin;
    reset_flags(g, b);
    cl_kernel k = b->k_check;
    eng_arg_int(g, k, 0, n);
    eng_arg_mem(g, k, 1, e->a.x);
    eng_arg_mem(g, k, 2, e->a.v);
    eng_arg_mem(g, k, 3, b->xhold);
    eng_arg_real(g, k, 4, trig * trig);
    eng_arg_mem(g, k, 5, b->flags);
    eng_launch(g, k, (size_t)n);
    cl_int fl[4];
    read_flags(g, b, fl);
    if (fl[1] != 0x7fffffff)
        nonfinite_error(g, fl[1]);
    b->ago++;
    int every = g->neigh.every > 0 ? g->neigh.every : 1;
    if (b->ago >= g->neigh.delay && b->ago % every == 0) {
        if (g->neigh.once)
            return 0;
        if (!g->neigh.check)
            return 1;
        if (fl[0]) {
            int first = every > g->neigh.delay ? every : g->neigh.delay;
            if (b->ago == first)
                e->st.ndanger++;
            return 1;
        }
    }
    return 0;
}

static void wrap_and_extent(struct gravel *g, struct nbr *b)
{
    struct engine *e = g->eng;
    struct domain *d = &g->dom;
    int n = e->a.n;
    int chunk = (n + NCHUNK_MAX - 1) / NCHUNK_MAX;
    if (chunk < 1)
        chunk = 1;
    int nch = (n + chunk - 1) / chunk;
    cl_kernel k = b->k_wrap;
    eng_arg_int(g, k, 0, n);
    eng_arg_int(g, k, 1, chunk);
    eng_arg_mem(g, k, 2, e->a.x);
    eng_arg_mem(g, k, 3, e->a.image);
    for (int q = 0; q < 3; q++)
        eng_arg_int(g, k, 4 + q, d->periodic[q]);
    for (int q = 0; q < 3; q++) {
        eng_arg_real(g, k, 7 + q, d->lo[q]);
        eng_arg_real(g, k, 10 + q, d->hi[q]);
    }
    eng_arg_mem(g, k, 13, b->ext);
    if (nch < 1)
        return;
    eng_launch(g, k, (size_t)nch);
    int shrink = 0;
    for (int q = 0; q < 3; q++)
        if (!d->periodic[q] && (d->bnd[q][0] != BND_F || d->bnd[q][1] != BND_F))
            shrink = 1;
    if (!shrink)
        return;
    double *ext = gr_malloc(g, (size_t)nch * 6 * sizeof(double));
    eng_read_reals(g, b->ext, (size_t)nch * 6, ext);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int c = 0; c < nch; c++)
        for (int q = 0; q < 3; q++) {
            lo[q] = fmin(lo[q], ext[6 * c + q]);
            hi[q] = fmax(hi[q], ext[6 * c + 3 + q]);
        }
    free(ext);
    domain_shrink_wrap(g, lo, hi);
}

/* Cell grid over the current box. */
static void make_grid(struct gravel *g, struct nbr *b, int n)
{
    struct domain *d = &g->dom;
    double cut = b->cutmax;
    for (;;) {
        long total = 1;
        for (int q = 0; q < 3; q++) {
            double L = d->hi[q] - d->lo[q];
            int nc = (int)(L / cut);
            if (nc < 1)
                nc = 1;
            if (nc > 1 << 20)
                nc = 1 << 20;
            b->nc[q] = nc;
            total *= nc;
        }
        if (total <= 8L * n + 4096 || total <= 1)
            break;
        cut *= 1.25; /* a sparse scene: fewer, larger cells */
    }
    b->ncell = b->nc[0] * b->nc[1] * b->nc[2];
    for (int q = 0; q < 3; q++) {
        b->lo[q] = d->lo[q];
        b->hi[q] = d->hi[q];
        b->inv[q] = b->nc[q] / (d->hi[q] - d->lo[q]);
        b->list.L[q] = d->periodic[q] ? d->hi[q] - d->lo[q] : 0.0;
        if (d->periodic[q] && d->hi[q] - d->lo[q] < 2 * b->cutmax)
            gr_error(g, "periodic box length %g in %c is less than twice the neighbor cut-off "
                        "%g (2 x largest radius + skin)", d->hi[q] - d->lo[q], "xyz"[q],
                     b->cutmax);
    }
}

static void build_list(struct gravel *g, struct nbr *b)
{
    struct engine *e = g->eng;
    int n = e->a.n;
    for (;;) {
        reset_flags(g, b);
        cl_kernel k = b->k_build;
        int a = 0;
        eng_arg_int(g, k, a++, n);
        eng_arg_mem(g, k, a++, e->a.x);
        eng_arg_mem(g, k, a++, e->a.radius);
        eng_arg_mem(g, k, a++, e->a.type);
        eng_arg_mem(g, k, a++, e->a.mask);
        eng_arg_mem(g, k, a++, e->a.tag);
        eng_arg_mem(g, k, a++, b->start);
        for (int q = 0; q < 3; q++)
            eng_arg_int(g, k, a++, b->nc[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_int(g, k, a++, g->dom.periodic[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_real(g, k, a++, b->lo[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_real(g, k, a++, b->inv[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_real(g, k, a++, b->list.L[q]);
        eng_arg_real(g, k, a++, g->neigh.skin);
        eng_arg_int(g, k, a++, b->list.maxn);
        eng_arg_mem(g, k, a++, b->list.nlist);
        eng_arg_mem(g, k, a++, b->list.ncount);
        eng_arg_mem(g, k, a++, b->flags);
        eng_arg_int(g, k, a++, g->atoms.ntypes > 0 ? g->atoms.ntypes : 1);
        eng_arg_mem(g, k, a++, b->excl_type);
        eng_arg_int(g, k, a++, b->nexg);
        eng_arg_mem(g, k, a++, b->excl_group);
        int hist = !e->history ? 0 : (b->old_valid && b->nlist_old) ? 2 : 1;
        eng_arg_int(g, k, a++, hist);
        eng_arg_mem(g, k, a++, b->perm);
        eng_arg_mem(g, k, a++, hist == 2 ? b->nlist_old : b->dummy);
        eng_arg_mem(g, k, a++, hist == 2 ? b->ncount_old : b->dummy);
        eng_arg_int(g, k, a++, hist == 2 ? b->maxn_old : 0);
        eng_arg_mem(g, k, a++, e->b.tag); /* tags in the old order */
        eng_arg_mem(g, k, a++, hist == 2 ? b->shear_old : b->dummy);
        eng_arg_mem(g, k, a++, e->history ? b->list.shear : b->dummy);
        eng_launch(g, k, (size_t)n);
        cl_int fl[4];
        read_flags(g, b, fl);
        if (fl[2] <= b->list.maxn)
            break;
        int maxn = fl[2] + fl[2] / 4 + 4;
        gr_print(g, "Neighbor list capacity grown from %d to %d per atom\n", b->list.maxn, maxn);
        cl_mem keep_count = b->list.ncount;
        b->list.ncount = NULL;
        alloc_list(g, b, maxn);
        rel(&keep_count);
    }
}

void nbr_rebuild(struct gravel *g)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    int n = e->a.n;
    wrap_and_extent(g, b);
    make_grid(g, b, n);
    grow_cells(g, b, (size_t)b->ncell);
    int m = b->ncell + 1; /* + sentinel cell of lost atoms */
    eng_fill_zero(g, b->counts, (size_t)m * sizeof(cl_int));
    cl_kernel k = b->k_bin;
    eng_arg_int(g, k, 0, n);
    eng_arg_mem(g, k, 1, e->a.x);
    for (int q = 0; q < 3; q++)
        eng_arg_int(g, k, 2 + q, b->nc[q]);
    for (int q = 0; q < 3; q++) {
        eng_arg_real(g, k, 5 + q, b->lo[q]);
        eng_arg_real(g, k, 8 + q, b->hi[q]);
        eng_arg_real(g, k, 11 + q, b->inv[q]);
    }
    eng_arg_mem(g, k, 14, b->cellof);
    eng_arg_mem(g, k, 15, b->counts);
    eng_launch(g, k, (size_t)n);
    nbr_scan(g, b->counts, b->start, m);
    cl_int nkeep = n;
    eng_read(g, b->start, (size_t)b->ncell * sizeof(cl_int), sizeof nkeep, &nkeep);
    if (nkeep < n) {
        char cause[400];
        probable_cause(g, cause, sizeof cause);
        if (g->thermo.lost == LOST_ERROR)
            gr_error(g, "Lost atoms: original %d current %d (step %lld: atoms left the box "
                        "through a fixed boundary or moved more than a box length in one step"
                        "%s; thermo_modify lost ignore|warn keeps going)",
                     n, (int)nkeep, (long long)g->step, cause);
        if (g->thermo.lost == LOST_WARN)
            gr_warn(g, "Lost atoms: original %d current %d (step %lld)", n, (int)nkeep,
                    (long long)g->step);
    }
    eng_fill_zero(g, b->cursor, (size_t)m * sizeof(cl_int));
    k = b->k_scatter;
    eng_arg_int(g, k, 0, n);
    eng_arg_mem(g, k, 1, b->cellof);
    eng_arg_mem(g, k, 2, b->start);
    eng_arg_mem(g, k, 3, b->cursor);
    eng_arg_mem(g, k, 4, b->perm);
    eng_launch(g, k, (size_t)n);
    k = b->k_cellsort;
    eng_arg_int(g, k, 0, b->ncell);
    eng_arg_mem(g, k, 1, b->start);
    eng_arg_mem(g, k, 2, b->perm);
    eng_arg_mem(g, k, 3, e->a.tag);
    eng_launch(g, k, (size_t)b->ncell);
    /* gather into set b, then swap: b holds the old order afterwards */
    k = b->k_reorder;
    struct dev_atoms *s0 = &e->a, *s1 = &e->b;
    int a = 0;
    eng_arg_int(g, k, a++, nkeep);
    eng_arg_mem(g, k, a++, b->perm);
    eng_arg_mem(g, k, a++, s0->x);
    eng_arg_mem(g, k, a++, s1->x);
    eng_arg_mem(g, k, a++, s0->v);
    eng_arg_mem(g, k, a++, s1->v);
    eng_arg_mem(g, k, a++, e->rotation ? s0->omega : s0->v);
    eng_arg_mem(g, k, a++, e->rotation ? s1->omega : s1->v);
    eng_arg_mem(g, k, a++, s0->radius);
    eng_arg_mem(g, k, a++, s1->radius);
    eng_arg_mem(g, k, a++, s0->rmass);
    eng_arg_mem(g, k, a++, s1->rmass);
    eng_arg_mem(g, k, a++, s0->type);
    eng_arg_mem(g, k, a++, s1->type);
    eng_arg_mem(g, k, a++, s0->mask);
    eng_arg_mem(g, k, a++, s1->mask);
    eng_arg_mem(g, k, a++, s0->tag);
    eng_arg_mem(g, k, a++, s1->tag);
    eng_arg_mem(g, k, a++, s0->image);
    eng_arg_mem(g, k, a++, s1->image);
    eng_launch(g, k, (size_t)nkeep);
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (!f->peratom)
            continue;
        k = b->k_reorder_words;
        eng_arg_int(g, k, 0, nkeep);
        eng_arg_int(g, k, 1, (int)(f->peratom_bytes / 4));
        eng_arg_mem(g, k, 2, b->perm);
        eng_arg_mem(g, k, 3, f->peratom);
        eng_arg_mem(g, k, 4, f->peratom_tmp);
        eng_launch(g, k, (size_t)nkeep);
        cl_mem t = f->peratom;
        f->peratom = f->peratom_tmp;
        f->peratom_tmp = t;
    }
    eng_swap(e);
    e->a.n = e->b.n = nkeep;
    /* the current list becomes the old one (for history transfer) */
    if (e->history && b->old_valid) {
        cl_mem t;
        t = b->nlist_old, b->nlist_old = b->list.nlist, b->list.nlist = t;
        t = b->shear_old, b->shear_old = b->list.shear, b->list.shear = t;
        t = b->ncount_old, b->ncount_old = b->list.ncount, b->list.ncount = t;
        int mo = b->maxn_old;
        b->maxn_old = b->list.maxn;
        if (!b->list.nlist || !b->list.shear || !b->list.ncount || mo != b->maxn_old) {
            rel(&b->list.nlist);
            rel(&b->list.shear);
            alloc_list(g, b, b->maxn_old);
        }
    }
    build_list(g, b);
    if (e->history)
        b->old_valid = 1;
    if (nkeep > 0)
        OCL_CHECK(g, clEnqueueCopyBuffer(e->ocl.queue, e->a.x, b->xhold, 0, 0,
                                         3 * (size_t)nkeep * e->rsz, 0, NULL, NULL));
    b->ago = 0;
    b->built = 1;
    e->st.nbuilds++;
}

double nbr_total(struct gravel *g)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    int n = e->a.n;
    if (!b->built || n == 0)
        return 0;
    cl_int *c = gr_malloc(g, (size_t)n * sizeof(cl_int));
    cl_int err = clEnqueueReadBuffer(e->ocl.queue, b->list.ncount, CL_TRUE, 0,
                                     (size_t)n * sizeof(cl_int), c, 0, NULL, NULL);
    double s = 0;
    if (err == CL_SUCCESS)
        for (int i = 0; i < n; i++)
            s += c[i];
    free(c);
    ocl_check(g, err, "clEnqueueReadBuffer");
    return s;
}

double nbr_max_overlap(struct gravel *g)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    int n = e->a.n;
    if (!b->built || n == 0)
        return 0;
    int chunk = (n + NCHUNK_MAX - 1) / NCHUNK_MAX;
    int nch = (n + chunk - 1) / chunk;
    cl_kernel k = b->k_overlap;
    eng_arg_int(g, k, 0, n);
    eng_arg_int(g, k, 1, chunk);
    eng_arg_mem(g, k, 2, e->a.x);
    eng_arg_mem(g, k, 3, e->a.radius);
    eng_arg_mem(g, k, 4, b->list.nlist);
    eng_arg_mem(g, k, 5, b->list.ncount);
    eng_arg_int(g, k, 6, b->list.maxn);
    for (int q = 0; q < 3; q++)
        eng_arg_real(g, k, 7 + q, b->list.L[q]);
    eng_arg_mem(g, k, 10, b->ext);
    eng_launch(g, k, (size_t)nch);
    double v[NCHUNK_MAX];
    eng_read_reals(g, b->ext, (size_t)nch, v);
    double best = 0;
    for (int c = 0; c < nch; c++)
        best = fmax(best, v[c]);
    return best;
}

/* ---- restart support (restart.c) ------------------------------------------ */

void nbr_state_free(struct nbr_state *s)
{
    free(s->ncount);
    free(s->nlist);
    free(s->shear);
    free(s->xhold);
    memset(s, 0, sizeof *s);
}

int nbr_export(struct gravel *g, struct nbr_state *s)
{
    memset(s, 0, sizeof *s);
    struct engine *e = g->eng;
    if (!e || !e->nbr || !e->nbr->built)
        return 0;
    struct nbr *b = e->nbr;
    int n = e->a.n, maxn = b->list.maxn;
    s->n = n;
    s->maxn = maxn;
    s->ago = b->ago;
    s->history = e->history;
    s->ncount = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
    s->nlist = gr_malloc(g, ((size_t)n * maxn + 1) * sizeof(int));
    s->xhold = gr_malloc(g, (3 * (size_t)n + 1) * sizeof(double));
    if (e->history)
        s->shear = gr_malloc(g, (3 * (size_t)n * maxn + 1) * sizeof(double));
    eng_read(g, b->list.ncount, 0, (size_t)n * sizeof(cl_int), s->ncount);
    eng_read(g, b->list.nlist, 0, (size_t)n * maxn * sizeof(cl_int), s->nlist);
    eng_read_reals(g, b->xhold, 3 * (size_t)n, s->xhold);
    if (e->history)
        eng_read_reals(g, b->list.shear, 3 * (size_t)n * maxn, s->shear);
    return 1;
}

void nbr_import(struct gravel *g, const struct nbr_state *s)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    int n = e->a.n;
    int maxn = s->maxn > 0 ? s->maxn : 1;
    if (s->n != n)
        gr_error(g, "restart: neighbor list of %d atoms for %d atoms on the device", s->n, n);
    alloc_list(g, b, maxn);
    eng_write(g, b->list.ncount, 0, (size_t)n * sizeof(cl_int), s->ncount);
    eng_write(g, b->list.nlist, 0, (size_t)n * maxn * sizeof(cl_int), s->nlist);
    if (e->history) {
        if (s->shear)
            eng_write_reals(g, b->list.shear, 3 * (size_t)n * maxn, s->shear);
        else
            eng_fill_zero(g, b->list.shear, (size_t)n * maxn * 3 * e->rsz);
    }
    eng_write_reals(g, b->xhold, 3 * (size_t)n, s->xhold);
    for (int q = 0; q < 3; q++)
        b->list.L[q] = g->dom.periodic[q] ? g->dom.hi[q] - g->dom.lo[q] : 0.0;
    b->ago = s->ago;
    b->built = 1;
    b->old_valid = e->history;
}
