/* test_delete_change.c - delete_atoms (styles, exact counts of random,
 * compress and the next tag, errors) and change_box (final/delta/scale in
 * lattice and box units, remap, boundary and image flags, lost atoms, 2d
 * rules, errors). The lmp comparisons are tests/scripts/lammps_compat.py. */
#include "test.h"

#include <math.h>
#include <time.h>

#define BOX "lattice sc 1.0\nregion b block 0 4 0 4 0 4\ncreate_box 2 b\ncreate_atoms 1 box\n"

TEST(delete_styles)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, BOX) == GR_OK);
    CHECK(g->atoms.n == 64);
    CHECK(test_script(g, "region r block 0 0.5 INF INF INF INF\ndelete_atoms region r "
                         "compress no\n") == GR_OK);
    CHECK(g->atoms.n == 48); /* the x = 0 plane */
    CHECK(g->atoms.maxtag == 64); /* tag 64 (x = 3) is kept */
    CHECK(test_script(g, "group top id 60:64\ndelete_atoms group top compress no\n") == GR_OK);
    CHECK(g->atoms.n == 44 && g->atoms.maxtag == 59);
    CHECK(test_script(g, "create_atoms 2 single 0.5 0.5 0.5\n") == GR_OK);
    CHECK(g->atoms.tag[g->atoms.n - 1] == 60); /* next tag after the largest left */
    /* random: exact counts */
    CHECK(test_script(g, "delete_atoms random count 7 yes all NULL 4242\n") == GR_OK);
    CHECK(g->atoms.n == 38);
    int ok = 1;
    for (int i = 0; i < g->atoms.n; i++) /* compress yes: 1..N in storage order */
        ok &= g->atoms.tag[i] == i + 1;
    CHECK(ok && g->atoms.maxtag == 38);
    CHECK(test_script(g, "delete_atoms random fraction 0.5 yes all NULL 77\n") == GR_OK);
    CHECK(g->atoms.n == 19);
    CHECK(test_script(g, "delete_atoms random fraction 0 no all NULL 77\n") == GR_OK);
    CHECK(g->atoms.n == 19);
    CHECK(test_script(g, "delete_atoms random fraction 1 no all NULL 77\n") == GR_OK);
    CHECK(g->atoms.n == 0);
    gr_destroy(g);
    /* overlap: two atoms 0.3 apart, both in both groups: the first is deleted */
    g = test_engine();
    CHECK(test_script(g, "region b block 0 4 0 4 0 4\ncreate_box 1 b\n"
                         "create_atoms 1 single 1 1 1 units box\n"
                         "create_atoms 1 single 1.3 1 1 units box\n"
                         "create_atoms 1 single 3 3 3 units box\n"
                         "delete_atoms overlap 0.5 all all compress no\n") == GR_OK);
    CHECK(g->atoms.n == 2 && g->atoms.tag[0] == 3 && g->atoms.tag[1] == 2);
    gr_destroy(g);
    /* across a periodic face: 0.1 and 3.95 are 0.15 apart; the larger tag is kept */
    g = test_engine();
    CHECK(test_script(g, "region b block 0 4 0 4 0 4\ncreate_box 1 b\n"
                         "create_atoms 1 single 0.1 1 1 units box\n"
                         "create_atoms 1 single 3.95 1 1 units box\n"
                         "delete_atoms overlap 0.5 all all compress no\n") == GR_OK);
    CHECK(g->atoms.n == 1 && g->atoms.tag[0] == 2);
    gr_destroy(g);
    CHECK_ERROR(BOX "delete_atoms blob 1\n", "unknown style 'blob'", 5);
    CHECK_ERROR(BOX "delete_atoms overlap 0.5 all\n", "style overlap needs 3 arguments", 5);
    CHECK_ERROR(BOX "delete_atoms group all mol yes\n", "no molecules or bonds", 5);
    CHECK_ERROR(BOX "delete_atoms group all compress maybe\n", "yes or no", 5);
    CHECK_ERROR(BOX "delete_atoms group all frob no\n", "unknown keyword 'frob'", 5);
    CHECK_ERROR(BOX "delete_atoms random count 99 yes all NULL 5\n", "more than the 64", 5);
    CHECK_ERROR(BOX "delete_atoms random half 1 yes all NULL 5\n", "fraction or count", 5);
    CHECK_ERROR(BOX "delete_atoms porosity nope 0.3 5\n", "nope", 5);
    CHECK_ERROR(BOX "delete_atoms porosity b 1.3 5\n", "in [0, 1]", 5);
}

TEST(change_box_ops)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "lattice sc 0.5\n" /* spacing 2^(1/3) */
                         "region b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 1 box\n")
          == GR_OK);
    double a = g->dom.lat.a[0];
    CHECK(test_script(g, "change_box all x final 0 8 remap\n") == GR_OK);
    CHECK_NEAR(g->dom.hi[0], 8 * a, 1e-12);
    CHECK_NEAR(g->atoms.x[3 * 1], 2 * a, 1e-12); /* atom 2 at x = a doubles */
    CHECK(test_script(g, "change_box all y delta -1 1 units box\n") == GR_OK);
    CHECK_NEAR(g->dom.lo[1], -1, 0);
    CHECK_NEAR(g->dom.hi[1], 4 * a + 1, 1e-12);
    CHECK(test_script(g, "change_box all z scale 2 remap\n") == GR_OK);
    CHECK_NEAR(g->dom.lo[2], -2 * a, 1e-12);
    CHECK_NEAR(g->dom.hi[2], 6 * a, 1e-12);
    CHECK_NEAR(g->atoms.x[2], -2 * a, 1e-12); /* atom 1 stays on the low face */
    /* boundary: image flags of a dimension made non-periodic are reset */
    g->atoms.image[0] = 3;
    g->atoms.image[2] = 5;
    CHECK(test_script(g, "change_box all boundary p p f\n") == GR_OK);
    CHECK(g->dom.periodic[0] && !g->dom.periodic[2]);
    CHECK(g->atoms.image[0] == 3 && g->atoms.image[2] == 0);
    /* shrinking a fixed face loses the atoms outside, with a warning */
    int n = g->atoms.n;
    CHECK(test_script(g, "change_box all z final -1 0 units box\n") == GR_OK);
    CHECK(g->atoms.n < n && g->atoms.n > 0);
    gr_destroy(g);
    /* triclinic: tilts, remap in lamda coordinates, ortho only without tilt */
    g = test_engine();
    CHECK(test_script(g, BOX "change_box all triclinic xy final 1.5 remap units box\n") == GR_OK);
    CHECK(g->dom.triclinic && g->dom.xy == 1.5 && g->dom.xz == 0.0);
    CHECK(test_script(g, "change_box all xy delta -1.5 units box ortho\n") == GR_OK);
    CHECK(!g->dom.triclinic && g->dom.xy == 0.0);
    gr_destroy(g);
    CHECK_ERROR(BOX "change_box all xy final 1\n", "tilt factors of an orthogonal box", 5);
    CHECK_ERROR(BOX "change_box all triclinic xy final 1 ortho\n",
                "cannot change the box to orthogonal", 5);
    CHECK_ERROR(BOX "change_box all x volume\n", "volume is not supported", 5);
    CHECK_ERROR(BOX "change_box all x final 3 1\n", "not lo < hi", 5);
    CHECK_ERROR(BOX "change_box all boundary p q p\n", "unknown boundary 'q'", 5);
    CHECK_ERROR(BOX "change_box all\n", "", 5);
    CHECK_ERROR(BOX "change_box all wobble\n", "unknown operation 'wobble'", 5);
    CHECK_ERROR("dimension 2\nregion b block 0 4 0 4 -0.5 0.5\ncreate_box 1 b\n"
                "change_box all boundary p p f\n", "non-periodic in a 2d", 4);
    CHECK_ERROR("dimension 2\nregion b block 0 4 0 4 -0.5 0.5\ncreate_box 1 b\n"
                "change_box all z final -1 1\n", "z dimension of a 2d", 4);
}

TEST(twod_rules)
{
    CHECK_ERROR(BOX "fix e all enforce2d\n", "3d simulation", 5);
    CHECK_ERROR(BOX "fix n all nve/sphere disc\n", "requires a 2d simulation", 5);
    CHECK_ERROR(BOX "set atom 1 density/disc 1\n", "requires a 2d simulation", 5);
    struct gravel *g = test_engine();
    CHECK(test_script(g, "dimension 2\nlattice sq 1\nregion b block 0 3 0 3 -0.5 0.5\n"
                         "create_box 1 b\ncreate_atoms 1 box\nset atom 1 density/disc 2\n"
                         "velocity all create 1 5 loop geom\n") == GR_OK);
    CHECK(g->atoms.n == 9);
    CHECK_NEAR(g->atoms.rmass[0], M_PI * 0.25 * 2, 1e-15);
    CHECK_NEAR(g->atoms.rmass[1], M_PI / 6, 1e-15); /* create_atoms: 4/3 pi r^3, as LAMMPS */
    int vz0 = 1;
    for (int i = 0; i < g->atoms.n; i++)
        vz0 &= g->atoms.v[3 * i + 2] == 0.0;
    CHECK(vz0);
    gr_destroy(g);
}

/* issue 24: a replication grid of 10^12 copies took over a minute with no
 * atoms (a loop per copy); now it is refused at once, with or without atoms,
 * and an empty box only grows */
TEST(replicate_huge_grid)
{
    const char *empty = "region b block 0 1 0 1 0 1\ncreate_box 1 b\n";
    char text[256];
    time_t t0 = time(NULL);
    snprintf(text, sizeof text, "%sreplicate 1000000 1000000 1\n", empty);
    CHECK_ERROR(text, "the replicated system is too big (1000000000000 copies of the box, at "
                      "most 2147483647)", 3);
    snprintf(text, sizeof text, "%sreplicate 2147483647 2147483647 2147483647\n", empty);
    CHECK_ERROR(text, "(9903520300447984143910830080 copies of the box", 3);
    snprintf(text, sizeof text, "%screate_atoms 1 single 0.5 0.5 0.5\nreplicate 1000000 "
                                "1000000 1\n", empty);
    CHECK_ERROR(text, "the replicated system is too big (1000000000000 copies of the box", 4);
    struct gravel *g = test_engine();
    snprintf(text, sizeof text, "%sreplicate 40000 40000 1\n", empty);
    CHECK(test_script(g, text) == GR_OK);
    CHECK(g->atoms.n == 0 && g->dom.hi[0] == 40000.0 && g->dom.hi[1] == 40000.0 &&
          g->dom.hi[2] == 1.0);
    gr_destroy(g);
    CHECK(time(NULL) - t0 < 5);
}

int main(void)
{
    RUN(delete_styles);
    RUN(change_box_ops);
    RUN(twod_rules);
    RUN(replicate_huge_grid);
    return 0;
}
