/* engine.c - what a run does with the device engine (device.c holds the
 * helpers): precision choice, the per-atom buffers (structure of arrays,
 * device order), program assembly for the active styles, upload at run
 * start, appended atoms, run_sync_host() and the teardown.
 *
 * One set of buffers: the neighbor re-sort gathers array by array through
 * the force buffer (src/engine/neighbor.c); omega and torque exist only when some
 * active style needs rotation. */
#include "engine.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"
#include "atoms.h"
#include "diagnose.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fused.h"
#include "kernel_sources.h"
#include "log.h"
#include "neighbor.h"
#include "pair.h"

extern const struct kernel_source gr_kernel_sources[];

/* The device origin for single precision: per dimension 0 while the box is
 * within its own size of 0 (most decks: no shift, lab coordinates), else
 * the box centre, so positions far from 0 keep the bits that resolve
 * contacts. A change moves every device position: the list is invalid. */
static void choose_origin(struct gravel *g)
{
    struct engine *e = g->eng;
    double o[3] = {0, 0, 0};
    for (int q = 0; q < 3 && e->single; q++) {
        double c = 0.5 * (g->dom.lo[q] + g->dom.hi[q]), L = g->dom.hi[q] - g->dom.lo[q];
        if (isfinite(c) && fabs(c) > L)
            o[q] = c;
    }
    if (o[0] != e->origin[0] || o[1] != e->origin[1] || o[2] != e->origin[2]) {
        memcpy(e->origin, o, sizeof o);
        e->tag_sum = 0;
    }
}

/* ---- the per-atom set, driven by the field table (atom_fields.h) ---------------- */

/* 1 when the current run holds fields of this `when` on the device. */
static int field_on(const struct gravel *g, enum atom_field_when when)
{
    switch (when) {
    case FW_ROTATION: return g->eng->rotation;
    case FW_MOLECULE: return g->atoms.molecule_flag;
    case FW_HEAT: return g->atoms.heat_flag != 0;
    case FW_ELLIPSOID: return g->atoms.ellipsoid_flag;
    default: return 1;
    }
}

/* Device bytes per atom of a field of host element size hsz. */
static size_t field_bytes(const struct engine *e, enum atom_field_dev dev, size_t hsz, int width)
{
    return (size_t)width * (dev == FD_RAW ? hsz : e->rsz);
}

/* Host atoms first .. first + n - 1 of one field (host array src) to the device. */
static void field_put(struct gravel *g, struct dev_atoms *s, cl_mem m, enum atom_field_dev dev,
                      size_t hsz, int width, int first, int n, const void *src)
{
    size_t o = (size_t)first * width, c = (size_t)n * width;
    switch (dev) {
    case FD_POS: eng_write_positions(g, s, first, n, (const double *)src + o); break;
    case FD_REAL: eng_write_reals_at(g, m, o, c, (const double *)src + o); break;
    case FD_RAW: eng_write(g, m, o * hsz, c * hsz, (const char *)src + o * hsz); break;
    }
}

/* The first n atoms of one field from the device into host array dst. */
static void field_get(struct gravel *g, struct dev_atoms *s, cl_mem m, enum atom_field_dev dev,
                      size_t hsz, int width, int n, void *dst)
{
    size_t c = (size_t)n * width;
    switch (dev) {
    case FD_POS: eng_read_positions(g, s, n, dst); break;
    case FD_REAL: eng_read_reals(g, m, c, dst); break;
    case FD_RAW: eng_read(g, m, 0, c * hsz, dst); break;
    }
}

static void release_mem(cl_mem *m)
{
    if (*m) {
        clReleaseMemObject(*m);
        *m = NULL;
    }
}

static void release_set(struct dev_atoms *s)
{
#define RELEASE(name, ctype, dev, width, when, life, sect, what) release_mem(&s->name);
    ATOM_FIELDS(RELEASE)
#undef RELEASE
    release_mem(&s->xlo);
    release_mem(&s->custom);
    release_mem(&s->custom_tmp);
    s->custom_slots = 0;
}

/* In double precision on a CPU device on host memory the per-atom set is
 * the host arrays themselves (the same bytes: origin 0, REAL = double, raw
 * fields as they are): one copy of the atoms instead of two. */
static int share_host(const struct engine *e) { return e->ocl.host_unified && !e->single; }

int eng_shares_host(struct gravel *g) { return share_host(g->eng); }

static uint64_t host_key(const struct atoms *at)
{
    uint64_t h = 1469598103934665603ull ^ (uint64_t)at->cap;
#define KEY(name, ctype, dev, width, when, life, sect, what)                                   \
    h = (h ^ (uint64_t)(uintptr_t)at->name) * 1099511628211ull;
    ATOM_FIELDS(KEY)
#undef KEY
    h = (h ^ (uint64_t)(uintptr_t)at->custom) * 1099511628211ull;
    return h;
}

/* A shared set's host arrays hold the capacity first, so that nothing
 * moves them while it exists (fix pour's atoms_add stays within it). */
static void alloc_set(struct gravel *g, struct dev_atoms *s, int cap)
{
    struct engine *e = g->eng;
    struct atoms *at = &g->atoms;
    size_t n = (size_t)cap;
    s->shared = share_host(e);
    if (s->shared)
        atoms_reserve(g, cap);
#define ALLOC(name, ctype, dev, width, when, life, sect, what)                                 \
    if (field_on(g, when))                                                                    \
        s->name = s->shared ? ocl_wrap(g, &e->ocl, at->name, n * sizeof(ctype) * (width), what) \
                            : eng_alloc(g, n * field_bytes(e, dev, sizeof(ctype), width), what);
    ATOM_FIELDS(ALLOC)
#undef ALLOC
    s->custom_slots = at->cus.slots;
    if (s->custom_slots) {
        size_t cb = n * (size_t)s->custom_slots * sizeof(double);
        s->custom = s->shared ? ocl_wrap(g, &e->ocl, at->custom, cb, "custom properties")
                              : eng_alloc(g, cb, "custom properties");
        s->custom_tmp = eng_alloc(g, cb, "custom properties (re-sort scratch)");
    }
    if (e->single)
        s->xlo = eng_alloc(g, 3 * n * e->rsz, "positions (low parts)");
    s->shared_key = s->shared ? host_key(at) : 0;
}

/* 1 when the set is still what share_host() asks for, over the current
 * host arrays. */
static int sharing_current(struct gravel *g, const struct dev_atoms *s)
{
    return s->shared == share_host(g->eng) && (!s->shared || s->shared_key == host_key(&g->atoms));
}

/* 1 when the set holds exactly the fields the current run needs. */
static int set_matches_run(struct gravel *g, const struct dev_atoms *s)
{
    int ok = 1;
#define MATCH(name, ctype, dev, width, when, life, sect, what)                                 \
    ok = ok && (s->name != NULL) == (field_on(g, when) != 0);
    ATOM_FIELDS(MATCH)
#undef MATCH
    return ok && s->custom_slots == g->atoms.cus.slots;
}

size_t eng_atom_bytes(struct gravel *g)
{
    struct engine *e = g->eng;
    size_t cb = (size_t)g->atoms.cus.slots * sizeof(double); /* custom properties */
    if (share_host(e))
        return cb; /* the host arrays, and the custom properties' re-sort scratch */
    size_t b = e->single ? 3 * e->rsz : 0; /* xlo */
#define BYTES(name, ctype, dev, width, when, life, sect, what)                                 \
    if (field_on(g, when))                                                                    \
        b += field_bytes(e, dev, sizeof(ctype), width);
    ATOM_FIELDS(BYTES)
#undef BYTES
    return b + 2 * cb; /* the custom properties and their re-sort scratch */
}

/* (Re)allocate the per-atom set for at least n atoms. Contents are not kept: call
 * before upload only. */
void eng_reserve(struct gravel *g, int n)
{
    struct engine *e = g->eng;
    if (n <= e->cap && e->a.x && set_matches_run(g, &e->a) && sharing_current(g, &e->a))
        return;
    int cap = n > 16 ? n : 16; /* exactly: insertions are reserved (fix reserve) */
    release_set(&e->a);
    alloc_set(g, &e->a, cap);
    e->cap = cap;
    e->ocl.atoms_hint = cap;
    nbr_invalidate(g); /* the neighbor list indexes the old buffers; the fixes' per-atom
                          state (its own buffers) stays with the atoms */
}

/* Host atoms first .. first + n - 1, every field the device holds. */
static void put_atoms(struct gravel *g, int first, int n)
{
    struct dev_atoms *s = &g->eng->a;
    const struct atoms *at = &g->atoms;
    if (s->shared)
        return; /* the device reads the host arrays */
#define PUT(name, ctype, dev, width, when, life, sect, what)                                   \
    if (s->name)                                                                              \
        field_put(g, s, s->name, dev, sizeof(ctype), width, first, n, at->name);
    ATOM_FIELDS(PUT)
#undef PUT
    if (s->custom)
        field_put(g, s, s->custom, FD_RAW, sizeof(double), s->custom_slots, first, n,
                  at->custom);
}

/* Per-atom state of fixes (fix.h): the one allocation path. A fix that
 * declares peratom_bytes gets zero-filled buffers of e->cap atoms when it
 * has none, when they are too small, or when !keep (the atoms changed since
 * the state was written); otherwise its state is kept, also when the
 * buffers grow (the state of the run's atoms moves into the new ones). */
void eng_fix_state(struct gravel *g, int keep)
{
    struct engine *e = g->eng;
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (!f->peratom_bytes)
            continue;
        if (f->peratom_bytes % 4)
            gr_error(g, "fix %s: per-atom state size %zu is not a multiple of 4 bytes", f->id,
                     f->peratom_bytes);
        if (keep && f->peratom && f->peratom_cap >= (size_t)e->cap)
            continue;
        cl_mem old = f->peratom;
        f->peratom = eng_alloc(g, (size_t)e->cap * f->peratom_bytes, "fix per-atom state");
        eng_fill_zero(g, f->peratom, (size_t)e->cap * f->peratom_bytes);
        /* a run that needs room for more atoms keeps the state of those it has */
        size_t nkeep = (size_t)e->a.n < f->peratom_cap ? (size_t)e->a.n : f->peratom_cap;
        if (keep && old && nkeep)
            OCL_CHECK(g, clEnqueueCopyBuffer(e->ocl.queue, old, f->peratom, 0, 0,
                                             nkeep * f->peratom_bytes, 0, NULL, NULL));
        release_mem(&old);
        release_mem(&f->peratom_tmp);
        f->peratom_tmp = eng_alloc(g, (size_t)e->cap * f->peratom_bytes, "fix per-atom state");
        f->peratom_cap = (size_t)e->cap;
    }
}

static uint64_t tag_checksum(const struct atoms *a)
{
    uint64_t h = 1469598103934665603ull ^ (uint64_t)a->n;
    for (int i = 0; i < a->n; i++) {
        h ^= (uint64_t)a->tag[i];
        h *= 1099511628211ull;
    }
    return h ? h : 1;
}

void eng_upload(struct gravel *g)
{
    struct engine *e = g->eng;
    struct atoms *at = &g->atoms;
    int n = at->n;
    choose_origin(g);
    int keep = e->tag_sum && e->n_at_sync == n && tag_checksum(at) == e->tag_sum;
    eng_reserve(g, n);
    if (!keep || !e->tag_sum)
        nbr_invalidate(g);
    e->a.n = n;
    put_atoms(g, 0, n);
    diag_keep_start(g);
    /* per-atom state of fixes: keep while the atoms are the same, else zero */
    eng_fix_state(g, keep);
    e->active = 1;
}

void eng_append(struct gravel *g, int nold)
{
    struct engine *e = g->eng;
    struct atoms *at = &g->atoms;
    struct dev_atoms *s = &e->a;
    int n = at->n, k = n - nold;
    if (!e->active || nold != s->n || k < 0)
        gr_error(g, "internal error: eng_append needs the host atoms of run_sync_host");
    if (k == 0)
        return;
    if (n > e->cap)
        gr_error(g, "internal error: %d atoms inserted beyond the run's capacity %d", n, e->cap);
    size_t o = (size_t)nold, c = (size_t)k;
    put_atoms(g, nold, k);
    cl_uint zero = 0;
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (f->peratom)
            OCL_CHECK(g, clEnqueueFillBuffer(e->ocl.queue, f->peratom, &zero, sizeof zero,
                                             o * f->peratom_bytes, c * f->peratom_bytes, 0,
                                             NULL, NULL));
    }
    nbr_atoms_appended(g, nold, n);
    s->n = n;
    e->tag_sum = tag_checksum(at);
    e->n_at_sync = n;
}

void eng_put_custom(struct gravel *g)
{
    struct engine *e = g->eng;
    struct dev_atoms *s = &e->a;
    if (!e->active || !s->custom || s->shared || s->custom_slots != g->atoms.cus.slots)
        return;
    field_put(g, s, s->custom, FD_RAW, sizeof(double), s->custom_slots, 0, s->n,
              g->atoms.custom);
}

void eng_reload(struct gravel *g, int nlocal, int nghost)
{
    struct engine *e = g->eng;
    struct atoms *at = &g->atoms;
    int nall = nlocal + nghost;
    if (nall > e->cap || !sharing_current(g, &e->a)) {
        at->n = nall; /* the host slots to keep while the shared arrays move */
        eng_reserve(g, nall > e->cap ? nall + nall / 4 + 64 : e->cap);
        eng_fix_state(g, 1);
    }
    put_atoms(g, 0, nall);
    at->n = nlocal;
    e->a.n = nlocal;
    e->nghost = nghost;
    e->tag_sum = tag_checksum(at);
    e->n_at_sync = nlocal;
}

void run_sync_host(struct gravel *g)
{
    struct engine *e = g->eng;
    if (!e || !e->active)
        return;
    struct atoms *at = &g->atoms;
    struct dev_atoms *s = &e->a;
    int n = s->n;
    if (n > at->cap)
        atoms_reserve(g, n);
    at->n = n;
    if (s->shared)
        eng_finish(g); /* the host arrays are the device's: only wait for its work */
    else {
#define GET(name, ctype, dev, width, when, life, sect, what)                                   \
    if (s->name)                                                                              \
        field_get(g, s, s->name, dev, sizeof(ctype), width, n, at->name);
        ATOM_FIELDS(GET)
#undef GET
        if (s->custom)
            field_get(g, s, s->custom, FD_RAW, sizeof(double), s->custom_slots, n, at->custom);
    }
    e->tag_sum = tag_checksum(at);
    e->n_at_sync = n;
}

/* The source text of kernels/<name>, or an error naming the style. */
static const char *kernel_text(struct gravel *g, const char *name, const char *who)
{
    for (const struct kernel_source *k = gr_kernel_sources; k->name; k++)
        if (!strcmp(k->name, name))
            return k->text;
    gr_error(g, "%s: kernel source kernels/%s is not in this build", who, name);
}

#define MAX_SOURCES 48

/* Adds text under name, once. */
static void add_text(struct gravel *g, const char **names, const char **texts, int *n,
                     const char *name, const char *text)
{
    for (int i = 0; i < *n; i++)
        if (!strcmp(names[i], name))
            return;
    if (*n >= MAX_SOURCES)
        gr_error(g, "too many kernel sources");
    names[*n] = name;
    texts[*n] = text;
    (*n)++;
}

static void add_source(struct gravel *g, const char **names, const char **texts, int *n,
                       const char *name, const char *who)
{
    add_text(g, names, texts, n, name, kernel_text(g, name, who));
}

/* whether a fix of the scene builds the program with option `def` */
static int fix_defines(const struct gravel *g, const char *def)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (strstr(g->styles.fix[i]->defines, def))
            return 1;
    return 0;
}

/* The pair kernel's width: the device's lanes for a law written in lanes
 * (kernels/gran_law.cl) in a scene kernels/pair_gran_lanes.cl covers (no
 * cohesion, approach, velocity remap, triclinic box, split positions or
 * history row beyond 3 REAL); one contact per work-item otherwise. */
static int pair_lanes(struct gravel *g, const struct pair_caps *pc, int single, int lmp2021)
{
    if (!pc || !pc->eval_lanes || pc->beyond || pc->approach || (single && !g->eng->ocl.fp64) ||
        lmp2021 || g->dom.triclinic || fix_defines(g, "VREMAP"))
        return 1;
    return single ? g->eng->ocl.lanes_float : g->eng->ocl.lanes_double;
}

/* The gather's width: the device's lanes in a scene kernels/atom_lanes.cl
 * covers (no velocity remap or triclinic box); one particle per work-item
 * otherwise. */
static int atom_lanes(struct gravel *g, int single)
{
    if (g->dom.triclinic || fix_defines(g, "VREMAP"))
        return 1;
    return single ? g->eng->ocl.lanes_float : g->eng->ocl.lanes_double;
}

/* The lane templates (kernels/lanes.cl, then the lane-generic laws:
 * kernels/gran_law.cl) at width 1 (names x_1) and, with pair_lw > 1, at the
 * pair kernel's width (x_w), each between its prologue and the epilogue. */
static void add_lanes(struct gravel *g, const char **names, const char **texts, int *n)
{
    struct engine *e = g->eng;
    static const char epilogue[] = "#undef LW\n#undef LR\n#undef LRI\n#undef LN\n#undef LSEL\n";
    static const char one[] = "#define LW 1\n#define LR REAL\n#define LRI int\n"
                              "#define LN(x) x##_1\n#define LSEL(a, b, m) ((m) ? (b) : (a))\n";
    add_text(g, names, texts, n, "lanes@1", one);
    add_text(g, names, texts, n, "lanes.cl@1", kernel_text(g, "lanes.cl", "engine"));
    add_text(g, names, texts, n, "gran_law.cl@1", kernel_text(g, "gran_law.cl", "engine"));
    add_text(g, names, texts, n, "lanes@1/", epilogue);
    if (e->pair_lw <= 1)
        return;
    snprintf(e->lanes_prologue, sizeof e->lanes_prologue,
             "#define LW %d\n#define LR %s%d\n#define LRI %s%d\n#define LN(x) x##_w\n"
             "#define LSEL(a, b, m) select((a), (b), (m))\n",
             e->pair_lw, e->single ? "float" : "double", e->pair_lw, e->single ? "int" : "long",
             e->pair_lw);
    add_text(g, names, texts, n, "lanes@w", e->lanes_prologue);
    add_text(g, names, texts, n, "lanes.cl@w", kernel_text(g, "lanes.cl", "engine"));
    add_text(g, names, texts, n, "gran_law.cl@w", kernel_text(g, "gran_law.cl", "engine"));
    add_text(g, names, texts, n, "lanes@w/", epilogue);
}

/* The run program's build options, assembled here and nowhere else:
 * precision, the state the run keeps, the box, the pair style's record
 * (src/style/pair.h: evaluator, approach, energy, its own options, reach) and
 * the fixes' options (f->defines). Returns the length (>= len: too long). */
static int build_options(struct gravel *g, const struct pair_caps *pc, int lmp2021,
                         int flip_lo, int flip_n, char *opts, size_t size)
{
    struct engine *e = g->eng;
    int single = e->single;
    size_t len = 0;
#define OPT(...)                                                                               \
    do {                                                                                       \
        if (len < size)                                                                        \
            len += (size_t)snprintf(opts + len, size - len, __VA_ARGS__);                      \
    } while (0)
    OPT("-D REAL=%s%s%s%s", single ? "float" : "double",
        !single ? " -D USE_DOUBLE"
        : e->ocl.fp64 ? " -D SPLIT_POS -D HAS_FP64" /* contact_refine in double */
                      : " -D SPLIT_POS", e->rotation ? " -D HAS_ROTATION" : "",
        e->history ? " -D HAS_HISTORY" : "");
    if (e->heat)
        OPT(" -D HAS_HEAT");
    if (e->hist_n != 3)
        OPT(" -D HIST_N=%d", e->hist_n);
    if (lmp2021)
        OPT(" -D LMP2021");
    if (flip_n > 0)
        OPT(" -D HIST_OWNER=%d -D HIST_ZERO_N=%d -D HIST_FLIP_LO=%d -D HIST_FLIP_N=%d",
            e->hist_n - 1, e->hist_n - 1, flip_lo, flip_n);
    for (int q = 0; q < 3; q++)
        if (domain_contact_periodic(g, q))
            OPT(" -D PERIODIC_%c", "XYZ"[q]);
    if (g->dom.triclinic)
        OPT(" -D TRICLINIC");
    if (pc) {
        if (pc->eval_row)
            OPT(" -D PAIR_EVAL_ROW=%s", pc->eval_row);
        else
            OPT(" -D PAIR_EVAL=%s", pc->eval);
        if (e->pair_lw > 1)
            OPT(" -D PAIR_LW=%d -D PAIR_EVAL_LANES=%s", e->pair_lw, pc->eval_lanes);
        if (e->atom_lw > 1)
            OPT(" -D ATOM_LW=%d", e->atom_lw);
        if (e->pair_tc)
            OPT(" -D PAIR_TC");
        if (pc->approach)
            OPT(" -D PAIR_APPROACH");
        if (pc->energy)
            OPT(" -D PAIR_ENERGY=%s", pc->energy);
        for (int k = 0; k < pc->ndef; k++)
            OPT(" -D %s%s%s", pc->def[k].name, pc->def[k].value[0] ? "=" : "",
                pc->def[k].value);
        if (pc->beyond) { /* cohesion: the loop's reach bound over the terms */
            double a = 0, b = 0;
            for (int k = 0; k < pc->nreach; k++) {
                double a0 = pc->reach_a[k] + pc->reach_b[k] * 0.0;
                double b0 = (pc->reach_a[k] + pc->reach_b[k] * 1.0) - a0;
                a = a0 > a ? a0 : a;
                b = b0 > b ? b0 : b;
            }
            OPT(" -D HAS_COHESION -D COH_REACH_A=%.17g -D COH_REACH_B=%.17g%s", a, b,
                pc->type_cut ? " -D PAIR_TYPECUT" : "");
        }
    }
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->defines[0])
            OPT(" -D %s", g->styles.fix[i]->defines);
#undef OPT
    return len < size ? (int)len : (int)size;
}

void eng_prepare(struct gravel *g)
{
    struct engine *e = eng_get(g);
    const struct pair *p = g->styles.pair;
    unsigned needs = fix_needs_all(g);
    int single = g->opt.single;
    if (!single && !e->ocl.fp64) {
        gr_warn(g, "device %s has no double precision: running in single precision",
                e->ocl.name);
        single = 1;
    }
    if (e->single != single) {
        /* precision change: every buffer is reallocated */
        e->single = single;
        e->cap = 0;
        e->tag_sum = 0;
    }
    e->rsz = single ? sizeof(float) : sizeof(double);
    /* the pair style answers every question of the run once: its record */
    pair_setup(g);
    /* a host-evaluated law puts no terms in the device program */
    const struct pair_caps *pc = p && !p->caps.host_forces ? &p->caps : NULL;
    e->rotation = (p && p->caps.rotation) || (needs & NEED_ROTATION);
    e->history = pc && pc->history;
    e->hist_n = e->history ? pc->hist_n : 3;
    /* -compat lammps2021: a trailing slot records LAMMPS's owner of each
     * listed pair (kernels/neighbor.cl, hist_transfer) */
    int lmp2021 = e->history && g->opt.lammps2021 && g->neigh.style == NEIGH_BIN;
    int flip_lo = lmp2021 ? pc->flip_lo : 0, flip_n = lmp2021 ? pc->flip_n : 0;
    e->hist_owner = flip_n > 0;
    if (flip_n > 0)
        e->hist_n++;

    /* heat conduction: temperature and heatflow on the device; the heat
     * records are written by kernels/pair_loop.cl's one-contact kernel */
    e->heat = g->atoms.heat_flag == ATOM_HEAT_BOTH;
    e->pair_lw = e->heat ? 1 : pair_lanes(g, pc, single, lmp2021);
    e->atom_lw = pc ? atom_lanes(g, single) : 1;
    /* a law without rolling torque: the torque record is the contact's tc */
    e->pair_tc = pc && pc->sym_torque && e->rotation;

    const char *names[MAX_SOURCES], *texts[MAX_SOURCES];
    int n = 0;
    add_source(g, names, texts, &n, "param_layout.h", "engine");
    add_source(g, names, texts, &n, "wall_layout.h", "engine");
    add_source(g, names, texts, &n, "fused_layout.h", "engine");
    /* the pipeline kernels' argument lists (src/engine/kargs.h binds them) */
    add_source(g, names, texts, &n, "kernel_args.h", "engine");
    add_source(g, names, texts, &n, "common.cl", "engine");
    /* each contact law's collision time, shared with the host (after
     * common.cl: REAL and fp64 are set up) */
    add_source(g, names, texts, &n, "collision_time.h", "engine");
    /* the contact record and the one contact body of every source */
    add_source(g, names, texts, &n, "contact.cl", "engine");
    /* the lane-generic laws: the LAMMPS gran laws at width 1 for every
     * source and at the pair width; then their contact evaluators (static
     * inline, free in scenes that do not call them) */
    add_lanes(g, names, texts, &n);
    add_source(g, names, texts, &n, "gran_common.cl", "engine");
    /* normal impulse of the source-document contact laws (same terms) */
    add_source(g, names, texts, &n, "contact_normal.cl", "engine");
    /* per-particle fix work run inside the check and gather kernels, and
     * the laws of the fixes it fuses */
    add_source(g, names, texts, &n, "drag_law.cl", "engine");
    add_source(g, names, texts, &n, "fused.cl", "engine");
    /* a step's opening per particle: nbr_check's, or pair_gather's look-ahead */
    add_source(g, names, texts, &n, "atom_step.cl", "engine");
    /* collision-resolution and wall-overlap records (src/contact/accuracy.c) */
    add_source(g, names, texts, &n, "accuracy.cl", "engine");
    for (int k = 0; pc && k < pc->nsources; k++) /* hybrid: one source per fused term */
        add_source(g, names, texts, &n, pc->sources[k], p->style->name);
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        for (int k = 0; k < f->nsources; k++)
            add_source(g, names, texts, &n, f->sources[k], f->style->name);
    }
    add_source(g, names, texts, &n, "pair_loop.cl", "engine");
    add_source(g, names, texts, &n, "pair_gran_lanes.cl", "engine");
    add_source(g, names, texts, &n, "atom_lanes.cl", "engine");
    add_source(g, names, texts, &n, "neighbor.cl", "engine");
    add_source(g, names, texts, &n, "box_change.cl", "engine");

    char opts[1024];
    int len = build_options(g, pc, lmp2021, flip_lo, flip_n, opts, sizeof opts);
    if (len >= (int)sizeof opts)
        gr_error(g, "kernel build options too long");
    eng_release_kernels(e);
    uint64_t before = e->ocl.program_key;
    ocl_build(g, &e->ocl, n, names, texts, opts);
    if (e->ocl.program_key != before || !e->ocl.cache_hit)
        gr_print(g, "OpenCL program: %s (%s)\n",
                 e->ocl.cache_hit ? "program cache hit"
                 : e->ocl.pcache  ? "compiled"
                                  : "compiled or taken from the driver's kernel cache",
                 opts);
}

void engine_destroy(struct gravel *g)
{
    struct engine *e = g->eng;
    if (!e)
        return;
    /* an error may stop a run with kernels still queued or running on the
     * buffers freed below (the atom arrays the device shares among them):
     * let them finish first; its status is of no use now */
    if (e->ocl.queue)
        (void)clFinish(e->ocl.queue);
    if (e->nprof && g->screen) {
        fprintf(stderr, "GRAVEL_PROFILE: device time per kernel\n");
        for (int i = 0; i < e->nprof; i++)
            fprintf(stderr, "  %-24s %8ld calls %10.4f s %8.1f us/call\n", e->prof_name[i],
                    e->prof_calls[i], e->prof_sec[i], 1e6 * e->prof_sec[i] / e->prof_calls[i]);
    }
    nbr_free(g);
    acc_free(g);
    fused_free(&e->fused);
    for (int k = 0; k < NHOOK; k++)
        free(e->hooks.call[k]);
    free(e->hooks.force);
    if (e->pair_param)
        clReleaseMemObject(e->pair_param);
    if (e->virial)
        clReleaseMemObject(e->virial);
    free(e->virial_snap_atoms);
    if (e->recq)
        clReleaseMemObject(e->recq);
    free(e->tag_seen);
    free(e->tag_order);
    if (e->hrate)
        clReleaseMemObject(e->hrate);
    eng_release_kernels(e);
    free(e->kern);
    free(e->kern_wg);
    free(e->kern_memo);
    release_set(&e->a);
    diag_free_start(&e->start);
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (f->peratom)
            clReleaseMemObject(f->peratom);
        if (f->peratom_tmp)
            clReleaseMemObject(f->peratom_tmp);
        f->peratom = f->peratom_tmp = NULL;
        f->peratom_cap = 0;
    }
    ocl_release(&e->ocl);
    free(e);
    g->eng = NULL;
}
