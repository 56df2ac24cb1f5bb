/* neighbor.c - host side of the device neighbor lists (kernels/neighbor.cl).
 *
 * A rebuild: wrap periodic positions and reduce the atom extent (one pass),
 * shrink-wrap the box, bin atoms into cells of size >= 2 r_max + skin
 * (atoms outside a fixed face go to a sentinel cell and are lost), scan the
 * cell counts, scatter and sort each cell by tag (deterministic), gather the
 * per-atom arrays into the new order one by one through a scratch buffer
 * (when a re-sort is due, atom_modify sort), build the full list in partner
 * tag order (a list longer than the capacity grows it and builds again),
 * then the contacts (one per pair, owned by the lower tag) and their history
 * from the previous contacts of the same owner and partner. */
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
    /* contacts of the previous build, for the history transfer: offsets,
     * and (during a rebuild only) partners and history parked in the force
     * record buffer recf, which is free then (old_cj_at: offset of the
     * partners, in ints) */
    cl_mem coff_old;
    int ncontact_old;
    size_t old_cj_at;
    size_t cap_pair, cap_contact;
    int old_valid;              /* the previous contacts index the atoms before this build */
    int built;                  /* a list exists for the current run */
    cl_mem xhold, cellof, perm, counts, start, cursor, sums, flags, ext, excl_type,
        excl_group;
    size_t cap_atoms, cap_cells;
    size_t rsz;
    int history, rotation;
    int ncell, nc[3];
    double cutmax, lo[3], hi[3], inv[3];
    int nexg;
    int ago;
    bigint last_sort;           /* step of the last re-sort (atom_modify sort) */
    cl_kernel k_check, k_wrap, k_bin, k_scan_partial, k_scan_top, k_scan_final, k_scatter,
        k_cellsort, k_reorder_words, k_build, k_contacts, k_invperm, k_hist_rename,
        k_hist_transfer, k_overlap;
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
    struct nbr_list *l = &b->list;
    cl_mem *m[] = {&l->nlist, &l->ncount, &l->nown, &l->ioff, &l->coff, &l->ci, &l->cj,
                   &l->cslot, &l->shear, &l->recf, &l->rect, &b->coff_old,
                   &b->xhold, &b->cellof, &b->perm, &b->counts, &b->start, &b->cursor,
                   &b->sums, &b->flags, &b->ext, &b->excl_type, &b->excl_group};
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
    struct nbr_list *l = &b->list;
    cl_mem *m[] = {&b->xhold, &b->cellof, &b->perm, &l->ncount, &l->nown, &l->coff,
                   &l->ioff, &b->coff_old};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++)
        rel(m[i]);
    b->xhold = eng_alloc(g, 3 * n * r, "neighbor reference positions");
    b->cellof = eng_alloc(g, n * sizeof(cl_int), "cell of atom");
    b->perm = eng_alloc(g, n * sizeof(cl_int), "sort permutation");
    l->ncount = eng_alloc(g, n * sizeof(cl_int), "neighbor counts");
    l->nown = eng_alloc(g, n * sizeof(cl_int), "owned contact counts");
    l->coff = eng_alloc(g, (n + 1) * sizeof(cl_int), "contact offsets");
    l->ioff = eng_alloc(g, (n + 1) * sizeof(cl_int), "incidence offsets");
    b->coff_old = eng_alloc(g, (n + 1) * sizeof(cl_int), "contact offsets");
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

/* Row buffers for maxn slots per atom. */
static void alloc_list(struct gravel *g, struct nbr *b, int maxn)
{
    size_t cap = (size_t)g->eng->cap;
    rel(&b->list.nlist);
    b->list.nlist = eng_alloc(g, cap * (size_t)maxn * sizeof(cl_int), "neighbor list");
    b->list.maxn = maxn;
}

/* Bytes of one buffer of incidence records per contact: both sides'
 * forces (recf), or both sides' torques (rect) (kernels/pair_loop.cl). */
static size_t cf_bytes(const struct engine *e) { return 6 * e->rsz; }

static size_t grown(size_t nc) { return nc + nc / 8 + 64; }

/* Contact buffers for at least nc contacts (contents not kept): ci, cj
 * cslot and shear (cap_contact); the incidence records recf, rect (cap_pair) separately,
 * after the history transfer has read what was parked there. */
static void alloc_contacts(struct gravel *g, struct nbr *b, size_t nc)
{
    struct engine *e = g->eng;
    struct nbr_list *l = &b->list;
    if (nc > b->cap_contact || !l->ci) {
        rel(&l->ci);
        rel(&l->cj);
        rel(&l->cslot);
        rel(&l->shear);
        b->cap_contact = grown(nc);
        l->ci = eng_alloc(g, b->cap_contact * sizeof(cl_int), "contact owners");
        l->cj = eng_alloc(g, b->cap_contact * sizeof(cl_int), "contact partners");
        l->cslot = eng_alloc(g, b->cap_contact * 2 * sizeof(cl_int), "contact incidences");
        if (e->history)
            l->shear = eng_alloc(g, b->cap_contact * 3 * e->rsz, "contact history");
    }
}

static void alloc_forces(struct gravel *g, struct nbr *b, size_t nc)
{
    struct nbr_list *l = &b->list;
    if (nc > b->cap_pair || !l->recf) {
        rel(&l->recf);
        rel(&l->rect);
        b->cap_pair = grown(nc);
        l->recf = eng_alloc(g, b->cap_pair * cf_bytes(g->eng), "incidence force records");
        if (g->eng->rotation)
            l->rect = eng_alloc(g, b->cap_pair * cf_bytes(g->eng), "incidence torque records");
    }
}

/* The current contacts become the previous ones: offsets swap, partners
 * and history are parked in the force record buffer (history 3 REAL per
 * contact from byte 0, then the partners; 6 REAL per contact hold both). */
static void retire_contacts(struct gravel *g, struct nbr *b)
{
    struct engine *e = g->eng;
    struct nbr_list *l = &b->list;
    cl_mem t = b->coff_old;
    b->coff_old = l->coff;
    l->coff = t;
    b->ncontact_old = l->ncontact;
    size_t nc = (size_t)l->ncontact, hist = nc * 3 * e->rsz;
    b->old_cj_at = (hist + sizeof(cl_int) - 1) / sizeof(cl_int);
    if (nc == 0)
        return;
    if (b->old_cj_at * sizeof(cl_int) + nc * sizeof(cl_int) > b->cap_pair * cf_bytes(e))
        gr_error(g, "internal error: the force buffer cannot hold the previous contacts");
    OCL_CHECK(g, clEnqueueCopyBuffer(e->ocl.queue, l->shear, l->recf, 0, 0, hist, 0, NULL, NULL));
    OCL_CHECK(g, clEnqueueCopyBuffer(e->ocl.queue, l->cj, l->recf, 0,
                                     b->old_cj_at * sizeof(cl_int), nc * sizeof(cl_int), 0,
                                     NULL, NULL));
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
    b->k_reorder_words = eng_kernel(g, "nbr_reorder_words");
    b->k_build = eng_kernel(g, "nbr_build");
    b->k_contacts = eng_kernel(g, "nbr_contacts");
    b->k_invperm = eng_kernel(g, "nbr_invperm");
    b->k_hist_rename = eng_kernel(g, "hist_rename");
    b->k_hist_transfer = eng_kernel(g, "hist_transfer");
    b->k_overlap = eng_kernel(g, "nbr_overlap");
    if (!b->flags)
        b->flags = eng_alloc(g, 4 * sizeof(cl_int), "neighbor flags");
    if (!b->sums)
        b->sums = eng_alloc(g, (NCHUNK_MAX + 1) * sizeof(cl_int), "scan sums");
    rel(&b->ext);
    b->ext = eng_alloc(g, NCHUNK_MAX * 6 * e->rsz, "extent");
    /* a different capacity, precision or feature set invalidates the kept list */
    if (b->cap_atoms != (size_t)e->cap || b->rsz != e->rsz || b->history != e->history) {
        b->old_valid = 0;
        b->built = 0;
        struct nbr_list *l = &b->list;
        cl_mem *m[] = {&l->ci, &l->cj, &l->cslot, &l->shear, &l->recf, &l->rect};
        for (size_t i = 0; i < sizeof m / sizeof *m; i++)
            rel(m[i]);
        b->cap_pair = b->cap_contact = 0;
        l->ncontact = b->ncontact_old = 0;
        grow_atoms(g, b, (size_t)e->cap);
        alloc_list(g, b, b->list.maxn ? b->list.maxn : 8); /* grows on overflow */
        b->rsz = e->rsz;
        b->history = e->history;
        b->rotation = e->rotation;
    }
    if (b->rotation != e->rotation) { /* torque records appear or go */
        rel(&b->list.rect);
        if (e->rotation)
            b->list.rect = eng_alloc(g, (b->cap_pair ? b->cap_pair : 1) * cf_bytes(e),
                                     "incidence torque records");
        b->rotation = e->rotation;
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
    double rmax = e->insert_rmax; /* atoms fixes may insert (fix pour) */
    for (int i = 0; i < g->atoms.n; i++)
        if (g->atoms.radius[i] > rmax)
            rmax = g->atoms.radius[i];
    b->cutmax = pair_reach(g, 2 * rmax) + g->neigh.skin; /* cohesion: effect range */
    if (b->cutmax <= 0)
        b->cutmax = 1.0;
    b->ago = 0;
    b->built = 0;
    b->last_sort = g->step;
    e->st.nbuilds = e->st.ndanger = 0;
}

static void read_flags(struct gravel *g, struct nbr *b, cl_int out[4])
{
    eng_read(g, b->flags, 0, 4 * sizeof(cl_int), out);
}

/* flags = {0, INT_MAX, 0, 0}, queued without waiting (the pattern buffer is
 * copied at enqueue). */
static void reset_flags(struct gravel *g, struct nbr *b)
{
    cl_int zero = 0, big = 0x7fffffff;
    OCL_CHECK(g, clEnqueueFillBuffer(g->eng->ocl.queue, b->flags, &zero, sizeof zero, 0,
                                     4 * sizeof(cl_int), 0, NULL, NULL));
    OCL_CHECK(g, clEnqueueFillBuffer(g->eng->ocl.queue, b->flags, &big, sizeof big,
                                     sizeof(cl_int), sizeof(cl_int), 0, NULL, NULL));
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

int nbr_decide(struct gravel *g, int forced)
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
    eng_arg_mem(g, k, 6, e->a.image);
    for (int q = 0; q < 3; q++)
        eng_arg_coord(g, k, 7 + q, q, g->dom.lo[q]);
    for (int q = 0; q < 3; q++)
        eng_arg_coord(g, k, 10 + q, q, g->dom.hi[q]);
    for (int q = 0; q < 3; q++)
        eng_arg_real(g, k, 13 + q, g->dom.periodic[q] ? g->dom.hi[q] - g->dom.lo[q] : 0.0);
    /* the fused initial_integrate ops (src/fused.h) run first */
    int a = 16;
    eng_arg_mem(g, k, a++, e->fused.ops);
    eng_arg_int(g, k, a++, e->fused.ninit);
    eng_arg_mem(g, k, a++, e->fused.prm);
    eng_arg_mem(g, k, a++, e->a.f);
    eng_arg_mem(g, k, a++, e->rotation ? e->a.omega : e->a.v);
    eng_arg_mem(g, k, a++, e->rotation ? e->a.torque : e->a.f);
    eng_arg_mem(g, k, a++, e->a.rmass);
    eng_arg_mem(g, k, a++, e->a.radius);
    eng_arg_mem(g, k, a++, e->a.type);
    eng_arg_mem(g, k, a++, e->a.mask);
    eng_arg_pos_lo(g, k, a);
    eng_launch(g, k, (size_t)n);
    cl_int fl[4];
    read_flags(g, b, fl);
    if (fl[1] != 0x7fffffff)
        nonfinite_error(g, fl[1]);
    if (forced)
        return 1;
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

void nbr_atoms_appended(struct gravel *g, int nold, int nnew)
{
    struct nbr *b = get(g);
    struct nbr_list *l = &b->list;
    /* the previous contacts' offsets (coff becomes coff_old at the rebuild)
     * end at nold: the new atoms' ranges are empty */
    if (!g->eng->history || !b->old_valid || nnew <= nold || !l->coff)
        return;
    if ((size_t)nnew + 1 > b->cap_atoms + 1)
        gr_error(g, "internal error: %d atoms beyond the neighbor capacity %zu", nnew,
                 b->cap_atoms);
    cl_int end = 0;
    eng_read(g, l->coff, (size_t)nold * sizeof(cl_int), sizeof end, &end);
    OCL_CHECK(g, clEnqueueFillBuffer(g->eng->ocl.queue, l->coff, &end, sizeof end,
                                     (size_t)(nold + 1) * sizeof(cl_int),
                                     (size_t)(nnew - nold) * sizeof(cl_int), 0, NULL, NULL));
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
        eng_arg_coord(g, k, 7 + q, q, d->lo[q]);
        eng_arg_coord(g, k, 10 + q, q, d->hi[q]);
    }
    eng_arg_mem(g, k, 13, b->ext);
    eng_arg_pos_lo(g, k, 14);
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
            lo[q] = fmin(lo[q], e->origin[q] + ext[6 * c + q]);
            hi[q] = fmax(hi[q], e->origin[q] + ext[6 * c + 3 + q]);
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

/* The full list in partner-tag order; cells list their atoms in b->perm
 * unless the atoms were just re-sorted (sorted: contiguous ranges). */
static void build_list(struct gravel *g, struct nbr *b, int sorted)
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
        eng_arg_mem(g, k, a++, b->perm);
        eng_arg_int(g, k, a++, sorted);
        for (int q = 0; q < 3; q++)
            eng_arg_int(g, k, a++, b->nc[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_int(g, k, a++, g->dom.periodic[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_coord(g, k, a++, q, b->lo[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_real(g, k, a++, b->inv[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_real(g, k, a++, b->list.L[q]);
        eng_arg_real(g, k, a++, g->neigh.skin);
        eng_arg_int(g, k, a++, b->list.maxn);
        eng_arg_mem(g, k, a++, b->list.nlist);
        eng_arg_mem(g, k, a++, b->list.ncount);
        eng_arg_mem(g, k, a++, b->list.nown);
        eng_arg_mem(g, k, a++, b->flags);
        eng_arg_int(g, k, a++, g->atoms.ntypes > 0 ? g->atoms.ntypes : 1);
        eng_arg_mem(g, k, a++, b->excl_type);
        eng_arg_int(g, k, a++, b->nexg);
        eng_arg_mem(g, k, a++, b->excl_group);
        eng_launch(g, k, (size_t)n);
        cl_int fl[4];
        read_flags(g, b, fl);
        if (fl[2] <= b->list.maxn)
            break;
        int maxn = fl[2] + fl[2] / 4 + 4;
        gr_print(g, "Neighbor list capacity grown from %d to %d per atom\n", b->list.maxn, maxn);
        alloc_list(g, b, maxn);
    }
}

/* Contacts of the rows just built: offsets (scan of the owned counts),
 * owners, partners, incidence; then their history. */
static void build_contacts(struct gravel *g, struct nbr *b, int permuted)
{
    struct engine *e = g->eng;
    struct nbr_list *l = &b->list;
    int n = e->a.n;
    nbr_scan(g, l->nown, l->coff, n);
    nbr_scan(g, l->ncount, l->ioff, n); /* rows packed: 2 incidences per contact */
    cl_int total = 0;
    eng_read(g, l->coff, (size_t)n * sizeof(cl_int), sizeof total, &total);
    alloc_contacts(g, b, (size_t)total);
    l->ncontact = total;
    reset_flags(g, b);
    cl_kernel k = b->k_contacts;
    int a = 0;
    eng_arg_int(g, k, a++, n);
    eng_arg_int(g, k, a++, l->maxn);
    eng_arg_mem(g, k, a++, l->nlist);
    eng_arg_mem(g, k, a++, l->ncount);
    eng_arg_mem(g, k, a++, l->nown);
    eng_arg_mem(g, k, a++, l->coff);
    eng_arg_mem(g, k, a++, l->ioff);
    eng_arg_mem(g, k, a++, e->a.tag);
    eng_arg_mem(g, k, a++, l->ci);
    eng_arg_mem(g, k, a++, l->cj);
    eng_arg_mem(g, k, a++, l->cslot);
    eng_arg_mem(g, k, a++, b->flags);
    eng_launch(g, k, (size_t)n);
    cl_int fl[4];
    read_flags(g, b, fl);
    if (fl[3])
        gr_error(g, "internal error: the neighbor list is not symmetric (a pair is missing "
                    "from one partner's row) at step %lld", (long long)g->step);
    if (e->history && (!b->old_valid || b->ncontact_old == 0))
        eng_fill_zero(g, l->shear, (size_t)total * 3 * e->rsz);
    if (!e->history || !b->old_valid || b->ncontact_old == 0) {
        alloc_forces(g, b, (size_t)total);
        return;
    }
    k = b->k_hist_transfer;
    a = 0;
    eng_arg_int(g, k, a++, total);
    eng_arg_mem(g, k, a++, l->ci);
    eng_arg_mem(g, k, a++, l->cj);
    eng_arg_mem(g, k, a++, b->perm);
    eng_arg_int(g, k, a++, permuted);
    eng_arg_mem(g, k, a++, b->coff_old);
    eng_arg_mem(g, k, a++, l->recf);
    eng_arg_int(g, k, a++, (int)b->old_cj_at);
    eng_arg_mem(g, k, a++, l->recf);
    eng_arg_mem(g, k, a++, l->shear);
    eng_launch(g, k, (size_t)total);
    alloc_forces(g, b, (size_t)total); /* after the transfer read the parked contacts */
}

/* Gather one per-atom array (bytes per atom) into the new order through the
 * force buffer, free scratch during a rebuild (the forces of the step are
 * computed after it), and copy it back. */
static void reorder_array(struct gravel *g, struct nbr *b, cl_mem m, size_t bytes, int n)
{
    struct engine *e = g->eng;
    if (n == 0)
        return;
    cl_kernel k = b->k_reorder_words;
    eng_arg_int(g, k, 0, n);
    eng_arg_int(g, k, 1, (int)(bytes / 4));
    eng_arg_mem(g, k, 2, b->perm);
    eng_arg_mem(g, k, 3, m);
    eng_arg_mem(g, k, 4, e->a.f);
    eng_launch(g, k, (size_t)n);
    OCL_CHECK(g, clEnqueueCopyBuffer(e->ocl.queue, e->a.f, m, 0, 0, (size_t)n * bytes, 0, NULL,
                                     NULL));
}

/* Re-sort every per-atom array (and the fixes' per-atom state) by b->perm,
 * keeping nkeep atoms; the previous contacts are renamed into the new order
 * for the history transfer. */
static void resort_atoms(struct gravel *g, struct nbr *b, int n, int nkeep)
{
    struct engine *e = g->eng;
    struct dev_atoms *s = &e->a;
    size_t r = e->rsz;
    if (e->history && b->old_valid && b->ncontact_old > 0) {
        /* cellof is free now: it becomes the inverse permutation */
        OCL_CHECK(g, clEnqueueFillBuffer(e->ocl.queue, b->cellof, &(cl_int){-1},
                                         sizeof(cl_int), 0, (size_t)n * sizeof(cl_int), 0,
                                         NULL, NULL));
        cl_kernel k = b->k_invperm;
        eng_arg_int(g, k, 0, nkeep);
        eng_arg_mem(g, k, 1, b->perm);
        eng_arg_mem(g, k, 2, b->cellof);
        eng_launch(g, k, (size_t)nkeep);
        k = b->k_hist_rename;
        eng_arg_int(g, k, 0, b->ncontact_old);
        eng_arg_mem(g, k, 1, b->cellof);
        eng_arg_mem(g, k, 2, b->list.recf);
        eng_arg_int(g, k, 3, (int)b->old_cj_at);
        eng_launch(g, k, (size_t)b->ncontact_old);
    }
    reorder_array(g, b, s->x, 3 * r, nkeep);
    if (s->xlo)
        reorder_array(g, b, s->xlo, 3 * r, nkeep);
    reorder_array(g, b, s->v, 3 * r, nkeep);
    if (e->rotation)
        reorder_array(g, b, s->omega, 3 * r, nkeep);
    reorder_array(g, b, s->radius, r, nkeep);
    reorder_array(g, b, s->rmass, r, nkeep);
    reorder_array(g, b, s->type, sizeof(cl_int), nkeep);
    reorder_array(g, b, s->mask, sizeof(cl_uint), nkeep);
    reorder_array(g, b, s->tag, sizeof(cl_long), nkeep);
    reorder_array(g, b, s->image, 3 * sizeof(cl_int), nkeep);
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (!f->peratom)
            continue;
        cl_kernel k = b->k_reorder_words;
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
    e->a.n = nkeep;
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
        eng_arg_coord(g, k, 5 + q, q, b->lo[q]);
        eng_arg_coord(g, k, 8 + q, q, b->hi[q]);
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
    /* atom_modify sort: every rebuild (default, < 0), never (0) or at the
     * first rebuild N steps after the last; lost atoms are always dropped */
    bigint every = g->neigh.sort_every;
    int resort = nkeep < n || !b->built || every < 0 ||
                 (every > 0 && g->step - b->last_sort >= every);
    if (e->history && b->old_valid)
        retire_contacts(g, b);
    if (resort) {
        resort_atoms(g, b, n, nkeep);
        b->last_sort = g->step;
    }
    build_list(g, b, resort);
    build_contacts(g, b, resort);
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
    const struct nbr_list *l = &b->list;
    int n = e->a.n, maxn = l->maxn, nc = l->ncontact;
    s->n = n;
    s->maxn = maxn;
    s->ago = b->ago;
    s->history = e->history;
    s->ncount = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
    s->nlist = gr_malloc(g, ((size_t)n * maxn + 1) * sizeof(int));
    s->xhold = gr_malloc(g, (3 * (size_t)n + 1) * sizeof(double));
    eng_read(g, l->ncount, 0, (size_t)n * sizeof(cl_int), s->ncount);
    eng_read(g, l->nlist, 0, (size_t)n * maxn * sizeof(cl_int), s->nlist);
    eng_read_reals(g, b->xhold, 3 * (size_t)n, s->xhold);
    if (e->single) /* the device's are relative to the origin */
        for (size_t i = 0; i < 3 * (size_t)n; i++)
            s->xhold[i] += e->origin[i % 3];
    if (e->history) {
        /* per row slot: the owner's history, its negative on the partner's side */
        s->shear = gr_calloc(g, 3 * (size_t)n * maxn + 1, sizeof(double));
        int *ioff = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
        int *cslot = gr_malloc(g, (2 * (size_t)nc + 1) * sizeof(int));
        int *owner = gr_malloc(g, (2 * (size_t)nc + 1) * sizeof(int));
        double *sh = gr_malloc(g, (3 * (size_t)nc + 1) * sizeof(double));
        eng_read(g, l->ioff, 0, ((size_t)n + 1) * sizeof(cl_int), ioff);
        eng_read(g, l->cslot, 0, 2 * (size_t)nc * sizeof(cl_int), cslot);
        eng_read_reals(g, l->shear, 3 * (size_t)nc, sh);
        /* incidence -> row slot: the atom whose packed row holds it */
        for (int i = 0; i < n; i++)
            for (int q = ioff[i]; q < ioff[i + 1]; q++)
                owner[q] = i;
        for (int c = 0; c < nc; c++)
            for (int side = 0; side < 2; side++) {
                int q = cslot[2 * c + side], i = owner[q];
                size_t slot = (size_t)i * maxn + (size_t)(q - ioff[i]);
                for (int d = 0; d < 3; d++)
                    s->shear[3 * slot + d] = (side ? -1.0 : 1.0) * sh[3 * (size_t)c + d];
            }
        free(ioff);
        free(cslot);
        free(owner);
        free(sh);
    }
    return 1;
}

/* Order row slots by partner tag (insertion sort: rows are short). */
static void sort_row(int *row, double *shear, int cnt, const int64_t *tag)
{
    for (int a = 1; a < cnt; a++) {
        int j = row[a];
        double sh[3] = {0, 0, 0};
        if (shear)
            memcpy(sh, shear + 3 * a, sizeof sh);
        int b = a - 1;
        while (b >= 0 && tag[row[b]] > tag[j]) {
            row[b + 1] = row[b];
            if (shear)
                memcpy(shear + 3 * (b + 1), shear + 3 * b, sizeof sh);
            b--;
        }
        row[b + 1] = j;
        if (shear)
            memcpy(shear + 3 * (b + 1), sh, sizeof sh);
    }
}

int nbr_import(struct gravel *g, const struct nbr_state *s)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    struct nbr_list *l = &b->list;
    int n = e->a.n;
    int maxn = s->maxn > 0 ? s->maxn : 1;
    if (s->n != n)
        gr_error(g, "restart: neighbor list of %d atoms for %d atoms on the device", s->n, n);
    const int64_t *tag = g->atoms.tag;
    size_t slots = (size_t)n * maxn;
    int *row = gr_malloc(g, (slots + 1) * sizeof(int));
    int *ioff = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
    int *nown = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
    int *coff = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
    double *rsh = e->history ? gr_calloc(g, 3 * slots + 1, sizeof(double)) : NULL;
    memcpy(row, s->nlist, slots * sizeof(int));
    if (rsh && s->shear)
        memcpy(rsh, s->shear, 3 * slots * sizeof(double));
    size_t total = 0, nin = 0;
    for (int i = 0; i < n; i++) {
        ioff[i] = (int)nin;
        nin += (size_t)s->ncount[i];
        sort_row(row + (size_t)i * maxn, rsh ? rsh + 3 * (size_t)i * maxn : NULL, s->ncount[i],
                 tag);
        int own = 0;
        for (int k = 0; k < s->ncount[i]; k++)
            own += tag[row[(size_t)i * maxn + k]] > tag[i];
        nown[i] = own;
        coff[i] = (int)total;
        total += (size_t)own;
    }
    coff[n] = (int)total;
    ioff[n] = (int)nin;
    int *ci = gr_malloc(g, (total + 1) * sizeof(int)), *cj = gr_malloc(g, (total + 1) * sizeof(int));
    int *cslot = gr_malloc(g, (2 * total + 1) * sizeof(int));
    double *sh = e->history ? gr_calloc(g, 3 * total + 1, sizeof(double)) : NULL;
    int asym = 0;
    for (int i = 0; i < n && !asym; i++) {
        int cnt = s->ncount[i], first = cnt - nown[i];
        for (int k = 0; k < cnt; k++) {
            size_t slot = (size_t)i * maxn + k;
            int j = row[slot];
            if (k >= first) {
                int c = coff[i] + k - first;
                ci[c] = i;
                cj[c] = j;
                cslot[2 * c] = ioff[i] + k;
                if (sh)
                    memcpy(sh + 3 * (size_t)c, rsh + 3 * slot, 3 * sizeof(double));
                continue;
            }
            int jfirst = s->ncount[j] - nown[j], at = -1;
            for (int q = jfirst; q < s->ncount[j]; q++)
                if (row[(size_t)j * maxn + q] == i)
                    at = q;
            if (at < 0) {
                asym = 1;
                break;
            }
            cslot[2 * (coff[j] + at - jfirst) + 1] = ioff[i] + k;
        }
    }
    if (!asym) {
        alloc_list(g, b, maxn);
        alloc_contacts(g, b, total);
        alloc_forces(g, b, total);
        l->ncontact = (int)total;
        eng_write(g, l->ncount, 0, (size_t)n * sizeof(cl_int), s->ncount);
        eng_write(g, l->nlist, 0, slots * sizeof(cl_int), row);
        eng_write(g, l->ioff, 0, ((size_t)n + 1) * sizeof(cl_int), ioff);
        eng_write(g, l->cslot, 0, 2 * total * sizeof(cl_int), cslot);
        eng_write(g, l->nown, 0, (size_t)n * sizeof(cl_int), nown);
        eng_write(g, l->coff, 0, ((size_t)n + 1) * sizeof(cl_int), coff);
        eng_write(g, l->ci, 0, total * sizeof(cl_int), ci);
        eng_write(g, l->cj, 0, total * sizeof(cl_int), cj);
        if (sh)
            eng_write_reals(g, l->shear, 3 * total, sh);
        double *xh = gr_malloc(g, (3 * (size_t)n + 1) * sizeof(double));
        for (size_t i = 0; i < 3 * (size_t)n; i++) /* device: relative to the origin */
            xh[i] = s->xhold[i] - e->origin[i % 3];
        eng_write_reals(g, b->xhold, 3 * (size_t)n, xh);
        free(xh);
    }
    free(row);
    free(ioff);
    free(cslot);
    free(nown);
    free(coff);
    free(rsh);
    free(ci);
    free(cj);
    free(sh);
    if (asym)
        return 0;
    for (int q = 0; q < 3; q++)
        l->L[q] = g->dom.periodic[q] ? g->dom.hi[q] - g->dom.lo[q] : 0.0;
    b->ago = s->ago;
    b->built = 1;
    b->old_valid = e->history;
    return 1;
}
