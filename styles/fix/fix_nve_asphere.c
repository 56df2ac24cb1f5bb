/* fix_nve_asphere.c - `fix ID group nve/asphere`: LAMMPS's velocity Verlet
 * for aspherical particles (kernels/fix_nve_asphere.cl): positions and
 * velocities as fix nve, the space-frame angular momentum kicked by the
 * torque in both half steps, the quaternion advanced a full step by
 * Richardson iteration with the angular velocity from the angular momentum
 * and the particle's principal moments (atom_style ellipsoid
 * superellipsoid, set shape / set block). Every atom of the group must
 * have a shape (LAMMPS: "Fix nve/asphere requires extended particles").
 * LAMMPS's optional `dipole` keyword is refused (no point dipoles). */
#include <string.h>

#include "device.h"
#include "error.h"
#include "fix.h"

struct kern {
    cl_kernel ini, fin;
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc > 0)
        gr_error(g, "fix nve/asphere: unknown keyword '%.64s' (it takes none here: the "
                    "dipole update is not supported)", argv[0]);
    if (!g->atoms.ellipsoid_flag)
        gr_error(g, "fix nve/asphere requires atom_style ellipsoid superellipsoid");
    f->data = gr_calloc(g, 1, sizeof(struct kern));
    f->hooks = HOOK_INITIAL_INTEGRATE | HOOK_FINAL_INTEGRATE;
    f->needs = NEED_ROTATION;
    f->sources[f->nsources++] = "fix_nve_asphere.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    const struct atoms *a = &g->atoms;
    if (!a->ellipsoid_flag)
        gr_error(g, "fix %s nve/asphere requires atom_style ellipsoid superellipsoid", f->id);
    for (int i = 0; i < a->n; i++) {
        const double *sh = a->shape + 3 * i;
        if ((a->mask[i] & f->groupbit) && sh[0] == 0.0 && sh[1] == 0.0 && sh[2] == 0.0)
            gr_error(g, "fix %s nve/asphere requires extended particles: atom %lld has no "
                        "shape (set shape)", f->id, (long long)a->tag[i]);
    }
    struct kern *k = f->data;
    k->ini = eng_kernel(g, "nve_asphere_initial");
    k->fin = eng_kernel(g, "nve_asphere_final");
}

static void initial_integrate(struct gravel *g, struct fix *f)
{
    struct kern *k = f->data;
    struct dev_atoms *a = eng_atoms(g);
    eng_arg_int(g, k->ini, 0, a->n);
    eng_arg_uint(g, k->ini, 1, f->groupbit);
    eng_arg_mem(g, k->ini, 2, a->mask);
    eng_arg_mem(g, k->ini, 3, a->x);
    eng_arg_mem(g, k->ini, 4, a->v);
    eng_arg_mem(g, k->ini, 5, a->f);
    eng_arg_mem(g, k->ini, 6, a->torque);
    eng_arg_mem(g, k->ini, 7, a->rmass);
    eng_arg_mem(g, k->ini, 8, a->quat);
    eng_arg_mem(g, k->ini, 9, a->angmom);
    eng_arg_mem(g, k->ini, 10, a->inertia);
    eng_arg_real(g, k->ini, 11, g->dt);
    eng_arg_real(g, k->ini, 12, 0.5 * g->dt);
    eng_arg_real(g, k->ini, 13, 0.5 * g->dt); /* dtq = dt/2 */
    eng_arg_pos_lo(g, k->ini, 14);
    eng_launch(g, k->ini, (size_t)a->n);
}

static void final_integrate(struct gravel *g, struct fix *f)
{
    struct kern *k = f->data;
    struct dev_atoms *a = eng_atoms(g);
    eng_arg_int(g, k->fin, 0, a->n);
    eng_arg_uint(g, k->fin, 1, f->groupbit);
    eng_arg_mem(g, k->fin, 2, a->mask);
    eng_arg_mem(g, k->fin, 3, a->v);
    eng_arg_mem(g, k->fin, 4, a->f);
    eng_arg_mem(g, k->fin, 5, a->torque);
    eng_arg_mem(g, k->fin, 6, a->rmass);
    eng_arg_mem(g, k->fin, 7, a->angmom);
    eng_arg_real(g, k->fin, 8, 0.5 * g->dt);
    eng_launch(g, k->fin, (size_t)a->n);
}

const struct fix_style fix_style_nve_asphere = {
    .name = "nve/asphere",
    .flags = FIX_CONSERVING,
    .create = create,
    .init = init,
    .initial_integrate = initial_integrate,
    .final_integrate = final_integrate,
};
