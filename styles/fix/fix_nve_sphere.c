/* fix_nve_sphere.c - `fix ID group nve/sphere [update dipole|dipole/dlm]
 * [disc]`: LAMMPS' velocity Verlet for finite-size spheres (kernels in
 * kernels/fix_nve_sphere.cl), moment of inertia 0.4 m r^2, or 0.5 m r^2
 * with `disc` (2d only, as LAMMPS). The dipole update is rejected with a
 * clear error (no point dipoles). */
#include <string.h>

#include "device.h"
#include "error.h"
#include "fix.h"
#include "fused.h"

struct kern {
    cl_kernel ini, fin;
    double inertia;             /* 0.4 sphere, 0.5 disc */
    double prm[3];              /* fused op parameters (dtv dtf dtf/I, or dtf dtf/I) */
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    double inertia = 0.4;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "update"))
            gr_error(g, "fix nve/sphere keyword 'update' is not supported (point dipoles are "
                        "not modeled)");
        if (!strcmp(argv[i], "disc")) {
            if (g->dom.dimension != 2)
                gr_error(g, "fix nve/sphere disc requires a 2d simulation (dimension 2)");
            inertia = 0.5;
            continue;
        }
        gr_error(g, "unknown fix nve/sphere keyword '%.64s' (disc)", argv[i]);
    }
    f->data = gr_calloc(g, 1, sizeof(struct kern));
    ((struct kern *)f->data)->inertia = inertia;
    f->hooks = HOOK_INITIAL_INTEGRATE | HOOK_FINAL_INTEGRATE;
    f->needs = NEED_ROTATION;
    f->sources[f->nsources++] = "fix_nve_sphere.cl";
}

/* LAMMPS's dtfrotate = dtf / inertia, once per run, rounded as the
 * device's REAL rounds it (the kernels no longer divide per particle) */
static double dtfrotate(const struct gravel *g, double inertia)
{
    const double dtf = 0.5 * g->dt;
    if (g->eng->single)
        return (double)((float)dtf / (float)inertia);
    return dtf / inertia;
}

static void init(struct gravel *g, struct fix *f)
{
    struct kern *k = f->data;
    k->ini = eng_kernel(g, "nve_sphere_initial");
    k->fin = eng_kernel(g, "nve_sphere_final");
}

static void initial_integrate(struct gravel *g, struct fix *f)
{
    struct kern *k = f->data;
    struct dev_atoms *a = eng_atoms(g);
    struct engine *e = g->eng;
    cl_mem om = e->rotation ? a->omega : a->v, tq = e->rotation ? a->torque : a->f;
    eng_arg_int(g, k->ini, 0, a->n);
    eng_arg_uint(g, k->ini, 1, f->groupbit);
    eng_arg_mem(g, k->ini, 2, a->mask);
    eng_arg_mem(g, k->ini, 3, a->x);
    eng_arg_mem(g, k->ini, 4, a->v);
    eng_arg_mem(g, k->ini, 5, a->f);
    eng_arg_mem(g, k->ini, 6, om);
    eng_arg_mem(g, k->ini, 7, tq);
    eng_arg_mem(g, k->ini, 8, a->radius);
    eng_arg_mem(g, k->ini, 9, a->rmass);
    eng_arg_real(g, k->ini, 10, g->dt);
    eng_arg_real(g, k->ini, 11, 0.5 * g->dt);
    eng_arg_real(g, k->ini, 12, dtfrotate(g, k->inertia));
    eng_arg_pos_lo(g, k->ini, 13);
    eng_launch(g, k->ini, (size_t)a->n);
}

static void final_integrate(struct gravel *g, struct fix *f)
{
    struct kern *k = f->data;
    struct dev_atoms *a = eng_atoms(g);
    struct engine *e = g->eng;
    cl_mem om = e->rotation ? a->omega : a->v, tq = e->rotation ? a->torque : a->f;
    eng_arg_int(g, k->fin, 0, a->n);
    eng_arg_uint(g, k->fin, 1, f->groupbit);
    eng_arg_mem(g, k->fin, 2, a->mask);
    eng_arg_mem(g, k->fin, 3, a->v);
    eng_arg_mem(g, k->fin, 4, a->f);
    eng_arg_mem(g, k->fin, 5, om);
    eng_arg_mem(g, k->fin, 6, tq);
    eng_arg_mem(g, k->fin, 7, a->radius);
    eng_arg_mem(g, k->fin, 8, a->rmass);
    eng_arg_real(g, k->fin, 9, 0.5 * g->dt);
    eng_arg_real(g, k->fin, 10, dtfrotate(g, k->inertia));
    eng_launch(g, k->fin, (size_t)a->n);
}

/* Fused: the kicks and the drift inside the check and gather kernels
 * (kernels/fused.cl), with dtv = dt, dtf = dt/2 and dtfrotate as above. */
static int fuse(struct gravel *g, struct fix *f, unsigned hook, struct fused_op *op)
{
    struct kern *k = f->data;
    if (hook == HOOK_INITIAL_INTEGRATE) {
        k->prm[0] = g->dt;
        k->prm[1] = 0.5 * g->dt;
        k->prm[2] = dtfrotate(g, k->inertia);
        op->kind = FOP_NVE_SPHERE_INITIAL;
        op->nprm = 3;
    } else if (hook == HOOK_FINAL_INTEGRATE) {
        k->prm[0] = 0.5 * g->dt;
        k->prm[1] = dtfrotate(g, k->inertia);
        op->kind = FOP_NVE_SPHERE_FINAL;
        op->nprm = 2;
    } else {
        return 0;
    }
    op->prm = k->prm;
    return 1;
}

const struct fix_style fix_style_nve_sphere = {
    .name = "nve/sphere",
    .flags = FIX_CONSERVING,
    .create = create,
    .init = init,
    .initial_integrate = initial_integrate,
    .final_integrate = final_integrate,
    .fuse = fuse,
};
