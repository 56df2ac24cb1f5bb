/* test_settings.c - units, dimension, atom_style, boundary, timestep,
 * neighbor, neigh_modify, mass: stored state and validation errors. */
#include "test.h"

#include "domain.h"

TEST(units_defaults)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "units si\n") == GR_OK);
    CHECK(g->dom.units == UNITS_SI);
    CHECK_NEAR(g->dt, 1e-8, 0);
    CHECK_NEAR(g->neigh.skin, 0.001, 0);
    CHECK(test_script(g, "units cgs\n") == GR_OK);
    CHECK_NEAR(g->neigh.skin, 0.1, 0);
    CHECK(test_script(g, "units lj\n") == GR_OK);
    CHECK_NEAR(g->dt, 0.005, 0);
    CHECK(g->thermo.norm == 1);
    gr_destroy(g);
    CHECK_ERROR("units real\n", "units 'real' is not supported", 1);
    CHECK_ERROR("\nunits furlong\n", "unknown units 'furlong'", 2);
}

TEST(dimension_atom_style)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "dimension 3\natom_style sphere\natom_style sphere 1\n") == GR_OK);
    CHECK(g->dom.dimension == 3);
    gr_destroy(g);
    g = test_engine();
    CHECK(test_script(g, "dimension 2\n") == GR_OK);
    CHECK(g->dom.dimension == 2);
    gr_destroy(g);
    CHECK_ERROR("dimension 4\n", "dimension must be 2 or 3", 1);
    CHECK_ERROR("dimension 2\nboundary p p f\nregion b block 0 1 0 1 0 1\ncreate_box 1 b\n",
                "non-periodic z", 4);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 1 b\ndimension 2\n",
                "before the simulation box", 3);
    CHECK_ERROR("atom_style atomic\n", "atom_style 'atomic' is not supported", 1);
    CHECK_ERROR("atom_style sphere 2\n", "radvary flag must be between 0 and 1", 1);
}

TEST(boundary_flags)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "boundary p fm s\n") == GR_OK);
    CHECK(g->dom.periodic[0] && !g->dom.periodic[1] && !g->dom.periodic[2]);
    CHECK(g->dom.bnd[1][0] == 'f' && g->dom.bnd[1][1] == 'm');
    CHECK(g->dom.bnd[2][0] == 's' && g->dom.bnd[2][1] == 's');
    gr_destroy(g);
    CHECK_ERROR("boundary p pf p\n", "both faces of y must be periodic", 1);
    CHECK_ERROR("boundary p p q\n", "unknown boundary 'q' for z", 1);
    CHECK_ERROR("boundary p p sss\n", "boundary for z must be one or two", 1);
}

TEST(timestep_neighbor)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "timestep 0.001\nneighbor 0.2 bin\n"
                         "neigh_modify every 2 delay 4 check no one 500 page 6000\n") == GR_OK);
    CHECK_NEAR(g->dt, 0.001, 0);
    CHECK(g->dt_set == 1);
    CHECK_NEAR(g->neigh.skin, 0.2, 0);
    CHECK(g->neigh.every == 2 && g->neigh.delay == 4 && g->neigh.check == 0);
    CHECK(g->neigh.one == 500 && g->neigh.page == 6000);
    gr_destroy(g);
    CHECK_ERROR("timestep -1\n", "timestep must be positive", 1);
    CHECK_ERROR("timestep abc\n", "expected a number for timestep, got 'abc'", 1);
    CHECK_ERROR("neighbor 0.3 nsq\n", "neighbor style 'nsq' is not supported", 1);
    CHECK_ERROR("neighbor -0.3 bin\n", "skin must not be negative", 1);
    CHECK_ERROR("neigh_modify every 3 delay 4\n", "delay (4) must be 0 or a multiple of every", 1);
    CHECK_ERROR("neigh_modify one 2000 page 100\n", "page (100) must be at least 10 x one", 1);
    CHECK_ERROR("neigh_modify evry 2\n", "unknown keyword 'evry'", 1);
    CHECK_ERROR("neigh_modify every\n", "keyword 'every' needs 1 value", 1);
}

TEST(neigh_exclude_and_mass)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "region b block 0 1 0 1 0 1\ncreate_box 3 b\n"
                         "neigh_modify exclude type 1 2 exclude type 2 3\n"
                         "group none empty\nneigh_modify exclude group none all\n"
                         "mass 2* 3.5\n") == GR_OK);
    CHECK(g->neigh.nexclude_type == 2);
    CHECK(g->neigh.exclude_type[1][0] == 2 && g->neigh.exclude_type[1][1] == 3);
    CHECK(g->neigh.nexclude == 1 && g->neigh.exclude_group[0][1] == 0);
    CHECK(g->atoms.type_mass[1] == 0 && g->atoms.type_mass[2] == 3.5 &&
          g->atoms.type_mass[3] == 3.5);
    CHECK(test_script(g, "neigh_modify exclude none\n") == GR_OK);
    CHECK(g->neigh.nexclude_type == 0 && g->neigh.nexclude == 0);
    gr_destroy(g);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 3 b\nneigh_modify exclude type 1 4\n",
                "exclude type must be between 1 and 3", 3);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 3 b\nneigh_modify exclude group a b\n",
                "unknown group 'a'", 3);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 3 b\nmass 4 1.0\n",
                "type range '4' is outside 1..3", 3);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 3 b\nmass 1 0\n",
                "mass must be positive", 3);
}

TEST(phase_guards)
{
    /* pre-box commands after the box, post-box commands before it: an error
     * on the right line (the text may come from the dispatcher's phase check) */
    static const char *after[] = {"units si", "dimension 3", "atom_style sphere",
                                  "boundary p p p"};
    for (int k = 0; k < 4; k++) {
        char s[256];
        snprintf(s, sizeof s, "region b block 0 1 0 1 0 1\ncreate_box 1 b\n%s\n", after[k]);
        CHECK_ERROR(s, "", 3);
    }
    static const char *before[] = {"mass 1 1.0", "group a empty", "set atom 1 mass 1",
                                   "velocity all set 1 1 1", "write_data x.data"};
    for (int k = 0; k < 5; k++) {
        char s[256];
        snprintf(s, sizeof s, "\n%s\n", before[k]);
        CHECK_ERROR(s, "", 2);
    }
}

int main(void)
{
    RUN(units_defaults);
    RUN(dimension_atom_style);
    RUN(boundary_flags);
    RUN(timestep_neighbor);
    RUN(neigh_exclude_and_mass);
    RUN(phase_guards);
    return 0;
}
