/* par.c - the atoms of a decomposed run: keep, migrate, ghosts, forward,
 * gather, and the contact history that moves with them (par.h). */
#include "par.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "comm.h"
#include "compute.h"
#include "device.h"
#include "domain.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "log.h"
#include "neighbor.h"
#include "par_hist.h"

/* ---- state ---------------------------------------------------------------------- */

struct par *par_state(struct gravel *g)
{
    if (!g->par)
        g->par = gr_calloc(g, 1, sizeof *g->par);
    return g->par;
}

void par_free(struct gravel *g)
{
    struct par *p = g->par;
    if (!p)
        return;
    free(p->sendn);
    free(p->soff);
    free(p->sendidx);
    free(p->recvn);
    par_hist_free(p->hist);
    decomp_free(&p->dc);
    for (int k = 0; k < p->nsaved; k++)
        free(p->saved[k].state);
    free(p->kept);
    free(p->tags_built);
    free(p->xhold_end);
    free(p->resume_ft);
    if (p->gathered) /* an error during an output step: this rank's own arrays */
        atoms_free_fields(&p->local);
    free(p);
    g->par = NULL;
}

int par_on(const struct gravel *g) { return g->par && g->par->on; }
int par_gathered(const struct gravel *g) { return g->par && g->par->gathered; }
int par_nghost(const struct gravel *g) { return par_on(g) ? g->par->nghost : 0; }

long long par_natoms(const struct gravel *g)
{
    if (par_on(g) && !par_gathered(g))
        return comm_sum_ll(g->atoms.n);
    return g->atoms.n;
}

/* ---- the processors command ------------------------------------------------------ */

void cmd_processors(struct gravel *g, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "processors needs Px Py Pz (a count or *), got %d arguments", argc);
    if (argc > 3)
        gr_error(g, "processors keyword '%s' is not supported (only Px Py Pz)", argv[3]);
    struct decomp *d = &par_state(g)->dc;
    for (int q = 0; q < 3; q++) {
        if (strcmp(argv[q], "*") == 0) {
            d->user[q] = 0;
            continue;
        }
        long v = arg_int(g, argv[q], "processors count");
        if (v < 1 || v > 1 << 20)
            gr_error(g, "processors count '%s' must be * or a positive integer", argv[q]);
        d->user[q] = (int)v;
    }
    if (g->dom.box_exists && g->dom.dimension == 2 && d->user[2] > 1)
        gr_error(g, "processors: Pz must be 1 for a 2d simulation, got %d", d->user[2]);
}

/* `comm_style brick|tiled`: tiled lets balance rcb tile the box (brick
 * drops a tiling at the next run). One process has nothing to decompose. */
void cmd_comm_style(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    if (strcmp(argv[0], "brick") != 0 && strcmp(argv[0], "tiled") != 0)
        gr_error(g, "comm_style '%s' is not brick or tiled", argv[0]);
    par_state(g)->dc.tiled = !strcmp(argv[0], "tiled");
}

/* ---- the per-atom record: the FL_STATE rows of the field table -------------------- */

static size_t raw_pos_bytes(const struct gravel *g)
{
    return g->eng->single ? 6 * g->eng->rsz : 0; /* x and xlo as the device has them */
}

/* Device bytes an atom carries besides its field-table rows: its position
 * bits (single precision), then each fix's per-atom state (fix.h). */
static size_t extra_bytes(const struct gravel *g)
{
    size_t b = raw_pos_bytes(g);
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->peratom)
            b += g->styles.fix[i]->peratom_bytes;
    return b;
}

static size_t record_bytes(const struct gravel *g)
{
    size_t b = extra_bytes(g);
#define BYTES(name, ctype, dev, width, when, life, sect, what)                                 \
    if (life == FL_STATE && atoms_holds(&g->atoms, when))                                     \
        b += sizeof(ctype) * (width);
    ATOM_FIELDS(BYTES)
#undef BYTES
    return b + (size_t)g->atoms.cus.slots * sizeof(double); /* the custom properties */
}

/* atom i's record; raw: its device position bytes (single precision) */
static void pack_rows(const struct atoms *a, int i, const unsigned char *raw, size_t rawb,
                      int all, unsigned char *out)
{
#define PACK(name, ctype, dev, width, when, life, sect, what)                                  \
    if ((life == FL_STATE || all) && atoms_holds(a, when)) {                                                            \
        memcpy(out, a->name + (size_t)i * (width), sizeof(ctype) * (width));                  \
        out += sizeof(ctype) * (width);                                                       \
    }
    ATOM_FIELDS(PACK)
#undef PACK
    size_t cb = (size_t)a->cus.slots * sizeof(double);
    memcpy(out, a->custom + (size_t)i * a->cus.slots, cb);
    out += cb;
    if (rawb)
        memcpy(out, raw, rawb);
}

static void unpack_rows(struct atoms *a, int i, const unsigned char *in, unsigned char *raw,
                        size_t rawb, int all)
{
#define UNPACK(name, ctype, dev, width, when, life, sect, what)                                \
    if ((life == FL_STATE || all) && atoms_holds(a, when)) {                                                            \
        memcpy(a->name + (size_t)i * (width), in, sizeof(ctype) * (width));                   \
        in += sizeof(ctype) * (width);                                                        \
    }
    ATOM_FIELDS(UNPACK)
#undef UNPACK
    size_t cb = (size_t)a->cus.slots * sizeof(double);
    memcpy(a->custom + (size_t)i * a->cus.slots, in, cb);
    in += cb;
    if (rawb)
        memcpy(raw, in, rawb);
}

static void pack_atom(const struct atoms *a, int i, const unsigned char *raw, size_t rawb,
                      unsigned char *out)
{
    pack_rows(a, i, raw, rawb, 0, out);
}

static void unpack_atom(struct atoms *a, int i, const unsigned char *in, unsigned char *raw,
                        size_t rawb)
{
    unpack_rows(a, i, in, raw, rawb, 0);
}

/* bytes of every row of the field table (FL_STEP ones too: dumps show forces)
 * and of the custom properties' record */
static size_t all_rows_bytes(const struct atoms *a)
{
    size_t b = (size_t)a->cus.slots * sizeof(double);
#define BYTES(name, ctype, dev, width, when, life, sect, what)                                 \
    if (atoms_holds(a, when))                                                                 \
        b += sizeof(ctype) * (width);
    ATOM_FIELDS(BYTES)
#undef BYTES
    return b;
}

/* ---- what runs across ranks --------------------------------------------------------- */

/* Fix styles that run on MPI ranks, each checked against one process in
 * its test (the rest stop a decomposed run: doc/parallel.md lists them). */
static const char *const par_fixes[] = {"nve/sphere", "nve", "gravity", "freeze", "enforce2d",
                                        "viscous", "setforce", "addforce", "aveforce", "wall/gran",
                                        "wall/gran/region", "wall/pair", "balance", "mesh/surface",
                                        "move/mesh", "pour", "ave/time", "ave/chunk", "ave/histo",
                                        "ave/atom", "wall/reflect", "drag", "property/global",
                                        "mesh/surface/stress", "mesh/surface/planar",
                                        "particletemplate/sphere", "particledistribution/discrete",
                                        "insert/pack", "insert/rate/region", "insert/stream",
                                        "check/timestep/gran", "heat/gran", "heat/gran/conduction",
                                        "adapt", "property/atom", "heat/flow", "viscous/nonlinear",
                                        "momentum", "rigid/small", "multisphere", "surface/global",
                                        "surface/local", "nvt", "nvt/sphere", "deform", "npt",
                                        "npt/sphere", "nph", "nph/sphere",
                                        "particletemplate/multisphere", "granular/mdr", "halt",
                                        "print", "move", "ave/correlate", "spring/self", "indent",
                                        "temp/rescale", "damping/cundall", "add/heat", "rigid",
                                        "store/state", "particledistribution/discrete/numberbased",
                                        "particledistribution/discrete/massbased", "deposit",
                                        "langevin", "nve/limit", "nve/noforce", "lineforce",
                                        "planeforce", "spring", "temp/berendsen",
                                        "massflow/mesh", "ave/spatial", "buoyancy", NULL};

static int listed(const char *const *list, const char *name)
{
    for (int i = 0; list[i]; i++)
        if (strcmp(list[i], name) == 0)
            return 1;
    return 0;
}

/* f_ID[...] of a fix whose global values are summed over the ranks
 * (mesh/surface: the force and torque on the mesh) */
int par_fix_value_global(const struct fix *f)
{
    static const char *const global[] = {"mesh/surface", "mesh/surface/stress", "insert/pack",
                                         "insert/rate/region", "insert/stream",
                                         "check/timestep/gran", "heat/gran",
                                         "heat/gran/conduction", "gravity", "freeze",
                                         /* sums in tag order (force_values.c, fix_indent.c,
                                          * fix_spring_self.c, temperature.c) */
                                         "setforce", "addforce", "aveforce", "spring/self",
                                         "indent", "temp/rescale", "langevin", "nve/limit",
                                         "spring", "temp/berendsen",
                                         "rigid", /* every rank holds every body */
                                         /* the chains' state, the same on every rank */
                                         "nvt", "nvt/sphere", "npt", "npt/sphere", "nph",
                                         "nph/sphere",
                                         "property/global", /* the script's values */
                                         /* each sample taken on every rank's atoms as one
                                          * process (ave_common.c) */
                                         "ave/time", "ave/chunk", "ave/histo", "ave/correlate",
                                         "massflow/mesh", "ave/spatial",
                                         "buoyancy", /* its sum in tag order */
                                         NULL};
    return listed(global, f->style->name);
}

static int fix_summed(struct gravel *g, const char *ref)
{
    size_t len = strcspn(ref, "[");
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *f = g->styles.fix[i];
        if (strlen(f->id) == len && !strncmp(f->id, ref, len))
            return par_fix_value_global(f);
    }
    return 0;
}

static void check_scene(struct gravel *g)
{
    const char *why = NULL;
    static char buf[160];
    for (int i = 0; !why && i < g->styles.nfix; i++)
        if (!listed(par_fixes, g->styles.fix[i]->style->name)) {
            snprintf(buf, sizeof buf, "fix %s (%.60s)", g->styles.fix[i]->id,
                     g->styles.fix[i]->style->name);
            why = buf;
        }
    for (int i = 0; !why && i < g->styles.nfix; i++)
        if (g->styles.fix[i]->energy && !par_fix_value_global(g->styles.fix[i])) {
            snprintf(buf, sizeof buf, "fix_modify %s energy yes", g->styles.fix[i]->id);
            why = buf;
        }
    for (int i = 0; !why && i < g->styles.ncompute; i++)
        if (g->styles.compute[i]->style->ranks == COMPUTE_RANKS_NO) {
            snprintf(buf, sizeof buf, "compute %s (%.60s)", g->styles.compute[i]->id,
                     g->styles.compute[i]->style->name);
            why = buf;
        }
    static const char *const kw[] = {"step", "elapsed", "elaplong", "atoms", "dt", "time", "cpu",
                                     "tpcpu", "spcpu", "cpuremain", "part", "temp", "ke",
                                     "vol", "lx", "ly", "lz", "xlo", "xhi", "ylo", "yhi",
                                     "zlo", "zhi", "xy", "xz", "yz", "cella", "cellb", "cellc",
                                     "cellalpha", "cellbeta", "cellgamma", "press", "pxx",
                                     "pyy", "pzz", "pxy", "pxz", "pyz", "epair", "emol", "pe",
                                     "etotal", "density", "evdwl", "ecoul", "elong", "etail",
                                     "ebond", "eangle", "edihed", "eimp", "nbuild", "ndanger",
                                     "xlat", "ylat", "zlat", "ecouple", "econserve", NULL};
    for (int i = 0; !why && i < g->thermo.ncol; i++) {
        const char *c = g->thermo.col[i];
        if (!strncmp(c, "f_", 2) && fix_summed(g, c + 2))
            continue;
        if (!listed(kw, c) && strncmp(c, "c_", 2) != 0 && strncmp(c, "v_", 2) != 0) {
            snprintf(buf, sizeof buf, "thermo keyword %.60s", c);
            why = buf;
        }
    }
    if (why)
        par_refuse(g, why);
}

void par_refuse(struct gravel *g, const char *why)
{
    gr_error(g, "%s cannot run on %d MPI ranks yet (doc/parallel.md lists what can); run "
                    "it on one rank", why, comm_size());
}

static unsigned char *extra_move(struct gravel *g, int n, unsigned char *extra, int up);

/* by tag: the first 8 bytes of a record */
static int by_first_tag(const void *x, const void *y)
{
    int64_t a, b;
    memcpy(&a, x, sizeof a);
    memcpy(&b, y, sizeof b);
    return (a > b) - (a < b);
}

/* ---- the fixes' per-atom state between runs ------------------------------------------ */

/* At a run's end: each fix's per-atom state of every atom (tag order),
 * from the gathered extra bytes (eb per atom, positions' bits first). */
static void save_fix_state(struct gravel *g, const unsigned char *extra, int total, size_t eb)
{
    struct par *p = g->par;
    for (int k = 0; k < p->nsaved; k++)
        free(p->saved[k].state);
    p->nsaved = 0;
    size_t at = raw_pos_bytes(g);
    for (int i = 0; i < g->styles.nfix && extra; i++) {
        struct fix *f = g->styles.fix[i];
        if (!f->peratom)
            continue;
        if (p->nsaved == PAR_MAXSAVED)
            gr_error(g, "more than %d fixes with per-atom state on several ranks", PAR_MAXSAVED);
        struct par_saved *sv = &p->saved[p->nsaved++];
        sv->fix = f;
        sv->bytes = f->peratom_bytes;
        sv->state = gr_malloc(g, (size_t)total * sv->bytes + 1);
        for (int a = 0; a < total; a++)
            memcpy(sv->state + (size_t)a * sv->bytes, extra + (size_t)a * eb + at, sv->bytes);
        at += f->peratom_bytes;
    }
}

void par_fix_state_restore(struct gravel *g)
{
    struct par *p = g->par;
    if (!p || !p->on || !p->kept)
        return;
    int n = g->atoms.n;
    for (int k = 0; k < p->nsaved; k++) {
        struct par_saved *sv = &p->saved[k];
        struct fix *f = NULL;
        for (int i = 0; i < g->styles.nfix; i++)
            if (g->styles.fix[i] == sv->fix && sv->fix->peratom &&
                sv->fix->peratom_bytes == sv->bytes)
                f = sv->fix;
        if (!f || n == 0)
            continue;
        unsigned char *buf = gr_malloc(g, (size_t)n * sv->bytes);
        for (int a = 0; a < n; a++)
            memcpy(buf + (size_t)a * sv->bytes, sv->state + (size_t)p->kept[a] * sv->bytes,
                   sv->bytes);
        eng_write(g, f->peratom, 0, (size_t)n * sv->bytes, buf);
        free(buf);
    }
}

/* ---- run start and end ---------------------------------------------------------- */

uint64_t par_tag_set_key(const struct atoms *a)
{
    uint64_t h = 1469598103934665603ull ^ (uint64_t)a->n;
    for (int i = 0; i < a->n; i++)
        h = (h ^ (uint64_t)a->tag[i]) * 1099511628211ull;
    return h ? h : 1;
}

/* This rank's atoms of the host's whole set (tag order): those of its brick
 * or tile, with the rows of the last run's end set that the fixes' saved
 * state and the contact history belong to when the set is the same. */
static void keep_brick(struct gravel *g, struct par *p)
{
    struct atoms *a = &g->atoms;
    /* the saved contact history belongs to these atoms only (as one rank
     * keeps its list only while the atoms are the same) */
    int same = par_tag_set_key(a) == p->tags_at_end;
    if (p->hist && !same) {
        par_hist_free(p->hist);
        p->hist = NULL;
    }
    free(p->kept); /* the fixes' saved state: rows of the kept atoms */
    p->kept = same && p->nsaved ? gr_malloc(g, ((size_t)a->n + 1) * sizeof(int)) : NULL;
    int me = comm_rank(), k = 0;
    for (int i = 0; i < a->n; i++)
        if (decomp_owner(g, &p->dc, a->x + 3 * (size_t)i) == me) {
            if (k != i)
                atoms_copy(a, i, k);
            if (p->kept)
                p->kept[k] = i;
            k++;
        }
    a->n = k;
}

void par_run_begin(struct gravel *g)
{
    struct par *p = par_state(g);
    p->on = comm_size() > 1;
    p->nghost = 0;
    p->list_current = 0; /* the device's contacts are the last run's */
    p->ended = 0;
    p->run_cost = 0;
    p->balance_time_last = 0; /* weight time: this run's Pair + Neigh from its start */
    if (!p->on)
        return;
    check_scene(g);
    decomp_setup(g, &p->dc);
    keep_brick(g, p);
    if (decomp_tiled(&p->dc))
        gr_print(g, "Decomposition: %d MPI ranks tiled by rcb\n", comm_size());
    else
        gr_print(g, "Decomposition: %d x %d x %d MPI ranks\n", p->dc.p[0], p->dc.p[1],
                 p->dc.p[2]);
}

/* The current contacts' history into *h by tag pair (the device's raw
 * bytes): the contacts of an owned atom, whose history this rank keeps. */
static void hist_collect(struct gravel *g, struct par_hist **h)
{
    struct engine *e = g->eng;
    const struct nbr_list *l = nbr_list(g);
    int nc = l->ncontact;
    size_t vb = e->history ? (size_t)e->hist_n * e->rsz : 0; /* without: the pairs only */
    if (!*h)
        *h = par_hist_new(g, (size_t)nc, vb);
    if (nc <= 0 || !l->ci)
        return;
    int *ci = gr_malloc(g, 2 * (size_t)nc * sizeof(int));
    unsigned char *sh = gr_malloc(g, (size_t)nc * vb + 1);
    eng_read(g, l->ci, 0, (size_t)nc * sizeof(cl_int), ci);
    eng_read(g, l->cj, 0, (size_t)nc * sizeof(cl_int), ci + nc);
    if (vb)
        eng_read(g, l->shear, 0, (size_t)nc * vb, sh);
    /* the tags of the atoms the list indexes (owned and ghosts at the build:
     * an insertion since may have written over the ghosts' host slots) */
    const int64_t *tag = g->par->tags_built;
    int nown = g->par->nlocal_built;
    for (int c = 0; c < nc; c++) {
        if (ci[c] >= nown && ci[nc + c] >= nown)
            continue; /* two ghosts: their history is their owners' business */
        int64_t a = tag[ci[c]], b = tag[ci[nc + c]];
        par_hist_put(g, h, a < b ? a : b, a < b ? b : a, sh + (size_t)c * vb);
    }
    free(ci);
    free(sh);
}

/* Every rank's contacts and their history by tag pair (a new table). */
static struct par_hist *hist_all(struct gravel *g)
{
    struct par_hist *h = NULL;
    hist_collect(g, &h);
    size_t eb = par_hist_entry_bytes(h);
    unsigned char *buf = gr_malloc(g, h->n * eb + 1), *all = NULL;
    size_t k = 0;
    for (size_t s = 0; s < h->cap; s++)
        if (h->key[2 * s])
            par_hist_entry_pack(h, s, buf + eb * k++);
    size_t bytes = comm_allgatherv(buf, k * eb, (void **)&all);
    free(buf);
    if (bytes == (size_t)-1)
        gr_error(g, "out of memory gathering the contact history of every rank");
    par_hist_free(h);
    h = par_hist_new(g, bytes / eb, eb - 2 * sizeof(int64_t));
    par_hist_entries_put(g, &h, all, bytes);
    free(all);
    return h;
}

/* ... into p->hist (for the next run and restart files). */
static void hist_gather(struct gravel *g)
{
    struct par *p = g->par;
    struct par_hist *h = hist_all(g);
    par_hist_free(p->hist);
    p->hist = h;
}

int par_pair_history(struct gravel *g, int np, const int64_t *tags, int maxw, double *hist)
{
    struct par *p = g->par;
    const struct engine *e = g->eng;
    if (!p || !p->gathered || !e || !e->history || !p->list_current)
        return 0;
    int hw = e->hist_n;
    if (hw <= 0 || hw > maxw)
        return 0;
    struct par_hist *h = hist_all(g);
    for (int k = 0; k < np; k++) {
        double *out = hist + (size_t)k * hw;
        int64_t a = tags[2 * k], b = tags[2 * k + 1];
        const unsigned char *v = par_hist_get(h, a < b ? a : b, a < b ? b : a);
        for (int d = 0; d < hw; d++) {
            out[d] = 0.0;
            if (!v)
                continue;
            if (e->rsz == sizeof(float)) {
                float f;
                memcpy(&f, v + (size_t)d * sizeof f, sizeof f);
                out[d] = f;
            } else {
                memcpy(out + d, v + (size_t)d * sizeof(double), sizeof(double));
            }
        }
    }
    par_hist_free(h);
    return hw;
}

/* Every rank's atoms, every field of the table (forces too), sorted by tag:
 * *total records of *rb bytes (malloc'd). With state, each record carries the
 * atom's extra bytes (the fixes' per-atom state) and the reference position
 * of the last build (3 doubles) at its end. */
static unsigned char *atoms_gather(struct gravel *g, int state, int *total, size_t *rb)
{
    const struct atoms *a = &g->atoms;
    int n = a->n;
    size_t eb = state ? extra_bytes(g) : 0, xb = state ? 3 * sizeof(double) : 0;
    *rb = all_rows_bytes(a) + eb + xb;
    unsigned char *extra = state ? extra_move(g, n, NULL, 0) : NULL;
    double *xh = NULL;
    if (state) {
        xh = gr_malloc(g, (3 * (size_t)n + 1) * sizeof(double));
        if (nbr_xhold_read(g, n, xh) < 0)
            memcpy(xh, a->x, 3 * (size_t)n * sizeof(double));
    }
    unsigned char *mine = gr_malloc(g, (size_t)n * *rb + 1), *all = NULL;
    for (int i = 0; i < n; i++) {
        unsigned char *r = mine + (size_t)i * *rb;
        pack_rows(a, i, extra ? extra + (size_t)i * eb : NULL, eb, 1, r);
        if (xh)
            memcpy(r + *rb - xb, xh + 3 * (size_t)i, xb);
    }
    free(extra);
    free(xh);
    size_t bytes = comm_allgatherv(mine, (size_t)n * *rb, (void **)&all);
    free(mine);
    if (bytes == (size_t)-1)
        gr_error(g, "out of memory gathering the atoms of every rank");
    *total = (int)(bytes / *rb);
    qsort(all, (size_t)*total, *rb, by_first_tag); /* tag: the table's first row */
    return all;
}

/* The gathered records into g->atoms (room reserved here); with state, the
 * fixes' per-atom state saved, the reference positions and the steps since
 * the build (ago) kept for restart files. */
static void atoms_unpack(struct gravel *g, unsigned char *all, int total, size_t rb, int state,
                         int ago)
{
    struct par *p = g->par;
    struct atoms *a = &g->atoms;
    size_t eb = state ? extra_bytes(g) : 0, xb = state ? 3 * sizeof(double) : 0;
    atoms_reserve(g, total);
    unsigned char *extra = eb ? gr_malloc(g, (size_t)total * eb + 1) : NULL;
    if (state) {
        free(p->xhold_end);
        p->xhold_end = gr_malloc(g, (3 * (size_t)total + 1) * sizeof(double));
    }
    for (int i = 0; i < total; i++) {
        const unsigned char *r = all + (size_t)i * rb;
        unpack_rows(a, i, r, extra ? extra + (size_t)i * eb : NULL, eb, 1);
        if (state)
            memcpy(p->xhold_end + 3 * (size_t)i, r + rb - xb, xb);
    }
    a->n = total;
    if (state) {
        save_fix_state(g, extra, total, eb);
        p->tags_at_end = par_tag_set_key(a);
        p->ago_end = ago;
        p->host_hash = atoms_fingerprint(&g->atoms);
        p->ended = 1;
    }
    free(extra);
}

/* steps since the last build, the same on every rank (one without atoms too) */
static int build_age(struct gravel *g)
{
    double *none = NULL, lo = 0, ago = nbr_xhold_read(g, 0, none);
    comm_minmax(&lo, &ago, 1);
    return ago > 0 ? (int)ago : 0;
}

void par_run_end(struct gravel *g)
{
    struct par *p = g->par;
    if (!p || !p->on)
        return;
    struct engine *e = g->eng;
    run_sync_host(g);
    if (p->list_current)
        hist_gather(g);
    int ago = build_age(g), total;
    size_t rb;
    unsigned char *all = atoms_gather(g, 1, &total, &rb);
    atoms_unpack(g, all, total, rb, 1, ago);
    free(all);
    p->on = 0;
    p->nghost = 0;
    e->nghost = 0;
    e->active = 0; /* the device holds one rank's atoms: the host is the truth */
}

/* ---- the exchange at a rebuild -------------------------------------------------- */

/* per-rank byte buffers of an exchange */
struct outbox {
    unsigned char **buf;
    size_t *len, *cap;
};

static void outbox_init(struct gravel *g, struct outbox *o, int P)
{
    o->buf = gr_calloc(g, (size_t)P, sizeof *o->buf);
    o->len = gr_calloc(g, (size_t)P, sizeof *o->len);
    o->cap = gr_calloc(g, (size_t)P, sizeof *o->cap);
}

static unsigned char *outbox_room(struct gravel *g, struct outbox *o, int r, size_t bytes)
{
    if (o->len[r] + bytes > o->cap[r]) {
        o->cap[r] = 2 * (o->len[r] + bytes) + 256;
        o->buf[r] = gr_realloc(g, o->buf[r], o->cap[r]);
    }
    unsigned char *at = o->buf[r] + o->len[r];
    o->len[r] += bytes;
    return at;
}

/* Send the outbox; returns what arrived (malloc'd), *bytes its size. */
static unsigned char *outbox_send(struct gravel *g, struct outbox *o, int P, size_t *bytes,
                                  size_t *from)
{
    void *in = NULL;
    *bytes = comm_alltoallv((void *const *)o->buf, o->len, &in, from);
    if (*bytes == (size_t)-1)
        gr_error(g, "out of memory exchanging atoms between ranks");
    for (int r = 0; r < P; r++)
        free(o->buf[r]);
    free(o->buf);
    free(o->len);
    free(o->cap);
    return in;
}

/* Distance from x to [lo, hi] in one dimension, periodic images included. */
static double gap(double x, double lo, double hi, double L, int periodic)
{
    double best = INFINITY;
    for (int k = periodic ? -1 : 0; k <= (periodic ? 1 : 0); k++) {
        double y = x + k * L, d = y < lo ? lo - y : y > hi ? y - hi : 0;
        best = fmin(best, d);
    }
    return best;
}

/* one device array's rows 0 .. n-1 (w bytes each) to or from column `at`
 * of the extra bytes (stride eb) */
static void extra_column(struct gravel *g, cl_mem m, int n, size_t w, unsigned char *extra,
                         size_t eb, size_t at, int up)
{
    unsigned char *col = gr_malloc(g, (size_t)n * w + 1);
    if (!up)
        eng_read(g, m, 0, (size_t)n * w, col);
    for (int i = 0; i < n; i++)
        if (up)
            memcpy(col + (size_t)i * w, extra + (size_t)i * eb + at, w);
        else
            memcpy(extra + (size_t)i * eb + at, col + (size_t)i * w, w);
    if (up)
        eng_write(g, m, 0, (size_t)n * w, col);
    free(col);
}

/* The extra bytes of atoms 0 .. n-1 from the device (NULL when none), or
 * back to it (up). */
static unsigned char *extra_move(struct gravel *g, int n, unsigned char *extra, int up)
{
    struct engine *e = g->eng;
    size_t eb = extra_bytes(g), half = 3 * e->rsz, at = 0;
    if (!eb || n == 0)
        return extra;
    if (!up)
        extra = gr_malloc(g, (size_t)n * eb);
    if (raw_pos_bytes(g)) {
        extra_column(g, e->a.x, n, half, extra, eb, 0, up);
        extra_column(g, e->a.xlo, n, half, extra, eb, half, up);
        at = 2 * half;
    }
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (!f->peratom)
            continue;
        extra_column(g, f->peratom, n, f->peratom_bytes, extra, eb, at, up);
        at += f->peratom_bytes;
    }
    return extra;
}

static int cmp_i64(const void *x, const void *y)
{
    int64_t a = *(const int64_t *)x, b = *(const int64_t *)y;
    return (a > b) - (a < b);
}

/* new owner of an owned tag (tagdest: pairs (tag, rank) sorted by tag); -1 if not owned here */
static int dest_of(const int64_t *tagdest, int n, int64_t tag)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        int64_t t = tagdest[2 * mid];
        if (t == tag)
            return (int)tagdest[2 * mid + 1];
        if (t < tag)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}

/* Per dimension, the box's width across its faces: the length of an
 * orthogonal box, 1 / |row q of h^-1| in a triclinic one (the distance
 * between the faces lamda_q = 0 and 1). A ghost cut-off c is c / width in
 * lamda (LAMMPS's cutghost of a triclinic box), so the ghosts of a brick
 * are the atoms within that of its lamda slabs: every atom within c of the
 * brick, and a few more. */
static void box_widths(const struct gravel *g, double W[3])
{
    const struct domain *d = &g->dom;
    for (int q = 0; q < 3; q++)
        W[q] = d->hi[q] - d->lo[q];
    if (!d->triclinic)
        return;
    double hi[6];
    domain_h_inv(g, hi);
    W[0] = 1.0 / sqrt(hi[0] * hi[0] + hi[5] * hi[5] + hi[4] * hi[4]);
    W[1] = 1.0 / sqrt(hi[1] * hi[1] + hi[3] * hi[3]);
    W[2] = 1.0 / hi[2];
}

/* fix balance at a rebuild, before the atoms move: when the imbalance
 * (largest rank's load over the mean; the load is the atom count, or the
 * sum of the atoms' weights with a weight keyword) exceeds thresh, the cuts
 * of the dimensions in dims move to the weighted quantiles of every rank's
 * atoms, or (rcb) the box is tiled again by bisecting every rank's atoms;
 * then the out file gets the new boxes. */
static void rebalance(struct gravel *g, unsigned dims, int rcb, double thresh)
{
    struct par *p = g->par;
    struct decomp *dc = &p->dc;
    const struct atoms *a = &g->atoms;
    int P = comm_size();
    /* each rank's costs (weight time, neigh) and atom count */
    double mine[3] = {p->run_cost - p->balance_time_last, nbr_total(g), (double)a->n};
    double *all = NULL;
    size_t b = comm_allgatherv(mine, sizeof mine, (void **)&all);
    if (b != (size_t)P * sizeof mine)
        gr_error(g, "out of memory balancing");
    double *ct = gr_malloc(g, 2 * (size_t)P * sizeof *ct), *cn = ct + P;
    long *nown = gr_malloc(g, (size_t)P * sizeof *nown);
    for (int r = 0; r < P; r++) {
        ct[r] = all[3 * r];
        cn[r] = all[3 * r + 1];
        nown[r] = (long)all[3 * r + 2];
    }
    free(all);
    p->balance_time_last = p->run_cost; /* LAMMPS: the time up to this balance */
    double *wt = p->balance_weigh ? p->balance_weigh(g, p->balance_ctx, a->n, ct, cn, nown)
                                  : NULL;
    free(ct);
    /* each rank's load under the current cuts: its own atoms' */
    double load = 0, *loads = NULL;
    for (int i = 0; i < a->n; i++)
        load += wt ? wt[i] : 1.0;
    b = comm_allgatherv(&load, sizeof load, (void **)&loads);
    if (b != (size_t)P * sizeof load)
        gr_error(g, "out of memory balancing");
    double big = 0, total = 0;
    for (int r = 0; r < P; r++) {
        big = fmax(big, loads[r]);
        total += loads[r];
    }
    free(loads);
    free(nown);
    double imb = total > 0 ? big * P / total : 1.0;
    if (!(imb > thresh)) {
        free(wt);
        return;
    }
    int rec = wt ? 4 : 3;
    if (rcb) {
        double *s = decomp_fractions(g, a->x, a->n, wt, -1), *all3 = NULL;
        b = comm_allgatherv(s, (size_t)rec * a->n * sizeof *s, (void **)&all3);
        free(s);
        if (b == (size_t)-1)
            gr_error(g, "out of memory balancing");
        long m = (long)(b / ((size_t)rec * sizeof *all3));
        decomp_rcb(g, dc, all3, m, wt != NULL);
        free(all3);
    } else {
        int st = wt ? 2 : 1;
        for (int q = 0; q < 3; q++) {
            if (!(dims & (1u << q)) || dc->p[q] < 2)
                continue;
            double *s = decomp_fractions(g, a->x, a->n, wt, q), *all1 = NULL;
            b = comm_allgatherv(s, (size_t)st * a->n * sizeof *s, (void **)&all1);
            free(s);
            if (b == (size_t)-1)
                gr_error(g, "out of memory balancing");
            long m = (long)(b / ((size_t)st * sizeof *all1));
            decomp_quantile_cuts(dc, q, all1, m, wt != NULL);
            free(all1);
        }
    }
    free(wt);
    if (p->balance_out)
        p->balance_out(g, p->balance_ctx);
}

void par_exchange(struct gravel *g, double cut)
{
    struct par *p = g->par;
    struct engine *e = g->eng;
    struct atoms *a = &g->atoms;
    const struct domain *dm = &g->dom;
    int P = comm_size(), me = comm_rank();
    p->cut = cut;
    run_sync_host(g);
    int n = a->n;
    size_t rawb = extra_bytes(g), rb = record_bytes(g);
    unsigned char *raw = extra_move(g, n, NULL, 0); /* positions' bits, fixes' state */
    /* the history to carry: the current contacts', or the table saved at the
     * last run's end (the first build of a run) */
    struct par_hist *old = p->hist;
    p->hist = NULL;
    if (e->history && p->list_current)
        hist_collect(g, &old);
    if (p->balance_dims || p->balance_rcb) { /* fix balance: quantile cuts or rcb tiles */
        rebalance(g, p->balance_dims, p->balance_rcb, p->balance_thresh);
        p->balance_dims = 0;
        p->balance_rcb = 0;
        p->balance_ctx = NULL;
        p->balance_weigh = NULL;
        p->balance_out = NULL;
    }
    /* destinations; an atom outside a fixed face is lost */
    int *dest = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
    int64_t *tagdest = gr_malloc(g, (2 * (size_t)n + 1) * sizeof(int64_t));
    int nlost = 0;
    for (int i = 0; i < n; i++) {
        const double *x = a->x + 3 * (size_t)i;
        int out = 0; /* as the bins of one process: [lo, hi) (triclinic: lamda in [0, 1)) */
        for (int q = 0; q < 3; q++) {
            if (dm->periodic[q])
                continue;
            if (dm->triclinic) {
                double s = decomp_fraction_raw(g, q, x);
                out = out || !(s >= 0 && s < 1);
            } else {
                out = out || !(x[q] >= dm->lo[q] && x[q] < dm->hi[q]);
            }
        }
        if (out && g->thermo.lost == LOST_ERROR)
            gr_error(g, "Lost atoms: atom %lld at %g %g %g left the box through a fixed face "
                        "at step %lld; thermo_modify lost ignore|warn keeps going",
                     (long long)a->tag[i], x[0], x[1], x[2], (long long)g->step);
        dest[i] = out ? -1 : decomp_owner(g, &p->dc, x); /* -1: lost, dropped */
        nlost += out;
        tagdest[2 * i] = a->tag[i];
        tagdest[2 * i + 1] = dest[i];
    }
    long long before = comm_sum_ll(n), lost = comm_sum_ll(nlost);
    if (lost && g->thermo.lost == LOST_WARN)
        gr_warn(g, "Lost atoms: original %lld current %lld (step %lld)", before, before - lost,
                (long long)g->step);
    qsort(tagdest, (size_t)n, 2 * sizeof(int64_t), cmp_i64);
    /* 1. atoms that left the brick */
    struct outbox ob;
    outbox_init(g, &ob, P);
    for (int i = 0; i < n; i++)
        if (dest[i] != me && dest[i] >= 0)
            pack_atom(a, i, raw ? raw + (size_t)i * rawb : NULL, rawb,
                      outbox_room(g, &ob, dest[i], rb));
    size_t inb, from[P];
    unsigned char *in = outbox_send(g, &ob, P, &inb, from);
    /* 2. their contacts' history: each entry to the new owners of the atoms
     * owned here (the other atom's owner sends it to its own) */
    if (e->history) {
        size_t vb = (size_t)e->hist_n * e->rsz;
        if (!old)
            old = par_hist_new(g, 0, vb);
        size_t eb = par_hist_entry_bytes(old);
        struct outbox hb;
        outbox_init(g, &hb, P);
        for (size_t s = 0; s < old->cap; s++) {
            if (!old->key[2 * s])
                continue;
            int da = dest_of(tagdest, n, old->key[2 * s]);
            int db = dest_of(tagdest, n, old->key[2 * s + 1]);
            if (da >= 0)
                par_hist_entry_pack(old, s, outbox_room(g, &hb, da, eb));
            if (db >= 0 && db != da)
                par_hist_entry_pack(old, s, outbox_room(g, &hb, db, eb));
        }
        size_t hin, hfrom[P];
        unsigned char *h = outbox_send(g, &hb, P, &hin, hfrom);
        p->hist = par_hist_new(g, hin / eb, vb);
        par_hist_entries_put(g, &p->hist, h, hin);
        free(h);
    }
    par_hist_free(old);
    /* 3. the owned atoms: those that stay, in order, then the arrivals */
    int k = 0;
    for (int i = 0; i < n; i++)
        if (dest[i] == me) {
            if (k != i) {
                atoms_copy(a, i, k);
                if (raw)
                    memcpy(raw + (size_t)k * rawb, raw + (size_t)i * rawb, rawb);
            }
            k++;
        }
    int narrive = (int)(inb / rb), nlocal = k + narrive;
    atoms_reserve(g, nlocal);
    if (rawb)
        raw = gr_realloc(g, raw, (size_t)(nlocal + 1) * rawb);
    for (int j = 0; j < narrive; j++)
        unpack_atom(a, k + j, in + (size_t)j * rb, raw ? raw + (size_t)(k + j) * rawb : NULL,
                    rawb);
    free(in);
    free(dest);
    free(tagdest);
    a->n = nlocal;
    /* 4. ghosts: every owned atom within the cut-off of another rank's brick
     * (in any periodic image), sent once at its own coordinates: each rank's
     * neighbor build takes every pair by its minimum image, unique because a
     * periodic box is at least twice the neighbor cut-off (checked as on one
     * process), so a ghost near a brick from both sides serves both, and a
     * brick plus twice the ghost cut-off may reach across the box */
    free(p->sendidx);
    p->sendn = gr_realloc(g, p->sendn, (size_t)P * sizeof(int));
    p->soff = gr_realloc(g, p->soff, ((size_t)P + 1) * sizeof(int));
    p->recvn = gr_realloc(g, p->recvn, (size_t)P * sizeof(int));
    double (*blo)[3] = gr_malloc(g, (size_t)P * sizeof *blo);
    double (*bhi)[3] = gr_malloc(g, (size_t)P * sizeof *bhi);
    /* per dimension: the coordinate tested, its period and the cut-off in it
     * (an orthogonal box: x, L and cut; a triclinic one: lamda, 1 and cut
     * over the width across the faces) */
    double per[3], cuts[3], W[3];
    double *lam = NULL;
    box_widths(g, W);
    for (int q = 0; q < 3; q++) {
        per[q] = dm->triclinic ? 1.0 : dm->hi[q] - dm->lo[q];
        cuts[q] = dm->triclinic ? cut / W[q] : cut;
    }
    for (int r = 0; r < P; r++) { /* a brick of the grid or an rcb tile */
        if (!dm->triclinic)
            decomp_brick(g, &p->dc, r, blo[r], bhi[r]);
        else
            decomp_box(&p->dc, r, blo[r], bhi[r]);
    }
    if (dm->triclinic) {
        lam = gr_malloc(g, (3 * (size_t)nlocal + 1) * sizeof *lam);
        for (int i = 0; i < nlocal; i++)
            for (int q = 0; q < 3; q++)
                lam[3 * (size_t)i + q] = decomp_fraction_raw(g, q, a->x + 3 * (size_t)i);
    }
    /* (atom, rank) pairs, atoms ascending; then rank by rank (a stable
     * counting sort), each rank's atoms ascending, as they are packed */
    int npair = 0, cap = nlocal + 16;
    int *pi = gr_malloc(g, (size_t)cap * sizeof(int)), *pr = gr_malloc(g, (size_t)cap * sizeof(int));
    const int grid = !decomp_tiled(&p->dc), *pg = p->dc.p;
    int *ranks[3], nr[3];
    for (int q = 0; q < 3; q++)
        ranks[q] = gr_malloc(g, (size_t)pg[q] * sizeof(int));
    for (int i = 0; i < nlocal; i++) {
        const double *x = lam ? lam + 3 * (size_t)i : a->x + 3 * (size_t)i;
        int cand = P;
        if (grid) { /* per dimension the slabs within the cut-off: the grid's near bricks */
            for (int q = 0; q < 3; q++) {
                nr[q] = 0;
                for (int k = 0; k < pg[q]; k++) {
                    int r0 = q == 0 ? k : q == 1 ? k * pg[0] : k * pg[0] * pg[1];
                    if (gap(x[q], blo[r0][q], bhi[r0][q], per[q], dm->periodic[q]) <= cuts[q])
                        ranks[q][nr[q]++] = k;
                }
            }
            cand = nr[0] * nr[1] * nr[2];
        }
        for (int c = 0; c < cand; c++) {
            int r = c;
            if (grid)
                r = ranks[0][c % nr[0]] +
                    pg[0] * (ranks[1][c / nr[0] % nr[1]] + pg[1] * ranks[2][c / (nr[0] * nr[1])]);
            if (r == me)
                continue;
            if (!grid) { /* rcb tiles: every other rank's box */
                int near = 1;
                for (int q = 0; q < 3 && near; q++)
                    near = gap(x[q], blo[r][q], bhi[r][q], per[q], dm->periodic[q]) <= cuts[q];
                if (!near)
                    continue;
            }
            if (npair == cap) {
                cap *= 2;
                pi = gr_realloc(g, pi, (size_t)cap * sizeof(int));
                pr = gr_realloc(g, pr, (size_t)cap * sizeof(int));
            }
            pi[npair] = i;
            pr[npair++] = r;
        }
    }
    for (int q = 0; q < 3; q++)
        free(ranks[q]);
    for (int r = 0; r < P; r++)
        p->sendn[r] = 0;
    for (int k = 0; k < npair; k++)
        p->sendn[pr[k]]++;
    p->soff[0] = 0;
    for (int r = 0; r < P; r++)
        p->soff[r + 1] = p->soff[r] + p->sendn[r];
    int *idx = gr_malloc(g, ((size_t)npair + 1) * sizeof(int));
    int *fill = gr_calloc(g, (size_t)P, sizeof(int));
    outbox_init(g, &ob, P);
    for (int k = 0; k < npair; k++) {
        int r = pr[k], i = pi[k];
        idx[p->soff[r] + fill[r]++] = i;
        pack_atom(a, i, raw ? raw + (size_t)i * rawb : NULL, rawb, outbox_room(g, &ob, r, rb));
    }
    free(fill);
    free(pi);
    free(pr);
    free(lam);
    p->sendidx = idx; /* rank by rank, as packed */
    free(blo);
    free(bhi);
    in = outbox_send(g, &ob, P, &inb, from);
    int nghost = (int)(inb / rb);
    for (int r = 0; r < P; r++)
        p->recvn[r] = (int)(from[r] / rb);
    atoms_reserve(g, nlocal + nghost);
    if (rawb)
        raw = gr_realloc(g, raw, (size_t)(nlocal + nghost + 1) * rawb);
    for (int j = 0; j < nghost; j++)
        unpack_atom(a, nlocal + j, in + (size_t)j * rb,
                    raw ? raw + (size_t)(nlocal + j) * rawb : NULL, rawb);
    free(in);
    /* 5. the device: owned, then ghosts */
    p->nghost = nghost;
    eng_reload(g, nlocal, nghost);
    extra_move(g, nlocal + nghost, raw, 1);
    free(raw);
    p->tags_built = gr_realloc(g, p->tags_built, ((size_t)nlocal + nghost + 1) * sizeof(int64_t));
    memcpy(p->tags_built, a->tag, ((size_t)nlocal + nghost) * sizeof(int64_t));
    p->nlocal_built = nlocal;
    p->list_current = 0;
}

void par_history_restore(struct gravel *g)
{
    struct par *p = g->par;
    struct engine *e = g->eng;
    const struct nbr_list *l = nbr_list(g);
    p->list_current = 1;
    int nc = l->ncontact;
    if (!e->history || !p->hist || nc <= 0)
        return;
    size_t vb = p->hist->vb;
    int *ci = gr_malloc(g, 2 * (size_t)nc * sizeof(int));
    unsigned char *sh = gr_calloc(g, (size_t)nc, vb);
    eng_read(g, l->ci, 0, (size_t)nc * sizeof(cl_int), ci);
    eng_read(g, l->cj, 0, (size_t)nc * sizeof(cl_int), ci + nc);
    const int64_t *tag = g->atoms.tag;
    for (int c = 0; c < nc; c++) {
        int64_t a = tag[ci[c]], b = tag[ci[nc + c]];
        const void *v = par_hist_get(p->hist, a < b ? a : b, a < b ? b : a);
        if (v)
            memcpy(sh + (size_t)c * vb, v, vb);
    }
    nbr_history_install(g, sh);
    free(ci);
    free(sh);
    par_hist_free(p->hist);
    p->hist = NULL;
}

/* ---- every other step ----------------------------------------------------------- */

/* The owned atoms' values of the nf device fields use[k] (uw[k] bytes per
 * atom) to their ghosts on the other ranks, one message per rank pair. */
static void forward(struct gravel *g, const cl_mem *use, const size_t *uw, int nf)
{
    struct par *p = g->par;
    int P = comm_size(), n = g->eng->a.n;
    size_t uo[8], ab = 0, w = 0; /* offsets in a ghost's bytes; bytes per ghost; widest */
    for (int k = 0; k < nf; k++) {
        uo[k] = ab;
        ab += uw[k];
        w = uw[k] > w ? uw[k] : w;
    }
    int nsend = p->soff[P];
    unsigned char *own = gr_malloc(g, (size_t)n * w + 1), *out = gr_malloc(g, (size_t)nsend * ab + 1);
    for (int k = 0; k < nf; k++) {
        eng_read(g, use[k], 0, (size_t)n * uw[k], own);
        for (int s = 0; s < nsend; s++)
            memcpy(out + (size_t)s * ab + uo[k], own + (size_t)p->sendidx[s] * uw[k], uw[k]);
    }
    free(own);
    void *sendp[P];
    size_t sendb[P], recvb[P];
    for (int r = 0; r < P; r++) {
        sendp[r] = out + (size_t)p->soff[r] * ab;
        sendb[r] = (size_t)p->sendn[r] * ab;
    }
    void *in = NULL;
    size_t inb = comm_alltoallv(sendp, sendb, &in, recvb);
    free(out);
    if (inb == (size_t)-1)
        gr_error(g, "out of memory exchanging ghost atoms");
    int ng = (int)(inb / (ab ? ab : 1));
    if (ng != p->nghost)
        gr_error(g, "internal error: %d ghost atoms arrived for %d slots", ng, p->nghost);
    unsigned char *col = gr_malloc(g, (size_t)ng * w + 1);
    for (int k = 0; k < nf && ng > 0; k++) {
        for (int s = 0; s < ng; s++)
            memcpy(col + (size_t)s * uw[k], (unsigned char *)in + (size_t)s * ab + uo[k], uw[k]);
        eng_write(g, use[k], (size_t)n * uw[k], (size_t)ng * uw[k], col);
    }
    free(col);
    free(in);
}

void par_forward(struct gravel *g)
{
    struct engine *e = g->eng;
    /* the fields a step changes that the ghosts' contacts read: x (and its
     * low part), v, omega, and the temperature of a heat-conducting scene */
    cl_mem f[5] = {e->a.x, e->a.xlo, e->a.v, e->rotation ? e->a.omega : NULL,
                   e->heat ? e->a.temperature : NULL};
    size_t fw[5] = {3 * e->rsz, 3 * e->rsz, 3 * e->rsz, 3 * e->rsz, e->rsz};
    cl_mem use[5];
    size_t uw[5];
    int nf = 0;
    for (int k = 0; k < 5; k++)
        if (f[k]) {
            use[nf] = f[k];
            uw[nf++] = fw[k];
        }
    forward(g, use, uw, nf);
}

void par_forward_radii(struct gravel *g)
{
    struct engine *e = g->eng;
    const cl_mem use[2] = {e->a.radius, e->a.rmass};
    const size_t uw[2] = {e->rsz, e->rsz};
    forward(g, use, uw, 2);
}

/* ---- every atom on every rank for an output step ------------------------------- */

/* The whole set on the host, this rank's own kept in p->local (state: with
 * what a restart file needs, par_snapshot_begin). */
static void gather_begin(struct gravel *g, int state)
{
    struct par *p = g->par;
    struct engine *e = g->eng;
    run_sync_host(g);
    struct atoms *a = &g->atoms;
    if (state && p->list_current)
        hist_gather(g);
    int ago = state ? build_age(g) : 0, total;
    size_t rb;
    unsigned char *all = atoms_gather(g, state, &total, &rb);
    p->local = *a;
    struct atoms full = {0};
    full.ntypes = a->ntypes;
    full.molecule_flag = a->molecule_flag;
    full.style_molecular = a->style_molecular;
    full.heat_flag = a->heat_flag;
    full.type_mass = a->type_mass;
    full.maxtag = a->maxtag;
    full.cus = a->cus; /* the custom properties' layout; their storage is the new set's */
    *a = full;
    atoms_unpack(g, all, total, rb, state, ago);
    free(all);
    p->gathered = 1;
    p->on = 0;      /* host sums over the whole set, as one process */
    e->active = 0;  /* the device holds this rank's atoms: no sync into the whole set */
}

void par_gather_begin(struct gravel *g)
{
    struct par *p = g->par;
    if (p && p->on && !p->gathered)
        gather_begin(g, 0);
}

void par_snapshot_begin(struct gravel *g)
{
    struct par *p = g->par;
    if (p && p->on && !p->gathered)
        gather_begin(g, 1);
}

void par_snapshot_end(struct gravel *g)
{
    struct par *p = g->par;
    if (!p || !p->gathered)
        return;
    par_hist_free(p->hist); /* the run's own carry is taken at its end */
    p->hist = NULL;
    for (int k = 0; k < p->nsaved; k++)
        free(p->saved[k].state);
    p->nsaved = 0;
    p->ended = 0;
    par_gather_end(g);
}

/* ---- rerun: a snapshot read into every rank's whole set ----------------------- */

void par_rerun_gather(struct gravel *g)
{
    par_snapshot_begin(g); /* the history and the fixes' state by tag, as at a run's end */
}

void par_rerun_keep(struct gravel *g)
{
    par_snapshot_end(g);
}

void par_rerun_scatter(struct gravel *g)
{
    struct par *p = g->par;
    if (!p || !p->gathered)
        return;
    atoms_free_fields(&p->local); /* the last snapshot's own: the new one replaces them */
    memset(&p->local, 0, sizeof p->local);
    p->gathered = 0;
    p->on = 1;
    p->ended = 0;
    p->nghost = 0;
    g->eng->nghost = 0;
    p->list_current = 0; /* the next build takes the history from p->hist by tag pair */
    keep_brick(g, p);
}

void par_gather_end(struct gravel *g)
{
    struct par *p = g->par;
    if (!p || !p->gathered)
        return;
    atoms_free_fields(&g->atoms);
    g->atoms = p->local;
    memset(&p->local, 0, sizeof p->local);
    p->gathered = 0;
    p->on = 1;
    g->eng->active = 1;
}
