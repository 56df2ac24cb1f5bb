/* test_dump.c - dump custom text (parsed back), dump vtk headers, sorting,
 * formats, the dump schedule, and the tmp+rename file scheme (no half-written
 * files, previous output intact until a run ends).
 *
 * `test_dump --write DIR` writes the VTK and custom files of a formula-defined
 * system into DIR for tests/scripts/output_vtk.py, which reads them back with
 * VTK's own readers and checks them against the same formulas. */
#include "output_fixture.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include "command.h"
#include "output.h"

static char dir[64];

static void make_dir(void)
{
    snprintf(dir, sizeof dir, "/tmp/gravel_dumpXXXXXX");
    if (!mkdtemp(dir))
        perror("mkdtemp");
}

static void remove_dir(const char *path)
{
    DIR *d = opendir(path);
    if (!d)
        return;
    struct dirent *e;
    char p[512];
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
            snprintf(p, sizeof p, "%s/%s", path, e->d_name);
            remove(p);
        }
    closedir(d);
    rmdir(path);
}

static int exists(const char *name)
{
    char p[512];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    struct stat st;
    return stat(p, &st) == 0;
}

static size_t slurp_len; /* length of the last slurp (binary files hold NULs) */

static char *slurp(const char *name)
{
    char p[512];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    FILE *fp = fopen(p, "rb");
    if (!fp)
        return NULL;
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    size_t k = fread(s, 1, (size_t)n, fp);
    s[k] = '\0';
    slurp_len = k;
    fclose(fp);
    return s;
}

static int count_str(const char *s, const char *what)
{
    int n = 0;
    for (const char *p = s; p && (p = strstr(p, what)); p += strlen(what))
        n++;
    return n;
}

/* Run script text with the dump directory substituted for @. */
static int script(struct gravel *g, const char *text)
{
    char buf[4096];
    size_t o = 0;
    for (const char *p = text; *p && o < sizeof buf - 80; p++) {
        if (*p == '@') {
            o += (size_t)snprintf(buf + o, sizeof buf - o, "%s", dir);
        } else {
            buf[o++] = *p;
        }
    }
    buf[o] = '\0';
    return test_script(g, buf);
}

/* The formula system shared with output_vtk.py: atom k (tag k+1) of n. Atoms
 * are added in reverse tag order so that `sort id` matters. */
static struct gravel *formula_system(int n)
{
    struct gravel *g = test_engine();
    double lo[3] = {-1, -2, 0}, hi[3] = {9, 8, 20};
    fx_box(g, lo, hi, 2);
    for (int k = n - 1; k >= 0; k--) {
        double x[3] = {0.1 + 1.3 * k, 2.0 - 0.7 * k, 0.25 * k * k};
        int i = atoms_add(g, k + 1, 1 + k % 2, x, 0.5 + 0.01 * k, 1.0 + 0.5 * k);
        double v[3] = {k, -2.0 * k, 0.5}, w[3] = {0.1 * k, 0, -k}, f[3] = {1e-3 * k, 2.0 * k, -3};
        for (int c = 0; c < 3; c++) {
            g->atoms.v[3 * i + c] = v[c];
            g->atoms.omega[3 * i + c] = w[c];
            g->atoms.f[3 * i + c] = f[c];
            g->atoms.torque[3 * i + c] = -f[c];
        }
        g->atoms.image[3 * i] = k % 3 - 1;
    }
    fx_group_parity(g, 1, "even", 0); /* host indices 0, 2, ...: tags n, n-2, ... */
    fx_group_parity(g, 2, "none", 7);
    return g;
}

static void write_now(struct gravel *g, const char *id)
{
    struct dump *d = dump_find(g, id);
    dump_write(g, d);
}

static void do_write(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    write_now(g, argv[0]);
}

static void do_run_end(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    (void)argv;
    dump_run_end(g);
}

static void do_setup(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    (void)argv;
    dump_setup_all(g);
}

/* ---- custom ------------------------------------------------------------------ */

TEST(custom_text)
{
    make_dir();
    struct gravel *g = formula_system(3);
    g->step = 5;
    CHECK(script(g, "dump d all custom 5 @/c.txt id type x y z xu ix vx fz radius diameter "
                    "mass omegaz tqy\ndump_modify d sort id\n") == GR_OK);
    CHECK(fx_call(g, do_write, 1, (char *[]){"d"}) == 0);
    CHECK(!exists("c.txt") && exists("c.txt.tmp")); /* not published before the run ends */
    CHECK(fx_call(g, do_run_end, 0, NULL) == 0);
    CHECK(exists("c.txt") && !exists("c.txt.tmp"));
    char *s = slurp("c.txt");
    const char *want =
        "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n3\nITEM: BOX BOUNDS pp pp ff\n"
        "-1.0000000000000000e+00 9.0000000000000000e+00\n"
        "-2.0000000000000000e+00 8.0000000000000000e+00\n"
        "0.0000000000000000e+00 2.0000000000000000e+01\n"
        "ITEM: ATOMS id type x y z xu ix vx fz radius diameter mass omegaz tqy\n"
        "1 1 0.1 2 0 -9.9 -1 0 -3 0.5 1 1 0 -0\n"
        "2 2 1.4 1.3 0.25 1.4 0 1 -3 0.51 1.02 1.5 -1 -2\n"
        "3 1 2.7 0.6 1 12.7 1 2 -3 0.52 1.04 2 -2 -4\n";
    CHECK(s && strcmp(s, want) == 0);
    if (s && strcmp(s, want))
        printf("  got:\n%s", s);
    free(s);

    /* unsorted: host order (reverse tags); group "even" = host 0 and 2 */
    CHECK(script(g, "dump u even custom 1 @/u.*.txt id\n") == GR_OK);
    CHECK(fx_call(g, do_write, 1, (char *[]){"u"}) == 0);
    s = slurp("u.5.txt");
    CHECK(s && strstr(s, "ITEM: NUMBER OF ATOMS\n2\n") && strstr(s, "ITEM: ATOMS id\n3\n1\n"));
    free(s);
    CHECK(!exists("u.5.txt.tmp"));
    fx_destroy(g);
    remove_dir(dir);
}

TEST(custom_formats)
{
    make_dir();
    struct gravel *g = formula_system(2);
    CHECK(script(g, "dump d all custom 1 @/f.*.txt id x vx\ndump_modify d sort id\n") == GR_OK);
    /* LAMMPS 2021 for format line "%d %10.4f %g": "1     2.0000 0.1" */
    char *a1[] = {"d", "format", "line", "%d %10.4f %g"};
    CHECK(fx_call(g, cmd_dump_modify, 4, a1) == 0);
    CHECK(fx_call(g, do_write, 1, (char *[]){"d"}) == 0);
    char *s = slurp("f.0.txt");
    CHECK(s && strstr(s, "ITEM: ATOMS id x vx\n1     0.1000 0\n2     1.4000 1\n"));
    free(s);
    /* format float and column 1 override the line (LAMMPS precedence) */
    CHECK(script(g, "dump_modify d format float %10.3e format 1 %5d\n") == GR_OK);
    g->step = 1;
    CHECK(fx_call(g, do_write, 1, (char *[]){"d"}) == 0);
    s = slurp("f.1.txt");
    CHECK(s && strstr(s, "\n    1  1.000e-01  0.000e+00\n    2  1.400e+00  1.000e+00\n"));
    free(s);
    CHECK(script(g, "dump_modify d format none format int %03d\n") == GR_OK);
    g->step = 2;
    CHECK(fx_call(g, do_write, 1, (char *[]){"d"}) == 0);
    s = slurp("f.2.txt");
    CHECK(s && strstr(s, "\n001 0.1 0\n002 1.4 1\n"));
    free(s);
    /* a short format line is caught when written */
    char *a2[] = {"d", "format", "line", "%d %g"};
    CHECK(fx_call(g, cmd_dump_modify, 4, a2) == 0);
    CHECK(script(g, "dump_modify d format int %d\n") == GR_OK);
    CHECK(script(g, "dump_modify d format none\n") == GR_OK);
    CHECK(fx_call(g, cmd_dump_modify, 4, a2) == 0);
    g->step = 3;
    CHECK(fx_call(g, do_write, 1, (char *[]){"d"}) == 1);
    CHECK(strstr(g->err.msg, "fewer words than the 3 fields") != NULL);
    CHECK(!exists("f.3.txt") && !exists("f.3.txt.tmp"));
    fx_destroy(g);
    remove_dir(dir);
}

/* Several runs into one file: the target keeps the last complete run's
 * snapshots until the next run ends. */
TEST(append_scheme)
{
    make_dir();
    struct gravel *g = formula_system(2);
    CHECK(script(g, "dump d all custom 10 @/a.txt id x\n") == GR_OK);
    g->step = 0;
    CHECK(fx_call(g, do_setup, 0, NULL) == 0); /* step 0 is a multiple: written */
    g->step = 5;
    CHECK(dump_step_all(g) == 0);
    g->step = 10;
    CHECK(dump_due(g, 10) == 1);
    CHECK(dump_step_all(g) == 1);
    CHECK(fx_call(g, do_run_end, 0, NULL) == 0);
    char *s = slurp("a.txt");
    CHECK(s && count_str(s, "ITEM: TIMESTEP") == 2 && strstr(s, "ITEM: TIMESTEP\n10\n"));
    free(s);
    /* second run from step 10: step 10 is not written twice */
    CHECK(fx_call(g, do_setup, 0, NULL) == 0);
    CHECK(!exists("a.txt.tmp"));
    g->step = 20;
    CHECK(dump_step_all(g) == 1);
    s = slurp("a.txt");
    CHECK(s && count_str(s, "ITEM: TIMESTEP") == 2); /* previous output intact */
    free(s);
    s = slurp("a.txt.tmp");
    CHECK(s && count_str(s, "ITEM: TIMESTEP") == 3);
    free(s);
    /* a run stopped by an error publishes what it wrote (output_abort) */
    g->step = 30;
    CHECK(dump_step_all(g) == 1);
    output_abort(g);
    CHECK(!exists("a.txt.tmp"));
    s = slurp("a.txt");
    CHECK(s && count_str(s, "ITEM: TIMESTEP") == 4 && strstr(s, "ITEM: TIMESTEP\n30\n"));
    free(s);
    /* undump publishes */
    CHECK(script(g, "undump d\n") == GR_OK);
    CHECK(!exists("a.txt.tmp"));
    s = slurp("a.txt");
    CHECK(s && count_str(s, "ITEM: TIMESTEP") == 4 && strstr(s, "ITEM: TIMESTEP\n20\n"));
    free(s);
    CHECK(g->styles.ndump == 0);
    fx_destroy(g);
    remove_dir(dir);
}

/* dump_modify first yes writes at a run's first step even off the multiple;
 * append yes continues an existing file. */
TEST(first_and_append)
{
    make_dir();
    struct gravel *g = formula_system(1);
    char p[300];
    snprintf(p, sizeof p, "%s/old.txt", dir);
    FILE *fp = fopen(p, "w");
    fputs("previous content\n", fp);
    fclose(fp);
    CHECK(script(g, "dump d all custom 7 @/old.txt id\ndump_modify d first yes append yes\n"
                    "dump e all vtk 7 @/e.*.vtk\n") == GR_OK);
    g->step = 3;
    CHECK(fx_call(g, do_setup, 0, NULL) == 0);
    CHECK(exists("old.txt.tmp") && !exists("e.3.vtk"));
    g->step = 7;
    CHECK(dump_step_all(g) == 1);
    CHECK(fx_call(g, do_run_end, 0, NULL) == 0);
    char *s = slurp("old.txt");
    CHECK(s && strncmp(s, "previous content\nITEM: TIMESTEP\n3\n", 33) == 0 &&
          count_str(s, "ITEM: TIMESTEP") == 2);
    free(s);
    /* first applies once: a later run starting off the multiple writes nothing */
    g->step = 9;
    CHECK(fx_call(g, do_setup, 0, NULL) == 0);
    CHECK(!exists("old.txt.tmp"));
    FX_CHECK_ERROR("dump 1 all vtk 1 f.vtk\ndump_modify 1 append yes\n", "append applies", 2);
    fx_destroy(g);
    remove_dir(dir);
}

/* write_dump: one snapshot now, through a temporary dump that disappears. */
TEST(write_dump)
{
    make_dir();
    struct gravel *g = formula_system(3);
    g->step = 12;
    CHECK(script(g, "write_dump all custom @/w.txt id x modify sort id format float %.3f\n"
                    "write_dump even vtk @/w_*.vtk modify binary yes\n") == GR_OK);
    char *s = slurp("w.txt");
    CHECK(s && strstr(s, "ITEM: TIMESTEP\n12\n") &&
          strstr(s, "ITEM: ATOMS id x\n1 0.100\n2 1.400\n3 2.700\n"));
    free(s);
    CHECK(!exists("w.txt.tmp") && exists("w_12.vtk"));
    CHECK(g->styles.ndump == 0);
    /* errors leave no temporary dump behind */
    CHECK(script(g, "write_dump all custom @/x.txt id modify sort q\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "sort must be id or off") != NULL);
    CHECK(g->styles.ndump == 0 && !exists("x.txt") && !exists("x.txt.tmp"));
    CHECK(script(g, "write_dump all custom @/x.txt bogus\n") == GR_ERR);
    CHECK(g->styles.ndump == 0);
    CHECK(script(g, "write_dump all custom @/x.txt id modify\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "modify needs") != NULL && g->styles.ndump == 0);
    fx_destroy(g);
    remove_dir(dir);
}

/* ---- vtk ---------------------------------------------------------------------- */

TEST(vtk_files)
{
    make_dir();
    struct gravel *g = formula_system(3);
    CHECK(script(g, "dump v all vtk 10 @/p.vtk\ndump s all vtk 10 @/s_*.vtk\n"
                    "dump_modify s pad 6 sort id\n") == GR_OK);
    g->step = 0;
    CHECK(fx_call(g, do_setup, 0, NULL) == 0);
    char *s = slurp("p.vtk");
    CHECK(s && strncmp(s, "# vtk DataFile Version 3.0\ngravel dump v step 0 time 0\nASCII\n"
                          "DATASET POLYDATA\n", 70) == 0);
    CHECK(s && strstr(s, "POINTS 3 double\n") && strstr(s, "VERTICES 3 6\n1 0\n1 1\n1 2\n"));
    CHECK(s && strstr(s, "POINT_DATA 3\nFIELD FieldData 7\nid 1 3 int\n3\n2\n1\n"));
    free(s);
    CHECK(exists("s_000000.vtk"));
    g->step = 10;
    g->time = 0.5;
    CHECK(dump_step_all(g) == 1);
    CHECK(exists("s_000010.vtk") && exists("s_000000.vtk"));
    s = slurp("p.vtk"); /* rewritten: holds the latest snapshot */
    CHECK(s && strstr(s, "gravel dump v step 10 time 0.5\n"));
    free(s);
    s = slurp("s_000010.vtk");
    CHECK(s && strstr(s, "id 1 3 int\n1\n2\n3\n")); /* sorted */
    free(s);
    /* binary: header text, big-endian payload */
    CHECK(script(g, "dump b all vtk 10 @/b.vtk\ndump_modify b binary yes sort id\n") == GR_OK);
    CHECK(fx_call(g, do_write, 1, (char *[]){"b"}) == 0);
    s = slurp("b.vtk");
    CHECK(s && strstr(s, "\nBINARY\nDATASET POLYDATA\n"));
    const char *pts = s ? memmem(s, slurp_len, "POINTS 3 double\n", 16) : NULL;
    CHECK(pts != NULL);
    if (pts) {
        const unsigned char *b = (const unsigned char *)pts + strlen("POINTS 3 double\n");
        double x0;
        uint64_t u = 0;
        for (int k = 0; k < 8; k++)
            u = (u << 8) | b[k];
        memcpy(&x0, &u, 8);
        CHECK(x0 == 0.1); /* atom tag 1 first, big-endian */
    }
    free(s);
    fx_destroy(g);
    remove_dir(dir);
}

TEST(write_failures)
{
    make_dir();
    struct gravel *g = formula_system(2);
    CHECK(script(g, "dump v all vtk 1 /nonexistent_gravel_dir/x.vtk\n") == GR_OK);
    CHECK(fx_call(g, do_write, 1, (char *[]){"v"}) == 1);
    CHECK(strstr(g->err.msg, "cannot open '/nonexistent_gravel_dir/x.vtk.tmp'") != NULL);
    /* a compute column that fails mid-file leaves no temporary behind and the
     * previous complete file untouched */
    CHECK(script(g, "compute ka all ke/atom\ndump c all custom 1 @/k.*.txt id c_ka\n") == GR_OK);
    CHECK(fx_call(g, do_write, 1, (char *[]){"c"}) == 0);
    char *good = slurp("k.0.txt");
    CHECK(good && strstr(good, "ITEM: ATOMS id c_ka\n2 3.9375\n1 0.125\n"));
    /* per-atom array columns */
    CHECK(script(g, "compute pa all property/atom vz diameter\n"
                    "dump p all custom 1 @/p.txt id c_pa[2] c_pa[1]\n") == GR_OK);
    CHECK(fx_call(g, do_write, 1, (char *[]){"p"}) == 0);
    CHECK(fx_call(g, do_run_end, 0, NULL) == 0);
    char *ps = slurp("p.txt");
    CHECK(ps && strstr(ps, "ITEM: ATOMS id c_pa[2] c_pa[1]\n2 1.02 0.5\n1 1 0.5\n"));
    free(ps);
    CHECK(script(g, "uncompute ka\ncompute ka all ke\n") == GR_OK);
    CHECK(fx_call(g, do_write, 1, (char *[]){"c"}) == 1);
    CHECK(strstr(g->err.msg, "does not produce per-atom values") != NULL);
    CHECK(!exists("k.0.txt.tmp"));
    char *after = slurp("k.0.txt");
    CHECK(good && after && strcmp(good, after) == 0);
    free(good);
    free(after);
    fx_destroy(g);
    remove_dir(dir);
}

TEST(errors)
{
    FX_CHECK_ERROR("dump 1 all xyz 10 f.xyz\n", "unknown dump style 'xyz'", 1);
    FX_CHECK_ERROR("dump 1 all vtk 0 f.vtk\n", "must be positive", 1);
    FX_CHECK_ERROR("dump 1 all vtk ten f.vtk\n", "expected an integer", 1);
    FX_CHECK_ERROR("dump 1 all vtk 1 f.vtk\ndump 1 all vtk 1 g.vtk\n", "already exists", 2);
    FX_CHECK_ERROR("dump 1 all vtk 1 f.*.*.vtk\n", "more than one '*'", 1);
    FX_CHECK_ERROR("dump 1 all custom 1 f.gz id\n", "compressed dumps", 1);
    FX_CHECK_ERROR("dump 1 all vtk 1 f.vtk extra\n", "takes no arguments", 1);
    FX_CHECK_ERROR("dump 1 all custom 1 f.txt\n", "at least one field", 1);
    FX_CHECK_ERROR("dump 1 all custom 1 f.txt id q\n", "unknown dump custom field 'q'", 1);
    FX_CHECK_ERROR("variable a equal 1\nwrite_dump all custom f.txt v_a\n",
                   "variable 'a' is equal-style, not atom-style", 2);
    FX_CHECK_ERROR("dump 1 nogroup vtk 1 f.vtk\n", "unknown group 'nogroup'", 1);
    FX_CHECK_ERROR("dump_modify 9 sort id\n", "unknown dump ID '9'", 1);
    FX_CHECK_ERROR("dump 1 all vtk 1 f.vtk\ndump_modify 1 sort x\n", "sort must be id or off", 2);
    FX_CHECK_ERROR("dump 1 all vtk 1 f.vtk\ndump_modify 1 binary maybe\n", "yes or no", 2);
    FX_CHECK_ERROR("dump 1 all vtk 1 f.vtk\ndump_modify 1 every 0\n", "must be positive", 2);
    FX_CHECK_ERROR("dump 1 all vtk 1 f.vtk\ndump_modify 1 format int %d\n", "unknown keyword", 2);
    FX_CHECK_ERROR("dump 1 all custom 1 f.txt id\ndump_modify 1 binary yes\n", "vtk only", 2);
    FX_CHECK_ERROR("dump 1 all custom 1 f.txt id\ndump_modify 1 format 2 %d\n", "outside 1..1",
                   2);
    FX_CHECK_ERROR("dump 1 all custom 1 f.txt id x\ndump_modify 1 format 2 %d\n",
                   "must convert a floating-point", 2);
    FX_CHECK_ERROR("dump 1 all custom 1 f.txt id\ndump_modify 1 format float\n", "needs 2", 2);
    FX_CHECK_ERROR("undump 4\n", "unknown dump ID '4'", 1);
    FX_CHECK_ERROR("dump 1 all atom 1 f.txt id\n", "takes no arguments", 1);
    FX_CHECK_ERROR("dump 1 all atom 1 f.txt\ndump_modify 1 scale perhaps\n", "yes or no", 2);
    FX_CHECK_ERROR("dump 1 all vtk 1 f.vtk\ndump_modify 1 image yes\n", "dump atom only", 2);
    FX_CHECK_ERROR("dump 1 all vtk 1 f.vtk\ndump 2 all custom 1 f.vtk id\n",
                   "already written by dump 1", 2);
    CHECK_ERROR("dump 1 all vtk 1 f.vtk\n", "needs a simulation box", 1);
}

/* ---- files for output_vtk.py ----------------------------------------------------- */

static int write_files(const char *out)
{
    snprintf(dir, sizeof dir, "%s", out);
    struct gravel *g = formula_system(7);
    g->step = 40;
    g->time = 0.125;
    int rc = script(g, "dump a all vtk 20 @/ascii.vtk\ndump_modify a sort id\n"
                       "dump b all vtk 20 @/binary.vtk\ndump_modify b sort id binary yes\n"
                       "dump e even vtk 20 @/even.vtk\ndump_modify e sort id binary yes\n"
                       "dump n none vtk 20 @/empty.vtk\n"
                       "dump s all vtk 20 @/series_*.vtk\n"
                       "dump c all custom 20 @/custom.txt id type x y z vx vy vz fx fy fz "
                       "radius diameter mass omegax omegay omegaz tqx tqy tqz xu ix\n"
                       "dump_modify c sort id\n");
    if (rc != GR_OK) {
        printf("FAIL write_files: %s\n", g->err.msg);
        fx_destroy(g);
        return 1;
    }
    if (fx_call(g, do_setup, 0, NULL) != 0) {
        printf("FAIL write_files: %s\n", g->err.msg);
        fx_destroy(g);
        return 1;
    }
    g->step = 60;
    g->time = 0.1875;
    dump_step_all(g);
    fx_destroy(g); /* publishes custom.txt */

    /* tags beyond 2^31 - 1: id becomes vtktypeint64 */
    g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    fx_box(g, lo, hi, 1);
    double x[3] = {0.5, 0.5, 0.5};
    atoms_add(g, 3000000000LL, 1, x, 0.1, 1.0);
    atoms_add(g, 7, 1, x, 0.1, 1.0);
    rc = script(g, "dump w all vtk 1 @/wide.vtk\ndump_modify w binary yes\n"
                   "dump x all vtk 1 @/wide_ascii.vtk\n");
    if (rc != GR_OK || fx_call(g, do_write, 1, (char *[]){"w"}) ||
        fx_call(g, do_write, 1, (char *[]){"x"})) {
        printf("FAIL write_files: %s\n", g->err.msg);
        fx_destroy(g);
        return 1;
    }
    fx_destroy(g);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "--write") == 0)
        return write_files(argv[2]);
    RUN(custom_text);
    RUN(custom_formats);
    RUN(append_scheme);
    RUN(first_and_append);
    RUN(write_dump);
    RUN(vtk_files);
    RUN(write_failures);
    RUN(errors);
    return 0;
}
