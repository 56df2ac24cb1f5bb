/* compute_com.c - `compute ID group com`: the centre of mass of the group,
 * from unwrapped positions (image flags), as LAMMPS's compute com: global
 * vector of 3 (x y z), intensive; 0 0 0 for a massless group. */
#include "compute.h"
#include "error.h"
#include "group.h"

static void com_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute com takes no arguments after the style, got %d", argc);
    c->vector_flag = 1;
    c->size_vector = 3;
    c->extvector = 0;
}

static void com_vector(struct gravel *g, struct compute *c)
{
    group_xcm(g, c->igroup, group_mass(g, c->igroup), c->vector);
}

const struct compute_style compute_style_com = {
    .name = "com",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = com_create,
    .vector = com_vector,
};
