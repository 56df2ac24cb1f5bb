/* pressure.c - the pressure from the granular pair virial (pressure.h). */
#include "pressure.h"
#include "par.h"
#include "par_sum.h"

#include <stdlib.h>

#include "atoms.h"
#include "device.h"
#include "error.h"
#include "neighbor.h"
#include "temperature.h"

cl_mem pressure_scratch(struct gravel *g)
{
    struct engine *e = g->eng;
    if (e->a.n > e->virial_cap || !e->virial) {
        if (e->virial)
            clReleaseMemObject(e->virial);
        e->virial = NULL;
        e->virial_cap = 0;
        e->virial = eng_alloc(g, (size_t)e->cap * 6 * e->rsz, "per-particle virial");
        e->virial_cap = e->cap;
    }
    return e->virial;
}

void pressure_virial(struct gravel *g, double w[6])
{
    for (int d = 0; d < 6; d++)
        w[d] = 0.0;
    struct engine *e = g->eng;
    if (!e || !e->active || !e->k_pair || !e->k_virial)
        return;
    if (e->virial_snap_step == g->step) {
        for (int d = 0; d < 6; d++)
            w[d] = e->virial_snap[d];
        return;
    }
    const struct nbr_list *l = nbr_list(g);
    int n = e->a.n;
    if (n <= 0 && !par_on(g)) /* a rank without atoms still joins the sum */
        return;
    pressure_scratch(g);
    cl_kernel k = e->k_virial;
    int a = 0;
    eng_arg_int(g, k, a++, n);
    eng_arg_mem(g, k, a++, l->nlist);
    eng_arg_int(g, k, a++, l->maxn);
    eng_arg_mem(g, k, a++, l->ioff);
    eng_arg_mem(g, k, a++, l->coff);
    eng_arg_mem(g, k, a++, l->pcon);
    eng_arg_mem(g, k, a++, l->rec);
    eng_arg_mem(g, k, a++, e->a.x);
    a = nbr_arg_box(g, k, a, l);
    eng_arg_mem(g, k, a++, e->virial);
    if (n > 0)
        eng_launch(g, k, (size_t)n);
    double *wi = gr_malloc(g, ((size_t)n + 1) * 6 * sizeof(double));
    eng_read_reals(g, e->virial, 6 * (size_t)n, wi);
    const int *order = eng_tag_order(g); /* sum in tag order, every rank's atoms */
    for (int d = 0; d < 6; d++) {
        struct par_sum s = {0};
        for (int k2 = 0; k2 < n; k2++)
            par_sum_add(g, &s, e->tag_seen[order[k2]], wi[6 * order[k2] + d]);
        w[d] = par_sum_total(g, &s);
    }
    free(wi);
}

double pressure_parts(struct gravel *g, struct temp_state *t, int keflag, int virialflag)
{
    const struct domain *d = &g->dom;
    int dim = d->dimension;
    double w[6] = {0, 0, 0, 0, 0, 0};
    if (virialflag)
        pressure_virial(g, w);
    double vol = pressure_volume(g);
    double ke = 0.0;
    if (keflag) {
        double temp = temp_scalar(g, t);
        ke = temp_dof(g, t) * temp_boltz(g) * temp;
    }
    double nktv2p = 1.0;
    double virial = dim == 3 ? w[0] + w[1] + w[2] : w[0] + w[1];
    return (ke + virial) / dim * (1.0 / vol) * nktv2p;
}

void pressure_virial_snapshot(struct gravel *g)
{
    struct engine *e = g->eng;
    if (!e || !e->active || e->virial_snap_step == g->step)
        return;
    double w[6];
    pressure_virial(g, w);
    for (int d = 0; d < 6; d++)
        e->virial_snap[d] = w[d];
    e->virial_snap_step = g->step;
}

double pressure_volume(const struct gravel *g)
{
    const struct domain *d = &g->dom;
    double vol = (d->hi[0] - d->lo[0]) * (d->hi[1] - d->lo[1]);
    if (d->dimension == 3)
        vol *= d->hi[2] - d->lo[2];
    return vol;
}

void pressure_tensor(struct gravel *g, struct temp_state *t, int keflag, int virialflag,
                     double out[6])
{
    double w[6] = {0, 0, 0, 0, 0, 0}, ke[6] = {0, 0, 0, 0, 0, 0};
    if (virialflag)
        pressure_virial(g, w);
    if (keflag)
        temp_vector(g, t, ke);
    double inv = 1.0 / pressure_volume(g), nktv2p = 1.0;
    for (int d = 0; d < 6; d++)
        out[d] = (ke[d] + w[d]) * inv * nktv2p;
    if (g->dom.dimension == 2)
        out[2] = out[4] = out[5] = 0.0;
}

double pressure_scalar(struct gravel *g, struct temp_state *t)
{
    return pressure_parts(g, t, 1, 1);
}
