/* fix_ave_atom.c - `fix ID group ave/atom Nevery Nrepeat Nfreq value ...`:
 * per-atom time averages, as LAMMPS's fix ave/atom: every Nevery steps,
 * Nrepeat samples ending on each multiple of Nfreq (ave_common.h's
 * schedule; a sample at a run's setup when its first step is due), each
 * atom of the group adds its values; the Nfreq step divides the sums by
 * Nrepeat. Values: x y z vx vy vz fx fy fz (the device's, positions wrapped
 * into the box as gravel keeps them at every step), c_ID / c_ID[I] of a
 * per-atom compute (c_ID[*] expands to its columns), f_ID / f_ID[I] of a
 * fix's per-atom output, v_name of an atom-style variable. Output: a
 * per-atom vector (one value) or array (one column per value) holding the
 * last complete average, 0 for atoms outside the group and before the
 * first Nfreq step. The sums are kept by atom ID, so they follow the atoms
 * through re-sorts; an atom that appears mid-average starts from 0, as in
 * LAMMPS. */
#include <stdlib.h>
#include <string.h>

#include "ave_common.h"
#include "compute.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "peratom_input.h"
#include "ref.h"

#define WHO "fix ave/atom"

struct ave_atom {
    struct ave_sched s;
    int nvalues;
    struct peratom_input *v;
    double *sum, *avg;          /* [cap * nvalues] by atom ID */
    int64_t cap;
    double *out;                /* peratom_values, host order */
};

static void destroy(struct fix *f)
{
    struct ave_atom *a = f->data;
    if (a) {
        free(a->v);
        free(a->sum);
        free(a->avg);
        free(a->out);
    }
    free(a);
    f->data = NULL;
}

static void add_value(struct gravel *g, struct ave_atom *a, const char *ref)
{
    a->v = gr_realloc(g, a->v, (size_t)(a->nvalues + 1) * sizeof *a->v);
    peratom_input_parse(g, ref, PERATOM_XVF, &a->v[a->nvalues++],
                        "x y z vx vy vz fx fy fz, c_ID, c_ID[I], f_ID, f_ID[I], v_name", WHO);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, WHO " needs Nevery Nrepeat Nfreq and at least one value");
    struct ave_atom *a = gr_calloc(g, 1, sizeof *a);
    f->data = a;
    ave_sched_parse(g, &a->s, argv, WHO);
    for (int i = 3; i < argc; i++) {
        char prefix[GR_NAMELEN + 2];
        int lo, hi;
        if (!ref_wildcard(g, argv[i], 1, prefix, &lo, &hi, WHO)) {
            add_value(g, a, argv[i]);
            continue;
        }
        for (int k = lo; k <= hi; k++) {
            char ref[GR_NAMELEN + 24];
            snprintf(ref, sizeof ref, "%s[%d]", prefix, k);
            add_value(g, a, ref);
        }
    }
    f->hooks = HOOK_END_OF_STEP;
    f->peratom_flag = 1;
    f->size_peratom_cols = a->nvalues == 1 ? 0 : a->nvalues;
    f->peratom_freq = a->s.nfreq;
    ave_sched_reset(g, &a->s);
}

static void init(struct gravel *g, struct fix *f)
{
    struct ave_atom *a = f->data;
    for (int j = 0; j < a->nvalues; j++)
        peratom_input_check(g, &a->v[j], WHO, f->id);
    if (a->s.nvalid < g->step)
        ave_sched_reset(g, &a->s);
}

/* room for atom ID t in the sums */
static void reserve(struct gravel *g, struct ave_atom *a, int64_t t)
{
    if (t < a->cap)
        return;
    int64_t cap = a->cap ? a->cap : 64;
    while (cap <= t)
        cap *= 2;
    size_t old = (size_t)a->cap * a->nvalues, now = (size_t)cap * a->nvalues;
    a->sum = gr_realloc(g, a->sum, now * sizeof *a->sum);
    a->avg = gr_realloc(g, a->avg, now * sizeof *a->avg);
    memset(a->sum + old, 0, (now - old) * sizeof *a->sum);
    memset(a->avg + old, 0, (now - old) * sizeof *a->avg);
    a->cap = cap;
}

/* One sample on the host atoms (and the average when it closes the epoch). */
static void take(struct gravel *g, struct fix *f)
{
    struct ave_atom *a = f->data;
    run_sync_host(g);
    const struct atoms *at = &g->atoms;
    const int nv = a->nvalues;
    for (int i = 0; i < at->n; i++)
        reserve(g, a, at->tag[i]);
    if (a->s.irepeat == 0)
        memset(a->sum, 0, (size_t)a->cap * nv * sizeof *a->sum);
    for (int j = 0; j < nv; j++) {
        int stride;
        double *owned;
        const double *p = peratom_input_values(g, &a->v[j], &stride, &owned, WHO);
        for (int i = 0; i < at->n; i++)
            if (at->mask[i] & f->groupbit)
                a->sum[(size_t)at->tag[i] * nv + j] += p[(size_t)i * stride];
        free(owned);
    }
    if (!ave_sched_next(g, &a->s))
        return;
    for (size_t k = 0; k < (size_t)a->cap * nv; k++)
        a->avg[k] = a->sum[k] / a->s.nrepeat;
}

static void sample(struct gravel *g, struct fix *f)
{
    struct ave_atom *a = f->data;
    ave_sample(g, f, &a->s, WHO, take);
}

static const double *peratom_values(struct gravel *g, struct fix *f)
{
    struct ave_atom *a = f->data;
    const struct atoms *at = &g->atoms;
    const int nv = a->nvalues;
    a->out = gr_realloc(g, a->out, (size_t)(at->n > 0 ? at->n : 1) * nv * sizeof *a->out);
    for (int i = 0; i < at->n; i++)
        for (int j = 0; j < nv; j++)
            a->out[(size_t)i * nv + j] =
                at->tag[i] < a->cap ? a->avg[(size_t)at->tag[i] * nv + j] : 0.0;
    return a->out;
}

const struct fix_style fix_style_ave_atom = {
    .name = "ave/atom",
    .flags = FIX_OUTPUT,
    .create = create,
    .init = init,
    .setup = sample, /* LAMMPS's setup(): a sample when the run's first step is due */
    .end_of_step = sample,
    .destroy = destroy,
    .peratom_values = peratom_values,
};
