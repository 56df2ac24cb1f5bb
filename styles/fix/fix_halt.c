/* fix_halt.c - `fix ID group halt N attribute operator avalue [error hard|soft|continue]
 * [message yes|no] [path P] [universe yes|no]`: LAMMPS's fix halt (2021).
 * Every N steps (end_of_step at multiples of N) the attribute, v_name (an
 * equal-style variable), tlimit (wall seconds since the run's setup ended)
 * or diskfree (MB free to the user on the file system of `path`, default
 * "."), is compared with avalue (<, <=, >, >=, ==, !=, |^: exactly one of
 * the two is zero). When the condition holds: error hard stops the script
 * with an error; soft (the default) and continue print "Fix halt condition
 * for fix-id ID met on step S with value V" (unless message no) and end the
 * run after this step (its output as scheduled, the "Loop time" of the
 * steps made); after soft every later run of the script is skipped, after
 * continue later runs go on (struct gravel's halt, src/engine/run.c).
 * On MPI ranks tlimit and diskfree are rank 0's. bondmax is refused
 * (gravel has no bonds); universe has one partition here.
 * The group is not used. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/statvfs.h>

#include "args.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "log.h"
#include "par.h"
#include "variable.h"
#include "wall_clock.h"


enum attribute { ATT_VARIABLE, ATT_TLIMIT, ATT_DISKFREE };
enum op { OP_LT, OP_LE, OP_GT, OP_GE, OP_EQ, OP_NE, OP_XOR };

struct halt {
    int every;
    enum attribute att;
    char *var;          /* v_name's name */
    enum op op;
    double value;
    int eflag;          /* HALT_SOFT, HALT_CONTINUE, or 0: hard */
    int message;
    char *path;         /* diskfree's file system */
    double t0;          /* tlimit's origin: the end of the run's setup */
};

static void destroy(struct fix *f)
{
    struct halt *h = f->data;
    if (!h)
        return;
    free(h->var);
    free(h->path);
    free(h);
}

static enum op parse_op(struct gravel *g, const char *s)
{
    static const char *const name[] = {"<", "<=", ">", ">=", "==", "!=", "|^"};
    for (int k = 0; k < 7; k++)
        if (!strcmp(s, name[k]))
            return (enum op)k;
    gr_error(g, "fix halt: invalid operator '%.16s' (expected <, <=, >, >=, ==, != or |^)", s);
    return OP_LT;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, "fix halt expects N attribute operator avalue [error hard|soft|continue] "
                    "[message yes|no] [path P] [universe yes|no]");
    struct halt *h = gr_calloc(g, 1, sizeof *h);
    f->data = h;
    h->every = arg_int(g, argv[0], "N");
    if (h->every <= 0)
        gr_error(g, "fix halt: N must be positive, got %d", h->every);
    const char *a = argv[1];
    if (!strcmp(a, "tlimit")) {
        h->att = ATT_TLIMIT;
    } else if (!strcmp(a, "diskfree")) {
        h->att = ATT_DISKFREE;
    } else if (!strcmp(a, "bondmax")) {
        gr_error(g, "fix halt: attribute bondmax needs bonds, which gravel does not have");
    } else if (a[0] == 'v' && a[1] == '_' && a[2] && strlen(a + 2) < GR_NAMELEN) {
        h->att = ATT_VARIABLE;
        h->var = gr_strdup(g, a + 2);
    } else {
        gr_error(g, "fix halt: invalid attribute '%.64s' (expected tlimit, diskfree or v_name)",
                 a);
    }
    h->op = parse_op(g, argv[2]);
    h->value = arg_double(g, argv[3], "avalue");
    h->eflag = HALT_SOFT;
    h->message = 1;
    for (int i = 4; i < argc; i += 2) {
        const char *k = argv[i];
        arg_need(g, argc, i, 1, k);
        const char *v = argv[i + 1];
        if (!strcmp(k, "error")) {
            if (!strcmp(v, "hard"))
                h->eflag = 0;
            else if (!strcmp(v, "soft"))
                h->eflag = HALT_SOFT;
            else if (!strcmp(v, "continue"))
                h->eflag = HALT_CONTINUE;
            else
                gr_error(g, "fix halt: error must be hard, soft or continue, got '%.32s'", v);
        } else if (!strcmp(k, "message")) {
            h->message = arg_yesno(g, v, "message");
        } else if (!strcmp(k, "path")) {
            free(h->path);
            h->path = gr_strdup(g, v);
        } else if (!strcmp(k, "universe")) {
            (void)arg_yesno(g, v, "universe"); /* one partition: the same either way */
        } else {
            gr_error(g, "fix halt: unknown keyword '%.64s' (expected error, message, path or "
                        "universe)", k);
        }
    }
    f->hooks = HOOK_END_OF_STEP;
}

static void init(struct gravel *g, struct fix *f)
{
    const struct halt *h = f->data;
    if (h->att != ATT_VARIABLE)
        return;
    if (!var_exists(g, h->var))
        gr_error(g, "fix halt %s: variable '%s' does not exist", f->id, h->var);
    if (!var_is_equal(g, h->var))
        gr_error(g, "fix halt %s: variable '%s' is not equal-style", f->id, h->var);
}

static void setup(struct gravel *g, struct fix *f)
{
    (void)g;
    struct halt *h = f->data;
    h->t0 = wall_clock();
}

/* MB available to the user on the file system of path (LAMMPS's diskfree) */
static double disk_free(struct gravel *g, struct fix *f, const char *path)
{
    struct statvfs s;
    if (statvfs(path, &s) != 0)
        gr_error(g, "fix halt %s: cannot read the free space of '%s'", f->id, path);
    return (double)s.f_bavail * (double)s.f_frsize / 1048576.0;
}

/* v as fmt's "{}" writes a double: the fewest digits that read back as v,
 * fixed for 1e-4 <= |v| < 1e16, else with an exponent (LAMMPS's message) */
static void format_shortest(double v, char *buf, size_t n)
{
    if (!isfinite(v) || v == 0.0) {
        snprintf(buf, n, "%g", v);
        return;
    }
    int p = 1;
    char e[40];
    for (; p < 17; p++) {
        snprintf(e, sizeof e, "%.*e", p - 1, v);
        if (strtod(e, NULL) == v)
            break;
    }
    snprintf(e, sizeof e, "%.*e", p - 1, v);
    const int exp10 = atoi(strchr(e, 'e') + 1);
    if (exp10 >= -4 && exp10 < 16) {
        const int dec = p - 1 - exp10;
        snprintf(buf, n, "%.*f", dec > 0 ? dec : 0, v);
    } else {
        char mant[32];
        snprintf(mant, sizeof mant, "%.*e", p - 1, v);
        *strchr(mant, 'e') = '\0';
        snprintf(buf, n, "%se%c%02d", mant, exp10 < 0 ? '-' : '+', abs(exp10));
    }
}

static int met(enum op op, double a, double b)
{
    switch (op) {
    case OP_LT: return a < b;
    case OP_LE: return a <= b;
    case OP_GT: return a > b;
    case OP_GE: return a >= b;
    case OP_EQ: return a == b;
    case OP_NE: return a != b;
    case OP_XOR: return (a == 0.0) != (b == 0.0);
    }
    return 0;
}

static void end_of_step(struct gravel *g, struct fix *f)
{
    struct halt *h = f->data;
    if (g->step % h->every)
        return;
    double v = h->att == ATT_VARIABLE ? var_compute_equal(g, h->var)
             : h->att == ATT_TLIMIT   ? wall_clock() - h->t0
                                      : disk_free(g, f, h->path ? h->path : ".");
    if (h->att != ATT_VARIABLE && par_on(g))
        comm_bcast(&v, sizeof v); /* rank 0's clock and disk: every rank halts alike */
    if (!met(h->op, v, h->value))
        return;
    char val[48];
    format_shortest(v, val, sizeof val);
    if (!h->eflag)
        gr_error(g, "Fix halt condition for fix-id %s met on step %lld with value %s", f->id,
                 (long long)g->step, val);
    if (h->message)
        gr_print(g, "Fix halt condition for fix-id %s met on step %lld with value %s\n", f->id,
                 (long long)g->step, val);
    if (g->halt != HALT_SOFT)
        g->halt = h->eflag;
}

const struct fix_style fix_style_halt = {
    .name = "halt",
    .create = create,
    .init = init,
    .setup = setup,
    .end_of_step = end_of_step,
    .destroy = destroy,
};
