/* kargs.c - the binders of the kernel argument lists (src/engine/kargs.h,
 * kernels/kernel_args.h): each walks its list and sets every argument by
 * its kind. */
#include "kargs.h"

#include "device.h"
#include "error.h"

static int bind_I(struct gravel *g, cl_kernel k, int i, int v)
{
    eng_arg_int(g, k, i, v);
    return i + 1;
}
static int bind_U(struct gravel *g, cl_kernel k, int i, unsigned v)
{
    eng_arg_uint(g, k, i, v);
    return i + 1;
}
static int bind_R(struct gravel *g, cl_kernel k, int i, double v)
{
    eng_arg_real(g, k, i, v);
    return i + 1;
}
static int bind_reals(struct gravel *g, cl_kernel k, int i, const double *v, int m)
{
    for (int q = 0; q < m; q++)
        eng_arg_real(g, k, i++, v[q]);
    return i;
}
static int bind_R3(struct gravel *g, cl_kernel k, int i, const double *v)
{
    return bind_reals(g, k, i, v, 3);
}
static int bind_C3(struct gravel *g, cl_kernel k, int i, const double *v)
{
    for (int q = 0; q < 3; q++)
        eng_arg_coord(g, k, i++, q, v[q]);
    return i;
}
static int bind_I3(struct gravel *g, cl_kernel k, int i, const int *v)
{
    for (int q = 0; q < 3; q++)
        eng_arg_int(g, k, i++, v[q]);
    return i;
}
static int bind_BOX(struct gravel *g, cl_kernel k, int i, const double *v)
{
    return bind_reals(g, k, i, v, 6);
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

#define KA_BIND(kind, name) KA_BIND_##kind(name)
#define KA_BIND_I(n) i = bind_I(g, k, i, a->n);
#define KA_BIND_U(n) i = bind_U(g, k, i, a->n);
#define KA_BIND_R(n) i = bind_R(g, k, i, a->n);
#define KA_BIND_R3(n) i = bind_R3(g, k, i, a->n);
#define KA_BIND_C3(n) i = bind_C3(g, k, i, a->n);
#define KA_BIND_I3(n) i = bind_I3(g, k, i, a->n);
#define KA_BIND_BOX(n) i = bind_BOX(g, k, i, a->n);
#define KA_BIND_M(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_BIND_CM(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_BIND_MI(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_BIND_CMI(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_BIND_CMU(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_BIND_MUC(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_BIND_MF(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_BIND_CML(n) i = bind_mem(g, k, i, a->n, #n);
#define KA_BIND_POS_LO(n) i = bind_POS_LO(g, k, i);
#define KA_BIND_PART(n) i = ka_bind_##n(g, k, i, &a->n);

#define KA_BINDER(name)                                                                        \
    int ka_bind_##name(struct gravel *g, cl_kernel k, int i, const struct name##_args *a)      \
    {                                                                                          \
        KARGS_##name(KA_BIND, KA_BIND) return i;                                               \
    }
KARGS_LISTS(KA_BINDER)

double ka_coord(const struct gravel *g, int q, double v) { return v - g->eng->origin[q]; }
