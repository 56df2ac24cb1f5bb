/* compute_com_chunk.c - the mass-weighted means of each chunk of a compute
 * chunk/atom, as LAMMPS's:
 *   compute ID group com/chunk chunkID   the centre of mass (unwrapped positions)
 *   compute ID group vcm/chunk chunkID   the centre-of-mass velocity
 * a global array of nchunk rows x 3 columns (x y z) over the atoms in both
 * the group and the chunk, 0 0 0 for a chunk without mass. Intensive. Read
 * as c_ID[I][J] in thermo output and variables (I the chunk, J the
 * coordinate). */
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "compute.h"
#include "compute_chunk_atom.h"
#include "domain.h"
#include "error.h"

static const char *who(const struct compute *c)
{
    return c->style->name[0] == 'c' ? "compute com/chunk" : "compute vcm/chunk";
}

static void cc_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, "%s expects one argument, the chunk/atom compute ID, got %d", who(c), argc);
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, "%s: chunk ID '%.64s...' is too long", who(c), argv[0]);
    chunk_atom_get(g, argv[0], who(c));
    c->data = gr_strdup(g, argv[0]);
    c->array_flag = 1;
    c->size_array_cols = 3;
    c->extarray = 0;
}

static void cc_init(struct gravel *g, struct compute *c)
{
    chunk_atom_get(g, c->data, who(c));
}

static void cc_array(struct gravel *g, struct compute *c)
{
    const struct atoms *a = &g->atoms;
    struct compute *ca = chunk_atom_get(g, c->data, who(c));
    const int vel = c->style->name[0] == 'v';
    const struct chunk_grid *grid = chunk_atom_setup(g, ca);
    const int *ichunk = chunk_atom_assign(g, ca);
    int n = grid->nchunk;
    chunk_mass_mean(g, c->groupbit, ichunk, n, vel ? a->v : NULL, compute_array_rows(g, c, n),
                    NULL);
}

const struct compute_style compute_style_com_chunk = {
    .name = "com/chunk",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = cc_create,
    .init = cc_init,
    .array = cc_array,
};

const struct compute_style compute_style_vcm_chunk = {
    .name = "vcm/chunk",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = cc_create,
    .init = cc_init,
    .array = cc_array,
};
