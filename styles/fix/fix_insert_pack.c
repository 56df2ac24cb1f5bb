/* fix_insert_pack.c - `fix ID group insert/pack seed S distributiontemplate
 * D insert_every once|N region R volumefraction_region F |
 * particles_in_region N | mass_in_region M [overlapcheck yes|no] [all_in
 * yes|no] [vel constant|uniform|gaussian ...] [omega constant ...] ...`:
 * fill region R up to a target at each insertion step (LIGGGHTS-PUBLIC 3.8
 * FixInsertPack). The count of a step: particles_in_region: N minus the
 * atoms whose centre is in R; volumefraction_region: int((F V - v) /
 * E[volume] + u), V the Monte-Carlo region volume, v the volume of the
 * atoms in R; mass_in_region: int((M - m) / E[mass] + u) (u a draw of the
 * fix's stream). Tries per step: n maxattempt / (1 - ratio of the target
 * already in R). The insertion step itself: fix_insert.c. Full contract:
 * doc/styles/fix_insert_pack.md. */
#include <limits.h>
#include <math.h>

#include "atoms.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_insert.h"
#include "par.h"
#include "par_sum.h"
#include "region.h"

#define WHO "fix insert/pack"

static void properties(struct gravel *g, struct insert *in)
{
    insert_region_setup(g, in);
    if (in->insert_every < 0)
        gr_error(g, WHO ": must define 'insert_every'");
    if (in->ninsert > 0 || in->massinsert > 0.)
        gr_error(g, WHO ": specifying 'nparticles' or 'mass' not allowed");
    if (in->nflowrate > 0. || in->massflowrate > 0.)
        gr_error(g, WHO ": specifying 'nflowrate' or 'massflowrate' not allowed");
    int n_defined = (in->volfrac > 0.) + (in->ntotal_region > 0) + (in->masstotal_region > 0.);
    if (n_defined != 1)
        gr_error(g, WHO ": must define exactly one keyword out of 'volumefraction_region', "
                    "'particles_in_region', and 'mass_in_region'");
}

static int ninsert_this(struct gravel *g, struct insert *in)
{
    if (in->warn_region)
        insert_region_check_box(g, in);
    const struct atoms *a = &g->atoms;
    const int *order = atoms_tag_order(g);
    long long np = 0;
    struct par_sum sv = {0}, sm = {0}; /* every rank's atoms, in tag order */
    region_prematch(g, in->reg);
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (region_match(in->reg, a->x + 3 * i)) {
            double r = a->radius[i];
            np++;
            par_sum_add(g, &sv, a->tag[i], 4. * M_PI / 3. * r * r * r);
            par_sum_add(g, &sm, a->tag[i], a->rmass[i]);
        }
    }
    const double vol = par_sum_total(g, &sv), mass = par_sum_total(g, &sm);
    if (par_on(g))
        np = comm_sum_ll(np);
    double n;
    if (in->volfrac > 0.) {
        n = (in->volfrac * in->region_volume - vol) / in->dist->volexpect +
            rng_park_uniform(&in->rng);
        in->insertion_ratio = vol / (in->volfrac * in->region_volume);
    } else if (in->ntotal_region > 0) {
        n = in->ntotal_region - np;
        in->insertion_ratio = (double)np / (double)in->ntotal_region;
    } else {
        n = (in->masstotal_region - mass) / in->dist->massexpect + rng_park_uniform(&in->rng);
        in->insertion_ratio = mass / in->masstotal_region;
    }
    if (n > 2e9)
        gr_error(g, WHO ": overflow in particle number calculation: inserting too many "
                    "particles in one step (%g)", n);
    int k = n > 0 ? (int)n : 0;
    if (in->insertion_ratio < 0.)
        in->insertion_ratio = 0.;
    if (in->insertion_ratio > 1.)
        in->insertion_ratio = 1.;
    return k;
}

static int maxtry(const struct insert *in, int n)
{
    if (!in->check_ol)
        return INT_MAX; /* one try each, no limit */
    if (in->insertion_ratio >= 1.)
        return n * in->maxattempt;
    double t = (double)(n * in->maxattempt) / (1. - in->insertion_ratio);
    return t < 2147483647.0 ? (int)t : 2147483647;
}

/* At most this many particles in one step: the target over the smallest
 * particle, in the region's bounds. */
static int reserve(struct gravel *g, struct insert *in, bigint nsteps)
{
    (void)nsteps;
    if (in->ntotal_region > 0)
        return in->ntotal_region;
    const struct region *r = region_find(g, in->reg_id);
    if (!r || !r->bbox)
        return 0; /* the run's setup reports it */
    double v = 1, vx = 1, e = 2 * in->dist->maxrad;
    for (int d = 0; d < 3; d++) {
        double lo = r->bbox_lo[d] > g->dom.lo[d] ? r->bbox_lo[d] : g->dom.lo[d];
        double hi = r->bbox_hi[d] < g->dom.hi[d] ? r->bbox_hi[d] : g->dom.hi[d];
        v *= hi > lo ? hi - lo : 0;
        vx *= hi > lo ? hi - lo + e : e;
    }
    double rmin = in->dist->minrad, vmin = 4. * M_PI / 3. * rmin * rmin * rmin, n;
    if (in->volfrac > 0.)
        n = in->volfrac * v / vmin;
    else {
        double dmin = INFINITY;
        for (int i = 0; i < in->dist->n; i++)
            dmin = in->dist->tpl[i]->density.min < dmin ? in->dist->tpl[i]->density.min : dmin;
        n = dmin > 0 ? in->masstotal_region / (dmin * vmin) : INFINITY;
    }
    /* without overlaps the particles fit in the bounds grown by a diameter */
    double cap = vx / vmin;
    if (in->check_ol || !(n < cap))
        n = n < cap ? n : cap;
    return n < 1e9 ? (int)n + 1 : 1000000000;
}

static const struct insert_ops ops = {
    .who = WHO,
    .keyword = insert_region_keyword,
    .properties = properties,
    .ninsert_this = ninsert_this,
    .maxtry = maxtry,
    .reserve = reserve,
    .point = insert_region_point,
    .redraw = insert_region_redraw,
    .nearby = insert_region_nearby,
    .fraction = insert_region_fraction,
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    insert_create(g, f, argc, argv, &ops);
    struct insert *in = f->data;
    in->ninsert_exists = 0;
}

const struct fix_style fix_style_insert_pack = {
    .name = "insert/pack",
    .create = create,
    .init = insert_init,
    .pre_exchange = insert_pre_exchange,
    .reserve = insert_reserve,
    .destroy = insert_destroy,
    .write_restart = insert_write_restart,
    .read_restart = insert_read_restart,
    .reset_step = insert_reset_step,
    .size_vector = 2,
    .vector = insert_vector,
};
