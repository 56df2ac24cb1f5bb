/* fix_nve_noforce.c - `fix ID group nve/noforce`: LAMMPS's fix nve/noforce,
 * the positions advanced at constant velocity (x += dt v), the forces not
 * applied (kernels/fix_nve_noforce.cl): an intruder driven through a bed
 * at a set speed, or a wall of particles moved as one. */
#include "device.h"
#include "error.h"
#include "fix.h"

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc > 0)
        gr_error(g, "fix nve/noforce takes no arguments, got '%.64s'", argv[0]);
    f->hooks = HOOK_INITIAL_INTEGRATE;
    f->sources[f->nsources++] = "fix_nve_noforce.cl";
}

struct noforce {
    cl_kernel ini;
};

static void init(struct gravel *g, struct fix *f)
{
    if (!f->data)
        f->data = gr_calloc(g, 1, sizeof(struct noforce));
    ((struct noforce *)f->data)->ini = eng_kernel(g, "nve_noforce_initial");
}

static void initial_integrate(struct gravel *g, struct fix *f)
{
    cl_kernel k = ((struct noforce *)f->data)->ini;
    struct dev_atoms *a = eng_atoms(g);
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->x);
    eng_arg_mem(g, k, 4, a->v);
    eng_arg_real(g, k, 5, g->dt);
    eng_arg_pos_lo(g, k, 6);
    eng_launch(g, k, (size_t)a->n);
}

const struct fix_style fix_style_nve_noforce = {
    .name = "nve/noforce",
    .create = create,
    .init = init,
    .initial_integrate = initial_integrate,
};
