/* compute_gyration.c - `compute ID group gyration`: the radius of gyration
 * of the group, as LAMMPS's compute gyration: scalar
 * Rg = sqrt(sum m_i |r_i - r_cm|^2 / M) and vector of 6, the gyration
 * tensor sum m_i d_a d_b / M in the order xx yy zz xy xz yz, with r_i the
 * unwrapped positions and r_cm the centre of mass. Intensive; 0 for a
 * massless group. */
#include <math.h>

#include "atoms.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "group.h"

static void gyration_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute gyration takes no arguments after the style, got %d", argc);
    c->scalar_flag = 1;
    c->vector_flag = 1;
    c->size_vector = 6;
    c->extscalar = 0;
    c->extvector = 0;
}

/* rg[0..5] = sum m d_a d_b over the group, rg[6] = sum |d|^2 m (LAMMPS's
 * scalar sum, one accumulator); returns the group mass. */
static double gyration_sums(struct gravel *g, struct compute *c, double rg[7])
{
    const struct atoms *a = &g->atoms;
    double mtot = group_mass(g, c->igroup), cm[3];
    group_xcm(g, c->igroup, mtot, cm);
    for (int k = 0; k < 7; k++)
        rg[k] = 0.0;
    const int *order = atoms_tag_order(g); /* sums that depend on the atoms only */
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!(a->mask[i] & c->groupbit))
            continue;
        double u[3];
        domain_unmap(g, a->x + 3 * i, a->image + 3 * i, u);
        double dx = u[0] - cm[0], dy = u[1] - cm[1], dz = u[2] - cm[2], m = a->rmass[i];
        rg[0] += dx * dx * m;
        rg[1] += dy * dy * m;
        rg[2] += dz * dz * m;
        rg[3] += dx * dy * m;
        rg[4] += dx * dz * m;
        rg[5] += dy * dz * m;
        rg[6] += (dx * dx + dy * dy + dz * dz) * m;
    }
    return mtot;
}

static double gyration_scalar(struct gravel *g, struct compute *c)
{
    double rg[7];
    double mtot = gyration_sums(g, c, rg);
    return mtot > 0 ? sqrt(rg[6] / mtot) : 0.0;
}

static void gyration_vector(struct gravel *g, struct compute *c)
{
    double rg[7];
    double mtot = gyration_sums(g, c, rg);
    for (int k = 0; k < 6; k++)
        c->vector[k] = mtot > 0 ? rg[k] / mtot : 0.0;
}

const struct compute_style compute_style_gyration = {
    .name = "gyration",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = gyration_create,
    .scalar = gyration_scalar,
    .vector = gyration_vector,
};
