/* compute_msd_chunk.c - `compute ID group msd/chunk chunkID`: the squared
 * displacement of each chunk's centre of mass, as LAMMPS's compute
 * msd/chunk: a global array of nchunk rows x 4 columns, dx^2 dy^2 dz^2 and
 * their sum, intensive, where d is the chunk's centre of mass now (unwrapped
 * positions, the atoms in both the group and the chunk, chunk_mass_mean)
 * minus its centre of mass at the setup of the first run after the compute
 * was defined (LAMMPS's firstflag; on several ranks taken on every rank's
 * atoms gathered). The chunk count must stay what it was then ("nchunk is
 * not static" otherwise, as LAMMPS). The reference is not written to
 * restart files (LAMMPS keeps it in a fix STORE that is): a restarted run
 * takes a new one. */
#include <stdlib.h>
#include <string.h>

#include "compute.h"
#include "compute_chunk_atom.h"
#include "engine.h"
#include "error.h"
#include "par.h"

#define WHO "compute msd/chunk"

struct msd_chunk {
    char chunk[GR_NAMELEN];
    int nchunk;         /* the reference's chunk count (-1: no reference yet) */
    double *ref;        /* [nchunk][3] the reference centres of mass */
};

static void mc_destroy(struct compute *c)
{
    struct msd_chunk *m = c->data;
    if (m)
        free(m->ref);
    free(m);
    c->data = NULL;
}

static void mc_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, WHO " expects one argument, the chunk/atom compute ID, got %d", argc);
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, WHO ": chunk ID '%.64s...' is too long", argv[0]);
    chunk_atom_get(g, argv[0], WHO);
    struct msd_chunk *m = gr_calloc(g, 1, sizeof *m);
    c->data = m;
    snprintf(m->chunk, sizeof m->chunk, "%s", argv[0]);
    m->nchunk = -1;
    c->array_flag = 1;
    c->size_array_cols = 4;
    c->extarray = 0;
}

/* every chunk's centre of mass now into com[3 n] (malloc'd); returns n */
static int centres(struct gravel *g, struct compute *c, double **com)
{
    struct msd_chunk *m = c->data;
    struct compute *ca = chunk_atom_get(g, m->chunk, WHO);
    const int n = chunk_atom_setup(g, ca)->nchunk;
    const int *ichunk = chunk_atom_assign(g, ca);
    *com = gr_malloc(g, 3 * (size_t)n * sizeof **com + 1);
    chunk_mass_mean(g, c->groupbit, ichunk, n, NULL, *com, NULL);
    return n;
}

/* run setup: the first one takes the reference (collective on several ranks:
 * every rank initialises its computes here) */
static void mc_init(struct gravel *g, struct compute *c)
{
    struct msd_chunk *m = c->data;
    chunk_atom_get(g, m->chunk, WHO);
    if (m->nchunk >= 0)
        return;
    run_sync_host(g);
    const int gather = par_on(g) && !par_gathered(g);
    if (gather)
        par_gather_begin(g);
    m->nchunk = centres(g, c, &m->ref);
    if (gather)
        par_gather_end(g);
}

static void mc_array(struct gravel *g, struct compute *c)
{
    struct msd_chunk *m = c->data;
    double *com;
    const int n = centres(g, c, &com);
    if (m->nchunk < 0) { /* evaluated before any run: its own reference, as LAMMPS's
                            first call gives zeros */
        m->nchunk = n;
        m->ref = com;
        com = NULL;
    }
    if (n != m->nchunk) {
        free(com);
        gr_error(g, WHO " %s: nchunk is not static (%d chunks, %d when the reference was "
                    "taken)", c->id, n, m->nchunk);
    }
    double *out = compute_array_rows(g, c, n);
    for (int k = 0; k < n; k++) {
        double s = 0;
        for (int d = 0; d < 3; d++) {
            const double dx = com ? com[3 * k + d] - m->ref[3 * k + d] : 0.0;
            out[4 * k + d] = dx * dx;
            s += dx * dx;
        }
        out[4 * k + 3] = s;
    }
    free(com);
}

const struct compute_style compute_style_msd_chunk = {
    .name = "msd/chunk",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = mc_create,
    .init = mc_init,
    .array = mc_array,
    .destroy = mc_destroy,
};
