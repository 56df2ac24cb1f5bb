/* dump_mesh_gran_vtk.c - LIGGGHTS's `dump ID group mesh/gran/VTK N file
 * [stress] [wear] [output face] [MESHID ...]` (keywords and mesh IDs in any
 * order; no ID: every mesh): the triangles of fix mesh/surface meshes at
 * their pose of the step with, per triangle, the normal and shear stress and
 * the wear of fix mesh/surface/stress (0 for a mesh that does not compute
 * them, as LIGGGHTS). The group is ignored.
 *
 * Layout (LIGGGHTS 3.8's file through VTK 9): legacy VTK 5.1 ASCII
 * POLYDATA; POINTS three per triangle (not welded), in double; POLYGONS as
 * OFFSETS and CONNECTIVITY (vtktypeint64); CELL_DATA FIELD arrays
 * normal_stress_average and shear_stress_average (stress) and wear (wear),
 * double, in that order. Other LIGGGHTS properties (stresscomponents, id,
 * vel, temp, owner, area, aedges, acorners, index, nneighs, liquid, distaa,
 * output interpolate|original) are refused. */
#include <stdlib.h>
#include <string.h>

#include "dump.h"
#include "dump_mesh.h"
#include "error.h"
#include "fix.h"
#include "fix_mesh_surface.h"
#include "fix_mesh_surface_stress.h"

struct gran_vtk {
    struct dump_meshes meshes;
    int stress, wear;
};

static void gv_create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    static const char *const refused[] = {"stresscomponents", "id", "vel", "temp", "owner",
                                          "area", "aedges", "acorners", "index", "nneighs",
                                          "liquid", "distaa", NULL};
    struct gran_vtk *gv = gr_calloc(g, 1, sizeof *gv);
    d->data = gv;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "stress")) {
            gv->stress = 1;
        } else if (!strcmp(a, "wear")) {
            gv->wear = 1;
        } else if (!strcmp(a, "output")) {
            if (i + 1 >= argc || strcmp(argv[i + 1], "face"))
                gr_error(g, "dump mesh/gran/VTK: only 'output face' is supported%s%s",
                         i + 1 < argc ? ", got " : "", i + 1 < argc ? argv[i + 1] : "");
            i++;
        } else {
            for (int k = 0; refused[k]; k++)
                if (!strcmp(a, refused[k]))
                    gr_error(g, "dump mesh/gran/VTK: property '%s' is not supported (stress "
                                "and wear are)", a);
            if (!fix_find(g, a))
                gr_error(g, "dump mesh/gran/VTK: '%.64s' is neither a property (stress, wear) "
                            "nor the ID of a fix mesh/surface", a);
            dump_meshes_add(g, &gv->meshes, a, "dump mesh/gran/VTK");
        }
    }
}

static void gv_destroy(struct dump *d)
{
    struct gran_vtk *gv = d->data;
    if (gv)
        dump_meshes_free(&gv->meshes);
    free(gv);
    d->data = NULL;
}

static void gv_init(struct gravel *g, struct dump *d)
{
    struct gran_vtk *gv = d->data;
    dump_meshes_check(g, &gv->meshes, "dump mesh/gran/VTK");
}

#define MAXM 64

/* One per-triangle array over every mesh: the values of mesh/surface/stress
 * (which 0: sigma_n, 1: sigma_t, 2: wear), 0 where a mesh has none. */
static void cell_array(FILE *fp, const char *name, struct fix **fx, int nm, int nt, int which)
{
    fprintf(fp, "%s 1 %d double\n", name, nt);
    for (int m = 0; m < nm; m++) {
        const struct mesh_surface *ms = fx[m]->data;
        const struct mesh_stress *st = ms->stress;
        const double *v = !st ? NULL
                          : which == 0 ? (st->do_stress ? st->sigma_n : NULL)
                          : which == 1 ? (st->do_stress ? st->sigma_t : NULL)
                                       : (st->do_wear ? st->wear : NULL);
        for (int t = 0; t < ms->m.ntri; t++)
            fprintf(fp, "%.17g\n", v ? v[t] : 0.0);
    }
}

static void gv_write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    (void)idx;
    (void)n;
    struct gran_vtk *gv = d->data;
    struct fix *fx[MAXM];
    int nm = dump_meshes_list(g, &gv->meshes, fx, MAXM);
    int nt = 0;
    for (int m = 0; m < nm; m++)
        nt += ((const struct mesh_surface *)fx[m]->data)->m.ntri;
    fprintf(fp, "# vtk DataFile Version 5.1\n");
    fprintf(fp, "gravel dump %s mesh/gran/VTK step %lld\n", d->id, (long long)g->step);
    fprintf(fp, "ASCII\nDATASET POLYDATA\nPOINTS %d double\n", 3 * nt);
    for (int m = 0; m < nm; m++) {
        const struct mesh_surface *ms = fx[m]->data;
        struct mesh_pose p;
        mesh_surface_pose(g, fx[m]->id, &p);
        for (int t = 0; t < ms->m.ntri; t++)
            for (int k = 0; k < 3; k++) {
                double q[3];
                mesh_pose_point(&p, ms->m.vert + 3 * ms->m.tri[3 * t + k], q);
                fprintf(fp, "%.17g %.17g %.17g\n", q[0], q[1], q[2]);
            }
    }
    fprintf(fp, "POLYGONS %d %d\nOFFSETS vtktypeint64\n", nt + 1, 3 * nt);
    for (int t = 0; t <= nt; t++)
        fprintf(fp, "%d\n", 3 * t);
    fprintf(fp, "CONNECTIVITY vtktypeint64\n");
    for (int t = 0; t < nt; t++)
        fprintf(fp, "%d %d %d\n", 3 * t, 3 * t + 1, 3 * t + 2);
    int nf = 2 * gv->stress + gv->wear;
    if (nt == 0 || nf == 0)
        return;
    fprintf(fp, "CELL_DATA %d\nFIELD FieldData %d\n", nt, nf);
    if (gv->stress) {
        cell_array(fp, "normal_stress_average", fx, nm, nt, 0);
        cell_array(fp, "shear_stress_average", fx, nm, nt, 1);
    }
    if (gv->wear)
        cell_array(fp, "wear", fx, nm, nt, 2);
}

const struct dump_style dump_style_mesh_gran_vtk = {
    .name = "mesh/gran/VTK",
    .append = 0,
    .create = gv_create,
    .init = gv_init,
    .write = gv_write,
    .destroy = gv_destroy,
};
