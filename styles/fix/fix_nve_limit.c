/* fix_nve_limit.c - `fix ID group nve/limit xmax`: LAMMPS's fix nve/limit,
 * velocity Verlet for point particles whose velocity is capped after each
 * kick so that no atom moves more than xmax in one step (kernels/
 * fix_nve_limit.cl); used to relax overlapping packings. The scalar f_ID is
 * the number of capped kicks in the current run (extensive, as LAMMPS's),
 * summed over every rank. */
#include <math.h>
#include <stdlib.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "par_sum.h"

#define WHO "fix nve/limit"

struct nve_limit {
    double xlimit, vlimitsq;
    cl_kernel ini, fin;
    cl_mem count;               /* device: the capped kicks of this run */
};

static void destroy(struct fix *f)
{
    struct nve_limit *l = f->data;
    if (l) {
        if (l->count)
            clReleaseMemObject(l->count);
        free(l);
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, WHO " expects xmax, got %d arguments", argc);
    struct nve_limit *l = gr_calloc(g, 1, sizeof *l);
    f->data = l;
    l->xlimit = arg_double(g, argv[0], WHO " xmax");
    f->hooks = HOOK_INITIAL_INTEGRATE | HOOK_FINAL_INTEGRATE;
    f->sources[f->nsources++] = "fix_nve_limit.cl";
}

/* LAMMPS's init: the cap from the step, the count from zero */
static void init(struct gravel *g, struct fix *f)
{
    struct nve_limit *l = f->data;
    const double vmax = l->xlimit / g->dt;
    l->vlimitsq = vmax * vmax;
    if (!l->count)
        l->count = eng_alloc(g, sizeof(cl_int), WHO " count");
    const cl_int zero = 0;
    eng_write(g, l->count, 0, sizeof zero, &zero);
    l->ini = eng_kernel(g, "nve_limit_initial");
    l->fin = eng_kernel(g, "nve_limit_final");
}

static void initial_integrate(struct gravel *g, struct fix *f)
{
    struct nve_limit *l = f->data;
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = l->ini;
    int p = 0;
    eng_arg_int(g, k, p++, a->n);
    eng_arg_uint(g, k, p++, f->groupbit);
    eng_arg_mem(g, k, p++, a->mask);
    eng_arg_mem(g, k, p++, a->x);
    eng_arg_mem(g, k, p++, a->v);
    eng_arg_mem(g, k, p++, a->f);
    eng_arg_mem(g, k, p++, a->rmass);
    eng_arg_real(g, k, p++, g->dt);
    eng_arg_real(g, k, p++, 0.5 * g->dt);
    eng_arg_real(g, k, p++, l->vlimitsq);
    eng_arg_mem(g, k, p++, l->count);
    eng_arg_pos_lo(g, k, p++);
    eng_launch(g, k, (size_t)a->n);
}

static void final_integrate(struct gravel *g, struct fix *f)
{
    struct nve_limit *l = f->data;
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = l->fin;
    int p = 0;
    eng_arg_int(g, k, p++, a->n);
    eng_arg_uint(g, k, p++, f->groupbit);
    eng_arg_mem(g, k, p++, a->mask);
    eng_arg_mem(g, k, p++, a->v);
    eng_arg_mem(g, k, p++, a->f);
    eng_arg_mem(g, k, p++, a->rmass);
    eng_arg_real(g, k, p++, 0.5 * g->dt);
    eng_arg_real(g, k, p++, l->vlimitsq);
    eng_arg_mem(g, k, p++, l->count);
    eng_launch(g, k, (size_t)a->n);
}

/* the capped kicks of this run on every rank (collective) */
static double scalar(struct gravel *g, struct fix *f)
{
    struct nve_limit *l = f->data;
    cl_int n = 0;
    if (l->count)
        eng_read(g, l->count, 0, sizeof n, &n);
    struct par_sum s = {0};
    par_sum_add(g, &s, 0, (double)n);
    return par_sum_total(g, &s);
}

const struct fix_style fix_style_nve_limit = {
    .name = "nve/limit",
    .create = create,
    .init = init,
    .initial_integrate = initial_integrate,
    .final_integrate = final_integrate,
    .scalar = scalar,
    .destroy = destroy,
};
