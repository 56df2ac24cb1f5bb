/* fix_aveforce.c - `fix ID group aveforce fx fy fz [region ID]`: LAMMPS's fix aveforce:
 * after the forces of the step (post_force, and at a run's setup), each
 * given component of the force on every atom of the group becomes the
 * group's average force in it plus the value (a number, or an equal-style
 * v_name evaluated then); NULL leaves that component. The average is summed
 * over the atoms in tag order on the host (the forces before the fix are
 * read back every step: a round trip per step, n atoms x 3 values). With
 * `region ID`, the group's atoms inside the region at the step (LAMMPS).
 * Global vector (f_ID[1..3], extensive): their total force before the fix.
 * Atom-style variables are refused, as LAMMPS refuses them. */
#include <stdlib.h>

#include "device.h"
#include "error.h"
#include "fix.h"
#include "force_values.h"
#include "par_sum.h"

#define WHO "fix aveforce"

struct aveforce {
    struct force_values fv;   /* the values added to the average */
    double sum[3];            /* the group's force before the fix at the last step */
};

static void destroy(struct fix *f)
{
    struct aveforce *a = f->data;
    if (a) {
        force_values_free(&a->fv);
        free(a);
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct aveforce *a = gr_calloc(g, 1, sizeof *a);
    f->data = a;
    force_values_create(g, f, &a->fv, argc, argv, WHO);
}

static void init(struct gravel *g, struct fix *f)
{
    struct aveforce *a = f->data;
    force_values_init(g, f, &a->fv, WHO);
}

/* The selected atoms' total force now and their count, in tag order. */
static void group_force(struct gravel *g, struct fix *f, const struct force_values *fv,
                        double sum[3], double *count)
{
    struct engine *e = g->eng;
    const int n = e->a.n;
    const int *ord = eng_tag_order(g);
    double *o = gr_malloc(g, 3 * (size_t)n * sizeof *o);
    cl_uint *mask = gr_malloc(g, (size_t)n * sizeof *mask);
    eng_read_reals(g, f->peratom, 3 * (size_t)n, o);
    eng_read(g, e->a.mask, 0, (size_t)n * sizeof *mask, mask);
    struct par_sum s[4] = {{0}};
    for (int k = 0; k < n; k++) {
        const int i = ord[k];
        if (!force_values_took(f, fv, mask, i))
            continue;
        for (int d = 0; d < 3; d++)
            par_sum_add(g, &s[d], e->tag_seen[i], o[3 * i + d]);
        par_sum_add(g, &s[3], e->tag_seen[i], 1.0);
    }
    free(o);
    free(mask);
    for (int d = 0; d < 3; d++)
        sum[d] = par_sum_total(g, &s[d]);
    *count = par_sum_total(g, &s[3]);
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct aveforce *a = f->data;
    force_values_prepare(g, f, &a->fv);
    force_values_launch(g, f, &a->fv, 0, a->fv.v, 0); /* keeps the forces before the fix */
    double count, v[3];
    group_force(g, f, &a->fv, a->sum, &count);
    if (count == 0)
        return;
    for (int d = 0; d < 3; d++)
        v[d] = a->sum[d] / count + a->fv.v[d];
    force_values_launch(g, f, &a->fv, a->fv.on, v, 0);
}

static double vector(struct gravel *g, struct fix *f, int i)
{
    (void)g;
    const struct aveforce *a = f->data;
    return a->sum[i - 1];
}

const struct fix_style fix_style_aveforce = {
    .name = "aveforce",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
    .size_vector = 3,
    .vector = vector,
};
