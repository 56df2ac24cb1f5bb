/* compute_reduce_chunk.c - `compute ID group reduce/chunk chunkID mode input
 * ...`: per-atom values reduced over the atoms of each chunk of a compute
 * chunk/atom, as LAMMPS's compute reduce/chunk: mode sum, min or max;
 * inputs c_ID, c_ID[N] (a per-atom compute), f_ID, f_ID[N] (a fix's
 * per-atom output), v_name (an atom-style variable); wildcards expanded by
 * the caller's expansion of the command line. An atom counts when it is in
 * the group and in a chunk. One input: a global vector of nchunk values;
 * several: an array nchunk x inputs. A chunk without atoms keeps LAMMPS's
 * initial value: 0 (sum), 1e20 (min), -1e20 (max). Intensive, as LAMMPS's.
 * Sums in atom-ID order. */
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "compute.h"
#include "compute_chunk_atom.h"
#include "error.h"
#include "peratom_input.h"

#define WHO "compute reduce/chunk"
#define RC_BIG 1.0e20

enum { RC_SUM, RC_MIN, RC_MAX };

struct reduce_chunk {
    char chunk[GR_NAMELEN];
    int mode, n;
    struct peratom_input *in;
};

static void rc_destroy(struct compute *c)
{
    struct reduce_chunk *r = c->data;
    if (r)
        free(r->in);
    free(r);
    c->data = NULL;
}

static void rc_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, WHO " expects chunkID mode input ..., got %d arguments", argc);
    struct reduce_chunk *r = gr_calloc(g, 1, sizeof *r);
    c->data = r;
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, WHO ": chunk ID '%.64s...' is too long", argv[0]);
    strcpy(r->chunk, argv[0]);
    chunk_atom_get(g, r->chunk, WHO);
    if (!strcmp(argv[1], "sum"))
        r->mode = RC_SUM;
    else if (!strcmp(argv[1], "min"))
        r->mode = RC_MIN;
    else if (!strcmp(argv[1], "max"))
        r->mode = RC_MAX;
    else
        gr_error(g, WHO ": mode must be sum, min or max, got '%.64s'", argv[1]);
    r->n = argc - 2;
    r->in = gr_calloc(g, (size_t)r->n, sizeof *r->in);
    for (int k = 0; k < r->n; k++) {
        peratom_input_parse(g, argv[2 + k], PERATOM_XVF, &r->in[k],
                            "c_ID, c_ID[N], f_ID, f_ID[N], v_name", WHO);
        if (r->in[k].kind == 'a')
            gr_error(g, WHO ": input '%.64s' must be c_ID, c_ID[N], f_ID, f_ID[N] or v_name",
                     argv[2 + k]);
    }
    if (r->n == 1) {
        c->vector_flag = 1;
        c->size_vector_variable = 1;
        c->extvector = 0;
    } else {
        c->array_flag = 1;
        c->size_array_cols = r->n;
        c->extarray = 0;
    }
}

static void rc_init(struct gravel *g, struct compute *c)
{
    struct reduce_chunk *r = c->data;
    chunk_atom_get(g, r->chunk, WHO);
    for (int k = 0; k < r->n; k++)
        peratom_input_check(g, &r->in[k], WHO, c->id);
}

/* the nchunk x n values into a new array (*rows the chunks) */
static double *rc_eval(struct gravel *g, struct compute *c, int *rows)
{
    struct reduce_chunk *r = c->data;
    const struct atoms *a = &g->atoms;
    struct compute *ca = chunk_atom_get(g, r->chunk, WHO);
    const int nchunk = chunk_atom_setup(g, ca)->nchunk;
    const int *ichunk = chunk_atom_assign(g, ca);
    const double init = r->mode == RC_SUM ? 0.0 : r->mode == RC_MIN ? RC_BIG : -RC_BIG;
    double *out = gr_malloc(g, ((size_t)nchunk * r->n + 1) * sizeof *out);
    for (size_t q = 0; q < (size_t)nchunk * r->n; q++)
        out[q] = init;
    const int *order = atoms_tag_order(g);
    for (int k = 0; k < r->n; k++) {
        int stride;
        double *owned = NULL;
        const double *v = peratom_input_values(g, &r->in[k], &stride, &owned, WHO);
        for (int q = 0; q < a->n; q++) {
            const int i = order[q], m = ichunk[i] - 1;
            if (m < 0 || !(a->mask[i] & c->groupbit))
                continue;
            double *o = out + (size_t)m * r->n + k;
            const double x = v[(size_t)i * stride];
            if (r->mode == RC_SUM)
                *o += x;
            else if (r->mode == RC_MIN ? x < *o : x > *o)
                *o = x;
        }
        free(owned);
    }
    *rows = nchunk;
    return out;
}

static void rc_vector(struct gravel *g, struct compute *c)
{
    int rows;
    double *v = rc_eval(g, c, &rows);
    free(c->vector);
    c->vector = v;
    c->size_vector = rows;
}

static void rc_array(struct gravel *g, struct compute *c)
{
    int rows;
    double *v = rc_eval(g, c, &rows);
    memcpy(compute_array_rows(g, c, rows), v, (size_t)rows * c->size_array_cols * sizeof *v);
    free(v);
}

const struct compute_style compute_style_reduce_chunk = {
    .name = "reduce/chunk",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = rc_create,
    .init = rc_init,
    .vector = rc_vector,
    .array = rc_array,
    .destroy = rc_destroy,
};
