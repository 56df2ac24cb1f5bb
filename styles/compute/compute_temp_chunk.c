/* compute_temp_chunk.c - `compute ID group temp/chunk chunkID [temp]
 * [kecom] [internal] [com yes|no] [adof A] [cdof C]`: LAMMPS's compute
 * temp/chunk, the temperature of the atoms that are in the group and in a
 * chunk of a compute chunk/atom:
 *   scalar  sum m |v'|^2 / (dof kB), dof = nchunk C + A count (intensive)
 *   vector  the kinetic tensor sum m v'_a v'_b: xx yy zz xy xz yz (extensive)
 *   array   per chunk, one column per value named: temp (sum m |v'|^2 /
 *           ((C + A n_chunk) kB)), kecom (1/2 M |vcm|^2), internal
 *           (1/2 sum m |v - vcm|^2) (intensive)
 * v' = v - vcm of the atom's chunk with com yes, else v (A defaults to the
 * dimension, C to 0). A granular temperature per layer, with com yes the
 * fluctuation about each layer's mean flow. Sums in atom-ID order. Not yet:
 * `bias`, and use as a thermostat's or thermo's temperature (it is not a
 * temperature compute here). */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "compute.h"
#include "compute_chunk_atom.h"
#include "error.h"
#include "temperature.h"

#define WHO "compute temp/chunk"

enum tc_value { TC_TEMP, TC_KECOM, TC_INTERNAL };

struct temp_chunk {
    char chunk[GR_NAMELEN];
    int com;
    double adof, cdof;
    int nvalues;
    enum tc_value *which;
};

static void tc_destroy(struct compute *c)
{
    struct temp_chunk *t = c->data;
    if (t)
        free(t->which);
    free(t);
}

static void tc_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, WHO " expects the chunk/atom compute ID [values] [keywords]");
    struct temp_chunk *t = gr_calloc(g, 1, sizeof *t);
    c->data = t;
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, WHO ": chunk ID '%.64s...' is too long", argv[0]);
    strcpy(t->chunk, argv[0]);
    t->which = gr_calloc(g, (size_t)argc, sizeof *t->which);
    int i = 1;
    for (; i < argc; i++) {
        if (!strcmp(argv[i], "temp"))
            t->which[t->nvalues++] = TC_TEMP;
        else if (!strcmp(argv[i], "kecom"))
            t->which[t->nvalues++] = TC_KECOM;
        else if (!strcmp(argv[i], "internal"))
            t->which[t->nvalues++] = TC_INTERNAL;
        else
            break;
    }
    t->adof = g->dom.dimension;
    for (; i < argc; i += 2) {
        arg_need(g, argc, i, 1, argv[i]);
        if (!strcmp(argv[i], "com"))
            t->com = arg_yesno(g, argv[i + 1], "com");
        else if (!strcmp(argv[i], "adof"))
            t->adof = arg_double(g, argv[i + 1], "adof");
        else if (!strcmp(argv[i], "cdof"))
            t->cdof = arg_double(g, argv[i + 1], "cdof");
        else if (!strcmp(argv[i], "bias"))
            gr_error(g, WHO ": keyword 'bias' is not supported yet (com yes removes each "
                        "chunk's mean velocity)");
        else
            gr_error(g, WHO ": unknown keyword '%.64s' (temp, kecom, internal, com, adof, cdof)",
                     argv[i]);
    }
    chunk_atom_get(g, t->chunk, WHO);
    c->scalar_flag = c->vector_flag = 1;
    c->size_vector = 6;
    c->extscalar = 0;
    c->extvector = 1;
    if (t->nvalues) {
        c->array_flag = 1;
        c->size_array_cols = t->nvalues;
        c->extarray = 0;
    }
}

static void tc_init(struct gravel *g, struct compute *c)
{
    chunk_atom_get(g, ((struct temp_chunk *)c->data)->chunk, WHO);
}

/* One pass over the atoms in the group and a chunk, in atom-ID order: the
 * sums every output is made of. */
struct tc_sums {
    int nchunk;
    double t, count, tensor[6]; /* whole: sum m |v'|^2, atoms, sum m v'_a v'_b */
    double *chunk;              /* per chunk: sum m |v'|^2, sum m |vcm|^2, sum m |v - vcm|^2 */
    int *n;                     /* per chunk: atoms */
};

static void tc_sums_free(struct tc_sums *s)
{
    free(s->chunk);
    free(s->n);
}

static void tc_sum(struct gravel *g, struct compute *c, struct tc_sums *s)
{
    struct temp_chunk *t = c->data;
    const struct atoms *a = &g->atoms;
    struct compute *ca = chunk_atom_get(g, t->chunk, WHO);
    const struct chunk_grid *grid = chunk_atom_setup(g, ca);
    const int *ichunk = chunk_atom_assign(g, ca);
    const int n = grid->nchunk > 0 ? grid->nchunk : 0;
    const size_t rows = (size_t)n + 1;
    double *vcm = gr_calloc(g, 3 * rows, sizeof *vcm);
    memset(s, 0, sizeof *s);
    s->nchunk = n;
    s->chunk = gr_calloc(g, 3 * rows, sizeof *s->chunk);
    s->n = gr_calloc(g, rows, sizeof *s->n);
    const int *order = atoms_tag_order(g);
    chunk_mass_mean(g, c->groupbit, ichunk, n, a->v, vcm, NULL);
    for (int q = 0; q < a->n; q++) { /* the sums, v' = v - vcm with com yes */
        const int i = order[q], k = (a->mask[i] & c->groupbit) ? ichunk[i] - 1 : -1;
        if (k < 0)
            continue;
        const double m = a->rmass[i], *v = a->v + 3 * i, *w = vcm + 3 * k;
        double r[3], u[3];
        for (int d = 0; d < 3; d++) {
            r[d] = v[d] - w[d];
            u[d] = t->com ? r[d] : v[d];
        }
        const double uu = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * m;
        s->t += uu;
        s->count += 1.0;
        double *e = s->tensor;
        e[0] += m * u[0] * u[0], e[1] += m * u[1] * u[1], e[2] += m * u[2] * u[2];
        e[3] += m * u[0] * u[1], e[4] += m * u[0] * u[2], e[5] += m * u[1] * u[2];
        s->chunk[3 * k] += uu;
        s->chunk[3 * k + 1] += (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * m;
        s->chunk[3 * k + 2] += (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) * m;
        s->n[k]++;
    }
    free(vcm);
}

static double tc_scalar(struct gravel *g, struct compute *c)
{
    struct temp_chunk *t = c->data;
    struct tc_sums s;
    tc_sum(g, c, &s);
    const double dof = s.nchunk * t->cdof + t->adof * s.count, sum = s.t, count = s.count;
    tc_sums_free(&s);
    if (dof < 0.0 && count > 0.0)
        gr_error(g, WHO " %s: temperature degrees of freedom < 0", c->id);
    return dof > 0.0 ? 1.0 / (dof * temp_boltz(g)) * sum : 0.0; /* LAMMPS's tfactor */
}

static void tc_vector(struct gravel *g, struct compute *c)
{
    struct tc_sums s;
    tc_sum(g, c, &s);
    if (!c->vector)
        c->vector = gr_calloc(g, 6, sizeof *c->vector);
    memcpy(c->vector, s.tensor, sizeof s.tensor);
    tc_sums_free(&s);
}

static void tc_array(struct gravel *g, struct compute *c)
{
    struct temp_chunk *t = c->data;
    struct tc_sums s;
    tc_sum(g, c, &s);
    double *out = compute_array_rows(g, c, s.nchunk);
    for (int j = 0; j < s.nchunk; j++)
        for (int v = 0; v < t->nvalues; v++) {
            double x;
            if (t->which[v] == TC_TEMP) {
                const double dof = t->cdof + t->adof * s.n[j];
                x = dof > 0.0 ? 1.0 / (dof * temp_boltz(g)) * s.chunk[3 * j] : 0.0;
            } else {
                x = 0.5 * s.chunk[3 * j + (t->which[v] == TC_KECOM ? 1 : 2)];
            }
            out[(size_t)j * t->nvalues + v] = x;
        }
    tc_sums_free(&s);
}

const struct compute_style compute_style_temp_chunk = {
    .name = "temp/chunk",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = tc_create,
    .init = tc_init,
    .scalar = tc_scalar,
    .vector = tc_vector,
    .array = tc_array,
    .destroy = tc_destroy,
};
