/* fix_temp_rescale.c - the velocity-rescaling thermostats of LAMMPS: `fix
 * ID group temp/rescale N Tstart Tstop window fraction` and `fix ID group
 * temp/berendsen Tstart Tstop Tdamp`.
 *
 * temp/rescale, as LAMMPS's fix temp/rescale: at the end of every N-th step, with T the group's
 * temperature (its own compute temp, or `fix_modify ID temp CID`) and the
 * target Tstart + (step - begin) / (end - begin) (Tstop - Tstart) over the
 * run (Tstart may be v_name, an equal-style variable: the target is then
 * its value), when |T - target| > window the group's velocities are scaled
 * by sqrt(T' / T), T' = T - fraction (T - target) (with a bias temperature,
 * temp/com, temp/partial, temp/region, the thermal part only). The energy taken out,
 * sum of (T - T') dof kB / 2, is the fix's scalar (extensive).
 *
 * temp/berendsen, as LAMMPS's fix temp/berendsen: at the end of every step
 * the velocities (the thermal part) are scaled by lambda = sqrt(1 + dt /
 * Tdamp (target / T - 1)), the target as above; the energy taken out, sum of
 * T (1 - lambda^2) dof kB / 2, is its scalar.
 *
 * Both: `fix_modify ID temp CID`; the scalar counts in thermo ecouple and is
 * kept in restart files. The work is on the host (the atoms synced, the
 * velocities written back), as fix momentum's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "compute.h"
#include "device.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "temperature.h"
#include "variable.h"

#define WHO (r->berendsen ? "fix temp/berendsen" : "fix temp/rescale")

struct temp_rescale {
    int berendsen;              /* temp/berendsen (else temp/rescale) */
    int nevery;
    double t_start, t_stop, window, fraction;
    double t_period;            /* temp/berendsen's Tdamp */
    char *tvar;                 /* Tstart as v_name (else NULL) */
    char temp_id[GR_NAMELEN];   /* fix_modify temp (else the fix's own) */
    struct temp_state own;      /* compute temp of the fix's group */
    double energy;
};

static void destroy(struct fix *f)
{
    struct temp_rescale *r = f->data;
    if (r)
        free(r->tvar);
    free(r);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct temp_rescale *r = gr_calloc(g, 1, sizeof *r);
    f->data = r;
    r->berendsen = !strcmp(f->style->name, "temp/berendsen");
    if (r->berendsen ? argc != 3 : argc != 5)
        gr_error(g, "%s expects %s, got %d arguments", WHO,
                 r->berendsen ? "Tstart Tstop Tdamp" : "N Tstart Tstop window fraction", argc);
    r->nevery = 1;
    if (!r->berendsen) {
        r->nevery = arg_int(g, argv[0], "fix temp/rescale N");
        if (r->nevery <= 0)
            gr_error(g, "fix temp/rescale: N must be > 0, got %d", r->nevery);
        argv++;
    }
    if (!strncmp(argv[0], "v_", 2) && argv[0][2])
        r->tvar = gr_strdup(g, argv[0] + 2);
    else
        r->t_start = arg_double(g, argv[0], "Tstart");
    r->t_stop = arg_double(g, argv[1], "Tstop");
    if (r->berendsen) {
        r->t_period = arg_double(g, argv[2], "Tdamp");
        if (!(r->t_period > 0))
            gr_error(g, "fix temp/berendsen: Tdamp must be > 0, got %g", r->t_period);
    } else {
        r->window = arg_double(g, argv[2], "window");
        r->fraction = arg_double(g, argv[3], "fraction");
    }
    r->own.kind = TEMP_TRANS;
    r->own.groupbit = f->groupbit;
    f->hooks = HOOK_END_OF_STEP;
}

static struct temp_state *temperature(struct gravel *g, struct fix *f)
{
    struct temp_rescale *r = f->data;
    if (!r->temp_id[0])
        return &r->own;
    struct compute *c = compute_get(g, r->temp_id, WHO);
    if (!c->temp)
        gr_error(g, "%s %s: compute %s (%s) is not a temperature", WHO, f->id, c->id,
                 c->style->name);
    return c->temp;
}

/* fix_modify ID temp CID */
static int modify_param(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct temp_rescale *r = f->data;
    if (strcmp(argv[0], "temp"))
        return 0;
    if (argc < 2)
        gr_error(g, "fix_modify %s temp needs a compute ID", f->id);
    compute_temp_arg(g, argv[1], r->temp_id, "fix_modify temp");
    if (!r->temp_id[0])
        gr_error(g, "fix_modify %s temp needs a compute ID, not NULL", f->id);
    temperature(g, f);
    return 2;
}

static void init(struct gravel *g, struct fix *f)
{
    struct temp_rescale *r = f->data;
    if (r->tvar && !var_is_equal(g, r->tvar))
        gr_error(g, "%s %s: variable '%s' %s", WHO, f->id, r->tvar,
                 var_exists(g, r->tvar) ? "is not equal-style" : "does not exist");
    temp_setup(g, temperature(g, f));
}

static void end_of_step(struct gravel *g, struct fix *f)
{
    struct temp_rescale *r = f->data;
    if (g->step % r->nevery)
        return;
    run_sync_host(g); /* host order = device order */
    struct temp_state *t = temperature(g, f);
    const double t_current = temp_scalar(g, t), dof = temp_dof(g, t);
    if (dof < 1)
        return;
    if (t_current == 0.0)
        gr_error(g, "computed temperature for %s cannot be 0.0 (step %lld)", WHO,
                 (long long)g->step);
    double delta = (double)(g->step - g->beginstep);
    if (delta != 0.0)
        delta /= (double)(g->endstep - g->beginstep);
    double target = r->tvar ? var_compute_equal(g, r->tvar)
                            : r->t_start + delta * (r->t_stop - r->t_start);
    if (r->tvar && target < 0.0)
        gr_error(g, "%s: variable %s returned a negative temperature %g at step %lld", WHO,
                 r->tvar, target, (long long)g->step);
    double factor;
    if (r->berendsen) { /* LAMMPS's lamda, and the energy it takes out */
        factor = sqrt(1.0 + g->dt / r->t_period * (target / t_current - 1.0));
        r->energy += t_current * (1.0 - factor * factor) * (0.5 * temp_boltz(g) * dof);
    } else {
        if (fabs(t_current - target) <= r->window)
            return;
        target = t_current - r->fraction * (t_current - target);
        factor = sqrt(target / t_current);
        r->energy += (t_current - target) * 0.5 * temp_boltz(g) * dof;
    }
    struct atoms *a = &g->atoms;
    temp_scale_thermal(g, t, f->groupbit, factor); /* a bias temperature keeps its bias */
    struct dev_atoms *s = eng_atoms(g);
    if (!s->shared)
        eng_write_reals(g, s->v, 3 * (size_t)a->n, a->v);
}

static double scalar(struct gravel *g, struct fix *f)
{
    (void)g;
    return ((struct temp_rescale *)f->data)->energy;
}

static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const double e = ((struct temp_rescale *)f->data)->energy;
    if (buf && cap >= sizeof e)
        memcpy(buf, &e, sizeof e);
    return sizeof e;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    if (len != sizeof(double))
        gr_error(g, "fix %s: restart state of %zu bytes, expected %zu", f->id, len,
                 sizeof(double));
    memcpy(&((struct temp_rescale *)f->data)->energy, buf, sizeof(double));
}

/* the two styles share every hook; create tells them apart by name */
#define TEMP_RESCALE_STYLE(ident, nm)                                                          \
    const struct fix_style fix_style_##ident = {                                               \
        .name = nm,                                                                            \
        .create = create,                                                                      \
        .init = init,                                                                          \
        .end_of_step = end_of_step,                                                            \
        .modify_param = modify_param,                                                          \
        .scalar = scalar,                                                                      \
        .ecouple = 1,                                                                          \
        .destroy = destroy,                                                                    \
        .write_restart = write_restart,                                                        \
        .read_restart = read_restart,                                                          \
    }

TEMP_RESCALE_STYLE(temp_rescale, "temp/rescale");
TEMP_RESCALE_STYLE(temp_berendsen, "temp/berendsen");
