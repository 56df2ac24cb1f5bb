/* fix_spring.c - `fix ID group spring tether K x y z R0` and `fix ID group
 * spring couple group2 K x y z R0`: LAMMPS's fix spring. tether: a spring
 * of stiffness K and rest length R0 between the group's centre of mass and
 * the point (x, y, z); couple: between the two groups' centres of mass,
 * (x, y, z) the rest offset of group2's from the group's. NULL drops a
 * component. At every post_force (setup included) the host takes the
 * centres of mass (unwrapped, every rank's atoms in tag order: src/state/
 * group.c) and the spring's force F = K (r - R0) d / r, d the separation;
 * each atom receives its mass's share (kernels/fix_spring.cl). Output: the
 * spring's energy K (r - R0)^2 / 2 as the scalar f_ID (`fix_modify ID
 * energy yes` adds it to pe) and the vector f_ID[1..4]: the force on the
 * group (tether: minus F; couple: F) and its length, negative when
 * compressed, as LAMMPS's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "group.h"

#define WHO "fix spring"
#define SPRING_SMALL 1.0e-10 /* LAMMPS's floor on the separation */

struct spring {
    int couple, igroup2;
    double k, r0, xc[3];
    int flag[3];                /* the components not NULL */
    double masstotal, masstotal2;
    double espring, ftotal[4];
    cl_kernel kern;
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, WHO " expects tether K x y z R0 or couple group2 K x y z R0");
    struct spring *s = gr_calloc(g, 1, sizeof *s);
    f->data = s;
    int i = 1;
    if (!strcmp(argv[0], "tether")) {
        if (argc != 6)
            gr_error(g, WHO " tether expects K x y z R0, got %d arguments", argc - 1);
    } else if (!strcmp(argv[0], "couple")) {
        if (argc != 7)
            gr_error(g, WHO " couple expects group2 K x y z R0, got %d arguments", argc - 1);
        s->couple = 1;
        s->igroup2 = group_find(g, argv[1]);
        if (s->igroup2 < 0)
            gr_error(g, WHO " couple: group '%.64s' does not exist", argv[1]);
        if (s->igroup2 == f->igroup)
            gr_error(g, WHO " couple: the two groups are the same");
        i = 2;
    } else {
        gr_error(g, WHO ": expected tether or couple, got '%.64s'", argv[0]);
    }
    s->k = arg_double(g, argv[i], WHO " K");
    for (int d = 0; d < 3; d++) {
        s->flag[d] = strcmp(argv[i + 1 + d], "NULL") != 0;
        if (s->flag[d])
            s->xc[d] = arg_double(g, argv[i + 1 + d], WHO " point");
    }
    s->r0 = arg_double(g, argv[i + 4], WHO " R0");
    if (s->r0 < 0)
        gr_error(g, WHO ": R0 must be >= 0, got %g", s->r0);
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_spring.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct spring *s = f->data;
    s->masstotal = group_mass(g, f->igroup);
    if (s->couple)
        s->masstotal2 = group_mass(g, s->igroup2);
    s->kern = eng_kernel(g, "spring_force");
}

/* The spring's force per unit mass on each group (c1 on the group, c2 on
 * group2, applied as f += m c1, f -= m c2), its energy and f_ID's vector:
 * LAMMPS's spring_tether / spring_couple. */
static void spring_forces(struct gravel *g, struct fix *f, double c1[3], double c2[3])
{
    struct spring *s = f->data;
    if (g->groups.dyn[f->igroup].on)
        s->masstotal = group_mass(g, f->igroup);
    if (s->couple && g->groups.dyn[s->igroup2].on)
        s->masstotal2 = group_mass(g, s->igroup2);
    double xcm[3], xcm2[3] = {0, 0, 0}, dx[3];
    group_xcm(g, f->igroup, s->masstotal, xcm);
    if (s->couple)
        group_xcm(g, s->igroup2, s->masstotal2, xcm2);
    for (int d = 0; d < 3; d++) {
        dx[d] = s->couple ? xcm2[d] - xcm[d] - s->xc[d] : xcm[d] - s->xc[d];
        if (!s->flag[d])
            dx[d] = 0.0;
    }
    double r = sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
    r = r > SPRING_SMALL ? r : SPRING_SMALL;
    const double dr = r - s->r0;
    double fs[3];
    for (int d = 0; d < 3; d++) {
        fs[d] = s->k * dx[d] * dr / r;
        s->ftotal[d] = s->couple ? fs[d] : -fs[d];
    }
    s->ftotal[3] = sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
    if (dr < 0.0)
        s->ftotal[3] = -s->ftotal[3];
    s->espring = 0.5 * s->k * dr * dr;
    for (int d = 0; d < 3; d++) {
        const double per = s->masstotal > 0.0 ? fs[d] / s->masstotal : s->couple ? 0.0 : fs[d];
        c1[d] = s->couple ? per : -per; /* tether: f -= m F / M; couple: f += m F / M */
        c2[d] = s->couple && s->masstotal2 > 0.0 ? fs[d] / s->masstotal2 : 0.0;
    }
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct spring *s = f->data;
    run_sync_host(g); /* the positions and images of the centres of mass */
    double c1[3], c2[3];
    spring_forces(g, f, c1, c2);
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = s->kern;
    int p = 0;
    eng_arg_int(g, k, p++, a->n);
    eng_arg_mem(g, k, p++, a->mask);
    eng_arg_mem(g, k, p++, a->rmass);
    eng_arg_mem(g, k, p++, a->f);
    eng_arg_uint(g, k, p++, f->groupbit);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, p++, c1[d]);
    eng_arg_uint(g, k, p++, s->couple ? group_bit(s->igroup2) : 0u);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, p++, c2[d]);
    eng_launch(g, k, (size_t)a->n);
}

static double scalar(struct gravel *g, struct fix *f)
{
    (void)g;
    return ((struct spring *)f->data)->espring;
}

static double vector(struct gravel *g, struct fix *f, int i)
{
    (void)g;
    return ((struct spring *)f->data)->ftotal[i - 1];
}

const struct fix_style fix_style_spring = {
    .name = "spring",
    .create = create,
    .init = init,
    .post_force = post_force,
    .scalar = scalar,
    .energy_global = 1,
    .vector = vector,
    .size_vector = 4,
};
