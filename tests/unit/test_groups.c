/* test_groups.c - group, set and velocity: membership counts, LAMMPS set
 * semantics (diameter keeps the mass, density uses the radius), velocity
 * create (zero momentum, LAMMPS temperature with dof 3N-3, loop geom order
 * independence), set/ramp/zero/scale, and validation errors. */
#include "test.h"

#include "atoms.h"
#include "group.h"

/* 4x4x4 simple cubic atoms at 0..3 (lattice sc 1.0 in lj = spacing 1). */
#define CUBE "lattice sc 1.0\nregion b block 0 4 0 4 0 4\ncreate_box 3 b\ncreate_atoms 1 box\n"

static bigint count(struct gravel *g, const char *name)
{
    int ig = group_find(g, name);
    return ig < 0 ? -1 : group_count(g, ig);
}

TEST(group_styles)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, CUBE "region low block INF INF INF INF 0 1.5 units box\n"
                              "group low region low\n"
                              "set group low type 2\n"
                              "group t2 type 2\ngroup t12 type 1:2\ngroup t3 type 3\n"
                              "group first id <= 10\ngroup mid id <> 5 14\n"
                              "group odd id 1:64:2\ngroup few id 1 3 5 64\n"
                              "group big id > 60\ngroup ne id != 1\n"
                              "group sub subtract all low\ngroup uni union first odd\n"
                              "group both intersect first odd\n") == GR_OK);
    CHECK(count(g, "all") == 64);
    CHECK(count(g, "low") == 32);
    CHECK(count(g, "t2") == 32 && count(g, "t12") == 64 && count(g, "t3") == 0);
    CHECK(count(g, "first") == 10 && count(g, "mid") == 10);
    CHECK(count(g, "odd") == 32 && count(g, "few") == 4);
    CHECK(count(g, "big") == 4 && count(g, "ne") == 63);
    CHECK(count(g, "sub") == 32);
    CHECK(count(g, "uni") == 37 && count(g, "both") == 5);
    /* atom-style variables: a static group of x < 2 and type == 2 (the low half has type 2,
     * z < 1.5), and a dynamic one (set at run setup: empty until a run) */
    CHECK(test_script(g, "variable v atom (x<2)*(type==2)\ngroup var variable v\n"
                         "group dyn dynamic all var v every 10\n") == GR_OK);
    CHECK(count(g, "var") == 16 && count(g, "dyn") == 0);
    CHECK(test_script(g, "group var type 1\n") == GR_OK);
    CHECK(test_script(g, "group dyn type 1\n") != GR_OK);
    CHECK(test_script(g, "group dyn static\ngroup dyn type 1\n") == GR_OK);
    CHECK(count(g, "var") == 48 && count(g, "dyn") == 32);
    /* assigning again adds atoms; delete frees the slot and the bits */
    CHECK(test_script(g, "group few id 10\n") == GR_OK);
    CHECK(count(g, "few") == 5);
    int slot = group_find(g, "few");
    CHECK(test_script(g, "group few delete\ngroup again empty\n") == GR_OK);
    CHECK(group_find(g, "few") == -1 && group_find(g, "again") == slot);
    CHECK(count(g, "again") == 0);
    CHECK(test_script(g, "group low clear\n") == GR_OK);
    CHECK(count(g, "low") == 0);
    /* reductions */
    double m = group_mass(g, 0), xcm[3], lo[3], hi[3];
    CHECK_NEAR(m, 64 * M_PI / 6, 1e-12);
    group_xcm(g, 0, m, xcm);
    CHECK_NEAR(xcm[0], 1.5, 1e-12);
    group_bounds(g, 0, lo, hi);
    CHECK(lo[2] == 0 && hi[2] == 3);
    gr_destroy(g);
}

TEST(group_errors)
{
    CHECK_ERROR(CUBE "group all delete\n", "group 'all' cannot be deleted", 5);
    CHECK_ERROR(CUBE "group all type 1\n", "group 'all' always holds every atom", 5);
    CHECK_ERROR(CUBE "group g region nowhere\n", "unknown region 'nowhere'", 5);
    CHECK_ERROR(CUBE "group g type < 1 2\n", "group type < needs exactly 1 value", 5);
    CHECK_ERROR(CUBE "group g id <> 5 2\n", "needs the smaller value first", 5);
    CHECK_ERROR(CUBE "group g id 5:2\n", "has its start after its end", 5);
    CHECK_ERROR(CUBE "group g id 1:5:0\n", "range step in '1:5:0' must be positive", 5);
    CHECK_ERROR(CUBE "group g type abc\n", "expected an integer for type, got 'abc'", 5);
    CHECK_ERROR(CUBE "group g subtract all\n", "group subtract needs at least 2 group IDs", 5);
    CHECK_ERROR(CUBE "group g union nope\n", "unknown group 'nope'", 5);
    CHECK_ERROR(CUBE "group g dynamic all foo b\n", "unknown group dynamic keyword 'foo'", 5);
    CHECK_ERROR(CUBE "group g dynamic all region nowhere\n", "unknown region 'nowhere'", 5);
    CHECK_ERROR(CUBE "variable e equal 1\ngroup g dynamic all var e\n",
                "variable 'e' is equal-style, not atom-style", 6);
    CHECK_ERROR(CUBE "group g dynamic g\n", "unknown group 'g'", 5);
    CHECK_ERROR(CUBE "group g static\n", "unknown group 'g'", 5);
    CHECK_ERROR(CUBE "group g empty\ngroup g static\n", "group 'g' is not dynamic", 6);
    CHECK_ERROR(CUBE "group g variable nope\n", "variable 'nope' is not defined", 5);
    CHECK_ERROR(CUBE "group g frobnicate\n", "unknown group style 'frobnicate'", 5);
    CHECK_ERROR(CUBE "group x.y empty\n", "may contain only letters", 5);
    CHECK_ERROR(CUBE "group nope delete\n", "unknown group 'nope'", 5);
    char s[4096] = CUBE;
    for (int k = 1; k <= 32; k++) {
        char line[64];
        snprintf(line, sizeof line, "group g%d empty\n", k);
        strcat(s, line);
    }
    CHECK_ERROR(s, "too many groups (at most 32", 4 + 32);
}

TEST(set_semantics)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, CUBE "set atom 1 diameter 2.0\n") == GR_OK);
    int i = atoms_find_tag(&g->atoms, 1);
    CHECK(g->atoms.radius[i] == 1.0);
    CHECK_NEAR(g->atoms.rmass[i], M_PI / 6, 1e-15); /* LAMMPS: diameter keeps the mass */
    CHECK(test_script(g, "set atom 1 density 2.0\n") == GR_OK);
    CHECK_NEAR(g->atoms.rmass[i], 8.37758040957278, 1e-13); /* LAMMPS value */
    CHECK(test_script(g, "set atom 2*4 mass 3.0 type 3 omega 1 2 3 vx -1 z 0.25\n") == GR_OK);
    for (int t = 2; t <= 4; t++) {
        int j = atoms_find_tag(&g->atoms, t);
        CHECK(g->atoms.rmass[j] == 3.0 && g->atoms.type[j] == 3);
        CHECK(g->atoms.omega[3 * j + 2] == 3 && g->atoms.v[3 * j] == -1);
        CHECK(g->atoms.x[3 * j + 2] == 0.25);
    }
    CHECK(test_script(g, "set type 3 diameter 0\nset type 3 density 5\n") == GR_OK);
    CHECK(g->atoms.rmass[atoms_find_tag(&g->atoms, 3)] == 5.0); /* point particle: mass */
    CHECK(test_script(g, "region r block INF INF INF INF 2.5 INF units box\n"
                         "set region r vz 7\nset atom * image 1 0 -2\n") == GR_OK);
    int nz = 0;
    for (int k = 0; k < g->atoms.n; k++)
        nz += g->atoms.v[3 * k + 2] == 7;
    CHECK(nz == 16);
    CHECK(g->atoms.image[3 * i + 2] == -2);
    /* a coordinate set outside a periodic box is wrapped, image updated */
    CHECK(test_script(g, "set atom 1 x 9.5\n") == GR_OK);
    CHECK(g->atoms.x[3 * i] == 1.5 && g->atoms.image[3 * i] == 3);
    /* a bad keyword late on the line changes nothing */
    CHECK(test_script(g, "set atom 1 mass 9.0 bogus 1\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "unknown keyword 'bogus'") != NULL);
    CHECK(g->atoms.rmass[i] != 9.0);
    gr_destroy(g);
    /* type/fraction: about half of 64000 atoms, reproducibly */
    g = test_engine();
    CHECK(test_script(g, "lattice sc 1.0\nregion b block 0 40 0 40 0 40\ncreate_box 2 b\n"
                         "create_atoms 1 box\nset type 1 type/fraction 2 0.5 12345\n"
                         "group two type 2\n") == GR_OK);
    bigint n2 = count(g, "two");
    CHECK(n2 > 32000 - 600 && n2 < 32000 + 600);
    gr_destroy(g);
}

TEST(set_errors)
{
    CHECK_ERROR(CUBE "set atom 1 diameter -1\n", "diameter must not be negative", 5);
    CHECK_ERROR(CUBE "set atom 1 density 0\n", "density must be positive", 5);
    CHECK_ERROR(CUBE "set atom 1 y 1e12\n", "too far outside the periodic box", 5);
    CHECK_ERROR(CUBE "set atom 1 type 4\n", "atom type must be between 1 and 3", 5);
    CHECK_ERROR(CUBE "set atom 99 mass 1\n", "atom ID 99 is outside 1..64", 5);
    CHECK_ERROR(CUBE "set type 4 mass 1\n", "atom type 4 is outside 1..3", 5);
    CHECK_ERROR(CUBE "set group nope mass 1\n", "unknown group 'nope'", 5);
    CHECK_ERROR(CUBE "set mol 1 mass 1\n", "style mol is not supported", 5);
    CHECK_ERROR(CUBE "set atom 1 omega 1 2\n", "keyword 'omega' needs 3 values", 5);
    CHECK_ERROR(CUBE "set atom 1 quat 1 0 0 0\n", "does not apply to atom_style sphere", 5);
    CHECK_ERROR("boundary p p f\n" CUBE "set atom 1 image 0 0 1\n",
                "non-zero image flag in non-periodic z", 6);
}

/* Temperature as LAMMPS compute temp: sum m v^2 / (3N - 3), lj units. */
static double temp(struct gravel *g)
{
    return 2 * group_ke(g, 0) / (3.0 * g->atoms.n - 3.0);
}

TEST(velocity_create)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, CUBE "set type 1 density 2.5\n"
                              "velocity all create 1.5 87287 dist gaussian\n") == GR_OK);
    double m = group_mass(g, 0), vcm[3];
    group_vcm(g, 0, m, vcm);
    for (int d = 0; d < 3; d++)
        CHECK_NEAR(vcm[d], 0, 1e-14);
    CHECK_NEAR(temp(g), 1.5, 1e-12);
    CHECK(test_script(g, "velocity all create 0.7 4 rot yes mom yes\n") == GR_OK);
    double xcm[3], L[3];
    group_xcm(g, 0, m, xcm);
    group_angmom(g, 0, xcm, L);
    for (int d = 0; d < 3; d++)
        CHECK_NEAR(L[d], 0, 1e-12);
    CHECK_NEAR(temp(g), 0.7, 1e-12);
    /* sum yes adds to the existing velocities */
    double v0 = g->atoms.v[0];
    CHECK(test_script(g, "velocity all create 0.7 4 rot yes sum yes\n") == GR_OK);
    CHECK_NEAR(g->atoms.v[0], 2 * v0, 1e-12);
    gr_destroy(g);
}

TEST(velocity_loop_geom_order)
{
    /* same positions, created in a different order (and so other tags and
     * indices): loop geom gives each atom the same velocity, up to the
     * rounding of the temperature sum (LAMMPS sums in storage order) */
    struct gravel *a = test_engine(), *b = test_engine();
    CHECK(test_script(a, CUBE "velocity all create 1.0 5 mom no loop geom\n") == GR_OK);
    CHECK(test_script(b, "lattice sc 1.0\nregion b block 0 4 0 4 0 4\ncreate_box 3 b\n"
                         "region up block INF INF INF INF 1.5 INF units box\n"
                         "region dn block INF INF INF INF INF 1.5 units box\n"
                         "create_atoms 1 region up\ncreate_atoms 1 region dn\n"
                         "velocity all create 1.0 5 mom no loop geom\n") == GR_OK);
    CHECK(a->atoms.n == 64 && b->atoms.n == 64);
    CHECK(a->atoms.x[2] == 0 && b->atoms.x[2] == 2); /* really a different order */
    int same = 0;
    for (int i = 0; i < 64; i++)
        for (int j = 0; j < 64; j++)
            if (memcmp(a->atoms.x + 3 * i, b->atoms.x + 3 * j, 3 * sizeof(double)) == 0)
                same += fabs(a->atoms.v[3 * i] - b->atoms.v[3 * j]) <= 1e-14 &&
                        fabs(a->atoms.v[3 * i + 1] - b->atoms.v[3 * j + 1]) <= 1e-14 &&
                        fabs(a->atoms.v[3 * i + 2] - b->atoms.v[3 * j + 2]) <= 1e-14;
    CHECK(same == 64);
    /* loop all follows tags: the same tags give the same velocities */
    struct gravel *c = test_engine();
    CHECK(test_script(c, CUBE "velocity all create 1.0 5 mom no loop all\n") == GR_OK);
    CHECK(test_script(a, "velocity all create 1.0 5 mom no loop all\n") == GR_OK);
    CHECK(memcmp(a->atoms.v, c->atoms.v, 64 * 3 * sizeof(double)) == 0);
    /* different seeds differ */
    CHECK(test_script(c, "velocity all create 1.0 6 mom no loop all\n") == GR_OK);
    CHECK(a->atoms.v[0] != c->atoms.v[0]);
    gr_destroy(a);
    gr_destroy(b);
    gr_destroy(c);
}

TEST(velocity_set_ramp_zero)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "lattice sc 0.5\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\n"
                         "create_atoms 1 box\nvelocity all set 1 NULL 2\n") == GR_OK);
    double a = pow(2.0, 1.0 / 3.0); /* lattice units by default, as LAMMPS */
    CHECK_NEAR(g->atoms.v[0], a, 1e-14);
    CHECK(g->atoms.v[1] == 0);
    CHECK_NEAR(g->atoms.v[2], 2 * a, 1e-14);
    CHECK(test_script(g, "velocity all set NULL 3 NULL units box sum yes\n") == GR_OK);
    CHECK(g->atoms.v[1] == 3);
    CHECK(test_script(g, "velocity all ramp vx 0 10 z 0 4 units box\n") == GR_OK);
    for (int i = 0; i < g->atoms.n; i++) {
        double z = g->atoms.x[3 * i + 2];
        CHECK_NEAR(g->atoms.v[3 * i], 10 * fmin(z / 4, 1.0), 1e-12);
    }
    CHECK(test_script(g, "velocity all zero linear\n") == GR_OK);
    double m = group_mass(g, 0), vcm[3];
    group_vcm(g, 0, m, vcm);
    CHECK_NEAR(vcm[0], 0, 1e-13);
    CHECK_NEAR(vcm[1], 0, 1e-13);
    CHECK(test_script(g, "velocity all zero angular\n") == GR_OK);
    double xcm[3], L[3];
    group_xcm(g, 0, m, xcm);
    group_angmom(g, 0, xcm, L);
    for (int d = 0; d < 3; d++)
        CHECK_NEAR(L[d], 0, 1e-12);
    CHECK(test_script(g, "velocity all scale 2.0\n") == GR_OK);
    CHECK_NEAR(temp(g), 2.0, 1e-12);
    gr_destroy(g);
    /* a two-atom group (singular inertia): rotation removed, motion along
     * the axis kept */
    g = test_engine();
    CHECK(test_script(g, "region b block 0 10 0 10 0 10 units box\ncreate_box 1 b\n"
                         "create_atoms 1 single 2 5 5 units box\n"
                         "create_atoms 1 single 4 5 5 units box\n"
                         "set atom 1 vx 1.0 vy 1.0\nset atom 2 vx 1.0 vy -1.0\n"
                         "velocity all zero angular\n") == GR_OK);
    CHECK_NEAR(g->atoms.v[0], 1.0, 1e-14);
    CHECK_NEAR(g->atoms.v[1], 0.0, 1e-14);
    CHECK_NEAR(g->atoms.v[3], 1.0, 1e-14);
    CHECK_NEAR(g->atoms.v[4], 0.0, 1e-14);
    gr_destroy(g);
}

TEST(velocity_errors)
{
    CHECK_ERROR(CUBE "velocity all create 1.0 0\n", "seed must be a positive integer", 5);
    CHECK_ERROR(CUBE "velocity all create -1.0 5\n", "temperature must be positive", 5);
    CHECK_ERROR(CUBE "velocity all create 1.0 5 dist poisson\n", "dist must be uniform or gaussian",
                5);
    CHECK_ERROR(CUBE "velocity all create 1.0 5 loop sideways\n", "loop must be all, local or geom",
                5);
    CHECK_ERROR(CUBE "velocity all create 1.0 5 mom\n", "keyword 'mom' needs 1 value", 5);
    CHECK_ERROR(CUBE "velocity all spin 1\n", "unknown style 'spin'", 5);
    CHECK_ERROR(CUBE "velocity nope set 1 1 1\n", "unknown group 'nope'", 5);
    CHECK_ERROR(CUBE "velocity all set 1 x 1\n", "expected a number for velocity component", 5);
    CHECK_ERROR(CUBE "velocity all zero sideways\n", "zero must be linear or angular", 5);
    CHECK_ERROR(CUBE "velocity all scale 1.0\n", "cannot rescale a zero temperature", 5);
    CHECK_ERROR(CUBE "velocity all ramp vw 0 1 z 0 1\n", "ramp velocity component must be", 5);
    CHECK_ERROR(CUBE "group one id 1\nvelocity one create 1.0 5\n", "needs at least 2 atoms", 6);
    CHECK_ERROR(CUBE "velocity all create 1.0 5 temp mytemp\n",
                "velocity temp refers to unknown compute ID 'mytemp'", 5);
}

int main(void)
{
    RUN(group_styles);
    RUN(group_errors);
    RUN(set_semantics);
    RUN(set_errors);
    RUN(velocity_create);
    RUN(velocity_loop_geom_order);
    RUN(velocity_set_ramp_zero);
    RUN(velocity_errors);
    return 0;
}
