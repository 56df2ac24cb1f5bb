/* compute_ke_atom.c - `compute ID group ke/atom`: per-atom translational
 * kinetic energy 1/2 m v^2 (x mvv2e); 0 for atoms outside the group, as
 * LAMMPS' compute ke/atom. Feeds compute reduce and dump custom c_ID. */
#include "compute.h"
#include "error.h"

static void ke_atom_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute ke/atom takes no arguments after the style, got %d", argc);
    c->peratom_flag = 1;
}

static void ke_atom_peratom(struct gravel *g, struct compute *c)
{
    const struct atoms *a = &g->atoms;
    double f = 0.5 * compute_mvv2e(g);
    for (int i = 0; i < a->n; i++) {
        const double *v = a->v + 3 * i;
        c->peratom[i] = (a->mask[i] & c->groupbit)
                            ? f * a->rmass[i] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
                            : 0.0;
    }
}

const struct compute_style compute_style_ke_atom = {
    .name = "ke/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = ke_atom_create,
    .peratom = ke_atom_peratom,
};
