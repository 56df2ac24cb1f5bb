/* compute_property_chunk.c - `compute ID group property/chunk chunkID input
 * ...`: per-chunk properties of a compute chunk/atom's bins, as LAMMPS's
 * compute property/chunk. Inputs:
 *   count          atoms of the group in the chunk
 *   id             the chunk's original ID: refused, as LAMMPS refuses it
 *                  without chunk/atom's `compress yes` (gravel's is always no)
 *   coord1 coord2 coord3   the bin centre along the 1st, 2nd, 3rd binned
 *                  dimension (box units, or fractions of the box with units
 *                  reduced, as LAMMPS)
 * One input gives a global vector of nchunk values, several a global array
 * (one column each, in order). Intensive, except count (extensive, as
 * LAMMPS's). */
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "compute.h"
#include "compute_chunk_atom.h"
#include "error.h"

#define WHO "compute property/chunk"
#define PC_MAXIN 16

enum { P_COUNT, P_ID, P_COORD1, P_COORD2, P_COORD3 };

struct property_chunk {
    char chunk[GR_NAMELEN];
    int n, in[PC_MAXIN];
};

static void pc_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, WHO " expects chunkID input ..., got %d arguments", argc);
    if (argc - 1 > PC_MAXIN)
        gr_error(g, WHO ": at most %d inputs, got %d", PC_MAXIN, argc - 1);
    struct property_chunk *pc = gr_calloc(g, 1, sizeof *pc);
    c->data = pc;
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, WHO ": chunk ID '%.64s...' is too long", argv[0]);
    strcpy(pc->chunk, argv[0]);
    const int ncoord = chunk_atom_ncoord(chunk_atom_get(g, pc->chunk, WHO));
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        int p;
        if (!strcmp(s, "count"))
            p = P_COUNT;
        else if (!strcmp(s, "id")) {
            if (!chunk_atom_compressed(chunk_atom_get(g, pc->chunk, WHO)))
                gr_error(g, WHO ": id needs compute chunk/atom %s with compress yes (the "
                            "original IDs), as LAMMPS", pc->chunk);
            p = P_ID;
        }
        else if (!strcmp(s, "coord1") || !strcmp(s, "coord2") || !strcmp(s, "coord3"))
            p = P_COORD1 + (s[5] - '1');
        else
            gr_error(g, WHO ": invalid input '%.64s' (count, id, coord1, coord2, coord3)", s);
        if (p >= P_COORD1 && p - P_COORD1 >= ncoord)
            gr_error(g, WHO ": %s needs a chunk/atom compute binned in %d dimensions "
                        "(%s bins %d)", s, p - P_COORD1 + 1, pc->chunk, ncoord);
        pc->in[pc->n++] = p;
    }
    if (pc->n == 1) {
        c->vector_flag = 1;
        c->size_vector_variable = 1;
        c->extvector = pc->in[0] == P_COUNT;
    } else {
        c->array_flag = 1;
        c->size_array_cols = pc->n;
        c->extarray = 0;
    }
}

static void pc_init(struct gravel *g, struct compute *c)
{
    chunk_atom_get(g, ((struct property_chunk *)c->data)->chunk, WHO);
}

/* the nchunk x n values, row-major, into out */
static void pc_fill(struct gravel *g, struct compute *c, double **outp, int *rows)
{
    const struct property_chunk *pc = c->data;
    struct compute *ca = chunk_atom_get(g, pc->chunk, WHO);
    const struct chunk_grid *grid = chunk_atom_setup(g, ca);
    const int *ichunk = chunk_atom_assign(g, ca);
    const int nchunk = grid->nchunk;
    int *count = gr_calloc(g, (size_t)nchunk + 1, sizeof *count);
    const struct atoms *a = &g->atoms;
    for (int i = 0; i < a->n; i++)
        if ((a->mask[i] & c->groupbit) && ichunk[i] > 0)
            count[ichunk[i] - 1]++;
    double *out = gr_malloc(g, ((size_t)nchunk * pc->n + 1) * sizeof *out);
    for (int m = 0; m < nchunk; m++)
        for (int k = 0; k < pc->n; k++) {
            double v = 0;
            switch (pc->in[k]) {
            case P_COUNT: v = count[m]; break;
            case P_ID: v = grid->ids ? grid->ids[m] : m + 1; break;
            default: v = grid->coord[(size_t)m * grid->ncoord + (pc->in[k] - P_COORD1)]; break;
            }
            out[(size_t)m * pc->n + k] = v;
        }
    free(count);
    *outp = out;
    *rows = nchunk;
}

static void pc_array(struct gravel *g, struct compute *c)
{
    double *v;
    int rows;
    pc_fill(g, c, &v, &rows);
    double *out = compute_array_rows(g, c, rows);
    memcpy(out, v, (size_t)rows * c->size_array_cols * sizeof *out);
    free(v);
}

static void pc_vector(struct gravel *g, struct compute *c)
{
    double *v;
    int rows;
    pc_fill(g, c, &v, &rows);
    free(c->vector);
    c->vector = v;
    c->size_vector = rows;
}

const struct compute_style compute_style_property_chunk = {
    .name = "property/chunk",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = pc_create,
    .init = pc_init,
    .array = pc_array,
    .vector = pc_vector,
};
