/* test_reliability.c - issue 12: bad input files, line endings, messages,
 * failed writes and unwinding. Each case feeds a bad script or file and
 * matches the message and the script line it names. */
#include <errno.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "test.h"
#include "test_tmp.h"

#include "error.h"
#include "dump.h"
#include "fix.h"
#include "pair.h"
#include "restart.h"
#include "variable.h"


static void write_bytes(const char *path, const char *text, size_t n)
{
    FILE *fp = fopen(path, "wb");
    fwrite(text, 1, n, fp);
    fclose(fp);
}

static char script[4096];

/* printf into script */
#define SCRIPT(...) snprintf(script, sizeof script, __VA_ARGS__)

/* A stream that gives `good` bytes, then fails with EIO: a read error. */
struct failing {
    const char *text;
    size_t pos, good;
};

static ssize_t failing_read(void *cookie, char *buf, size_t n)
{
    struct failing *f = cookie;
    if (f->pos >= f->good) {
        errno = EIO;
        return -1;
    }
    size_t k = f->good - f->pos < n ? f->good - f->pos : n;
    memcpy(buf, f->text + f->pos, k);
    f->pos += k;
    return (ssize_t)k;
}

/* item 1: a read error is an error, not the end of the script */
TEST(read_error_is_error)
{
    struct failing f = {"variable a equal 1\nvariable b equal 2\n", 0, 19};
    cookie_io_functions_t io = {failing_read, NULL, NULL, NULL};
    FILE *fp = fopencookie(&f, "r", io);
    struct gravel *g = test_engine();
    int rc = inp_stream(g, fp, "bad.in");
    CHECK(rc == GR_ERR);
    CHECK(strstr(g->err.msg, "read error in bad.in after line 1: Input/output error") != NULL);
    CHECK(var_retrieve(g, "a") != NULL && var_retrieve(g, "b") == NULL);
    fclose(fp);
    gr_destroy(g);

    /* a line longer than the limit (an endless device, a binary file) */
    g = test_engine();
    inp_set_limits(g, NULL, 0, 1000);
    char *big = malloc(5000);
    memset(big, 'x', 4999);
    big[4999] = '\0';
    write_bytes(tmp_path("big.in"), big, 4999);
    free(big);
    SCRIPT("print ok\ninclude %s\nprint after\n", tmp_path("big.in"));
    rc = inp_string(g, script, "test.in");
    CHECK(rc == GR_ERR);
    CHECK(strstr(g->err.msg, "is longer than 1000 bytes (is it a text file?)") != NULL);
    gr_destroy(g);
}

/* item 2: directories, FIFOs and devices are rejected at the command's line */
TEST(not_regular_files)
{
    mkdir(tmp_path("adir"), 0755);
    mkfifo(tmp_path("afifo"), 0644);
    SCRIPT("print a\ninclude %s\n", tmp_path("adir"));
    CHECK_ERROR(script, "is a directory", 2);
    SCRIPT("print a\n\ninclude %s\n", tmp_path("afifo"));
    CHECK_ERROR(script, "is a FIFO (named pipe), not a regular file", 3);
    CHECK_ERROR("include /dev/zero\n", "is a character device, not a regular file", 1);
    SCRIPT("label x\njump %s\n", tmp_path("adir"));
    CHECK_ERROR(script, "is a directory", 2);
    SCRIPT("read_data %s\n", tmp_path("adir"));
    CHECK_ERROR(script, "cannot open data file", 1);
    CHECK_ERROR("print a\nread_data /dev/zero\n", "is a character device, not a regular file",
                2);
    SCRIPT("read_data %s\n", tmp_path("afifo"));
    CHECK_ERROR(script, "is a FIFO (named pipe), not a regular file", 1);
    SCRIPT("read_restart %s\n", tmp_path("adir"));
    CHECK_ERROR(script, "cannot open restart file", 1);
    SCRIPT("\nread_restart %s\n", tmp_path("afifo"));
    CHECK_ERROR(script, "is a FIFO (named pipe), not a regular file", 2);
    CHECK_ERROR("read_restart /dev/null\n", "is a character device", 1);
    /* a restart header that announces more than the file holds: no allocation of it */
    char hdr[40] = "GRAVELRS";
    uint32_t marker = RESTART_ENDIAN_MARKER, version = RESTART_FORMAT_VERSION;
    uint64_t len = (uint64_t)1 << 62, hash = 0;
    memcpy(hdr + 8, &marker, 4);
    memcpy(hdr + 12, &version, 4);
    memcpy(hdr + 16, &len, 8);
    memcpy(hdr + 24, &hash, 8);
    write_bytes(tmp_path("huge.rst"), hdr, 40);
    SCRIPT("read_restart %s\n", tmp_path("huge.rst"));
    CHECK_ERROR(script, "is truncated: the header announces 4611686018427387904 bytes", 1);
}

/* item 3: CR-only and CR LF line ends, a UTF-8 byte-order mark */
TEST(line_endings_and_bom)
{
    struct gravel *g = test_engine();
    CHECK(inp_string(g, "variable a equal 1\rvariable b equal 2\r\rvariable c equal 3", "t")
          == GR_OK);
    CHECK(var_retrieve(g, "c") && !strcmp(var_retrieve(g, "c"), "3"));
    CHECK(inp_string(g, "\xEF\xBB\xBFvariable d equal 4\r\n", "t") == GR_OK);
    CHECK(var_retrieve(g, "d") && !strcmp(var_retrieve(g, "d"), "4"));
    write_bytes(tmp_path("mac.in"), "\xEF\xBB\xBFvariable e equal 5\rvariable f string &\r  x\r",
                45);
    SCRIPT("include %s\n", tmp_path("mac.in"));
    CHECK(inp_string(g, script, "t") == GR_OK);
    CHECK(var_retrieve(g, "e") && !strcmp(var_retrieve(g, "e"), "5"));
    CHECK(var_retrieve(g, "f") && !strcmp(var_retrieve(g, "f"), "x"));
    gr_destroy(g);
    /* line numbers count CR-only lines */
    CHECK_ERROR("print a\rprint b\rbogus\r", "unknown command 'bogus'", 3);
    CHECK_ERROR("\xEF\xBB\xBF" "bogus\n", "unknown command 'bogus'", 1);
    /* a data file with CR-only line ends and a BOM */
    const char *data = "\xEF\xBB\xBF# CR data\r\r2 atoms\r1 atom types\r0 2 xlo xhi\r"
                       "0 2 ylo yhi\r0 2 zlo zhi\r\rAtoms # sphere\r\r"
                       "1 1 1.0 1.0 0.5 0.5 0.5\r2 1 1.0 1.0 1.5 1.5 1.5\r";
    write_bytes(tmp_path("cr.data"), data, strlen(data));
    g = test_engine();
    SCRIPT("atom_style sphere\nread_data %s\n", tmp_path("cr.data"));
    CHECK(inp_string(g, script, "test.in") == GR_OK);
    CHECK(g->atoms.n == 2);
    gr_destroy(g);
}

/* item 4: messages that named the wrong thing */
TEST(messages)
{
    struct gravel *g = test_engine();
    char name[200];
    memset(name, 'E', sizeof name - 1);
    name[sizeof name - 1] = '\0';
    SCRIPT("variable e getenv %s\nvariable h getenv HOME\n", name);
    CHECK(inp_string(g, script, "test.in") == GR_OK);
    CHECK(var_retrieve(g, "e") && !strcmp(var_retrieve(g, "e"), ""));
    gr_destroy(g);
    CHECK_ERROR("print a\nvariable e getenv A=B\n",
                "environment variable name 'A=B' may contain only letters", 2);
    /* denormals are numbers */
    g = test_engine();
    CHECK(inp_string(g, "region b block 0 1 0 1 0 1\ncreate_box 1 b\nmass 1 4.9e-324\n",
                     "test.in") == GR_OK);
    CHECK(g->atoms.type_mass[1] > 0 && g->atoms.type_mass[1] < 1e-320);
    gr_destroy(g);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 1 b\nmass 1 1e999\n",
                "expected a number", 3);
    /* in a data file and in expressions too */
    const char *dn = "# denormal\n\n1 atoms\n1 atom types\n0 2 xlo xhi\n0 2 ylo yhi\n"
                     "0 2 zlo zhi\n\nAtoms # sphere\n\n1 1 1.0 1.0 0.5 0.5 4.9e-324\n\n"
                     "Velocities\n\n1 4.9e-324 0 0 0 0 0\n";
    write_bytes(tmp_path("dn.data"), dn, strlen(dn));
    g = test_engine();
    SCRIPT("atom_style sphere\nread_data %s\nvariable d equal 4.9e-324*2\n", tmp_path("dn.data"));
    CHECK(inp_string(g, script, "test.in") == GR_OK);
    CHECK(g->atoms.n == 1 && g->atoms.x[2] > 0 && g->atoms.x[2] < 1e-320 &&
          g->atoms.v[0] > 0 && g->atoms.v[0] < 1e-320);
    CHECK(var_compute_equal(g, "d") > 0 && var_compute_equal(g, "d") < 1e-320);
    gr_destroy(g);
    /* a region with huge finite bounds is bounded: usable for a group */
    g = test_engine();
    CHECK(inp_string(g, "region b block 0 1 0 1 0 1\ncreate_box 1 b\n"
                        "region h block -1e308 1e308 -1e308 1e308 -1e308 1e308\n"
                        "create_atoms 1 single 0.5 0.5 0.5\ngroup in region h\n",
                     "test.in") == GR_OK);
    CHECK(g->atoms.n == 1 && (g->atoms.mask[0] & 2u));
    gr_destroy(g);
    /* a huge bounded range is not "unbounded" */
    CHECK_ERROR("region b block -1e308 1e308 0 1 0 1\ncreate_box 1 b\n",
                "region 'b' spans -1e+308 to 1e+308 in x: a box length of inf is too large", 2);
    CHECK_ERROR("region b block 0 INF 0 1 0 1\ncreate_box 1 b\n", "is unbounded in x", 2);
}

/* item 5: failed writes are errors naming the file and the reason */
TEST(failed_writes)
{
    CHECK_ERROR("print a\nprint x append /dev/full\n",
                "cannot write '/dev/full': No space left on device", 2);
    CHECK_ERROR("print x file /dev/full\n", "cannot write '/dev/full': No space left", 1);
    CHECK_ERROR("print a\nlog /dev/full\nprint b\n",
                "cannot write log file '/dev/full': No space left on device", 2);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 1 b\n"
                "compute ag all agglomerate file /dev/full\n",
                "cannot write histogram file '/dev/full': No space left on device", 3);
    /* a good print append adds whole lines */
    struct gravel *g = test_engine();
    SCRIPT("print one append %s\nprint two append %s\n", tmp_path("p.txt"), tmp_path("p.txt"));
    CHECK(inp_string(g, script, "test.in") == GR_OK);
    gr_destroy(g);
    FILE *fp = fopen(tmp_path("p.txt"), "r");
    char buf[64] = "";
    size_t n = fp ? fread(buf, 1, sizeof buf - 1, fp) : 0;
    if (fp)
        fclose(fp);
    buf[n] = '\0';
    CHECK(!strcmp(buf, "one\ntwo\n"));
    /* a log that fails after it was opened: the next command stops */
    g = test_engine();
    CHECK(gr_log_open(g, "/dev/full", 0) == 0);
    CHECK(inp_string(g, "variable a equal 1\nvariable b equal 2\n", "test.in") == GR_ERR);
    CHECK(strstr(g->err.msg, "cannot write log file '/dev/full'") &&
          strstr(g->err.msg, "(test.in:1)"));
    CHECK(g->logfile == NULL && var_retrieve(g, "b") == NULL);
    gr_destroy(g);
}

/* item 7: a fix whose create fails is not registered; a replacement leaves one */
TEST(fix_unwinding)
{
    struct gravel *g = test_engine();
    const char *base = "region b block 0 1 0 1 0 1\ncreate_box 1 b\n"
                       "fix 1 all gravity 1.0 vector 0 0 -1\n";
    CHECK(inp_string(g, base, "test.in") == GR_OK);
    CHECK(g->styles.nfix == 1);
    struct fix *f1 = fix_find(g, "1");
    CHECK(inp_string(g, "fix 2 all gravity bogus\n", "test.in") == GR_ERR);
    CHECK(g->styles.nfix == 1 && fix_find(g, "2") == NULL);
    CHECK(inp_string(g, "fix 1 all gravity 2.0 vector 0 0 -1 bogus\n", "test.in") == GR_ERR);
    CHECK(g->styles.nfix == 1 && fix_find(g, "1") == f1);
    CHECK(inp_string(g, "fix 1 all gravity 2.0 vector 0 0 -1\nfix 3 all nve/sphere\n"
                        "fix 1 all gravity 3.0 vector 0 0 -1\n", "test.in") == GR_OK);
    CHECK(g->styles.nfix == 2 && g->styles.fix[0] == fix_find(g, "1") &&
          g->styles.fix[1] == fix_find(g, "3"));
    gr_destroy(g);
}

/* The state a failing command must leave as it was: counts and identities of
 * fixes, computes, dumps, regions and groups, the pair style and its
 * coefficients, the thermo columns, atom values. */
struct snapshot {
    int nfix, ncompute, ndump, nregion, ngroup, natoms, ncol, ntypes, lost, norm, flush;
    int dump_every, dump_sort, dump_pad;
    char *format_float;
    void *fix0, *compute0, *dump0, *region0, *pair;
    unsigned mask[8];
    double coef0, diam0, mass0, vx0;
    char col1[GR_NAMELEN];
};

static void snap(struct gravel *g, struct snapshot *s)
{
    memset(s, 0, sizeof *s);
    s->nfix = g->styles.nfix;
    s->ncompute = g->styles.ncompute;
    s->ndump = g->styles.ndump;
    s->nregion = g->regions.n;
    for (int k = 0; k < GR_MAXGROUP; k++)
        s->ngroup += g->groups.used[k];
    s->natoms = g->atoms.n;
    s->ntypes = g->atoms.ntypes;
    s->ncol = g->thermo.ncol;
    s->lost = (int)g->thermo.lost;
    s->norm = g->thermo.norm;
    s->flush = g->thermo.flush;
    s->format_float = g->thermo.format_float;
    snprintf(s->col1, sizeof s->col1, "%s", g->thermo.ncol > 1 ? g->thermo.col[1] : "");
    s->fix0 = s->nfix ? g->styles.fix[0] : NULL;
    s->compute0 = s->ncompute ? g->styles.compute[0] : NULL;
    s->dump0 = s->ndump ? g->styles.dump[0] : NULL;
    if (s->ndump) {
        s->dump_every = g->styles.dump[0]->every;
        s->dump_sort = g->styles.dump[0]->sort;
        s->dump_pad = g->styles.dump[0]->pad;
    }
    s->region0 = s->nregion ? g->regions.r[0] : NULL;
    s->pair = g->styles.pair;
    s->coef0 = g->styles.pair ? g->styles.pair->coef[0] : 0;
    for (int i = 0; i < g->atoms.n && i < 8; i++)
        s->mask[i] = g->atoms.mask[i];
    if (g->atoms.n) {
        s->diam0 = g->atoms.radius[0];
        s->mass0 = g->atoms.rmass[0];
        s->vx0 = g->atoms.v[0];
    }
}

/* item 7: every failing command leaves the engine as it was */
TEST(failing_commands_change_nothing)
{
    struct gravel *g = test_engine();
    SCRIPT("units lj\natom_style sphere\nregion b block 0 4 0 4 0 4\ncreate_box 2 b\n"
           "create_atoms 1 single 1 1 1\ncreate_atoms 2 single 3 3 3\n"
           "set group all diameter 0.5 density 1\n"
           "pair_style gran/hooke 2000 NULL 50 NULL 0.5 0\npair_coeff * *\n"
           "group g1 type 1\nregion r1 sphere 1 1 1 0.5\ncompute c1 all ke\n"
           "fix 1 all nve/sphere\ndump d1 all atom 100 %s\n"
           "thermo_style custom step atoms ke\n", tmp_path("d1.atom"));
    CHECK(inp_string(g, script, "test.in") == GR_OK);
    static const char *bad[] = {
        "fix 1 all gravity bogus\n",
        "fix 2 g1 wall/gran hooke 1 NULL 1 NULL 0.5 0 zplane 0 NULL bogus\n",
        "compute c1 all reduce bogus ke\n",
        "compute c2 all reduce sum c_nonexistent\n",
        "compute c3 all property/atom bogus\n",
        "dump d2 all custom 10 d2.txt id bogus\n",
        "dump d1 all atom 10 other.atom\n",
        "dump_modify d1 every 10 bogus 1\n",
        "dump_modify d1 every 7 sort id pad 3 format float %10.4f scale no first maybe\n",
        "region r1 block 0 1 0 1 0 1\n",
        "region r2 block 0 1 0 1 0 bogus\n",
        "region r3 union 2 r1 nonexistent\n",
        "region r4 sphere 0 0 0 -1\n",
        "group g1 region nonexistent\n",
        "group g2 type 1 bogus\n",
        "group g3 id 1:x\n",
        "group g1 subtract all nonexistent\n",
        "pair_style gran/hooke 2000 NULL 50 NULL bogus 0\n",
        "pair_style bogus/style 1\n",
        "pair_coeff 1 3\n",
        "thermo_style custom step bogus\n",
        "thermo_style custom step c_nonexistent\n",
        "set group all diameter 2.0 density -1\n",
        "set group all vx 5.0 bogus 1\n",
        "velocity all set 1 0 0 bogus yes\n",
        "velocity all create -1 1234\n",
        "mass 1 -1\n",
        "create_atoms 1 single 1 1 1 bogus\n",
        "create_atoms 1 single 9 9 9\n",
        "delete_atoms group g1 bogus\n",
        "displace_atoms all move 1 0 0 bogus\n",
        "neigh_modify every 2 delay 3\n",
        "neigh_modify exclude group g1 nonexistent\n",
        "timestep -1\n",
        "unfix nonexistent\n",
        "uncompute nonexistent\n",
        "undump nonexistent\n",
        "thermo_modify lost warn norm maybe\n",
        "lattice sc -1\n",
        "lattice fcc 1.0 origin 0.5 0.5 0.5 orient x 1 0 0 bogus\n",
        "lattice sc 1.0 spacing 1 1\n",
        "change_box all x final 0 8 bogus\n",
        "units real\n",
        "boundary f f f\n",
        "atom_modify sort 100 -1\n",
        "thermo_modify format float %12.5f flush bogus\n",
        NULL};
    for (int k = 0; bad[k]; k++) {
        struct snapshot a, b;
        struct neigh_settings ns = g->neigh;
        struct domain dom = g->dom;
        double dt = g->dt;
        snap(g, &a);
        int rc = inp_string(g, bad[k], "test.in");
        snap(g, &b);
        int same = !memcmp(&a, &b, sizeof a) && !memcmp(&ns, &g->neigh, sizeof ns) &&
                   !memcmp(&dom, &g->dom, sizeof dom) && dt == g->dt;
        if (rc != GR_ERR || !same)
            printf("  command '%.*s': rc %d, state %s\n", (int)strlen(bad[k]) - 1, bad[k], rc,
                   same ? "unchanged" : "CHANGED");
        CHECK(rc == GR_ERR && same);
    }
    /* and the engine still runs */
    CHECK(inp_string(g, "run 5\n", "test.in") == GR_OK);
    gr_destroy(g);
    /* before a box: a failing read_data or create_box creates nothing */
    const char *bad_data = "# bad\n\n2 atoms\n1 atom types\n0 2 xlo xhi\n0 2 ylo yhi\n"
                           "0 2 zlo zhi\n\nAtoms # sphere\n\n1 1 1.0 1.0 0.5 0.5 0.5\n"
                           "2 1 1.0 1.0 1.5 x 1.5\n";
    write_bytes(tmp_path("bad.data"), bad_data, strlen(bad_data));
    g = test_engine();
    SCRIPT("atom_style sphere\nregion r block 0 1 0 1 0 1\nread_data %s\n", tmp_path("bad.data"));
    CHECK(inp_string(g, script, "test.in") == GR_ERR);
    CHECK(g->atoms.n == 0 && !g->dom.box_exists && g->regions.n == 1);
    CHECK(inp_string(g, "create_box 1 nonexistent\n", "test.in") == GR_ERR);
    CHECK(inp_string(g, "boundary p p bogus\n", "test.in") == GR_ERR);
    CHECK(g->dom.bnd[2][0] == BND_P && !g->dom.box_exists);
    CHECK(inp_string(g, "create_box 1 r\n", "test.in") == GR_OK);
    CHECK(g->dom.box_exists && g->atoms.ntypes == 1);
    gr_destroy(g);
    /* references are checked when the command is read, as in LAMMPS */
    const char *box = "region b block 0 1 0 1 0 1\ncreate_box 1 b\n";
    SCRIPT("%sthermo_style custom step c_nope\n", box);
    CHECK_ERROR(script, "could not find thermo custom compute ID 'nope'", 3);
    SCRIPT("%sthermo_style custom step v_nope\n", box);
    CHECK_ERROR(script, "could not find thermo custom variable name 'nope'", 3);
    SCRIPT("%sthermo_style custom step f_nope[1]\n", box);
    CHECK_ERROR(script, "could not find thermo custom fix ID 'nope'", 3);
    SCRIPT("%scompute r all reduce sum c_nope\n", box);
    CHECK_ERROR(script, "compute reduce refers to unknown compute ID 'nope'", 3);
}

/* item 7: a run that stops on an error ends its output (output_abort): the
 * append-mode dump holds the snapshots written so far, and the engine runs
 * again afterwards */
TEST(failing_run_aborts_output)
{
    struct gravel *g = test_engine();
    SCRIPT("units lj\natom_style sphere\nboundary p p f\nregion b block 0 10 0 10 0 10\n"
           "create_box 1 b\ncreate_atoms 1 single 5 5 5\ncreate_atoms 1 single 2 2 2\n"
           "set group all diameter 1 density 1\n"
           "pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *\n"
           "group one id 2\nvelocity one set 0 0 -100\nfix 1 all nve/sphere\n"
           "timestep 0.001\ndump 1 all atom 1 %s\nrun 100\n", tmp_path("abort.atom"));
    CHECK(inp_string(g, script, "test.in") == GR_ERR);
    CHECK(strstr(g->err.msg, "Lost atoms: original 2 current 1") &&
          strstr(g->err.msg, "atom 2 at (") && strstr(g->err.msg, "(test.in:16)"));
    /* the dump file is complete up to the error: no temporary left */
    struct stat st;
    CHECK(stat(tmp_path("abort.atom"), &st) == 0 && st.st_size > 0);
    CHECK(stat(tmp_path("abort.atom.tmp"), &st) != 0);
    FILE *fp = fopen(tmp_path("abort.atom"), "r");
    int snaps = 0;
    char line[256];
    while (fp && fgets(line, sizeof line, fp))
        snaps += !strncmp(line, "ITEM: TIMESTEP", 14);
    if (fp)
        fclose(fp);
    CHECK(snaps >= 2);
    CHECK(inp_string(g, "thermo_modify lost ignore\nrun 10\n", "test.in") == GR_OK);
    gr_destroy(g);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/gravel-test-rel-XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    RUN(read_error_is_error);
    RUN(not_regular_files);
    RUN(line_endings_and_bom);
    RUN(messages);
    RUN(failed_writes);
    RUN(fix_unwinding);
    RUN(failing_commands_change_nothing);
    RUN(failing_run_aborts_output);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    return system(cmd) != 0;
}
