/* fix_lineforce.c - `fix ID group lineforce x y z` and `fix ID group
 * planeforce x y z`: LAMMPS's fix lineforce (each atom's force projected on
 * the line through it along (x, y, z): motion along a line) and fix
 * planeforce (the force's component along (x, y, z) removed: motion in the
 * plane normal to it), at every post_force and at setup
 * (kernels/fix_lineforce.cl). The direction is normalised; zero is an
 * error. */
#include <math.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix.h"

struct lineforce {
    double dir[3];
    int plane;
    cl_kernel k;
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    const char *who = f->style->name;
    if (argc != 3)
        gr_error(g, "fix %s expects x y z, got %d arguments", who, argc);
    struct lineforce *l = gr_calloc(g, 1, sizeof *l);
    f->data = l;
    l->plane = !strcmp(who, "planeforce");
    for (int d = 0; d < 3; d++)
        l->dir[d] = arg_double(g, argv[d], "direction component");
    const double len = sqrt(l->dir[0] * l->dir[0] + l->dir[1] * l->dir[1] + l->dir[2] * l->dir[2]);
    if (len == 0.0)
        gr_error(g, "fix %s: the direction (0, 0, 0) has no length", who);
    for (int d = 0; d < 3; d++)
        l->dir[d] /= len;
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_lineforce.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    ((struct lineforce *)f->data)->k = eng_kernel(g, "line_plane_force");
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct lineforce *l = f->data;
    struct dev_atoms *a = eng_atoms(g);
    int p = 0;
    eng_arg_int(g, l->k, p++, a->n);
    eng_arg_uint(g, l->k, p++, f->groupbit);
    eng_arg_mem(g, l->k, p++, a->mask);
    eng_arg_mem(g, l->k, p++, a->f);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, l->k, p++, l->dir[d]);
    eng_arg_int(g, l->k, p++, l->plane);
    eng_launch(g, l->k, (size_t)a->n);
}

const struct fix_style fix_style_lineforce = {
    .name = "lineforce",
    .create = create,
    .init = init,
    .post_force = post_force,
};

const struct fix_style fix_style_planeforce = {
    .name = "planeforce",
    .create = create,
    .init = init,
    .post_force = post_force,
};
