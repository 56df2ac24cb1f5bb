/* fix_gravity.c - `fix ID group gravity magnitude style args`: a constant
 * acceleration, LAMMPS fix_gravity.cpp semantics (kernels/fix_gravity.cl):
 *   chute angle            phi = 0, theta = 180 - angle
 *   spherical phi theta    (degrees) 3d: (sin t cos p, sin t sin p, cos t)
 *                          2d: (sin t, cos t, 0)
 *   vector x y z           normalized direction
 * Acceleration = magnitude x direction; the force on atom i is m_i times it
 * (force/mass units: ftm2v = 1 in lj, si and cgs). `disable` (LAMMPS
 * 2020+): no force on the atoms; fix rigid/small's `gravity` keyword applies
 * the acceleration to each body's centre of mass instead. Variable magnitudes and
 * the gradient style are not supported (clear error). f_ID is LAMMPS's
 * scalar, the group's gravitational potential energy, which fix_modify
 * energy yes adds to the thermo pe. */
#include <math.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fused.h"
#include "fix_gravity.h"
#include "par_sum.h"

struct grav {
    double acc[3];
    int disable;                /* `disable`: no force on atoms (fix rigid/small gravity) */
    double mag, dir[3];         /* magnitude and unit direction (fix pour reads them) */
    cl_kernel post;
};

int fix_gravity_field(const struct fix *f, double *magnitude, double dir[3])
{
    if (!f || strcmp(f->style->name, "gravity") || !f->data)
        return 0;
    const struct grav *gr = f->data;
    *magnitude = gr->mag;
    for (int d = 0; d < 3; d++)
        dir[d] = gr->dir[d];
    return 1;
}

int fix_gravity_vector(const struct fix *f, double acc[3])
{
    if (!f || strcmp(f->style->name, "gravity") || !f->data)
        return 0;
    const struct grav *gr = f->data;
    for (int d = 0; d < 3; d++)
        acc[d] = gr->acc[d];
    return 1;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, "fix gravity expects magnitude and a style (chute, spherical, vector)");
    if (!strncmp(argv[0], "v_", 2))
        gr_error(g, "fix gravity: variable magnitude '%s' is not supported", argv[0]);
    double mag = arg_double(g, argv[0], "gravity magnitude");
    double dir[3] = {0, 0, 0};
    double theta = 0, phi = 0;
    const double d2r = M_PI / 180.0;
    int dim = g->dom.dimension;
    int used;
    for (int i = 1; i < argc; i++)
        if (!strncmp(argv[i], "v_", 2))
            gr_error(g, "fix gravity: variable argument '%s' is not supported", argv[i]);
    if (!strcmp(argv[1], "chute")) {
        arg_need(g, argc, 1, 1, "chute");
        double vert = arg_double(g, argv[2], "chute angle");
        phi = 0.0;
        theta = 180.0 - vert;
        used = 3;
    } else if (!strcmp(argv[1], "spherical")) {
        arg_need(g, argc, 1, 2, "spherical");
        phi = arg_double(g, argv[2], "phi");
        theta = arg_double(g, argv[3], "theta");
        used = 4;
    } else if (!strcmp(argv[1], "vector")) {
        arg_need(g, argc, 1, 3, "vector");
        for (int d = 0; d < 3; d++)
            dir[d] = arg_double(g, argv[2 + d], "vector component");
        if (dim == 2 && dir[2] != 0.0)
            gr_error(g, "fix gravity vector must have z = 0 for a 2d simulation");
        used = 5;
    } else if (!strcmp(argv[1], "gradient")) {
        gr_error(g, "fix gravity style gradient is not supported");
    } else {
        gr_error(g, "unknown fix gravity style '%.64s' (expected chute, spherical or vector)",
                 argv[1]);
    }
    int disable = 0;
    for (int i = used; i < argc; i++) {
        if (!strcmp(argv[i], "disable"))
            disable = 1;
        else
            gr_error(g, "unexpected fix gravity argument '%.64s' (keyword: disable)", argv[i]);
    }
    double gv[3];
    if (strcmp(argv[1], "vector")) {
        if (dim == 3) {
            gv[0] = sin(d2r * theta) * cos(d2r * phi);
            gv[1] = sin(d2r * theta) * sin(d2r * phi);
            gv[2] = cos(d2r * theta);
        } else {
            gv[0] = sin(d2r * theta);
            gv[1] = cos(d2r * theta);
            gv[2] = 0.0;
        }
    } else {
        double len = dim == 3 ? sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2])
                              : sqrt(dir[0] * dir[0] + dir[1] * dir[1]);
        if (len == 0.0)
            gr_error(g, "fix gravity vector has zero length");
        gv[0] = dir[0] / len;
        gv[1] = dir[1] / len;
        gv[2] = dim == 3 ? dir[2] / len : 0.0;
    }
    struct grav *gr = gr_calloc(g, 1, sizeof *gr);
    f->data = gr;
    gr->mag = mag;
    gr->disable = disable;
    for (int d = 0; d < 3; d++) {
        gr->acc[d] = mag * gv[d];
        gr->dir[d] = gv[d];
    }
    f->hooks = disable ? 0 : HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_gravity.cl";
}

/* |acceleration| of a fix gravity (the accuracy map's free-fall speed). */
static double magnitude(const struct fix *f)
{
    const struct grav *gr = f->data;
    return sqrt(gr->acc[0] * gr->acc[0] + gr->acc[1] * gr->acc[1] + gr->acc[2] * gr->acc[2]);
}

static void init(struct gravel *g, struct fix *f)
{
    ((struct grav *)f->data)->post = eng_kernel(g, "gravity_post_force");
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct grav *gr = f->data;
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = gr->post;
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->rmass);
    eng_arg_mem(g, k, 4, a->f);
    eng_arg_real(g, k, 5, gr->acc[0]);
    eng_arg_real(g, k, 6, gr->acc[1]);
    eng_arg_real(g, k, 7, gr->acc[2]);
    eng_launch(g, k, (size_t)a->n);
}

/* Fused: f += m g inside the gather kernel (kernels/fused.cl). */
static int fuse(struct gravel *g, struct fix *f, unsigned hook, struct fused_op *op)
{
    (void)g;
    struct grav *gr = f->data;
    if (hook != HOOK_POST_FORCE || gr->disable)
        return 0;
    op->kind = FOP_GRAVITY;
    op->nprm = 3;
    op->prm = gr->acc;
    return 1;
}

/* LAMMPS's scalar: the gravitational potential energy of the group,
 * -sum m (a . x) over its atoms at their (wrapped) positions, summed in tag
 * order; extensive. */
static double scalar(struct gravel *g, struct fix *f)
{
    const struct grav *gr = f->data;
    const struct atoms *a = &g->atoms;
    const int *ord = atoms_tag_order(g);
    struct par_sum e = {0}; /* every rank's atoms, in tag order (0 - t == 0 + -t) */
    for (int k = 0; k < a->n; k++) {
        int i = ord[k];
        if (!(a->mask[i] & f->groupbit))
            continue;
        const double *x = a->x + 3 * i;
        par_sum_add(g, &e, a->tag[i],
                    -(a->rmass[i] * (gr->acc[0] * x[0] + gr->acc[1] * x[1] + gr->acc[2] * x[2])));
    }
    return par_sum_total(g, &e);
}

const struct fix_style fix_style_gravity = {
    .name = "gravity",
    .acceleration = magnitude,
    .create = create,
    .init = init,
    .post_force = post_force,
    .fuse = fuse,
    .scalar = scalar,
    .energy_global = 1,
};
