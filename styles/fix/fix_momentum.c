/* fix_momentum.c - `fix ID group momentum N [linear xflag yflag zflag]
 * [angular] [rescale]`: every N steps (end_of_step) the group's linear
 * momentum (the flagged components of its centre-of-mass velocity) and/or
 * its angular momentum about its centre of mass are removed from the
 * velocities, as LAMMPS's and LIGGGHTS's fix_momentum.cpp:
 *   linear   v -= vcm (flagged components)
 *   angular  v -= omega x (x_unwrapped - xcm), I omega = L (group_omega)
 *   rescale  velocities scaled by sqrt(KE_before / KE_after) of the group.
 * The group's mass is taken at the run's start (LAMMPS's init), every step
 * of a dynamic group. The sums are group.h's (tag order, over every rank's
 * atoms: one process's bits on any number of MPI ranks). The work is on the
 * host: the atoms synced, the velocities written back. */
#include <math.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "comm.h"
#include "device.h"
#include "domain.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "group.h"
#include "par.h"

struct momentum {
    int nevery, linear, xflag, yflag, zflag, angular, rescale;
    double masstotal;
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "Illegal fix momentum command: expected N");
    struct momentum *m = gr_calloc(g, 1, sizeof *m);
    f->data = m;
    m->nevery = arg_int(g, argv[0], "fix momentum N");
    if (m->nevery <= 0)
        gr_error(g, "Illegal fix momentum command: N must be > 0, got %d", m->nevery);
    for (int i = 1; i < argc;) {
        if (!strcmp(argv[i], "linear")) {
            arg_need(g, argc, i, 3, "linear");
            int *fl[3] = {&m->xflag, &m->yflag, &m->zflag};
            for (int k = 0; k < 3; k++) {
                *fl[k] = arg_int(g, argv[i + 1 + k], "fix momentum linear flag");
                if (*fl[k] != 0 && *fl[k] != 1)
                    gr_error(g, "Illegal fix momentum command: linear flags are 0 or 1, got %d",
                             *fl[k]);
            }
            m->linear = 1;
            i += 4;
        } else if (!strcmp(argv[i], "angular")) {
            m->angular = 1;
            i++;
        } else if (!strcmp(argv[i], "rescale")) {
            m->rescale = 1;
            i++;
        } else {
            gr_error(g, "Illegal fix momentum command: unknown keyword '%.64s' (linear, "
                        "angular, rescale)", argv[i]);
        }
    }
    if (!m->linear && !m->angular)
        gr_error(g, "Illegal fix momentum command: give linear and/or angular");
    f->hooks = HOOK_END_OF_STEP;
}

static void init(struct gravel *g, struct fix *f)
{
    struct momentum *m = f->data;
    long long count = 0;
    for (int i = 0; i < g->atoms.n; i++)
        count += (g->atoms.mask[i] & f->groupbit) != 0;
    if (par_on(g))
        count = comm_sum_ll(count);
    if (!g->groups.dyn[f->igroup].on && count == 0)
        gr_error(g, "Fix momentum group has no atoms");
    m->masstotal = group_mass(g, f->igroup);
}

static void end_of_step(struct gravel *g, struct fix *f)
{
    struct momentum *m = f->data;
    if (g->step % m->nevery)
        return;
    run_sync_host(g); /* host order = device order */
    struct atoms *a = &g->atoms;
    const unsigned bit = f->groupbit;
    if (g->groups.dyn[f->igroup].on)
        m->masstotal = group_mass(g, f->igroup);
    if (m->masstotal == 0.0)
        return;
    const double ekin_old = m->rescale ? group_ke(g, f->igroup) : 0.0;
    if (m->linear) {
        double vcm[3];
        group_vcm(g, f->igroup, m->masstotal, vcm);
        const int flag[3] = {m->xflag, m->yflag, m->zflag};
        for (int i = 0; i < a->n; i++)
            if (a->mask[i] & bit)
                for (int d = 0; d < 3; d++)
                    if (flag[d])
                        a->v[3 * i + d] -= vcm[d];
    }
    if (m->angular) {
        double xcm[3], L[3], I[3][3], w[3];
        group_xcm(g, f->igroup, m->masstotal, xcm);
        group_angmom(g, f->igroup, xcm, L);
        group_inertia(g, f->igroup, xcm, I);
        group_omega(L, I, w);
        for (int i = 0; i < a->n; i++) {
            if (!(a->mask[i] & bit))
                continue;
            double u[3];
            domain_unmap(g, a->x + 3 * i, a->image + 3 * i, u);
            const double dx = u[0] - xcm[0], dy = u[1] - xcm[1], dz = u[2] - xcm[2];
            double *v = a->v + 3 * i;
            v[0] -= w[1] * dz - w[2] * dy;
            v[1] -= w[2] * dx - w[0] * dz;
            v[2] -= w[0] * dy - w[1] * dx;
        }
    }
    if (m->rescale) {
        const double ekin_new = group_ke(g, f->igroup); /* 1/2 of both: the same ratio */
        const double factor = ekin_new != 0.0 ? sqrt(ekin_old / ekin_new) : 1.0;
        for (int i = 0; i < a->n; i++)
            if (a->mask[i] & bit)
                for (int d = 0; d < 3; d++)
                    a->v[3 * i + d] *= factor;
    }
    struct dev_atoms *s = eng_atoms(g);
    if (!s->shared)
        eng_write_reals(g, s->v, 3 * (size_t)a->n, a->v);
}

const struct fix_style fix_style_momentum = {
    .name = "momentum",
    .create = create,
    .init = init,
    .end_of_step = end_of_step,
};
