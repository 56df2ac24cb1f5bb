/* fix_viscous_nonlinear.c - `fix ID group viscous/nonlinear rho_gas mu_gas
 * [velocity vx vy vz]` (LAMMPS 2026, GRANULAR fix_viscous_nonlinear.cpp):
 * Reynolds-number dependent (Schiller-Naumann) drag of a uniform gas of
 * density rho_gas and viscosity mu_gas moving at (vx, vy, vz) (default at
 * rest) on every sphere of the group, at post_force
 * (kernels/fix_viscous_nonlinear.cl). */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "coeff_check.h"
#include "device.h"
#include "error.h"
#include "fix.h"

struct visc_nl {
    double rho, mu, vgas[3];
    cl_kernel k;
};

static void destroy(struct fix *f)
{
    free(f->data);
    f->data = NULL;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, "fix viscous/nonlinear expects rho_gas mu_gas [velocity vx vy vz]");
    struct visc_nl *v = gr_calloc(g, 1, sizeof *v);
    f->data = v;
    const char *who = "fix viscous/nonlinear";
    v->rho = coeff_check(g, who, "gas density rho_gas", arg_double(g, argv[0], "rho_gas"),
                         CR_POSITIVE);
    v->mu = coeff_check(g, who, "gas viscosity mu_gas", arg_double(g, argv[1], "mu_gas"),
                        CR_POSITIVE);
    for (int i = 2; i < argc; i += 4) {
        if (strcmp(argv[i], "velocity"))
            gr_error(g, "fix viscous/nonlinear: unknown keyword '%.64s' (expected velocity)",
                     argv[i]);
        arg_need(g, argc, i, 3, "velocity");
        for (int d = 0; d < 3; d++)
            v->vgas[d] = arg_double(g, argv[i + 1 + d], "gas velocity");
    }
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_viscous_nonlinear.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct visc_nl *v = f->data;
    v->k = eng_kernel(g, "viscous_nonlinear_post_force");
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct visc_nl *v = f->data;
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = v->k;
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->v);
    eng_arg_mem(g, k, 4, a->radius);
    eng_arg_mem(g, k, 5, a->f);
    eng_arg_real(g, k, 6, v->rho);
    eng_arg_real(g, k, 7, v->mu);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, 8 + d, v->vgas[d]);
    eng_launch(g, k, (size_t)a->n);
}

const struct fix_style fix_style_viscous_nonlinear = {
    .name = "viscous/nonlinear",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
};
