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
#include "dump_mesh.h"
#include "fix_mesh_surface.h"

static void mv_create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    struct dump_meshes *dm = gr_calloc(g, 1, sizeof *dm);
    d->data = dm;
    for (int i = 0; i < argc; i++)
        dump_meshes_add(g, dm, argv[i], "dump mesh/vtk");
}

static void mv_destroy(struct dump *d)
{
    if (d->data)
        dump_meshes_free(d->data);
    free(d->data);
    d->data = NULL;
}

static void mv_init(struct gravel *g, struct dump *d)
{
    dump_meshes_check(g, d->data, "dump mesh/vtk");
}

#define MAXM 64

static void mv_write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    (void)idx;
    (void)n;
    struct fix *fx[MAXM];
    int nm = dump_meshes_list(g, d->data, fx, MAXM);
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
        for (int v = 0; v < ms->m.nvert; v++) {
            double q[3];
            mesh_pose_point(&pose[m], ms->m.vert + 3 * v, q);
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
        for (int t = 0; t < ms->m.ntri; t++) {
            double q[3];
            mesh_pose_vector(&pose[m], ms->normal + 3 * t, q);
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
            mesh_pose_point(ps, c, q);
            mesh_pose_velocity(ps, q, v);
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
