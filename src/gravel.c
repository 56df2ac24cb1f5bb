/* gravel.c - creation, defaults, `clear` and destruction of a simulation. */
#include "gravel.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "error.h"
#include "fileio.h"
#include "input.h"
#include "molecule.h"
#include "restart.h"
#include "run.h"
#include "styles.h"
#include "variable.h"

void gr_unit_defaults(struct gravel *g)
{
    switch (g->dom.units) {
    case UNITS_LJ: g->dt = 0.005; g->neigh.skin = 0.3; break;
    case UNITS_SI: g->dt = 1e-8; g->neigh.skin = 0.001; break;
    case UNITS_CGS: g->dt = 1e-8; g->neigh.skin = 0.1; break;
    }
    g->thermo.norm = g->dom.units == UNITS_LJ;
}

static void set_defaults(struct gravel *g)
{
    g->dom.units = UNITS_LJ;
    g->dom.dimension = 3;
    for (int d = 0; d < 3; d++) {
        g->dom.bnd[d][0] = g->dom.bnd[d][1] = BND_P;
        g->dom.periodic[d] = 1;
        g->dom.lat.a[d] = 1.0;
    }
    g->neigh.every = 1;
    g->neigh.delay = 0;
    g->neigh.check = 1;
    g->neigh.one = 2000;
    g->neigh.page = 100000;
    g->neigh.style = NEIGH_BIN;
    g->neigh.sort_every = -1;
    g->thermo.lost = LOST_ERROR;
    g->thermo.temp.kind = TEMP_TRANS; /* thermo_temp: compute temp of group all */
    g->thermo.temp.groupbit = 1u;
    g->groups.n = 1;
    g->groups.used[0] = 1;
    strcpy(g->groups.name[0], "all");
    gr_unit_defaults(g);
}

struct gravel *gr_create(void)
{
    struct gravel *g = calloc(1, sizeof *g);
    if (!g)
        return NULL;
    g->screen = stdout;
    g->echo = ECHO_LOG;
    g->vars = var_create();
    g->inp = inp_create();
    set_defaults(g);
    return g;
}

static void free_state(struct gravel *g)
{
    engine_destroy(g);
    restart_free(g);
    styles_free(g);
    regions_free(g);
    atoms_free(&g->atoms);
    molecules_free(g);
    thermo_settings_free(&g->thermo);
}

void gr_clear(struct gravel *g)
{
    struct gravel keep = *g;
    free_state(g);
    memset(g, 0, sizeof *g);
    g->opt = keep.opt;
    g->err = keep.err;
    g->inp = keep.inp;
    g->vars = keep.vars;
    g->screen = keep.screen;
    g->logfile = keep.logfile;
    g->logname = keep.logname;
    g->logerr = keep.logerr;
    g->echo = keep.echo;
    set_defaults(g);
}

static void log_forget(struct gravel *g)
{
    free(g->logname);
    free(g->logerr);
    g->logname = NULL;
    g->logerr = NULL;
}

void gr_destroy(struct gravel *g)
{
    if (!g)
        return;
    free_state(g);
    var_destroy(g->vars);
    inp_destroy(g->inp);
    if (g->logfile)
        fclose(g->logfile);
    log_forget(g);
    free(g);
}

/* Close the log; 0 if it and every write to it succeeded, else the errno. */
static int log_close(struct gravel *g)
{
    int err = 0;
    if (g->logfile) {
        int bad = ferror(g->logfile) || (g->logerr && *g->logerr);
        if (fclose(g->logfile) != 0)
            bad = 1;
        if (bad)
            err = g->logerr && *g->logerr ? *g->logerr : EIO;
    }
    g->logfile = NULL;
    return err;
}

static void log_message(struct gravel *g, int err)
{
    snprintf(g->err.msg, sizeof g->err.msg, "cannot write log file '%.200s': %s",
             g->logname ? g->logname : "(log)", strerror(err));
}

int gr_log_close(struct gravel *g)
{
    int err = log_close(g);
    if (err)
        log_message(g, err);
    log_forget(g);
    return err ? -1 : 0;
}

int gr_log_open(struct gravel *g, const char *path, int append)
{
    const char *why;
    char *name = strdup(path);
    int *slot = malloc(sizeof *slot);
    if (!name || !slot) {
        free(name);
        free(slot);
        return ENOMEM;
    }
    FILE *fp = fio_open_write_checked(path, append, slot, &why);
    if (!fp) {
        int err = errno ? errno : EIO;
        free(name);
        free(slot);
        return err;
    }
    int bad = gr_log_close(g); /* the previous log, checked */
    g->logfile = fp;
    g->logname = name;
    g->logerr = slot;
    return bad;
}

void gr_log_check(struct gravel *g)
{
    if (!g->logfile)
        return;
    int err = g->logerr ? *g->logerr : 0;
    if (!err && !ferror(g->logfile))
        return;
    char *name = g->logname ? strdup(g->logname) : NULL;
    if (gr_log_close(g) == 0) { /* cannot happen: an error was seen */
        snprintf(g->err.msg, sizeof g->err.msg, "cannot write log file '%.200s': %s",
                 name ? name : "(log)", strerror(err ? err : EIO));
    }
    free(name);
    /* g->err.msg holds the message; raise it with the command's context */
    char msg[sizeof g->err.msg];
    snprintf(msg, sizeof msg, "%s", g->err.msg);
    gr_error(g, "%s", msg);
}
void gr_print(struct gravel *g, const char *fmt, ...)
{
    va_list ap;
    if (g->screen) {
        va_start(ap, fmt);
        vfprintf(g->screen, fmt, ap);
        va_end(ap);
    }
    if (g->logfile) {
        va_start(ap, fmt);
        vfprintf(g->logfile, fmt, ap);
        va_end(ap);
    }
}
