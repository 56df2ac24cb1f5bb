/* compute_erotate_sphere_atom.c - `compute ID group erotate/sphere/atom`:
 * per-atom rotational kinetic energy 1/2 I w^2 of a solid sphere, I = 2/5 m
 * r^2 (x mvv2e), in LAMMPS's order of operations; 0 for atoms outside the
 * group, as LAMMPS' compute erotate/sphere/atom. Feeds compute reduce and
 * dump custom c_ID. */
#include "compute.h"
#include "error.h"

#define INERTIA 0.4 /* a solid sphere's moment of inertia / (m r^2) */

static void erotate_atom_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute erotate/sphere/atom takes no arguments after the style, got %d",
                 argc);
    c->peratom_flag = 1;
}

static void erotate_atom_peratom(struct gravel *g, struct compute *c)
{
    const struct atoms *a = &g->atoms;
    const double pfactor = 0.5 * compute_mvv2e(g) * INERTIA;
    for (int i = 0; i < a->n; i++) {
        const double *w = a->omega + 3 * i;
        c->peratom[i] = (a->mask[i] & c->groupbit)
                            ? (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * a->radius[i] *
                                  a->radius[i] * a->rmass[i] * pfactor
                            : 0.0;
    }
}

const struct compute_style compute_style_erotate_sphere_atom = {
    .name = "erotate/sphere/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = erotate_atom_create,
    .peratom = erotate_atom_peratom,
};
