/* fix_nve.c - `fix ID group nve`: velocity Verlet for point particles
 * (LAMMPS fix_nve.cpp with per-atom mass; kernels/fix_nve.cl). */
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fused.h"

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc > 0)
        gr_error(g, "fix nve takes no arguments, got '%.64s'", argv[0]);
    f->hooks = HOOK_INITIAL_INTEGRATE | HOOK_FINAL_INTEGRATE;
    f->sources[f->nsources++] = "fix_nve.cl";
}

struct kern {
    cl_kernel ini, fin;
    double prm[2];              /* fused op parameters (dtv dtf, or dtf) */
};

static void init(struct gravel *g, struct fix *f)
{
    if (!f->data)
        f->data = gr_calloc(g, 1, sizeof(struct kern));
    struct kern *k = f->data;
    k->ini = eng_kernel(g, "nve_initial");
    k->fin = eng_kernel(g, "nve_final");
}

static void initial_integrate(struct gravel *g, struct fix *f)
{
    struct kern *k = f->data;
    struct dev_atoms *a = eng_atoms(g);
    eng_arg_int(g, k->ini, 0, a->n);
    eng_arg_uint(g, k->ini, 1, f->groupbit);
    eng_arg_mem(g, k->ini, 2, a->mask);
    eng_arg_mem(g, k->ini, 3, a->x);
    eng_arg_mem(g, k->ini, 4, a->v);
    eng_arg_mem(g, k->ini, 5, a->f);
    eng_arg_mem(g, k->ini, 6, a->rmass);
    eng_arg_real(g, k->ini, 7, g->dt);
    eng_arg_real(g, k->ini, 8, 0.5 * g->dt);
    eng_arg_pos_lo(g, k->ini, 9);
    eng_launch(g, k->ini, (size_t)a->n);
}

static void final_integrate(struct gravel *g, struct fix *f)
{
    struct kern *k = f->data;
    struct dev_atoms *a = eng_atoms(g);
    eng_arg_int(g, k->fin, 0, a->n);
    eng_arg_uint(g, k->fin, 1, f->groupbit);
    eng_arg_mem(g, k->fin, 2, a->mask);
    eng_arg_mem(g, k->fin, 3, a->v);
    eng_arg_mem(g, k->fin, 4, a->f);
    eng_arg_mem(g, k->fin, 5, a->rmass);
    eng_arg_real(g, k->fin, 6, 0.5 * g->dt);
    eng_launch(g, k->fin, (size_t)a->n);
}

/* Fused: the kicks and the drift inside the check and gather kernels
 * (kernels/fused.cl), with dtv = dt and dtf = dt/2 as above. */
static int fuse(struct gravel *g, struct fix *f, unsigned hook, struct fused_op *op)
{
    struct kern *k = f->data;
    if (hook == HOOK_INITIAL_INTEGRATE) {
        k->prm[0] = g->dt;
        k->prm[1] = 0.5 * g->dt;
        op->kind = FOP_NVE_INITIAL;
        op->nprm = 2;
    } else if (hook == HOOK_FINAL_INTEGRATE) {
        k->prm[0] = 0.5 * g->dt;
        op->kind = FOP_NVE_FINAL;
        op->nprm = 1;
    } else {
        return 0;
    }
    op->prm = k->prm;
    return 1;
}

const struct fix_style fix_style_nve = {
    .name = "nve",
    .flags = FIX_CONSERVING,
    .create = create,
    .init = init,
    .initial_integrate = initial_integrate,
    .final_integrate = final_integrate,
    .fuse = fuse,
};
