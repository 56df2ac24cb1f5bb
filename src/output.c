/* output.c - PLACEHOLDER thermo output until the output module lands:
 * prints step and atom count only. Replaced wholesale by the output owner. */
#include "output.h"

#include <string.h>

void output_setup(struct gravel *g) { gr_print(g, "Step Atoms\n"); output_step(g); }

int output_due(struct gravel *g, bigint step)
{
    int every = g->thermo.every;
    return step == g->laststep || (every > 0 && step % every == 0);
}

void output_step(struct gravel *g)
{
    if (output_due(g, g->step))
        gr_print(g, "%8lld %8d\n", (long long)g->step, g->atoms.n);
}

void output_finish(struct gravel *g, const struct run_stats *st)
{
    gr_print(g, "Loop time of %g on 1 procs for %lld steps with %d atoms\n", st->t_total,
             (long long)st->nsteps, st->natoms);
}

int thermo_keyword_value(struct gravel *g, const char *name, double *out)
{
    if (strcmp(name, "step") == 0)
        *out = (double)g->step;
    else if (strcmp(name, "atoms") == 0)
        *out = g->atoms.n;
    else if (strcmp(name, "dt") == 0)
        *out = g->dt;
    else if (strcmp(name, "time") == 0)
        *out = g->time;
    else
        return 0;
    return 1;
}

void thermo_settings_free(struct thermo_settings *t)
{
    (void)t;
}
