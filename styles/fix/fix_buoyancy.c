/* fix_buoyancy.c - LIGGGHTS's `fix ID group buoyancy density rho level L dim
 * x|y|z` (LIGGGHTS 3.8 fix_buoyancy.cpp): each sphere of the group below the
 * fluid surface at coordinate L of axis dim takes Archimedes's force, -dir |g|
 * rho V_immersed along that axis (dir the sign of gravity along it, V the
 * immersed volume: kernels/buoyancy.h), at post_force
 * (kernels/fix_buoyancy.cl). Needs exactly one fix gravity, along dim.
 * f_ID[1..3]: the total buoyancy force on the group at the current step
 * (extensive), from the host's positions, summed in atom-ID order (the
 * kernel's force in the run's precision; LIGGGHTS sums in its own order). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "buoyancy.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fix_gravity.h"
#include "par.h"
#include "par_sum.h"

#define WHO "fix buoyancy"

struct buoyancy {
    double rho, level;
    int dim;
    cl_kernel k;
};

static void destroy(struct fix *f)
{
    free(f->data);
    f->data = NULL;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct buoyancy *b = gr_calloc(g, 1, sizeof *b);
    f->data = b;
    b->dim = -1;
    for (int i = 0; i < argc; i += 2) {
        const char *kw = argv[i];
        if (!strcmp(kw, "density")) {
            arg_need(g, argc, i, 1, kw);
            b->rho = arg_double(g, argv[i + 1], "density");
            if (!(b->rho > 0.))
                gr_error(g, WHO ": 'density' > 0 required");
        } else if (!strcmp(kw, "level")) {
            arg_need(g, argc, i, 1, kw);
            b->level = arg_double(g, argv[i + 1], "level");
            if (!(b->level > 0.))
                gr_error(g, WHO ": 'level' > 0 required");
        } else if (!strcmp(kw, "dim")) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[i + 1];
            if (!strcmp(v, "x") || !strcmp(v, "y") || !strcmp(v, "z"))
                b->dim = v[0] - 'x';
            else
                gr_error(g, WHO ": expecting 'x' or 'y' or 'z' after 'dim'");
        } else if (!strcmp(kw, "region")) {
            gr_error(g, WHO ": keyword 'region' is not supported (density, level, dim)");
        } else {
            gr_error(g, WHO ": expecting 'density' or 'region', got '%.32s'", kw);
        }
    }
    if (b->dim < 0)
        gr_error(g, WHO ": you have to specify 'dim'");
    if (fabs(b->rho) <= 1e-6) /* LIGGGHTS's compDouble(density, 0, 1e-6) */
        gr_error(g, WHO ": you have to specify 'density'");
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "buoyancy.h";
    f->sources[f->nsources++] = "fix_buoyancy.cl";
    f->size_vector = 3;
}

/* the one fix gravity's acceleration and its sign along dim (LIGGGHTS's
 * test_direction: no component across dim) */
static double gravity_along(struct gravel *g, const struct buoyancy *b, double *gmag)
{
    double acc[3], a[3];
    int n = 0;
    for (int i = 0; i < g->styles.nfix; i++)
        n += fix_gravity_vector(g->styles.fix[i], n ? a : acc);
    if (n != 1)
        gr_error(g, WHO ": need exactly one fix gravity (%d defined)", n);
    double across = 0;
    for (int d = 0; d < 3; d++)
        across += d == b->dim ? 0. : acc[d];
    if (fabs(across) > 0.)
        gr_error(g, WHO ": fix gravity direction is not equal to 'dim'");
    *gmag = sqrt(acc[0] * acc[0] + acc[1] * acc[1] + acc[2] * acc[2]);
    return acc[b->dim] / fabs(acc[b->dim]);
}

static void init(struct gravel *g, struct fix *f)
{
    struct buoyancy *b = f->data;
    double gmag;
    gravity_along(g, b, &gmag);
    b->k = eng_kernel(g, "buoyancy_post_force");
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct buoyancy *b = f->data;
    double gmag;
    const double dir = gravity_along(g, b, &gmag);
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = b->k;
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->x);
    eng_arg_mem(g, k, 4, a->radius);
    eng_arg_mem(g, k, 5, a->f);
    eng_arg_int(g, k, 6, b->dim);
    eng_arg_coord(g, k, 7, b->dim, b->level);
    eng_arg_real(g, k, 8, dir);
    eng_arg_real(g, k, 9, gmag);
    eng_arg_real(g, k, 10, b->rho);
    eng_arg_pos_lo(g, k, 11);
    eng_launch(g, k, (size_t)a->n);
}

/* the group's total buoyancy force now (host arrays current) */
static double vector(struct gravel *g, struct fix *f, int i)
{
    const struct buoyancy *b = f->data;
    const struct atoms *a = &g->atoms;
    double gmag;
    const double dir = gravity_along(g, b, &gmag);
    const int *order = atoms_tag_order(g);
    struct par_sum s = {0}; /* every rank's atoms, in tag order */
    for (int q = 0; q < a->n; q++) {
        const int j = order[q];
        if (!(a->mask[j] & f->groupbit))
            continue;
        const double vol = buoyancy_volume(a->x[3 * (size_t)j + b->dim], b->level, dir,
                                           a->radius[j]);
        if (vol != 0.)
            par_sum_add(g, &s, a->tag[j], -dir * gmag * vol * b->rho);
    }
    const double total = par_sum_total(g, &s);
    return i - 1 == b->dim ? total : 0.;
}

const struct fix_style fix_style_buoyancy = {
    .name = "buoyancy",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
    .size_vector = 3,
    .vector = vector,
};
