/* fix_heat_flow.c - `fix ID group heat/flow constant cp` or `fix ID group
 * heat/flow type cp1 ... cpN` (LAMMPS 2023, GRANULAR fix_heat_flow.cpp):
 * integrates each atom's temperature from the heat flow the contacts give
 * it (pair granular / fix wall/gran `heat` sub-models), T += dt Q / (m cp),
 * at final_integrate (kernels/fix_heat_flow.cl). Needs fix property/atom
 * temperature heatflow. LAMMPS's pre_force zeroing of the heat flow is the
 * gather's: every step's heatflow is that step's sum (kernels/pair_loop.cl). */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "coeff_check.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fix_heat_flow.h"

struct heat_flow {
    int ntypes;
    double *cp;                 /* [ntypes] */
    cl_mem buf;
    cl_kernel k;
};

static void destroy(struct fix *f)
{
    struct heat_flow *h = f->data;
    if (h) {
        if (h->buf)
            clReleaseMemObject(h->buf);
        free(h->cp);
        free(h);
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix heat/flow expects constant cp or type cp1 ... cpN");
    if (g->atoms.ntypes < 1)
        gr_error(g, "fix heat/flow needs atom types (create the box first)");
    struct heat_flow *h = gr_calloc(g, 1, sizeof *h);
    f->data = h;
    h->ntypes = g->atoms.ntypes;
    h->cp = gr_calloc(g, (size_t)h->ntypes, sizeof(double));
    const char *who = "fix heat/flow";
    if (!strcmp(argv[0], "constant")) {
        if (argc != 2)
            gr_error(g, "fix heat/flow constant expects one specific heat cp, got %d values",
                     argc - 1);
        double cp = coeff_check(g, who, "specific heat cp", arg_double(g, argv[1], "cp"),
                                CR_POSITIVE);
        for (int t = 0; t < h->ntypes; t++)
            h->cp[t] = cp;
    } else if (!strcmp(argv[0], "type")) {
        if (argc != 1 + h->ntypes)
            gr_error(g, "fix heat/flow type expects one specific heat per atom type (%d), got %d",
                     h->ntypes, argc - 1);
        for (int t = 0; t < h->ntypes; t++)
            h->cp[t] = coeff_check(g, who, "specific heat cp", arg_double(g, argv[1 + t], "cp"),
                                   CR_NONNEG); /* 0: a type no atom of the group has */
    } else {
        gr_error(g, "fix heat/flow: unknown style '%.64s' (expected constant or type)", argv[0]);
    }
    f->hooks = HOOK_FINAL_INTEGRATE;
    f->sources[f->nsources++] = "fix_heat_flow.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct heat_flow *h = f->data;
    if (!(g->atoms.heat_flag & ATOM_HEAT_T))
        gr_error(g, "fix heat/flow requires atoms store temperature property (fix property/atom "
                    "temperature heatflow)");
    if (!(g->atoms.heat_flag & ATOM_HEAT_Q))
        gr_error(g, "fix heat/flow requires atoms store heatflow property (fix property/atom "
                    "temperature heatflow)");
    if (h->ntypes < g->atoms.ntypes)
        gr_error(g, "fix %s heat/flow was defined for %d atom types, now there are %d", f->id,
                 h->ntypes, g->atoms.ntypes);
    if (h->buf)
        clReleaseMemObject(h->buf);
    h->buf = eng_alloc(g, (size_t)h->ntypes * g->eng->rsz, "fix heat/flow cp");
    eng_write_reals(g, h->buf, (size_t)h->ntypes, h->cp);
    h->k = eng_kernel(g, "heat_flow_final");
}

void heat_flow_integrate(struct gravel *g, unsigned groupbit, cl_kernel k, cl_mem cp)
{
    struct dev_atoms *a = eng_atoms(g);
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->type);
    eng_arg_mem(g, k, 4, a->rmass);
    eng_arg_mem(g, k, 5, a->heatflow);
    eng_arg_mem(g, k, 6, a->heatsource);
    eng_arg_mem(g, k, 7, a->temperature);
    eng_arg_mem(g, k, 8, cp);
    eng_arg_real(g, k, 9, g->dt);
    eng_launch(g, k, (size_t)a->n);
}

static void final_integrate(struct gravel *g, struct fix *f)
{
    struct heat_flow *h = f->data;
    heat_flow_integrate(g, f->groupbit, h->k, h->buf);
}

const struct fix_style fix_style_heat_flow = {
    .name = "heat/flow",
    .create = create,
    .init = init,
    .final_integrate = final_integrate,
    .destroy = destroy,
};
