/* test_mesh.c - triangle-mesh walls (src/state/mesh.c, fix mesh/surface, fix
 * move/mesh, fix wall/gran ... mesh, dump mesh/vtk, f_ID output):
 *  - the readers (ASCII STL, binary STL, legacy VTK polydata and
 *    unstructured grid) give the same welded box: 8 vertices, 18 edges,
 *    12 triangles, every edge shared by two;
 *  - welding counts and tolerance; every bad mesh gets its message naming
 *    the file and triangle;
 *  - physics: a box of 12 triangles = six plane walls (1e-10); a sphere
 *    rolling across the shared edge of two coplanar triangles, or over the
 *    centre vertex of a fan of 8, = the same on one plane wall (1e-10: no
 *    bump, no double force, history carried across); a floor moving with
 *    move/mesh linear = wall/gran zplane shear (1e-10); model granular on
 *    the square and the fan = on the plane wall (1e-12); a resting sphere
 *    weighs m g on f_ID[3];
 *  - the pose of stacked motions (rotate + linear) against closed form;
 *  - dump mesh/vtk writes the moved triangles. */
#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

#include "test.h"
#include "atoms.h"
#include "fix.h"
#include "fix_mesh_surface.h"
#include "mesh.h"
#include "mesh_planar.h"
#include "output.h"
#include "thermo.h"

static char dir[64];

static const char *path(const char *name)
{
    static char buf[4][256];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

/* ---- mesh files ------------------------------------------------------------------ */

/* the box [lo, hi]^3 as 12 triangles, 2 per face, normals inward */
static int box_soup(double lo, double hi, double *s)
{
    const int q[6][4][3] = {
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}},
        {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, {{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}},
        {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}},
    };
    const int split[2][3] = {{0, 1, 2}, {0, 2, 3}};
    int n = 0;
    for (int f = 0; f < 6; f++)
        for (int h = 0; h < 2; h++, n++)
            for (int k = 0; k < 3; k++)
                for (int d = 0; d < 3; d++)
                    s[9 * n + 3 * k + d] = q[f][split[h][k]][d] ? hi : lo;
    return n;
}

static void write_ascii_stl(const char *name, const double *s, int n)
{
    FILE *fp = fopen(path(name), "w");
    fprintf(fp, "solid test\n");
    for (int t = 0; t < n; t++) {
        fprintf(fp, "  facet normal 0 0 0\n    outer loop\n");
        for (int k = 0; k < 3; k++)
            fprintf(fp, "      vertex %.17g %.17g %.17g\n", s[9 * t + 3 * k], s[9 * t + 3 * k + 1],
                    s[9 * t + 3 * k + 2]);
        fprintf(fp, "    endloop\n  endfacet\n");
    }
    fprintf(fp, "endsolid test\n");
    fclose(fp);
}

static void put_le32(unsigned char *p, uint32_t u)
{
    for (int k = 0; k < 4; k++)
        p[k] = (unsigned char)(u >> (8 * k));
}

/* binary STL with header count `count`, n triangles, cut to `cut` bytes if > 0 */
static void write_binary_stl(const char *name, const double *s, int n, uint32_t count, long cut)
{
    size_t len = 84 + 50 * (size_t)n;
    unsigned char *b = calloc(1, len);
    memcpy(b, "binary test mesh", 16);
    put_le32(b + 80, count);
    for (int t = 0; t < n; t++)
        for (int c = 0; c < 9; c++) {
            float f = (float)s[9 * t + c];
            uint32_t u;
            memcpy(&u, &f, 4);
            put_le32(b + 84 + 50 * t + 12 + 4 * c, u);
        }
    FILE *fp = fopen(path(name), "wb");
    fwrite(b, 1, cut > 0 ? (size_t)cut : len, fp);
    fclose(fp);
    free(b);
}

static void write_text(const char *name, const char *text)
{
    FILE *fp = fopen(path(name), "w");
    fputs(text, fp);
    fclose(fp);
}

static void check_box(const struct mesh *m)
{
    CHECK(m->ntri == 12);
    CHECK(m->nvert == 8);
    CHECK(m->nedge == 18);
    int boundary = 0;
    for (int i = 0; i < 36; i++)
        boundary += m->nbr[i] < 0;
    CHECK(boundary == 0);
    /* each box corner is in 3..6 triangles; 36 incidences in all */
    CHECK(m->vtri_start[8] == 36);
    for (int v = 0; v < 8; v++) {
        int c = m->vtri_start[v + 1] - m->vtri_start[v];
        CHECK(c >= 3 && c <= 6);
    }
}

TEST(read_ascii_stl)
{
    double s[108];
    int n = box_soup(-2, 2, s);
    write_ascii_stl("box.stl", s, n);
    struct mesh m;
    char err[256] = "";
    CHECK(mesh_read(path("box.stl"), 0, &m, err, sizeof err) == 0);
    check_box(&m);
    /* welded ids in order of first appearance; triangle 0 is (0 1 2) */
    CHECK(m.tri[0] == 0 && m.tri[1] == 1 && m.tri[2] == 2);
    CHECK(m.vert[0] == -2 && m.vert[3] == 2);
    mesh_free(&m);
}

TEST(read_binary_stl)
{
    double s[108];
    int n = box_soup(-2, 2, s);
    write_binary_stl("boxb.stl", s, n, (uint32_t)n, 0);
    struct mesh m;
    char err[256] = "";
    CHECK(mesh_read(path("boxb.stl"), 0, &m, err, sizeof err) == 0);
    check_box(&m);
    mesh_free(&m);
    /* a binary header that starts with "solid" is still binary */
    FILE *fp = fopen(path("boxb.stl"), "r+b");
    fwrite("solid", 1, 5, fp);
    fclose(fp);
    CHECK(mesh_read(path("boxb.stl"), 0, &m, err, sizeof err) == 0);
    CHECK(m.ntri == 12);
    mesh_free(&m);
}

TEST(read_vtk)
{
    write_text("box.vtk", "# vtk DataFile Version 3.0\nbox\nASCII\nDATASET POLYDATA\n"
                          "POINTS 8 float\n-2 -2 -2 2 -2 -2 2 2 -2 -2 2 -2\n"
                          "-2 -2 2 2 -2 2 2 2 2 -2 2 2\n"
                          "POLYGONS 12 48\n3 0 1 2\n3 0 2 3\n3 4 7 6\n3 4 6 5\n"
                          "3 0 3 7\n3 0 7 4\n3 1 5 6\n3 1 6 2\n3 0 4 5\n3 0 5 1\n"
                          "3 3 2 6\n3 3 6 7\nCELL_DATA 12\n");
    struct mesh m;
    char err[256] = "";
    CHECK(mesh_read(path("box.vtk"), 0, &m, err, sizeof err) == 0);
    if (!err[0])
        check_box(&m);
    mesh_free(&m);
    write_text("tri.vtk", "# vtk DataFile Version 2.0\nug\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                          "POINTS 4 double\n0 0 0 1 0 0 1 1 0 0 1 0\nCELLS 2 8\n3 0 1 2\n"
                          "3 0 2 3\nCELL_TYPES 2\n5\n5\n");
    CHECK(mesh_read(path("tri.vtk"), 0, &m, err, sizeof err) == 0);
    CHECK(m.ntri == 2 && m.nvert == 4 && m.nedge == 5);
    CHECK(m.nbr[1] == 1 || m.nbr[2] == 1);  /* shared diagonal 0-2 */
    mesh_free(&m);
}

TEST(welding)
{
    /* two triangles sharing an edge, the shared vertices off by 1e-12 */
    double s[18] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 1e-12, 0, 0, 1, 1 + 1e-12, 0, 0, 1, 0};
    struct mesh m;
    char err[256];
    CHECK(mesh_from_soup("soup", s, 2, 0, &m, err, sizeof err) == 0);
    CHECK(m.nvert == 4);
    CHECK(m.nedge == 5);
    CHECK(m.nbr[3 * 0 + 2] == 1);   /* edge (2, 0) of triangle 0 */
    mesh_free(&m);
    /* a tolerance below the offset keeps them apart */
    CHECK(mesh_from_soup("soup", s, 2, 1e-14, &m, err, sizeof err) == 0);
    CHECK(m.nvert == 6);
    CHECK(m.nedge == 6);
    mesh_free(&m);
}

/* distance from p to segment ab */
static double seg_dist(const double *p, const double *a, const double *b)
{
    double ab[3], ap[3], t = 0, l = 0, d = 0;
    for (int k = 0; k < 3; k++) {
        ab[k] = b[k] - a[k];
        ap[k] = p[k] - a[k];
        t += ab[k] * ap[k];
        l += ab[k] * ab[k];
    }
    t = t / l < 0 ? 0 : t / l > 1 ? 1 : t / l;
    for (int k = 0; k < 3; k++)
        d += (ap[k] - t * ab[k]) * (ap[k] - t * ab[k]);
    return sqrt(d);
}

/* distance from p to triangle abc (inside the prism: to the plane, else to the edges) */
static double tri_dist(const double *p, const double *a, const double *b, const double *c)
{
    double e1[3], e2[3], n[3], w[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
        w[k] = p[k] - a[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    double h = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) / nn;
    double q[3] = {w[0] - h * n[0], w[1] - h * n[1], w[2] - h * n[2]};
    /* barycentric of q in (e1, e2) */
    double d00 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
    double d01 = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
    double d11 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
    double d20 = q[0] * e1[0] + q[1] * e1[1] + q[2] * e1[2];
    double d21 = q[0] * e2[0] + q[1] * e2[1] + q[2] * e2[2];
    double den = d00 * d11 - d01 * d01;
    double v = (d11 * d20 - d01 * d21) / den, u = (d00 * d21 - d01 * d20) / den;
    if (v >= 0 && u >= 0 && u + v <= 1)
        return fabs(h) * sqrt(nn);
    double d = seg_dist(p, a, b), d2 = seg_dist(p, b, c), d3 = seg_dist(p, c, a);
    return d < d2 ? (d < d3 ? d : d3) : (d2 < d3 ? d2 : d3);
}

/* every triangle within reach of a point is in the bin of that point */
TEST(bins_cover_reach)
{
    double fan[72 + 108];
    for (int k = 0; k < 8; k++) {
        double a0 = 2 * M_PI * k / 8, a1 = 2 * M_PI * (k + 1) / 8;
        double t[9] = {0, 0, 0.3 * k, 3 * cos(a0), 3 * sin(a0), 0, 3 * cos(a1), 3 * sin(a1), 1};
        memcpy(fan + 9 * k, t, sizeof t);
    }
    box_soup(-2.5, 2.5, fan + 72);
    struct mesh m;
    char err[256];
    CHECK(mesh_from_soup("mix", fan, 20, 0, &m, err, sizeof err) == 0);
    const double reaches[3] = {0.05, 0.5, 2.0};
    unsigned seed = 12345;
    for (int r = 0; r < 3; r++) {
        struct mesh_bins b;
        CHECK(mesh_bin(&m, reaches[r], &b, err, sizeof err) == 0);
        CHECK(b.h >= 2 * reaches[r]);
        int missing = 0;
        for (int s = 0; s < 20000; s++) {
            double p[3];
            for (int k = 0; k < 3; k++) {
                seed = seed * 1103515245u + 12345u;
                p[k] = -4 + 8.0 * ((seed >> 8) & 0xffff) / 65535.0;
            }
            int c[3], inside = 1;
            for (int k = 0; k < 3; k++) {
                c[k] = (int)floor((p[k] - b.lo[k]) / b.h);
                inside &= c[k] >= 0 && c[k] < b.n[k];
            }
            int cell = inside ? (c[2] * b.n[1] + c[1]) * b.n[0] + c[0] : -1;
            for (int t = 0; t < m.ntri; t++) {
                const int *v = m.tri + 3 * t;
                if (tri_dist(p, m.vert + 3 * v[0], m.vert + 3 * v[1], m.vert + 3 * v[2]) >
                    reaches[r])
                    continue;
                int found = 0;
                for (int k = cell < 0 ? 0 : b.start[cell]; cell >= 0 && k < b.start[cell + 1]; k++)
                    found |= b.list[k] == t;
                missing += !found;
            }
            /* lists ascend (the kernel sums contacts in triangle order) */
            for (int k = cell < 0 ? 0 : b.start[cell] + 1; cell >= 0 && k < b.start[cell + 1]; k++)
                if (b.list[k] <= b.list[k - 1])
                    missing++;
        }
        CHECK(missing == 0);
        mesh_bins_free(&b);
    }
    mesh_free(&m);
}

static void check_bad(const char *file, const char *what)
{
    struct mesh m;
    char err[512] = "";
    int rc = mesh_read(path(file), 0, &m, err, sizeof err);
    if (rc != -1 || !strstr(err, what) || !strstr(err, file)) {
        printf("  check failed: %s: expected '%s', got rc %d '%s'\n", file, what, rc, err);
        t_failed_checks++;
    }
    /* the same through the command, with the script line */
    char script[1024];
    snprintf(script, sizeof script, "units lj\natom_style sphere\nregion b block -4 4 -4 4 -4 "
             "4\ncreate_box 1 b\nfix m all mesh/surface file %s type 1\n", path(file));
    struct gravel *g = test_engine();
    rc = test_script(g, script);
    if (rc != GR_ERR || !strstr(g->err.msg, what) || !strstr(g->err.msg, "(test.in:5)")) {
        printf("  check failed: command for %s: got rc %d '%s'\n", file, rc, g->err.msg);
        t_failed_checks++;
    }
    gr_destroy(g);
}

TEST(bad_meshes)
{
    double s[108];
    int n = box_soup(-2, 2, s);
    check_bad("missing.stl", "cannot open mesh file");
    write_text("empty.stl", "");
    check_bad("empty.stl", "the mesh file is empty");
    /* zero area: triangle 3 collapsed onto a line */
    double z[108];
    memcpy(z, s, sizeof z);
    for (int d = 0; d < 3; d++)
        z[9 * 3 + 6 + d] = 0.5 * (z[9 * 3 + d] + z[9 * 3 + 3 + d]);
    write_ascii_stl("zero.stl", z, n);
    check_bad("zero.stl", "triangle 3: zero area");
    /* two coincident vertices */
    memcpy(z, s, sizeof z);
    memcpy(z + 9 * 5 + 3, z + 9 * 5, 3 * sizeof(double));
    write_ascii_stl("dup.stl", z, n);
    check_bad("dup.stl", "triangle 5: zero area");
    /* needle */
    double nd[9] = {0, 0, 0, 1, 0, 0, 0.5, 1e-7, 0};
    write_ascii_stl("needle.stl", nd, 1);
    check_bad("needle.stl", "triangle 0: needle triangle");
    /* NaN */
    write_text("nan.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                          "vertex 0 1 0\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\n"
                          "vertex 0 0 0\nvertex nan 0 0\nvertex 0 1 1\nendloop\nendfacet\n"
                          "endsolid x\n");
    check_bad("nan.stl", "triangle 1: vertex 1 is not finite");
    /* truncated binary: 12 triangles promised, 7 and a half there */
    write_binary_stl("trunc.stl", s, n, 12, 84 + 50 * 7 + 25);
    check_bad("trunc.stl", "truncated binary STL");
    check_bad("trunc.stl", "triangle 7 is cut");
    /* inconsistent count: header says 10, 12 present */
    write_binary_stl("count.stl", s, n, 10, 0);
    check_bad("count.stl", "inconsistent triangle count");
    write_text("count.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
                            "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 2 8\n3 0 1 2\n");
    check_bad("count.vtk", "triangle 1 is missing");
    write_text("quad.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
                           "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 1 5\n4 0 1 2 3\n");
    check_bad("quad.vtk", "inconsistent triangle count");
    /* ASCII STL syntax, with the line */
    write_text("syntax.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                             "vertex 1 0 0\nvertx 0 1 0\nendloop\nendfacet\nendsolid\n");
    check_bad("syntax.stl", "syntax.stl:6: expected 'vertex', got 'vertx' (triangle 0)");
    write_text("short.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n");
    check_bad("short.stl", "unexpected end of file");
}

/* random bytes and random keyword soups never crash the readers (ASan) and
 * always end in 0 or a message naming the file */
TEST(reader_survives_garbage)
{
    static const char *const words[] = {"solid", "facet", "normal", "outer", "loop", "vertex",
                                        "endloop", "endfacet", "endsolid", "1", "nan", "-0",
                                        "1e308", "POINTS", "POLYGONS", "3", "0", "2", "float",
                                        "OFFSETS", "CONNECTIVITY", "vtktypeint64", "FIELD",
                                        "CELLS", "CELL_TYPES", "5", "-1", "x"};
    const int nw = (int)(sizeof words / sizeof *words);
    unsigned seed = 99;
    int bad = 0;
    for (int k = 0; k < 300; k++) {
        char name[32];
        snprintf(name, sizeof name, "garbage%d.%s", k, k % 3 == 2 ? "vtk" : "stl");
        FILE *fp = fopen(path(name), "wb");
        if (k % 3 == 0) {   /* bytes, sometimes with a plausible binary header */
            seed = seed * 1103515245u + 12345u;
            int n = (int)(seed >> 16) % 600;
            for (int i = 0; i < n; i++) {
                seed = seed * 1103515245u + 12345u;
                fputc((int)(seed >> 16) & 255, fp);
            }
        } else {
            fputs(k % 3 == 1 ? "solid g\n" : "# vtk DataFile Version 3.0\ng\nASCII\n"
                                             "DATASET POLYDATA\n", fp);
            seed = seed * 1103515245u + 12345u;
            int n = (int)(seed >> 16) % 90;
            for (int i = 0; i < n; i++) {
                seed = seed * 1103515245u + 12345u;
                fprintf(fp, "%s%c", words[(seed >> 16) % (unsigned)nw], i % 7 ? ' ' : '\n');
            }
        }
        fclose(fp);
        struct mesh m;
        char err[512] = "";
        int rc = mesh_read(path(name), 0, &m, err, sizeof err);
        if (rc == 0)
            mesh_free(&m);
        else if (rc != -1 || !strstr(err, name))
            bad++;
    }
    CHECK(bad == 0);
}

TEST(command_errors)
{
    double s[108];
    int n = box_soup(-2, 2, s);
    write_ascii_stl("box.stl", s, n);
    char pre[512], t[1024];
    snprintf(pre, sizeof pre, "units lj\natom_style sphere\nregion b block -4 4 -4 4 -4 4\n"
             "create_box 1 b\n");
#define MESH_ERR(cmd, what, line)                                                            \
    do {                                                                                     \
        snprintf(t, sizeof t, "%s" cmd, pre, path("box.stl"));                               \
        CHECK_ERROR(t, what, line);                                                          \
    } while (0)
    MESH_ERR("fix m all mesh/surface file %s\n", "needs 'type T'", 5);
    MESH_ERR("fix m all mesh/surface file %s type 3\n", "type 3 is out of range", 5);
    MESH_ERR("fix m all mesh/surface file %s type 1 scal 2\n", "unknown fix mesh/surface keyword 'scal'", 5);
    MESH_ERR("fix m all mesh/surface file %s type 1 rotate axis 0 0 1 ang 3\n", "rotate expects", 5);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix v all move/mesh mesh q linear 1 0 0\n",
             "no fix with ID 'q'", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix v all move/mesh mesh m spin 1 0 0\n",
             "unknown fix move/mesh style 'spin'", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix v all move/mesh mesh m rotate origin 0 "
             "0 0 axis 0 0 1 period 0\n", "rotate period", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 "
             "mesh n_meshes 2 meshes m\n", "n_meshes is 2 but 1 mesh ID(s) follow", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 "
             "mesh n_meshes 1 meshes m shear x 1\n", "use fix move/mesh", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 "
             "mesh n_meshes 1 meshes x\n", "no fix with ID 'x'", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix w all wall/gran model hertz tangential "
             "history mesh n_meshes 1 meshes m shear x 1\n", "use fix move/mesh", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix w all wall/pair mesh n_meshes 1 meshes m "
             "extra\n", "fix wall/pair mesh: unexpected argument 'extra'", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 "
             "mesh n_meshes 9 meshes m\n", "n_meshes", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\n"
             "pair_style gran/hooke 1 NULL 1 NULL 0.5 1\npair_coeff * *\n"
             "create_atoms 1 single 0 0 0 units box\n"
             "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 mesh n_meshes 1 meshes m\n"
             "fix w2 all wall/gran hooke 1 NULL 1 NULL 0.5 1 mesh n_meshes 1 meshes m\nrun 1\n",
             "mesh m is already a wall of fix w", 11);
    MESH_ERR("fix m all mesh/surface file %s type 1\nthermo_style custom step f_m[8]\n"
             "create_atoms 1 single 0 0 0 units box\nrun 0\n",
             "f_m[8] is out of range: fix m has 7 values", 8);
    MESH_ERR("fix m all mesh/surface file %s type 1\nthermo_style custom step f_q[1]\n"
             "create_atoms 1 single 0 0 0 units box\nrun 0\n",
             "could not find thermo custom fix ID 'q'", 6);
    MESH_ERR("fix m all mesh/surface file %s type 1\nfix q all gravity 1.0 vector 0 0 -1\n"
             "thermo_style custom step f_q[1]\nunfix q\n"
             "create_atoms 1 single 0 0 0 units box\nrun 0\n", "no fix with ID 'q'", 10);
#undef MESH_ERR
}

/* ---- physics ---------------------------------------------------------------------- */

/* run `script` and store the atoms' x, v, omega in tag order */
static int run_state(const char *script, double *out, int natoms)
{
    struct gravel *g = test_engine();
    int rc = test_script(g, script);
    if (rc != GR_OK)
        printf("  script failed: %s\n", g->err.msg);
    CHECK(rc == GR_OK);
    CHECK(g->atoms.n == natoms);
    for (int i = 0; rc == GR_OK && i < g->atoms.n && i < natoms; i++) {
        int k = (int)g->atoms.tag[i] - 1;
        for (int d = 0; d < 3; d++) {
            out[9 * k + d] = g->atoms.x[3 * i + d];
            out[9 * k + 3 + d] = g->atoms.v[3 * i + d];
            out[9 * k + 6 + d] = g->atoms.omega[3 * i + d];
        }
    }
    gr_destroy(g);
    return rc;
}

static double max_diff(const double *a, const double *b, int n)
{
    double m = 0;
    for (int i = 0; i < n; i++)
        m = fabs(a[i] - b[i]) > m ? fabs(a[i] - b[i]) : m;
    return m;
}

#define WALL "hooke/history 2000 NULL 50 NULL 0.5 1"

TEST(box_equals_planes)
{
    double s[108];
    int n = box_soup(-2, 2, s);
    write_ascii_stl("box.stl", s, n);
    const char *deck = "units lj\natom_style sphere\nboundary f f f\n"
                       "region b block -3 3 -3 3 -3 3\ncreate_box 1 b\n"
                       "region inner block -1.5 1.5 -1.5 1.5 -1.5 1.5\nlattice sc 0.6\n"
                       "create_atoms 1 region inner\nset group all diameter 0.8 density 1.0\n"
                       "velocity all create 5.0 4928459 loop geom\n"
                       "pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
                       "timestep 0.0005\nfix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
                       "thermo 0\n";
    char a[4096], b[4096];
    snprintf(a, sizeof a, "%sfix m all mesh/surface file %s type 1\n"
             "fix w all wall/gran " WALL " mesh n_meshes 1 meshes m\nrun 4000\n", deck,
             path("box.stl"));
    snprintf(b, sizeof b, "%s"
             "fix w1 all wall/gran " WALL " zplane -2 NULL\nfix w2 all wall/gran " WALL " zplane NULL 2\n"
             "fix w3 all wall/gran " WALL " xplane -2 NULL\nfix w4 all wall/gran " WALL " xplane NULL 2\n"
             "fix w5 all wall/gran " WALL " yplane -2 NULL\nfix w6 all wall/gran " WALL " yplane NULL 2\n"
             "run 4000\n", deck);
    double sa[27 * 9], sb[27 * 9];
    if (run_state(a, sa, 27) == GR_OK && run_state(b, sb, 27) == GR_OK) {
        double d = max_diff(sa, sb, 27 * 9);
        CHECK(d <= 1e-10);
        if (d > 1e-10)
            printf("  box vs planes: max |diff| %.3g\n", d);
        /* the walls did act: the atoms have fallen onto the floor */
        double zmin = 1e9;
        for (int k = 0; k < 27; k++)
            zmin = sa[9 * k + 2] < zmin ? sa[9 * k + 2] : zmin;
        CHECK(zmin < -1.5);
    }
}

/* one sphere rolling and sliding on a floor: a plane wall, two coplanar
 * triangles with the diagonal crossed, a fan of 8 around the vertex crossed */
TEST(shared_edge_and_vertex)
{
    double two[18] = {-5, -5, 0, 5, -5, 0, 5, 5, 0, -5, -5, 0, 5, 5, 0, -5, 5, 0};
    write_ascii_stl("two.stl", two, 2);
    double fan[72];
    for (int k = 0; k < 8; k++) {
        double a0 = 2 * M_PI * k / 8, a1 = 2 * M_PI * (k + 1) / 8;
        double t[9] = {0, 0, 0, 6 * cos(a0), 6 * sin(a0), 0, 6 * cos(a1), 6 * sin(a1), 0};
        memcpy(fan + 9 * k, t, sizeof t);
    }
    write_ascii_stl("fan.stl", fan, 8);
    const char *deck = "units lj\natom_style sphere\nboundary f f f\n"
                       "region b block -6 6 -6 6 -1 6\ncreate_box 1 b\n"
                       "create_atoms 1 single %s 0.4995 units box\n"
                       "set atom 1 diameter 1.0 density 1.9098593\n"
                       "velocity all set %s 0 units box\n"
                       "set atom 1 omega 0 0 3\n"
                       "pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
                       "timestep 0.0005\nfix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
                       "thermo 0\n%s\nrun 3000\n";
    char wall[512], s[4096];
    double ref[9], got[9];
    /* across the diagonal of the square: start at (-1, -0.5) moving along (1, 1) */
    snprintf(s, sizeof s, deck, "-1 -0.5", "1.2 0", "fix w all wall/gran " WALL " zplane 0 NULL");
    run_state(s, ref, 1);
    snprintf(wall, sizeof wall, "fix m all mesh/surface file %s type 1\n"
             "fix w all wall/gran " WALL " mesh n_meshes 1 meshes m", path("two.stl"));
    snprintf(s, sizeof s, deck, "-1 -0.5", "1.2 0", wall);
    run_state(s, got, 1);
    CHECK(max_diff(ref, got, 9) <= 1e-10);
    /* the sphere did cross the diagonal y = x */
    CHECK(got[1] - got[0] < 0);
    printf("  edge: end at %.6g %.6g\n", got[0], got[1]);
    /* through the centre vertex of the fan and across two fan edges */
    snprintf(s, sizeof s, deck, "-1.3 -1.2", "1.2 1.1", "fix w all wall/gran " WALL " zplane 0 NULL");
    run_state(s, ref, 1);
    snprintf(wall, sizeof wall, "fix m all mesh/surface file %s type 1\n"
             "fix w all wall/gran " WALL " mesh n_meshes 1 meshes m", path("fan.stl"));
    snprintf(s, sizeof s, deck, "-1.3 -1.2", "1.2 1.1", wall);
    run_state(s, got, 1);
    CHECK(max_diff(ref, got, 9) <= 1e-10);
    printf("  fan: end at %.6g %.6g\n", got[0], got[1]);
    CHECK(got[0] > 0.05 && got[1] > 0.05);  /* passed the centre */
}

/* fix wall/gran granular ... mesh: the granular evaluator of the plane wall,
 * its whole history row per mesh contact. A sphere thrown sliding and
 * spinning onto the two-triangle square and across its diagonal, and over
 * the centre vertex of the fan, gives the zplane wall's trajectory to 1e-12
 * (x, v, omega): the tangential, rolling and twisting history goes with the
 * sphere from triangle to triangle. Two models: width 7 (mindlin, rolling,
 * marshall) and width 8 (mindlin_rescale/force keeps the contact radius). */
TEST(granular_mesh_equals_plane)
{
    static const char *const model[] = {
        "granular hertz/material 50000 200 0.3 tangential mindlin NULL 1.0 0.4 "
        "rolling sds 300 3 0.02 twisting marshall",
        "granular dmt 50000 0.5 0.3 2.0 damping mass_velocity tangential mindlin_rescale/force 3000 "
        "1.0 0.4 rolling sds 300 3 0.02 twisting sds 100 1 0.01"};
    const char *deck = "units lj\natom_style sphere\nboundary f f f\n"
                       "region b block -6 6 -6 6 -1 6\ncreate_box 1 b\n"
                       "create_atoms 1 single %s 0.52 units box\n"
                       "set atom 1 diameter 1.0 density 1.9098593\n"
                       "velocity all set %s -0.3 units box\n"
                       "set atom 1 omega 1 -2 3\n"
                       "timestep 0.0002\nfix 1 all nve/sphere\nfix 2 all gravity 10.0 vector 0 0 -1\n"
                       "thermo 0\n%s\nrun 6000\n";
    static const char *const start[][3] = {{"-1 -0.5", "2.4 0", "two.stl"},
                                           {"-1.3 -1.2", "2.4 2.2", "fan.stl"}};
    char wall[1024], s[4096];
    for (int m = 0; m < 2; m++)
        for (int k = 0; k < 2; k++) {
            double ref[9], got[9];
            snprintf(wall, sizeof wall, "fix w all wall/gran %s zplane 0 NULL", model[m]);
            snprintf(s, sizeof s, deck, start[k][0], start[k][1], wall);
            int ok = run_state(s, ref, 1) == GR_OK;
            snprintf(wall, sizeof wall, "fix m all mesh/surface file %s type 1\n"
                     "fix w all wall/gran %s mesh n_meshes 1 meshes m", path(start[k][2]),
                     model[m]);
            snprintf(s, sizeof s, deck, start[k][0], start[k][1], wall);
            ok = ok && run_state(s, got, 1) == GR_OK;
            double d = ok ? max_diff(ref, got, 9) : 1e9;
            printf("  granular model %d on %s: end at %.6g %.6g, max |diff| %.3g\n", m,
                   start[k][2], got[0], got[1], d);
            CHECK(ok && d <= 1e-12);
            /* it rolled across the diagonal (square) or past the centre (fan), resting */
            CHECK(k == 0 ? got[1] - got[0] < 0 : got[0] > 0.05 && got[1] > 0.05);
            CHECK(fabs(got[2] - 0.5) < 0.01);
        }
}

/* A sphere resting on a convex ridge (two triangles share the edge) and on
 * the apex of a pyramid (four share the vertex) feels one contact: it sinks
 * m g / kn, not half of it. */
TEST(convex_edge_and_vertex_count_once)
{
    double tent[36] = {-1, -2, 0, 0, -2, 1, 0, 2, 1,   -1, -2, 0, 0, 2, 1, -1, 2, 0,
                       1, -2, 0, 0, 2, 1, 0, -2, 1,    1, -2, 0, 1, 2, 0, 0, 2, 1};
    write_ascii_stl("tent.stl", tent, 4);
    double pyr[36] = {0, 0, 1, -1, -1, 0, 1, -1, 0,   0, 0, 1, 1, -1, 0, 1, 1, 0,
                      0, 0, 1, 1, 1, 0, -1, 1, 0,     0, 0, 1, -1, 1, 0, -1, -1, 0};
    write_ascii_stl("pyr.stl", pyr, 4);
    const char *deck = "units lj\natom_style sphere\nboundary f f f\n"
                       "region b block -3 3 -3 3 -1 4\ncreate_box 1 b\n"
                       "create_atoms 1 single %s units box\n"
                       "set atom 1 diameter 1.0 density 1.9098593\n"
                       "pair_style gran/hooke 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
                       "timestep 0.001\nfix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
                       "fix m all mesh/surface file %s type 1\n"
                       "fix w all wall/gran hooke 2000 NULL 200 NULL 0.5 1 mesh n_meshes 1 meshes m\n"
                       "thermo 0\nrun 4000\n";
    const char *files[2] = {"tent.stl", "pyr.stl"};
    const char *at[2] = {"0 0.3 1.5", "0 0 1.5"};
    for (int k = 0; k < 2; k++) {
        char s[2048];
        snprintf(s, sizeof s, deck, at[k], path(files[k]));
        double st[9];
        if (run_state(s, st, 1) != GR_OK)
            continue;
        CHECK_NEAR(st[2], 1.5 - 1.0 / 2000.0, 1e-6);
        CHECK_NEAR(st[0], 0.0, 1e-12);
    }
}

/* fix wall/pair ... mesh: hertz/mindlin with rolling resistance and
 * linear/restitution against a two-triangle floor = against wall/pair zplane,
 * rolling across the shared edge */
TEST(wall_pair_mesh)
{
    double two[18] = {-5, -5, 0, 5, -5, 0, 5, 5, 0, -5, -5, 0, 5, 5, 0, -5, 5, 0};
    write_ascii_stl("two.stl", two, 2);
    const char *deck = "units si\natom_style sphere\nboundary f f f\n"
                       "region b block -0.1 0.1 -0.1 0.1 -0.01 0.1\ncreate_box 1 b\n"
                       "create_atoms 1 single -0.0055 -0.005 0.00149 units box\n"
                       "set atom 1 diameter 0.003 density 2500\n"
                       "velocity all set 0.2 0 0 units box\nset atom 1 omega 0 30 0\n"
                       "%s\npair_coeff * *\n"
                       "timestep 1e-6\nfix 1 all nve/sphere\nfix 2 all gravity 9.81 vector 0 0 -1\n"
                       "thermo 0\n%s\nrun 8000\n";
    const char *pairs[2] = {"pair_style hertz/mindlin 6.396e7 0.23 0.66 0.154 rolling 0.05",
                            "pair_style linear/restitution 1000 0.8 0.3"};
    for (int k = 0; k < 2; k++) {
        char wall[512], s[4096];
        double ref[9], got[9];
        snprintf(s, sizeof s, deck, pairs[k], "fix w all wall/pair zplane 0 NULL");
        if (run_state(s, ref, 1) != GR_OK)
            continue;
        snprintf(wall, sizeof wall, "fix m all mesh/surface file %s type 1\n"
                 "fix w all wall/pair mesh n_meshes 1 meshes m", path("two.stl"));
        snprintf(s, sizeof s, deck, pairs[k], wall);
        if (run_state(s, got, 1) != GR_OK)
            continue;
        double d = max_diff(ref, got, 9);
        CHECK(d <= 1e-10);
        if (d > 1e-10)
            printf("  %s: max |diff| %.3g\n", pairs[k], d);
        CHECK(got[1] - got[0] < 0);   /* crossed the diagonal y = x */
    }
}

/* A rotating drum of N flat facets (circumscribed: the facet centres on the
 * circle) converges to wall/gran zcylinder with azimuthal shear as N grows:
 * a sphere dragged up the inside of the turning drum. */
TEST(faceted_drum_converges)
{
    const double R = 2.0;
    const char *deck = "units lj\natom_style sphere\nboundary f f f\n"
                       "region b block -3 3 -3 3 -1.5 1.5\ncreate_box 1 b\n"
                       "create_atoms 1 single 0 -1.5 0 units box\n"
                       "set atom 1 diameter 1.0 density 1.9098593\n"
                       "pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
                       "timestep 0.0005\nfix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 -1 0\n"
                       "thermo 0\n%s\nrun 4000\n";
    char s[4096], wall[1024];
    double ref[9], got[9];
    /* surface speed omega R = 1 counterclockwise about +z: vshear = -omega R */
    snprintf(s, sizeof s, deck, "fix w all wall/gran " WALL " zcylinder 2 shear x -1.0");
    if (run_state(s, ref, 1) != GR_OK)
        return;
    CHECK(ref[0] > 0.05);   /* dragged towards +x and up */
    const int nf[3] = {16, 64, 256};
    double err[3];
    for (int k = 0; k < 3; k++) {
        int n = nf[k];
        double rv = R / cos(M_PI / n);
        double *soup = malloc((size_t)2 * n * 9 * sizeof(double));
        for (int f = 0; f < n; f++) {
            double a0 = 2 * M_PI * (f - 0.5) / n - M_PI / 2, a1 = 2 * M_PI * (f + 0.5) / n - M_PI / 2;
            double p0[3] = {rv * cos(a0), rv * sin(a0), -1}, p1[3] = {rv * cos(a1), rv * sin(a1), -1};
            double q0[3] = {p0[0], p0[1], 1}, q1[3] = {p1[0], p1[1], 1};
            double *t = soup + 18 * f;
            memcpy(t, p0, 24); memcpy(t + 3, p1, 24); memcpy(t + 6, q1, 24);
            memcpy(t + 9, p0, 24); memcpy(t + 12, q1, 24); memcpy(t + 15, q0, 24);
        }
        write_ascii_stl("drum.stl", soup, 2 * n);
        free(soup);
        snprintf(wall, sizeof wall, "fix m all mesh/surface file %s type 1\n"
                 "fix r all move/mesh mesh m rotate origin 0 0 0 axis 0 0 1 period %.17g\n"
                 "fix w all wall/gran " WALL " mesh n_meshes 1 meshes m", path("drum.stl"),
                 4 * M_PI);
        snprintf(s, sizeof s, deck, wall);
        if (run_state(s, got, 1) != GR_OK)
            return;
        err[k] = max_diff(ref, got, 9);
        printf("  drum of %d facets: max |diff| from zcylinder %.3g\n", n, err[k]);
    }
    CHECK(err[1] < err[0] && err[2] < err[1]);
    CHECK(err[2] < 0.02);
}

/* A damped contact never gains energy: spheres hit a face, a convex ridge
 * (edge) and a pyramid apex (vertex) at 5 to 85 degrees to the horizontal;
 * after the bounce translational + rotational energy is below the start. */
TEST(energy_on_faces_edges_vertices)
{
    /* the three features, copies side by side along x, each target at z = 1 */
    const double feat[3][36] = {
        {-2, -2, 1, 2, -2, 1, 2, 2, 1,  -2, -2, 1, 2, 2, 1, -2, 2, 1},
        {-1, -2, 0, 0, -2, 1, 0, 2, 1,  -1, -2, 0, 0, 2, 1, -1, 2, 0,
         1, -2, 0, 0, 2, 1, 0, -2, 1,   1, -2, 0, 1, 2, 0, 0, 2, 1},
        {0, 0, 1, -1, -1, 0, 1, -1, 0,  0, 0, 1, 1, -1, 0, 1, 1, 0,
         0, 0, 1, 1, 1, 0, -1, 1, 0,    0, 0, 1, -1, 1, 0, -1, -1, 0},
    };
    const int ntri[3] = {2, 4, 4};
    const double angle[5] = {5, 25, 45, 65, 85};
    double soup[15 * 4 * 9];
    int n = 0;
    for (int f = 0; f < 3; f++)
        for (int a = 0; a < 5; a++) {
            double ox = 10.0 * (5 * f + a) - 70;
            for (int t = 0; t < ntri[f]; t++, n++)
                for (int v = 0; v < 3; v++) {
                    soup[9 * n + 3 * v] = feat[f][9 * t + 3 * v] + ox;
                    soup[9 * n + 3 * v + 1] = feat[f][9 * t + 3 * v + 1];
                    soup[9 * n + 3 * v + 2] = feat[f][9 * t + 3 * v + 2];
                }
        }
    write_ascii_stl("features.stl", soup, n);
    char s[16384];
    int len = snprintf(s, sizeof s, "units lj\natom_style sphere\nboundary f f f\n"
                       "region b block -80 80 -5 5 -5 10\ncreate_box 1 b\n");
    for (int f = 0; f < 3; f++)
        for (int a = 0; a < 5; a++) {
            int k = 5 * f + a;
            double ox = 10.0 * k - 70, th = angle[a] * M_PI / 180;
            double vx = 2 * cos(th), vz = -2 * sin(th);
            /* aimed so that the centre would pass (ox, y, 1.45) at t = 0.5: y = 0.3 off
             * the ridge line on the face and ridge, on the apex for the pyramid */
            len += snprintf(s + len, sizeof s - len,
                            "create_atoms 1 single %.17g %g %.17g units box\n", ox - 0.5 * vx,
                            f == 2 ? 0.0 : 0.3, 1.45 - 0.5 * vz);
            len += snprintf(s + len, sizeof s - len,
                            "group g%d id %d\nvelocity g%d set %.17g 0 %.17g units box\n", k,
                            k + 1, k, vx, vz);
        }
    snprintf(s + len, sizeof s - len,
             "set group all diameter 1.0 density 1.9098593\n"
             "pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
             "timestep 0.0005\nfix 1 all nve/sphere\n"
             "fix m all mesh/surface file %s type 1\n"
             "fix w all wall/gran hooke/history 2000 NULL 50 NULL 0.5 1 mesh n_meshes 1 meshes m\n"
             "thermo 0\nrun 2000\n", path("features.stl"));
    double st[15 * 9];
    if (run_state(s, st, 15) != GR_OK)
        return;
    /* m = 1, I = 2/5 m r^2 = 0.1; start energy 1/2 m |v|^2 = 2 */
    for (int k = 0; k < 15; k++) {
        const double *v = st + 9 * k + 3, *w = st + 9 * k + 6;
        double e = 0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
                   0.5 * 0.1 * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        if (!(e <= 2.0 * (1 + 1e-12)) || !(e < 1.99))
            printf("  feature %d angle %g: energy %.6g after the bounce (start 2)\n", k / 5,
                   angle[k % 5], e);
        CHECK(e <= 2.0 * (1 + 1e-12));
        CHECK(e < 1.99);   /* the sphere did hit something */
    }
}

/* a floor moving in its plane = LAMMPS' shear wall */
TEST(linear_equals_shear)
{
    double fl[18] = {-50, -50, 0, 50, -50, 0, 50, 50, 0, -50, -50, 0, 50, 50, 0, -50, 50, 0};
    write_ascii_stl("floor.stl", fl, 2);
    const char *deck = "units lj\natom_style sphere\nboundary f f f\n"
                       "region b block -6 6 -6 6 -1 6\ncreate_box 1 b\n"
                       "create_atoms 1 single 0 0 0.6 units box\n"
                       "create_atoms 1 single 2 1 1.5 units box\n"
                       "set group all diameter 1.0 density 1.9098593\n"
                       "pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
                       "timestep 0.0005\nfix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
                       "thermo 0\n%s\nrun 4000\n";
    char wall[512], s[4096];
    double ref[18], got[18];
    snprintf(s, sizeof s, deck, "fix w all wall/gran " WALL " zplane 0 NULL shear x 0.7");
    run_state(s, ref, 2);
    snprintf(wall, sizeof wall, "fix m all mesh/surface file %s type 1\n"
             "fix mv all move/mesh mesh m linear 0.7 0 0\n"
             "fix w all wall/gran " WALL " mesh n_meshes 1 meshes m", path("floor.stl"));
    snprintf(s, sizeof s, deck, wall);
    run_state(s, got, 2);
    CHECK(max_diff(ref, got, 18) <= 1e-10);
    CHECK(got[3] > 0.1);   /* friction dragged the sphere along x */
}

/* a sphere at rest on the floor: the force on the mesh is its weight */
TEST(mesh_force_output)
{
    double fl[18] = {-5, -5, 0, 5, -5, 0, 5, 5, 0, -5, -5, 0, 5, 5, 0, -5, 5, 0};
    write_ascii_stl("floor.stl", fl, 2);
    char s[4096];
    snprintf(s, sizeof s, "units lj\natom_style sphere\nboundary f f f\n"
             "region b block -6 6 -6 6 -1 6\ncreate_box 1 b\n"
             "create_atoms 1 single 1 2 0.5 units box\n"
             "set atom 1 diameter 1.0 density 1.9098593\n"
             "pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
             "timestep 0.0005\nfix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
             "fix m all mesh/surface file %s type 1 reference_point 0 0 0\n"
             "fix w all wall/gran " WALL " mesh n_meshes 1 meshes m\n"
             "variable fz equal f_m[3]\nvariable ty equal f_m[5]\n"
             "thermo_style custom step f_m[1] f_m[2] f_m[3] f_m[4] f_m[5] f_m[6] f_m[7]\n"
             "thermo 1000\nrun 6000\n", path("floor.stl"));
    struct gravel *g = test_engine();
    CHECK(test_script(g, s) == GR_OK);
    double fz = 0, ty = 0;
    CHECK(thermo_keyword_value(g, "f_m[3]", &fz));
    CHECK(thermo_keyword_value(g, "f_m[5]", &ty));
    CHECK_NEAR(fz, -1.0, 1e-6);
    /* torque about the origin of the weight at (1, 2, 0): r x F = (2 * -1, -(1 * -1), 0) */
    CHECK_NEAR(ty, 1.0, 1e-6);
    double vfz = 0;
    CHECK(thermo_keyword_value(g, "v_fz", &vfz));   /* f_ID[i] in an equal-style variable */
    CHECK(vfz == fz);
    gr_destroy(g);
}

/* run 2N = run N + write_restart + read_restart + run N, bit for bit, with a
 * rotating box mesh and contact history on its triangles */
TEST(restart_exact)
{
    double b[108];
    int n = box_soup(-2, 2, b);
    write_ascii_stl("box.stl", b, n);
    char setup[2048], styles[1024], s[4096];
    snprintf(styles, sizeof styles,
             "pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
             "timestep 0.0005\nfix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
             "fix m all mesh/surface file %s type 1\n"
             "fix r all move/mesh mesh m rotate origin 0 0 0 axis 0 1 0 period 40\n"
             "fix w all wall/gran " WALL " mesh n_meshes 1 meshes m\nthermo 0\n",
             path("box.stl"));
    snprintf(setup, sizeof setup, "units lj\natom_style sphere\nboundary f f f\n"
             "region b block -3 3 -3 3 -3 3\ncreate_box 1 b\n"
             "region inner block -1.5 1.5 -1.5 1.5 -1.5 1.5\nlattice sc 0.6\n"
             "create_atoms 1 region inner\nset group all diameter 0.8 density 1.0\n"
             "velocity all create 5.0 4928459 loop geom\n%s", styles);
    double full[27 * 9], half[27 * 9];
    snprintf(s, sizeof s, "%srun 3000\n", setup);
    if (run_state(s, full, 27) != GR_OK)
        return;
    snprintf(s, sizeof s, "%srun 1500\nwrite_restart %s\n", setup, path("r.bin"));
    struct gravel *g = test_engine();
    CHECK(test_script(g, s) == GR_OK);
    gr_destroy(g);
    snprintf(s, sizeof s, "read_restart %s\n%srun 1500\n", path("r.bin"), styles);
    if (run_state(s, half, 27) != GR_OK)
        return;
    CHECK(max_diff(full, half, 27 * 9) == 0.0);
}

/* rotate about z through (1, 0, 0) then translate: closed form pose */
TEST(stacked_pose)
{
    double fl[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    write_ascii_stl("tri.stl", fl, 1);
    char s[2048];
    snprintf(s, sizeof s, "units lj\natom_style sphere\nregion b block -4 4 -4 4 -4 4\n"
             "create_box 1 b\ntimestep 0.01\nfix m all mesh/surface file %s type 1\n"
             "fix r all move/mesh mesh m rotate origin 1 0 0 axis 0 0 1 period 8\n"
             "fix l all move/mesh mesh m linear 0.5 0 0.25\n", path("tri.stl"));
    struct gravel *g = test_engine();
    CHECK(test_script(g, s) == GR_OK);
    g->step = 100;  /* t = 1: angle pi/4 */
    struct mesh_pose p;
    mesh_surface_pose(g, "m", &p);
    double a = M_PI / 4, w = 2 * M_PI / 8;
    CHECK(p.moving);
    CHECK_NEAR(p.R[0], cos(a), 1e-14);
    CHECK_NEAR(p.R[1], -sin(a), 1e-14);
    CHECK_NEAR(p.R[3], sin(a), 1e-14);
    /* the mesh vertex (0,0,0) is at o + R(-o) + (0.5, 0, 0.25) */
    CHECK_NEAR(p.d[0], 1 - cos(a) + 0.5, 1e-14);
    CHECK_NEAR(p.d[1], -sin(a), 1e-14);
    CHECK_NEAR(p.d[2], 0.25, 1e-14);
    CHECK_NEAR(p.omega[2], w, 1e-14);
    CHECK_NEAR(p.omega[0], 0, 1e-14);
    /* velocity of the moved vertex x = d: omega x (x - o) + v_lin, with the
     * rotation centre o = (1, 0, 0) + (0.5, 0, 0.25) t ... here the linear
     * motion follows the rotation, so v = omega x (x - o_rot) + v_lin with
     * o_rot the rotation origin translated: (1.5, 0, 0.25) */
    double x[3] = {p.d[0], p.d[1], p.d[2]};
    double vx = p.V0[0] - p.omega[2] * x[1], vy = p.V0[1] + p.omega[2] * x[0];
    double ox = 1.5, oy = 0;
    CHECK_NEAR(vx, -w * (x[1] - oy) + 0.5, 1e-13);
    CHECK_NEAR(vy, w * (x[0] - ox), 1e-13);
    CHECK_NEAR(p.V0[2], 0.25, 1e-14);
    gr_destroy(g);
}

TEST(dump_mesh_vtk)
{
    double fl[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    write_ascii_stl("tri.stl", fl, 1);
    char s[2048];
    snprintf(s, sizeof s, "units lj\natom_style sphere\nregion b block -4 4 -4 4 -4 4\n"
             "create_box 1 b\ncreate_atoms 1 single 0 0 3 units box\ntimestep 0.01\n"
             "fix 1 all nve/sphere\n"
             "fix m all mesh/surface file %s type 1 move 1 0 0\n"
             "fix l all move/mesh mesh m linear 0 0 1\n"
             "dump d all mesh/vtk 100 %s\nthermo 0\nrun 100\n", path("tri.stl"), path("m.vtk"));
    struct gravel *g = test_engine();
    CHECK(test_script(g, s) == GR_OK);
    gr_destroy(g);
    FILE *fp = fopen(path("m.vtk"), "r");
    CHECK(fp != NULL);
    char text[4096] = "";
    if (fp) {
        size_t n = fread(text, 1, sizeof text - 1, fp);
        text[n] = 0;
        fclose(fp);
    }
    CHECK(strstr(text, "DATASET POLYDATA") != NULL);
    CHECK(strstr(text, "POINTS 3 double\n1 0 1\n2 0 1\n1 1 1\n") != NULL);
    CHECK(strstr(text, "POLYGONS 1 4\n3 0 1 2\n") != NULL);
    CHECK(strstr(text, "velocity 3 1 double\n0 0 1\n") != NULL);
    /* our own dump reads back as a mesh (its FIELD data skipped) */
    struct mesh m;
    char err[256] = "";
    CHECK(mesh_read(path("m.vtk"), 0, &m, err, sizeof err) == 0);
    CHECK(m.ntri == 1 && m.nvert == 3 && m.vert[0] == 1 && m.vert[2] == 1);
    mesh_free(&m);
}

/* fix mesh/surface/planar's geometry (src/state/mesh_planar.c): the unit
 * square of two triangles, its four border edges active and the diagonal
 * not; LIGGGHTS's edgePointDist across, beyond and within an edge; a
 * folded square is not planar, a slight fold passes a 10 degree curvature. */
TEST(planar_edges)
{
    double sq[18] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
    struct mesh m;
    char err[256];
    CHECK(mesh_from_soup("square", sq, 2, 0, &m, err, sizeof err) == 0);
    CHECK(mesh_planar_check(&m, 1. - 1e-5) == -1);
    struct mesh_planar p = {0};
    CHECK(mesh_planar_build(&m, &p) == 0);
    /* 2 triangles x (3 own edges x 2 active edges of each triangle) = 12
     * candidates per triangle: the list is full and never names the diagonal */
    for (int t = 0; t < 2; t++)
        for (int q = 0; q < MESH_PLANAR_NEDGE; q++) {
            int j = p.edge_tri[MESH_PLANAR_NEDGE * t + q], k = p.edge_k[MESH_PLANAR_NEDGE * t + q];
            CHECK(j >= 0 && m.nbr[3 * j + k] == -1);
        }
    CHECK_NEAR(p.min_dist[0], 0., 0);   /* a vertex of its own edge */
    const double x[3] = {0.5, 0.2, 0.}, far[3] = {2., -1., 0.};
    CHECK_NEAR(mesh_edge_point_dist(&m, 0, 0, x), 0.2, 1e-15);     /* across edge (0,0)-(1,0) */
    CHECK_NEAR(mesh_edge_point_dist(&m, 0, 0, far), sqrt(2.), 1e-15); /* beyond its end (1,0) */
    CHECK(!mesh_planar_far(&m, &p, 0, x, 0.25));
    const double mid[3] = {0.6, 0.4, 0.};
    CHECK(mesh_planar_far(&m, &p, 0, mid, 0.39));
    mesh_planar_free(&p);
    mesh_free(&m);
    /* fold the second triangle's free vertex out of the plane */
    double fold[18];
    memcpy(fold, sq, sizeof fold);
    fold[17] = 0.1;   /* (0, 1, 0.1): about 5.7 degrees */
    CHECK(mesh_from_soup("fold", fold, 2, 0, &m, err, sizeof err) == 0);
    CHECK(mesh_planar_check(&m, 1. - 1e-5) == 0);
    CHECK(mesh_planar_check(&m, cos(10. * M_PI / 180.)) == -1);
    mesh_free(&m);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/gravel_mesh_XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    RUN(read_ascii_stl);
    RUN(read_binary_stl);
    RUN(read_vtk);
    RUN(welding);
    RUN(bins_cover_reach);
    RUN(bad_meshes);
    RUN(reader_survives_garbage);
    RUN(command_errors);
    RUN(box_equals_planes);
    RUN(shared_edge_and_vertex);
    RUN(granular_mesh_equals_plane);
    RUN(convex_edge_and_vertex_count_once);
    RUN(wall_pair_mesh);
    RUN(linear_equals_shear);
    RUN(faceted_drum_converges);
    RUN(energy_on_faces_edges_vertices);
    RUN(mesh_force_output);
    RUN(restart_exact);
    RUN(stacked_pose);
    RUN(dump_mesh_vtk);
    RUN(planar_edges);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        return 1;
    return 0;
}
