/* fuzz_input.c - libFuzzer target: arbitrary bytes as an input script, a
 * data file or a restart file.
 *
 * The first line selects what the rest is: "#!data" (the rest is written to
 * fz.data and read by `read_data fz.data`), "#!restart" (written to fz.rst,
 * read by `read_restart fz.rst`, then a few commands that use the restored
 * state), "#!restart+" (the same, after the harness rewrote the header's
 * payload length and FNV-1a checksum to match the bytes, so mutations reach
 * the section parser and the validation instead of the checksum test),
 * "#!stl", "#!stlb", "#!vtk" (a mesh file read by fix mesh/surface, then
 * used by create_atoms: see mesh_input below),
 * "#!molecule" (written to fz.mol, read by `molecule m fz.mol`, then used by
 * fix rigid/small and fix pour, which derive its centre, mass, inertia and
 * extent without starting OpenCL), "#!dump" (written to fz.dump, read by
 * three `read_dump` commands: add, replace + trim, purge + add keep),
 * anything else: the whole input is the script. Each input runs on a fresh engine with no screen and no log, inside a
 * scratch directory (print/log may write files there). Commands that would
 * start the OpenCL engine, write outputs endlessly or read outside the
 * scratch directory are refused through inp_set_limits(), and a command
 * budget ends `jump SELF` loops that never finish. Build and run: make fuzz. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gravel.h"
#include "input.h"

static const char *denied[] = {"run", "minimize", "create_atoms", "read_data", "write_data",
                               "read_restart", "write_restart", "restart", "dump",
                               "dump_modify", "shell", NULL};

/* Files named in include/jump/print must stay in the scratch directory
 * (no '/'), so the fuzzer never reads /dev/stdin or writes elsewhere. `log`
 * is allowed only as `log none`: a log file per input made every run slow
 * (opening and echoing into files) without reaching new code. */
static int harness_file; /* the harness' own read_data / read_restart are allowed */

static int mesh_allow(int argc, char **argv);

static int allow(int argc, char **argv)
{
    int m = mesh_allow(argc, argv);
    if (m)
        return m > 0;
    if (harness_file && argc == 2 &&
        ((!strcmp(argv[0], "read_data") && !strcmp(argv[1], "fz.data")) ||
         (!strcmp(argv[0], "read_restart") && !strcmp(argv[1], "fz.rst"))))
        return 1;
    for (int i = 0; denied[i]; i++)
        if (strcmp(argv[0], denied[i]) == 0)
            return 0;
    if (strcmp(argv[0], "log") == 0 && (argc < 2 || strcmp(argv[1], "none") != 0))
        return 0;
    for (int i = 1; i < argc; i++)
        if (strchr(argv[i], '/') && (!strcmp(argv[0], "include") || !strcmp(argv[0], "jump") ||
                                     !strcmp(argv[0], "log") || !strcmp(argv[0], "print")))
            return 0;
    return 1;
}

static char scratch[] = "/tmp/gravel-fuzz-XXXXXX";

static void remove_scratch(void)
{
    char cmd[64];
    snprintf(cmd, sizeof cmd, "rm -rf %s", scratch);
    if (chdir("/") == 0 && system(cmd) != 0)
        fprintf(stderr, "fuzz_input: could not remove %s\n", scratch);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc; (void)argv;
    if (!mkdtemp(scratch) || chdir(scratch) != 0)
        abort();
    atexit(remove_scratch);
    return 0;
}

/* The script run after a data or restart file is read: commands that walk
 * the restored atoms, groups and box. */
static const char data_script[] =
    "atom_style sphere\n"
    "read_data fz.data\n"
    "group g1 type 1\n"
    "set group all density 1.0\n"
    "variable n equal count(all)+xcm(all,x)\n"
    "print \"$n\"\n";
static const char restart_script[] =
    "read_restart fz.rst\n"
    "group g1 type 1\n"
    "variable n equal count(all)+xcm(all,x)+mass(all)\n"
    "print \"$n\"\n"
    "pair_coeff * *\n";

/* ---- molecule and dump files ("#!molecule", "#!dump") ---- */

static const char molecule_script[] =
    "atom_style sphere\n"
    "region b block 0 10 0 10 0 10\n"
    "create_box 4 b\n"
    "fix pm all property/atom mol\n"
    "molecule m fz.mol\n"
    "fix g all gravity 1.0 vector 0 0 -1\n"
    "fix r all rigid/small molecule mol m\n"
    "fix p all pour 5 0 1 region b mol m rigid r\n";
static const char dump_script[] =
    "atom_style sphere\n"
    "region b block 0 10 0 10 0 10\n"
    "create_box 2 b\n"
    "read_dump fz.dump 0 x y z vx vy vz ix iy iz add yes\n"
    "read_dump fz.dump 0 x y z replace yes trim yes box no\n"
    "group g1 type 1\n"
    "variable n equal count(all)+xcm(all,x)\n"
    "print \"$n\"\n"
    "read_dump fz.dump 10 x y z purge yes replace no add keep\n";

/* The text-file modes: the input after the first line is the file. */
static const struct text_mode {
    const char *magic, *file, *script;
} text_modes[] = {
    {"#!molecule\n", "fz.mol", molecule_script},
    {"#!dump\n", "fz.dump", dump_script},
};

static int write_file(const char *name, const uint8_t *data, size_t size);

/* The script of the text-file mode `data` starts with, after writing its
 * file; NULL when it starts with none. *skip: the file could not be written. */
static const char *text_file_mode(const uint8_t *data, size_t size, int *skip)
{
    for (size_t i = 0; i < sizeof text_modes / sizeof text_modes[0]; i++) {
        const struct text_mode *m = &text_modes[i];
        size_t n = strlen(m->magic);
        if (size >= n && !memcmp(data, m->magic, n)) {
            *skip = write_file(m->file, data + n, size - n) != 0;
            return m->script;
        }
    }
    return NULL;
}

static int write_file(const char *name, const uint8_t *data, size_t size)
{
    FILE *fp = fopen(name, "wb");
    if (!fp)
        return -1;
    size_t w = fwrite(data, 1, size, fp);
    return (fclose(fp) == 0 && w == size) ? 0 : -1;
}

/* "#!restart+": make the header's length and checksum those of the payload
 * (restart.h: 32-byte header, u64 length at 16, u64 FNV-1a 64 at 24). */
static void fix_header(uint8_t *b, size_t n)
{
    if (n < 32)
        return;
    uint64_t len = n - 32, h = 14695981039346656037ull;
    for (size_t i = 32; i < n; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    memcpy(b + 16, &len, 8);
    memcpy(b + 24, &h, 8);
}

static int has_prefix(const uint8_t *data, size_t size, const char *p)
{
    size_t n = strlen(p);
    return size >= n && !memcmp(data, p, n);
}

/* ---- mesh files: "#!stl", "#!stlb", "#!vtk" ----------------------------------------
 * The rest of the input is a mesh file: "#!stl" writes it as it is to fz.stl
 * (the reader tells ASCII from binary STL by the contents), "#!stlb" first
 * sets the binary STL header's triangle count to what the bytes hold and
 * drops a cut last triangle (so mutations reach the triangle data instead of
 * the count check), "#!vtk" writes it to fz.vtk. mesh_script then reads it
 * (fix mesh/surface: parsing, welding, validation, adjacency, transforms),
 * bins it and keeps random sites clear of it (create_atoms ... mesh: host
 * code, no OpenCL), and reads it again with a coarse weld tolerance. */
static int harness_mesh; /* the harness' own create_atoms is allowed */

/* 1: allow (the harness' create_atoms), -1: refuse (a mesh file named with
 * '/': it could be /dev/zero or a FIFO outside the scratch directory),
 * 0: no opinion. */
static int mesh_allow(int argc, char **argv)
{
    if (harness_mesh && argc > 0 && !strcmp(argv[0], "create_atoms"))
        return 1;
    if (argc > 0 && !strcmp(argv[0], "fix"))
        for (int i = 1; i + 1 < argc; i++)
            if (!strcmp(argv[i], "file") && strchr(argv[i + 1], '/'))
                return -1;
    return 0;
}

static const char mesh_script_fmt[] =
    "region b block -2 2 -2 2 -2 2\n"
    "create_box 1 b\n"
    "fix m all mesh/surface file %s type 1 rotate axis 1 1 0 angle 30 move 0.1 0 0\n"
    "create_atoms 1 random 50 123 NULL mesh m 0.3\n"
    "fix p all mesh/surface file %s type 1 precision 0.01\n"
    "variable n equal count(all)+f_m[1]\n"
    "print \"$n\"\n";
static char mesh_script[sizeof mesh_script_fmt + 16];

/* "#!stlb": header count := complete 50-byte triangles after the 84-byte header. */
static size_t fix_stl_count(uint8_t *b, size_t n)
{
    if (n < 84)
        return n;
    uint64_t t = (n - 84) / 50;
    uint32_t c = t > 0xffffffffu ? 0xffffffffu : (uint32_t)t;
    for (int k = 0; k < 4; k++)
        b[80 + k] = (uint8_t)(c >> (8 * k));
    return 84 + 50 * (size_t)c;
}

/* 1: a mesh input, *script set; 0: not one; -1: the file could not be written. */
static int mesh_input(const uint8_t *data, size_t size, const char **script)
{
    const char *file = NULL;
    size_t skip = 0;
    int fix = 0;
    if (has_prefix(data, size, "#!stlb\n")) {
        file = "fz.stl", skip = 7, fix = 1;
    } else if (has_prefix(data, size, "#!stl\n")) {
        file = "fz.stl", skip = 6;
    } else if (has_prefix(data, size, "#!vtk\n")) {
        file = "fz.vtk", skip = 6;
    } else {
        return 0;
    }
    uint8_t *copy = malloc(size - skip + 1);
    if (!copy)
        return -1;
    memcpy(copy, data + skip, size - skip);
    size_t n = fix ? fix_stl_count(copy, size - skip) : size - skip;
    int bad = write_file(file, copy, n);
    free(copy);
    if (bad)
        return -1;
    snprintf(mesh_script, sizeof mesh_script, mesh_script_fmt, file, file);
    *script = mesh_script;
    harness_mesh = 1;
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *script = NULL;
    int skip = 0;
    harness_file = 0;
    harness_mesh = 0;
    if ((script = text_file_mode(data, size, &skip))) {
        if (skip)
            return 0;
    } else if (has_prefix(data, size, "#!data\n")) {
        if (write_file("fz.data", data + 7, size - 7))
            return 0;
        script = data_script;
    } else if (has_prefix(data, size, "#!restart+\n")) {
        uint8_t *copy = malloc(size);
        if (!copy)
            return 0;
        memcpy(copy, data + 11, size - 11);
        fix_header(copy, size - 11);
        int bad = write_file("fz.rst", copy, size - 11);
        free(copy);
        if (bad)
            return 0;
        script = restart_script;
    } else if (has_prefix(data, size, "#!restart\n")) {
        if (write_file("fz.rst", data + 10, size - 10))
            return 0;
        script = restart_script;
    }
    if (!script && mesh_input(data, size, &script) < 0)
        return 0;
    char *text = NULL;
    if (!script) {
        text = malloc(size + 1);
        if (!text)
            return 0;
        memcpy(text, data, size);
        text[size] = '\0';
    }
    harness_file = script != NULL;
    struct gravel *g = gr_create();
    g->screen = NULL;
    g->echo = ECHO_NONE;
    inp_set_limits(g, allow, 1000, (size_t)4 << 20);
    inp_string(g, script ? script : text, "fuzz.in");
    gr_destroy(g);
    free(text);
    return 0;
}
