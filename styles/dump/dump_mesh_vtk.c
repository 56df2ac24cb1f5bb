/* dump_mesh_vtk.c - `dump ID group mesh/vtk N file [MESHID ...]`: the
 * triangles of fix mesh/surface meshes, as they are moved at the step, as
 * legacy VTK POLYDATA that ParaView opens next to the particles of dump vtk
 * (LIGGGHTS' dump mesh/vtk; the group is ignored). Without mesh IDs every
 * mesh is written. One snapshot per file: '*' in the name for a series,
 * else the file is rewritten atomically at each snapshot (src/io/dump.h).
 *
 * Layout: ASCII, FIELD TIME/CYCLE as dump vtk, POINTS (welded vertices of
 * every mesh, double), POLYGONS (3 per triangle), CELL_DATA field arrays:
 * mesh (index in the list, from 0), triangle (index in its file, from 0),
 * type (the mesh's type), normal and velocity (of the surface at the
 * triangle's centroid, 3-component double). */
#include <stdlib.h>
#include <string.h>

#include "dump.h"
#include "error.h"
#include "fix.h"
#include "fix_mesh_surface.h"

struct mvtk {
    int nmesh;
    char (*id)[GR_NAMELEN];
};

static void mv_create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    struct mvtk *mv = gr_calloc(g, 1, sizeof *mv);
    d->data = mv;
    if (argc) {
        mv->id = gr_calloc(g, (size_t)argc, sizeof *mv->id);
        for (int i = 0; i < argc; i++) {
            mesh_surface_get(g, argv[i], "dump mesh/vtk");
            snprintf(mv->id[i], GR_NAMELEN, "%s", argv[i]);
        }
        mv->nmesh = argc;
    }
}

static void mv_destroy(struct dump *d)
{
    struct mvtk *mv = d->data;
    if (mv)
        free(mv->id);
    free(mv);
    d->data = NULL;
}

/* The meshes to write: the listed ones, else every fix mesh/surface. */
static int mesh_list(struct gravel *g, struct dump *d, struct fix **out, int cap)
{
    struct mvtk *mv = d->data;
    int n = 0;
    for (int k = 0; k < g->styles.nfix && n < cap; k++) {
        struct fix *f = g->styles.fix[k];
        if (f->style != &fix_style_mesh_surface)
            continue;
        int want = mv->nmesh == 0;
        for (int i = 0; i < mv->nmesh; i++)
            want |= !strcmp(mv->id[i], f->id);
        if (want)
            out[n++] = f;
    }
    return n;
}

static void mv_init(struct gravel *g, struct dump *d)
{
    struct mvtk *mv = d->data;
    for (int i = 0; i < mv->nmesh; i++)
        mesh_surface_get(g, mv->id[i], "dump mesh/vtk");
}

#define MAXM 64

static void mv_write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    (void)idx;
    (void)n;
    struct fix *fx[MAXM];
    int nm = mesh_list(g, d, fx, MAXM);
    struct mesh_pose pose[MAXM];
    int nv = 0, nt = 0;
    for (int m = 0; m < nm; m++) {
        const struct mesh_surface *ms = fx[m]->data;
        mesh_surface_pose(g, fx[m]->id, &pose[m]);
        nv += ms->m.nvert;
        nt += ms->m.ntri;
    }
    fprintf(fp, "# vtk DataFile Version 3.0\n");
    fprintf(fp, "gravel dump %s meshes step %lld time %.17g\n", d->id, (long long)g->step,
            g->time);
    fprintf(fp, "ASCII\nDATASET POLYDATA\n");
    fprintf(fp, "FIELD FieldData 2\nTIME 1 1 double\n%.17g\nCYCLE 1 1 int\n%lld\n", g->time,
            (long long)g->step);
    fprintf(fp, "POINTS %d double\n", nv);
    for (int m = 0; m < nm; m++) {
        const struct mesh_surface *ms = fx[m]->data;
        const double *R = pose[m].R, *dd = pose[m].d;
        for (int v = 0; v < ms->m.nvert; v++) {
            const double *p = ms->m.vert + 3 * v;
            double q[3];
            for (int r = 0; r < 3; r++)
                q[r] = R[3 * r] * p[0] + R[3 * r + 1] * p[1] + R[3 * r + 2] * p[2] + dd[r];
            fprintf(fp, "%.17g %.17g %.17g\n", q[0], q[1], q[2]);
        }
    }
    fprintf(fp, "POLYGONS %d %d\n", nt, 4 * nt);
    int base = 0;
    for (int m = 0; m < nm; m++) {
        const struct mesh_surface *ms = fx[m]->data;
        for (int t = 0; t < ms->m.ntri; t++) {
            const int *v = ms->m.tri + 3 * t;
            fprintf(fp, "3 %d %d %d\n", base + v[0], base + v[1], base + v[2]);
        }
        base += ms->m.nvert;
    }
    if (nt == 0)
        return;
    fprintf(fp, "CELL_DATA %d\nFIELD FieldData 5\n", nt);
    fprintf(fp, "mesh 1 %d int\n", nt);
    for (int m = 0; m < nm; m++)
        for (int t = 0; t < ((const struct mesh_surface *)fx[m]->data)->m.ntri; t++)
            fprintf(fp, "%d\n", m);
    fprintf(fp, "triangle 1 %d int\n", nt);
    for (int m = 0; m < nm; m++)
        for (int t = 0; t < ((const struct mesh_surface *)fx[m]->data)->m.ntri; t++)
            fprintf(fp, "%d\n", t);
    fprintf(fp, "type 1 %d int\n", nt);
    for (int m = 0; m < nm; m++) {
        const struct mesh_surface *ms = fx[m]->data;
        for (int t = 0; t < ms->m.ntri; t++)
            fprintf(fp, "%d\n", ms->type);
    }
    fprintf(fp, "normal 3 %d double\n", nt);
    for (int m = 0; m < nm; m++) {
        const struct mesh_surface *ms = fx[m]->data;
        const double *R = pose[m].R;
        for (int t = 0; t < ms->m.ntri; t++) {
            const double *p = ms->normal + 3 * t;
            double q[3];
            for (int r = 0; r < 3; r++)
                q[r] = R[3 * r] * p[0] + R[3 * r + 1] * p[1] + R[3 * r + 2] * p[2];
            fprintf(fp, "%.17g %.17g %.17g\n", q[0], q[1], q[2]);
        }
    }
    fprintf(fp, "velocity 3 %d double\n", nt);
    for (int m = 0; m < nm; m++) {
        const struct mesh_surface *ms = fx[m]->data;
        const struct mesh_pose *ps = &pose[m];
        for (int t = 0; t < ms->m.ntri; t++) {
            double c[3] = {0, 0, 0}, q[3], v[3];
            for (int k = 0; k < 3; k++)
                for (int r = 0; r < 3; r++)
                    c[r] += ms->m.vert[3 * ms->m.tri[3 * t + k] + r] / 3.0;
            for (int r = 0; r < 3; r++)
                q[r] = ps->R[3 * r] * c[0] + ps->R[3 * r + 1] * c[1] + ps->R[3 * r + 2] * c[2] +
                       ps->d[r];
            const double *om = ps->omega;
            v[0] = ps->V0[0] + om[1] * q[2] - om[2] * q[1];
            v[1] = ps->V0[1] + om[2] * q[0] - om[0] * q[2];
            v[2] = ps->V0[2] + om[0] * q[1] - om[1] * q[0];
            fprintf(fp, "%.17g %.17g %.17g\n", v[0], v[1], v[2]);
        }
    }
}

const struct dump_style dump_style_mesh_vtk = {
    .name = "mesh/vtk",
    .append = 0,
    .create = mv_create,
    .init = mv_init,
    .write = mv_write,
    .destroy = mv_destroy,
};
