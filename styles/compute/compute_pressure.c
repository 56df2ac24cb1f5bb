/* compute_pressure.c - `compute ID group pressure temp-ID [ke] [pair]
 * [virial] [fix]`: the scalar pressure as LAMMPS' compute pressure
 * (src/engine/pressure.h): (dof kB T + W) / (dim V) with T and dof of compute
 * temp-ID (a temp or temp/sphere; NULL when only the virial is asked) and
 * W the granular pair virial. Keywords choose the parts: ke the kinetic
 * part, pair or virial the pair virial (fixes contribute none, so `fix`
 * adds nothing); none given = both. The group is ignored, as LAMMPS (the
 * pressure is of the whole system). Global scalar and the pressure tensor
 * as a 6-vector pxx pyy pzz pxy pxz pyz (pressure_tensor; xz yz zz are 0 in
 * 2d), both intensive. */
#include <stdio.h>
#include <string.h>

#include "compute.h"
#include "error.h"
#include "par.h"
#include "pressure.h"

struct press {
    char temp_id[GR_NAMELEN];
    int keflag, virialflag;
};

static void create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "compute pressure needs a temperature compute ID (or NULL)");
    struct press *p = gr_calloc(g, 1, sizeof *p);
    c->data = p;
    compute_temp_arg(g, argv[0], p->temp_id, "compute pressure");
    compute_virial_terms(g, argc - 1, argv + 1, &p->keflag, &p->virialflag,
                         "compute pressure");
    if (p->keflag && !p->temp_id[0])
        gr_error(g, "compute pressure: the kinetic part needs a temperature compute, not NULL");
    c->scalar_flag = 1;
    c->vector_flag = 1;
    c->size_vector = 6;
    c->extvector = 0;
    c->vector = gr_calloc(g, 6, sizeof(double));
}

static struct temp_state *temperature(struct gravel *g, struct compute *c)
{
    const struct press *p = c->data;
    return compute_temp_named(g, p->temp_id, "compute pressure");
}

static void init(struct gravel *g, struct compute *c)
{
    temperature(g, c);
}

/* several ranks: each rank's contacts' virial, summed in tag order
 * (src/engine/pressure.c); a variable's evaluation on the gathered atoms has
 * no contacts to read */
static void ranks_check(struct gravel *g, struct compute *c)
{
    if (par_gathered(g)) {
        char why[160];
        snprintf(why, sizeof why, "compute %.40s pressure read by a variable (the thermo "
                                  "keywords press and pxx ... pyz can be)", c->id);
        par_refuse(g, why);
    }
}

static double scalar(struct gravel *g, struct compute *c)
{
    struct press *p = c->data;
    ranks_check(g, c);
    return pressure_parts(g, temperature(g, c), p->keflag, p->virialflag);
}

static void vector(struct gravel *g, struct compute *c)
{
    struct press *p = c->data;
    ranks_check(g, c);
    pressure_tensor(g, temperature(g, c), p->keflag, p->virialflag, c->vector);
}

const struct compute_style compute_style_pressure = {
    .name = "pressure",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = create,
    .init = init,
    .scalar = scalar,
    .vector = vector,
};
