/* compute_msd.c - `compute ID group msd [com yes|no] [average yes|no]`:
 * the mean-squared displacement of the group's atoms, as LAMMPS's compute
 * msd: global vector of 4, <dx^2> <dy^2> <dz^2> <|d|^2> over the group
 * (count taken at run setup), intensive.
 *
 * d = (unwrapped position - com) - reference. The reference of each atom is
 * its unwrapped position when the compute is defined (minus the group's
 * centre of mass then, with com yes), kept by atom ID; with average yes it
 * is the running average of the positions seen at each evaluation
 * (LAMMPS's: on its n-th evaluation ref = (ref n + x) / (n + 1), the
 * reference updated before d is taken). An atom of the group without a
 * reference (created later) gets its current position, as LAMMPS's
 * set_arrays. Evaluated once per step: thermo and variables asking for
 * several elements on one step see one evaluation. References are not
 * written to restart files. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "tag_ref.h"

struct msd {
    int comflag, avflag;
    struct tag_ref ref;     /* reference positions by tag */
    bigint naverage;
    bigint nmsd;
    double masstotal;
    int inited, cached;
    bigint cache_step;
};

static void msd_destroy(struct compute *c)
{
    struct msd *m = c->data;
    if (m) {
        tag_ref_free(&m->ref);
    }
    free(m);
    c->data = NULL;
}

static void msd_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    struct msd *m = gr_calloc(g, 1, sizeof *m);
    c->data = m;
    for (int i = 0; i < argc; i += 2) {
        if (strcmp(argv[i], "com") && strcmp(argv[i], "average"))
            gr_error(g, "compute msd: unknown keyword '%.64s' (expected com or average)",
                     argv[i]);
        arg_need(g, argc, i, 1, argv[i]);
        int yes = arg_yesno(g, argv[i + 1], argv[i]);
        if (argv[i][0] == 'c')
            m->comflag = yes;
        else
            m->avflag = yes;
    }
    if (g->groups.dyn[c->igroup].on)
        gr_error(g, "compute msd is not compatible with dynamic groups (group %s)",
                 g->groups.name[c->igroup]);
    const struct atoms *a = &g->atoms;
    tag_ref_reserve(g, &m->ref, a->maxtag);
    double cm[3] = {0, 0, 0};
    if (m->comflag)
        group_xcm(g, c->igroup, group_mass(g, c->igroup), cm);
    for (int i = 0; i < a->n; i++) {
        int64_t t = a->tag[i];
        tag_ref_reserve(g, &m->ref, t);
        m->ref.have[t] = 1;
        double *r = m->ref.v + 3 * t;
        if (a->mask[i] & c->groupbit) {
            domain_unmap(g, a->x + 3 * i, a->image + 3 * i, r);
            for (int d = 0; d < 3; d++)
                r[d] -= cm[d];
        } else {
            r[0] = r[1] = r[2] = 0.0;
        }
    }
    c->vector_flag = 1;
    c->size_vector = 4;
    c->extvector = 0;
}

static void msd_init(struct gravel *g, struct compute *c)
{
    struct msd *m = c->data;
    m->nmsd = group_count(g, c->igroup);
    m->masstotal = group_mass(g, c->igroup);
    m->cached = 0;
    m->inited = 1;
}

static void msd_vector(struct gravel *g, struct compute *c)
{
    struct msd *m = c->data;
    if (m->cached && m->cache_step == g->step)
        return; /* c->vector holds this step's values */
    if (!m->inited)
        msd_init(g, c);
    const struct atoms *a = &g->atoms;
    double cm[3] = {0, 0, 0};
    if (m->comflag)
        group_xcm(g, c->igroup, m->masstotal, cm);
    double navfac = 0.0;
    if (m->avflag) {
        m->naverage++;
        navfac = 1.0 / (double)(m->naverage + 1);
    }
    double s[4] = {0, 0, 0, 0};
    const int *order = atoms_tag_order(g);
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!(a->mask[i] & c->groupbit))
            continue;
        int64_t t = a->tag[i];
        tag_ref_reserve(g, &m->ref, t);
        double *r = m->ref.v + 3 * t;
        if (!m->ref.have[t]) {
            memcpy(r, a->x + 3 * i, 3 * sizeof *r);
            m->ref.have[t] = 1;
        }
        double u[3];
        domain_unmap(g, a->x + 3 * i, a->image + 3 * i, u);
        for (int d = 0; d < 3; d++)
            u[d] -= cm[d];
        if (m->avflag)
            for (int d = 0; d < 3; d++)
                r[d] = (r[d] * (double)m->naverage + u[d]) * navfac;
        double dx = u[0] - r[0], dy = u[1] - r[1], dz = u[2] - r[2];
        s[0] += dx * dx;
        s[1] += dy * dy;
        s[2] += dz * dz;
        s[3] += dx * dx + dy * dy + dz * dz;
    }
    for (int k = 0; k < 4; k++)
        c->vector[k] = m->nmsd ? s[k] / (double)m->nmsd : s[k];
    m->cached = 1;
    m->cache_step = g->step;
}

/* Run setup: the group's count is taken at the first evaluation of the run
 * (the setup's output), when every atom is on the host (several MPI ranks:
 * gathered, par.h). */
static void msd_setup(struct gravel *g, struct compute *c)
{
    (void)g;
    struct msd *m = c->data;
    m->inited = 0;
}

const struct compute_style compute_style_msd = {
    .name = "msd",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = msd_create,
    .init = msd_setup,
    .vector = msd_vector,
    .destroy = msd_destroy,
};
