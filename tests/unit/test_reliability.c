/* test_reliability.c - issue 12: bad input files, line endings, messages,
 * failed writes and unwinding. Each case feeds a bad script or file and
 * matches the message and the script line it names. */
#include <errno.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "test.h"

#include "error.h"
#include "fix.h"
#include "variable.h"

static char tmpdir[64];

static const char *tmp_path(const char *name)
{
    static char buf[4][160];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", tmpdir, name);
    return buf[k];
}

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
    uint32_t marker = 0x01020304u, version = 2;
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
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    return system(cmd) != 0;
}
