/* engine.c - what a run does with the device engine (device.c holds the
 * helpers): precision choice, the per-atom buffers (structure of arrays,
 * device order), program assembly for the active styles, upload at run
 * start, appended atoms, run_sync_host() and the teardown.
 *
 * One set of buffers: the neighbor re-sort gathers array by array through
 * the force buffer (src/neighbor.c); omega and torque exist only when some
 * active style needs rotation. */
#include "engine.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"
#include "atoms.h"
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

static void release_set(struct dev_atoms *s)
{
    cl_mem *m[] = {&s->x, &s->xlo, &s->v, &s->f, &s->omega, &s->torque, &s->radius,
                   &s->rmass, &s->type, &s->mask, &s->tag, &s->image, &s->mol};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++)
        if (*m[i]) {
            clReleaseMemObject(*m[i]);
            *m[i] = NULL;
        }
}

static void alloc_set(struct gravel *g, struct dev_atoms *s, int cap)
{
    struct engine *e = g->eng;
    size_t r = e->rsz, n = (size_t)cap;
    s->x = eng_alloc(g, 3 * n * r, "positions");
    if (e->single)
        s->xlo = eng_alloc(g, 3 * n * r, "positions (low parts)");
    s->v = eng_alloc(g, 3 * n * r, "velocities");
    s->f = eng_alloc(g, 3 * n * r, "forces");
    if (e->rotation) {
        s->omega = eng_alloc(g, 3 * n * r, "angular velocities");
        s->torque = eng_alloc(g, 3 * n * r, "torques");
    }
    s->radius = eng_alloc(g, n * r, "radii");
    s->rmass = eng_alloc(g, n * r, "masses");
    s->type = eng_alloc(g, n * sizeof(cl_int), "types");
    s->mask = eng_alloc(g, n * sizeof(cl_uint), "group masks");
    s->tag = eng_alloc(g, n * sizeof(cl_long), "tags");
    s->image = eng_alloc(g, 3 * n * sizeof(cl_int), "image flags");
    if (g->atoms.molecule_flag)
        s->mol = eng_alloc(g, n * sizeof(cl_long), "molecule IDs");
}

/* (Re)allocate the per-atom set for at least n atoms. Contents are not kept: call
 * before upload only. */
void eng_reserve(struct gravel *g, int n)
{
    struct engine *e = g->eng;
    int rot_have = e->a.x && (e->a.omega != NULL);
    int mol_have = e->a.mol != NULL;
    if (n <= e->cap && e->a.x && rot_have == e->rotation && mol_have == g->atoms.molecule_flag)
        return;
    int cap = n > 16 ? n + n / 8 : 16;
    release_set(&e->a);
    alloc_set(g, &e->a, cap);
    e->cap = cap;
    e->ocl.atoms_hint = cap;
    e->tag_sum = 0; /* the neighbor list indexes the old buffers */
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
    struct dev_atoms *s = &e->a;
    s->n = n;
    eng_write_positions(g, s, 0, n, at->x);
    eng_write_reals(g, s->v, 3 * (size_t)n, at->v);
    eng_write_reals(g, s->f, 3 * (size_t)n, at->f);
    if (e->rotation) {
        eng_write_reals(g, s->omega, 3 * (size_t)n, at->omega);
        eng_write_reals(g, s->torque, 3 * (size_t)n, at->torque);
    }
    eng_write_reals(g, s->radius, (size_t)n, at->radius);
    eng_write_reals(g, s->rmass, (size_t)n, at->rmass);
    eng_write(g, s->type, 0, (size_t)n * sizeof(cl_int), at->type);
    eng_write(g, s->mask, 0, (size_t)n * sizeof(cl_uint), at->mask);
    eng_write(g, s->tag, 0, (size_t)n * sizeof(cl_long), at->tag);
    eng_write(g, s->image, 0, 3 * (size_t)n * sizeof(cl_int), at->image);
    if (s->mol)
        eng_write(g, s->mol, 0, (size_t)n * sizeof(cl_long), at->mol);
    /* per-atom state of fixes: keep while the atoms are the same, else zero */
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (!f->peratom_bytes)
            continue;
        if (f->peratom_bytes % 4)
            gr_error(g, "fix %s: per-atom state size %zu is not a multiple of 4 bytes", f->id,
                     f->peratom_bytes);
        if (!keep || f->peratom_cap < (size_t)e->cap || !f->peratom) {
            if (f->peratom)
                clReleaseMemObject(f->peratom);
            if (f->peratom_tmp)
                clReleaseMemObject(f->peratom_tmp);
            f->peratom = eng_alloc(g, (size_t)e->cap * f->peratom_bytes, "fix per-atom state");
            f->peratom_tmp =
                eng_alloc(g, (size_t)e->cap * f->peratom_bytes, "fix per-atom state");
            f->peratom_cap = (size_t)e->cap;
            eng_fill_zero(g, f->peratom, (size_t)e->cap * f->peratom_bytes);
        }
    }
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
    eng_write_positions(g, s, nold, k, at->x + 3 * o);
    eng_write_reals_at(g, s->v, 3 * o, 3 * c, at->v + 3 * o);
    eng_write_reals_at(g, s->f, 3 * o, 3 * c, at->f + 3 * o);
    if (e->rotation) {
        eng_write_reals_at(g, s->omega, 3 * o, 3 * c, at->omega + 3 * o);
        eng_write_reals_at(g, s->torque, 3 * o, 3 * c, at->torque + 3 * o);
    }
    eng_write_reals_at(g, s->radius, o, c, at->radius + o);
    eng_write_reals_at(g, s->rmass, o, c, at->rmass + o);
    eng_write(g, s->type, o * sizeof(cl_int), c * sizeof(cl_int), at->type + o);
    eng_write(g, s->mask, o * sizeof(cl_uint), c * sizeof(cl_uint), at->mask + o);
    eng_write(g, s->tag, o * sizeof(cl_long), c * sizeof(cl_long), at->tag + o);
    eng_write(g, s->image, 3 * o * sizeof(cl_int), 3 * c * sizeof(cl_int), at->image + 3 * o);
    if (s->mol)
        eng_write(g, s->mol, o * sizeof(cl_long), c * sizeof(cl_long), at->mol + o);
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
    eng_read_positions(g, s, n, at->x);
    eng_read_reals(g, s->v, 3 * (size_t)n, at->v);
    eng_read_reals(g, s->f, 3 * (size_t)n, at->f);
    if (e->rotation) {
        eng_read_reals(g, s->omega, 3 * (size_t)n, at->omega);
        eng_read_reals(g, s->torque, 3 * (size_t)n, at->torque);
    }
    eng_read_reals(g, s->radius, (size_t)n, at->radius);
    eng_read_reals(g, s->rmass, (size_t)n, at->rmass);
    eng_read(g, s->type, 0, (size_t)n * sizeof(cl_int), at->type);
    eng_read(g, s->mask, 0, (size_t)n * sizeof(cl_uint), at->mask);
    eng_read(g, s->tag, 0, (size_t)n * sizeof(cl_long), at->tag);
    eng_read(g, s->image, 0, 3 * (size_t)n * sizeof(cl_int), at->image);
    if (s->mol)
        eng_read(g, s->mol, 0, (size_t)n * sizeof(cl_long), at->mol);
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

static void add_source(struct gravel *g, const char **names, const char **texts, int *n,
                       const char *name, const char *who)
{
    for (int i = 0; i < *n; i++)
        if (!strcmp(names[i], name))
            return;
    if (*n >= 32)
        gr_error(g, "too many kernel sources");
    names[*n] = name;
    texts[*n] = kernel_text(g, name, who);
    (*n)++;
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
    /* cohesion: pair styles may be composed (hybrid/overlay) */
    if (p)
        pair_prepare(g);
    e->rotation = (p && pair_needs_rotation(p)) || (needs & NEED_ROTATION);
    e->history = p && pair_needs_history(p);
    e->hist_n = e->history ? pair_history_size(p) : 3;
    /* -compat lammps2021: a trailing slot records LAMMPS's owner of each
     * listed pair (kernels/neighbor.cl, hist_transfer) */
    int flip_lo = 0, flip_n = 0, lmp2021 = e->history && g->opt.lammps2021 &&
                                            g->neigh.style == NEIGH_BIN;
    if (lmp2021 && p->style->lammps2021_flip)
        flip_n = p->style->lammps2021_flip(p, &flip_lo);
    e->hist_owner = flip_n > 0;
    if (flip_n > 0)
        e->hist_n++;

    const char *names[32], *texts[32];
    int n = 0;
    add_source(g, names, texts, &n, "param_layout.h", "engine");
    add_source(g, names, texts, &n, "common.cl", "engine");
    /* LAMMPS granular kinematics for the gran pair and wall evaluators:
     * static inline helpers, free in scenes that do not call them */
    add_source(g, names, texts, &n, "gran_common.cl", "engine");
    /* normal impulse of the source-document contact laws (same terms) */
    add_source(g, names, texts, &n, "contact_normal.cl", "engine");
    /* per-particle fix work run inside the check and gather kernels */
    add_source(g, names, texts, &n, "fused.cl", "engine");
    /* collision-resolution and wall-overlap records (src/accuracy.c) */
    add_source(g, names, texts, &n, "accuracy.cl", "engine");
    for (int k = 0; p && pair_source(p, k); k++) /* cohesion: one source per fused term */
        add_source(g, names, texts, &n, pair_source(p, k), p->style->name);
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        for (int k = 0; k < f->nsources; k++)
            add_source(g, names, texts, &n, f->sources[k], f->style->name);
    }
    add_source(g, names, texts, &n, "pair_loop.cl", "engine");
    add_source(g, names, texts, &n, "neighbor.cl", "engine");
    add_source(g, names, texts, &n, "box_change.cl", "engine");

    char opts[1024];
    int len = snprintf(opts, sizeof opts, "-D REAL=%s%s%s%s", single ? "float" : "double",
                       !single ? " -D USE_DOUBLE"
                       : e->ocl.fp64 ? " -D SPLIT_POS -D HAS_FP64" /* contact_refine in double */
                                     : " -D SPLIT_POS", e->rotation ? " -D HAS_ROTATION" : "",
                       e->history ? " -D HAS_HISTORY" : "");
    if (e->hist_n != 3)
        len += snprintf(opts + len, sizeof opts - (size_t)len, " -D HIST_N=%d", e->hist_n);
    if (lmp2021)
        len += snprintf(opts + len, sizeof opts - (size_t)len, " -D LMP2021");
    if (flip_n > 0)
        len += snprintf(opts + len, sizeof opts - (size_t)len,
                        " -D HIST_OWNER=%d -D HIST_ZERO_N=%d -D HIST_FLIP_LO=%d -D HIST_FLIP_N=%d",
                        e->hist_n - 1, e->hist_n - 1, flip_lo, flip_n);
    for (int q = 0; q < 3; q++)
        if (domain_contact_periodic(g, q))
            len += snprintf(opts + len, sizeof opts - (size_t)len, " -D PERIODIC_%c", "XYZ"[q]);
    if (g->dom.triclinic)
        len += snprintf(opts + len, sizeof opts - (size_t)len, " -D TRICLINIC");
    if (p) /* cohesion: PAIR_EVAL, or the fused terms of hybrid/overlay */
        len += pair_defines(p, opts + len, sizeof opts - (size_t)len);
    for (int i = 0; i < g->styles.nfix && len < (int)sizeof opts; i++)
        if (g->styles.fix[i]->defines[0])
            len += snprintf(opts + len, sizeof opts - (size_t)len, " %s",
                            g->styles.fix[i]->defines);
    if (len >= (int)sizeof opts)
        gr_error(g, "kernel build options too long");
    eng_release_kernels(e);
    uint64_t before = e->ocl.program_key;
    ocl_build(g, &e->ocl, n, names, texts, opts);
    if (e->ocl.program_key != before || !e->ocl.cache_hit)
        gr_print(g, "OpenCL program: %s (%s)\n",
                 e->ocl.cache_hit ? "program cache hit" : "compiled", opts);
}

void engine_destroy(struct gravel *g)
{
    struct engine *e = g->eng;
    if (!e)
        return;
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
    free(e->tag_seen);
    free(e->tag_order);
    if (e->hrate)
        clReleaseMemObject(e->hrate);
    eng_release_kernels(e);
    free(e->kern);
    free(e->kern_wg);
    release_set(&e->a);
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
