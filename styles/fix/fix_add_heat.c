/* fix_add_heat.c - `fix ID group add/heat constant|linear|quartic value
 * [k] [overwrite yes|no]`: heat added to the atoms' heat flow at every step,
 * as today's LAMMPS's fix add/heat (GRANULAR package): constant Q += value
 * (energy/time), linear Q += k (value - T), quartic Q += k (value^4 - T^4),
 * value a number, an equal-style variable (evaluated at every step) or an
 * atom-style variable (per atom, evaluated on the host at every step);
 * overwrite yes sets the heat flow of the step to this fix's alone (the
 * contacts' and earlier fixes' heat dropped). Runs at post_force in fix
 * order after the contacts' heat (kernels/fix_add_heat.cl), at every step
 * but not at a run's setup (as LAMMPS); fix heat/flow integrates the
 * result. Needs fix property/atom temperature heatflow. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "variable.h"

#define WHO "fix add/heat"

enum { ADD_CONSTANT, ADD_LINEAR, ADD_QUARTIC };

struct add_heat {
    int style, overwrite;
    double value, prefactor;
    char *var;                  /* v_name: equal- or atom-style, else NULL */
    int var_atom;
    double *vals;               /* the atom-style variable's values, host order */
    cl_mem dvals;
    size_t dvals_n;
    cl_kernel k;
};

static void destroy(struct fix *f)
{
    struct add_heat *h = f->data;
    if (h) {
        if (h->dvals)
            clReleaseMemObject(h->dvals);
        free(h->var);
        free(h->vals);
        free(h);
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, WHO " expects constant|linear|quartic value [k] [overwrite yes|no], got %d "
                    "arguments", argc);
    struct add_heat *h = gr_calloc(g, 1, sizeof *h);
    f->data = h;
    if (!strcmp(argv[0], "constant"))
        h->style = ADD_CONSTANT;
    else if (!strcmp(argv[0], "linear"))
        h->style = ADD_LINEAR;
    else if (!strcmp(argv[0], "quartic"))
        h->style = ADD_QUARTIC;
    else
        gr_error(g, WHO ": invalid option '%.64s' (constant, linear, quartic)", argv[0]);
    if (!strncmp(argv[1], "v_", 2) && argv[1][2])
        h->var = gr_strdup(g, argv[1] + 2);
    else
        h->value = arg_double(g, argv[1], WHO " value");
    int i = 2;
    if (h->style != ADD_CONSTANT) {
        if (argc < 3)
            gr_error(g, WHO " %s expects Ttarget and a prefactor k", argv[0]);
        h->prefactor = arg_double(g, argv[2], WHO " prefactor");
        i = 3;
    }
    for (; i < argc; i += 2) {
        if (strcmp(argv[i], "overwrite"))
            gr_error(g, WHO ": invalid argument '%.64s' (overwrite)", argv[i]);
        arg_need(g, argc, i, 1, "overwrite");
        h->overwrite = arg_yesno(g, argv[i + 1], "overwrite");
    }
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_add_heat.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct add_heat *h = f->data;
    if (!g->eng->heat)
        gr_error(g, WHO " %s requires atoms with temperature and heatflow (fix property/atom "
                    "temperature heatflow)", f->id);
    if (h->var) {
        if (var_is_equal(g, h->var))
            h->var_atom = 0;
        else if (var_is_atom(g, h->var))
            h->var_atom = 1;
        else
            gr_error(g, WHO " %s: variable %s %s", f->id, h->var,
                     var_exists(g, h->var) ? "is not equal- or atom-style" : "does not exist");
    }
    h->k = eng_kernel(g, "add_heat_post_force");
}

/* the atom-style variable's value of every atom, uploaded in device order */
static cl_mem atom_values(struct gravel *g, struct add_heat *h)
{
    const int n = g->atoms.n;
    free(h->vals);
    h->vals = gr_malloc(g, ((size_t)n + 1) * sizeof *h->vals);
    var_compute_atom(g, h->var, h->vals); /* syncs the host arrays: host order = device order */
    if (!h->dvals || h->dvals_n < (size_t)n) {
        if (h->dvals)
            clReleaseMemObject(h->dvals);
        h->dvals_n = (size_t)n + (size_t)n / 8 + 16;
        h->dvals = eng_alloc(g, h->dvals_n * g->eng->rsz, WHO " values");
    }
    eng_write_reals(g, h->dvals, (size_t)n, h->vals);
    return h->dvals;
}

static void post_force(struct gravel *g, struct fix *f)
{
    if (eng_in_setup(g)) /* LAMMPS's fix add/heat has no setup(): the run's steps only */
        return;
    struct add_heat *h = f->data;
    struct dev_atoms *a = eng_atoms(g);
    const int peratom = h->var && h->var_atom;
    const double value = h->var && !peratom ? var_compute_equal(g, h->var) : h->value;
    cl_mem vals = peratom ? atom_values(g, h) : a->heatflow;
    cl_kernel k = h->k;
    int q = 0;
    eng_arg_int(g, k, q++, a->n);
    eng_arg_uint(g, k, q++, f->groupbit);
    eng_arg_mem(g, k, q++, a->mask);
    eng_arg_mem(g, k, q++, a->heatflow);
    eng_arg_mem(g, k, q++, a->temperature);
    eng_arg_int(g, k, q++, h->style);
    eng_arg_real(g, k, q++, value);
    eng_arg_real(g, k, q++, h->prefactor);
    eng_arg_mem(g, k, q++, vals);
    eng_arg_int(g, k, q++, peratom);
    eng_arg_int(g, k, q++, h->overwrite);
    eng_launch(g, k, (size_t)a->n);
}

const struct fix_style fix_style_add_heat = {
    .name = "add/heat",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
};
