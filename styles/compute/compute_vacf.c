/* compute_vacf.c - `compute ID group vacf`: the velocity auto-correlation
 * of the group, as LAMMPS's compute vacf: global vector of 4,
 * <vx(0) vx> <vy(0) vy> <vz(0) vz> and their sum, averaged over the group's
 * atom count (taken at run setup), intensive. v(0) is each atom's velocity
 * when the compute is defined, kept by atom ID (0 for atoms outside the
 * group then); an atom of the group without one (created later) gets its
 * current velocity, as LAMMPS's set_arrays. Not written to restart files. */
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "compute.h"
#include "error.h"
#include "group.h"
#include "tag_ref.h"

struct vacf {
    struct tag_ref ref;     /* velocities at the start, by tag */
    bigint nvacf;
    int inited;
};

static void vacf_destroy(struct compute *c)
{
    struct vacf *w = c->data;
    if (w) {
        tag_ref_free(&w->ref);
    }
    free(w);
    c->data = NULL;
}

static void vacf_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute vacf takes no arguments after the style, got %d", argc);
    if (g->groups.dyn[c->igroup].on)
        gr_error(g, "compute vacf is not compatible with dynamic groups (group %s)",
                 g->groups.name[c->igroup]);
    struct vacf *w = gr_calloc(g, 1, sizeof *w);
    c->data = w;
    const struct atoms *a = &g->atoms;
    tag_ref_reserve(g, &w->ref, a->maxtag);
    for (int i = 0; i < a->n; i++) {
        int64_t t = a->tag[i];
        tag_ref_reserve(g, &w->ref, t);
        w->ref.have[t] = 1;
        for (int d = 0; d < 3; d++)
            w->ref.v[3 * t + d] = (a->mask[i] & c->groupbit) ? a->v[3 * i + d] : 0.0;
    }
    c->vector_flag = 1;
    c->size_vector = 4;
    c->extvector = 0;
}

static void vacf_init(struct gravel *g, struct compute *c)
{
    struct vacf *w = c->data;
    w->nvacf = group_count(g, c->igroup);
    w->inited = 1;
}

static void vacf_vector(struct gravel *g, struct compute *c)
{
    struct vacf *w = c->data;
    if (!w->inited)
        vacf_init(g, c);
    const struct atoms *a = &g->atoms;
    double s[4] = {0, 0, 0, 0};
    const int *order = atoms_tag_order(g);
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!(a->mask[i] & c->groupbit))
            continue;
        int64_t t = a->tag[i];
        tag_ref_reserve(g, &w->ref, t);
        double *v0 = w->ref.v + 3 * t;
        const double *v = a->v + 3 * i;
        if (!w->ref.have[t]) {
            memcpy(v0, v, 3 * sizeof *v0);
            w->ref.have[t] = 1;
        }
        double vx = v[0] * v0[0], vy = v[1] * v0[1], vz = v[2] * v0[2];
        s[0] += vx;
        s[1] += vy;
        s[2] += vz;
        s[3] += vx + vy + vz;
    }
    for (int k = 0; k < 4; k++)
        c->vector[k] = w->nvacf ? s[k] / (double)w->nvacf : s[k];
}

/* Run setup: the group's count is taken at the first evaluation of the run
 * (the setup's output), when every atom is on the host (several MPI ranks:
 * gathered, par.h). */
static void vacf_setup(struct gravel *g, struct compute *c)
{
    (void)g;
    struct vacf *w = c->data;
    w->inited = 0;
}

const struct compute_style compute_style_vacf = {
    .name = "vacf",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = vacf_create,
    .init = vacf_setup,
    .vector = vacf_vector,
    .destroy = vacf_destroy,
};
