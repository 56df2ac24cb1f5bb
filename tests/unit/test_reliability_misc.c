/* test_reliability_misc.c - issue 24, silent wrong results and misleading
 * messages of boxes, read_dump and rerun, groups, atom renumbering,
 * displace_atoms, if, pair colloid and run every. Each bad case is matched
 * by its message fragment and the script line it names; the good neighbours
 * of each case still run. */
#include <stdlib.h>
#include <unistd.h>

#include "test.h"
#include "test_tmp.h"

#include "atoms.h"
#include "group.h"

static char script[8192];
#define SCRIPT(...) snprintf(script, sizeof script, __VA_ARGS__)

#define BOX "units lj\natom_style sphere\nregion b block 0 10 0 10 0 10\ncreate_box 1 b\n"

/* change_box: the box length and the skew are checked as create_box does */
TEST(change_box_limits)
{
    CHECK_ERROR(BOX "change_box all x final -1e308 1e308\n", "give a box length of inf: too large",
                5);
    CHECK_ERROR(BOX "change_box all x final 0 2e19 units box\n", "too large", 5);
    CHECK_ERROR(BOX "change_box all triclinic\nchange_box all xy final 30\n",
                "triclinic box skew is too large: tilts xy 30", 6);
    CHECK_ERROR(BOX "change_box all triclinic xy final 1e300\n", "skew is too large", 5);
    CHECK_ERROR(BOX "change_box all triclinic yz delta -6 units box\n",
                "skew is too large: tilts xy 0 xz 0 yz -6", 5);
    /* shrinking x under a tilt that was legal: LAMMPS checks after each change */
    CHECK_ERROR(BOX "change_box all triclinic xy final 4 units box\n"
                    "change_box all x final 0 6 units box\n",
                "skew is too large", 6);
    /* create_box shares the check */
    CHECK_ERROR("units lj\natom_style sphere\nregion p prism 0 10 0 10 0 10 8 0 0\n"
                "create_box 1 p\n",
                "triclinic box skew is too large: tilts xy 8", 4);
    /* at half the length it is legal, as in LAMMPS */
    struct gravel *g = test_engine();
    CHECK(test_script(g, BOX "change_box all triclinic xy final 5 xz final -5 yz final 5 "
                             "units box\n") == GR_OK);
    CHECK(g->dom.xy == 5 && g->dom.xz == -5 && g->dom.yz == 5);
    gr_destroy(g);
}

static const char *DUMP_HEAD = "ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\n"
                               "ITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\n"
                               "ITEM: ATOMS id type x y z\n";

/* a one-snapshot dump at step 5 whose atom lines are `atoms` */
static const char *dump_file(const char *name, int n, const char *atoms)
{
    char text[2048];
    int k = snprintf(text, sizeof text, DUMP_HEAD, 5, n);
    snprintf(text + k, sizeof text - (size_t)k, "%s", atoms);
    const char *p = tmp_path(name);
    write_text(p, text);
    return p;
}

TEST(read_dump_values)
{
    const char *f = dump_file("nan.dump", 3, "1 1 1 1 1\n2 1 nan 2 2\n3 1 3 3 3\n");
    SCRIPT(BOX "read_dump %s 5 x y z add keep\n", f);
    CHECK_ERROR(script, "line 11 (step 5): atom ID 2 has a non-finite x ('nan')", 5);
    f = dump_file("inf.dump", 2, "1 1 1 1 1\n4 1 1 -inf 2\n");
    SCRIPT(BOX "read_dump %s 5 x y z add keep\n", f);
    CHECK_ERROR(script, "line 11 (step 5): atom ID 4 has a non-finite y ('-inf')", 5);
    f = dump_file("dup.dump", 3, "1 1 1 1 1\n2 1 2 2 2\n2 1 3 3 3\n");
    SCRIPT(BOX "read_dump %s 5 x y z add keep\n", f);
    CHECK_ERROR(script, "(step 5): atom ID 2 appears twice, on lines 11 and 12", 5);
    f = dump_file("big.dump", 2, "1 1 1 1 1\n9223372036854775807 1 3 3 3\n");
    SCRIPT(BOX "read_dump %s 5 x y z add keep\n", f);
    CHECK_ERROR(script, "line 11 (step 5): atom ID 9223372036854775807 is too big (at most "
                        "9223372036854775806)", 5);
    f = dump_file("huge.dump", 1, "99999999999999999999 1 3 3 3\n");
    SCRIPT(BOX "read_dump %s 5 x y z add keep\n", f);
    CHECK_ERROR(script, "atom ID 99999999999999999999 is too big", 5);
    f = dump_file("frac.dump", 1, "1.5 1 3 3 3\n");
    SCRIPT(BOX "read_dump %s 5 x y z add keep\n", f);
    CHECK_ERROR(script, "atom ID '1.5' is not an integer", 5);
    f = dump_file("type.dump", 1, "1 1e300 3 3 3\n");
    SCRIPT(BOX "read_dump %s 5 x y z add keep\n", f);
    CHECK_ERROR(script, "atom ID 1 has type '1e300' (an integer", 5);
    /* a large ID that fits is kept exactly (not rounded through a double) */
    f = dump_file("ok.dump", 2, "1 1 1 1 1\n9007199254740993 1 3 3 3\n");
    SCRIPT(BOX "read_dump %s 5 x y z add keep\n", f);
    struct gravel *g = test_engine();
    CHECK(test_script(g, script) == GR_OK);
    CHECK(g->atoms.n == 2 && g->atoms.tag[1] == 9007199254740993LL);
    CHECK(g->atoms.maxtag == 9007199254740993LL);
    gr_destroy(g);
}

/* an orthogonal snapshot into a triclinic box: box yes errors as LAMMPS,
 * box no keeps the box and its tilt */
TEST(read_dump_triclinic_box)
{
    const char *f = dump_file("ortho.dump", 1, "1 1 1 1 1\n");
    SCRIPT(BOX "change_box all triclinic xy final 1 units box\nread_dump %s 5 x y z add yes\n",
           f);
    CHECK_ERROR(script, "has an orthogonal box but the simulation box is triclinic", 6);
    SCRIPT(BOX "change_box all triclinic xy final 1 units box\n"
               "read_dump %s 5 x y z add yes box no\n",
           f);
    struct gravel *g = test_engine();
    CHECK(test_script(g, script) == GR_OK);
    CHECK(g->dom.triclinic == 1 && g->dom.xy == 1.0 && g->atoms.n == 1);
    gr_destroy(g);
}

/* a triclinic snapshot (gravel's own dump of a prism box): box yes takes its
 * box and tilts, and the atoms come back where they were (to the round-off
 * of the remap through lamda coordinates, as LAMMPS's) */
TEST(read_dump_triclinic_snapshot)
{
    const char *prism = "units lj\natom_style sphere\n"
                        "region p prism 0 10 0 8 0 6 2 -1 1.5\ncreate_box 1 p\n";
    const char *other = "units lj\natom_style sphere\n"
                        "region p prism 0 5 0 5 0 5 1 0 0\ncreate_box 1 p\n";
    struct gravel *g = test_engine();
    SCRIPT("%screate_atoms 1 single 1 1 1\ncreate_atoms 1 single 9.5 7 5.5\n"
           "create_atoms 1 single 3 4 2\n"
           "write_dump all custom %s id type x y z modify format float %%.17g\n"
           "write_dump all custom %s id type xs ys zs modify format float %%.17g\n",
           prism, tmp_path("tri_u.dump"), tmp_path("tri_s.dump"));
    CHECK(test_script(g, script) == GR_OK);
    double x0[9];
    memcpy(x0, g->atoms.x, sizeof x0);
    gr_destroy(g);
    for (int scaled = 0; scaled < 2; scaled++) {
        g = test_engine();
        SCRIPT("%sread_dump %s 0 x y z add keep\n", other,
               tmp_path(scaled ? "tri_s.dump" : "tri_u.dump"));
        CHECK(test_script(g, script) == GR_OK);
        CHECK(g->dom.triclinic && g->dom.xy == 2 && g->dom.xz == -1 && g->dom.yz == 1.5);
        CHECK(g->dom.lo[0] == 0 && g->dom.hi[0] == 10 && g->dom.hi[1] == 8 &&
              g->dom.hi[2] == 6);
        CHECK(g->atoms.n == 3);
        for (int k = 0; k < 9 && g->atoms.n == 3; k++)
            CHECK_NEAR(g->atoms.x[k], x0[k], 1e-12);
        gr_destroy(g);
    }
    /* into an orthogonal box: box yes refuses (LAMMPS), box no keeps the box */
    SCRIPT(BOX "read_dump %s 0 x y z add keep\n", tmp_path("tri_u.dump"));
    CHECK_ERROR(script, "has a triclinic box but the simulation box is orthogonal", 5);
    g = test_engine();
    SCRIPT(BOX "read_dump %s 0 x y z add keep box no\n", tmp_path("tri_u.dump"));
    CHECK(test_script(g, script) == GR_OK);
    CHECK(!g->dom.triclinic && g->dom.hi[0] == 10 && g->atoms.n == 3);
    gr_destroy(g);
    /* scaled triclinic coordinates need all three columns */
    g = test_engine();
    SCRIPT("%sread_dump %s 0 x y add keep\n", other, tmp_path("tri_s.dump"));
    CHECK(test_script(g, script) == GR_ERR);
    CHECK(strstr(g->err.msg, "need all of the x, y, z fields") != NULL);
    gr_destroy(g);
}

/* rerun: a non-finite position in a later snapshot names the snapshot */
TEST(rerun_nonfinite)
{
    char text[2048];
    int k = snprintf(text, sizeof text, DUMP_HEAD, 0, 2);
    k += snprintf(text + k, sizeof text - (size_t)k, "1 1 1 1 1\n2 1 3 3 3\n");
    k += snprintf(text + k, sizeof text - (size_t)k, DUMP_HEAD, 10, 2);
    snprintf(text + k, sizeof text - (size_t)k, "1 1 1 1 1\n2 1 3 nan 3\n");
    write_text(tmp_path("rerun.dump"), text);
    SCRIPT(BOX "create_atoms 1 single 1 1 1\ncreate_atoms 1 single 3 3 3\n"
               "pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *\n"
               "rerun %s dump x y z\n",
           tmp_path("rerun.dump"));
    CHECK_ERROR(script, "line 22 (step 10): atom ID 2 has a non-finite y ('nan')", 9);
}

TEST(group_delete_in_use)
{
    const char *setup = BOX "create_atoms 1 single 1 1 1\ngroup p id 1\n";
    SCRIPT("%sgroup d dynamic p every 1\ngroup p delete\n", setup);
    CHECK_ERROR(script, "group 'p' is the parent of dynamic group 'd' and cannot be deleted", 8);
    SCRIPT("%sfix 1 p nve/sphere\ngroup p delete\n", setup);
    CHECK_ERROR(script, "group 'p' is used by fix 1 and cannot be deleted", 8);
    SCRIPT("%scompute k p ke\ngroup p delete\n", setup);
    CHECK_ERROR(script, "group 'p' is used by compute k and cannot be deleted", 8);
    SCRIPT("%sdump d p atom 10 %s\ngroup p delete\n", setup, tmp_path("g.dump"));
    CHECK_ERROR(script, "group 'p' is used by dump d and cannot be deleted", 8);
    /* once the dynamic group is static, or gone, p can go */
    struct gravel *g = test_engine();
    SCRIPT("%sgroup d dynamic p every 1\ngroup d static\ngroup p delete\n", setup);
    CHECK(test_script(g, script) == GR_OK);
    CHECK(group_find(g, "p") < 0 && group_find(g, "d") >= 0);
    gr_destroy(g);
}

static int index_of(const struct gravel *g, int64_t tag)
{
    for (int i = 0; i < g->atoms.n; i++)
        if (g->atoms.tag[i] == tag)
            return i;
    return -1;
}

static double dist(const struct gravel *g, int64_t t1, int64_t t2)
{
    int i = index_of(g, t1), j = index_of(g, t2);
    if (i < 0 || j < 0)
        return -1;
    double s = 0;
    for (int d = 0; d < 3; d++) {
        double dx = g->atoms.x[3 * i + d] - g->atoms.x[3 * j + d];
        s += dx * dx;
    }
    return sqrt(s);
}

/* Two bodies whose atoms a spatial sort would renumber across them. */
#define RIGID                                                                               \
    "units lj\natom_style sphere\nboundary p p p\nfix prop all property/atom mol\n"        \
    "region box block 0 10 0 10 0 10\ncreate_box 1 box\n"                                   \
    "create_atoms 1 single 8.0 5.0 5.0 units box\ncreate_atoms 1 single 8.9 5.0 5.0 units box\n" \
    "create_atoms 1 single 1.0 5.0 5.0 units box\ncreate_atoms 1 single 1.9 5.0 5.0 units box\n" \
    "set atom 1*2 mol 1\nset atom 3*4 mol 2\nset atom * diameter 1.0 density 1.0\n"          \
    "pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1\npair_coeff * *\n"          \
    "neigh_modify delay 0 exclude molecule/intra all\ntimestep 0.001\n"                      \
    "velocity all set 0 0 0\nset atom 1 vx 0.5 vy 1.0\nset atom 3 vz -1.0\n"                 \
    "fix rig all rigid/small molecule\ncompute_modify thermo_temp extra/dof 0\n"

TEST(renumber_rigid_bodies)
{
    /* line 21: the rigid fix; line 23 the refused command */
    CHECK_ERROR(RIGID "reset_atom_ids sort yes\n",
                "cannot reset atom IDs while fix rig (rigid/small) holds atoms by their IDs", 23);
    CHECK_ERROR(RIGID "delete_atoms group all\n",
                "compress yes would renumber the atoms that fix rig (rigid/small) holds", 23);
    /* the refusal changes nothing: a body's atoms keep their distance in a run */
    struct gravel *g = test_engine();
    CHECK(test_script(g, RIGID) == GR_OK);
    CHECK(test_script(g, "reset_atom_ids sort yes\n") == GR_ERR);
    CHECK(test_script(g, "run 200\n") == GR_OK);
    CHECK_NEAR(dist(g, 1, 2), 0.9, 1e-12);
    CHECK_NEAR(dist(g, 3, 4), 0.9, 1e-12);
    gr_destroy(g);
    /* without the fix, sort yes renumbers spatially (atoms 3, 4 first) */
    g = test_engine();
    CHECK(test_script(g, RIGID "unfix rig\nreset_atom_ids sort yes\n") == GR_OK);
    CHECK(g->atoms.tag[2] == 1 && g->atoms.tag[0] == 3);
    gr_destroy(g);
}

TEST(displace_nonfinite)
{
    CHECK_ERROR(BOX "create_atoms 1 single 1 1 1\nvariable dx equal 1e309\n"
                    "displace_atoms all move v_dx 0 0\n",
                "move would put atom 1 at a non-finite position (inf 1 1); no atom was moved", 7);
    /* an error leaves every atom where it was, the other dimensions too */
    struct gravel *g = test_engine();
    CHECK(test_script(g, BOX "create_atoms 1 single 1 1 1\nvariable dz equal 1e309\n") ==
          GR_OK);
    CHECK(test_script(g, "displace_atoms all move 2 2 v_dz units box\n") == GR_ERR);
    CHECK(g->atoms.x[0] == 1 && g->atoms.x[1] == 1 && g->atoms.x[2] == 1);
    CHECK(test_script(g, "displace_atoms all move 2 2 0 units box\n") == GR_OK);
    CHECK(g->atoms.x[0] == 3 && g->atoms.x[1] == 3 && g->atoms.x[2] == 1);
    gr_destroy(g);
}

TEST(if_else_twice)
{
    CHECK_ERROR("print a\nif \"1 > 2\" then \"print a\" else \"print b\" else \"print c\"\n",
                "'else' after 'else' (argument 6): 'else' must be the last branch", 2);
    CHECK_ERROR("if \"1 > 2\" then \"print a\" else \"print b\" elif \"1 < 2\" \"print c\"\n",
                "'elif' after 'else'", 1);
    /* nothing ran: the check precedes the branches */
    struct gravel *g = test_engine();
    CHECK(test_script(g, "variable n equal 1\n"
                         "if \"1 < 2\" then \"variable n equal 2\" else \"print b\" else "
                         "\"print c\"\n") == GR_ERR);
    CHECK(test_script(g, "if \"${n} == 1\" then \"variable ok equal 1\" elif \"1 < 2\" "
                         "\"variable ok equal 0\" else \"variable ok equal 0\"\n") == GR_OK);
    CHECK(test_script(g, "print ${ok}\n") == GR_OK);
    gr_destroy(g);
}

/* LAMMPS stops on overlapping colloids ("Overlapping large/large in pair colloid") */
TEST(colloid_overlap)
{
    const char *deck =
        "units lj\natom_style sphere\nboundary f f f\nregion box block -40 40 -40 40 -40 40\n"
        "create_box 2 box\ncreate_atoms 1 single 0 0 0 units box\n"
        "create_atoms %d single %s 0 0 units box\npair_style colloid 30.0\n"
        "pair_coeff 1 1 39.5 1.0 10.0 10.0\npair_coeff 2 2 1.0 1.0 0.0 0.0\n"
        "pair_coeff 1 2 39.5 1.0 10.0 0.0\nset type 1 mass 400.0\ntimestep 0.001\n"
        "fix 1 all nve\nrun 10\n";
    SCRIPT(deck, 1, "8.0");
    CHECK_ERROR(script, "non-finite position or velocity at step 1", 15);
    CHECK_ERROR(script, "Overlapping large/large in pair colloid", 15);
    SCRIPT(deck, 2, "4.0"); /* a point particle inside the colloid (radius 5) */
    CHECK_ERROR(script, "pair colloid stops on overlapping particles", 15);
    /* apart, they run */
    struct gravel *g = test_engine();
    SCRIPT(deck, 1, "12.5");
    CHECK(test_script(g, script) == GR_OK);
    gr_destroy(g);
}

TEST(messages)
{
    CHECK_ERROR(BOX "fix 1 all nph xy 1 1 1\n",
                "keyword 'xy' (a tilt factor or off-diagonal stress) is not supported", 5);
    CHECK_ERROR("units lj\natom_style sphere\nregion b block 0 5e18 0 1 0 1\ncreate_box 1 b\n"
                "replicate 200000 1 1\n",
                "replicating 200000 times in x makes the box 0 to 1e+24, a length of 1e+24: too "
                "large", 5);
    CHECK_ERROR(BOX "create_atoms 1 single 1 1 1\nset group all diameter 1 density 1\n"
                    "pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *\n"
                    "fix 1 all nve/sphere\ntimestep 0.001\nrun 4 every 2 \"clear\"\n",
                "clear: cannot be used in the commands of 'run ... every'", 11);
    /* after the refusal, clear works again at the top level */
    struct gravel *g = test_engine();
    CHECK(test_script(g, BOX "create_atoms 1 single 1 1 1\nset group all diameter 1 density 1\n"
                             "pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *\n"
                             "fix 1 all nve/sphere\ntimestep 0.001\n") == GR_OK);
    CHECK(test_script(g, "run 2 every 1 \"clear\"\n") == GR_ERR);
    CHECK(test_script(g, "clear\n") == GR_OK);
    CHECK(g->atoms.n == 0 && !g->dom.box_exists);
    gr_destroy(g);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/gravel_relmisc_XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    RUN(change_box_limits);
    RUN(read_dump_values);
    RUN(read_dump_triclinic_box);
    RUN(read_dump_triclinic_snapshot);
    RUN(rerun_nonfinite);
    RUN(group_delete_in_use);
    RUN(renumber_rigid_bodies);
    RUN(displace_nonfinite);
    RUN(if_else_twice);
    RUN(colloid_overlap);
    RUN(messages);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0)
        return 1;
    return t_failed_checks ? 1 : 0;
}
