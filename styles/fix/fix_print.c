/* fix_print.c - `fix ID group print N string [file F | append F] [screen
 * yes|no] [title T]`: LAMMPS's fix print (2021). Every N steps (at
 * end_of_step, and at a run's setup when its first step is a multiple of
 * N), the string with its variables substituted ($x, ${name}, $(expr), as
 * the print command) goes to the screen and log (screen yes) and to the
 * file, which is opened when the fix is defined and begins with the title
 * line ("# Fix print output for fix ID" unless `title`). N may be v_name,
 * an equal-style variable giving the step of the next print (LAMMPS: the
 * first one evaluated at the run's setup, each next after a print; a value
 * not after the step is an error). The group is not used. On MPI ranks the
 * string is substituted over every rank's atoms gathered (as fix ave/time's
 * variables), printed and written by rank 0. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "ave_common.h"
#include "error.h"
#include "fix.h"
#include "input.h"
#include "log.h"
#include "par.h"
#include "thermo.h"
#include "variable.h"

#define WHO "fix print"

struct print {
    int every;          /* N, or 0 with var */
    char *var;          /* v_name's name, else NULL */
    char *text;
    int screen;
    struct ave_file af; /* af.fp NULL: no file */
    bigint next;        /* the step of the next print */
};

static void destroy(struct fix *f)
{
    struct print *p = f->data;
    if (!p)
        return;
    ave_file_close(&p->af);
    free(p->var);
    free(p->text);
    free(p);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, "fix print expects N string [file F | append F] [screen yes|no] [title T]");
    struct print *p = gr_calloc(g, 1, sizeof *p);
    f->data = p;
    p->screen = 1;
    if (argv[0][0] == 'v' && argv[0][1] == '_') {
        if (!argv[0][2] || strlen(argv[0] + 2) >= GR_NAMELEN)
            gr_error(g, "fix print: v_name needs a variable name, got '%.64s'", argv[0]);
        p->var = gr_strdup(g, argv[0] + 2);
    } else {
        p->every = arg_int(g, argv[0], "N");
        if (p->every <= 0)
            gr_error(g, "fix print: N must be positive, got %d", p->every);
    }
    p->text = gr_strdup(g, argv[1]);
    const char *file = NULL, *title = NULL;
    int append = 0;
    for (int i = 2; i < argc; i += 2) {
        const char *k = argv[i];
        if (strcmp(k, "file") && strcmp(k, "append") && strcmp(k, "screen") &&
            strcmp(k, "title"))
            gr_error(g, "fix print: unknown keyword '%.64s' (expected file, append, screen or "
                        "title; quote a string that contains spaces)", k);
        arg_need(g, argc, i, 1, k);
        if (!strcmp(k, "screen")) {
            p->screen = arg_yesno(g, argv[i + 1], "screen");
        } else if (!strcmp(k, "title")) {
            title = argv[i + 1];
        } else {
            file = argv[i + 1];
            append = k[0] == 'a';
        }
    }
    if (file) {
        ave_file_open(g, &p->af, file, append, WHO);
        if (title)
            fprintf(p->af.fp, "%s\n", title);
        else
            fprintf(p->af.fp, "# Fix print output for fix %s\n", f->id);
        ave_file_header_done(g, &p->af, WHO);
    }
    f->hooks = HOOK_END_OF_STEP;
}

/* The step of the next print after `step` (v_name: the variable's value) */
static bigint next_print(struct gravel *g, struct fix *f, bigint step)
{
    struct print *p = f->data;
    if (!p->var)
        return (step / p->every) * p->every + p->every;
    char who[GR_NAMELEN + 32];
    snprintf(who, sizeof who, "fix %s print: variable", f->id);
    return var_next_step(g, p->var, step, who);
}

static void print_now(struct gravel *g, struct fix *f)
{
    struct print *p = f->data;
    if (g->step != p->next)
        return;
    thermo_pre_take(g); /* several ranks: the keywords a gathered pass cannot take */
    par_gather_begin(g); /* several ranks: every rank's atoms, as one process */
    const char *text = inp_substitute(g, p->text);
    if (p->screen)
        gr_print(g, "%s\n", text);
    if (p->af.fp) {
        ave_file_begin(&p->af);
        fprintf(p->af.fp, "%s\n", text);
        ave_file_end(g, &p->af, WHO, f->id);
    }
    p->next = next_print(g, f, g->step);
    par_gather_end(g);
    thermo_pre_clear(g);
}

/* LAMMPS's setup: the first print is due at the run's first step when it is
 * a multiple of N (v_name: the variable's first value, never this step) */
static void setup(struct gravel *g, struct fix *f)
{
    struct print *p = f->data;
    if (p->var) {
        thermo_pre_take(g);
        par_gather_begin(g);
        p->next = next_print(g, f, g->step);
        par_gather_end(g);
        thermo_pre_clear(g);
    } else
        p->next = g->step % p->every ? next_print(g, f, g->step) : g->step;
    print_now(g, f);
}

const struct fix_style fix_style_print = {
    .name = "print",
    .flags = FIX_OUTPUT,
    .create = create,
    .setup = setup,
    .end_of_step = print_now,
    .destroy = destroy,
};
