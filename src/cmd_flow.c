/* cmd_flow.c - interpreter and flow commands: variable next jump label include
 * print log echo clear quit info shell, and the LAMMPS commands that have no
 * meaning in gravel (accepted with one warning each).
 *
 * Handlers receive the arguments after the command name; arity and phase were
 * checked by the dispatcher (input.c), so they validate only their keywords. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "error.h"
#include "fileio.h"
#include "input.h"
#include "variable.h"

void cmd_variable(struct gravel *g, int argc, char **argv)
{
    var_define(g, argc, argv);
}

/* next V1 V2 ...: advance each; an exhausted variable is deleted and the next
 * jump is skipped, which ends a `label`/`next`/`jump SELF` loop. */
void cmd_next(struct gravel *g, int argc, char **argv)
{
    int done = 0;
    for (int i = 0; i < argc; i++)
        done |= var_next(g, argv[i]);
    if (done)
        inp_skip_next_jump(g);
}

void cmd_jump(struct gravel *g, int argc, char **argv)
{
    inp_jump(g, argv[0], argc > 1 ? argv[1] : NULL);
}

void cmd_label(struct gravel *g, int argc, char **argv)
{
    (void)g; (void)argc; (void)argv; /* a marker for jump; nothing to do when run */
}

void cmd_include(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    inp_include(g, argv[0]);
}

/* print TEXT [file F] [append F] [screen yes|no] */
void cmd_print(struct gravel *g, int argc, char **argv)
{
    const char *file = NULL;
    int append = 0, screen = 1;
    for (int i = 1; i < argc; i += 2) {
        const char *k = argv[i];
        if (strcmp(k, "file") && strcmp(k, "append") && strcmp(k, "screen"))
            gr_error(g, "unknown keyword '%.64s' (expected file, append or screen; quote text "
                     "that contains spaces)", k);
        arg_need(g, argc, i, 1, k);
        if (strcmp(k, "screen") == 0) {
            screen = arg_yesno(g, argv[i + 1], "screen");
        } else {
            file = argv[i + 1];
            append = k[0] == 'a';
        }
    }
    const char *text = inp_substitute(g, argv[0]);
    if (file) {
        /* the whole line in one write; a failed write leaves no partial line */
        size_t n = strlen(text);
        char *line = gr_malloc(g, n + 2);
        memcpy(line, text, n);
        line[n] = '\n';
        line[n + 1] = '\0';
        int opened;
        int err = fio_append_whole(file, append, line, n + 1, &opened);
        free(line);
        if (err && !opened)
            gr_error(g, "cannot open '%s' for writing: %s", file, strerror(err));
        if (err)
            gr_error(g, "cannot write '%s': %s", file, strerror(err));
    }
    if (screen && g->screen) {
        fprintf(g->screen, "%s\n", text);
        fflush(g->screen);
    }
    if (g->logfile)
        fprintf(g->logfile, "%s\n", text);
}

/* log FILE [append] | log none */
void cmd_log(struct gravel *g, int argc, char **argv)
{
    int append = 0;
    if (argc == 2) {
        if (strcmp(argv[1], "append") != 0)
            gr_error(g, "unknown keyword '%.64s' (expected append)", argv[1]);
        append = 1;
    }
    /* the previous log is closed checked: a failed write to it is an error */
    char msg[sizeof g->err.msg];
    if (strcmp(argv[0], "none") == 0) {
        if (gr_log_close(g) != 0) {
            snprintf(msg, sizeof msg, "%s", g->err.msg);
            gr_error(g, "%s", msg);
        }
        return;
    }
    int err = gr_log_open(g, argv[0], append);
    if (err > 0)
        gr_error(g, "cannot open log file '%s': %s", argv[0], strerror(err));
    if (err < 0) {
        snprintf(msg, sizeof msg, "%s", g->err.msg);
        gr_error(g, "%s", msg);
    }
    fprintf(g->logfile, "gravel (%s)\n", GR_VERSION);
}

void cmd_echo(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    static const char *names[] = {"none", "screen", "log", "both"};
    for (int i = 0; i < 4; i++)
        if (strcmp(argv[0], names[i]) == 0) {
            g->echo = (enum echo_mode)i;
            return;
        }
    gr_error(g, "expected none, screen, log or both, got '%.64s'", argv[0]);
}

void cmd_clear(struct gravel *g, int argc, char **argv)
{
    (void)argc; (void)argv;
    gr_clear(g);
}

void cmd_quit(struct gravel *g, int argc, char **argv)
{
    int status = argc ? arg_int_range(g, argv[0], 0, 255, "exit status") : 0;
    inp_quit(g, status);
}

void cmd_shell(struct gravel *g, int argc, char **argv)
{
    (void)argc; (void)argv;
    gr_error(g, "not supported: gravel does not run shell commands from scripts");
}

static void info_system(struct gravel *g)
{
    static const char *units[] = {"lj", "si", "cgs"};
    const struct domain *d = &g->dom;
    gr_print(g, "gravel (%s)\n", GR_VERSION);
    gr_print(g, "Units: %s  Dimension: %d  Timestep: %g\n", units[d->units], d->dimension, g->dt);
    gr_print(g, "Boundary: %c%c %c%c %c%c\n", d->bnd[0][0], d->bnd[0][1], d->bnd[1][0],
             d->bnd[1][1], d->bnd[2][0], d->bnd[2][1]);
    if (d->box_exists)
        gr_print(g, "Box: (%g %g %g) to (%g %g %g)\n", d->lo[0], d->lo[1], d->lo[2], d->hi[0],
                 d->hi[1], d->hi[2]);
    else
        gr_print(g, "Box: not yet created\n");
    gr_print(g, "Atoms: %d  Atom types: %d\n", g->atoms.n, g->atoms.ntypes);
    gr_print(g, "Step: %lld  Time: %g\n", (long long)g->step, g->time);
}

static void info_groups(struct gravel *g)
{
    int n = 0;
    for (int i = 0; i < GR_MAXGROUP; i++)
        n += g->groups.used[i] != 0;
    gr_print(g, "Groups: %d\n", n);
    for (int i = 0; i < GR_MAXGROUP; i++)
        if (g->groups.used[i]) {
            int count = 0;
            for (int k = 0; k < g->atoms.n; k++)
                count += (g->atoms.mask[k] >> i) & 1u;
            gr_print(g, "  %s (%d atoms)\n", g->groups.name[i], count);
        }
}

static void info_styles(struct gravel *g)
{
    gr_print(g, "Regions: %d\n", g->regions.n);
    gr_print(g, "Pair style: %s\n", g->styles.pair ? "defined" : "none");
    gr_print(g, "Fixes: %d  Computes: %d  Dumps: %d\n", g->styles.nfix, g->styles.ncompute,
             g->styles.ndump);
}

/* info [all|system|groups|styles|variables] ... */
void cmd_info(struct gravel *g, int argc, char **argv)
{
    int sys = 0, grp = 0, sty = 0, var = 0;
    if (argc == 0)
        sys = grp = sty = var = 1;
    for (int i = 0; i < argc; i++) {
        const char *k = argv[i];
        if (!strcmp(k, "all"))
            sys = grp = sty = var = 1;
        else if (!strcmp(k, "system"))
            sys = 1;
        else if (!strcmp(k, "groups"))
            grp = 1;
        else if (!strcmp(k, "styles"))
            sty = 1;
        else if (!strcmp(k, "variables"))
            var = 1;
        else
            gr_error(g, "unknown category '%.64s' (expected all, system, groups, styles or "
                     "variables)", k);
    }
    gr_print(g, "Info-Info-Info-Info-Info-Info-Info-Info-Info-Info-Info\n");
    if (sys)
        info_system(g);
    if (grp)
        info_groups(g);
    if (sty)
        info_styles(g);
    if (var)
        var_print_all(g);
    gr_print(g, "Info-Info-Info-Info-Info-Info-Info-Info-Info-Info-Info\n");
}

/* LAMMPS commands about parallel layout, Newton's 3rd law bookkeeping or
 * accelerator packages: they change nothing here, so one warning each. */
static const char *ignored[] = {"atom_modify", "comm_modify", "communicate", "newton",
                                "package", "processors", "suffix", NULL};

void cmd_ignored(struct gravel *g, int argc, char **argv)
{
    (void)argc; (void)argv;
    const char *name = g->err.cmd ? g->err.cmd : "";
    for (int i = 0; ignored[i]; i++)
        if (strcmp(name, ignored[i]) == 0) {
            if (!g->warned_ignored[i]++)
                gr_warn(g, "ignored: this LAMMPS command has no meaning in gravel");
            return;
        }
}
