/* test_wall_gran.c - fix wall/gran argument validation (every error names
 * the problem and the script line) and the wall physics that needs no
 * reference: a sphere resting on the floor settles where kn delta = m g, a
 * sphere outside the reach of a NULL face feels nothing, the wiggle moves the
 * wall face, the history of a model is zeroed when the contact ends, and
 * fix wall/pair with pair_style granular is the wall/gran granular wall. */
#include <math.h>

#include "test.h"
#include "atoms.h"

#define BOX "units lj\natom_style sphere\nboundary f f f\nregion b block -4 4 -4 4 -4 4\n" \
            "create_box 1 b\n"
#define BOXP "units lj\natom_style sphere\nboundary p p f\nregion b block -4 4 -4 4 -4 4\n" \
             "create_box 1 b\n"

TEST(errors)
{
    CHECK_ERROR(BOX "fix w all wall/gran\n", "expects model", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hook 1 NULL 1 NULL 0.5 1 zplane 0 NULL\n",
                "unknown fix wall/gran model 'hook'", 6);
    CHECK_ERROR(BOX "fix w all wall/gran granular hooke 1 1 zplane 0 NULL\n",
                "fix wall/gran granular: must specify normal or tangential contact model", 6);
    CHECK_ERROR(BOX "fix w all wall/gran granular jkr 1e5 1 0.3 10 tangential linear_history "
                    "1 1 0.5 mesh n_meshes 1 meshes m\n",
                "jkr normal model is not supported for meshes", 6);
    CHECK_ERROR(BOX "fix w all wall/gran granular hertz/material 1e5 1 0.3 tangential mindlin "
                    "NULL 1 0.5\n",
                "missing the wall style", 6);
    CHECK_ERROR(BOX "fix w all wall/gran granular hertz 1 1 tangential mindlin NULL 1 0.5 "
                    "zplane 0 NULL\n",
                "NULL setting for Mindlin tangential stiffness", 6);
    CHECK_ERROR(BOX "fix w all wall/gran granular hertz/material 1e5 1 0.3 tangential mindlin "
                    "NULL 1 0.5 cutoff 1 zplane 0 NULL\n",
                "unknown keyword 'cutoff'", 6);
    CHECK_ERROR(BOX "fix w all wall/gran granular hertz/material 1e5 1 0.3 tangential mindlen "
                    "NULL 1 0.5 zplane 0 NULL\n",
                "unknown tangential model 'mindlen'", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5\n", "got 5 argument(s)", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke -1 NULL 1 NULL 0.5 1 zplane 0 NULL\n", "Kn", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 20000 1 zplane 0 NULL\n",
                "xmu must be between 0 and 10000", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 2 zplane 0 NULL\n", "dampflag",
                6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zplne 0 NULL\n",
                "unknown fix wall/gran wall style 'zplne'", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zplane 0\n", "zplane", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zplane 1 0\n",
                "must be below hi", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zcylinder -2\n",
                "cylinder radius", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 region r\n",
                "wall style 'region' belongs to fix wall/gran/region", 6);
    CHECK_ERROR(BOX "fix w all wall/gran/region hooke 1 NULL 1 NULL 0.5 1 zplane 0 1\n",
                "expects 'region ID'", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL wigle z 1 1\n",
                "unknown fix wall/gran keyword 'wigle'", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL wiggle q 1 1\n",
                "expected dimension x, y or z", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL wiggle z 1 0\n",
                "wiggle period", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL wiggle z 1 1 "
                    "shear x 1\n",
                "cannot both wiggle and shear", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zcylinder 2 wiggle x 1 1\n",
                "can only wiggle along z", 6);
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL shear z 1\n",
                "cannot shear along its normal", 6);
    CHECK_ERROR(BOXP "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 xplane 0 NULL\n",
                "periodic dimension x", 6);
    CHECK_ERROR(BOXP "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zcylinder 2\n",
                "periodic x or y", 6);
    /* contacts (LAMMPS 2023+): an 8-column per-atom array */
    CHECK_ERROR(BOX "fix w all wall/gran hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL contacts\n"
                    "compute c all reduce sum f_w[9]\nrun 0\n",
                "f_w[9] is out of range: fix w's per-atom array has 8 columns", 7);
    CHECK_ERROR(BOX "fix w all wall/gran hooke/history 1 0 1 NULL 0.5 1 zplane 0 NULL\n",
                "needs Kt > 0", 6);
}

static const char *atom_deck(void)
{
    return BOX "create_atoms 1 single 0.5 0.5 -2.0 units box\n"
               "set atom 1 diameter 1.0 density 1.9098593\n"
               "pair_style gran/hooke 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
               "timestep 0.001\nfix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
               "thermo 0\n";
}

/* A sphere (m = 1) left on the floor comes to rest with overlap m g / kn. */
TEST(rest_on_floor)
{
    struct gravel *g = test_engine();
    char s[2048];
    snprintf(s, sizeof s, "%sfix 3 all wall/gran hooke/history 2000 NULL 50 NULL 0.5 1 zplane "
                          "-2.5 NULL\nrun 3000\n", atom_deck());
    CHECK(test_script(g, s) == GR_OK);
    double m = g->atoms.rmass[0];
    CHECK_NEAR(m, 1.0, 1e-6);
    CHECK_NEAR(g->atoms.x[2], -2.5 + 0.5 - m * 1.0 / 2000.0, 1e-7);
    CHECK_NEAR(g->atoms.v[2], 0.0, 1e-7);
    gr_destroy(g);
}

/* The hi face alone (lo NULL) pushes down a sphere that touches it; one
 * that does not touch it falls freely: z = z0 - t^2/2 exactly. */
TEST(null_face_free_fall)
{
    struct gravel *g = test_engine();
    char s[2048];
    snprintf(s, sizeof s, "%sfix 3 all wall/gran hooke 2000 NULL 50 NULL 0.5 1 zplane NULL "
                          "3.0\nrun 500\n", atom_deck());
    CHECK(test_script(g, s) == GR_OK);
    /* velocity Verlet is exact for constant acceleration */
    CHECK_NEAR(g->atoms.x[2], -2.0 - 0.5 * 0.5 * 0.5, 1e-12);
    CHECK_NEAR(g->atoms.v[2], -0.5, 1e-12);
    gr_destroy(g);
}

/* A wiggling floor lifts a resting sphere: after a quarter period the floor
 * has risen by A (1 - cos(pi/2)) = A, and so has the sphere (within its
 * contact compliance). */
TEST(wiggle_lifts)
{
    struct gravel *g = test_engine();
    char s[2048];
    snprintf(s, sizeof s, "%sfix 3 all wall/gran hooke/history 200000 NULL 500 NULL 0.5 1 "
                          "zplane -2.5 NULL\nrun 2000\nunfix 3\n"
                          "fix 4 all wall/gran hooke/history 200000 NULL 500 NULL 0.5 1 "
                          "zplane -2.5 NULL wiggle z 0.05 4.0\nrun 1000\n", atom_deck());
    CHECK(test_script(g, s) == GR_OK);
    CHECK_NEAR(g->atoms.x[2], -2.0 + 0.05, 2e-3);
    gr_destroy(g);
}

/* fix wall/pair with pair_style granular (the row form of the contact
 * body, issue 18) is the pair law against the wall: a spinning sphere thrown
 * obliquely onto the floor moves normally exactly as with fix wall/gran
 * granular and the same coefficients (z, v_z to 1e-12), and its friction
 * acts within the Coulomb bound |dv_t| <= mu |dv_n| and within 2 % of
 * wall/gran's (whose history follows LAMMPS 2021's wall code). A granular
 * law that acts beyond contact (jkr) is refused with a message naming fix
 * wall/gran. */
static void granular_wall_run(const char *wall, double out[9])
{
    struct gravel *g = test_engine();
    char s[2048];
    snprintf(s, sizeof s,
             BOX "create_atoms 1 single 0.5 0.5 -1.9 units box\n"
                 "set atom 1 diameter 1.0 density 1.9098593\n"
                 "velocity all set 0.7 -0.2 -1.5\nset atom 1 omega 0.3 2.0 -1.0\n"
                 "pair_style granular\npair_coeff * * hooke 2000 0.3 tangential "
                 "linear_history 800 0.5 0.4 damping mass_velocity\n"
                 "timestep 0.0005\nfix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
                 "thermo 0\n%s\nrun 400\n",
             wall);
    CHECK(test_script(g, s) == GR_OK);
    for (int q = 0; q < 3; q++) {
        out[q] = g->atoms.x[q];
        out[3 + q] = g->atoms.v[q];
        out[6 + q] = g->atoms.omega[q];
    }
    gr_destroy(g);
}

TEST(wall_pair_granular)
{
    double a[9], b[9];
    granular_wall_run("fix 3 all wall/pair zplane -2.5 NULL", a);
    granular_wall_run("fix 3 all wall/gran granular hooke 2000 0.3 tangential linear_history 800 "
                      "0.5 0.4 damping mass_velocity zplane -2.5 NULL", b);
    CHECK_NEAR(a[2], b[2], 1e-12);          /* z */
    CHECK_NEAR(a[5], b[5], 1e-12);          /* v_z */
    CHECK(a[5] > 0.1);                      /* rising after the bounce: the wall acted */
    const double g_t = 400 * 0.0005;        /* gravity's share of dv_z */
    const double dvn = a[5] - (-1.5) + g_t, dvx = a[3] - 0.7, dvy = a[4] + 0.2;
    CHECK(fabs(dvx) > 1e-3);                /* friction acted */
    CHECK(sqrt(dvx * dvx + dvy * dvy) <= 0.4 * dvn);
    for (int q = 3; q < 9; q++)
        CHECK_NEAR(a[q], b[q], 0.02 * fabs(b[q]) + 1e-6);
    CHECK_ERROR(BOX "create_atoms 1 single 0 0 0 units box\npair_style granular\n"
                    "pair_coeff * * jkr 1000 50 0.3 5 tangential linear_history 800 0.5 0.4\n"
                    "fix 1 all nve/sphere\nfix 3 all wall/pair zplane -2.5 NULL\nrun 1\n",
                "use fix wall/gran", 11);
}

int main(void)
{
    RUN(errors);
    RUN(rest_on_floor);
    RUN(null_face_free_fall);
    RUN(wiggle_lifts);
    RUN(wall_pair_granular);
    return 0;
}
