/* test_input_files.c - issue 24: every reader of an input file refuses a
 * FIFO (which would block), a device such as /dev/zero (endless) and a
 * directory at the command's own line, and a file slurped whole has a size
 * limit; the molecule and dump file findings of the fuzzer (each with its
 * input in tests/fuzz/corpus/crash-*.in). */
#include <stdlib.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "test.h"
#include "test_tmp.h"

#include "fileio.h"
#include "variable.h"


static char script[4096];
#define SCRIPT(...) snprintf(script, sizeof script, __VA_ARGS__)

static const char box[] = "region b block -1 1 -1 1 -1 1\ncreate_box 2 b\n";

/* `cmd` with %s for the file name fails at line 3 with `what` for each
 * special file: a FIFO, /dev/zero and a directory. */
static void check_reader(const char *cmd, const char *what)
{
    const char *files[] = {tmp_path("fifo"), "/dev/zero", tmpdir};
    const char *why[] = {"is a FIFO (named pipe), not a regular file",
                         "is a character device, not a regular file", "is a directory"};
    for (int i = 0; i < 3; i++) {
        char line[512], msg[256];
        snprintf(line, sizeof line, cmd, files[i]);
        SCRIPT("%s%s\n", box, line);
        snprintf(msg, sizeof msg, "%s'%s': %s", what, files[i], why[i]);
        if (!strcmp(what, "mesh"))
            snprintf(msg, sizeof msg, "%s: cannot open mesh file: %s", files[i], why[i]);
        time_t t0 = time(NULL);
        CHECK_ERROR(script, msg, 3);
        CHECK(time(NULL) - t0 < 5); /* refused, never waited on */
    }
}

TEST(special_files_every_reader)
{
    CHECK(mkfifo(tmp_path("fifo"), 0644) == 0);
    check_reader("fix m all mesh/surface file %s type 1", "mesh");
    check_reader("molecule m %s", "cannot open molecule file ");
    check_reader("read_dump %s 0 x y z", "cannot open dump file ");
    check_reader("rerun %s dump x y z", "cannot open dump file ");
    check_reader("include %s", "cannot open input script ");
}

/* a mesh file is read whole: one byte over the limit is refused before any
 * allocation (a sparse file: no disk space used) */
TEST(mesh_size_limit)
{
    const char *big = tmp_path("big.stl");
    FILE *fp = fopen(big, "w");
    CHECK(fp && ftruncate(fileno(fp), ((off_t)1 << 30) + 1) == 0);
    fclose(fp);
    SCRIPT("%sfix m all mesh/surface file %s type 1\n", box, big);
    CHECK_ERROR(script, "cannot open mesh file: is 1073741825 bytes, more than the limit of "
                        "1073741824 bytes", 3);
    unlink(big);
    /* fio_read_all itself: contents, length and the terminating NUL */
    write_text(tmp_path("small.txt"), "abc\n");
    size_t len = 0;
    char why[128];
    unsigned char *b = fio_read_all(tmp_path("small.txt"), 4, &len, why, sizeof why);
    CHECK(b && len == 4 && !memcmp(b, "abc\n", 5));
    free(b);
    CHECK(fio_read_all(tmp_path("small.txt"), 3, &len, why, sizeof why) == NULL);
    CHECK(!strcmp(why, "is 4 bytes, more than the limit of 3 bytes"));
    write_text(tmp_path("empty.txt"), "");
    b = fio_read_all(tmp_path("empty.txt"), 3, &len, why, sizeof why);
    CHECK(b && len == 0 && b[0] == 0);
    free(b);
}

/* molecule files: values that do not fit the integer they become are errors
 * (fuzzer: a molecule ID of 7.8e120 converted to int64_t, UBSan) */
TEST(molecule_integer_ranges)
{
    const char *mol = tmp_path("m.mol");
    const char *head = "title\n2 atoms\n\nCoords\n\n1 0 0 0\n2 1 0 0\n\nTypes\n\n1 1\n";
    char text[512];
    snprintf(text, sizeof text, "%s2 2\n\nMolecules\n\n1 1\n2 7777777777777777777777770\n",
             head);
    write_text(mol, text);
    SCRIPT("%smolecule m %s\n", box, mol);
    CHECK_ERROR(script, "invalid molecule ID 7.77778e+24 for atom 2 (an integer "
                        "1..2147483647)", 3);
    snprintf(text, sizeof text, "%s2 2\n\nMolecules\n\n1 1\n2 1.5\n", head);
    write_text(mol, text);
    CHECK_ERROR(script, "invalid molecule ID 1.5 for atom 2", 3);
    snprintf(text, sizeof text, "%s2 1e20\n", head);
    write_text(mol, text);
    CHECK_ERROR(script, "invalid atom type 1e+20 for atom 2 (1..2 with offset 0)", 3);
    snprintf(text, sizeof text, "%s2 nan\n", head);
    write_text(mol, text);
    CHECK_ERROR(script, "line 12: expected a finite number, got 'nan'", 3);
    /* an offset that would overflow int */
    snprintf(text, sizeof text, "%s2 2\n", head);
    write_text(mol, text);
    SCRIPT("%smolecule m %s toff 2147483647\n", box, mol);
    CHECK_ERROR(script, "invalid atom type 1 for atom 1 (1..2 with offset 2147483647)", 3);
    /* a section given twice (fuzzer: the second Diameters section leaked the first) */
    const char *twice[] = {"Coords\n\n1 0 0 0\n2 1 0 0\n", "Types\n\n1 1\n2 2\n",
                           "Diameters\n\n1 1\n2 1\n", "Masses\n\n1 1\n2 1\n",
                           "Molecules\n\n1 1\n2 1\n"};
    for (int i = 0; i < 5; i++) {
        snprintf(text, sizeof text, "%s2 2\n\n%s\n%s", head, twice[i], twice[i]);
        write_text(mol, text);
        char want[64];
        snprintf(want, sizeof want, "line %d: a second %.*s section", i < 2 ? 14 : 19,
                 (int)strcspn(twice[i], "\n"), twice[i]);
        SCRIPT("%smolecule m %s\n", box, mol);
        CHECK_ERROR(script, want, 3);
    }
    /* the good file reads, with the offset applied */
    snprintf(text, sizeof text, "%s2 2\n", head);
    write_text(mol, text);
    SCRIPT("%smolecule m %s toff 0\nvariable ok equal 1\n", box, mol);
    struct gravel *g = test_engine();
    CHECK(test_script(g, script) == GR_OK && var_retrieve(g, "ok"));
    gr_destroy(g);
}

/* dump files: ID, type and image flag columns must hold integers that fit
 * (fuzzer: an image flag of 1e12 converted to int, UBSan) */
static void check_dump_value(const char *id, const char *type, const char *ix, const char *what)
{
    char text[2048];
    snprintf(text, sizeof text,
             "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n"
             "-1 1\n-1 1\n-1 1\nITEM: ATOMS id type x y z ix\n1 1 0 0 0 0\n%s %s 0.5 0 0 %s\n",
             id, type, ix);
    write_text(tmp_path("d.dump"), text);
    SCRIPT("%s\nread_dump %s 0 x y z ix add keep\n", box, tmp_path("d.dump"));
    if (what) {
        CHECK_ERROR(script, what, 4);
        return;
    }
    struct gravel *g = test_engine();
    CHECK(test_script(g, script) == GR_OK && g->atoms.n == 2);
    gr_destroy(g);
}

TEST(dump_integer_columns)
{
    check_dump_value("2", "2", "-3", NULL);
    check_dump_value("9007199254740992", "2", "1", NULL);
    check_dump_value("2", "2", "1e12", "atom ID 2 has ix '1e12' (an integer within");
    check_dump_value("2", "1.5", "0", "atom ID 2 has type '1.5' (an integer within");
    check_dump_value("2", "nan", "0", "atom ID 2 has a non-finite type ('nan')");
    check_dump_value("9223372036854775807", "1", "0",
                     "atom ID 9223372036854775807 is too big");
    /* a bad number on an atom line longer than the buffer that held the column
     * labels: the message names the field (it used to read the labels from the
     * freed buffer) */
    char pad[700];
    memset(pad, '0', sizeof pad - 5);
    memcpy(pad + sizeof pad - 5, "1.5x", 5);
    check_dump_value("2", "1", pad, "bad number '00000000000000000000000000000000' in column ix");
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/gravel-test-files-XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    RUN(special_files_every_reader);
    RUN(mesh_size_limit);
    RUN(molecule_integer_ranges);
    RUN(dump_integer_columns);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    return system(cmd) != 0;
}
