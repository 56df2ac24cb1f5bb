/* gravel.c - creation, defaults, `clear` and destruction of a simulation. */
#include "gravel.h"
#include "par.h"

#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "engine.h"
#include "error.h"
#include "input.h"
#include "molecule.h"
#include "region.h"
#include "restart.h"
#include "style.h"
#include "thermo.h"
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
    g->run_start = g->run_stop = -1; /* no `run ... start/stop` pending */
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
    par_free(g); /* `clear` forgets the processor grid too, as LAMMPS */
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
    g->thermolog = keep.thermolog;
    g->thermologname = keep.thermologname;
    g->thermologerr = keep.thermologerr;
    g->echo = keep.echo;
    set_defaults(g);
}

void gr_destroy(struct gravel *g)
{
    if (!g)
        return;
    free_state(g);
    var_destroy(g->vars);
    inp_destroy(g->inp);
    gr_log_release(g);
    free(g);
}
