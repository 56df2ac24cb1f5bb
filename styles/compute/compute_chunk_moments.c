/* compute_chunk_moments.c - the moments of each chunk of a compute
 * chunk/atom about its centre of mass, as LAMMPS's (atoms in both the
 * group and a chunk; positions unwrapped; d = x - xcm of the chunk):
 *   gyration/chunk chunkID [tensor]  sqrt(sum m |d|^2 / M) (a vector, one
 *                                    value per chunk), or with tensor the
 *                                    rows sum m d_a d_b / M (xx yy zz xy xz yz)
 *   inertia/chunk chunkID            sum m (|d|^2 - d_a d_b) as rows
 *                                    ixx iyy izz ixy iyz ixz (ixy = -sum m dx dy)
 *   angmom/chunk chunkID             sum m d x v  (x y z rows)
 *   torque/chunk chunkID             sum d x f
 *   omega/chunk chunkID              I^-1 L (omega_of: a singular I too)
 * The atoms are points (a sphere's own inertia and spin are not added, as
 * LAMMPS 2021's; today's LAMMPS adds a finite-size particle's spin to
 * angmom/chunk). Intensive, as LAMMPS's. Sums in atom-ID order; a chunk
 * without mass gets zeros. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "compute.h"
#include "compute_chunk_atom.h"
#include "domain.h"
#include "error.h"
#include "rigid_math.h"

enum moment { M_GYRATION, M_INERTIA, M_ANGMOM, M_TORQUE, M_OMEGA };

struct moments {
    char chunk[GR_NAMELEN];
    enum moment kind;
    int tensor;                 /* gyration/chunk tensor */
};

static enum moment kind_of(const struct compute *c)
{
    const char *n = c->style->name;
    return !strcmp(n, "gyration/chunk") ? M_GYRATION
         : !strcmp(n, "inertia/chunk")  ? M_INERTIA
         : !strcmp(n, "angmom/chunk")   ? M_ANGMOM
         : !strcmp(n, "torque/chunk")   ? M_TORQUE
                                        : M_OMEGA;
}

static void cm_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    const char *who = c->style->name;
    struct moments *m = gr_calloc(g, 1, sizeof *m);
    c->data = m;
    m->kind = kind_of(c);
    const int max = m->kind == M_GYRATION ? 2 : 1;
    if (argc < 1 || argc > max)
        gr_error(g, "compute %s expects the chunk/atom compute ID%s, got %d arguments", who,
                 m->kind == M_GYRATION ? " [tensor]" : "", argc);
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, "compute %s: chunk ID '%.64s...' is too long", who, argv[0]);
    strcpy(m->chunk, argv[0]);
    if (argc == 2) {
        if (strcmp(argv[1], "tensor"))
            gr_error(g, "compute %s: unknown keyword '%.64s' (tensor)", who, argv[1]);
        m->tensor = 1;
    }
    chunk_atom_get(g, m->chunk, who);
    if (m->kind == M_GYRATION && !m->tensor) {
        c->vector_flag = 1;
        c->size_vector_variable = 1;
        c->extvector = 0;
    } else {
        c->array_flag = 1;
        c->size_array_cols = m->kind == M_INERTIA || m->tensor ? 6 : 3;
        c->extarray = 0;
    }
}

static void cm_init(struct gravel *g, struct compute *c)
{
    chunk_atom_get(g, ((struct moments *)c->data)->chunk, c->style->name);
}

/* LAMMPS's omega/chunk: L = I w, by the adjugate when det I > 1e-6; else (a
 * chunk of two atoms, a line of atoms) in I's eigenbasis, the principal
 * moments below 1e-6 of the largest taken as 0 (no rotation about that
 * axis). As LAMMPS's, a chunk whose inertia is round-off (one atom) gets
 * round-off over round-off. */
static void omega_of(struct gravel *g, const double in[6], const double L[3], double w[3])
{
    const double I[3][3] = {{in[0], in[3], in[5]}, {in[3], in[1], in[4]}, {in[5], in[4], in[2]}};
    const double det = in[0] * (in[1] * in[2] - in[4] * in[4]) +
                       in[3] * (in[4] * in[5] - in[3] * in[2]) +
                       in[5] * (in[3] * in[4] - in[1] * in[5]);
    if (det > 1.0e-6) {
        double inv[3][3];
        inv[0][0] = I[1][1] * I[2][2] - I[1][2] * I[2][1];
        inv[0][1] = -(I[0][1] * I[2][2] - I[0][2] * I[2][1]);
        inv[0][2] = I[0][1] * I[1][2] - I[0][2] * I[1][1];
        inv[1][0] = -(I[1][0] * I[2][2] - I[1][2] * I[2][0]);
        inv[1][1] = I[0][0] * I[2][2] - I[0][2] * I[2][0];
        inv[1][2] = -(I[0][0] * I[1][2] - I[0][2] * I[1][0]);
        inv[2][0] = I[1][0] * I[2][1] - I[1][1] * I[2][0];
        inv[2][1] = -(I[0][0] * I[2][1] - I[0][1] * I[2][0]);
        inv[2][2] = I[0][0] * I[1][1] - I[0][1] * I[1][0];
        const double invdet = 1.0 / det;
        for (int i = 0; i < 3; i++)
            w[i] = inv[i][0] * invdet * L[0] + inv[i][1] * invdet * L[1] +
                   inv[i][2] * invdet * L[2];
        return;
    }
    double ev[3], e[3][3];
    if (rm_jacobi3(I, ev, e))
        gr_error(g, "compute omega/chunk: the principal axes of a chunk did not converge");
    const double max = fmax(fmax(ev[0], ev[1]), ev[2]);
    double wb[3];
    for (int k = 0; k < 3; k++) {
        const double lk = L[0] * e[0][k] + L[1] * e[1][k] + L[2] * e[2][k];
        wb[k] = ev[k] < 1.0e-6 * max || ev[k] == 0.0 ? 0.0 : lk / ev[k];
    }
    for (int i = 0; i < 3; i++)
        w[i] = wb[0] * e[i][0] + wb[1] * e[i][1] + wb[2] * e[i][2];
}

/* Each chunk's row (cols values) into out[nchunk x cols]; returns nchunk. */
static int cm_eval(struct gravel *g, struct compute *c, double **out, int *cols)
{
    struct moments *m = c->data;
    const struct atoms *a = &g->atoms;
    struct compute *ca = chunk_atom_get(g, m->chunk, c->style->name);
    const struct chunk_grid *grid = chunk_atom_setup(g, ca);
    const int *ichunk = chunk_atom_assign(g, ca);
    const int n = grid->nchunk > 0 ? grid->nchunk : 0;
    const size_t rows = (size_t)(n > 0 ? n : 1);
    double *mass = gr_calloc(g, rows, sizeof *mass), *com = gr_calloc(g, 3 * rows, sizeof *com);
    double *in = gr_calloc(g, 6 * rows, sizeof *in), *L = gr_calloc(g, 3 * rows, sizeof *L);
    double *u = gr_malloc(g, 3 * ((size_t)a->n + 1) * sizeof *u);
    const int *order = atoms_tag_order(g); /* sums that depend on the atoms only */
    for (int i = 0; i < a->n; i++)
        domain_unmap(g, a->x + 3 * i, a->image + 3 * i, u + 3 * i);
    chunk_mass_mean(g, c->groupbit, ichunk, n, u, com, mass);
    for (int q = 0; q < a->n; q++) {
        const int i = order[q], k = ichunk[i] - 1;
        if (!(a->mask[i] & c->groupbit) || k < 0)
            continue;
        const double mi = a->rmass[i], *v = a->v + 3 * i, *f = a->f + 3 * i;
        const double dx = u[3 * i] - com[3 * k], dy = u[3 * i + 1] - com[3 * k + 1],
                     dz = u[3 * i + 2] - com[3 * k + 2];
        double *r = in + 6 * k, *l = L + 3 * k;
        if (m->kind == M_GYRATION) {
            if (m->tensor) {
                r[0] += mi * dx * dx, r[1] += mi * dy * dy, r[2] += mi * dz * dz;
                r[3] += mi * dx * dy, r[4] += mi * dx * dz, r[5] += mi * dy * dz;
            } else {
                r[0] += (dx * dx + dy * dy + dz * dz) * mi;
            }
        }
        if (m->kind == M_INERTIA || m->kind == M_OMEGA) {
            r[0] += mi * (dy * dy + dz * dz), r[1] += mi * (dx * dx + dz * dz);
            r[2] += mi * (dx * dx + dy * dy);
            r[3] -= mi * dx * dy, r[4] -= mi * dy * dz, r[5] -= mi * dx * dz;
        }
        if (m->kind == M_ANGMOM || m->kind == M_OMEGA) {
            l[0] += mi * (dy * v[2] - dz * v[1]), l[1] += mi * (dz * v[0] - dx * v[2]);
            l[2] += mi * (dx * v[1] - dy * v[0]);
        }
        if (m->kind == M_TORQUE) {
            l[0] += dy * f[2] - dz * f[1], l[1] += dz * f[0] - dx * f[2];
            l[2] += dx * f[1] - dy * f[0];
        }
    }
    *cols = m->kind == M_GYRATION ? (m->tensor ? 6 : 1) : m->kind == M_INERTIA ? 6 : 3;
    double *o = gr_calloc(g, rows * (size_t)*cols, sizeof *o);
    for (int k = 0; k < n; k++) {
        double *row = o + (size_t)k * *cols;
        if (m->kind == M_GYRATION)
            for (int j = 0; j < *cols; j++)
                row[j] = mass[k] > 0 ? (m->tensor ? in[6 * k + j] / mass[k]
                                                  : sqrt(in[6 * k] / mass[k]))
                                     : 0.0;
        else if (m->kind == M_INERTIA)
            memcpy(row, in + 6 * k, 6 * sizeof *row);
        else if (m->kind == M_OMEGA)
            omega_of(g, in + 6 * k, L + 3 * k, row);
        else
            memcpy(row, L + 3 * k, 3 * sizeof *row);
    }
    free(mass);
    free(com);
    free(in);
    free(L);
    free(u);
    *out = o;
    return n;
}

static void cm_vector(struct gravel *g, struct compute *c)
{
    int cols;
    double *v;
    const int n = cm_eval(g, c, &v, &cols);
    free(c->vector);
    c->vector = v;
    c->size_vector = n;
}

static void cm_array(struct gravel *g, struct compute *c)
{
    int cols;
    double *v;
    const int n = cm_eval(g, c, &v, &cols);
    memcpy(compute_array_rows(g, c, n), v, (size_t)n * cols * sizeof *v);
    free(v);
}

#define CHUNK_MOMENT(ident, nm)                                                                \
    const struct compute_style compute_style_##ident = {                                       \
        .name = nm,                                                                            \
        .ranks = COMPUTE_RANKS_GATHER,                                                         \
        .create = cm_create,                                                                   \
        .init = cm_init,                                                                       \
        .vector = cm_vector,                                                                   \
        .array = cm_array,                                                                     \
    }

CHUNK_MOMENT(gyration_chunk, "gyration/chunk");
CHUNK_MOMENT(inertia_chunk, "inertia/chunk");
CHUNK_MOMENT(angmom_chunk, "angmom/chunk");
CHUNK_MOMENT(torque_chunk, "torque/chunk");
CHUNK_MOMENT(omega_chunk, "omega/chunk");
