/* pressure.c - the pressure from the granular pair virial (pressure.h). */
#include "pressure.h"

#include <stdlib.h>

#include "atoms.h"
#include "engine.h"
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
        e->virial = eng_alloc(g, (size_t)e->cap * 3 * e->rsz, "per-particle virial");
        e->virial_cap = e->cap;
    }
    return e->virial;
}

void pressure_virial(struct gravel *g, double w[3])
{
    w[0] = w[1] = w[2] = 0.0;
    struct engine *e = g->eng;
    if (!e || !e->active || !e->k_pair || !e->k_virial)
        return;
    const struct nbr_list *l = nbr_list(g);
    int n = e->a.n;
    if (n <= 0)
        return;
    pressure_scratch(g);
    cl_kernel k = e->k_virial;
    int a = 0;
    eng_arg_int(g, k, a++, n);
    eng_arg_mem(g, k, a++, l->nlist);
    eng_arg_int(g, k, a++, l->maxn);
    eng_arg_mem(g, k, a++, l->ioff);
    eng_arg_mem(g, k, a++, l->recf);
    eng_arg_mem(g, k, a++, e->a.x);
    for (int q = 0; q < 3; q++)
        eng_arg_real(g, k, a++, l->L[q]);
    eng_arg_mem(g, k, a++, e->virial);
    eng_launch(g, k, (size_t)n);
    double *wi = gr_malloc(g, (size_t)n * 3 * sizeof(double));
    eng_read_reals(g, e->virial, 3 * (size_t)n, wi);
    const int *order = eng_tag_order(g); /* sum in tag order */
    for (int k2 = 0; k2 < n; k2++)
        for (int d = 0; d < 3; d++)
            w[d] += wi[3 * order[k2] + d];
    free(wi);
}

double pressure_parts(struct gravel *g, struct temp_state *t, int keflag, int virialflag)
{
    const struct domain *d = &g->dom;
    int dim = d->dimension;
    double w[3] = {0, 0, 0};
    if (virialflag)
        pressure_virial(g, w);
    double vol = (d->hi[0] - d->lo[0]) * (d->hi[1] - d->lo[1]);
    if (dim == 3)
        vol *= d->hi[2] - d->lo[2];
    double ke = 0.0;
    if (keflag) {
        double temp = temp_scalar(g, t);
        ke = temp_dof(g, t) * temp_boltz(g) * temp;
    }
    double nktv2p = 1.0;
    double virial = dim == 3 ? w[0] + w[1] + w[2] : w[0] + w[1];
    return (ke + virial) / dim * (1.0 / vol) * nktv2p;
}

double pressure_scalar(struct gravel *g, struct temp_state *t)
{
    return pressure_parts(g, t, 1, 1);
}
