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

/* The chunk of each atom (0-based; < 0: none or outside the group), each
 * chunk's centre-of-mass velocity (vcm, 3 per chunk) and mass; returns
 * nchunk. */
static int tc_chunks(struct gravel *g, struct compute *c, int **idx, double **vcm,
                     double **mass)
{
    struct temp_chunk *t = c->data;
    const struct atoms *a = &g->atoms;
    struct compute *ca = chunk_atom_get(g, t->chunk, WHO);
    const struct chunk_grid *grid = chunk_atom_setup(g, ca);
    const int *ichunk = chunk_atom_assign(g, ca);
    const int n = grid->nchunk > 0 ? grid->nchunk : 0;
    int *k = gr_malloc(g, ((size_t)a->n + 1) * sizeof *k);
    double *v = gr_calloc(g, 3 * (size_t)(n + 1), sizeof *v), *m = gr_calloc(g, (size_t)n + 1,
                                                                              sizeof *m);
    const int *order = atoms_tag_order(g);
    for (int q = 0; q < a->n; q++) {
        const int i = order[q];
        k[i] = (a->mask[i] & c->groupbit) ? ichunk[i] - 1 : -1;
        if (k[i] < 0)
            continue;
        for (int d = 0; d < 3; d++)
            v[3 * k[i] + d] += a->v[3 * i + d] * a->rmass[i];
        m[k[i]] += a->rmass[i];
    }
    for (int j = 0; j < n; j++)
        for (int d = 0; d < 3; d++)
            v[3 * j + d] = m[j] > 0.0 ? v[3 * j + d] / m[j] : 0.0;
    *idx = k;
    *vcm = v;
    *mass = m;
    return n;
}

/* v' of atom i: its velocity, less its chunk's vcm when sub */
static void thermal_v(const struct atoms *a, int i, const double *vcm, int k, int sub,
                      double out[3])
{
    for (int d = 0; d < 3; d++)
        out[d] = a->v[3 * i + d] - (sub ? vcm[3 * k + d] : 0.0);
}

static double tc_scalar(struct gravel *g, struct compute *c)
{
    struct temp_chunk *t = c->data;
    const struct atoms *a = &g->atoms;
    int *k;
    double *vcm, *mass;
    const int n = tc_chunks(g, c, &k, &vcm, &mass);
    double sum = 0.0, count = 0.0;
    const int *order = atoms_tag_order(g);
    for (int q = 0; q < a->n; q++) {
        const int i = order[q];
        if (k[i] < 0)
            continue;
        double u[3];
        thermal_v(a, i, vcm, k[i], t->com, u);
        sum += (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * a->rmass[i];
        count += 1.0;
    }
    free(k);
    free(vcm);
    free(mass);
    const double dof = n * t->cdof + t->adof * count;
    if (dof < 0.0 && count > 0.0)
        gr_error(g, WHO " %s: temperature degrees of freedom < 0", c->id);
    return dof > 0.0 ? 1.0 / (dof * temp_boltz(g)) * sum : 0.0; /* LAMMPS's tfactor */
}

static void tc_vector(struct gravel *g, struct compute *c)
{
    struct temp_chunk *t = c->data;
    const struct atoms *a = &g->atoms;
    int *k;
    double *vcm, *mass;
    tc_chunks(g, c, &k, &vcm, &mass);
    double s[6] = {0};
    const int *order = atoms_tag_order(g);
    for (int q = 0; q < a->n; q++) {
        const int i = order[q];
        if (k[i] < 0)
            continue;
        double u[3];
        const double m = a->rmass[i];
        thermal_v(a, i, vcm, k[i], t->com, u);
        s[0] += m * u[0] * u[0], s[1] += m * u[1] * u[1], s[2] += m * u[2] * u[2];
        s[3] += m * u[0] * u[1], s[4] += m * u[0] * u[2], s[5] += m * u[1] * u[2];
    }
    free(k);
    free(vcm);
    free(mass);
    if (!c->vector)
        c->vector = gr_calloc(g, 6, sizeof *c->vector);
    memcpy(c->vector, s, sizeof s);
}

static void tc_array(struct gravel *g, struct compute *c)
{
    struct temp_chunk *t = c->data;
    const struct atoms *a = &g->atoms;
    int *k;
    double *vcm, *mass;
    const int n = tc_chunks(g, c, &k, &vcm, &mass);
    const size_t rows = (size_t)(n > 0 ? n : 1);
    double *sum = gr_calloc(g, rows * 3, sizeof *sum); /* temp, kecom, internal sums */
    int *count = gr_calloc(g, rows, sizeof *count);
    const int *order = atoms_tag_order(g);
    for (int q = 0; q < a->n; q++) {
        const int i = order[q];
        if (k[i] < 0)
            continue;
        const int j = k[i];
        const double m = a->rmass[i], *w = vcm + 3 * j;
        double u[3], r[3];
        thermal_v(a, i, vcm, j, t->com, u);
        thermal_v(a, i, vcm, j, 1, r);
        sum[3 * j] += (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * m;
        sum[3 * j + 1] += (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * m;
        sum[3 * j + 2] += (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) * m;
        count[j]++;
    }
    double *out = compute_array_rows(g, c, n);
    for (int j = 0; j < n; j++)
        for (int v = 0; v < t->nvalues; v++) {
            double x;
            if (t->which[v] == TC_TEMP) {
                const double dof = t->cdof + t->adof * count[j];
                x = dof > 0.0 ? 1.0 / (dof * temp_boltz(g)) * sum[3 * j] : 0.0;
            } else {
                x = 0.5 * sum[3 * j + (t->which[v] == TC_KECOM ? 1 : 2)];
            }
            out[(size_t)j * t->nvalues + v] = x;
        }
    free(sum);
    free(count);
    free(k);
    free(vcm);
    free(mass);
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
