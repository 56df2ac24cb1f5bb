/* cmd_flow.c - interpreter and flow commands: variable next jump label include
 * print log echo clear quit info shell if timer run_style, and the LAMMPS
 * commands that have no meaning in gravel (accepted with one warning each).
 *
 * Handlers receive the arguments after the command name; arity and phase were
 * checked by the dispatcher (input.c), so they validate only their keywords. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "comm.h"
#include "error.h"
#include "fileio.h"
#include "gravel.h"
#include "input.h"
#include "log.h"
#include "variable.h"

/* A string variable's text is substituted at its definition, except text
 * quoted inside it (LAMMPS Variable::set, string style, since 2018; lmp
 * 29Sep2021 does). */
void cmd_variable(struct gravel *g, int argc, char **argv)
{
    if (argc == 3 && !strcmp(argv[1], "string")) {
        /* the input's scratch, valid until the next substitution (var_define
         * makes none and copies the text); nothing to free when it stops on
         * an error */
        char *a[3] = {argv[0], argv[1], (char *)inp_substitute_quoted(g, argv[2])};
        var_define(g, argc, a);
        return;
    }
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

/* thermo_log FILE [append] | thermo_log none (LIGGGHTS): the thermo header and
 * rows go to FILE as well (rank 0 writes it) */
void cmd_thermo_log(struct gravel *g, int argc, char **argv)
{
    int append = 0;
    if (argc == 2) {
        if (strcmp(argv[1], "append") != 0)
            gr_error(g, "Illegal thermo_log command: unknown keyword '%.64s' (expected append)",
                     argv[1]);
        append = 1;
    }
    if (comm_rank() != 0)
        return;
    char msg[sizeof g->err.msg];
    int err = strcmp(argv[0], "none") == 0 ? gr_thermolog_close(g)
                                           : gr_thermolog_open(g, argv[0], append);
    if (err > 0)
        gr_error(g, "Cannot open thermo log file %s: %s", argv[0], strerror(err));
    if (err < 0) {
        snprintf(msg, sizeof msg, "%s", g->err.msg);
        gr_error(g, "%s", msg);
    }
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
    if (g->in_run_every)
        gr_error(g, "cannot be used in the commands of 'run ... every': the run continues "
                    "with the simulation that clear would delete");
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
static const char *ignored[] = {"comm_modify", "communicate",
                                "newton", "package", "suffix", NULL};

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

/* ---- if / elif / else ------------------------------------------------------- */

/* LAMMPS's Boolean expressions (Variable::evaluate_boolean): operands are
 * numbers (they may start with a digit, '-' or '.') or words (a letter, then
 * letters, digits and '_'); operators, loosest first: || |^ (xor), &&,
 * == !=, < <= > >=, unary !; parentheses group. Numbers compare as numbers;
 * two words compare as strings with == and != only; anything else mixed is
 * an error. Every operator yields 1 or 0; the expression is true when its
 * value is non-zero. */
struct bval {
    int num;
    double v;
    const char *s;
    size_t n;
};

struct bparse {
    struct gravel *g;
    const char *p, *text;
};

static void bskip(struct bparse *b)
{
    while (*b->p == ' ' || *b->p == '\t' || *b->p == '\n' || *b->p == '\r')
        b->p++;
}

static int bop(struct bparse *b, const char *op)
{
    bskip(b);
    size_t n = strlen(op);
    if (strncmp(b->p, op, n) != 0)
        return 0;
    /* '<' must not take the first char of '<=' etc.; '!' not of '!=' */
    if (n == 1 && (op[0] == '<' || op[0] == '>' || op[0] == '!') && b->p[1] == '=')
        return 0;
    b->p += n;
    return 1;
}

static struct bval b_or(struct bparse *b);

static double bnum(struct bparse *b, struct bval v, const char *op)
{
    if (!v.num)
        gr_error(b->g, "if: operator %s needs numbers, got the word '%.*s' in \"%s\"", op,
                 (int)v.n, v.s, b->text);
    return v.v;
}

static struct bval bmake(double x)
{
    struct bval r = {1, x, NULL, 0};
    return r;
}

static struct bval b_primary(struct bparse *b)
{
    bskip(b);
    const char *p = b->p;
    if (*p == '(') {
        b->p++;
        struct bval v = b_or(b);
        if (!bop(b, ")"))
            gr_error(b->g, "if: missing ')' in \"%s\"", b->text);
        return v;
    }
    if (isdigit((unsigned char)*p) || *p == '-' || *p == '.') {
        char *end;
        errno = 0;
        double x = strtod(p, &end);
        if (end == p)
            gr_error(b->g, "if: invalid number at '%.20s' in \"%s\"", p, b->text);
        b->p = end;
        return bmake(x);
    }
    if (isalpha((unsigned char)*p)) {
        const char *q = p + 1;
        while (isalnum((unsigned char)*q) || *q == '_')
            q++;
        b->p = q;
        struct bval v = {0, 0, p, (size_t)(q - p)};
        return v;
    }
    if (!*p)
        gr_error(b->g, "if: the Boolean expression \"%s\" ends where an operand is expected",
                 b->text);
    gr_error(b->g, "if: unexpected '%.20s' in the Boolean expression \"%s\"", p, b->text);
}

static struct bval b_unary(struct bparse *b)
{
    if (bop(b, "!"))
        return bmake(bnum(b, b_unary(b), "!") == 0.0);
    return b_primary(b);
}

static struct bval b_rel(struct bparse *b)
{
    struct bval l = b_unary(b);
    for (;;) {
        const char *op = bop(b, "<=") ? "<=" : bop(b, ">=") ? ">=" : bop(b, "<") ? "<"
                       : bop(b, ">") ? ">" : NULL;
        if (!op)
            return l;
        double x = bnum(b, l, op), y = bnum(b, b_unary(b), op);
        l = bmake(op[0] == '<' ? (op[1] ? x <= y : x < y) : (op[1] ? x >= y : x > y));
    }
}

static struct bval b_eq(struct bparse *b)
{
    struct bval l = b_rel(b);
    for (;;) {
        int eq = bop(b, "==");
        if (!eq && !bop(b, "!="))
            return l;
        struct bval r = b_rel(b);
        int same;
        if (l.num && r.num)
            same = l.v == r.v;
        else if (!l.num && !r.num)
            same = l.n == r.n && strncmp(l.s, r.s, l.n) == 0;
        else
            gr_error(b->g, "if: cannot compare a number with a word in \"%s\"", b->text);
        l = bmake(eq ? same : !same);
    }
}

static struct bval b_and(struct bparse *b)
{
    struct bval l = b_eq(b);
    while (bop(b, "&&")) {
        double x = bnum(b, l, "&&"), y = bnum(b, b_eq(b), "&&");
        l = bmake(x != 0.0 && y != 0.0);
    }
    return l;
}

static struct bval b_or(struct bparse *b)
{
    struct bval l = b_and(b);
    for (;;) {
        int xr = 0;
        if (!bop(b, "||") && !(xr = bop(b, "|^")))
            return l;
        const char *op = xr ? "|^" : "||";
        double x = bnum(b, l, op), y = bnum(b, b_and(b), op);
        l = bmake(xr ? ((x != 0.0) != (y != 0.0)) : (x != 0.0 || y != 0.0));
    }
}

/* Substitute variables in a condition (it was quoted, so the reader left
 * them) and evaluate it. */
static int if_test(struct gravel *g, const char *cond)
{
    char *text = gr_strdup(g, inp_substitute(g, cond));
    jmp_buf *outer = g->err.jmp, here;
    g->err.jmp = &here;
    if (setjmp(here)) {
        free(text);
        g->err.jmp = outer;
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    struct bparse b = {g, text, text};
    struct bval v = b_or(&b);
    bskip(&b);
    if (*b.p)
        gr_error(g, "if: unexpected '%.20s' after the Boolean expression \"%s\"", b.p, text);
    if (!v.num)
        gr_error(g, "if: the Boolean expression \"%s\" is a word, not a test", text);
    g->err.jmp = outer;
    free(text);
    return v.v != 0.0;
}

/* Run argv[first..last] as commands, copied first: running a command reuses
 * the reader's buffers that argv points into. */
static void if_run(struct gravel *g, int argc, char **argv, int first, int last)
{
    (void)argc;
    int n = last - first + 1;
    if (n <= 0)
        gr_error(g, "if: no command after '%s'", argv[first - 1]);
    for (int i = first; i <= last; i++)
        if (!argv[i][0])
            gr_error(g, "if: empty command (argument %d)", i + 1);
    inp_run_commands(g, n, argv + first);
}

static int if_block_end(int argc, char **argv, int i)
{
    while (i < argc && strcmp(argv[i], "elif") && strcmp(argv[i], "else"))
        i++;
    return i;
}

/* if "cond" then "cmd" ... [elif "cond" "cmd" ...]... [else "cmd" ...]
 * (LAMMPS if): the first branch whose condition holds runs its commands, in
 * order, as if they were script lines here (so `jump SELF label` and `quit`
 * work from inside). */
/* The branch structure, checked before any condition or command runs
 * (LAMMPS errors on it too): nothing may follow the 'else' branch but its commands. */
static void if_check_branches(struct gravel *g, int argc, char **argv)
{
    int seen_else = 0;
    for (int i = 2; i < argc; i++) {
        if (strcmp(argv[i], "elif") && strcmp(argv[i], "else"))
            continue;
        if (seen_else)
            gr_error(g, "'%s' after 'else' (argument %d): 'else' must be the last branch",
                     argv[i], i + 1);
        if (!strcmp(argv[i], "else"))
            seen_else = 1;
        else
            i++; /* the elif condition */
    }
}

void cmd_if(struct gravel *g, int argc, char **argv)
{
    if (strcmp(argv[1], "then") != 0)
        gr_error(g, "expected: if \"condition\" then \"command\" ..., got '%.64s' after the "
                    "condition", argv[1]);
    if_check_branches(g, argc, argv);
    int first = 2, end = if_block_end(argc, argv, first);
    if (end == first)
        gr_error(g, "if: no command after 'then'");
    if (if_test(g, argv[0])) {
        if_run(g, argc, argv, first, end - 1);
        return;
    }
    int i = end;
    while (i < argc) {
        int take;
        if (!strcmp(argv[i], "elif")) {
            if (i + 2 >= argc)
                gr_error(g, "if: 'elif' needs a condition and at least one command");
            take = if_test(g, argv[i + 1]);
            first = i + 2;
        } else {
            if (i + 1 >= argc)
                gr_error(g, "if: no command after 'else'");
            take = 1;
            first = i + 1;
        }
        end = if_block_end(argc, argv, first);
        if (end == first)
            gr_error(g, "if: no command after '%s'", argv[first - 1]);
        if (take) {
            if_run(g, argc, argv, first, end - 1);
            return;
        }
        i = end;
    }
}

/* ---- timer, run_style --------------------------------------------------------- */

/* timer [off|loop|normal|full] [sync|nosync] [timeout T|off] [every N]: LAMMPS
 * timer settings. gravel always prints its timing breakdown and has no
 * wall-time limit, so the keywords are checked and then ignored (one
 * warning). */
void cmd_timer(struct gravel *g, int argc, char **argv)
{
    for (int i = 0; i < argc; i++) {
        const char *k = argv[i];
        if (!strcmp(k, "off") || !strcmp(k, "loop") || !strcmp(k, "normal") ||
            !strcmp(k, "full") || !strcmp(k, "sync") || !strcmp(k, "nosync"))
            continue;
        if (!strcmp(k, "timeout")) {
            arg_need(g, argc, i, 1, k);
            i++;
        } else if (!strcmp(k, "every")) {
            arg_need(g, argc, i, 1, k);
            arg_int_range(g, argv[++i], 1, 1 << 30, "timeout check interval");
        } else {
            gr_error(g, "unknown keyword '%.64s' (expected off, loop, normal, full, sync, "
                        "nosync, timeout or every)", k);
        }
    }
    static int warned;
    if (!warned++)
        gr_warn(g, "ignored: gravel always reports its timing breakdown and has no run "
                   "timeout");
}

/* run_style verlet: the only integrator loop gravel has (velocity Verlet
 * split into initial/final integrate, as LAMMPS's verlet). */
void cmd_run_style(struct gravel *g, int argc, char **argv)
{
    if (strcmp(argv[0], "verlet") != 0)
        gr_error(g, "run_style %s is not supported: gravel has only run_style verlet",
                 argv[0]);
    if (argc > 1)
        gr_error(g, "run_style verlet takes no arguments, got '%.64s'", argv[1]);
}
