/* lanes_tune.c - the lane width of the contact and particle kernels,
 * measured in the run (see lanes_tune.h). */
#include "lanes_tune.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "wall_clock.h"

/* Whether stage s has both forms in this run. */
static int two_forms(const struct engine *e, enum lanes_stage s)
{
    return s == LANES_PAIR ? e->k_pair && e->k_pair1 : e->k_gather1 != NULL;
}

void lanes_begin(struct gravel *g, bigint nsteps)
{
    struct engine *e = g->eng;
    struct lanes_tune *t = &e->lanes;
    const char *env = getenv("GRAVEL_LANES_TUNE");
    memset(t, 0, sizeof *t);
    t->wide[LANES_PAIR] = t->wide[LANES_ATOM] = 1;
    const char *fixed = getenv("GRAVEL_LANES");
    t->always = env && !strcmp(env, "always");
    int off = (env && !strcmp(env, "0")) || (fixed && *fixed && !t->always);
    int both = two_forms(e, LANES_PAIR) || two_forms(e, LANES_ATOM);
    t->trial = both && !off && (t->always || nsteps >= LANES_MIN_STEPS) ? 0 : -1;
}

void lanes_step(struct gravel *g)
{
    struct lanes_tune *t = &g->eng->lanes;
    t->measured = 0;
    if (t->trial < 0)
        return;
    /* even trials the lane forms, odd ones the others */
    const int wide = t->trial % 2 == 0;
    for (int s = 0; s < LANES_STAGES; s++)
        t->wide[s] = wide || !two_forms(g->eng, (enum lanes_stage)s);
    if (t->always) {
        t->trial = (t->trial + 1) % 2;
        return;
    }
    t->measured = 1;
    eng_finish(g);
    t->t0 = wall_clock();
}

static int by_value(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

static double median(float *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, by_value);
    return n % 2 ? v[n / 2] : 0.5 * ((double)v[n / 2 - 1] + (double)v[n / 2]);
}

/* After the last trial: each stage's form, and the report. */
static void choose(struct gravel *g)
{
    struct engine *e = g->eng;
    struct lanes_tune *t = &e->lanes;
    static const char *const name[LANES_STAGES] = {"pair_contacts", "pair_gather"};
    static const char *const item[LANES_STAGES] = {"contact", "particle"};
    const int width[LANES_STAGES] = {e->pair_lw, e->atom_lw};
    char *line = t->report;
    const size_t size = sizeof t->report;
    int len = snprintf(line, size, "Lanes measured over %d steps:", 2 * LANES_TRIALS);
    for (int s = 0; s < LANES_STAGES; s++) {
        if (!two_forms(e, (enum lanes_stage)s))
            continue;
        double wide = median(t->sec[s][1], LANES_TRIALS);
        double one = median(t->sec[s][0], LANES_TRIALS);
        t->wide[s] = !(one < (1.0 - LANES_MARGIN) * wide);
        if (len < (int)size)
            len += snprintf(line + len, size - (size_t)len,
                            "%s %s %d %s%s per work-item (median %.0f us; %d per work-item "
                            "%.0f us)", s > 0 && two_forms(e, LANES_PAIR) ? "," : "", name[s],
                            t->wide[s] ? width[s] : 1, item[s], t->wide[s] ? "s" : "",
                            1e6 * (t->wide[s] ? wide : one), t->wide[s] ? 1 : width[s],
                            1e6 * (t->wide[s] ? one : wide));
    }
}

void lanes_done(struct gravel *g, enum lanes_stage s)
{
    struct lanes_tune *t = &g->eng->lanes;
    if (!t->measured)
        return;
    eng_finish(g);
    double t1 = wall_clock();
    t->sec[s][t->trial % 2 == 0][t->trial / 2] = (float)(t1 - t->t0);
    t->t0 = t1;
    if (s != LANES_ATOM)
        return;
    t->measured = 0;
    if (++t->trial == 2 * LANES_TRIALS) {
        t->trial = -1;
        choose(g);
    }
}

cl_kernel lanes_pair_kernel(struct gravel *g, size_t *per_item)
{
    struct engine *e = g->eng;
    int wide = !e->k_pair1 || e->lanes.wide[LANES_PAIR];
    *per_item = wide ? (size_t)e->pair_lw : 1;
    return wide ? e->k_pair : e->k_pair1;
}

cl_kernel lanes_gather_kernel(struct gravel *g, int tail, size_t *per_item)
{
    struct engine *e = g->eng;
    int wide = !e->k_gather1 || e->lanes.wide[LANES_ATOM];
    *per_item = wide ? (size_t)e->atom_lw : 1;
    if (tail)
        return wide ? e->k_tail : e->k_tail1;
    return wide ? e->k_gather : e->k_gather1;
}

const char *lanes_report(const struct gravel *g)
{
    return g->eng && g->eng->lanes.report[0] ? g->eng->lanes.report : NULL;
}
