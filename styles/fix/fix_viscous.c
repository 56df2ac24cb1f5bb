/* fix_viscous.c - `fix ID group viscous gamma [scale type ratio ...]`:
 * drag f -= gamma_type v (LAMMPS fix_viscous.cpp; kernels/fix_viscous.cl).
 * Per-type gamma = gamma x ratio, packed on the host and uploaded at init. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fused.h"

struct visc {
    int ntypes;
    double *gamma;      /* [ntypes] */
    cl_mem buf;
    cl_kernel post;
};

static void destroy(struct fix *f)
{
    struct visc *v = f->data;
    if (v) {
        if (v->buf)
            clReleaseMemObject(v->buf);
        free(v->gamma);
        free(v);
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix viscous expects gamma [scale type ratio ...]");
    if (g->atoms.ntypes < 1)
        gr_error(g, "fix viscous needs atom types (create the box first)");
    struct visc *v = gr_calloc(g, 1, sizeof *v);
    f->data = v;
    v->ntypes = g->atoms.ntypes;
    v->gamma = gr_calloc(g, (size_t)v->ntypes, sizeof(double));
    double gamma = arg_double(g, argv[0], "gamma");
    for (int t = 0; t < v->ntypes; t++)
        v->gamma[t] = gamma;
    for (int i = 1; i < argc; i += 3) {
        if (strcmp(argv[i], "scale"))
            gr_error(g, "unknown fix viscous keyword '%.64s' (expected scale)", argv[i]);
        arg_need(g, argc, i, 2, "scale");
        int t = arg_int_range(g, argv[i + 1], 1, v->ntypes, "scale type");
        v->gamma[t - 1] = gamma * arg_double(g, argv[i + 2], "scale ratio");
    }
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_viscous.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct visc *v = f->data;
    if (v->ntypes < g->atoms.ntypes)
        gr_error(g, "fix %s viscous was defined for %d atom types, now there are %d", f->id,
                 v->ntypes, g->atoms.ntypes);
    if (v->buf)
        clReleaseMemObject(v->buf);
    v->buf = eng_alloc(g, (size_t)v->ntypes * g->eng->rsz, "fix viscous gamma");
    eng_write_reals(g, v->buf, (size_t)v->ntypes, v->gamma);
    v->post = eng_kernel(g, "viscous_post_force");
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct visc *v = f->data;
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = v->post;
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->type);
    eng_arg_mem(g, k, 4, a->v);
    eng_arg_mem(g, k, 5, a->f);
    eng_arg_mem(g, k, 6, v->buf);
    eng_launch(g, k, (size_t)a->n);
}

/* Fused: f -= gamma_type v inside the gather kernel (kernels/fused.cl). */
static int fuse(struct gravel *g, struct fix *f, unsigned hook, struct fused_op *op)
{
    (void)g;
    struct visc *v = f->data;
    if (hook != HOOK_POST_FORCE)
        return 0;
    op->kind = FOP_VISCOUS;
    op->nprm = v->ntypes;
    op->prm = v->gamma;
    return 1;
}

const struct fix_style fix_style_viscous = {
    .name = "viscous",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
    .fuse = fuse,
};
