/* fix_freeze.c - `fix ID group freeze`: zero force and torque of the group
 * after the pair forces (LAMMPS fix_freeze.cpp). The gran pair styles use
 * this group's bit for their effective mass (frozen partner: meff = m of the
 * other particle). At most one freeze fix, as in LAMMPS.
 * f_ID[1..3] is LAMMPS's global vector: the total force on the group before
 * it was zeroed at the last force computation. Only when a thermo_style
 * column shows it (checked at run setup) does the fix keep each atom's force
 * (a per-atom buffer, its own kernel instead of the fused op); the host sums
 * the group in tag order (on several MPI ranks every rank's atoms, as one
 * process). The fused path runs first, so a fix gravity
 * defined after the freeze fix is still counted (LAMMPS: not counted). */
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "device.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "fused.h"
#include "par_sum.h"
#include "thermo.h"

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
    int keep;                   /* this run keeps the forces (f_ID[N] shown) */
    bigint sum_step;            /* step of sum[] (-1: none) */
    double sum[3];
};

static void init(struct gravel *g, struct fix *f)
{
    if (!f->data)
        f->data = gr_calloc(g, 1, sizeof(struct kern));
    struct kern *k = f->data;
    k->keep = thermo_shows_fix_vector(g, f->id);
    k->sum_step = -1;
    k->post = eng_kernel(g, k->keep ? "freeze_post_force_keep" : "freeze_post_force");
    f->peratom_bytes = k->keep ? 3 * g->eng->rsz : 0;
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct kern *kd = f->data;
    cl_kernel k = kd->post;
    struct dev_atoms *a = eng_atoms(g);
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->f);
    eng_arg_mem(g, k, 4, g->eng->rotation ? a->torque : a->f);
    if (kd->keep)
        eng_arg_mem(g, k, 5, f->peratom);
    eng_launch(g, k, (size_t)a->n);
    kd->sum_step = -1;
}

/* f_ID[i]: component i of the group's force before zeroing. */
static double vector(struct gravel *g, struct fix *f, int i)
{
    struct kern *kd = f->data;
    if (!kd || !kd->keep || !f->peratom || !g->eng)
        gr_error(g, "fix %s (freeze): f_%s[%d] is available as a thermo_style column of a "
                    "run (the fix keeps the forces only then)",
                 f->id, f->id, i);
    if (kd->sum_step != g->step) {
        run_sync_host(g); /* host order = device order = the buffer's */
        const struct atoms *a = &g->atoms;
        double *orig = gr_malloc(g, ((size_t)a->n + 1) * 3 * sizeof(double));
        eng_read_reals(g, f->peratom, 3 * (size_t)a->n, orig);
        const int *ord = atoms_tag_order(g);
        struct par_sum s[3] = {{0}}; /* every rank's atoms in tag order (collective) */
        for (int k = 0; k < a->n; k++) {
            int j = ord[k];
            if (a->mask[j] & f->groupbit)
                for (int d = 0; d < 3; d++)
                    par_sum_add(g, &s[d], a->tag[j], orig[3 * j + d]);
        }
        free(orig);
        for (int d = 0; d < 3; d++)
            kd->sum[d] = par_sum_total(g, &s[d]);
        kd->sum_step = g->step;
    }
    return kd->sum[i - 1];
}

/* Fused: f = torque = 0 inside the gather kernel (kernels/fused.cl); not
 * when this run keeps the forces. */
static int fuse(struct gravel *g, struct fix *f, unsigned hook, struct fused_op *op)
{
    (void)g;
    if (hook != HOOK_POST_FORCE || ((struct kern *)f->data)->keep)
        return 0;
    op->kind = FOP_FREEZE;
    op->nprm = 0;
    op->prm = NULL;
    return 1;
}

const struct fix_style fix_style_freeze = {
    .name = "freeze",
    .flags = FIX_FROZEN | FIX_CONSERVING,
    .create = create,
    .init = init,
    .post_force = post_force,
    .fuse = fuse,
    .size_vector = 3,
    .vector = vector,
};
