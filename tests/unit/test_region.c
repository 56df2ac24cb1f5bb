/* test_region.c - region styles: membership, side out, union/intersect,
 * lattice units, INF/EDGE, bounding boxes, validation errors; create_box. */
#include "test.h"

#include "domain.h"
#include "region.h"

static int in(struct gravel *g, const char *id, double x, double y, double z)
{
    const double p[3] = {x, y, z};
    struct region *r = region_find(g, id);
    return r ? region_match(r, p) : -1;
}

TEST(block_sphere_side)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "region b block 0 2 0 3 0 4 units box\n"
                         "region o block 0 2 0 3 0 4 side out units box\n"
                         "region s sphere 1 1 1 0.5 units box\n") == GR_OK);
    CHECK(in(g, "b", 1, 1, 1) == 1);
    CHECK(in(g, "b", 2, 3, 4) == 1); /* faces are inside, as LAMMPS */
    CHECK(in(g, "b", 2.0001, 1, 1) == 0);
    CHECK(in(g, "o", 2.0001, 1, 1) == 1);
    CHECK(in(g, "o", 1, 1, 1) == 0);
    CHECK(in(g, "s", 1.5, 1, 1) == 1);
    CHECK(in(g, "s", 1.3, 1.3, 1.3) == 0); /* |d| = 0.52 */
    struct region *s = region_find(g, "s");
    CHECK(s->bbox && s->bbox_lo[0] == 0.5 && s->bbox_hi[2] == 1.5);
    CHECK(region_find(g, "nope") == NULL);
    gr_destroy(g);
}

TEST(cylinder_cone_plane)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "region c cylinder y 1 2 0.5 -1 1 units box\n"
                         "region k cone z 0 0 1 0 0 2 units box\n"
                         "region p plane 0 0 1 0 0 -1 units box\n") == GR_OK);
    /* cylinder along y through x=1, z=2 */
    CHECK(in(g, "c", 1.4, 0.9, 2) == 1);
    CHECK(in(g, "c", 1.6, 0.0, 2) == 0);
    CHECK(in(g, "c", 1.0, 1.1, 2) == 0);
    CHECK(in(g, "c", 1.0, 0.0, 2.5) == 1);
    /* cone radius 1 at z=0 down to 0 at z=2: radius 0.5 at z=1 */
    CHECK(in(g, "k", 0.45, 0, 1) == 1);
    CHECK(in(g, "k", 0.55, 0, 1) == 0);
    CHECK(in(g, "k", 0, 0, 2.1) == 0);
    /* plane through z=1 with normal -z: inside is z <= 1 */
    CHECK(in(g, "p", 5, 5, 0.5) == 1);
    CHECK(in(g, "p", 5, 5, 1.0) == 1);
    CHECK(in(g, "p", 5, 5, 1.5) == 0);
    CHECK(region_find(g, "p")->bbox == 0);
    gr_destroy(g);
}

TEST(union_intersect)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "region a sphere 0 0 0 1 units box\n"
                         "region b sphere 1.5 0 0 1 units box\n"
                         "region hole sphere 0 0 0 0.5 side out units box\n"
                         "region u union 2 a b\n"
                         "region i intersect 2 a b\n"
                         "region shell intersect 2 a hole\n") == GR_OK);
    CHECK(in(g, "u", -0.9, 0, 0) == 1 && in(g, "u", 2.4, 0, 0) == 1 && in(g, "u", 0, 2, 0) == 0);
    CHECK(in(g, "i", 0.75, 0, 0) == 1 && in(g, "i", -0.9, 0, 0) == 0);
    CHECK(in(g, "shell", 0.7, 0, 0) == 1 && in(g, "shell", 0.2, 0, 0) == 0);
    struct region *u = region_find(g, "u"), *i = region_find(g, "i");
    CHECK(u->bbox && u->bbox_lo[0] == -1 && u->bbox_hi[0] == 2.5);
    CHECK(i->bbox && i->bbox_lo[0] == 0.5 && i->bbox_hi[0] == 1);
    /* LAMMPS: a sub-region in use may be deleted; its compounds take the
     * region of that ID defined when next used, or stop */
    CHECK(test_script(g, "region a delete\n") == GR_OK);
    CHECK(region_find(g, "a") == NULL && g->regions.n == 5);
    CHECK(test_script(g, "create_box 1 u\ngroup gu region u\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "sub-region 'a' was deleted") != NULL);
    CHECK(test_script(g, "region a sphere 5 0 0 1 units box\ngroup gu region u\n") == GR_OK);
    CHECK(in(g, "u", 5, 0, 0) == 1 && in(g, "u", -0.9, 0, 0) == 0 && in(g, "u", 2.4, 0, 0) == 1);
    CHECK(test_script(g, "region u delete\nregion i delete\nregion shell delete\n"
                         "region a delete\n") == GR_OK);
    CHECK(region_find(g, "a") == NULL && g->regions.n == 2);
    gr_destroy(g);
}

TEST(lattice_units_inf_edge)
{
    struct gravel *g = test_engine();
    /* default units lattice with lattice sc 2.0 (lj: a = (1/2)^(1/3)) */
    CHECK(test_script(g, "lattice sc 2.0\nregion b block 0 2 0 2 0 2\n"
                         "region c block 0 1 0 1 INF INF units box\n"
                         "create_box 1 b\nregion e block EDGE EDGE 0 0.5 EDGE 1.0 units box\n")
          == GR_OK);
    double a = pow(0.5, 1.0 / 3.0);
    CHECK_NEAR(g->dom.hi[0], 2 * a, 1e-15);
    CHECK(in(g, "c", 0.5, 0.5, -1e6) == 1);
    double v[3] = {1, 2, 3};
    domain_lattice_to_box(g, v);
    CHECK_NEAR(v[2], 3 * a, 1e-15);
    domain_box_to_lattice(g, v);
    CHECK_NEAR(v[2], 3, 1e-15);
    /* remap and minimum image on the periodic box of side 2a */
    double x[3] = {-0.25 * a, 4.5 * a, a};
    int im[3] = {0, 0, 0};
    domain_remap(g, x, im);
    CHECK_NEAR(x[0], 1.75 * a, 1e-14);
    CHECK_NEAR(x[1], 0.5 * a, 1e-14);
    CHECK(im[0] == -1 && im[1] == 2 && im[2] == 0);
    double del[3] = {1.5 * a, -1.2 * a, 0.1};
    domain_minimum_image(g, del);
    CHECK_NEAR(del[0], -0.5 * a, 1e-14);
    CHECK_NEAR(del[1], 0.8 * a, 1e-14);
    CHECK_NEAR(domain_volume(g), 8 * a * a * a, 1e-14);
    struct region *e = region_find(g, "e");
    CHECK_NEAR(e->p[1], 2 * a, 1e-15);
    CHECK_NEAR(e->p[4], 0, 0);
    gr_destroy(g);
}

TEST(region_errors)
{
    CHECK_ERROR("region b blob 0 1\n", "unknown region style 'blob'", 1);
    CHECK_ERROR("region b block 0 1 0 1 0\n", "region block needs 6 arguments", 1);
    CHECK_ERROR("region b block 1 0 0 1 0 1\n", "needs xlo < xhi", 1);
    CHECK_ERROR("region b block 0 1 0 1 0 x\n", "expected a number for zhi, got 'x'", 1);
    CHECK_ERROR("region b block EDGE 1 0 1 0 1\n", "cannot use EDGE for xlo before the box", 1);
    CHECK_ERROR("region b sphere 0 0 0 -1\n", "sphere radius must not be negative", 1);
    CHECK_ERROR("region b cylinder w 0 0 1 0 1\n", "axis must be x, y or z", 1);
    CHECK_ERROR("region b cone z 0 0 0 0 0 1\n", "cone radii cannot both be zero", 1);
    CHECK_ERROR("region b plane 0 0 0 0 0 0\n", "plane normal cannot be zero", 1);
    CHECK_ERROR("region b sphere 0 0 0 1 side sideways\n", "side must be 'in' or 'out'", 1);
    CHECK_ERROR("region b sphere 0 0 0 1 units furlong\n", "units must be 'box' or 'lattice'", 1);
    CHECK_ERROR("region b sphere 0 0 0 1 move x NULL NULL\n", "expected v_name or NULL", 1);
    CHECK_ERROR("region b sphere 0 0 0 1 rotate v_t 0 0 0 0 0 0\n",
                "rotation axis cannot have zero length", 1);
    CHECK_ERROR("region b sphere 0 0 0 1 open 1\n", "has no faces to open", 1);
    CHECK_ERROR("region b block 0 1 0 1 0 1 open 7\n", "open face", 1);
    CHECK_ERROR("region b sphere 0 0 0 1\nregion b sphere 0 0 0 2\n", "region 'b' already exists",
                2);
    CHECK_ERROR("region b sphere 0 0 0 1\nregion u union 2 b c\n", "unknown region 'c'", 2);
    CHECK_ERROR("region b sphere 0 0 0 1\nregion u union 3 b b\n", "at least 2 sub-region IDs", 2);
    CHECK_ERROR("region b-1 sphere 0 0 0 1\n", "may contain only letters", 1);
    CHECK_ERROR("region x delete\n", "unknown region 'x'", 1);
}

TEST(motion_open)
{
    struct gravel *g = test_engine();
    /* rotate by pi/2 about z through (0, 0, 0), then move by (0, 0, 3) */
    CHECK(test_script(g, "region box block -5 5 -5 5 -5 5 units box\ncreate_box 1 box\n"
                         "variable t equal PI/2\nvariable dz equal 3\n"
                         "region r block 1 2 -0.5 0.5 -0.5 0.5 units box "
                         "rotate v_t 0 0 0 0 0 1 move NULL NULL v_dz\n"
                         "region o cylinder z 0 0 1 -1 1 open 3 units box\n"
                         "group gr region r\n") == GR_OK);
    CHECK(in(g, "r", 0, 1.5, 3) == 1 && in(g, "r", 1.5, 0, 3) == 0 && in(g, "r", 0, 1.5, 0) == 0);
    struct region *r = region_find(g, "r");
    CHECK_NEAR(r->theta, M_PI / 2, 1e-15);
    CHECK(r->d[2] == 3 && r->d[0] == 0 && r->bbox == 0);
    /* LAMMPS: a region with an open face matches every point */
    CHECK(in(g, "o", 4, 4, 4) == 1 && region_find(g, "o")->open_faces[2] == 1);
    CHECK(r->cmax == 6 && region_find(g, "o")->cmax == 3);
    gr_destroy(g);
}

TEST(create_box_rules)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "boundary p fm s\nregion b block 0 10 -1 1 0 20\ncreate_box 2 b\n")
          == GR_OK);
    CHECK(g->dom.box_exists && g->atoms.ntypes == 2);
    CHECK(g->dom.lo[0] == 0 && g->dom.hi[0] == 10);
    CHECK(g->dom.lo[1] == -1 && g->dom.hi[1] == 1 && g->dom.minhi[1] == 1);
    /* 's' faces start small = 1e-4 x length outside, as LAMMPS set_initial_box */
    CHECK_NEAR(g->dom.small[2], 2e-3, 1e-18);
    CHECK_NEAR(g->dom.lo[2], -2e-3, 1e-18);
    CHECK_NEAR(g->dom.hi[2], 20.002, 1e-12);
    gr_destroy(g);
    CHECK_ERROR("region b sphere 0 0 0 1\ncreate_box 0 b\n",
                "number of atom types must be between 1 and 1000000", 2);
    CHECK_ERROR("create_box 1 nothere\n", "unknown region 'nothere'", 1);
    CHECK_ERROR("region b block 0 1 0 1 0 1 side out\ncreate_box 1 b\n", "must be side in", 2);
    CHECK_ERROR("region p plane 0 0 0 0 0 1\ncreate_box 1 p\n", "has no bounding box", 2);
    CHECK_ERROR("region b block 0 1 0 1 INF 1\ncreate_box 1 b\n", "unbounded in z", 2);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 1 b\ncreate_box 1 b\n",
                "", 3); /* phase error (dispatcher or handler) */
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 1 b bond/types 1\n",
                "unsupported keyword 'bond/types'", 2);
}

int main(void)
{
    RUN(block_sphere_side);
    RUN(cylinder_cone_plane);
    RUN(union_intersect);
    RUN(lattice_units_inf_edge);
    RUN(region_errors);
    RUN(create_box_rules);
    RUN(motion_open);
    return 0;
}
