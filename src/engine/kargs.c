/* kargs.c - the binders of the kernel argument lists (src/engine/kargs.h,
 * kernels/kernel_args.h): a kernel's scalars go in one struct ka_<name>
 * (the REALs in list order, parts in place, then the ints and uints, then
 * ka_end), set as its first argument; its buffers follow in list order. */
#include "kargs.h"

#include <string.h>

#include "device.h"
#include "error.h"

/* the struct ka_<name> being laid out: the device's layout of REALs,
 * then 4-byte ints, then the padding to the struct's alignment */
struct ka_blob {
    unsigned char bytes[512];
    size_t len;
    int nreal;
};

static void put(struct gravel *g, struct ka_blob *b, const void *p, size_t sz)
{
    if (b->len + sz > sizeof b->bytes)
        gr_error(g, "internal error: a kernel's scalar arguments exceed %zu bytes",
                 sizeof b->bytes);
    memcpy(b->bytes + b->len, p, sz);
    b->len += sz;
}
static void put_real(struct gravel *g, struct ka_blob *b, double v)
{
    b->nreal++;
    if (g->eng->single) {
        float f = (float)v;
        put(g, b, &f, sizeof f);
    } else {
        put(g, b, &v, sizeof v);
    }
}
static void put_reals(struct gravel *g, struct ka_blob *b, const double *v, int m)
{
    for (int q = 0; q < m; q++)
        put_real(g, b, v[q]);
}
static void put_coords(struct gravel *g, struct ka_blob *b, const double *v)
{
    for (int q = 0; q < 3; q++)
        put_real(g, b, ka_coord(g, q, v[q]));
}
static void put_int(struct gravel *g, struct ka_blob *b, int v) { put(g, b, &v, sizeof v); }
static void put_uint(struct gravel *g, struct ka_blob *b, unsigned v)
{
    cl_uint u = v;
    put(g, b, &u, sizeof u);
}
static void put_ints(struct gravel *g, struct ka_blob *b, const int *v, int m)
{
    for (int q = 0; q < m; q++)
        put_int(g, b, v[q]);
}

/* a buffer argument: every one is set (a field left out of a designated
 * initializer is NULL, and stops the run here rather than in the kernel) */
static int bind_mem(struct gravel *g, cl_kernel k, int i, cl_mem m, const char *name)
{
    if (!m) {
        char kname[128] = "?";
        clGetKernelInfo(k, CL_KERNEL_FUNCTION_NAME, sizeof kname, kname, NULL);
        gr_error(g, "internal error: kernel %s argument %d (%s) has no buffer", kname, i, name);
    }
    eng_arg_mem(g, k, i, m);
    return i + 1;
}
/* the low position parts: an argument in single precision only */
static int bind_POS_LO(struct gravel *g, cl_kernel k, int i)
{
    eng_arg_pos_lo(g, k, i);
    return g->eng->single ? i + 1 : i;
}

/* the REALs of a list (KA_PR), its ints (KA_PI), its buffers (KA_PB) */
#define KA_PR(kind, name) KA_PR_##kind(name)
#define KA_PR_R(n) put_real(g, b, a->n);
#define KA_PR_R3(n) put_reals(g, b, a->n, 3);
#define KA_PR_C3(n) put_coords(g, b, a->n);
#define KA_PR_BOX(n) put_reals(g, b, a->n, 6);
#define KA_PR_PART(n) ka_reals_##n(g, b, &a->n);
#define KA_PI(kind, name) KA_PI_##kind(name)
#define KA_PI_I(n) put_int(g, b, a->n);
#define KA_PI_U(n) put_uint(g, b, a->n);
#define KA_PI_I3(n) put_ints(g, b, a->n, 3);
#define KA_PI_PART(n) ka_ints_##n(g, b, &a->n);
#define KA_PB(kind, name) KA_PB_##kind(name)
#define KA_PB_M(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_PB_CM(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_PB_MI(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_PB_CMI(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_PB_CMU(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_PB_MUC(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_PB_MF(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_PB_CML(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_PB_POS_LO(n) i = bind_POS_LO(g, k, i);
#define KA_PB_PART(n) i = ka_bufs_##n(g, k, i, &a->n);
/* what each pass leaves out */
#define KA_PR_I(n)
#define KA_PR_U(n)
#define KA_PR_I3(n)
#define KA_PI_R(n)
#define KA_PI_R3(n)
#define KA_PI_C3(n)
#define KA_PI_BOX(n)
#define KA_PB_I(n)
#define KA_PB_U(n)
#define KA_PB_R(n)
#define KA_PB_R3(n)
#define KA_PB_C3(n)
#define KA_PB_I3(n)
#define KA_PB_BOX(n)
#define KA_PR_M(n)
#define KA_PR_CM(n)
#define KA_PR_MI(n)
#define KA_PR_CMI(n)
#define KA_PR_CMU(n)
#define KA_PR_MUC(n)
#define KA_PR_MF(n)
#define KA_PR_CML(n)
#define KA_PR_POS_LO(n)
#define KA_PI_M(n)
#define KA_PI_CM(n)
#define KA_PI_MI(n)
#define KA_PI_CMI(n)
#define KA_PI_CMU(n)
#define KA_PI_MUC(n)
#define KA_PI_MF(n)
#define KA_PI_CML(n)
#define KA_PI_POS_LO(n)

#define KA_BINDER(name)                                                                        \
    static void ka_reals_##name(struct gravel *g, struct ka_blob *b,                           \
                                const struct name##_args *a)                                   \
    {                                                                                          \
        (void)g, (void)b, (void)a;                                                             \
        KARGS_##name(KA_PR, KA_PR)                                                             \
    }                                                                                          \
    static void ka_ints_##name(struct gravel *g, struct ka_blob *b, const struct name##_args *a) \
    {                                                                                          \
        (void)g, (void)b, (void)a;                                                             \
        KARGS_##name(KA_PI, KA_PI)                                                             \
    }                                                                                          \
    static int ka_bufs_##name(struct gravel *g, cl_kernel k, int i, const struct name##_args *a) \
    {                                                                                          \
        KARGS_##name(KA_PB, KA_PB) return i;                                                   \
    }                                                                                          \
    int ka_bind_##name(struct gravel *g, cl_kernel k, int i, const struct name##_args *a)      \
    {                                                                                          \
        struct ka_blob b = {.len = 0};                                                         \
        ka_reals_##name(g, &b, a);                                                             \
        ka_ints_##name(g, &b, a);                                                              \
        put_int(g, &b, 0); /* ka_end */                                                        \
        size_t align = b.nreal ? g->eng->rsz : sizeof(cl_int);                                 \
        while (b.len % align)                                                                  \
            put(g, &b, "", 1);                                                                 \
        eng_arg_bytes(g, k, i, b.len, b.bytes);                                                \
        return ka_bufs_##name(g, k, i + 1, a);                                                 \
    }
KARGS_LISTS(KA_BINDER)

double ka_coord(const struct gravel *g, int q, double v) { return v - g->eng->origin[q]; }
