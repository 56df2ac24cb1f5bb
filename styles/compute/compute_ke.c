/* compute_ke.c - `compute ID group ke`: translational kinetic energy of the
 * group, sum of 1/2 m v^2 (x mvv2e), as LAMMPS' compute ke. Global scalar,
 * extensive (thermo divides it by the atom count when norm is yes). */
#include "atoms.h"
#include "compute.h"
#include "par_sum.h"
#include "error.h"

static void ke_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute ke takes no arguments after the style, got %d", argc);
    c->scalar_flag = 1;
    c->extscalar = 1;
}

/* 1/2 sum m |v|^2 over atoms in the group, per-atom mass (atom_style sphere). */
static double ke_scalar(struct gravel *g, struct compute *c)
{
    const struct atoms *a = &g->atoms;
    const int *order = atoms_tag_order(g);
    struct par_sum sum = {0}; /* every rank's atoms, in tag order */
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!(a->mask[i] & c->groupbit))
            continue;
        const double *v = a->v + 3 * i;
        par_sum_add(g, &sum, a->tag[i], a->rmass[i] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    }
    return 0.5 * compute_mvv2e(g) * par_sum_total(g, &sum);
}

const struct compute_style compute_style_ke = {
    .name = "ke",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = ke_create,
    .scalar = ke_scalar,
};
