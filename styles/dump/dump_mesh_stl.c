/* dump_mesh_stl.c - `dump ID group mesh/stl N file*.stl [MESHID ...]
 * [binary] [region R] [local|ghost|all]`: the triangles of fix
 * mesh/surface meshes as STL, at their pose of the step (moving meshes
 * where fix move/mesh has put them), one file per snapshot (LIGGGHTS-PUBLIC
 * 3.8 DumpMeshSTL; the group is ignored). The file name must hold '*'.
 *
 * Meshes: those listed, in list order, else every mesh/surface fix in the
 * order of definition (dump_mesh.h). region R keeps the triangles whose
 * centre (the mean of its vertices) is in R. local, ghost and all choose
 * LIGGGHTS's parallel parts of a mesh; on one process they are the same.
 *
 * ASCII (LIGGGHTS's layout, "%g" numbers): "solid LIGGGHTS_STL_EXPORT",
 * per triangle "  facet normal nx ny nz", "    outer loop", three
 * "      vertex x y z", "    endloop", "  endfacet"; "endsolid
 * LIGGGHTS_STL_EXPORT". binary: the 80-byte header "STL File written by
 * LIGGGHTS" padded with blanks, the triangle count (uint32), per triangle
 * 12 floats (normal, vertices) and a zero uint16. Normals are the unit
 * normals of the vertices' order (right hand over 0 1 2), turned with the
 * mesh. Write errors are reported by the dump machinery (src/io/dump.h). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "dump.h"
#include "dump_mesh.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "region.h"

#define WHO "dump mesh/stl"

struct mstl {
    struct dump_meshes dm;
    int binary;
    char region[GR_NAMELEN];
};

static void ms_create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    struct mstl *s = gr_calloc(g, 1, sizeof *s);
    d->data = s;
    if (!d->multifile)
        gr_error(g, WHO ": You should use a filename like 'dump*.stl' for the 'mesh/stl' "
                    "command to produce one file per time-step (got '%.200s')", d->file);
    for (int i = 0; i < argc; i++) {
        const char *k = argv[i];
        if (!strcmp(k, "binary"))
            s->binary = 1;
        else if (!strcmp(k, "local") || !strcmp(k, "ghost") || !strcmp(k, "all"))
            continue; /* parts of a parallel mesh: the whole mesh on one process */
        else if (!strcmp(k, "region")) {
            if (i + 1 >= argc)
                gr_error(g, WHO ": not enough arguments after 'region'");
            if (!region_find(g, argv[i + 1]))
                gr_error(g, WHO ": region ID does not exist: %.64s", argv[i + 1]);
            snprintf(s->region, sizeof s->region, "%s", argv[++i]);
        } else if (fix_find(g, k))
            dump_meshes_add(g, &s->dm, k, WHO);
        else
            gr_error(g, WHO ": unknown keyword or mesh '%.64s' (expected a fix mesh/surface "
                        "ID, binary, region, local, ghost or all)", k);
    }
}

static void ms_destroy(struct dump *d)
{
    struct mstl *s = d->data;
    if (s)
        dump_meshes_free(&s->dm);
    free(s);
    d->data = NULL;
}

static void ms_init(struct gravel *g, struct dump *d)
{
    struct mstl *s = d->data;
    dump_meshes_check(g, &s->dm, WHO);
    if (s->region[0] && !region_find(g, s->region))
        gr_error(g, WHO " %s: region %s was deleted", d->id, s->region);
}

/* Triangle t of ms at pose p: normal and vertices, 12 numbers. */
static void facet(const struct mesh_surface *ms, const struct mesh_pose *p, int t,
                  double out[12])
{
    mesh_pose_vector(p, ms->normal + 3 * t, out);
    for (int k = 0; k < 3; k++)
        mesh_pose_point(p, ms->m.vert + 3 * ms->m.tri[3 * t + k], out + 3 + 3 * k);
}

static void ms_write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    (void)idx, (void)n;
    struct mstl *s = d->data;
    int cap = g->styles.nfix + s->dm.n;
    struct fix **fx = gr_calloc(g, (size_t)(cap ? cap : 1), sizeof *fx);
    int nm = dump_meshes_list(g, &s->dm, fx, cap);
    struct region *reg = s->region[0] ? region_find(g, s->region) : NULL;
    if (reg)
        region_prematch(g, reg);
    /* the facets kept, 12 numbers each */
    size_t nf = 0, fcap = 0;
    double *buf = NULL;
    for (int m = 0; m < nm; m++) {
        const struct mesh_surface *ms = fx[m]->data;
        struct mesh_pose p;
        mesh_surface_pose(g, fx[m]->id, &p);
        for (int t = 0; t < ms->m.ntri; t++) {
            if (nf == fcap) {
                fcap = fcap ? 2 * fcap : 64;
                buf = gr_realloc(g, buf, fcap * 12 * sizeof *buf);
            }
            double *q = buf + 12 * nf;
            facet(ms, &p, t, q);
            double c[3];
            for (int r = 0; r < 3; r++)
                c[r] = (q[3 + r] + q[6 + r] + q[9 + r]) / 3.0;
            if (!reg || region_match(reg, c))
                nf++;
        }
    }
    free(fx);
    if (s->binary) {
        char head[80];
        memset(head, ' ', sizeof head);
        memcpy(head, "STL File written by LIGGGHTS", 28);
        uint32_t count = (uint32_t)nf;
        uint16_t attr = 0;
        fwrite(head, 1, sizeof head, fp);
        fwrite(&count, sizeof count, 1, fp);
        for (size_t i = 0; i < nf; i++) {
            float v[12];
            for (int k = 0; k < 12; k++)
                v[k] = (float)buf[12 * i + k];
            fwrite(v, sizeof v[0], 12, fp);
            fwrite(&attr, sizeof attr, 1, fp);
        }
    } else {
        fprintf(fp, "solid LIGGGHTS_STL_EXPORT\n");
        for (size_t i = 0; i < nf; i++) {
            const double *q = buf + 12 * i;
            fprintf(fp, "  facet normal %g %g %g\n    outer loop\n", q[0], q[1], q[2]);
            for (int k = 0; k < 3; k++)
                fprintf(fp, "      vertex %g %g %g\n", q[3 + 3 * k], q[4 + 3 * k],
                        q[5 + 3 * k]);
            fprintf(fp, "    endloop\n  endfacet\n");
        }
        fprintf(fp, "endsolid LIGGGHTS_STL_EXPORT\n");
    }
    free(buf);
}

const struct dump_style dump_style_mesh_stl = {
    .name = "mesh/stl",
    .append = 0,
    .create = ms_create,
    .init = ms_init,
    .write = ms_write,
    .destroy = ms_destroy,
};
