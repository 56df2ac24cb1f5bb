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
 * from the previous contacts of the same owner and partner.
 *
 * neighbor multi bins each collection (neigh_modify collection/type,
 * collection/interval; by default one per atom type) into its own grid of
 * cells sized by the collection's own cut-off, and an atom searches each
 * collection's cells within the cut-off of that pair of collections; the
 * pair test and the row order are style bin's, so both styles give the same
 * lists. */
#include "neighbor.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagnose.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "kargs.h"
#include "log.h"
#include "memfit.h"
#include "pair.h"
#include "par.h"
#include "comm.h"

#define NCHUNK_MAX 256

/* At most NBR_SPEC steps in a row decided on speculation (nbr_decide):
 * each holds what its decision would restore were its opening to ask for a
 * rebuild. A failed speculation wastes the launches of the steps after the
 * failed one, so the window stays short beside the steps between rebuilds. */
#define NBR_SPEC 16
struct nbr_spec {
    bigint step;
    double time;
    int stamp, ago;
};

struct nbr {
    struct nbr_list list;
    /* contacts of the previous build, for the history transfer: offsets,
     * and (during a rebuild only) history and partners parked in the record
     * buffer, which is free then (retire_contacts; old_cj_at: offset of the
     * partners, in ints) */
    cl_mem coff_old;
    int ncontact_old;
    size_t old_cj_at;
    size_t cap_pair, cap_contact;
    int old_valid;              /* the previous contacts index the atoms before this build */
    int built;                  /* a list exists for the current run */
    int radii_changed;          /* nbr_radii_changed: rebuild at the next decision */
    cl_mem xhold, cellof, perm, counts, start, cursor, sums, flags, ext, excl_type,
        excl_group, typecut;
    size_t cap_atoms, cap_cells;
    size_t rsz;
    int history, rotation, pair_tc; /* the engine's, when the records were sized */
    int ncell, nc[3];
    long cells_per_atom;        /* env GRAVEL_CELLS_PER_ATOM: the grid's budget (-1: grid_dims's) */
    double cutmax, lo[3], hi[3], inv[3];
    double cutpair;             /* largest cut-off of a pair (minimum image needs L >= 2 x) */
    double lmp_cutmax;          /* -compat lammps2021: LAMMPS's cutneighmax (its bins) */
    int nexg;
    int ago;
    int opened;                 /* the last pair_gather ran this step's opening (nbr_step_args) */
    int stamp;                  /* of the last opening: flags[0] == stamp when it asks to rebuild */
    int spec_on;                /* steps may be decided on speculation in this run */
    int nspec;                  /* steps decided on speculation since the last flag read */
    int interval;               /* steps from a build to the next one asked for (0: none yet) */
    struct nbr_spec spec[NBR_SPEC];
    double corners_hold[8][3];  /* box corners at the last build */
    int box_moved;              /* the box changed since the last build (nbr_box_changed) */
    bigint last_sort;           /* step of the last re-sort (atom_modify sort) */
    /* neighbor multi: ncoll collections (ninterval of them by diameter
     * interval, else by type: type2coll), per collection its atom count at
     * setup, its radius bound and grid (mnc, mbase: first global cell), the
     * bound of the pair cut-off of every collection pair (cutab, skin
     * included); device copies in d_* */
    int multi, ncoll, ninterval;
    int *mcount, *mnc, *mbase, *type2coll;
    double *mrad, *cutab, *minvh;
    cl_mem d_collcut, d_type2coll, d_mgrid, d_minv, d_cutab;
    cl_kernel k_bin_multi, k_build_multi;
    cl_kernel k_check, k_wrap, k_bin, k_scan_serial, k_scan_partial, k_scan_top, k_scan_final,
        k_scatter, k_cellsort, k_reorder_words, k_build, k_contacts, k_invperm, k_hist_rename,
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

static void free_multi(struct nbr *b)
{
    free(b->mcount);
    free(b->mnc);
    free(b->mbase);
    free(b->type2coll);
    free(b->mrad);
    free(b->cutab);
    free(b->minvh);
    b->mcount = b->mnc = b->mbase = b->type2coll = NULL;
    b->mrad = b->cutab = b->minvh = NULL;
}

void nbr_free(struct gravel *g)
{
    if (!g->eng || !g->eng->nbr)
        return;
    struct nbr *b = g->eng->nbr;
    struct nbr_list *l = &b->list;
    cl_mem *m[] = {&l->nlist, &l->ncount, &l->nown, &l->ioff, &l->coff, &l->ci, &l->cj,
                   &l->pcon, &l->quiet, &l->shear, &l->rec, &b->coff_old,
                   &b->xhold, &b->cellof, &b->perm, &b->counts, &b->start, &b->cursor,
                   &b->sums, &b->flags, &b->ext, &b->excl_type, &b->excl_group, &b->typecut,
                   &b->d_collcut, &b->d_type2coll, &b->d_mgrid, &b->d_minv, &b->d_cutab};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++)
        rel(m[i]);
    free_multi(b);
    free(b);
    g->eng->nbr = NULL;
}

void nbr_invalidate(struct gravel *g)
{
    if (g->eng && g->eng->nbr)
        g->eng->nbr->old_valid = 0;
}

const struct nbr_list *nbr_list(struct gravel *g) { return &get(g)->list; }

/* REAL per contact record (kernels/pair_loop.cl, REC_W) */
static size_t rec_reals(const struct engine *e)
{
    return (size_t)(!e->rotation ? 3 : e->pair_tc ? 6 : 9);
}

static void quiet_clear(struct gravel *g)
{
    const struct nbr_list *l = &get(g)->list;
    if (l->quiet && l->ncontact > 0)
        eng_fill_zero(g, l->quiet, ((size_t)l->ncontact + 3) / 4 * 4);
}

/* Record nc, the one past nc contacts' records: zeros, which pair_gather
 * reads for a quiet contact's (kernels/pair_loop.cl rec_take). Nothing
 * writes there until a rebuild parks history in the records; alloc_records
 * writes it again after the history transfer. */
static void zero_record(struct gravel *g, size_t nc)
{
    const struct nbr_list *l = &get(g)->list;
    if (!l->rec)
        return;
    const size_t w = rec_reals(g->eng) * g->eng->rsz;
    const cl_uint zero = 0;
    OCL_CHECK(g, clEnqueueFillBuffer(g->eng->ocl.queue, l->rec, &zero, sizeof zero, nc * w, w,
                                     0, NULL, NULL));
}

void nbr_quiet_reset(struct gravel *g)
{
    quiet_clear(g);
    zero_record(g, (size_t)get(g)->list.ncontact);
}


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
    if (g->eng->ocl.serial) { /* work-items run in turn there: one pass, one launch */
        eng_arg_int(g, b->k_scan_serial, 0, m);
        eng_arg_mem(g, b->k_scan_serial, 1, in);
        eng_arg_mem(g, b->k_scan_serial, 2, out);
        eng_launch(g, b->k_scan_serial, 1);
        return;
    }
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
    l->ioff = eng_alloc(g, (n + 1) * sizeof(cl_int), "row offsets");
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

/* Bytes per contact of the record buffer (kernels/pair_loop.cl, REC_W):
 * the owner's force, and with rotation the contact's tc (a law without
 * rolling torque: e->pair_tc) or both sides' torques. A rebuild parks the
 * previous contacts' history rows and then their partners there, so it is
 * sized to hold those too. */
static size_t rec_bytes(const struct engine *e)
{
    size_t own = rec_reals(e) * e->rsz;
    size_t park = e->history ? (size_t)e->hist_n * e->rsz + sizeof(cl_int) : 0;
    return park > own ? park : own;
}

static size_t grown(size_t nc) { return nc + nc / 8 + 64; }

/* The buffers of grow_atoms, per atom slot. */
static size_t atom_bytes(const struct engine *e) { return 3 * e->rsz + 7 * sizeof(cl_int); }

/* ci, cj, pcon, the quiet flag and the history row of one contact. */
static size_t contact_bytes(const struct engine *e)
{
    return 3 * sizeof(cl_int) + 1 + (e->history ? (size_t)e->hist_n * e->rsz : 0);
}

size_t nbr_atom_bytes(struct gravel *g)
{
    int maxn = get(g)->list.maxn;
    return atom_bytes(g->eng) + (size_t)(maxn > 0 ? maxn : 8) * sizeof(cl_int);
}

size_t nbr_contact_bytes(struct gravel *g)
{
    return contact_bytes(g->eng) + rec_bytes(g->eng);
}

size_t nbr_capacity(size_t ncontact) { return grown(ncontact); }

size_t nbr_held_bytes(struct gravel *g)
{
    const struct engine *e = g->eng;
    const struct nbr *b = get(g);
    size_t rows = b->list.nlist ? (size_t)e->cap * (size_t)b->list.maxn * sizeof(cl_int) : 0;
    return b->cap_atoms * atom_bytes(e) + rows + b->cap_contact * contact_bytes(e) +
           b->cap_pair * rec_bytes(e) + 3 * b->cap_cells * sizeof(cl_int);
}

/* Contact buffers for at least nc contacts (contents not kept): ci, cj,
 * pcon and shear (cap_contact); the records (cap_pair) separately, after
 * the history transfer has read what was parked there. */
static void alloc_contacts(struct gravel *g, struct nbr *b, size_t nc)
{
    struct engine *e = g->eng;
    struct nbr_list *l = &b->list;
    if (nc > b->cap_contact || !l->ci) {
        rel(&l->ci);
        rel(&l->cj);
        rel(&l->pcon);
        rel(&l->quiet);
        rel(&l->shear);
        b->cap_contact = grown(nc);
        l->ci = eng_alloc(g, b->cap_contact * sizeof(cl_int), "contact owners");
        l->cj = eng_alloc(g, b->cap_contact * sizeof(cl_int), "contact partners");
        l->pcon = eng_alloc(g, b->cap_contact * sizeof(cl_int), "partner-side contacts");
        /* whole words: nbr_quiet_reset fills 4 bytes at a time */
        l->quiet = eng_alloc(g, (b->cap_contact + 3) / 4 * 4, "contact quiet flags");
        if (e->history)
            l->shear = eng_alloc(g, b->cap_contact * (size_t)e->hist_n * e->rsz, "contact history");
    }
}

/* Records for nc contacts and, after them, the record of zeros
 * (zero_record); contents otherwise not kept. */
static void alloc_records(struct gravel *g, struct nbr *b, size_t nc)
{
    struct nbr_list *l = &b->list;
    if (nc >= b->cap_pair || !l->rec) {
        rel(&l->rec);
        b->cap_pair = grown(nc);
        l->rec = eng_alloc(g, b->cap_pair * rec_bytes(g->eng), "contact records");
    }
    zero_record(g, nc);
}

/* The current contacts become the previous ones: offsets swap, history
 * rows (hist_n REAL per contact) are parked in the records from byte 0,
 * partners after them from int offset old_cj_at. */
static void retire_contacts(struct gravel *g, struct nbr *b)
{
    struct engine *e = g->eng;
    struct nbr_list *l = &b->list;
    cl_mem t = b->coff_old;
    b->coff_old = l->coff;
    l->coff = t;
    b->ncontact_old = l->ncontact;
    size_t nc = (size_t)l->ncontact, hist = nc * (size_t)e->hist_n * e->rsz;
    b->old_cj_at = (hist + sizeof(cl_int) - 1) / sizeof(cl_int);
    if (nc == 0)
        return;
    if (b->old_cj_at * sizeof(cl_int) + nc * sizeof(cl_int) > b->cap_pair * rec_bytes(e))
        gr_error(g, "internal error: the record buffer cannot hold the previous contacts");
    OCL_CHECK(g, clEnqueueCopyBuffer(e->ocl.queue, l->shear, l->rec, 0, 0, hist, 0, NULL, NULL));
    OCL_CHECK(g, clEnqueueCopyBuffer(e->ocl.queue, l->cj, l->rec, 0,
                                     b->old_cj_at * sizeof(cl_int), nc * sizeof(cl_int), 0,
                                     NULL, NULL));
}

/* Collections of neighbor multi (LAMMPS Neighbor::init and
 * build_collection): by type (collection/type, or one per type), each
 * collection's radius bound the largest radius of its atoms; or by diameter
 * interval (collection/interval: the first collection whose cut-off is >= the
 * diameter), the bound half the interval's cut-off. */
static void setup_multi(struct gravel *g, struct nbr *b)
{
    struct engine *e = g->eng;
    const struct neigh_settings *ns = &g->neigh;
    rel(&b->d_collcut);
    rel(&b->d_type2coll);
    rel(&b->d_mgrid);
    rel(&b->d_minv);
    rel(&b->d_cutab);
    free_multi(b);
    b->multi = ns->style == NEIGH_MULTI;
    if (!b->multi)
        return;
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    int nc = ns->ncoll > 0 ? ns->ncoll : nt;
    b->ncoll = nc;
    b->ninterval = ns->ncoll > 0 && ns->coll_interval ? nc : 0;
    b->mcount = gr_calloc(g, (size_t)nc, sizeof(int));
    b->mnc = gr_calloc(g, 3 * (size_t)nc, sizeof(int));
    b->mbase = gr_calloc(g, (size_t)nc + 1, sizeof(int));
    b->type2coll = gr_calloc(g, (size_t)nt, sizeof(int));
    b->mrad = gr_calloc(g, (size_t)nc, sizeof(double));
    b->cutab = gr_calloc(g, (size_t)nc * nc, sizeof(double));
    b->minvh = gr_calloc(g, 3 * (size_t)nc, sizeof(double));
    for (int t = 0; t < nt; t++)
        b->type2coll[t] = ns->ncoll > 0 ? -1 : t;
    if (ns->ncoll > 0 && !ns->coll_interval)
        for (int k = 0; k < ns->ncoll_range; k++)
            for (int t = ns->coll_range[k][0]; t <= ns->coll_range[k][1] && t <= nt; t++)
                b->type2coll[t - 1] = ns->coll_range[k][2];
    if (!b->ninterval)
        for (int t = 0; t < nt; t++)
            if (b->type2coll[t] < 0)
                gr_error(g, "atom type %d is in no collection of neigh_modify collection/type "
                            "(types created after the command)", t + 1);
    for (int i = 0; i < g->atoms.n; i++) {
        double r = g->atoms.radius[i];
        int c = -1;
        if (b->ninterval) {
            for (int k = 0; k < nc && c < 0; k++)
                if (ns->coll_cut[k] >= 2 * r)
                    c = k;
            if (c < 0)
                gr_error(g, "atom %lld of diameter %g exceeds the largest collection/interval "
                            "cut-off %g of neighbor multi", (long long)g->atoms.tag[i], 2 * r,
                         ns->coll_cut[nc - 1]);
        } else {
            c = b->type2coll[g->atoms.type[i] - 1];
        }
        b->mcount[c]++;
        if (r > b->mrad[c])
            b->mrad[c] = r;
    }
    if (b->ninterval)
        for (int k = 0; k < nc; k++)
            b->mrad[k] = 0.5 * ns->coll_cut[k];
    else /* atoms fixes may insert this run (fix pour), of any type: every bound */
        for (int k = 0; k < nc; k++) {
            if (e->insert_rmax > b->mrad[k])
                b->mrad[k] = e->insert_rmax;
            if (e->insert_rmax > 0)
                b->mcount[k] = b->mcount[k] > 0 ? b->mcount[k] : 1;
        }
    /* a bound: the kernel's cell ranges must not lose a pair to rounding */
    /* a potential's type-pair cut-offs: the largest between the two
     * collections' types (every type for collection/interval) */
    unsigned *tmask = gr_calloc(g, (size_t)nc, sizeof(unsigned));
    for (int t = 0; t < nt; t++)
        if (b->ninterval || t >= 32)
            for (int k = 0; k < nc; k++)
                tmask[k] = ~0u;
        else
            tmask[b->type2coll[t]] |= 1u << t;
    for (int a = 0; a < nc; a++)
        for (int c = 0; c < nc; c++)
            b->cutab[a * nc + c] =
                (fmax(pair_reach(g, b->mrad[a] + b->mrad[c]),
                      pair_type_cut_max(g, tmask[a], tmask[c])) + ns->skin) * (1 + 1e-5);
    free(tmask);
    b->d_cutab = eng_alloc(g, (size_t)nc * nc * e->rsz, "multi collection cut-offs");
    eng_write_reals(g, b->d_cutab, (size_t)nc * nc, b->cutab);
    b->d_collcut = eng_alloc(g, (size_t)nc * e->rsz, "multi collection intervals");
    eng_write_reals(g, b->d_collcut, (size_t)nc, ns->coll_cut);
    b->d_type2coll = eng_alloc(g, (size_t)nt * sizeof(cl_int), "multi type collections");
    eng_write(g, b->d_type2coll, 0, (size_t)nt * sizeof(cl_int), b->type2coll);
    b->d_mgrid = eng_alloc(g, 4 * (size_t)nc * sizeof(cl_int), "multi grids");
    b->d_minv = eng_alloc(g, 3 * (size_t)nc * e->rsz, "multi grid scales");
}

/* LAMMPS 2021's cutneighmax: the largest init_one cut-off over type pairs
 * whose types have a radius (their atoms', or what fix pour may insert),
 * plus the skin. */
/* The two largest radii over the ranks, from each rank's two largest. */
static void top_two_radii(struct gravel *g, double *rmax, double *r2nd)
{
    double mine[2] = {*rmax, *r2nd}, *all = NULL;
    size_t bytes = comm_allgatherv(mine, sizeof mine, (void **)&all);
    if (bytes == (size_t)-1)
        gr_error(g, "out of memory gathering the radii of the ranks");
    double a = 0, b = 0;
    for (size_t k = 0; k < bytes / sizeof(double); k++) {
        double r = all[k];
        if (r > a) {
            b = a;
            a = r;
        } else if (r > b) {
            b = r;
        }
    }
    free(all);
    *rmax = a;
    *r2nd = b;
}

static double lammps2021_cutneighmax(struct gravel *g, double insert_rmax)
{
    const struct pair *p = g->styles.pair;
    int nt = g->atoms.ntypes;
    double *rt = gr_calloc(g, (size_t)nt + 1, sizeof *rt), cut = 0;
    for (int t = 1; t <= nt; t++)
        rt[t] = insert_rmax;
    for (int k = 0; k < g->atoms.n; k++)
        if (g->atoms.radius[k] > rt[g->atoms.type[k]])
            rt[g->atoms.type[k]] = g->atoms.radius[k];
    for (int i = 1; i <= nt; i++)
        for (int j = i; j <= nt; j++)
            if (rt[i] > 0 && rt[j] > 0)
                cut = fmax(cut, p && p->caps.lammps2021_cut
                                    ? p->caps.lammps2021_cut(p->caps.cut2021_of, i, j, rt[i],
                                                             rt[j])
                                    : rt[i] + rt[j]);
    free(rt);
    return cut + g->neigh.skin;
}


/* The cut-offs from the largest radii of the host atoms (and of the atoms
 * fixes may insert): the cells' size, the largest pair cut-off, the multi
 * collections. */
static void set_cutoffs(struct gravel *g, struct nbr *b)
{
    struct engine *e = g->eng;
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    double rmax = e->insert_rmax, r2nd = e->insert_rmax; /* atoms fixes may insert (fix pour) */
    for (int i = 0; i < g->atoms.n; i++) {
        double r = g->atoms.radius[i];
        if (r > rmax) {
            r2nd = rmax;
            rmax = r;
        } else if (r > r2nd) {
            r2nd = r;
        }
    }
    if (par_on(g)) /* the two largest radii of every rank's atoms */
        top_two_radii(g, &rmax, &r2nd);
    b->cutmax = fmax(pair_reach(g, 2 * rmax), /* cohesion: effect range */
                     pair_type_cut_max(g, ~0u, ~0u)) + g->neigh.skin; /* a potential's */
    double *tc = gr_calloc(g, (size_t)nt * nt, sizeof(double));
    const struct pair *pp = g->styles.pair;
    if (pp && pp->caps.type_cut)
        for (int a = 0; a < nt; a++)
            for (int c = 0; c < nt; c++)
                tc[a * nt + c] = pp->caps.type_cut(pp->caps.cut_of, a + 1, c + 1);
    rel(&b->typecut);
    b->typecut = eng_alloc(g, (size_t)nt * nt * e->rsz, "type-pair cut-offs");
    eng_write_reals(g, b->typecut, (size_t)nt * nt, tc);
    free(tc);
    if (b->cutmax <= 0)
        b->cutmax = 1.0;
    /* the largest cut-off of a pair of two atoms: the two largest radii */
    b->cutpair = fmax(pair_reach(g, rmax + r2nd) + g->neigh.skin, 0.5 * b->cutmax);
    b->lmp_cutmax = g->opt.lammps2021 ? lammps2021_cutneighmax(g, e->insert_rmax) : 0;
    setup_multi(g, b);
}

/* Whether this run may decide steps on speculation (nbr_decide): on a
 * threaded device, whose flag read costs a hand-off to the host and back
 * (doc/opencl.md; the serial device's costs a microsecond), one process,
 * LAMMPS's default decision (every 1 delay 0 check yes), and not switched
 * off (environment GRAVEL_SPECULATE=0). */
static int speculation_wanted(struct gravel *g)
{
    const char *env = getenv("GRAVEL_SPECULATE");
    if (env && *env && strcmp(env, "0") && strcmp(env, "1"))
        gr_error(g, "GRAVEL_SPECULATE must be 0 or 1, got '%.32s'", env);
    return !(env && !strcmp(env, "0")) && !g->eng->ocl.serial && !par_on(g) &&
           g->neigh.every <= 1 && g->neigh.delay == 0 && g->neigh.check && !g->neigh.once;
}

void nbr_setup(struct gravel *g)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    b->k_check = eng_kernel(g, "nbr_check");
    b->k_wrap = eng_kernel(g, "nbr_wrap_extent");
    b->k_bin = eng_kernel(g, "nbr_bin");
    b->k_scan_serial = eng_kernel(g, "scan_serial");
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
    b->k_bin_multi = eng_kernel(g, "nbr_bin_multi");
    b->k_build_multi = eng_kernel(g, "nbr_build_multi");
    b->cells_per_atom = -1;
    const char *cpa = getenv("GRAVEL_CELLS_PER_ATOM");
    if (cpa && *cpa) {
        char *end;
        b->cells_per_atom = strtol(cpa, &end, 10);
        if (*end || b->cells_per_atom < 0 || b->cells_per_atom > 1024)
            gr_error(g, "GRAVEL_CELLS_PER_ATOM must be a number of cells per atom 0..1024, got "
                        "'%.32s'", cpa);
    }
    if (!b->flags)
        b->flags = eng_alloc(g, 4 * sizeof(cl_int), "neighbor flags");
    b->nspec = b->interval = 0;
    b->spec_on = speculation_wanted(g);
    if (!b->sums)
        b->sums = eng_alloc(g, (NCHUNK_MAX + 1) * sizeof(cl_int), "scan sums");
    rel(&b->ext);
    b->ext = eng_alloc(g, NCHUNK_MAX * 6 * e->rsz, "extent");
    /* a different capacity, precision or feature set invalidates the kept list */
    int hist_id = e->history ? e->hist_n : 0;
    if (b->cap_atoms != (size_t)e->cap || b->rsz != e->rsz || b->history != hist_id) {
        b->old_valid = 0;
        b->built = 0;
        struct nbr_list *l = &b->list;
        cl_mem *m[] = {&l->ci, &l->cj, &l->pcon, &l->quiet, &l->shear, &l->rec};
        for (size_t i = 0; i < sizeof m / sizeof *m; i++)
            rel(m[i]);
        b->cap_pair = b->cap_contact = 0;
        l->ncontact = b->ncontact_old = 0;
        grow_atoms(g, b, (size_t)e->cap);
        alloc_list(g, b, b->list.maxn ? b->list.maxn : 8); /* grows on overflow */
        b->rsz = e->rsz;
        b->history = hist_id;
        b->rotation = e->rotation;
        b->pair_tc = e->pair_tc;
    }
    if (b->rotation != e->rotation || b->pair_tc != e->pair_tc) { /* the records change */
        size_t cap = b->cap_pair;
        rel(&b->list.rec);
        b->rotation = e->rotation;
        b->pair_tc = e->pair_tc;
        b->cap_pair = 0;
        if (cap)
            alloc_records(g, b, cap);
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
    /* group and molecule exclusions: (bits 1, bits 2, kind) triples, kind 0
     * a group pair, 1 molecule/intra, 2 molecule/inter (kernels/neighbor.cl) */
    cl_uint eg[96];
    b->nexg = 0;
    for (int k = 0; k < g->neigh.nexclude && k < 16; k++, b->nexg++) {
        eg[3 * b->nexg] = 1u << g->neigh.exclude_group[k][0];
        eg[3 * b->nexg + 1] = 1u << g->neigh.exclude_group[k][1];
        eg[3 * b->nexg + 2] = 0;
    }
    if (g->neigh.nexclude_mol && !g->atoms.molecule_flag)
        gr_error(g, "neigh_modify exclude molecule/%s requires atom attribute molecule (fix "
                    "property/atom mol)", g->neigh.exclude_mol[0][1] ? "intra" : "inter");
    for (int k = 0; k < g->neigh.nexclude_mol && k < 16; k++, b->nexg++) {
        eg[3 * b->nexg] = eg[3 * b->nexg + 1] = 1u << g->neigh.exclude_mol[k][0];
        eg[3 * b->nexg + 2] = g->neigh.exclude_mol[k][1] ? 1 : 2;
    }
    rel(&b->excl_group);
    b->excl_group = eng_alloc(g, sizeof eg, "group exclusions");
    if (b->nexg)
        eng_write(g, b->excl_group, 0, (size_t)b->nexg * 3 * sizeof(cl_uint), eg);
    set_cutoffs(g, b);
    b->radii_changed = 0;
    b->ago = 0;
    b->built = 0;
    b->last_sort = g->step;
    e->st.nbuilds = e->st.ndanger = e->st.nspec = e->st.nspec_back = 0;
}

void nbr_radii_changed(struct gravel *g)
{
    struct nbr *b = get(g);
    set_cutoffs(g, b);
    b->radii_changed = 1;
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

/* Device position and velocity of atom index i (error paths only). */
static void atom_state(struct gravel *g, int i, long long *tag, double x[3], double v[3])
{
    struct engine *e = g->eng;
    size_t n3 = 3 * (size_t)e->a.n;
    double *buf = gr_malloc(g, (n3 + 1) * sizeof(double));
    eng_read(g, e->a.tag, (size_t)i * sizeof(cl_long), sizeof(cl_long), tag);
    eng_read_positions(g, &e->a, e->a.n, buf); /* lab frame (origin, split parts) */
    memcpy(x, buf + 3 * (size_t)i, 3 * sizeof(double));
    eng_read_reals(g, e->a.v, n3, buf);
    memcpy(v, buf + 3 * (size_t)i, 3 * sizeof(double));
    free(buf);
}

/* Stop on non-finite atom index i: the step, the atom and what the start of
 * the run shows about it (diagnose.h); the time step is discussed only when
 * nothing else explains it. */
static void nonfinite_error(struct gravel *g, int i)
{
    long long tag = 0;
    double x[3], v[3];
    atom_state(g, i, &tag, x, v);
    char seen[700], cause[400] = "";
    const struct pair *p = g->styles.pair;
    int explained = diag_nonfinite(g, tag, x, v, seen, sizeof seen);
    if (p && p->caps.nonfinite_cause)
        snprintf(cause, sizeof cause, "; %s", p->caps.nonfinite_cause);
    else if (!explained)
        diag_time_step(g, cause, sizeof cause);
    gr_error(g, "non-finite position or velocity at step %lld: %s%s", (long long)g->step, seen,
             cause);
}

/* The box corners (LAMMPS's Domain::box_corners order). */
static void box_corners(const struct gravel *g, double c[8][3])
{
    for (int k = 0; k < 8; k++) {
        double lam[3] = {(double)(k & 1), (double)((k >> 1) & 1), (double)((k >> 2) & 1)};
        domain_lamda2x(g, lam, c[k]);
    }
}

/* Displacement that triggers a rebuild: half the skin, less the two largest
 * corner displacements of a box changed since the build (LAMMPS's
 * check_distance: delta = 0.5 (skin - (delta1 + delta2)), at least 0). */
static double trigger_distance(struct gravel *g, struct nbr *b)
{
    double trig = 0.5 * g->neigh.skin;
    if (!b->box_moved)
        return trig;
    double c[8][3], d1 = 0, d2 = 0;
    box_corners(g, c);
    for (int k = 0; k < 8; k++) {
        double dx = c[k][0] - b->corners_hold[k][0], dy = c[k][1] - b->corners_hold[k][1];
        double dz = c[k][2] - b->corners_hold[k][2];
        double dl = sqrt(dx * dx + dy * dy + dz * dz);
        if (dl > d1)
            d1 = dl;
        else if (dl > d2)
            d2 = dl;
    }
    trig = 0.5 * (g->neigh.skin - (d1 + d2));
    return trig < 0 ? 0 : trig;
}

int nbr_arg_box(struct gravel *g, cl_kernel k, int a, const struct nbr_list *l)
{
    for (int q = 0; q < 3; q++)
        eng_arg_real(g, k, a++, l->L[q]);
    for (int q = 0; q < 3; q++)
        eng_arg_real(g, k, a++, l->tilt[q]);
    return a;
}

static void list_box(struct gravel *g, struct nbr_list *l)
{
    for (int q = 0; q < 3; q++)
        l->L[q] = domain_contact_periodic(g, q) ? g->dom.hi[q] - g->dom.lo[q] : 0.0;
    l->tilt[0] = g->dom.xy;
    l->tilt[1] = g->dom.xz;
    l->tilt[2] = g->dom.yz;
}

void nbr_box_changed(struct gravel *g)
{
    struct nbr *b = get(g);
    list_box(g, &b->list);
    b->box_moved = 1;
}

/* The arguments of a step's opening (kernels/atom_step.cl); with reset, a
 * new stamp for it: its rebuild request is flags[0] == stamp, so the flags
 * need no reset command per step (one at the run's first opening, and when
 * the stamps wrap); a non-finite particle in flags[1] stops the run. */
static void step_args(struct gravel *g, struct nbr *b, struct atom_step_args *a, int reset)
{
    struct engine *e = g->eng;
    double trig = trigger_distance(g, b);
    if (reset) {
        if (b->stamp <= 0 || b->stamp == INT_MAX) {
            reset_flags(g, b);
            b->stamp = 0;
        }
        b->stamp++;
    }
    *a = (struct atom_step_args){
        .x = e->a.x,
        .xhold = b->xhold,
        .trigsq = trig * trig,
        .flags = b->flags,
        .stamp = b->stamp,
        .image = e->a.image,
        .box = {0, 0, 0, g->dom.xy, g->dom.xz, g->dom.yz},
        .hrate = e->hrate,
        .vgroup = e->vgroup,
        .ninit = e->fused.ninit,
    };
    for (int q = 0; q < 3; q++) {
        a->lo[q] = g->dom.lo[q];
        a->hi[q] = g->dom.hi[q];
        a->box[q] = domain_contact_periodic(g, q) ? g->dom.hi[q] - g->dom.lo[q] : 0.0;
    }
}

void nbr_step_args(struct gravel *g, struct atom_step_args *a, int ahead)
{
    struct nbr *b = get(g);
    step_args(g, b, a, ahead);
    b->opened = ahead;
}

void nbr_step_reset(struct gravel *g)
{
    get(g)->opened = 0;
    get(g)->stamp = 0; /* the run's first opening resets the flags */
}

/* A step decided on speculation: no rebuild, recorded for the flag read
 * that checks it; its kernels carry the halt (nbr_halt_args). Only a step
 * whose opening ran in the step before (opened), that nothing forces to
 * rebuild, while the stamps stay clear of their wrap (step_args), and not
 * in the last eighth of the interval between the last two builds, nor the
 * 4 steps after it, where a rebuild is likely: a speculation that fails
 * wastes the launches of the steps after the failed one (a 10^4-particle
 * suspension rebuilding every 6 steps lost 5 % to them without this). */
static int speculate(struct gravel *g, struct nbr *b, int forced)
{
    const int next = b->ago + 1, iv = b->interval;
    if (!b->spec_on || !b->opened || forced || b->radii_changed || b->box_moved ||
        b->nspec == NBR_SPEC || b->stamp <= 0 || b->stamp > INT_MAX - 2 * NBR_SPEC ||
        (iv > 0 && next >= iv - iv / 8 && next <= iv + 4))
        return 0;
    b->spec[b->nspec++] = (struct nbr_spec){g->step, g->time, b->stamp, b->ago};
    g->eng->st.nspec++;
    b->opened = 0;
    b->ago++; /* as a decision that read no request */
    return 1;
}

/* The flags read after steps decided on speculation (fl): when the opening
 * of one of them asked for a rebuild or met a non-finite particle (flags[0]
 * its stamp), its kernels and those of every later step did nothing
 * (KARGS_halt), so the run goes back to it (g->step, g->time, the stamp and
 * the count since the build) with its opening done. Returns 1 then. */
static int speculation_failed(struct gravel *g, struct nbr *b, const cl_int fl[4])
{
    int k = 0;
    while (k < b->nspec && b->spec[k].stamp != fl[0])
        k++;
    const int failed = k < b->nspec;
    if (failed) {
        const struct nbr_spec *p = &b->spec[k];
        g->eng->st.nspec_back += g->step - p->step;
        g->step = p->step;
        g->time = p->time;
        b->stamp = p->stamp;
        b->ago = p->ago;
        b->opened = 1;
    }
    b->nspec = 0;
    return failed;
}

void nbr_halt_args(struct gravel *g, struct halt_args *h)
{
    const struct nbr *b = get(g);
    h->hflags = b->flags;
    h->hlo = b->nspec > 0 ? b->spec[0].stamp : 1;
    h->hhi = b->nspec > 0 ? b->spec[b->nspec - 1].stamp : 0;
}

int nbr_decide(struct gravel *g, int forced, int plain)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    if (plain && speculate(g, b, forced))
        return 0;
    cl_int fl[4];
    int have = 0; /* fl holds this step's flags */
    if (b->nspec > 0) {
        read_flags(g, b, fl);
        have = 1;
        if (speculation_failed(g, b, fl))
            forced = 0; /* nothing forced the step gone back to (speculate) */
    }
    if (!b->opened) { /* the step's opening; else the last pair_gather ran it */
        struct nbr_check_args ck = {
            .n = e->a.n,
            .v = e->a.v,
            .ops = e->fused.ops,
            .prm = e->fused.prm,
            .f = e->a.f,
            .omega = e->rotation ? e->a.omega : e->a.v,
            .torque = e->rotation ? e->a.torque : e->a.f,
            .rmass = e->a.rmass,
            .radius = e->a.radius,
            .type = e->a.type,
            .mask = e->a.mask,
        };
        step_args(g, b, &ck.atom_step, 1);
        ka_bind_nbr_check(g, b->k_check, 0, &ck);
        eng_launch(g, b->k_check, (size_t)e->a.n);
        have = 0;
    }
    b->opened = 0;
    if (!have)
        read_flags(g, b, fl);
    if (fl[1] != 0x7fffffff)
        nonfinite_error(g, fl[1]);
    if (forced || b->radii_changed) {
        b->radii_changed = 0;
        return 1;
    }
    b->ago++;
    int every = g->neigh.every > 0 ? g->neigh.every : 1;
    if (b->ago >= g->neigh.delay && b->ago % every == 0) {
        if (g->neigh.once)
            return 0;
        if (!g->neigh.check)
            return 1;
        /* a decomposed run rebuilds on every rank when one needs it */
        if (par_on(g) ? comm_max_int(fl[0] == b->stamp) : fl[0] == b->stamp) {
            b->interval = b->ago;
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
    struct nbr_wrap_extent_args wa = {
        .n = n,
        .chunk = chunk,
        .x = e->a.x,
        .v = e->a.v,
        .mask = e->a.mask,
        .hrate = e->hrate,
        .vgroup = e->vgroup,
        .image = e->a.image,
        .xy = d->xy,
        .xz = d->xz,
        .yz = d->yz,
        .ext = b->ext,
    };
    for (int q = 0; q < 3; q++) {
        wa.p[q] = domain_contact_periodic(g, q);
        wa.lo[q] = d->lo[q];
        wa.hi[q] = d->hi[q];
    }
    cl_kernel k = b->k_wrap;
    ka_bind_nbr_wrap_extent(g, k, 0, &wa);
    if (nch < 1 && !par_on(g)) /* a rank without atoms still joins the extent */
        return;
    if (nch >= 1)
        eng_launch(g, k, (size_t)nch);
    int shrink = 0;
    for (int q = 0; q < 3; q++)
        if (!d->periodic[q] && (d->bnd[q][0] != BND_F || d->bnd[q][1] != BND_F))
            shrink = 1;
    if (!shrink)
        return;
    double *ext = gr_malloc(g, ((size_t)nch + 1) * 6 * sizeof(double));
    eng_read_reals(g, b->ext, (size_t)nch * 6, ext);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int c = 0; c < nch; c++)
        for (int q = 0; q < 3; q++) {
            lo[q] = fmin(lo[q], e->origin[q] + ext[6 * c + q]);
            hi[q] = fmax(hi[q], e->origin[q] + ext[6 * c + 3 + q]);
        }
    free(ext);
    if (par_on(g))
        comm_minmax(lo, hi, 3); /* the extent of every rank's atoms */
    if (!(lo[0] <= hi[0]))
        return; /* no atom on any rank */
    domain_shrink_wrap(g, lo, hi);
}

/* Cells per dimension of a grid of cells >= cut over the box, coarsened
 * (x 1.25) until there are at most max(8 natoms + 4096, min(32 natoms,
 * 2^20)), or with cpa >= 0 (GRAVEL_CELLS_PER_ATOM) cpa natoms + 4096. A
 * rebuild's cost has a part per cell (the counting sort, 12 bytes each) and a
 * part per candidate pair (the 27 cells around each atom): a sparse scene's
 * coarse cells hold many candidates, so a small one may have up to 32 cells
 * per atom (the 10^4-particle agglomeration box: cells of the cut-off, 0.1
 * m, instead of 0.157 m), at most 2^20 cells in all (12 MB). The lists do
 * not depend on the grid (rows in tag order). */
static long grid_dims(const struct domain *d, double cut, int natoms, long cpa, int nc[3])
{
    const long small = 32L * natoms < (1L << 20) ? 32L * natoms : 1L << 20;
    long budget = 8L * natoms + 4096;
    if (cpa >= 0)
        budget = cpa * natoms + 4096;
    else if (small > budget)
        budget = small;
    double f[3];
    domain_ufac(d, f);
    for (;;) {
        long total = 1;
        for (int q = 0; q < 3; q++) {
            double L = d->hi[q] - d->lo[q];
            int m = (int)(L / (cut * f[q]));
            if (m < 1)
                m = 1;
            if (m > 1 << 20)
                m = 1 << 20;
            nc[q] = m;
            total *= m;
        }
        if (total <= budget || total <= 1)
            return total;
        cut *= 1.25;
    }
}

/* neighbor multi: one grid per collection, cells of the collection's own
 * cut-off (an empty collection: one cell), numbered one grid after the
 * other; written to the device. */
static void make_grids_multi(struct gravel *g, struct nbr *b)
{
    struct domain *d = &g->dom;
    int nc = b->ncoll;
    long total = 0;
    int *mg = gr_malloc(g, 4 * (size_t)nc * sizeof(int));
    for (int c = 0; c < nc; c++) {
        int *m = b->mnc + 3 * c;
        if (b->mcount[c] == 0 && !b->ninterval)
            m[0] = m[1] = m[2] = 1;
        else
            grid_dims(d, b->cutab[c * nc + c], b->mcount[c], b->cells_per_atom, m);
        b->mbase[c] = (int)total;
        total += (long)m[0] * m[1] * m[2];
        if (total > 1L << 30)
            gr_error(g, "neighbor multi: more than 2^30 cells");
        for (int q = 0; q < 3; q++) {
            mg[4 * c + q] = m[q];
            b->minvh[3 * c + q] = m[q] / (d->hi[q] - d->lo[q]);
        }
        mg[4 * c + 3] = b->mbase[c];
    }
    b->mbase[nc] = (int)total;
    b->ncell = (int)total;
    eng_write(g, b->d_mgrid, 0, 4 * (size_t)nc * sizeof(int), mg);
    eng_write_reals(g, b->d_minv, 3 * (size_t)nc, b->minvh);
    free(mg);
}

/* Cell grid over the current box. */
static void make_grid(struct gravel *g, struct nbr *b, int n)
{
    struct domain *d = &g->dom;
    double f[3];
    domain_ufac(d, f);
    grid_dims(d, b->cutmax, n, b->cells_per_atom, b->nc); /* a sparse scene: larger cells */
    b->ncell = b->nc[0] * b->nc[1] * b->nc[2];
    if (b->multi)
        make_grids_multi(g, b);
    for (int q = 0; q < 3; q++) {
        b->lo[q] = d->lo[q];
        b->hi[q] = d->hi[q];
        b->inv[q] = b->nc[q] / (d->hi[q] - d->lo[q]);
        if (domain_contact_periodic(g, q) && (d->hi[q] - d->lo[q]) / f[q] < 2 * b->cutpair)
            gr_error(g, "periodic box %s %g in %c is less than twice the neighbor cut-off "
                        "%g (the two largest radii + skin)", d->triclinic ? "width" : "length",
                     (d->hi[q] - d->lo[q]) / f[q], "xyz"[q], b->cutpair);
    }
    list_box(g, &b->list);
    box_corners(g, b->corners_hold);
    b->box_moved = 0;
}

/* The full list of atoms 0 .. n-1 (ghosts included) in partner-tag order;
 * cells list their atoms in b->perm unless the atoms were just re-sorted
 * (sorted: contiguous ranges). */
static void build_list(struct gravel *g, struct nbr *b, int sorted, int n)
{
    struct engine *e = g->eng;
    for (;;) {
        reset_flags(g, b);
        cl_kernel k = b->multi ? b->k_build_multi : b->k_build;
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
        if (b->multi) {
            eng_arg_int(g, k, a++, b->ncoll);
            eng_arg_int(g, k, a++, b->ninterval);
            eng_arg_mem(g, k, a++, b->d_collcut);
            eng_arg_mem(g, k, a++, b->d_type2coll);
            eng_arg_mem(g, k, a++, b->d_mgrid);
            eng_arg_mem(g, k, a++, b->d_minv);
            eng_arg_mem(g, k, a++, b->d_cutab);
        } else {
            for (int q = 0; q < 3; q++)
                eng_arg_int(g, k, a++, b->nc[q]);
        }
        for (int q = 0; q < 3; q++)
            eng_arg_int(g, k, a++, domain_contact_periodic(g, q));
        for (int q = 0; q < 3; q++)
            eng_arg_coord(g, k, a++, q, b->lo[q]);
        if (!b->multi)
            for (int q = 0; q < 3; q++)
                eng_arg_real(g, k, a++, b->inv[q]);
        a = nbr_arg_box(g, k, a, &b->list);
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
        eng_arg_mem(g, k, a++, e->a.mol ? e->a.mol : e->a.tag);
        eng_arg_mem(g, k, a++, b->typecut);
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

/* LAMMPS 2021's bin grid (NBinStandard::setup_bins, one process, style
 * bin): bins of half the largest cut-off plus skin, fitted exactly into the
 * box; z a single bin in 2-d. Arguments a.. of hist_transfer (used under
 * -compat lammps2021); returns the next argument index. */
static int lammps2021_bins(struct gravel *g, struct nbr *b, cl_kernel k, int a)
{
    const struct domain *d = &g->dom;
    double binsize = 0.5 * (b->lmp_cutmax > 0 ? b->lmp_cutmax : b->cutmax), lo[3], hi[3], inv[3];
    int nb[3];
    for (int q = 0; q < 3; q++) {
        double len = d->hi[q] - d->lo[q];
        nb[q] = q == 2 && d->dimension == 2 ? 1 : (int)(len * (1.0 / binsize));
        if (nb[q] < 1)
            nb[q] = 1;
        lo[q] = d->lo[q];
        hi[q] = d->hi[q];
        inv[q] = 1.0 / (len / nb[q]);
    }
    for (int q = 0; q < 3; q++)
        eng_arg_coord(g, k, a++, q, lo[q]);
    for (int q = 0; q < 3; q++)
        eng_arg_coord(g, k, a++, q, hi[q]);
    for (int q = 0; q < 3; q++)
        eng_arg_real(g, k, a++, inv[q]);
    for (int q = 0; q < 3; q++)
        eng_arg_int(g, k, a++, nb[q]);
    double cut = b->lmp_cutmax > 0 ? b->lmp_cutmax : b->cutmax;
    eng_arg_real(g, k, a++, cut * cut);
    return a;
}

/* The history transfer (kernels/neighbor.cl hist_transfer) of the current
 * contacts from previous ones: nc < 0 for none (-nc contacts). */
static void transfer(struct gravel *g, struct nbr *b, int nc, cl_mem perm, int permuted,
                     cl_mem coff_old, cl_mem parked, int at, cl_mem old_shear)
{
    struct engine *e = g->eng;
    struct nbr_list *l = &b->list;
    cl_kernel k = b->k_hist_transfer;
    int a = 0;
    eng_arg_int(g, k, a++, nc);
    eng_arg_mem(g, k, a++, l->ci);
    eng_arg_mem(g, k, a++, l->cj);
    eng_arg_mem(g, k, a++, perm);
    eng_arg_int(g, k, a++, permuted);
    eng_arg_mem(g, k, a++, coff_old);
    eng_arg_mem(g, k, a++, parked);
    eng_arg_int(g, k, a++, at);
    eng_arg_mem(g, k, a++, old_shear);
    eng_arg_mem(g, k, a++, l->shear);
    eng_arg_mem(g, k, a++, e->a.x);
    eng_arg_mem(g, k, a++, e->a.radius);
    a = nbr_arg_box(g, k, a, l);
    eng_arg_mem(g, k, a++, e->a.tag);
    a = lammps2021_bins(g, b, k, a);
    eng_arg_pos_lo(g, k, a); /* single precision only (POS_LO_PARAM) */
    eng_launch(g, k, (size_t)(nc < 0 ? -nc : nc));
}

/* Contacts of the rows just built (atoms 0 .. n-1): offsets (scan of the
 * owned counts), owners, partners, the partner side's contacts; then their
 * history. */
static void build_contacts(struct gravel *g, struct nbr *b, int permuted, int n)
{
    struct engine *e = g->eng;
    struct nbr_list *l = &b->list;
    nbr_scan(g, l->nown, l->coff, n);
    nbr_scan(g, l->ncount, l->ioff, n); /* rows packed: 2 slots per contact */
    cl_int total = 0;
    eng_read(g, l->coff, (size_t)n * sizeof(cl_int), sizeof total, &total);
    if ((size_t)total > b->cap_contact || (size_t)total > b->cap_pair)
        mem_fit_contacts(g, (size_t)total); /* all of the contacts' buffers, before any */
    alloc_contacts(g, b, (size_t)total);
    l->ncontact = total;
    quiet_clear(g); /* the records' buffer holds the parked history */
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
    eng_arg_mem(g, k, a++, l->pcon);
    eng_arg_mem(g, k, a++, b->flags);
    eng_launch(g, k, (size_t)n);
    cl_int fl[4];
    read_flags(g, b, fl);
    if (fl[3])
        gr_error(g, "internal error: the neighbor list is not symmetric (a pair is missing "
                    "from one partner's row) at step %lld", (long long)g->step);
    int have_old = e->history && b->old_valid && b->ncontact_old > 0;
    if (e->history && !have_old)
        eng_fill_zero(g, l->shear, (size_t)total * e->hist_n * e->rsz);
    if (!have_old && !(e->history && e->hist_owner && total > 0)) {
        alloc_records(g, b, (size_t)total);
        return;
    }
    /* the transfer; with no previous contacts it only records LAMMPS's owners */
    cl_mem any = l->ci; /* the previous contacts' buffers are not read without them */
    transfer(g, b, have_old ? total : -total, have_old ? b->perm : any, permuted,
             have_old ? b->coff_old : any, have_old ? l->rec : any, (int)b->old_cj_at,
             have_old ? l->rec : l->shear);
    alloc_records(g, b, (size_t)total); /* after the transfer read the parked contacts */
}

void nbr_history_install(struct gravel *g, const void *hist)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    struct nbr_list *l = &b->list;
    size_t bytes = (size_t)l->ncontact * e->hist_n * e->rsz;
    if (!e->history || l->ncontact <= 0)
        return;
    cl_mem from = eng_alloc(g, bytes, "contact history by tag pair");
    eng_write(g, from, 0, bytes, hist);
    /* each contact its own previous one: the transfer keeps what overlaps */
    transfer(g, b, l->ncontact, l->ci, 0, l->coff, l->cj, 0, from);
    eng_finish(g);
    clReleaseMemObject(from);
}

/* Gather one per-atom array (bytes per atom) into the new order through a
 * scratch buffer and copy it back: `scratch` when given (n * bytes at
 * least), else the force buffer, free during a rebuild (the forces of the
 * step are computed after it), or for a field wider than a force (the
 * superellipsoids' quaternions, 4 REALs) a buffer allocated here. */
static void reorder_array(struct gravel *g, struct nbr *b, cl_mem m, size_t bytes, int n,
                          cl_mem scratch)
{
    struct engine *e = g->eng;
    if (n == 0)
        return;
    if (bytes % 4)
        gr_error(g, "internal error: a per-atom field of %zu bytes per atom is not a whole "
                    "number of words", bytes);
    cl_mem own = NULL;
    if (!scratch)
        scratch = bytes > 3 * e->rsz ? (own = eng_alloc(g, (size_t)n * bytes, "re-sort scratch"))
                                     : e->a.f;
    cl_kernel k = b->k_reorder_words;
    eng_arg_int(g, k, 0, n);
    eng_arg_int(g, k, 1, (int)(bytes / 4));
    eng_arg_mem(g, k, 2, b->perm);
    eng_arg_mem(g, k, 3, m);
    eng_arg_mem(g, k, 4, scratch);
    eng_launch(g, k, (size_t)n);
    OCL_CHECK(g, clEnqueueCopyBuffer(e->ocl.queue, scratch, m, 0, 0, (size_t)n * bytes, 0, NULL,
                                     NULL));
    if (own) {
        eng_finish(g);
        clReleaseMemObject(own);
    }
}

/* Re-sort every per-atom array (and the fixes' per-atom state) by b->perm,
 * keeping nkeep atoms; the previous contacts are renamed into the new order
 * for the history transfer. */
static void resort_atoms(struct gravel *g, struct nbr *b, int n, int nkeep)
{
    struct engine *e = g->eng;
    struct dev_atoms *s = &e->a;
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
        eng_arg_mem(g, k, 2, b->list.rec);
        eng_arg_int(g, k, 3, (int)b->old_cj_at);
        eng_launch(g, k, (size_t)b->ncontact_old);
    }
    /* the fields that move with their atoms (atom_fields.h, FL_STATE) */
#define REORDER(name, ctype, dev, width, when, life, sect, what)                               \
    if (life == FL_STATE && s->name)                                                          \
        reorder_array(g, b, s->name, eng_field_bytes(g, dev, sizeof(ctype), width), nkeep, NULL);
    ATOM_FIELDS(REORDER)
#undef REORDER
    if (s->xlo)
        reorder_array(g, b, s->xlo, 3 * e->rsz, nkeep, NULL);
    if (s->custom) /* the custom properties' records: their own scratch (any width) */
        reorder_array(g, b, s->custom, (size_t)s->custom_slots * sizeof(double), nkeep,
                      s->custom_tmp);
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

/* Bin by collection (neighbor multi); an atom in no collection (a
 * diameter above the last collection/interval cut-off) stops the run. */
static void bin_multi(struct gravel *g, struct nbr *b, int n)
{
    struct engine *e = g->eng;
    reset_flags(g, b);
    cl_kernel k = b->k_bin_multi;
    int a = 0;
    eng_arg_int(g, k, a++, n);
    eng_arg_mem(g, k, a++, e->a.x);
    eng_arg_mem(g, k, a++, e->a.radius);
    eng_arg_mem(g, k, a++, e->a.type);
    eng_arg_int(g, k, a++, b->ninterval);
    eng_arg_mem(g, k, a++, b->d_collcut);
    eng_arg_mem(g, k, a++, b->d_type2coll);
    eng_arg_mem(g, k, a++, b->d_mgrid);
    eng_arg_mem(g, k, a++, b->d_minv);
    eng_arg_int(g, k, a++, b->ncell);
    for (int q = 0; q < 3; q++)
        eng_arg_coord(g, k, a++, q, b->lo[q]);
    for (int q = 0; q < 3; q++)
        eng_arg_coord(g, k, a++, q, b->hi[q]);
    for (int q = 0; q < 3; q++)
        eng_arg_real(g, k, a++, b->list.tilt[q]);
    eng_arg_mem(g, k, a++, b->cellof);
    eng_arg_mem(g, k, a++, b->counts);
    eng_arg_mem(g, k, a++, b->flags);
    eng_launch(g, k, (size_t)n);
    cl_int fl[4];
    read_flags(g, b, fl);
    if (fl[1] != 0x7fffffff) {
        long long tag = 0;
        union {
            double d;
            float f;
        } r;
        eng_read(g, e->a.tag, (size_t)fl[1] * sizeof(cl_long), sizeof(cl_long), &tag);
        eng_read(g, e->a.radius, (size_t)fl[1] * e->rsz, e->rsz, &r);
        gr_error(g, "atom %lld of diameter %g exceeds the largest collection/interval cut-off "
                    "%g of neighbor multi (step %lld)", tag,
                 2 * (e->rsz == sizeof(double) ? r.d : (double)r.f),
                 g->neigh.coll_cut[b->ncoll - 1], (long long)g->step);
    }
}

void nbr_rebuild(struct gravel *g)
{
    struct engine *e = g->eng;
    struct nbr *b = get(g);
    wrap_and_extent(g, b);
    if (par_on(g)) { /* a decomposed run: atoms to their ranks, ghosts behind them */
        b->old_valid = 0; /* the history comes back by tag pair (par_history_restore) */
        par_exchange(g, b->cutmax);
        if (b->cap_atoms != (size_t)e->cap) { /* the exchange grew the atoms' room */
            grow_atoms(g, b, (size_t)e->cap);
            alloc_list(g, b, b->list.maxn);
        }
    }
    int n = e->a.n + par_nghost(g);
    make_grid(g, b, n);
    grow_cells(g, b, (size_t)b->ncell);
    int m = b->ncell + 1; /* + sentinel cell of lost atoms */
    eng_fill_zero(g, b->counts, (size_t)m * sizeof(cl_int));
    if (b->multi) {
        bin_multi(g, b, n);
    } else {
        cl_kernel k = b->k_bin;
        eng_arg_int(g, k, 0, n);
        eng_arg_mem(g, k, 1, e->a.x);
        for (int q = 0; q < 3; q++)
            eng_arg_int(g, k, 2 + q, b->nc[q]);
        for (int q = 0; q < 3; q++) {
            eng_arg_coord(g, k, 5 + q, q, b->lo[q]);
            eng_arg_coord(g, k, 8 + q, q, b->hi[q]);
            eng_arg_real(g, k, 11 + q, b->inv[q]);
            eng_arg_real(g, k, 14 + q, b->list.tilt[q]);
        }
        eng_arg_mem(g, k, 17, b->cellof);
        eng_arg_mem(g, k, 18, b->counts);
        eng_launch(g, k, (size_t)n);
    }
    nbr_scan(g, b->counts, b->start, m);
    cl_int nkeep = n;
    eng_read(g, b->start, (size_t)b->ncell * sizeof(cl_int), sizeof nkeep, &nkeep);
    if (nkeep < n) {
        if (g->thermo.lost == LOST_ERROR) {
            /* name the first lost atom (in the sentinel cell) */
            int *cell = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
            eng_read(g, b->cellof, 0, (size_t)n * sizeof(cl_int), cell);
            int first = 0;
            while (first < n - 1 && cell[first] != b->ncell)
                first++;
            free(cell);
            long long tag = 0;
            double x[3], v[3];
            atom_state(g, first, &tag, x, v);
            char seen[600], cause[400];
            diag_lost_atom(g, tag, x, v, seen, sizeof seen);
            diag_time_step(g, cause, sizeof cause);
            gr_error(g, "Lost atoms: original %d current %d at step %lld: %s%s; thermo_modify "
                        "lost ignore|warn keeps going", n, (int)nkeep, (long long)g->step, seen,
                     cause);
        }
        if (g->thermo.lost == LOST_WARN)
            gr_warn(g, "Lost atoms: original %d current %d (step %lld)", n, (int)nkeep,
                    (long long)g->step);
    }
    eng_fill_zero(g, b->cursor, (size_t)m * sizeof(cl_int));
    cl_kernel k = b->k_scatter;
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
    /* atom_modify sort: every rebuild (default, < 0; on the serial device,
     * whose scenes stay in cache, LAMMPS's 1000 steps), never (0) or at the
     * first rebuild N steps after the last; lost atoms are always dropped */
    bigint every = g->neigh.sort_every;
    if (every < 0 && e->ocl.serial)
        every = 1000;
    int resort = !par_on(g) && (nkeep < n || !b->built || every < 0 ||
                                (every > 0 && g->step - b->last_sort >= every));
    if (e->history && b->old_valid)
        retire_contacts(g, b);
    if (resort) {
        resort_atoms(g, b, n, nkeep);
        b->last_sort = g->step;
    }
    build_list(g, b, resort, resort ? nkeep : n);
    build_contacts(g, b, resort, resort ? nkeep : n);
    if (par_on(g)) {
        par_history_restore(g);
        nkeep = e->a.n; /* the owned atoms: ghosts are never checked */
    }
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
    /* a potential (pair colloid) has no bodies in contact: radii mean nothing */
    if (g->styles.pair && g->styles.pair->caps.energy)
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
    nbr_arg_box(g, k, 7, &b->list);
    eng_arg_mem(g, k, 13, b->ext);
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

int nbr_xhold_read(struct gravel *g, int n, double *out)
{
    struct engine *e = g->eng;
    if (!e || !e->nbr || !e->nbr->built)
        return -1;
    if (n > 0)
        eng_read_reals(g, e->nbr->xhold, 3 * (size_t)n, out);
    if (e->single) /* the device's are relative to the origin */
        for (size_t i = 0; i < 3 * (size_t)n; i++)
            out[i] += e->origin[i % 3];
    return e->nbr->ago;
}

int nbr_contact_forces(struct gravel *g, int **ci, int **cj, double **f, double **t)
{
    struct engine *e = g->eng;
    if (!e || !e->nbr || !e->nbr->built || e->a.n != g->atoms.n)
        return -1;
    const struct nbr_list *l = &e->nbr->list;
    const int nc = l->ncontact;
    const size_t w = rec_reals(e);
    *ci = gr_malloc(g, ((size_t)nc + 1) * sizeof(int));
    *cj = gr_malloc(g, ((size_t)nc + 1) * sizeof(int));
    *f = gr_malloc(g, (3 * (size_t)nc + 1) * sizeof(double));
    if (t)
        *t = gr_calloc(g, 3 * (size_t)nc + 1, sizeof(double));
    if (nc == 0)
        return 0;
    double *rec = gr_malloc(g, w * (size_t)nc * sizeof(double));
    unsigned char *quiet = gr_calloc(g, (size_t)nc, 1);
    eng_read(g, l->ci, 0, (size_t)nc * sizeof(cl_int), *ci);
    eng_read(g, l->cj, 0, (size_t)nc * sizeof(cl_int), *cj);
    if (l->quiet)
        eng_read(g, l->quiet, 0, (size_t)nc, quiet);
    if (l->rec)
        eng_read_reals(g, l->rec, w * (size_t)nc, rec);
    else
        memset(rec, 0, w * (size_t)nc * sizeof(double));
    for (int c = 0; c < nc; c++)
        for (int d = 0; d < 3; d++) {
            const double *r = rec + w * (size_t)c;
            (*f)[3 * (size_t)c + d] = quiet[c] ? 0.0 : r[d];
            /* the owner's torque: its own (F ti tj), or -radi tc (PAIR_TC) */
            if (t && !quiet[c] && w > 3)
                (*t)[3 * (size_t)c + d] =
                    w == 9 ? r[3 + d] : -g->atoms.radius[(*ci)[c]] * r[3 + d];
        }
    free(rec);
    free(quiet);
    return nc;
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
    s->history = e->history ? e->hist_n : 0;
    s->ncount = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
    s->nlist = gr_malloc(g, ((size_t)n * maxn + 1) * sizeof(int));
    s->xhold = gr_malloc(g, (3 * (size_t)n + 1) * sizeof(double));
    eng_read(g, l->ncount, 0, (size_t)n * sizeof(cl_int), s->ncount);
    eng_read(g, l->nlist, 0, (size_t)n * maxn * sizeof(cl_int), s->nlist);
    nbr_xhold_read(g, n, s->xhold);
    const int hw = e->hist_n;
    if (e->history) {
        /* per row slot: the owner's history, its negative on the partner's side
         * (only the owner's is read back: contacts are owned by the lower tag) */
        s->shear = gr_calloc(g, (size_t)hw * n * maxn + 1, sizeof(double));
        int *ioff = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
        int *coff = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
        int *pcon = gr_malloc(g, ((size_t)nc + 1) * sizeof(int));
        double *sh = gr_malloc(g, ((size_t)hw * nc + 1) * sizeof(double));
        eng_read(g, l->ioff, 0, ((size_t)n + 1) * sizeof(cl_int), ioff);
        eng_read(g, l->coff, 0, ((size_t)n + 1) * sizeof(cl_int), coff);
        eng_read(g, l->pcon, 0, (size_t)nc * sizeof(cl_int), pcon);
        eng_read_reals(g, l->shear, (size_t)hw * nc, sh);
        for (int i = 0; i < n; i++) {
            int cnt = ioff[i + 1] - ioff[i], first = cnt - (coff[i + 1] - coff[i]);
            for (int k = 0; k < cnt; k++) {
                int c = k < first ? pcon[ioff[i] - coff[i] + k] : coff[i] + k - first;
                double sign = k < first ? -1.0 : 1.0;
                size_t slot = (size_t)i * maxn + (size_t)k;
                for (int d = 0; d < hw; d++)
                    s->shear[hw * slot + d] = sign * sh[hw * (size_t)c + d];
            }
        }
        free(ioff);
        free(coff);
        free(pcon);
        free(sh);
    }
    return 1;
}

/* Order row slots by partner tag (insertion sort: rows are short). */
static void sort_row(int *row, double *shear, int hw, int cnt, const int64_t *tag)
{
    double sh[GR_HIST_MAX] = {0};
    size_t w = (size_t)hw * sizeof(double);
    for (int a = 1; a < cnt; a++) {
        int j = row[a];
        if (shear)
            memcpy(sh, shear + (size_t)hw * a, w);
        int b = a - 1;
        while (b >= 0 && tag[row[b]] > tag[j]) {
            row[b + 1] = row[b];
            if (shear)
                memcpy(shear + (size_t)hw * (b + 1), shear + (size_t)hw * b, w);
            b--;
        }
        row[b + 1] = j;
        if (shear)
            memcpy(shear + (size_t)hw * (b + 1), sh, w);
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
    const int hw = e->hist_n;
    if (e->history && s->shear && s->history != hw)
        gr_error(g, "internal error: neighbor state of history width %d for width %d",
                 s->history, hw);
    double *rsh = e->history ? gr_calloc(g, (size_t)hw * slots + 1, sizeof(double)) : NULL;
    memcpy(row, s->nlist, slots * sizeof(int));
    if (rsh && s->shear)
        memcpy(rsh, s->shear, (size_t)hw * slots * sizeof(double));
    size_t total = 0, nin = 0;
    for (int i = 0; i < n; i++) {
        ioff[i] = (int)nin;
        nin += (size_t)s->ncount[i];
        sort_row(row + (size_t)i * maxn, rsh ? rsh + (size_t)hw * i * maxn : NULL, hw,
                 s->ncount[i], tag);
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
    int *pcon = gr_malloc(g, (total + 1) * sizeof(int));
    char *met = gr_calloc(g, total + 1, 1); /* the owned contact's partner slot was found */
    double *sh = e->history ? gr_calloc(g, (size_t)hw * total + 1, sizeof(double)) : NULL;
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
                if (sh)
                    memcpy(sh + (size_t)hw * c, rsh + (size_t)hw * slot, (size_t)hw * sizeof(double));
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
            pcon[ioff[i] - coff[i] + k] = coff[j] + at - jfirst;
            met[coff[j] + at - jfirst] = 1;
        }
    }
    /* an owned contact whose partner's row lacks the owner is asymmetric too */
    for (size_t c = 0; c < total && !asym; c++)
        asym = !met[c];
    if (!asym) {
        alloc_list(g, b, maxn);
        alloc_contacts(g, b, total);
        alloc_records(g, b, total);
        l->ncontact = (int)total;
        eng_write(g, l->ncount, 0, (size_t)n * sizeof(cl_int), s->ncount);
        eng_write(g, l->nlist, 0, slots * sizeof(cl_int), row);
        eng_write(g, l->ioff, 0, ((size_t)n + 1) * sizeof(cl_int), ioff);
        eng_write(g, l->pcon, 0, total * sizeof(cl_int), pcon);
        eng_write(g, l->nown, 0, (size_t)n * sizeof(cl_int), nown);
        eng_write(g, l->coff, 0, ((size_t)n + 1) * sizeof(cl_int), coff);
        eng_write(g, l->ci, 0, total * sizeof(cl_int), ci);
        eng_write(g, l->cj, 0, total * sizeof(cl_int), cj);
        if (sh)
            eng_write_reals(g, l->shear, (size_t)hw * total, sh);
        double *xh = gr_malloc(g, (3 * (size_t)n + 1) * sizeof(double));
        for (size_t i = 0; i < 3 * (size_t)n; i++) /* device: relative to the origin */
            xh[i] = s->xhold[i] - e->origin[i % 3];
        eng_write_reals(g, b->xhold, 3 * (size_t)n, xh);
        free(xh);
    }
    free(row);
    free(ioff);
    free(pcon);
    free(met);
    free(nown);
    free(coff);
    free(rsh);
    free(ci);
    free(cj);
    free(sh);
    if (asym)
        return 0;
    list_box(g, l);
    box_corners(g, b->corners_hold);
    b->box_moved = 0;
    b->ago = s->ago;
    b->built = 1;
    b->old_valid = e->history;
    return 1;
}

void nbr_list_box(const struct nbr_list *l, double box[6])
{
    for (int q = 0; q < 3; q++) {
        box[q] = l->L[q];
        box[3 + q] = l->tilt[q];
    }
}
