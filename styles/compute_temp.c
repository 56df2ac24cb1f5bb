/* compute_temp.c - `compute ID group temp`: translational temperature of the
 * group as LAMMPS' compute temp, T = mvv2e sum m v.v / (dof kB) with
 * dof = dim N - extra/dof (src/temperature.h), global scalar (intensive),
 * and the kinetic-energy tensor as a 6-vector (extensive). compute_modify
 * sets dynamic/dof and extra/dof. */
#include "compute.h"
#include "error.h"
#include "temperature.h"

static void create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute temp takes no arguments after the style, got %d", argc);
    struct temp_state *t = gr_calloc(g, 1, sizeof *t);
    c->data = c->temp = t;
    t->kind = TEMP_TRANS;
    t->groupbit = c->groupbit;
    c->scalar_flag = c->vector_flag = 1;
    c->size_vector = 6;
    c->extvector = 1;
}

static void init(struct gravel *g, struct compute *c)
{
    temp_setup(g, c->temp);
}

static double scalar(struct gravel *g, struct compute *c)
{
    return temp_scalar(g, c->temp);
}

static void vector(struct gravel *g, struct compute *c)
{
    temp_vector(g, c->temp, c->vector);
}

const struct compute_style compute_style_temp = {
    .name = "temp",
    .create = create,
    .init = init,
    .scalar = scalar,
    .vector = vector,
};
