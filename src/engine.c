/* engine.c - device state of a simulation: device and precision choice, the
 * per-atom buffers (structure of arrays, device order), program assembly for
 * the active styles, upload at run start and run_sync_host().
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
#include "kernel_sources.h"
#include "neighbor.h"
#include "pair.h"

extern const struct kernel_source gr_kernel_sources[];

struct engine *eng_get(struct gravel *g)
{
    if (!g->eng) {
        g->eng = gr_calloc(g, 1, sizeof *g->eng);
    }
    struct engine *e = g->eng;
    if (!e->ready) {
        ocl_init(g, &e->ocl, g->opt.device);
        e->ready = 1;
        gr_print(g, "OpenCL device: %s (%s)\n", e->ocl.name, e->ocl.version);
    }
    return e;
}

struct dev_atoms *eng_atoms(struct gravel *g) { return &g->eng->a; }
int eng_in_setup(struct gravel *g) { return g->eng && g->eng->setup; }

cl_kernel eng_kernel(struct gravel *g, const char *name)
{
    struct engine *e = g->eng;
    if (e->nkern == e->kern_cap) {
        e->kern_cap = e->kern_cap ? 2 * e->kern_cap : 32;
        e->kern = gr_realloc(g, e->kern, (size_t)e->kern_cap * sizeof *e->kern);
        e->kern_wg = gr_realloc(g, e->kern_wg, (size_t)e->kern_cap * sizeof *e->kern_wg);
    }
    cl_kernel k = ocl_kernel(g, &e->ocl, name);
    /* the device's choice (ocl.wg) capped by what the compiled kernel allows */
    size_t kmax = 0;
    if (clGetKernelWorkGroupInfo(k, e->ocl.device, CL_KERNEL_WORK_GROUP_SIZE, sizeof kmax, &kmax,
                                 NULL) != CL_SUCCESS || kmax == 0)
        kmax = 1;
    e->kern_wg[e->nkern] = e->ocl.wg < kmax ? e->ocl.wg : kmax;
    e->kern[e->nkern++] = k;
    return k;
}

void eng_release_kernels(struct engine *e)
{
    for (int i = 0; i < e->nkern; i++)
        clReleaseKernel(e->kern[i]);
    e->nkern = 0;
}

static void set_arg(struct gravel *g, cl_kernel k, int i, size_t sz, const void *p)
{
    cl_int err = clSetKernelArg(k, (cl_uint)i, sz, p);
    if (err != CL_SUCCESS) {
        char name[128] = "?";
        clGetKernelInfo(k, CL_KERNEL_FUNCTION_NAME, sizeof name, name, NULL);
        gr_error(g, "OpenCL clSetKernelArg(%s, %d) failed: %s", name, i, ocl_errname(err));
    }
}

void eng_arg_mem(struct gravel *g, cl_kernel k, int i, cl_mem m) { set_arg(g, k, i, sizeof m, &m); }
void eng_arg_int(struct gravel *g, cl_kernel k, int i, int v) { set_arg(g, k, i, sizeof v, &v); }
void eng_arg_uint(struct gravel *g, cl_kernel k, int i, unsigned v)
{
    cl_uint u = v;
    set_arg(g, k, i, sizeof u, &u);
}
void eng_arg_real(struct gravel *g, cl_kernel k, int i, double v)
{
    if (g->eng->single) {
        float f = (float)v;
        set_arg(g, k, i, sizeof f, &f);
    } else {
        set_arg(g, k, i, sizeof v, &v);
    }
}
void eng_arg_local(struct gravel *g, cl_kernel k, int i, size_t bytes)
{
    set_arg(g, k, i, bytes, NULL);
}

/* Work-group size for kernel k, fixed when eng_kernel created it. Kernels
 * guard their index, so the global size is rounded up to a multiple of it;
 * results never depend on it (no cross-work-item sums). */
static size_t work_group(struct engine *e, cl_kernel k)
{
    for (int i = 0; i < e->nkern; i++)
        if (e->kern[i] == k)
            return e->kern_wg[i];
    return 1;
}

void eng_launch(struct gravel *g, cl_kernel k, size_t n)
{
    if (n == 0)
        return;
    struct engine *e = g->eng;
    cl_event ev = NULL;
    size_t local = work_group(e, k);
    e->st.nlaunch++;
    size_t global = (n + local - 1) / local * local;
    cl_int err = clEnqueueNDRangeKernel(e->ocl.queue, k, 1, NULL, &global, &local, 0, NULL,
                                        e->ocl.profile ? &ev : NULL);
    if (err == CL_SUCCESS && ev) {
        cl_ulong t0 = 0, t1 = 0;
        clWaitForEvents(1, &ev);
        clGetEventProfilingInfo(ev, CL_PROFILING_COMMAND_START, sizeof t0, &t0, NULL);
        clGetEventProfilingInfo(ev, CL_PROFILING_COMMAND_END, sizeof t1, &t1, NULL);
        clReleaseEvent(ev);
        char name[40] = "?";
        clGetKernelInfo(k, CL_KERNEL_FUNCTION_NAME, sizeof name, name, NULL);
        int s = 0;
        while (s < e->nprof && strcmp(e->prof_name[s], name))
            s++;
        if (s < 48) {
            if (s == e->nprof) {
                snprintf(e->prof_name[s], sizeof e->prof_name[s], "%s", name);
                e->nprof++;
            }
            e->prof_sec[s] += 1e-9 * (double)(t1 - t0);
            e->prof_calls[s]++;
        }
    }
    if (err != CL_SUCCESS) {
        char name[128] = "?";
        clGetKernelInfo(k, CL_KERNEL_FUNCTION_NAME, sizeof name, name, NULL);
        gr_error(g, "OpenCL launch of kernel %s over %zu items failed: %s", name, n,
                 ocl_errname(err));
    }
}

cl_mem eng_alloc(struct gravel *g, size_t bytes, const char *what)
{
    return ocl_alloc(g, &g->eng->ocl, bytes, what);
}

void eng_write(struct gravel *g, cl_mem m, size_t off, size_t bytes, const void *src)
{
    if (bytes)
        OCL_CHECK(g, clEnqueueWriteBuffer(g->eng->ocl.queue, m, CL_TRUE, off, bytes, src, 0,
                                          NULL, NULL));
}

void eng_read(struct gravel *g, cl_mem m, size_t off, size_t bytes, void *dst)
{
    if (bytes)
        OCL_CHECK(g, clEnqueueReadBuffer(g->eng->ocl.queue, m, CL_TRUE, off, bytes, dst, 0,
                                         NULL, NULL));
}

void eng_fill_zero(struct gravel *g, cl_mem m, size_t bytes)
{
    if (!bytes)
        return;
    cl_uint zero = 0;
    OCL_CHECK(g, clEnqueueFillBuffer(g->eng->ocl.queue, m, &zero, sizeof zero, 0, bytes, 0,
                                     NULL, NULL));
}

void eng_finish(struct gravel *g) { OCL_CHECK(g, clFinish(g->eng->ocl.queue)); }

void eng_write_reals(struct gravel *g, cl_mem m, size_t count, const double *src)
{
    eng_write_reals_at(g, m, 0, count, src);
}

void eng_write_reals_at(struct gravel *g, cl_mem m, size_t first, size_t count,
                        const double *src)
{
    if (!count)
        return;
    if (!g->eng->single) {
        eng_write(g, m, first * sizeof(double), count * sizeof(double), src);
        return;
    }
    float *tmp = gr_malloc(g, count * sizeof(float));
    for (size_t i = 0; i < count; i++)
        tmp[i] = (float)src[i];
    cl_int err = clEnqueueWriteBuffer(g->eng->ocl.queue, m, CL_TRUE, first * sizeof(float),
                                      count * sizeof(float), tmp, 0, NULL, NULL);
    free(tmp);
    ocl_check(g, err, "clEnqueueWriteBuffer");
}

void eng_read_reals(struct gravel *g, cl_mem m, size_t count, double *dst)
{
    if (!count)
        return;
    if (!g->eng->single) {
        eng_read(g, m, 0, count * sizeof(double), dst);
        return;
    }
    float *tmp = gr_malloc(g, count * sizeof(float));
    cl_int err = clEnqueueReadBuffer(g->eng->ocl.queue, m, CL_TRUE, 0, count * sizeof(float),
                                     tmp, 0, NULL, NULL);
    if (err == CL_SUCCESS)
        for (size_t i = 0; i < count; i++)
            dst[i] = tmp[i];
    free(tmp);
    ocl_check(g, err, "clEnqueueReadBuffer");
}

void eng_write_positions(struct gravel *g, const struct dev_atoms *s, int first, int n,
                         const double *src)
{
    struct engine *e = g->eng;
    size_t count = 3 * (size_t)n, off = 3 * (size_t)first;
    if (!count)
        return;
    if (!e->single) {
        eng_write(g, s->x, off * sizeof(double), count * sizeof(double), src);
        return;
    }
    float *hi = gr_malloc(g, 2 * count * sizeof(float)), *lo = hi + count;
    for (size_t i = 0; i < count; i++) {
        double rel = src[i] - e->origin[i % 3];
        hi[i] = (float)rel;
        lo[i] = (float)(rel - (double)hi[i]);
    }
    eng_write(g, s->x, off * sizeof(float), count * sizeof(float), hi);
    eng_write(g, s->xlo, off * sizeof(float), count * sizeof(float), lo);
    free(hi);
}

void eng_read_positions(struct gravel *g, const struct dev_atoms *s, int n, double *dst)
{
    struct engine *e = g->eng;
    size_t count = 3 * (size_t)n;
    if (!count)
        return;
    if (!e->single) {
        eng_read(g, s->x, 0, count * sizeof(double), dst);
        return;
    }
    float *hi = gr_malloc(g, 2 * count * sizeof(float)), *lo = hi + count;
    cl_int err = clEnqueueReadBuffer(e->ocl.queue, s->x, CL_TRUE, 0, count * sizeof(float), hi,
                                     0, NULL, NULL);
    if (err == CL_SUCCESS)
        err = clEnqueueReadBuffer(e->ocl.queue, s->xlo, CL_TRUE, 0, count * sizeof(float), lo,
                                  0, NULL, NULL);
    if (err == CL_SUCCESS)
        for (size_t i = 0; i < count; i++)
            dst[i] = e->origin[i % 3] + ((double)hi[i] + (double)lo[i]);
    free(hi);
    ocl_check(g, err, "clEnqueueReadBuffer");
}

void eng_arg_coord(struct gravel *g, cl_kernel k, int i, int q, double v)
{
    eng_arg_real(g, k, i, v - g->eng->origin[q]);
}

void eng_arg_pos_lo(struct gravel *g, cl_kernel k, int i)
{
    if (g->eng->single)
        eng_arg_mem(g, k, i, g->eng->a.xlo);
}

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
    add_source(g, names, texts, &n, "wall_layout.h", "engine");
    /* the pipeline kernels' argument lists (src/kargs.h binds them) */
    add_source(g, names, texts, &n, "kernel_args.h", "engine");
    add_source(g, names, texts, &n, "common.cl", "engine");
    /* the contact record and the one contact body of every source */
    add_source(g, names, texts, &n, "contact.cl", "engine");
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

const int *eng_tag_order(struct gravel *g)
{
    struct engine *e = g->eng;
    int n = e->a.n;
    if (n + 1 > e->tag_cap) {
        free(e->tag_seen);
        free(e->tag_order);
        e->tag_seen = gr_malloc(g, ((size_t)n + 1) * sizeof(int64_t));
        e->tag_order = gr_malloc(g, ((size_t)n + 1) * sizeof(int));
        e->tag_cap = n + 1;
        e->tag_n = -1;
    }
    int64_t *t = gr_malloc(g, ((size_t)n + 1) * sizeof(int64_t));
    if (n > 0)
        eng_read(g, e->a.tag, 0, (size_t)n * sizeof(cl_long), t);
    if (n != e->tag_n || memcmp(t, e->tag_seen, (size_t)n * sizeof(int64_t))) {
        memcpy(e->tag_seen, t, (size_t)n * sizeof(int64_t));
        atoms_order_by_tag(e->tag_seen, n, e->tag_order);
        e->tag_n = n;
    }
    free(t);
    return e->tag_order;
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
