/* fix_momentum.c - `fix ID group momentum N [linear xflag yflag zflag]
 * [angular] [rescale]`: every N steps (end_of_step) the group's linear
 * momentum (the flagged components of its centre-of-mass velocity) and/or
 * its angular momentum about its centre of mass are removed from the
 * velocities, as LAMMPS's and LIGGGHTS's fix_momentum.cpp:
 *   linear   v -= vcm (flagged components)
 *   angular  v -= omega x (x_unwrapped - xcm), I omega = L (group_omega)
 *   rescale  velocities scaled by sqrt(KE_before / KE_after) of the group.
 * The group's mass is taken at the run's start (LAMMPS's init), every step
 * of a dynamic group. The sums run over every rank's atoms in tag order
 * (group_sums: one process's bits on any number of MPI ranks). The work is
 * on the host: the atoms synced, the velocities written back. */
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
#include "par_sum.h"

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

/* What group_sums adds up per atom (n terms each, in this order). */
enum sum_kind { S_MASS, S_P, S_MX, S_L, S_I, S_KE };

/* Sums over the group's atoms of every rank, in tag order (par_sum: on one
 * process the loops of group.c, term for term): mass (1); momentum m v (3);
 * m x (3, x unwrapped); angular momentum about c (3); the inertia tensor
 * about c (6: xx yy zz xy yz xz); m v^2 (1). */
static void group_sums(struct gravel *g, unsigned bit, enum sum_kind kind, const double c[3],
                       double *out)
{
    static const int nterm[] = {1, 3, 3, 3, 6, 1};
    const int n = nterm[kind];
    const struct atoms *a = &g->atoms;
    const int *order = atoms_tag_order(g);
    struct par_sum s[6];
    memset(s, 0, sizeof s);
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!(a->mask[i] & bit))
            continue;
        const double m = a->rmass[i], *v = a->v + 3 * i;
        double t[6] = {0}, u[3] = {0}, dx = 0, dy = 0, dz = 0;
        if (kind == S_MX || kind == S_L || kind == S_I) {
            domain_unmap(g, a->x + 3 * i, a->image + 3 * i, u);
            if (c)
                dx = u[0] - c[0], dy = u[1] - c[1], dz = u[2] - c[2];
        }
        switch (kind) {
        case S_MASS:
            t[0] = m;
            break;
        case S_P:
            t[0] = m * v[0], t[1] = m * v[1], t[2] = m * v[2];
            break;
        case S_MX:
            t[0] = m * u[0], t[1] = m * u[1], t[2] = m * u[2];
            break;
        case S_L:
            t[0] = m * (dy * v[2] - dz * v[1]);
            t[1] = m * (dz * v[0] - dx * v[2]);
            t[2] = m * (dx * v[1] - dy * v[0]);
            break;
        case S_I: /* the off-diagonal terms subtracted: + (-t) is - t */
            t[0] = m * (dy * dy + dz * dz), t[1] = m * (dx * dx + dz * dz);
            t[2] = m * (dx * dx + dy * dy), t[3] = -(m * dx * dy);
            t[4] = -(m * dy * dz), t[5] = -(m * dx * dz);
            break;
        case S_KE:
            t[0] = m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            break;
        }
        for (int q = 0; q < n; q++)
            par_sum_add(g, &s[q], a->tag[i], t[q]);
    }
    for (int q = 0; q < n; q++)
        out[q] = par_sum_total(g, &s[q]);
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
    group_sums(g, f->groupbit, S_MASS, NULL, &m->masstotal);
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
        group_sums(g, bit, S_MASS, NULL, &m->masstotal);
    if (m->masstotal == 0.0)
        return;
    double ekin_old = 0.0;
    if (m->rescale)
        group_sums(g, bit, S_KE, NULL, &ekin_old);
    if (m->linear) {
        double p[3], vcm[3];
        group_sums(g, bit, S_P, NULL, p);
        for (int d = 0; d < 3; d++)
            vcm[d] = p[d] / m->masstotal;
        const int flag[3] = {m->xflag, m->yflag, m->zflag};
        for (int i = 0; i < a->n; i++)
            if (a->mask[i] & bit)
                for (int d = 0; d < 3; d++)
                    if (flag[d])
                        a->v[3 * i + d] -= vcm[d];
    }
    if (m->angular) {
        double mx[3], xcm[3], L[3], t[6], w[3];
        group_sums(g, bit, S_MX, NULL, mx);
        for (int d = 0; d < 3; d++)
            xcm[d] = mx[d] / m->masstotal;
        group_sums(g, bit, S_L, xcm, L);
        group_sums(g, bit, S_I, xcm, t);
        double I[3][3] = {{t[0], t[3], t[5]}, {t[3], t[1], t[4]}, {t[5], t[4], t[2]}};
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
        double ekin_new;
        group_sums(g, bit, S_KE, NULL, &ekin_new);
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
