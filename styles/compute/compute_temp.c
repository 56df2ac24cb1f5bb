/* compute_temp.c - `compute ID group temp`: translational temperature of the
 * group as LAMMPS' compute temp, T = mvv2e sum m v.v / (dof kB) with
 * dof = dim N - extra/dof (src/engine/temperature.h), global scalar (intensive),
 * and the kinetic-energy tensor as a 6-vector (extensive). compute_modify
 * sets dynamic/dof and extra/dof. */
#include "compute.h"
#include "error.h"
#include "temperature.h"

static void create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute temp takes no arguments after the style, got %d", argc);
    temp_compute_attach(g, c, TEMP_TRANS);
}

const struct compute_style compute_style_temp = {
    .name = "temp",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = create,
    .init = temp_compute_init,
    .scalar = temp_compute_scalar,
    .vector = temp_compute_vector,
};
