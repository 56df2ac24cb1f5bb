/* fix_insert_rate_region.c - `fix ID group insert/rate/region seed S
 * distributiontemplate D nparticles N|INF | mass M  particlerate R |
 * massrate Q  insert_every N  region R ...`: insert at a rate into region R
 * every N steps (LIGGGHTS-PUBLIC 3.8 FixInsertRateRegion). Per step
 * int(R N dt + u) particles (u a draw of the fix's stream), capped by the
 * total; massrate Q gives R = Q / E[mass], mass M gives N = int(M /
 * E[mass]). n maxattempt tries per step. The insertion step itself:
 * fix_insert.c; the region keywords as fix insert/pack (volume, count and
 * mass targets are not used). Full contract:
 * doc/styles/fix_insert_rate_region.md. */
#include <limits.h>
#include <math.h>

#include "error.h"
#include "fix.h"
#include "fix_insert.h"
#include "region.h"

#define WHO "fix insert/rate/region"

static void properties(struct gravel *g, struct insert *in)
{
    insert_region_setup(g, in);
    if (in->insert_every < 0)
        gr_error(g, WHO ": must define 'insert_every'");
    if (in->insert_every == 0)
        gr_error(g, WHO ": 'insert_every' = once not allowed");
    if (in->volfrac > 0. || in->ntotal_region > 0 || in->masstotal_region > 0.)
        gr_error(g, WHO ": volumefraction_region, particles_in_region and mass_in_region are "
                    "insert/pack keywords (use nparticles or mass with a rate)");
    insert_rate_counts(g, in, 0.);
}

static int ninsert_this(struct gravel *g, struct insert *in)
{
    insert_region_check_box(g, in);
    return insert_ninsert_rate(g, in);
}

static int maxtry(const struct insert *in, int n)
{
    return in->check_ol ? insert_maxtry(in, n) : INT_MAX; /* no check: one try each */
}

static int reserve(struct gravel *g, struct insert *in, bigint nsteps)
{
    (void)nsteps;
    return insert_rate_reserve(g, in);
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
}

const struct fix_style fix_style_insert_rate_region = {
    .name = "insert/rate/region",
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
