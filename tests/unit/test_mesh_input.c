/* test_mesh_input.c - mesh files a careless user or an attacker hands in
 * (src/state/mesh.c) and rotation axes (rm_unit_axis, src/state/rigid_math.c):
 *  - welding is linear: 120,000 copies of one triangle (VTK) and a
 *    40,000-triangle wall in the plane x = 0 (ASCII STL) load in a few
 *    seconds of CPU time (the sorted sweep took > 60 s and 10 s), with the
 *    exact vertex count; a chain of vertices each within the tolerance of the
 *    next is one vertex, numbered and placed by its first appearance;
 *  - a vertex token over 127 characters, a NUL byte in an ASCII STL or a
 *    text file, an ASCII STL cut short, VTK counts the file cannot hold
 *    (no allocation of gigabytes), triangles of size 1e200 and 1e-300,
 *    create_atoms ... mesh m 1e308 and a scale or move beyond 1e75 get
 *    messages saying what is wrong;
 *  - rotation axes of any finite length: rotate axis 0 0 1e300 (and 1e-300)
 *    turns a mesh, a move/mesh rotation and displace_atoms exactly as 0 0 1;
 *    zero or non-finite axes are refused. */
#include <stdint.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#include "test.h"
#include "atoms.h"
#include "fix.h"
#include "fix_mesh_surface.h"
#include "mesh.h"
#include "rigid_math.h"

static char dir[64];

static const char *path(const char *name)
{
    static char buf[4][256];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

static void write_bytes(const char *name, const char *b, size_t n)
{
    FILE *fp = fopen(path(name), "wb");
    fwrite(b, 1, n, fp);
    fclose(fp);
}

static void write_text(const char *name, const char *text)
{
    write_bytes(name, text, strlen(text));
}

static double cpu_seconds(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

/* mesh_read(file) fails with a message holding `what` and the file name. */
static void check_bad(const char *file, const char *what)
{
    struct mesh m;
    char err[512] = "";
    int rc = mesh_read(path(file), 0, &m, err, sizeof err);
    if (rc != -1 || !strstr(err, what) || !strstr(err, file)) {
        printf("  check failed: %s: expected '%s', got rc %d '%s'\n", file, what, rc, err);
        t_failed_checks++;
    }
    if (rc == 0)
        mesh_free(&m);
}

/* ---- welding ------------------------------------------------------------------- */

TEST(weld_copies_linear)
{
    const int n = 120000;
    FILE *fp = fopen(path("copies.vtk"), "w");
    fprintf(fp, "# vtk DataFile Version 3.0\ncopies\nASCII\nDATASET POLYDATA\nPOINTS %d float\n",
            3 * n);
    for (int i = 0; i < n; i++)
        fputs("0 0 0\n1 0 0\n0 1 0\n", fp);
    fprintf(fp, "POLYGONS %d %d\n", n, 4 * n);
    for (int i = 0; i < n; i++)
        fprintf(fp, "3 %d %d %d\n", 3 * i, 3 * i + 1, 3 * i + 2);
    fclose(fp);
    struct mesh m;
    char err[512] = "";
    double t0 = cpu_seconds();
    int rc = mesh_read(path("copies.vtk"), 0, &m, err, sizeof err);
    double t = cpu_seconds() - t0;
    printf("  120000 copies of one triangle: %.2f s CPU\n", t);
    CHECK(rc == 0);
    CHECK(t < 5.0);
    if (rc == 0) {
        CHECK(m.ntri == n);
        CHECK(m.nvert == 3);
        CHECK(m.nedge == 3);
        CHECK(m.nbr[0] == -1);  /* an edge of 120000 triangles has no single neighbour */
        mesh_free(&m);
    }
}

TEST(weld_plane_linear)
{
    /* 100 x 200 unit squares in the plane x = 0, two triangles each */
    FILE *fp = fopen(path("plane.stl"), "w");
    fputs("solid plane\n", fp);
    for (int i = 0; i < 100; i++)
        for (int j = 0; j < 200; j++) {
            int q[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
            int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int h = 0; h < 2; h++) {
                fputs(" facet normal 1 0 0\n  outer loop\n", fp);
                for (int k = 0; k < 3; k++)
                    fprintf(fp, "   vertex 0 %d %d\n", q[tri[h][k]][0], q[tri[h][k]][1]);
                fputs("  endloop\n endfacet\n", fp);
            }
        }
    fputs("endsolid plane\n", fp);
    fclose(fp);
    struct mesh m;
    char err[512] = "";
    double t0 = cpu_seconds();
    int rc = mesh_read(path("plane.stl"), 0, &m, err, sizeof err);
    double t = cpu_seconds() - t0;
    printf("  40000-triangle wall in x = 0: %.2f s CPU\n", t);
    CHECK(rc == 0);
    CHECK(t < 5.0);
    if (rc == 0) {
        CHECK(m.ntri == 40000);
        CHECK(m.nvert == 101 * 201);
        CHECK(m.nedge == 100 * 201 + 101 * 200 + 100 * 200);
        /* vertex numbering by first appearance: triangle 0 is (0,0) (1,0) (1,1) */
        CHECK(m.tri[0] == 0 && m.tri[1] == 1 && m.tri[2] == 2);
        CHECK(m.vert[3 * 2 + 1] == 1 && m.vert[3 * 2 + 2] == 1);
        mesh_free(&m);
    }
}

TEST(weld_chain)
{
    /* tolerance 0.1: (1,0,0) - (1.07,0,0) - (1.14,0,0) is a chain of links,
     * so one vertex although its ends are 0.14 apart; it keeps the first
     * coordinates. (0,1.06,0) joins (0,1,0). */
    double s[27] = {0, 0, 0,    1, 0, 0,    0, 1, 0,
                    1.07, 0, 0, 1, 1, 0,    0, 1.06, 0,
                    1.14, 0, 0, 2, 0, 0,    1.5, -1, 0};
    struct mesh m;
    char err[256] = "";
    CHECK(mesh_from_soup("chain", s, 3, 0.1, &m, err, sizeof err) == 0);
    CHECK(m.nvert == 6);
    int want[9] = {0, 1, 2, 1, 3, 2, 1, 4, 5};
    for (int i = 0; i < 9; i++)
        CHECK(m.tri[i] == want[i]);
    CHECK(m.vert[3] == 1 && m.vert[4] == 0 && m.vert[5] == 0);
    CHECK(m.vert[7] == 1); /* vertex 2 at (0, 1, 0), not 1.06 */
    CHECK(m.nbr[3 * 0 + 1] == 1);    /* edge (1, 2) is shared by triangles 0 and 1 */
    mesh_free(&m);
    /* -0 and +0 are one coordinate; tolerance 0 still joins exact copies */
    double z[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, -0.0, -0.0, -0.0, 0, 1, 0, 0, 0, 1};
    CHECK(mesh_from_soup("zero", z, 2, 1e-300, &m, err, sizeof err) == 0);
    CHECK(m.nvert == 4);
    mesh_free(&m);
}

/* ---- parsing messages ------------------------------------------------------------ */

static const char *stl_head = "solid x\nfacet normal 0 0 1\nouter loop\n";
static const char *stl_tail = "endloop\nendfacet\nendsolid x\n";

TEST(long_and_nul_tokens)
{
    char t[1024];
    char num[200];
    memset(num, '0', sizeof num);
    memcpy(num, "0.5", 3);
    memcpy(num + 190, "abc", 4);  /* 193 characters */
    snprintf(t, sizeof t, "%svertex %s 0 0\nvertex 1 0 0\nvertex 0 1 0\n%s", stl_head, num,
             stl_tail);
    write_text("long.stl", t);
    check_bad("long.stl", "long.stl:4: expected a vertex coordinate");
    check_bad("long.stl", "a token longer than 127 characters");
    /* a legitimate number, but longer than a token: refused, never cut */
    num[190] = 0;
    snprintf(t, sizeof t, "%svertex %s 0 0\nvertex 1 0 0\nvertex 0 1 0\n%s", stl_head, num,
             stl_tail);
    write_text("long2.stl", t);
    check_bad("long2.stl", "a token longer than 127 characters");
    /* a NUL byte in a VTK token is not a number */
    static const char vtk[] = "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
                              "POINTS 3 float\n0 0 0 1\0abc 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n";
    write_bytes("nul.vtk", vtk, sizeof vtk - 1);
    check_bad("nul.vtk", "point 1 is missing or bad");
}

TEST(text_files)
{
    /* an ASCII STL with one NUL byte: an ASCII STL, not a truncated binary one */
    char t[512];
    int n = snprintf(t, sizeof t, "%svertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n%s", stl_head,
                     stl_tail);
    t[50] = 0;
    write_bytes("nulascii.stl", t, (size_t)n);
    check_bad("nulascii.stl", "nulascii.stl:4: ASCII STL file with a NUL byte (offset 50)");
    static const char txt[] = "these are my notes\nnot a mesh\0 at all\n";
    write_bytes("notes.stl", txt, sizeof txt - 1);
    check_bad("notes.stl", "not a mesh file: text that starts with 'these are my notes' and "
                           "holds a NUL byte");
    write_text("hello.stl", "hello world\n");
    check_bad("hello.stl", "not a mesh file: text that starts with 'hello world'");
}

TEST(cut_short)
{
    char t[512];
    snprintf(t, sizeof t, "%svertex 0 0 0\nvertex 1 0\n", stl_head);
    write_text("cut1.stl", t);
    check_bad("cut1.stl", "cut1.stl:6: unexpected end of file: the file is cut short in "
                          "triangle 0, expected a vertex coordinate");
    snprintf(t, sizeof t, "%svertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendlo", stl_head);
    write_text("cut2.stl", t);
    check_bad("cut2.stl", "cut2.stl:7: the file is cut short in triangle 0: it ends in 'endlo', "
                          "expected 'endloop'");
    snprintf(t, sizeof t, "%svertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0.2", stl_head);
    write_text("cut3.stl", t);
    check_bad("cut3.stl", "cut3.stl:6: the file is cut short in triangle 0: it ends in '0.2'");
    /* a wrong token that is not at the end still says what was expected */
    snprintf(t, sizeof t, "%svertex 0 0 0\nvertex 1 zero 0\nvertex 0 1 0\n%s", stl_head,
             stl_tail);
    write_text("word.stl", t);
    check_bad("word.stl", "word.stl:5: expected a vertex coordinate, got 'zero' (triangle 0)");
}

TEST(vtk_counts_fit)
{
    /* counts that the file cannot hold are refused before they are allocated */
    write_text("pts.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
                          "POINTS 200000000 float\n0 0 0 1 0 0 0 1 0\n");
    check_bad("pts.vtk", "pts.vtk:5: POINTS: 200000000 points cannot fit in the 19 bytes left");
    write_text("cells.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
                            "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 300000000 1200000000\n"
                            "3 0 1 2\n");
    check_bad("cells.vtk", "POLYGONS: 300000000 triangles cannot fit in the 9 bytes left");
    write_text("cells5.vtk", "# vtk DataFile Version 5.1\nx\nASCII\nDATASET POLYDATA\n"
                             "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 100000 299997\n"
                             "OFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\n");
    check_bad("cells5.vtk", "99999 triangles cannot fit");
    /* a second POINTS section after the cells (which index the first one) */
    write_text("twice.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
                            "POINTS 5 float\n0 0 0 1 0 0 0 1 0 0 0 1 1 1 1\nPOLYGONS 1 4\n"
                            "3 2 3 4\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n");
    check_bad("twice.vtk", "twice.vtk:9: a second POINTS section");
}

TEST(scale_limits)
{
    double big[9] = {0, 0, 0, 1e200, 0, 0, 0, 1e200, 0};
    double tiny[9] = {0, 0, 0, 1e-300, 0, 0, 0, 1e-300, 0};
    struct mesh m;
    char err[512] = "";
    CHECK(mesh_from_soup("big", big, 1, 0, &m, err, sizeof err) == -1);
    CHECK(strstr(err, "big: triangle 0: vertex 1 has coordinate 1e+200, beyond 1e+75: its area "
                      "would overflow double precision") != NULL);
    CHECK(mesh_from_soup("tiny", tiny, 1, 0, &m, err, sizeof err) == -1);
    CHECK(strstr(err, "tiny: triangle 0: degenerate at this scale: its edges (1e-300) are "
                      "shorter than 1e-75") != NULL);
    /* the limits themselves are fine */
    double lim[9] = {0, 0, 0, 1e75, 0, 0, 0, 1e75, 0};
    CHECK(mesh_from_soup("lim", lim, 1, 0, &m, err, sizeof err) == 0);
    mesh_free(&m);
    double small[9] = {0, 0, 0, 1e-70, 0, 0, 0, 1e-70, 0};
    CHECK(mesh_from_soup("small", small, 1, 0, &m, err, sizeof err) == 0);
    mesh_free(&m);
    /* a triangle far smaller than the mesh is still one that welds away */
    double mix[18] = {2, 2, 2, 3, 2, 2, 2, 3, 2, 0, 0, 0, 1e-80, 0, 0, 0, 1e-80, 0};
    CHECK(mesh_from_soup("mix", mix, 2, 0, &m, err, sizeof err) == -1);
    CHECK(strstr(err, "triangle 1: zero area (two vertices coincide)") != NULL);
}

static const char *box_pre = "units lj\natom_style sphere\nregion b block -4 4 -4 4 -4 4\n"
                             "create_box 1 b\n";

TEST(create_atoms_huge_distance)
{
    write_text("tri.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                          "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
    char s[1024];
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1\n"
             "create_atoms 1 random 10 5 NULL mesh m 1e308\n", box_pre, path("tri.stl"));
    CHECK_ERROR(s, "create_atoms mesh m: distance 1e+308 is too large for the mesh grid", 6);
    /* 1e300 still works: every site is within it */
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1\n"
             "create_atoms 1 random 10 5 NULL mesh m 1e300\n", box_pre, path("tri.stl"));
    struct gravel *g = test_engine();
    CHECK(test_script(g, s) == GR_OK);
    CHECK(g->atoms.n == 0);
    gr_destroy(g);
}

TEST(transform_range)
{
    write_text("tri.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                          "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
    char s[1024];
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1 scale 1e300\n", box_pre,
             path("tri.stl"));
    CHECK_ERROR(s, "tri.stl: scale, move or rotate puts vertex 1 at (1e+300, 0, 0), beyond "
                   "1e+75", 5);
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1 move 0 0 2e75\n", box_pre,
             path("tri.stl"));
    CHECK_ERROR(s, "puts vertex 0 at (0, 0, 2e+75)", 5);
    /* the vertices collapse at 1e70 or shrink below what an area can hold */
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1 move 1e70 0 0\n", box_pre,
             path("tri.stl"));
    CHECK_ERROR(s, "tri.stl: scale, move or rotate leaves triangle 0 without an area", 5);
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1 scale 1e-300\n", box_pre,
             path("tri.stl"));
    CHECK_ERROR(s, "leaves triangle 0 without an area", 5);
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1 scale 1e70 move 0 0 1e70\n",
             box_pre, path("tri.stl"));
    struct gravel *g = test_engine();
    CHECK(test_script(g, s) == GR_OK);
    gr_destroy(g);
}

/* ---- rotation axes ---------------------------------------------------------------- */

TEST(unit_axis)
{
    double u[3];
    const double cases[][3] = {{0, 0, 1e300}, {0, 0, 1e-300}, {0, 0, 4.9e-324},
                               {0, 0, 1.7e308}};
    for (int c = 0; c < 4; c++) {
        CHECK(rm_unit_axis(cases[c], u) == 0);
        CHECK(u[0] == 0 && u[1] == 0 && u[2] == 1);
    }
    const double d[3] = {1e300, 1e300, 0};
    CHECK(rm_unit_axis(d, u) == 0);
    CHECK_NEAR(u[0], sqrt(0.5), 2e-16);
    CHECK_NEAR(u[1], sqrt(0.5), 2e-16);
    /* an ordinary axis: a / |a| as before, bit for bit */
    const double a[3] = {1, 2, 3};
    double len = sqrt(14.0);
    CHECK(rm_unit_axis(a, u) == 0);
    CHECK(u[0] == 1 / len && u[1] == 2 / len && u[2] == 3 / len);
    const double z[3] = {0, 0, 0}, inf[3] = {0, INFINITY, 0}, nan[3] = {NAN, 0, 1};
    CHECK(rm_unit_axis(z, u) == -1);
    CHECK(rm_unit_axis(inf, u) == -1);
    CHECK(rm_unit_axis(nan, u) == -1);
}

/* the vertices of mesh m after fix mesh/surface ... rotate axis AXIS angle 90 */
static void rotated_mesh(const char *axis, double out[9])
{
    char s[1024];
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1 rotate axis %s angle 90\n",
             box_pre, path("tri.stl"), axis);
    struct gravel *g = test_engine();
    CHECK(test_script(g, s) == GR_OK);
    struct mesh_surface *ms = mesh_surface_get(g, "m", "test");
    memcpy(out, ms->m.vert, 9 * sizeof(double));
    gr_destroy(g);
}

TEST(huge_axes_rotate)
{
    write_text("tri.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                          "vertex 0 1 1\nendloop\nendfacet\nendsolid t\n");
    double ref[9], big[9], small[9];
    rotated_mesh("0 0 1", ref);
    rotated_mesh("0 0 1e300", big);
    rotated_mesh("0 0 1e-300", small);
    CHECK_NEAR(ref[3], 0, 1e-15);   /* (1,0,0) -> (0,1,0) */
    CHECK_NEAR(ref[4], 1, 1e-15);
    for (int i = 0; i < 9; i++)
        CHECK(big[i] == ref[i] && small[i] == ref[i]);
    char s[1024];
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1 rotate axis 0 0 0 angle 9\n",
             box_pre, path("tri.stl"));
    CHECK_ERROR(s, "fix mesh/surface rotate axis is zero", 5);
    /* fix move/mesh rotate: the unit axis */
    snprintf(s, sizeof s, "%stimestep 0.01\nfix m all mesh/surface file %s type 1\n"
             "fix r all move/mesh mesh m rotate origin 0 0 0 axis 0 0 1e300 period 8\n",
             box_pre, path("tri.stl"));
    struct gravel *g = test_engine();
    CHECK(test_script(g, s) == GR_OK);
    g->step = 200;   /* t = 2: a quarter turn */
    struct mesh_pose p;
    mesh_surface_pose(g, "m", &p);
    CHECK_NEAR(p.R[1], -1, 1e-15);
    CHECK_NEAR(p.R[3], 1, 1e-15);
    CHECK_NEAR(p.omega[2], 2 * M_PI / 8, 1e-15);
    gr_destroy(g);
    snprintf(s, sizeof s, "%sfix m all mesh/surface file %s type 1\n"
             "fix r all move/mesh mesh m rotate origin 0 0 0 axis 0 0 0 period 8\n", box_pre,
             path("tri.stl"));
    CHECK_ERROR(s, "fix move/mesh rotate axis is zero", 6);
    /* displace_atoms rotate */
    const char *axes[3] = {"0 0 1", "0 0 1e300", "0 0 1e-300"};
    double x[3][3];
    for (int k = 0; k < 3; k++) {
        snprintf(s, sizeof s, "%screate_atoms 1 single 1 0.5 0.25 units box\n"
                 "displace_atoms all rotate 0 0 0 %s 90 units box\n", box_pre, axes[k]);
        g = test_engine();
        CHECK(test_script(g, s) == GR_OK);
        memcpy(x[k], g->atoms.x, sizeof x[k]);
        gr_destroy(g);
    }
    CHECK_NEAR(x[0][0], -0.5, 1e-15);
    CHECK_NEAR(x[0][1], 1, 1e-15);
    CHECK_NEAR(x[0][2], 0.25, 1e-15);
    for (int d = 0; d < 3; d++)
        CHECK(x[1][d] == x[0][d] && x[2][d] == x[0][d]);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/gravel-meshin-XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    RUN(weld_copies_linear);
    RUN(weld_plane_linear);
    RUN(weld_chain);
    RUN(long_and_nul_tokens);
    RUN(text_files);
    RUN(cut_short);
    RUN(vtk_counts_fit);
    RUN(scale_limits);
    RUN(create_atoms_huge_distance);
    RUN(transform_range);
    RUN(unit_axis);
    RUN(huge_axes_rotate);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0)
        return 1;
    return 0;
}
