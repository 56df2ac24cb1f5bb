/* test_thermo.c - thermo header and lines in LAMMPS 2021's layout (checked
 * against lines printed by `lmp` 29Sep2021 for the same settings), formats
 * and their precedence, normalization, keyword values, the output schedule
 * and the run footer. */
#include "device.h"
#include "output_fixture.h"

#include <unistd.h>

#include "command.h"
#include "output.h"
#include "thermo.h"
#include "variable.h"
#include "wall_clock.h"

static struct gravel *make(void)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    fx_box(g, lo, hi, 2);
    return g;
}

/* Three atoms at rest except for 1/2 m v^2 = 0.32 each (m = 1, |v| = 0.8). */
static struct gravel *make3(void)
{
    struct gravel *g = make();
    double v[3] = {0.8, 0, 0};
    fx_atom(g, 1, 5, 5, 5, 0.5, 1.0, v, NULL);
    fx_atom(g, 1, 5.9, 5, 5, 0.5, 1.0, v, NULL);
    fx_atom(g, 1, 5.45, 5.8, 5, 0.5, 1.0, v, NULL);
    return g;
}

static void do_init(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    (void)argv;
    thermo_init(g);
}

static void do_setup(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    (void)argv;
    output_setup(g);
}

/* The chute benchmark's step-0 line: same layout and digits as LAMMPS
 * ("       0    32000    784139.13    1601.1263    29833.783"), here with 2
 * atoms whose energies are set to the chute's totals. */
TEST(chute_layout)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {29833.783, 1, 1};
    fx_box(g, lo, hi, 2);
    double v[3] = {sqrt(784139.13), 0, 0};                /* with m 2 */
    double w[3] = {sqrt(16011.263), 0, 0}; /* 1/2 (0.4 m r^2) w^2 with m 2, r 0.5 */
    fx_atom(g, 1, 0.5, 0.5, 0.5, 0.5, 2.0, v, w); /* 1/2 m v^2 = 784139.13 */
    fx_atom(g, 1, 2.5, 0.5, 0.5, 0.5, 1.0, NULL, NULL);
    CHECK(test_script(g, "compute 1 all erotate/sphere\n"
                         "thermo_style custom step atoms ke c_1 vol\n"
                         "thermo_modify norm no\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    CHECK(strcmp(thermo_header_text(g), "Step Atoms KinEng c_1 Volume \n") == 0);
    output_state(g)->firstflag = 1;
    const char *line = thermo_line_text(g);
    CHECK(strcmp(line, "       0        2    784139.13    1601.1263    29833.783 \n") == 0);
    if (strcmp(line, "       0        2    784139.13    1601.1263    29833.783 \n"))
        printf("  got '%s'\n", line);
    fx_destroy(g);
}

/* norm yes (lj default) divides extensive values by the atom count. */
TEST(norm)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {29833.783, 1, 1};
    fx_box(g, lo, hi, 2);
    double v[3] = {10, 20, 20}, w[3] = {10, 0, 0};
    fx_atom(g, 1, 1, 0.5, 0.5, 0.5, 2.0, v, w); /* ke 900, erotate 10 */
    fx_atom(g, 2, 3, 0.5, 0.5, 0.5, 1.0, NULL, NULL);
    CHECK(test_script(g, "compute 1 all erotate/sphere\n"
                         "compute 2 all reduce max vx vy\n"
                         "thermo_style custom step atoms ke c_1 vol c_2[2] etotal pe\n") ==
          GR_OK);
    CHECK(g->thermo.norm == 1);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    const char *line = thermo_line_text(g);
    const char *want = "       0        2          450            5    29833.783           20  "
                       "        450            0 \n";
    CHECK(strcmp(line, want) == 0);
    if (strcmp(line, want))
        printf("  got '%s'\n", line);
    CHECK(test_script(g, "thermo_modify norm no\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    line = thermo_line_text(g);
    want = "       0        2          900           10    29833.783           20          "
           "900            0 \n";
    CHECK(strcmp(line, want) == 0);
    if (strcmp(line, want))
        printf("  got '%s'\n", line);
    fx_destroy(g);
}

/* Every keyword's header name, and the time/step columns of a first line,
 * as `lmp` prints them (log of the same thermo_style at step 100). */
TEST(all_keywords)
{
    struct gravel *g = make3();
    CHECK(test_script(g, "thermo_style custom step elapsed dt time cpu tpcpu spcpu atoms ke pe "
                         "etotal vol lx ly lz xlo xhi ylo yhi zlo zhi\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    CHECK(strcmp(thermo_header_text(g),
                 "Step Elapsed Dt Time CPU T/CPU S/CPU Atoms KinEng PotEng TotEng Volume Lx Ly "
                 "Lz Xlo Xhi Ylo Yhi Zlo Zhi \n") == 0);
    g->step = 100;
    g->firststep = 100;
    g->dt = 0.001;
    g->time = 0.1;
    output_state(g)->firstflag = 1;
    const char *line = thermo_line_text(g);
    const char *want = "     100        0        0.001          0.1            0            0 "
                       "           0        3         0.32            0         0.32         "
                       "1000           10           10           10            0           10 "
                       "           0           10            0           10 \n";
    CHECK(strcmp(line, want) == 0);
    if (strcmp(line, want))
        printf("  got '%s'\n  want '%s'\n", line, want);
    /* later lines: elapsed counts steps of this run; spcpu > 0 */
    output_state(g)->firstflag = 0;
    g->step = 150;
    g->time = 0.15;
    double v;
    CHECK(thermo_keyword_value(g, "elapsed", &v) && v == 50);
    CHECK(thermo_keyword_value(g, "cpu", &v) && v >= 0);
    g->laststep = 200;
    output_state(g)->wall0 = wall_clock() - 2.0; /* 2 s for 50 steps: 50 left = 2 s */
    CHECK(thermo_keyword_value(g, "cpuremain", &v));
    CHECK_NEAR(v, 2.0, 0.2);
    fx_destroy(g);
}

/* Format precedence, as `lmp` 29Sep2021 printed for these thermo_modify
 * commands: format N > format int/float > format line word > default. */
TEST(format_precedence)
{
    struct gravel *g = make3();
    CHECK(test_script(g, "thermo_style custom step atoms ke vol\n") == GR_OK);
    char *a1[] = {"format", "line", "%5d %3d %10.3f %g", "format", "float", "%8.2f"};
    CHECK(fx_call(g, cmd_thermo_modify, 6, a1) == 0);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    g->step = 2;
    CHECK(strcmp(thermo_line_text(g), "    2   3     0.32  1000.00 \n") == 0);
    CHECK(test_script(g, "thermo_modify format 3 %7.1e\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    CHECK(strcmp(thermo_line_text(g), "    2   3 3.2e-01  1000.00 \n") == 0);
    CHECK(test_script(g, "thermo_modify format int %4d\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    g->step = 4;
    CHECK(strcmp(thermo_line_text(g), "   4    3 3.2e-01  1000.00 \n") == 0);
    CHECK(test_script(g, "thermo_modify format none\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    CHECK(strcmp(thermo_line_text(g), "       4        3         0.32         1000 \n") == 0);
    /* a format line word of the wrong kind is caught at run setup */
    char *a2[] = {"format", "line", "%d %f %f %f"};
    CHECK(fx_call(g, cmd_thermo_modify, 3, a2) == 0);
    CHECK(fx_call(g, do_init, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "column 2 (atoms, an integer)") != NULL);
    char *a3[] = {"format", "line", "%d %d %g"};
    CHECK(fx_call(g, cmd_thermo_modify, 3, a3) == 0);
    CHECK(fx_call(g, do_init, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "fewer words than the 4 columns") != NULL);
    fx_destroy(g);
}

/* multi: LAMMPS' banner and "%-8s = %14.4f" fields, three per line. */
TEST(multi_layout)
{
    struct gravel *g = make3();
    CHECK(test_script(g, "thermo_style multi\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    CHECK(strcmp(thermo_header_text(g), "") == 0);
    g->step = 8;
    output_state(g)->firstflag = 1;
    const char *want = "---------------- Step        8 ----- CPU =      0.0000 (sec) ----------------\n"
                       "Step     =              8 Atoms    =              3 TotEng   =         0.3200 \n"
                       "KinEng   =         0.3200 PotEng   =         0.0000 Volume   =      1000.0000 \n";
    const char *line = thermo_line_text(g);
    CHECK(strcmp(line, want) == 0);
    if (strcmp(line, want))
        printf("  got '%s'\n", line);
    /* line one switches a custom style back */
    CHECK(test_script(g, "thermo_style custom step ke\nthermo_modify line multi\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    CHECK(strstr(thermo_line_text(g), "KinEng   =         0.3200 \n") != NULL);
    fx_destroy(g);
}

/* LAMMPS' ke comes from compute temp: zero without degrees of freedom. */
TEST(ke_single_atom)
{
    struct gravel *g = make();
    double v[3] = {1, 2, 3};
    fx_atom(g, 1, 5, 5, 5, 0.5, 2.0, v, NULL);
    double val = -1;
    CHECK(thermo_keyword_value(g, "ke", &val) && val == 0.0);
    fx_atom(g, 1, 7, 5, 5, 0.5, 2.0, v, NULL);
    CHECK(thermo_keyword_value(g, "ke", &val));
    CHECK_NEAR(val, 14.0, 1e-12); /* 2 x 1/2 x 2 x 14, normalized by 2 atoms */
    fx_destroy(g);
}

TEST(keyword_values)
{
    struct gravel *g = make3();
    g->step = 42;
    double v;
    CHECK(thermo_keyword_value(g, "step", &v) && v == 42);
    CHECK(thermo_keyword_value(g, "atoms", &v) && v == 3);
    CHECK(thermo_keyword_value(g, "vol", &v) && v == 1000);
    CHECK(thermo_keyword_value(g, "lz", &v) && v == 10);
    CHECK(thermo_keyword_value(g, "zhi", &v) && v == 10);
    CHECK(thermo_keyword_value(g, "pe", &v) && v == 0);
    CHECK(thermo_keyword_value(g, "epair", &v) && v == 0);
    CHECK(thermo_keyword_value(g, "emol", &v) && v == 0);
    /* temp = 2 KE / (dof kB), dof = 3N - 3 = 6, KE = 0.96; intensive */
    CHECK(thermo_keyword_value(g, "temp", &v));
    CHECK_NEAR(v, 0.32, 1e-15);
    g->dom.units = UNITS_SI;
    CHECK(thermo_keyword_value(g, "temp", &v));
    CHECK_NEAR(v, 0.32 / 1.3806504e-23, 1e-15 / 1.3806504e-23); /* LAMMPS 2021 k_B */
    g->dom.units = UNITS_LJ;
    /* compute_modify thermo_temp extra/dof 0: dof = 9 */
    CHECK(test_script(g, "compute_modify thermo_temp dynamic/dof yes extra/dof 0\n") == GR_OK);
    CHECK(thermo_keyword_value(g, "temp", &v));
    CHECK_NEAR(v, 2 * 0.96 / 9, 1e-15);
    CHECK(test_script(g, "compute_modify thermo_temp extra/dof 9\n") == GR_OK);
    CHECK(thermo_keyword_value(g, "temp", &v) && v == 0.0);
    CHECK(thermo_keyword_value(g, "ke", &v) && v == 0.0); /* as LAMMPS: no dof, no ke */
    CHECK(test_script(g, "compute_modify thermo_temp extra/dof 3\n") == GR_OK);
    CHECK(thermo_keyword_value(g, "etotal", &v));
    CHECK_NEAR(v, 0.32, 1e-15);
    CHECK(test_script(g, "compute k all ke\ncompute c all count/type atom\n") == GR_OK);
    CHECK(thermo_keyword_value(g, "c_k", &v));
    CHECK_NEAR(v, 0.96, 1e-15); /* as it is: LAMMPS's variables never normalize c_ID */
    CHECK(thermo_keyword_value(g, "c_c[1]", &v) && v == 3.0);
    CHECK(!thermo_keyword_value(g, "c_nope", &v));
    /* LAMMPS' implicit computes */
    CHECK(thermo_keyword_value(g, "c_thermo_temp", &v));
    CHECK_NEAR(v, 0.32, 1e-15);
    CHECK(thermo_keyword_value(g, "c_thermo_pe", &v) && v == 0.0);
    CHECK(test_script(g, "thermo_style custom step c_thermo_temp c_thermo_pe\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 0);
    CHECK(strcmp(thermo_header_text(g), "Step c_thermo_temp c_thermo_pe \n") == 0);
    CHECK(strcmp(thermo_line_text(g), "      42         0.32            0 \n") == 0);
    CHECK(!thermo_keyword_value(g, "bogus", &v));
    CHECK(test_script(g, "thermo_modify norm no\n") == GR_OK);
    gr_unit_defaults(g); /* a later `units lj` does not undo the user's choice */
    CHECK(thermo_keyword_value(g, "c_k", &v));
    CHECK_NEAR(v, 0.96, 1e-15);
    CHECK(thermo_keyword_value(g, "c_c[1]", &v) && v == 3.0);
    fx_destroy(g);
}

TEST(errors)
{
    FX_CHECK_ERROR("thermo 10\nthermo_style custom step kee\n", "unknown keyword 'kee'", 2);
    FX_CHECK_ERROR("thermo -5\n", "must not be negative", 1);
    FX_CHECK_ERROR("thermo abc\n", "expected an integer", 1);
    FX_CHECK_ERROR("thermo_style fancy\n", "unknown style 'fancy'", 1);
    FX_CHECK_ERROR("thermo_style one extra\n", "takes no keywords", 1);
    FX_CHECK_ERROR("thermo_style custom step c_\n", "invalid compute reference", 1);
    FX_CHECK_ERROR("thermo_style custom step c_a[0]\n", "invalid compute reference", 1);
    FX_CHECK_ERROR("thermo_style custom f_1[0]\n", "invalid fix reference", 1);
    FX_CHECK_ERROR("thermo_style custom f_\n", "invalid fix reference", 1);
    FX_CHECK_ERROR("thermo_style custom f_1\n", "could not find thermo custom fix ID '1'", 1);
    FX_CHECK_ERROR("\nthermo_modify format float %d\n", "format float '%d' must convert a float", 2);
    FX_CHECK_ERROR("thermo_modify format int %5.2f\n", "must convert an integer", 1);
    FX_CHECK_ERROR("thermo_modify format int %d%d\n", "exactly one conversion", 1);
    FX_CHECK_ERROR("thermo_modify format int %*d\n", "must convert an integer", 1);
    FX_CHECK_ERROR("thermo_modify format int %99999d\n", "width over 999", 1);
    FX_CHECK_ERROR("thermo_modify format 7 %d\n", "outside 1..6", 1);
    FX_CHECK_ERROR("thermo_modify format\n", "needs 1 value", 1);
    FX_CHECK_ERROR("thermo_modify lost maybe\n", "error, warn or ignore", 1);
    FX_CHECK_ERROR("thermo_modify norm perhaps\n", "expected yes or no", 1);
    FX_CHECK_ERROR("thermo_modify temp t\n", "unknown compute ID 't'", 1);
    FX_CHECK_ERROR("compute k all ke\nthermo_modify temp k\n", "does not compute a temperature", 2);
    FX_CHECK_ERROR("compute t all temp/sphere dof some\n", "all or rotate", 1);
    FX_CHECK_ERROR("compute t all temp/sphere bias\n", "bias needs a compute ID", 1);
    FX_CHECK_ERROR("thermo_modify frobnicate 1\n", "unknown keyword 'frobnicate'", 1);
    FX_CHECK_ERROR("compute_modify thermo_temp dynamic/dof maybe\n", "yes or no", 1);
    FX_CHECK_ERROR("compute_modify thermo_temp extra/dof x\n", "expected a number", 1);
    FX_CHECK_ERROR("compute_modify thermo_temp bias yes\n", "unknown keyword 'bias'", 1);
    FX_CHECK_ERROR("compute k all ke\ncompute_modify k extra/dof 1\n", "no settings", 2);
    FX_CHECK_ERROR("compute_modify nope extra/dof 1\n", "unknown compute ID 'nope'", 1);

    /* as LAMMPS, referenced computes, fixes and variables must exist when
     * thermo_style is read; the values are resolved at run setup */
    FX_CHECK_ERROR("thermo_style custom step c_missing\n",
                   "could not find thermo custom compute ID 'missing'", 1);
    FX_CHECK_ERROR("thermo_style custom step v_nothing\n",
                   "could not find thermo custom variable name 'nothing'", 1);
    struct gravel *g = make3();
    CHECK(test_script(g, "compute missing all ke\nthermo_style custom step c_missing\n"
                         "uncompute missing\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "unknown compute ID 'missing'") != NULL);
    CHECK(test_script(g, "compute k all ke\nthermo_style custom step c_k[2]\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "does not produce a global vector") != NULL);
    CHECK(test_script(g, "compute r all reduce sum vx vy\nthermo_style custom c_r[3]\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "out of range") != NULL);
    CHECK(test_script(g, "thermo_style custom c_r\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "use c_ID[N]") != NULL);
    CHECK(test_script(g, "variable nothing equal 1\nthermo_style custom v_nothing\n"
                         "variable nothing delete\n") == GR_OK);
    CHECK(fx_call(g, do_init, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "variable 'nothing' is not defined") != NULL);
    /* lost is stored for the core */
    CHECK(test_script(g, "thermo_modify lost warn flush yes\n") == GR_OK);
    CHECK(g->thermo.lost == LOST_WARN && g->thermo.flush == 1);
    CHECK(test_script(g, "thermo_modify lost ignore\n") == GR_OK);
    CHECK(g->thermo.lost == LOST_IGNORE);
    /* a new thermo_style resets thermo_modify settings with a warning */
    int nwarn = g->err.nwarn;
    CHECK(test_script(g, "thermo_style custom step\n") == GR_OK);
    CHECK(g->thermo.lost == LOST_ERROR && g->thermo.flush == 0 && g->err.nwarn == nwarn + 1);
    fx_destroy(g);
}

/* output_setup / output_step / output_finish: lines at 0, 4, 8 and the last
 * step 10 for `thermo 4`; the footer in LAMMPS' layout. */
TEST(schedule_and_footer)
{
    struct gravel *g = make3();
    CHECK(test_script(g, "thermo 4\nthermo_style custom step atoms\n") == GR_OK);
    struct fx_capture cap;
    fx_capture_begin(g, &cap);
    g->step = g->firststep = 0;
    g->laststep = 10;
    CHECK(fx_call(g, do_setup, 0, NULL) == 0);
    for (bigint s = 1; s <= 10; s++) {
        g->step = s;
        CHECK(output_due(g, s) == (s == 4 || s == 8 || s == 10));
        output_step(g);
    }
    struct run_stats st = {.nsteps = 10, .natoms = 3, .t_total = 2.0, .t_pair = 1.0,
                           .t_neigh = 0.25, .t_modify = 0.25, .t_output = 0.25,
                           .nbuilds = 3, .ndanger = 0, .total_neighbors = 12,
                           .max_overlap_frac = 0.0125, .nlaunch = 31, .ncontact = 6,
                           .mem_peak = 3000, .res_q = 0.25, .res_vn = 1.5, .res_step = 7,
                           .res_tag_i = 1, .res_tag_j = 3};
    output_finish(g, &st);
    char *out = fx_capture_end(g, &cap);
    const char *want =
        "Step Atoms \n"
        "       0        3 \n"
        "       4        3 \n"
        "       8        3 \n"
        "      10        3 \n"
        "Loop time of 2 on 1 procs for 10 steps with 3 atoms\n"
        "\n"
        "Performance: 2160.000 tau/day, 5.000 timesteps/s, 0.015 katom-step/s\n"
        "\n"
        "MPI task timing breakdown:\n"
        "Section |  min time  |  avg time  |  max time  |%varavg| %total\n"
        "---------------------------------------------------------------\n"
        "Pair    | 1          | 1          | 1          |   0.0 | 50.00\n"
        "Neigh   | 0.25       | 0.25       | 0.25       |   0.0 | 12.50\n"
        "Output  | 0.25       | 0.25       | 0.25       |   0.0 | 12.50\n"
        "Modify  | 0.25       | 0.25       | 0.25       |   0.0 | 12.50\n"
        "Other   |            | 0.25       |            |       | 12.50\n"
        "\n"
        "Nlocal:        3.00000 ave           3 max           3 min\n"
        "Histogram: 1 0 0 0 0 0 0 0 0 0\n"
        "Neighs:        6.00000 ave           6 max           6 min\n"
        "Histogram: 1 0 0 0 0 0 0 0 0 0\n"
        "\n"
        "Total # of neighbors = 6\n"
        "Ave neighs/atom = 2.0000000\n"
        "Neighbor list builds = 3\n"
        "Dangerous builds = 0\n"
        "Largest overlap / radius = 0.0125\n"
        "Collision resolution = 4 steps per collision at worst (step 7, atoms 1 and 3, normal "
        "speed 1.5)\n"
        "Contacts = 6 (each evaluated once); kernel launches per step = 3.10\n"
        "Device memory = 0.003 Mbytes at most (1000 bytes per atom)\n";
    CHECK(out && strcmp(out, want) == 0);
    if (out && strcmp(out, want))
        printf("  got:\n%s\n", out);
    free(out);

    /* thermo 0: first and last step only; a second run continues */
    CHECK(test_script(g, "thermo 0\n") == GR_OK);
    fx_capture_begin(g, &cap);
    g->firststep = 10;
    g->laststep = 20;
    CHECK(fx_call(g, do_setup, 0, NULL) == 0);
    for (bigint s = 11; s <= 20; s++) {
        g->step = s;
        output_step(g);
    }
    out = fx_capture_end(g, &cap);
    CHECK(out && strcmp(out, "Step Atoms \n      10        3 \n      20        3 \n") == 0);
    free(out);

    /* the chute's footer numbers, as `lmp` printed them */
    fx_capture_begin(g, &cap);
    struct run_stats chute = {.nsteps = 100, .natoms = 32000, .t_total = 0.222894,
                              .t_pair = 0.12176, .t_neigh = 0.025657, .t_output = 0.00020322,
                              .t_modify = 0.051746, .t_other = 0.01368, .nbuilds = 2,
                              .total_neighbors = 2 * 115133};
    g->dt = 0.0001;
    output_finish(g, &chute);
    out = fx_capture_end(g, &cap);
    CHECK(out && strstr(out, "Loop time of 0.222894 on 1 procs for 100 steps with 32000 atoms\n"));
    /* lmp: 3876.279 tau/day, 448.643 timesteps/s from its unrounded loop time */
    CHECK(out && strstr(out, "Performance: 3876.282 tau/day, 448.644 timesteps/s, 14.357 "
                             "Matom-step/s\n"));
    CHECK(out && strstr(out, "Pair    | 0.12176    | 0.12176    | 0.12176    |   0.0 | 54.63\n"));
    CHECK(out && strstr(out, "Output  | 0.00020322 | 0.00020322 | 0.00020322 |   0.0 |  0.09\n"));
    CHECK(out && strstr(out, "Other   |            | 0.01368    |            |       |  6.14\n"));
    CHECK(out && strstr(out, "Nlocal:        32000.0 ave       32000 max       32000 min\n"));
    CHECK(out && strstr(out, "Neighs:        115133.0 ave      115133 max      115133 min\n"
                             "Histogram: 1 0 0 0 0 0 0 0 0 0\n"));
    /* several ranks (LAMMPS's Finish): min, mean, max, %varavg and the histogram */
    double ranks[4] = {0.10, 0.12, 0.12, 0.18};
    struct rank_spread rs;
    rank_spread(ranks, 4, &rs);
    CHECK(rs.min == 0.10 && rs.max == 0.18 && fabs(rs.avg - 0.13) < 1e-15);
    /* sqrt(<t^2>/<t> - <t>) x 100 = sqrt(0.0178/0.13 - 0.13) x 100 */
    CHECK(fabs(rs.varavg - 100.0 * sqrt(0.0178 / 0.13 - 0.13)) < 1e-9);
    CHECK(rs.histo[0] == 1 && rs.histo[2] == 2 && rs.histo[9] == 1);
    CHECK(out && strstr(out, "Total # of neighbors = 115133\nAve neighs/atom = 3.5979062\n"
                             "Neighbor list builds = 2\nDangerous builds = 0\n"));
    free(out);

    /* run ... post no: only the loop line, as lmp */
    fx_capture_begin(g, &cap);
    output_finish_brief(g, &chute);
    out = fx_capture_end(g, &cap);
    CHECK(out && strcmp(out, "Loop time of 0.222894 on 1 procs for 100 steps with 32000 atoms\n"
                             "\n") == 0);
    free(out);

    /* Performance in si units: simulated seconds per day, Matom-step/s */
    g->dom.units = UNITS_SI;
    g->dt = 1e-6;
    fx_capture_begin(g, &cap);
    struct run_stats big = {.nsteps = 1000, .natoms = 32000, .t_total = 2.0};
    output_finish(g, &big);
    out = fx_capture_end(g, &cap);
    CHECK(out && strstr(out, "Performance: 43.2 s/day, 500.000 timesteps/s, 16.000 "
                             "Matom-step/s\n") != NULL);
    free(out);
    fx_destroy(g);
}

/* -progress: an updating line on stderr (never in the screen/log stream),
 * erased at the end of the run. */
TEST(progress_line)
{
    struct gravel *g = make3();
    g->opt.progress = 1;
    CHECK(test_script(g, "thermo 0\nthermo_style custom step\n") == GR_OK);
    fflush(stderr);
    int saved = dup(2);
    FILE *tmp = tmpfile();
    dup2(fileno(tmp), 2);
    struct fx_capture cap;
    fx_capture_begin(g, &cap);
    g->step = g->firststep = 0;
    g->laststep = 10;
    CHECK(fx_call(g, do_setup, 0, NULL) == 0);
    for (bigint s = 1; s <= 10; s++) {
        g->step = s;
        if (s == 5) {
            output_state(g)->prog_last_wall = 0; /* force a redraw now */
            CHECK(output_due(g, s) == 1);         /* progress alone makes it due */
        }
        output_step(g);
    }
    struct run_stats st = {.nsteps = 10, .natoms = 3, .t_total = 1.0};
    output_finish(g, &st);
    char *out = fx_capture_end(g, &cap);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    char err[512] = "";
    rewind(tmp);
    size_t n = fread(err, 1, sizeof err - 1, tmp);
    err[n] = '\0';
    fclose(tmp);
    CHECK(strncmp(err, "\rstep 5 / 10   50.0%  ", 22) == 0);
    CHECK(strstr(err, "steps/s  ETA 0:00:0") != NULL);
    /* erased: ends with \r, blanks over the line, \r */
    size_t len = strcspn(err + 1, "\r") ;
    CHECK(n == 2 * (len + 1) + 1 && err[n - 1] == '\r' && err[len + 2] == ' ');
    CHECK(out && !strstr(out, "steps/s  ETA"));
    free(out);
    /* without -progress and with stderr not a terminal: nothing */
    g->opt.progress = 0;
    tmp = tmpfile();
    saved = dup(2);
    dup2(fileno(tmp), 2);
    fx_capture_begin(g, &cap);
    g->firststep = 10;
    g->laststep = 20;
    CHECK(fx_call(g, do_setup, 0, NULL) == 0);
    output_state(g)->prog_last_wall = 0;
    g->step = 11;
    output_step(g);
    output_finish(g, &st);
    free(fx_capture_end(g, &cap));
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    fseek(tmp, 0, SEEK_END);
    CHECK(ftell(tmp) == 0);
    fclose(tmp);
    fx_destroy(g);
}

/* With the interpreter: v_name columns, `thermo v_name`, quoted format
 * lines, and thermo keywords / c_ID inside expressions. */
TEST(with_variables)
{
    struct gravel *g = make3();
    CHECK(test_script(g, "variable twice equal 2*step\n"
                         "variable every equal step+3\n"
                         "compute k all ke\n"
                         "thermo_style custom step v_twice c_k\n"
                         "thermo_modify format line \"%4d %6.1f %8.3f\"\n"
                         "thermo v_every\n") == GR_OK);
    struct fx_capture cap;
    fx_capture_begin(g, &cap);
    g->step = g->firststep = 0;
    g->laststep = 10;
    CHECK(fx_call(g, do_setup, 0, NULL) == 0);
    for (bigint s = 1; s <= 10; s++) {
        g->step = s;
        output_step(g);
    }
    char *out = fx_capture_end(g, &cap);
    /* lines at 0, 3, 6, 9 (variable) and 10 (last); c_k normalized: 0.32 */
    const char *want = "Step v_twice c_k \n"
                       "   0    0.0    0.320 \n"
                       "   3    6.0    0.320 \n"
                       "   6   12.0    0.320 \n"
                       "   9   18.0    0.320 \n"
                       "  10   20.0    0.320 \n";
    CHECK(out && strcmp(out, want) == 0);
    if (out && strcmp(out, want))
        printf("  got:\n%s", out);
    free(out);
    /* a variable that does not advance is an error */
    CHECK(test_script(g, "variable every delete\nvariable every equal 2\n") == GR_OK);
    g->step = g->firststep = 10;
    g->laststep = 20;
    fx_capture_begin(g, &cap);
    CHECK(fx_call(g, do_setup, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "variable 'every' returned 2, which is not a step after 10") !=
          NULL);
    free(fx_capture_end(g, &cap));
    /* expressions see thermo keywords normalized like thermo, and computes as they are
     * (LAMMPS's Variable: c_ID is never normalized; lmp 2021 checked, fix_ave_time.py) */
    CHECK(test_script(g, "variable e equal ke*atoms+vol+c_k\n") == GR_OK);
    CHECK_NEAR(var_compute_equal(g, "e"), 0.96 + 1000 + 0.96, 1e-12);
    CHECK(test_script(g, "compute r all reduce sum vx vy\nvariable r equal c_r[1]\n") ==
          GR_OK);
    CHECK_NEAR(var_compute_equal(g, "r"), 2.4, 1e-15); /* the sum over 3 atoms */
    fx_destroy(g);
}

int main(void)
{
    RUN(chute_layout);
    RUN(norm);
    RUN(all_keywords);
    RUN(format_precedence);
    RUN(multi_layout);
    RUN(ke_single_atom);
    RUN(keyword_values);
    RUN(errors);
    RUN(schedule_and_footer);
    RUN(progress_line);
    RUN(with_variables);
    return 0;
}
