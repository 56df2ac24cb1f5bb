/* fix_freeze.c - `fix ID group freeze`: zero force and torque of the group
 * after the pair forces (LAMMPS fix_freeze.cpp). The gran pair styles use
 * this group's bit for their effective mass (frozen partner: meff = m of the
 * other particle). At most one freeze fix, as in LAMMPS. */
#include <string.h>

#include "engine.h"
#include "error.h"
#include "fix.h"

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc > 0)
        gr_error(g, "fix freeze takes no arguments, got '%.64s'", argv[0]);
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *o = g->styles.fix[i];
        if (o != f && o->style == f->style && strcmp(o->id, f->id))
            gr_error(g, "more than one fix freeze (fix %s exists)", o->id);
    }
    f->hooks = HOOK_POST_FORCE;
    f->needs = NEED_ROTATION;
    f->sources[f->nsources++] = "fix_freeze.cl";
}

struct kern {
    cl_kernel post;
};

static void init(struct gravel *g, struct fix *f)
{
    if (!f->data)
        f->data = gr_calloc(g, 1, sizeof(struct kern));
    ((struct kern *)f->data)->post = eng_kernel(g, "freeze_post_force");
}

static void post_force(struct gravel *g, struct fix *f)
{
    cl_kernel k = ((struct kern *)f->data)->post;
    struct dev_atoms *a = eng_atoms(g);
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->f);
    eng_arg_mem(g, k, 4, g->eng->rotation ? a->torque : a->f);
    eng_launch(g, k, (size_t)a->n);
}

/* Fused: f = torque = 0 inside the gather kernel (kernels/fused.cl). */
static int fuse(struct gravel *g, struct fix *f, unsigned hook, struct fused_op *op)
{
    (void)g;
    (void)f;
    if (hook != HOOK_POST_FORCE)
        return 0;
    op->kind = FOP_FREEZE;
    op->nprm = 0;
    op->prm = NULL;
    return 1;
}

const struct fix_style fix_style_freeze = {
    .name = "freeze",
    .create = create,
    .init = init,
    .post_force = post_force,
    .fuse = fuse,
};
