/* test_liggghts_materials.c - LIGGGHTS's material front-end: atom_style
 * granular, fix property/global (forms, lookups, errors), the mixing of
 * pair_style gran (Y*, G*, beta against numbers worked from LIGGGHTS's
 * global_properties.cpp formulas), and the parse errors of pair_style gran,
 * fix wall/gran model ... and fix check/timestep/gran. */
#include <math.h>

#include "test.h"

#include "fix_property_global.h"
#include "pair_gran.h"

#define BOX "units si\natom_style granular\nregion b block -1 1 -1 1 -1 1\ncreate_box 2 b\n"
#define MAT                                                                                    \
    "fix m1 all property/global youngsModulus peratomtype 5.e6 2.e7\n"                         \
    "fix m2 all property/global poissonsRatio peratomtype 0.45 0.3\n"                          \
    "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.7 0.6 0.6 0.9\n"    \
    "fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.3 0.3 0.2\n"

TEST(atom_style_granular)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "atom_style granular\n") == GR_OK);
    gr_destroy(g);
    CHECK_ERROR("atom_style granular 1\n", "atom_style granular takes no arguments", 1);
}

TEST(property_global_forms)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, BOX MAT
                      "fix m5 all property/global characteristicVelocity scalar 2.\n"
                      "fix m6 all property/global v vector 1 2 3\n"
                      "fix m7 all property/global mm matrix 2 1 2 3 4 5 6\n") == GR_OK);
    const struct fpg *p = fpg_find(g, "characteristicVelocity");
    CHECK(p && p->form == FPG_SCALAR && p->n == 1 && p->v[0] == 2.0);
    CHECK(fpg_scalar(g, "characteristicVelocity", "t") == 2.0);
    p = fpg_find(g, "mm");
    CHECK(p && p->form == FPG_MATRIX && p->ncol == 2 && p->n == 6 && p->v[5] == 6.0);
    CHECK(fpg_pertype(g, "youngsModulus", 2, "t")[1] == 2e7);
    CHECK(fpg_pair(g, "coefficientRestitution", 2, 1, 2, "t") == 0.6);
    CHECK(fpg_pair(g, "coefficientRestitution", 2, 2, 2, "t") == 0.9);
    CHECK(fpg_find(g, "nothing") == NULL);
    gr_destroy(g);
    CHECK_ERROR(BOX "fix m all property/global Y perparticle 1\n", "unknown form 'perparticle'",
                5);
    CHECK_ERROR(BOX "fix m all property/global e peratomtypepair 2 0.7 0.6 0.5 0.9\n",
                "must be symmetric", 5);
    CHECK_ERROR(BOX "fix m all property/global e peratomtypepair 2 0.7 0.6 0.6\n",
                "must be a multiple of nCols", 5);
    CHECK_ERROR(BOX "fix m all property/global c scalar 1 2\n", "expected 1 value, got 2", 5);
    CHECK_ERROR(BOX "fix m all property/global c scalar\n", "expects a property name", 5);
    CHECK_ERROR(BOX "fix m all property/global c vector 1 x\n", "x", 5);
    CHECK_ERROR(BOX "fix a all property/global c scalar 1\nfix b all property/global c scalar 2\n",
                "already registers a variable of the same name", 6);
}

/* Y* = 1 / ((1 - nu_i^2) / Y_i + (1 - nu_j^2) / Y_j), G* = 1 / (2 (2 - nu_i)
 * (1 + nu_i) / Y_i + ...), beta = ln e / sqrt(ln^2 e + pi^2): for types 1
 * (5e6, 0.45) and 2 (2e7, 0.3), e = 0.6: 1 / 2.05e-7, 1 / 1.12e-6 and
 * ln 0.6 / sqrt(ln^2 0.6 + pi^2) */
TEST(gran_mixing)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, BOX MAT "fix m5 all property/global characteristicVelocity scalar 2.\n") ==
          GR_OK);
    struct lg_model m = {LG_N_HOOKE, 1, LG_C_NONE, LG_R_NONE, 1, 0, 0, 0, 0};
    double q[LG_NPARAM];
    lg_check(g, &m, 2, "t");
    lg_pack(g, &m, 2, 1, 2, 0, q, "t");
    CHECK_NEAR(q[LG_YEFF], 1.0 / 2.05e-7, 1e-8 / 2.05e-7);
    CHECK_NEAR(q[LG_GEFF], 1.0 / 1.12e-6, 1e-8 / 1.12e-6);
    CHECK_NEAR(q[LG_BETA], log(0.6) / sqrt(log(0.6) * log(0.6) + M_PI * M_PI), 1e-15);
    CHECK_NEAR(q[LG_BETA], -0.16049305, 1e-8);
    CHECK(q[LG_MU] == 0.3 && q[LG_CHARV] == 2.0 && q[LG_WALL] == 0.0 && q[LG_NMODEL] == LG_N_HOOKE);
    lg_pack(g, &m, 2, 2, 2, 1, q, "t");
    CHECK_NEAR(q[LG_YEFF], 0.5 * 2e7 / (1 - 0.09), 1e-6);
    CHECK(q[LG_WALL] == 1.0 && q[LG_MU] == 0.2);
    gr_destroy(g);
}

TEST(gran_parse_errors)
{
    CHECK_ERROR(BOX "pair_style gran model hooke/plastic tangential history\n",
                "model 'hooke/plastic' is not supported", 5);
    CHECK_ERROR(BOX "pair_style gran model hertz\n", "expected 'tangential history|no_history'",
                5);
    CHECK_ERROR(BOX "pair_style gran tangential history\n", "expected 'model hertz", 5);
    CHECK_ERROR(BOX "pair_style gran model hertz tangential history rolling_friction luding\n",
                "rolling_friction model 'luding' is not supported", 5);
    CHECK_ERROR(BOX "pair_style gran model hertz tangential history cohesion washino\n",
                "cohesion model 'washino' is not supported", 5);
    CHECK_ERROR(BOX "pair_style gran model hertz tangential history limitForce maybe\n",
                "expected on or off after 'limitForce'", 5);
    CHECK_ERROR(BOX "pair_style gran model hertz tangential history heating_normal_hertz on\n",
                "'heating_normal_hertz on' is not supported", 5);
    CHECK_ERROR(BOX "pair_style gran model hertz tangential history bogus 1\n",
                "unknown keyword 'bogus'", 5);
    CHECK_ERROR(BOX "pair_style gran model hertz tangential\n", "missing the value after", 5);
    CHECK_ERROR(BOX "fix w all wall/gran model hertz tangential history primitive type 3 zplane 0\n",
                "primitive type 3 is out of range 1..2", 5);
    CHECK_ERROR(BOX "fix w all wall/gran model hertz tangential history primitive type 1 "
                    "xcone 0.1 0 0\n",
                "primitive 'xcone' is not supported", 5);
    /* LIGGGHTS's primitives may stand across periodic dimensions (LAMMPS's may not) */
    {
        struct gravel *gp = test_engine();
        CHECK(test_script(gp, BOX "fix w all wall/gran model hertz tangential history "
                                  "primitive type 1 xcylinder 0.1 0 0\n"
                                  "fix w2 all wall/gran model hertz tangential history "
                                  "primitive type 1 zplane 0\n") == GR_OK);
        gr_destroy(gp);
    }
    CHECK_ERROR(BOX "fix w all wall/gran hooke/history 2000 NULL 50 NULL 0.5 0 zplane 0 NULL\n",
                "cannot use a zplane wall in the periodic dimension z", 5);
    CHECK_ERROR(BOX "fix w all wall/gran model hertz tangential history\n",
                "missing the wall ('primitive type T", 5);
    CHECK_ERROR(BOX "fix w all wall/gran model hertz tangential history primitive kind 1 zplane "
                    "0\n",
                "expected 'type T'", 5);
    CHECK_ERROR(BOX "fix w all wall/gran model hertz tangential history primitive type 1 zplane "
                    "0 store_force yes\n",
                "'store_force yes' is not supported", 5);
    CHECK_ERROR(BOX "fix w all wall/gran/region model hertz tangential history region r\n",
                "LIGGGHTS's 'model ...' form is not supported", 5);
    CHECK_ERROR(BOX "fix ts all check/timestep/gran 0 0.1 0.1\n", "N must be >= 1", 5);
    CHECK_ERROR(BOX "fix ts all check/timestep/gran 10 0.1 0.1 warn maybe\n", "warn", 5);
    CHECK_ERROR(BOX "fix ts all check/timestep/gran 10 0.1 0.1 loud yes\n",
                "unknown fix check/timestep/gran keyword 'loud'", 5);
}

/* What a run checks: every property the model reads, its range */
TEST(gran_run_errors)
{
    const char *atoms = "create_atoms 1 single 0 0 0\nset type 1 diameter 0.01\n"
                        "set type 1 density 2500\npair_coeff * *\nfix i all nve/sphere\n";
    char buf[2048];
    snprintf(buf, sizeof buf, "%s%s%s%srun 0\n", BOX,
             "fix m1 all property/global youngsModulus peratomtype 5.e6 2.e7\n"
             "fix m2 all property/global poissonsRatio peratomtype 0.45 0.3\n"
             "fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.3 0.3 0.2\n",
             "pair_style gran model hertz tangential history\n", atoms);
    CHECK_ERROR(buf, "requires a fix property/global that defines coefficientRestitution", 14);
    snprintf(buf, sizeof buf, "%s%s%s%srun 0\n", BOX MAT,
             "fix m5 all property/global characteristicVelocity peratomtype 2. 2.\n",
             "pair_style gran model hooke tangential history\n", atoms);
    CHECK_ERROR(buf, "characteristicVelocity must be defined as a scalar", 16);
    snprintf(buf, sizeof buf, "%s%s%srun 0\n", BOX
             "fix m1 all property/global youngsModulus peratomtype 5.e6\n"
             "fix m2 all property/global poissonsRatio peratomtype 0.45 0.3\n",
             "pair_style gran model hertz tangential history\n", atoms);
    CHECK_ERROR(buf, "youngsModulus has 1 value(s), 2 atom type(s) need one each", 13);
    snprintf(buf, sizeof buf, "%s%s%srun 0\n", BOX MAT
             "fix m6 all property/global coefficientRestitution2 scalar 1\n",
             "pair_style gran model hertz tangential history cohesion sjkr\n", atoms);
    CHECK_ERROR(buf, "defines cohesionEnergyDensity", 16);
#define ROLL "fix m6 all property/global coefficientRollingFriction peratomtypepair 2 .1 .1 .1 .1\n"
    snprintf(buf, sizeof buf, "%s%s%srun 0\n", BOX MAT ROLL,
             "pair_style gran model hertz tangential history rolling_friction epsd\n", atoms);
    CHECK_ERROR(buf, "defines coefficientRollingViscousDamping", 16);
    snprintf(buf, sizeof buf, "%s%s%srun 0\n", BOX MAT ROLL
             "fix m7 all property/global coefficientRollingViscousDamping peratomtypepair 2 "
             ".3 .3 .3 .3\nfix m8 all property/global rollingStiffness scalar 0.5\n",
             "pair_style gran model hertz tangential history rolling_friction epsd3\n", atoms);
    CHECK_ERROR(buf, "rollingStiffness must be >= 0 (>= 1 for SI units), got 0.5", 18);
#undef ROLL
    snprintf(buf, sizeof buf, "%s%s%s%srun 0\n", BOX,
             "fix m1 all property/global youngsModulus peratomtype 5.e6 2.e7\n"
             "fix m2 all property/global poissonsRatio peratomtype 0.45 0.6\n"
             "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.7 0.6 0.6 0.9\n"
             "fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.3 0.3 0.2\n",
             "pair_style gran model hertz tangential history\n", atoms);
    CHECK_ERROR(buf, "0 <= poissonsRatio <= 0.5 required (type 2: 0.6)", 15);
    snprintf(buf, sizeof buf, "%s%s%s%srun 0\n", BOX MAT,
             "fix ts all check/timestep/gran 10 0.1 0.1\n", "pair_style gran/hooke 1 NULL 0 NULL 0 0\n",
             "create_atoms 1 single 0 0 0\npair_coeff * *\nrun 0\n");
    CHECK_ERROR(buf, "can only be used together with: gran", 13);
}

int main(void)
{
    RUN(atom_style_granular);
    RUN(property_global_forms);
    RUN(gran_mixing);
    RUN(gran_parse_errors);
    RUN(gran_run_errors);
    return 0;
}
