/* main.c - the gravel command line (LAMMPS-compatible where LAMMPS has the flag):
 *
 *   gravel [-in FILE] [-var NAME VALUE...] [-log FILE|none] [-echo none|screen|log|both]
 *          [-screen none|FILE] [-device cpu|serial|gpu|N] [-precision single|double]
 *          [-progress] [-check [FILE]] [-compat lammps2021] [-h] [-version]
 *
 * Without -in the script comes from stdin. Exit status: 0 on success (or the
 * status given to `quit`), 1 on any error (a bad command line included). */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <unistd.h>

#include "comm.h"
#include "command.h"
#include "error.h"
#include "fileio.h"
#include "gravel.h"
#include "input.h"
#include "variable.h"

/* Every style from the registry, stringified, for -h. */
static const struct {
    const char *kind, *name;
} style_list[] = {
#define PAIR(k, id) {"pair_style", k},
#define FIX(k, id) {"fix", k},
#define COMPUTE(k, id) {"compute", k},
#define DUMP(k, id) {"dump", k},
#define REGION(k, id) {"region", k},
#include "styles.def"
#undef PAIR
#undef FIX
#undef COMPUTE
#undef DUMP
#undef REGION
    {NULL, NULL}};

static void usage(FILE *out)
{
    fprintf(out,
            "gravel %s - a DEM engine driven by LAMMPS-style input scripts\n\n"
            "usage: gravel [options] [< script]\n"
            "  -in, -i FILE                 read the script from FILE (default: stdin)\n"
            "  -check [FILE]                each run prints the accuracy map of the scene\n"
            "                               (doc/accuracy_map.md) instead of running\n"
            "  -var, -v NAME VALUE...       define index variable NAME with the values\n"
            "  -log, -l FILE|none           log file (default log.gravel)\n"
            "  -echo, -e none|screen|log|both  echo commands (default log)\n"
            "  -screen, -sc none|FILE       screen output off or to a file\n"
            "  -device cpu|serial|gpu|N     OpenCL device (default: env GRAVEL_DEVICE, else cpu;\n"
            "                               serial under 1500 atoms)\n"
            "  -precision single|double     floating point in kernels (default double)\n"
            "  -progress                    progress line on stderr during runs\n"
            "  -compat lammps2021           reproduce LAMMPS 29Sep2021 (its quirks, and its\n"
            "                               granular results that today's LAMMPS changed)\n"
            "                               (doc/lammps.md, Compatibility)\n"
            "  -h, -help                    this help, every command and style\n"
            "  -version                     print the version\n",
            GR_VERSION);
}

static void help(void)
{
    usage(stdout);
    printf("\nCommands:\n");
    for (const struct command *c = gr_commands; c->name; c++)
        printf("  %-16s %s\n", c->name, c->summary);
    static const char *kinds[] = {"region", "pair_style", "fix", "compute", "dump"};
    for (int k = 0; k < 5; k++) {
        printf("\n%s styles:", kinds[k]);
        int n = 0, col = 100;
        for (int i = 0; style_list[i].kind; i++) {
            if (strcmp(style_list[i].kind, kinds[k]) != 0)
                continue;
            int len = (int)strlen(style_list[i].name) + 1;
            if (col + len > 78) {
                printf("\n ");
                col = 1;
            }
            printf(" %s", style_list[i].name);
            col += len;
            n++;
        }
        printf(n ? "\n" : " (none)\n");
    }
}

static int bad(const char *fmt, const char *arg)
{
    fprintf(stderr, "ERROR: command line: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (see gravel -h)\n");
    return 1;
}

static int is_flag(const char *s)
{
    /* "-3" or "-1e5" are values, not flags */
    return s[0] == '-' && s[1] && !isdigit((unsigned char)s[1]) && s[1] != '.';
}

static int valid_device(const char *s)
{
    if (!strcmp(s, "cpu") || !strcmp(s, "serial") || !strcmp(s, "gpu"))
        return 1;
    if (!*s || strlen(s) > 6)
        return 0;
    for (const char *p = s; *p; p++)
        if (!isdigit((unsigned char)*p))
            return 0;
    return 1;
}

static int is_opt(const char *a, const char *x, const char *y)
{
    return strcmp(a, x) == 0 || (y && strcmp(a, y) == 0);
}

/* Define -var NAME V... as an index variable; 0 on success. */
static int define_var(struct gravel *g, const char *name, int n, char **values)
{
    jmp_buf jb;
    int ok = 1;
    g->err.jmp = &jb;
    g->err.cmd = "-var";
    if (setjmp(jb)) {
        gr_report_error(g);
        ok = 0;
    } else {
        var_set_index(g, name, n, values);
    }
    g->err.jmp = NULL;
    g->err.cmd = NULL;
    return ok ? 0 : 1;
}

/* An error on several ranks: rank 0 has reported it (every rank reads the
 * same script, so most errors happen on all of them) and ends the job; a
 * rank whose error rank 0 did not see (an atom it owns) waits for that,
 * then reports it as LAMMPS's "ERROR on proc N" and ends the job. */
static _Noreturn void rank_failed(struct gravel *g, int rank)
{
    if (rank != 0) {
        sleep(2);
        fprintf(stderr, "ERROR on proc %d: %s\n", rank, g->err.msg);
        fflush(stderr);
    }
    comm_abort(1);
}

static double now(void)
{
    struct timeval tv;
    gettimeofday(&tv, NULL);
    return tv.tv_sec + 1e-6 * tv.tv_usec;
}

/* Ranks of an MPI launch (mpirun/mpiexec of OpenMPI or MPICH, srun with PMI):
 * the size of the job from the launcher's environment, 1 when not launched so. */
static int launcher_size(int *rank)
{
    static const char *const size_vars[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"};
    static const char *const rank_vars[] = {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"};
    for (int k = 0; k < 3; k++) {
        const char *s = getenv(size_vars[k]), *r = getenv(rank_vars[k]);
        if (s && atoi(s) > 1) {
            *rank = r ? atoi(r) : 0;
            return atoi(s);
        }
    }
    *rank = 0;
    return 1;
}

int main(int argc, char **argv)
{
    const char *in = NULL, *log = "log.gravel", *screen = NULL, *echo = NULL;
    const char *device = NULL, *precision = NULL;
    int progress = 0, check = 0, lammps2021 = 0;
    /* first pass: validate everything before any file is created */
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int more = i + 1 < argc;
#define IS(x, y) is_opt(a, x, y)
        if (IS("-h", "-help") || IS("--help", NULL)) {
            help();
            return 0;
        } else if (IS("-version", "--version")) {
            printf("gravel %s\n", GR_VERSION);
            return 0;
        } else if (IS("-check", NULL)) {
            /* -check [FILE]: each run prints the accuracy map instead of running */
            check = 1;
            if (more && !is_flag(argv[i + 1]))
                in = argv[++i];
        } else if (IS("-in", "-i")) {
            if (!more)
                return bad("%s needs a file name", a);
            in = argv[++i];
        } else if (IS("-var", "-v")) {
            if (i + 2 >= argc || is_flag(argv[i + 2]))
                return bad("%s needs a name and at least one value", a);
            i += 2;
            while (i + 1 < argc && !is_flag(argv[i + 1]))
                i++;
        } else if (IS("-log", "-l")) {
            if (!more)
                return bad("%s needs a file name or none", a);
            log = argv[++i];
        } else if (IS("-echo", "-e")) {
            if (!more)
                return bad("%s needs none, screen, log or both", a);
            echo = argv[++i];
            if (strcmp(echo, "none") && strcmp(echo, "screen") && strcmp(echo, "log") &&
                strcmp(echo, "both"))
                return bad("-echo must be none, screen, log or both, got '%s'", echo);
        } else if (IS("-screen", "-sc")) {
            if (!more)
                return bad("%s needs none or a file name", a);
            screen = argv[++i];
        } else if (IS("-device", NULL)) {
            if (!more || !valid_device(argv[i + 1]))
                return bad("-device must be cpu, serial, gpu or a device number, got '%s'",
                           more ? argv[i + 1] : "");
            device = argv[++i];
        } else if (IS("-precision", NULL)) {
            if (!more || (strcmp(argv[i + 1], "single") && strcmp(argv[i + 1], "double")))
                return bad("-precision must be single or double, got '%s'",
                           more ? argv[i + 1] : "");
            precision = argv[++i];
        } else if (IS("-progress", NULL)) {
            progress = 1;
        } else if (IS("-compat", NULL)) {
            if (!more || strcmp(argv[i + 1], "lammps2021"))
                return bad("-compat must be lammps2021, got '%s'", more ? argv[i + 1] : "");
            lammps2021 = 1;
            i++;
        } else {
            return bad("unknown option '%s'", a);
        }
#undef IS
    }
    /* bin/gravel runs in one process: N copies under mpirun would each run the
     * whole deck and overwrite one another's outputs. Stop every rank before any
     * file is opened; rank 0 says why (doc/parallel.md). bin/gravel-mpi starts
     * MPI here instead. */
    int rank, nranks = launcher_size(&rank);
    if (nranks > 1 && !comm_parallel_build()) {
        if (rank == 0)
            fprintf(stderr,
                    "ERROR: bin/gravel was launched as %d MPI ranks, but it is the one-process "
                    "build: run bin/gravel-mpi under mpirun (doc/parallel.md), or bin/gravel "
                    "without mpirun\n",
                    nranks);
        return 1;
    }
    rank = comm_init(&argc, &argv);
    if (rank != 0) { /* rank 0 alone writes the screen and the log */
        screen = "none";
        log = "none";
    }

    struct gravel *g = gr_create();
    if (!g) {
        fprintf(stderr, "ERROR: out of memory\n");
        return 1;
    }
    if (device)
        snprintf(g->opt.device, sizeof g->opt.device, "%s", device);
    g->opt.single = precision && strcmp(precision, "single") == 0;
    g->opt.progress = progress;
    g->opt.check = check;
    g->opt.lammps2021 = lammps2021;
    if (echo)
        g->echo = !strcmp(echo, "none") ? ECHO_NONE : !strcmp(echo, "screen") ? ECHO_SCREEN
                : !strcmp(echo, "log") ? ECHO_LOG : ECHO_BOTH;
    int rc = 0, screen_err = 0; /* screen_err outlives the -screen stream */
    const char *why = NULL;
    if (screen) {
        if (strcmp(screen, "none") == 0) {
            g->screen = NULL;
            g->opt.quiet_screen = 1;
        } else if (!(g->screen = fio_open_write_checked(screen, 0, &screen_err, &why))) {
            fprintf(stderr, "ERROR: command line: cannot open screen file '%s': %s\n", screen,
                    why);
            gr_destroy(g);
            return 1;
        }
    }
    if (strcmp(log, "none") != 0) {
        int err = gr_log_open(g, log, 0);
        if (err) {
            fprintf(stderr, "ERROR: command line: cannot open log file '%s': %s\n", log,
                    strerror(err));
            rc = 1;
        }
    }
    gr_print(g, "gravel (%s)\n", GR_VERSION);
    /* -var definitions, in order (a later -var of the same name wins) */
    for (int i = 1; i < argc && rc == 0; i++) {
        if (strcmp(argv[i], "-var") && strcmp(argv[i], "-v")) {
            if (!strcmp(argv[i], "-check") && i + 1 < argc && !is_flag(argv[i + 1]))
                i++;
            if (!strcmp(argv[i], "-in") || !strcmp(argv[i], "-i") || !strcmp(argv[i], "-log") ||
                !strcmp(argv[i], "-l") || !strcmp(argv[i], "-echo") || !strcmp(argv[i], "-e") ||
                !strcmp(argv[i], "-screen") || !strcmp(argv[i], "-sc") ||
                !strcmp(argv[i], "-device") || !strcmp(argv[i], "-precision") ||
                !strcmp(argv[i], "-compat"))
                i++;
            continue;
        }
        const char *name = argv[i + 1];
        int first = i + 2, n = 0;
        while (first + n < argc && !is_flag(argv[first + n]))
            n++;
        rc = define_var(g, name, n, argv + first);
        i = first + n - 1;
    }
    double t0 = now();
    if (rc == 0) {
        int r = in ? inp_file(g, in) : inp_stream(g, stdin, "stdin");
        rc = r == GR_ERR ? 1 : r == GR_QUIT ? inp_quit_status(g) : 0;
    }
    if (rc != 1) {
        int s = (int)(now() - t0);
        gr_print(g, "Total wall time: %d:%02d:%02d\n", s / 3600, s / 60 % 60, s % 60);
    }
    /* a log cut short (disk full) is a failed run, named with the reason */
    if (gr_log_close(g) != 0) {
        fprintf(stderr, "ERROR: %s\n", g->err.msg);
        rc = 1;
    }
    if (gr_thermolog_close(g) != 0) { /* thermo_log's file, as the log */
        fprintf(stderr, "ERROR: %s\n", g->err.msg);
        rc = 1;
    }
    if (g->screen && g->screen != stdout && (fclose(g->screen) != 0 || screen_err)) {
        /* a screen file cut short is a failed run too */
        fprintf(stderr, "ERROR: cannot write screen file '%s': %s\n", screen,
                strerror(screen_err ? screen_err : EIO));
        rc = 1;
    }
    if (g->screen != stdout) /* closed above; the profile's table goes to stderr */
        g->screen = NULL;
    if (rc == 1 && comm_size() > 1)
        rank_failed(g, rank);
    gr_destroy(g);
    comm_finalize();
    return rc;
}
