/* device.c - the device engine's helpers: device choice on first use,
 * kernels and their checked argument setters and launches, buffer
 * allocation and transfers (REAL conversion, split positions), and the tag
 * order of the device atoms. Knows no style and no run phase: what a run
 * builds, uploads and releases is engine.c. */
#include "device.h"

#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "comm.h"
#include "error.h"
#include "log.h"

struct engine *eng_open(struct gravel *g, long atoms)
{
    if (!g->eng)
        g->eng = gr_calloc(g, 1, sizeof *g->eng);
    struct engine *e = g->eng;
    if (!e->ready) {
        ocl_init(g, &e->ocl, g->opt.device, atoms);
        e->ready = 1;
        gr_print(g, "OpenCL device: %s (%s)%s\n", e->ocl.name, e->ocl.version,
                 e->ocl.serial ? "; serial: kernels run in gravel's own thread" : "");
        if (e->ocl.threads && !e->ocl.is_gpu)
            gr_print(g, "PoCL threads per rank: %d (%d ranks share this node's cores; "
                        "POCL_MAX_PTHREAD_COUNT overrides)\n", e->ocl.threads,
                     comm_local_size());
    }
    return e;
}

struct engine *eng_get(struct gravel *g) { return eng_open(g, -1); }

struct dev_atoms *eng_atoms(struct gravel *g) { return &g->eng->a; }
int eng_in_setup(struct gravel *g) { return g->eng && g->eng->setup; }

/* The arguments last set on a kernel, so that setting one to the value it
 * holds is skipped: PoCL allocates and copies at every clSetKernelArg, and a
 * step's launches set mostly the buffers of the step before. An argument
 * keeps its value on the kernel until it is set again (OpenCL 1.2 5.9.2);
 * a local-memory size is not remembered. */
#define MEMO_ARGS 64
#define MEMO_INLINE 16
struct arg_memo {
    size_t sz; /* 0: unknown */
    unsigned char v[MEMO_INLINE];
    unsigned char *big; /* a value over MEMO_INLINE bytes (a struct of scalars) */
    size_t bigcap;
};
struct kern_memo {
    struct arg_memo a[MEMO_ARGS];
};

static void memo_forget(struct kern_memo *m)
{
    for (int i = 0; i < MEMO_ARGS; i++)
        free(m->a[i].big);
    memset(m, 0, sizeof *m);
}

cl_kernel eng_kernel(struct gravel *g, const char *name)
{
    struct engine *e = g->eng;
    if (e->nkern == e->kern_cap) {
        e->kern_cap = e->kern_cap ? 2 * e->kern_cap : 32;
        e->kern = gr_realloc(g, e->kern, (size_t)e->kern_cap * sizeof *e->kern);
        e->kern_wg = gr_realloc(g, e->kern_wg, (size_t)e->kern_cap * sizeof *e->kern_wg);
        e->kern_memo = gr_realloc(g, e->kern_memo, (size_t)e->kern_cap * sizeof *e->kern_memo);
    }
    memset(&e->kern_memo[e->nkern], 0, sizeof *e->kern_memo);
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
    for (int i = 0; i < e->nkern; i++) {
        clReleaseKernel(e->kern[i]);
        memo_forget(&e->kern_memo[i]);
    }
    e->nkern = 0;
    e->kern_last = 0;
}

/* index of kernel k in e->kern (-1: not made by eng_kernel); the last one
 * found is tried first, as a launch's arguments are set in a row */
static int kernel_index(struct engine *e, cl_kernel k)
{
    if (e->kern_last < e->nkern && e->kern[e->kern_last] == k)
        return e->kern_last;
    for (int i = 0; i < e->nkern; i++)
        if (e->kern[i] == k)
            return e->kern_last = i;
    return -1;
}

static void set_arg(struct gravel *g, cl_kernel k, int i, size_t sz, const void *p)
{
    struct engine *e = g->eng;
    const int ki = kernel_index(e, k);
    struct arg_memo *m = ki >= 0 && i < MEMO_ARGS ? &e->kern_memo[ki].a[i] : NULL;
    if (m && p && m->sz == sz && !memcmp(sz <= MEMO_INLINE ? m->v : m->big, p, sz))
        return;
    cl_int err = clSetKernelArg(k, (cl_uint)i, sz, p);
    if (err != CL_SUCCESS) {
        char name[128] = "?";
        clGetKernelInfo(k, CL_KERNEL_FUNCTION_NAME, sizeof name, name, NULL);
        gr_error(g, "OpenCL clSetKernelArg(%s, %d) failed: %s", name, i, ocl_errname(err));
    }
    if (!m)
        return;
    m->sz = 0;
    if (!p) /* local memory */
        return;
    if (sz > MEMO_INLINE && m->bigcap < sz) {
        free(m->big);
        m->big = gr_malloc(g, sz);
        m->bigcap = sz;
    }
    memcpy(sz <= MEMO_INLINE ? m->v : m->big, p, sz);
    m->sz = sz;
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
void eng_arg_bytes(struct gravel *g, cl_kernel k, int i, size_t bytes, const void *p)
{
    set_arg(g, k, i, bytes, p);
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
    const int i = kernel_index(e, k);
    return i >= 0 ? e->kern_wg[i] : 1;
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

size_t eng_field_bytes(const struct gravel *g, enum atom_field_dev dev, size_t hsz, int width)
{
    return (size_t)width * (dev == FD_RAW ? hsz : g->eng->rsz);
}
