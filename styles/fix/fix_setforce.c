/* fix_setforce.c - `fix ID group setforce fx fy fz [region ID]`: LAMMPS's
 * fix setforce: after the forces of the step (post_force, and at a run's
 * setup), each given component of the group's forces becomes the value (a
 * number, an equal-style v_name evaluated every step, or an atom-style
 * v_name: each atom's own); NULL leaves that component. The global vector
 * (f_ID[1..3], extensive) is the group's total force before the fix at the
 * last step (force_values.h). `region ID`: only the group's atoms inside
 * the region at the step (LAMMPS). */
#include <stdlib.h>

#include "error.h"
#include "fix.h"
#include "force_values.h"

#define WHO "fix setforce"

static void destroy(struct fix *f)
{
    struct force_values *fv = f->data;
    if (fv) {
        force_values_free(fv);
        free(fv);
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct force_values *fv = gr_calloc(g, 1, sizeof *fv);
    f->data = fv;
    fv->allow_atom = 1;
    force_values_create(g, f, fv, argc, argv, WHO);
}

static void init(struct gravel *g, struct fix *f)
{
    force_values_init(g, f, f->data, WHO);
}

static void post_force(struct gravel *g, struct fix *f)
{
    force_values_apply(g, f, f->data, 0);
}

static double vector(struct gravel *g, struct fix *f, int i)
{
    return force_values_original(g, f, i - 1);
}

const struct fix_style fix_style_setforce = {
    .name = "setforce",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
    .size_vector = 3,
    .vector = vector,
};
