/* compute_fragment_atom.c - `compute ID group fragment/atom [single
 * yes|no]`: LAMMPS's fragment IDs are the clusters of atoms joined by
 * bonds, which need a molecular atom style with bonds; gravel's atom styles
 * (sphere, with molecule IDs for rigid bodies) have no bonds, so the
 * command is refused with that reason, as LAMMPS refuses it without bonds
 * ("Compute fragment/atom used when bonds are not allowed"). Contact
 * clusters are compute cluster/atom. */
#include "compute.h"
#include "error.h"

static void fragment_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)c;
    (void)argc;
    (void)argv;
    gr_error(g, "compute fragment/atom needs bonds (a molecular atom style with bonds), which "
                "gravel's atom styles do not have; use compute cluster/atom for clusters of "
                "touching or nearby particles");
}

const struct compute_style compute_style_fragment_atom = {
    .name = "fragment/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = fragment_create,
};
