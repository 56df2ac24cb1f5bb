/* compute_count_type.c - `compute ID group count/type atom`: number of atoms
 * of each type in the group, as LAMMPS' compute count/type (atom mode only:
 * gravel has no bonds). Global vector of length ntypes, extensive. */
#include <string.h>

#include "compute.h"
#include "error.h"

static void count_type_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, "compute count/type expects one argument 'atom', got %d", argc);
    if (strcmp(argv[0], "atom") != 0)
        gr_error(g, "compute count/type supports only 'atom' (gravel has no bonds), got '%.64s'",
                 argv[0]);
    if (g->atoms.ntypes < 1)
        gr_error(g, "compute count/type needs atom types (create the box first)");
    c->vector_flag = 1;
    c->size_vector = g->atoms.ntypes;
    c->extvector = 1;
}

static void count_type_vector(struct gravel *g, struct compute *c)
{
    const struct atoms *a = &g->atoms;
    int nt = c->size_vector;
    for (int t = 0; t < nt; t++)
        c->vector[t] = 0.0;
    for (int i = 0; i < a->n; i++)
        if ((a->mask[i] & c->groupbit) && a->type[i] >= 1 && a->type[i] <= nt)
            c->vector[a->type[i] - 1] += 1.0;
}

const struct compute_style compute_style_count_type = {
    .name = "count/type",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = count_type_create,
    .vector = count_type_vector,
};
