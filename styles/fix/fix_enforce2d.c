/* fix_enforce2d.c - `fix ID group enforce2d`: keep a 2d simulation planar
 * (LAMMPS fix_enforce2d.cpp). After the forces (post_force, also at the
 * setup of each run) each atom of the group gets vz = fz = 0 and, with
 * rotation, omega_x = omega_y = torque_x = torque_y = 0, so a disc spins
 * about z only. Requires `dimension 2`. Runs as its own kernel
 * (kernels/fix_enforce2d.cl): it changes velocities, which a fused
 * post_force op does not write back. */
#include "device.h"
#include "error.h"
#include "fix.h"

struct kern {
    cl_kernel post;
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc > 0)
        gr_error(g, "fix enforce2d takes no arguments, got '%.64s'", argv[0]);
    if (g->dom.dimension != 2)
        gr_error(g, "cannot use fix enforce2d with a 3d simulation");
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_enforce2d.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    if (g->dom.dimension != 2)
        gr_error(g, "cannot use fix enforce2d with a 3d simulation");
    if (!f->data)
        f->data = gr_calloc(g, 1, sizeof(struct kern));
    ((struct kern *)f->data)->post = eng_kernel(g, "enforce2d_post_force");
}

static void post_force(struct gravel *g, struct fix *f)
{
    cl_kernel k = ((struct kern *)f->data)->post;
    struct dev_atoms *a = eng_atoms(g);
    int rot = g->eng->rotation;
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->v);
    eng_arg_mem(g, k, 4, a->f);
    eng_arg_mem(g, k, 5, rot ? a->omega : a->v);
    eng_arg_mem(g, k, 6, rot ? a->torque : a->f);
    eng_launch(g, k, (size_t)a->n);
}

const struct fix_style fix_style_enforce2d = {
    .name = "enforce2d",
    .create = create,
    .init = init,
    .post_force = post_force,
};
