/* compute_multisphere_energy.c - LIGGGHTS's `compute ID group ke/multisphere`
 * and `compute ID group erotate/multisphere`: the kinetic energy of the clumps
 * of the fix multisphere, translational (sum 1/2 M vcm^2) or rotational (sum
 * 1/2 I w^2 in each body's principal frame), x mvv2e. Global scalars,
 * extensive; the group is ignored (LIGGGHTS: every body of the fix counts).
 * On several MPI ranks every rank holds every body: the same value on each. */
#include "compute.h"
#include "error.h"
#include "fix.h"
#include "fix_rigid_small.h"

static void create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute %s takes no arguments after the style, got %d", c->style->name,
                 argc);
    c->scalar_flag = 1;
    c->extscalar = 1;
}

static double energy(struct gravel *g, struct compute *c, int rotational)
{
    struct fix *f = fix_find_style(g, "multisphere");
    if (!f)
        gr_error(g, "compute %s %s requires a fix multisphere", c->id, c->style->name);
    double ke, erot;
    rigid_small_body_energy(f, &ke, &erot);
    return compute_mvv2e(g) * (rotational ? erot : ke);
}

static double ke_scalar(struct gravel *g, struct compute *c)
{
    return energy(g, c, 0);
}

static double erotate_scalar(struct gravel *g, struct compute *c)
{
    return energy(g, c, 1);
}

const struct compute_style compute_style_ke_multisphere = {
    .name = "ke/multisphere",
    .ranks = COMPUTE_RANKS_SUMS, /* every rank's bodies are all the bodies */
    .create = create,
    .scalar = ke_scalar,
};

const struct compute_style compute_style_erotate_multisphere = {
    .name = "erotate/multisphere",
    .ranks = COMPUTE_RANKS_SUMS, /* every rank's bodies are all the bodies */
    .create = create,
    .scalar = erotate_scalar,
};
