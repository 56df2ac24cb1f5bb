/* fix_mesh_surface_stress.c - LIGGGHTS's `fix ID group mesh/surface/stress
 * file F type T [mesh/surface keywords] [stress on|off] [wear finnie|off]`:
 * a mesh/surface wall that also sums, per triangle and step, the force of
 * the particles on it (normal and shear stress) and accumulates Finnie's
 * wear (LIGGGHTS's mesh_module_stress.cpp).
 *
 * The wall kernel writes, per atom, a record of each contact with this mesh
 * (kernels/wall_layout.h MESH_SREC_*); at the end of the step the records
 * of every rank's atoms are summed in atom-tag order (so any number of MPI
 * ranks gives one process's bits):
 *   f_t      = sum of the contact forces on triangle t (this step only)
 *   sigma_n  = |f_t . n_t| / A_t,  sigma_t = |f_t - (f_t . n_t) n_t| / A_t
 *   wear_t  += sum over contacts approaching the surface (c . v_rel >= 0,
 *              c from the centre to the contact point, |v_rel| >= 1e-7) of
 *              E 2 k |v_rel| |F| dt / A_t, with sin g = |v_rel . n| / |v_rel|,
 *              cos g = |v_rel x n| / |v_rel| and E = cos^2 g / 3 (0.33333 as
 *              LIGGGHTS) when cos g < 1e-4 or 3 sin g > cos g, else
 *              sin 2g - 3 sin^2 g; k = k_finnie (mesh type, atom type) from
 *              fix property/global k_finnie peratomtypepair.
 * The global vector is mesh/surface's 1-6 (force and torque on the mesh)
 * and, as LIGGGHTS, 7-9 the reference point. dump mesh/gran/VTK writes
 * sigma_n, sigma_t and wear. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "fix_mesh_surface_stress.h"
#include "fix_property_global.h"
#include "comm.h"
#include "par.h"
#include "par_sum.h"

cl_mem mesh_stress_records(struct gravel *g, struct mesh_stress *st, int n)
{
    if (!st)
        return NULL;
    if (!st->rec || st->cap < (size_t)n) {
        if (st->rec)
            clReleaseMemObject(st->rec);
        st->rec = NULL;
        st->cap = (size_t)n + 64;
        st->rec = eng_alloc(g, st->cap * MESH_SLOTS * MESH_SREC_W * eng_get(g)->rsz,
                            "mesh stress records");
    }
    return st->rec;
}

void mesh_stress_free(struct mesh_stress *st)
{
    if (!st)
        return;
    if (st->rec)
        clReleaseMemObject(st->rec);
    free(st->f);
    free(st->sigma_n);
    free(st->sigma_t);
    free(st->wear);
    free(st->area);
    free(st->kf);
    free(st);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    int stress = 1, wear = 0, n = 0;
    char *rest[256]; /* the mesh/surface arguments */
    if (argc >= 256)
        gr_error(g, "fix mesh/surface/stress: too many arguments (%d)", argc);
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "stress") || !strcmp(argv[i], "wear")) {
            if (i + 1 >= argc)
                gr_error(g, "fix mesh/surface/stress: '%s' needs a value", argv[i]);
            const char *v = argv[++i];
            int on = !strcmp(argv[i - 1], "stress") ? !strcmp(v, "on") : !strcmp(v, "finnie");
            int off = !strcmp(v, "off");
            if (!on && !off) {
                int is_stress = !strcmp(argv[i - 1], "stress");
                gr_error(g, "fix mesh/surface/stress: expecting %s as %s argument, got '%.32s'",
                         is_stress ? "'on' or 'off'" : "'finnie' or 'off'",
                         is_stress ? "stress" : "wear", v);
            }
            if (!strcmp(argv[i - 1], "stress"))
                stress = on;
            else
                wear = on;
        } else {
            rest[n++] = argv[i];
        }
    }
    rest[n] = NULL;
    mesh_surface_create(g, f, n, rest);
    struct mesh_surface *ms = f->data;
    struct mesh_stress *st = gr_calloc(g, 1, sizeof *st);
    ms->stress = st;
    st->do_stress = stress;
    st->do_wear = wear;
    int nt = ms->m.ntri;
    st->f = gr_calloc(g, 3 * (size_t)nt, sizeof(double));
    st->sigma_n = gr_calloc(g, (size_t)nt, sizeof(double));
    st->sigma_t = gr_calloc(g, (size_t)nt, sizeof(double));
    st->wear = gr_calloc(g, (size_t)nt, sizeof(double));
    st->area = gr_calloc(g, (size_t)nt, sizeof(double));
    for (int t = 0; t < nt; t++) {
        double n[3];
        st->area[t] = mesh_surface_tri_normal(&ms->m, t, n);
    }
    st->step = -1;
    f->hooks = stress || wear ? HOOK_END_OF_STEP : 0;
}

static void init(struct gravel *g, struct fix *f)
{
    struct mesh_surface *ms = f->data;
    struct mesh_stress *st = ms->stress;
    int nt = g->atoms.ntypes;
    free(st->kf);
    st->kf = NULL;
    st->nt = nt;
    if (!st->do_wear)
        return;
    st->kf = gr_malloc(g, (size_t)(nt > 0 ? nt : 1) * sizeof(double));
    char who[GR_NAMELEN + 40];
    snprintf(who, sizeof who, "fix %s mesh/surface/stress wear finnie", f->id);
    for (int t = 1; t <= nt; t++)
        st->kf[t - 1] = fpg_pair(g, "k_finnie", nt, ms->type, t, who);
}

/* Finnie's angle factor E of a relative velocity v (|v| = vm) on a surface
 * of unit normal n (LIGGGHTS's operation order). */
static double finnie_angle(const double v[3], double vm, const double n[3])
{
    double cx = v[1] * n[2] - v[2] * n[1], cy = v[2] * n[0] - v[0] * n[2],
           cz = v[0] * n[1] - v[1] * n[0];
    double sin_g = fabs(v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / vm;
    double cos_g = fabs(sqrt(cx * cx + cy * cy + cz * cz)) / vm;
    if (cos_g > 1.)
        cos_g = 1.;
    if (sin_g > 1.)
        sin_g = 1.;
    if (cos_g < 0.0001 || 3. * sin_g > cos_g)
        return 0.33333 * cos_g * cos_g;
    return 2. * sin_g * cos_g - 3. * sin_g * sin_g;
}

/* Row of an atom's records for the sums: tag, type, its MESH_SLOTS records */
#define ROW_W (2 + MESH_SLOTS * MESH_SREC_W)

static int cmp_row(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The rows of the atoms of the group with a contact on the mesh this step,
 * every rank's (par_gather_rows), in ascending tag order; *nrows set. */
static double *contact_rows(struct gravel *g, struct fix *f, struct mesh_stress *st, int *nrows)
{
    struct dev_atoms *a = eng_atoms(g);
    int n = a->n;
    size_t w = MESH_SLOTS * MESH_SREC_W;
    double *rec = gr_malloc(g, (size_t)(n ? n : 1) * w * sizeof(double));
    int64_t *tag = gr_malloc(g, (size_t)(n ? n : 1) * sizeof(int64_t));
    unsigned *mask = gr_malloc(g, (size_t)(n ? n : 1) * sizeof(unsigned));
    int *type = gr_malloc(g, (size_t)(n ? n : 1) * sizeof(int));
    eng_read_reals(g, st->rec, (size_t)n * w, rec);
    eng_read(g, a->tag, 0, (size_t)n * sizeof(int64_t), tag);
    eng_read(g, a->mask, 0, (size_t)n * sizeof(unsigned), mask);
    eng_read(g, a->type, 0, (size_t)n * sizeof(int), type);
    double *rows = gr_malloc(g, (size_t)(n ? n : 1) * ROW_W * sizeof(double));
    int m = 0;
    for (int i = 0; i < n; i++) {
        const double *r = rec + (size_t)i * w;
        if (!(mask[i] & f->groupbit) || (int)r[MESH_SREC_KEY] < 1)
            continue;
        double *row = rows + (size_t)m++ * ROW_W;
        row[0] = (double)tag[i]; /* exact: tags stay below 2^53 */
        row[1] = type[i];
        memcpy(row + 2, r, w * sizeof(double));
    }
    free(rec);
    free(tag);
    free(mask);
    free(type);
    m = par_gather_rows(g, &rows, m, ROW_W);
    qsort(rows, (size_t)m, ROW_W * sizeof(double), cmp_row);
    *nrows = m;
    return rows;
}

/* The step's sums over the atoms' records in atom-tag order: one process's
 * bits on any number of ranks (every rank gathers every rank's rows). */
static void end_of_step(struct gravel *g, struct fix *f)
{
    struct mesh_surface *ms = f->data;
    struct mesh_stress *st = ms->stress;
    int ntri = ms->m.ntri;
    memset(st->f, 0, 3 * (size_t)ntri * sizeof(double));
    st->step = g->step;
    /* no wall used the mesh this step: no force (the same on every rank) */
    int used = ms->fmesh_valid && ms->fmesh_step == g->step && st->rec;
    if (par_on(g))
        used = comm_max_int(used);
    if (!used)
        return;
    int m;
    double *rows = contact_rows(g, f, st, &m);
    struct mesh_pose p;
    mesh_surface_pose(g, f->id, &p);
    double *wstep = st->do_wear ? gr_calloc(g, (size_t)(ntri ? ntri : 1), sizeof(double)) : NULL;
    for (int k = 0; k < m; k++) {
        const double *row = rows + (size_t)k * ROW_W;
        const int type = (int)row[1];
        for (int s = 0; s < MESH_SLOTS; s++) {
            const double *r = row + 2 + (size_t)s * MESH_SREC_W;
            int t = (int)r[MESH_SREC_KEY] - 1;
            if (t < 0 || t >= ntri)
                break;
            const double *F = r + MESH_SREC_F, *v = r + MESH_SREC_V;
            for (int q = 0; q < 3; q++)
                st->f[3 * t + q] += F[q];
            if (!st->do_wear || r[MESH_SREC_CV] < 0.)
                continue;
            double vm = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            if (0.0000001 > vm)
                continue;
            double nrm[3];
            mesh_pose_vector(&p, ms->normal + 3 * t, nrm);
            double fm = sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
            double E = finnie_angle(v, vm, nrm);
            E *= 2. * st->kf[type - 1] * vm * fm;
            wstep[t] += E * g->dt / st->area[t];
        }
    }
    for (int t = 0; st->do_wear && t < ntri; t++)
        st->wear[t] += wstep[t];
    for (int t = 0; st->do_stress && t < ntri; t++) {
        double nrm[3], *ft = st->f + 3 * t;
        mesh_pose_vector(&p, ms->normal + 3 * t, nrm);
        double sn = ft[0] * nrm[0] + ft[1] * nrm[1] + ft[2] * nrm[2];
        double d[3] = {ft[0] - sn * nrm[0], ft[1] - sn * nrm[1], ft[2] - sn * nrm[2]};
        st->sigma_n[t] = fabs(sn) / st->area[t];
        st->sigma_t[t] = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / st->area[t];
    }
    free(wstep);
    free(rows);
}

/* 1-6 as mesh/surface (force, torque), 7-9 the reference point (LIGGGHTS) */
static double vector(struct gravel *g, struct fix *f, int i)
{
    if (i <= 6)
        return mesh_surface_vector(g, f, i);
    struct mesh_surface *ms = f->data;
    struct mesh_pose p;
    mesh_surface_pose(g, f->id, &p);
    double ref[3];
    mesh_pose_point(&p, ms->ref, ref);
    return ref[i - 7];
}

const struct fix_style fix_style_mesh_surface_stress = {
    .name = "mesh/surface/stress",
    .reset_step = mesh_surface_reset_step,
    .create = create,
    .init = init,
    .destroy = mesh_surface_destroy,
    .end_of_step = end_of_step,
    .size_vector = 9,
    .vector = vector,
};
