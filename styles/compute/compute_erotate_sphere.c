/* compute_erotate_sphere.c - `compute ID group erotate/sphere`: rotational
 * kinetic energy of finite-size spheres, sum of 1/2 I w^2 with the solid-sphere
 * inertia I = 2/5 m r^2 (x mvv2e), as LAMMPS' compute erotate/sphere. Global
 * scalar, extensive. */
#include "atoms.h"
#include "compute.h"
#include "error.h"
#include "par_sum.h"

#define INERTIA 0.4 /* moment of inertia prefactor for a solid sphere */

static void erotate_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute erotate/sphere takes no arguments after the style, got %d", argc);
    c->scalar_flag = 1;
    c->extscalar = 1;
}

static double erotate_scalar(struct gravel *g, struct compute *c)
{
    const struct atoms *a = &g->atoms;
    const int *order = atoms_tag_order(g);
    struct par_sum sum = {0}; /* every rank's atoms, in tag order */
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!(a->mask[i] & c->groupbit))
            continue;
        const double *w = a->omega + 3 * i;
        par_sum_add(g, &sum, a->tag[i],
                    (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * a->radius[i] * a->radius[i] *
                        a->rmass[i]);
    }
    return 0.5 * INERTIA * compute_mvv2e(g) * par_sum_total(g, &sum);
}

const struct compute_style compute_style_erotate_sphere = {
    .name = "erotate/sphere",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = erotate_create,
    .scalar = erotate_scalar,
};
