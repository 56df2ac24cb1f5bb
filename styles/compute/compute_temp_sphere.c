/* compute_temp_sphere.c - `compute ID group temp/sphere [bias ID] [dof
 * all|rotate]`: temperature of finite-size spheres as LAMMPS' compute
 * temp/sphere: translational plus rotational kinetic energy with the
 * solid-sphere inertia 0.4 m r^2 (in 2d too), or (dof rotate) the rotational
 * part only; degrees of freedom 6 per sphere in 3d, 3 per disc in 2d (dof
 * rotate: 3 and 1; point particles count their translations only), minus
 * extra/dof in mode all (src/engine/temperature.h). Global scalar (intensive) and
 * the 6-vector of the kinetic-energy tensor (extensive). `bias ID`: the
 * translational velocities counted are those less the bias of temperature
 * compute ID (temp/com, temp/partial, temp/region, of the same group), and
 * the degrees of freedom less what that bias removes, as LAMMPS's
 * (temperature.c). */
#include <string.h>

#include "compute.h"
#include "error.h"
#include "temperature.h"

/* LAMMPS's init: the bias compute is a temperature with a velocity bias, of
 * this compute's group; resolved again at each use (it may be redefined) */
static void resolve_bias(struct gravel *g, struct compute *c)
{
    struct temp_state *t = c->temp;
    t->bias = NULL;
    if (t->bias_id[0]) {
        struct compute *b = compute_get(g, t->bias_id, "compute temp/sphere bias");
        if (!b->temp)
            gr_error(g, "compute temp/sphere %s: bias compute %s does not compute temperature",
                     c->id, b->id);
        if (!temp_has_bias(b->temp))
            gr_error(g, "compute temp/sphere %s: bias compute %s does not calculate a velocity "
                        "bias", c->id, b->id);
        if (b->groupbit != c->groupbit)
            gr_error(g, "compute temp/sphere %s: bias compute %s's group does not match its "
                        "group", c->id, b->id);
        if (b->temp->kind == TEMP_REGION && b->style->init)
            b->style->init(g, b); /* its region looked up again (com, partial: nothing to) */
        t->bias = b->temp;
    }
}

static void init(struct gravel *g, struct compute *c)
{
    resolve_bias(g, c);
    temp_compute_init(g, c);
}

static double scalar(struct gravel *g, struct compute *c)
{
    resolve_bias(g, c);
    return temp_compute_scalar(g, c);
}

static void vector(struct gravel *g, struct compute *c)
{
    resolve_bias(g, c);
    temp_compute_vector(g, c);
}

static void create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    enum temp_kind kind = TEMP_SPHERE_ALL;
    const char *bias = NULL;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "dof")) {
            if (i + 1 >= argc)
                gr_error(g, "compute temp/sphere: dof needs all or rotate");
            const char *v = argv[++i];
            if (!strcmp(v, "all"))
                kind = TEMP_SPHERE_ALL;
            else if (!strcmp(v, "rotate"))
                kind = TEMP_SPHERE_ROTATE;
            else
                gr_error(g, "compute temp/sphere: dof must be all or rotate, got '%.64s'", v);
        } else if (!strcmp(argv[i], "bias")) {
            if (i + 1 >= argc)
                gr_error(g, "compute temp/sphere: bias needs a compute ID");
            bias = argv[++i];
            if (strlen(bias) >= GR_NAMELEN)
                gr_error(g, "compute temp/sphere: bias ID '%.64s...' is too long", bias);
        } else {
            gr_error(g, "compute temp/sphere: unknown keyword '%.64s' (dof, bias)", argv[i]);
        }
    }
    temp_compute_attach(g, c, kind);
    if (bias)
        strcpy(c->temp->bias_id, bias);
}

const struct compute_style compute_style_temp_sphere = {
    .name = "temp/sphere",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = create,
    .init = init,
    .scalar = scalar,
    .vector = vector,
};
