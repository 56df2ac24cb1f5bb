/* kargs.h - host side of the kernel argument lists of kernels/kernel_args.h:
 * for each list KARGS_<name> a struct <name>_args, one field per argument
 * named as the kernel's parameter (kinds and host types: the header of
 * kernel_args.h), and a binder
 *     int ka_bind_<name>(g, k, i, const struct <name>_args *a)
 * that sets the kernel's arguments from index i (KA_KERNEL of kernel_args.h:
 * its scalars in one struct, then its buffers in list order) and returns the
 * next index. A caller fills the struct by name and binds it with one call: no
 * positional index is written by hand. */
#ifndef GR_KARGS_H
#define GR_KARGS_H

#include "state.h"
#include "kernel_args.h"
#include "ocl.h"

/* host field of each kind */
#define KA_FIELD(kind, name) KA_FIELD_##kind(name)
#define KA_FIELD_I(n) int n;
#define KA_FIELD_U(n) unsigned n;
#define KA_FIELD_R(n) double n;
#define KA_FIELD_R3(n) double n[3];
#define KA_FIELD_C3(n) double n[3];
#define KA_FIELD_I3(n) int n[3];
#define KA_FIELD_BOX(n) double n[6];
#define KA_FIELD_M(n) cl_mem n;
#define KA_FIELD_CM(n) cl_mem n;
#define KA_FIELD_MI(n) cl_mem n;
#define KA_FIELD_CMI(n) cl_mem n;
#define KA_FIELD_CMU(n) cl_mem n;
#define KA_FIELD_MUC(n) cl_mem n;
#define KA_FIELD_MF(n) cl_mem n;
#define KA_FIELD_CML(n) cl_mem n;
#define KA_FIELD_POS_LO(n) /* bound from the engine */
#define KA_FIELD_PART(n) struct n##_args n;

#define KA_STRUCT(name)                                                                        \
    struct name##_args {                                                                       \
        KARGS_##name(KA_FIELD, KA_FIELD)                                                       \
    };                                                                                         \
    int ka_bind_##name(struct gravel *g, cl_kernel k, int i, const struct name##_args *a);
KARGS_LISTS(KA_STRUCT)
#undef KA_STRUCT

/* A lab-frame coordinate of dimension q as the device sees it (x - origin;
 * what eng_arg_coord binds), for an R field. */
double ka_coord(const struct gravel *g, int q, double v);

#endif
