/* fix_property_atom_tracer.c - LIGGGHTS's `fix ID group property/atom/tracer
 * region_mark R mark_step s [marker_style dirac|heaviside|none]
 * [check_mark_every n]`: a per-atom marker (f_ID; 0 or 1) that the fix sets
 * to 1 for the group's atoms in region R, at the end of every n-th step (a
 * multiple of n, default 10) from step s on: once, at the first such step
 * (dirac), or at every such step (heaviside: atoms passing through R later
 * are marked too); none marks nothing. Its global scalar is the number of
 * atoms marked since the scalar was last read. compute nparticles/tracer/
 * region counts (and by default unmarks) them: residence-time
 * distributions. The markers are a custom per-atom property named ID
 * (d_ID: dump custom, set, restart files keep them), as LIGGGHTS keeps them
 * in a fix property/atom of that name. A marker counts as set when it is
 * within 1e-5 of 1 (LIGGGHTS's compDouble). One process. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_custom.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "fix_property_atom_tracer.h"
#include "region.h"

#define WHO "fix property/atom/tracer"

enum tracer_style { TR_DIRAC, TR_HEAVISIDE, TR_NONE };

struct tracer {
    char region[GR_NAMELEN];
    bigint mark_step;
    int style, every;
    int first_mark;             /* dirac: not marked yet */
    bigint nmarked, nmarked_last;
    double *out;                /* peratom_values */
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (!custom_name_ok(f->id))
        gr_error(g, WHO ": its ID '%s' names the per-atom marker and must be letters, digits "
                    "and underscores", f->id);
    struct tracer *t = gr_calloc(g, 1, sizeof *t);
    f->data = t;
    t->mark_step = -1;
    t->every = 10;
    t->style = TR_DIRAC;
    for (int i = 0; i < argc; i += 2) {
        const char *kw = argv[i];
        if (i + 1 >= argc)
            gr_error(g, WHO ": not enough arguments for '%.64s'", kw);
        const char *v = argv[i + 1];
        if (!strcmp(kw, "region_mark")) {
            if (!region_find(g, v))
                gr_error(g, WHO ": region ID '%.64s' does not exist", v);
            snprintf(t->region, sizeof t->region, "%s", v);
        } else if (!strcmp(kw, "mark_step")) {
            t->mark_step = arg_bigint(g, v, "mark_step");
            if (t->mark_step < 0)
                gr_error(g, WHO ": mark_step > 0 required, got %s", v);
        } else if (!strcmp(kw, "marker_style")) {
            if (!strcmp(v, "dirac"))
                t->style = TR_DIRAC;
            else if (!strcmp(v, "heaviside"))
                t->style = TR_HEAVISIDE;
            else if (!strcmp(v, "none"))
                t->style = TR_NONE;
            else
                gr_error(g, WHO ": expecting 'heaviside' or 'dirac' after keyword "
                            "'marker_style', got '%.64s'", v);
        } else if (!strcmp(kw, "check_mark_every")) {
            t->every = arg_int(g, v, "check_mark_every");
            if (t->every < 1)
                gr_error(g, WHO ": check_mark_every > 0 required, got %s", v);
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s' (region_mark mark_step marker_style "
                        "check_mark_every)", kw);
        }
    }
    if (!t->region[0])
        gr_error(g, WHO ": expecting keyword 'region_mark'");
    if (t->mark_step < 0)
        gr_error(g, WHO ": expecting keyword 'mark_step'");
    t->first_mark = t->mark_step >= g->step; /* LIGGGHTS: a mark step past is done */
    const struct custom_def def = {f->id, 0, 0, NULL};
    custom_define(g, f->id, 1, &def);
    f->hooks = HOOK_END_OF_STEP;
    f->peratom_flag = 1;
    f->size_peratom_cols = 0;
}

static void init(struct gravel *g, struct fix *f)
{
    const struct tracer *t = f->data;
    if (!region_find(g, t->region))
        gr_error(g, WHO " %s: region ID '%s' does not exist", f->id, t->region);
    /* a run with nothing left to mark keeps no per-step host hook (its steps
     * stay fused) */
    const int done = t->style == TR_NONE || (t->style == TR_DIRAC && !t->first_mark);
    f->hooks = done ? 0 : HOOK_END_OF_STEP;
}

static struct custom_ref marker_ref(struct gravel *g, const struct fix *f)
{
    const int k = custom_find(&g->atoms, f->id);
    if (k < 0)
        gr_error(g, WHO " %s: its marker property is gone", f->id);
    return (struct custom_ref){k, 0};
}

int tracer_marked(double marker) { return marker == 1.0 || fabs(marker - 1.0) < 1e-5; }

static void end_of_step(struct gravel *g, struct fix *f)
{
    struct tracer *t = f->data;
    if (g->step % t->every || g->step < t->mark_step || t->style == TR_NONE ||
        (t->style == TR_DIRAC && !t->first_mark))
        return;
    run_sync_host(g);
    struct atoms *a = &g->atoms;
    struct region *r = region_get(g, t->region);
    region_prematch(g, r);
    const struct custom_ref ref = marker_ref(g, f);
    bigint n = 0;
    for (int i = 0; i < a->n; i++) {
        double *m = custom_at(a, ref, i);
        if ((a->mask[i] & f->groupbit) && !tracer_marked(*m) && region_match(r, a->x + 3 * i)) {
            *m = 1.0;
            n++;
        }
    }
    if (n)
        eng_put_custom(g);
    t->nmarked += n;
    t->first_mark = 0;
}

static double scalar(struct gravel *g, struct fix *f)
{
    (void)g;
    struct tracer *t = f->data;
    const bigint n = t->nmarked - t->nmarked_last;
    t->nmarked_last = t->nmarked;
    return (double)n;
}

static const double *peratom_values(struct gravel *g, struct fix *f)
{
    struct tracer *t = f->data;
    const struct atoms *a = &g->atoms;
    const struct custom_ref ref = marker_ref(g, f);
    t->out = gr_realloc(g, t->out, (size_t)(a->n > 0 ? a->n : 1) * sizeof *t->out);
    for (int i = 0; i < a->n; i++)
        t->out[i] = custom_get(a, ref, i);
    return t->out;
}

static void unfix(struct gravel *g, struct fix *f) { custom_remove_fix(g, f->id); }

static void destroy(struct fix *f)
{
    struct tracer *t = f->data;
    if (t)
        free(t->out);
    free(t);
    f->data = NULL;
}

const struct fix_style fix_style_property_atom_tracer = {
    .name = "property/atom/tracer",
    .create = create,
    .init = init,
    .end_of_step = end_of_step,
    .scalar = scalar,
    .peratom_values = peratom_values,
    .unfix = unfix,
    .destroy = destroy,
};
