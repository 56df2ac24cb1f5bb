/* pressure.c - the pressure from the granular pair virial (pressure.h). */
#include "pressure.h"
#include "par.h"
#include "par_sum.h"

#include <stdlib.h>
#include <string.h>

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

/* The pair virial of each of the n device particles (pair_virial), 6
 * doubles each in device order, malloc'd; NULL when there is none (no pair
 * style, outside a run). */
static double *virial_of_atoms(struct gravel *g, int n)
{
    struct engine *e = g->eng;
    if (!e || !e->active || !e->k_pair || !e->k_virial)
        return NULL;
    double *wi = gr_malloc(g, ((size_t)n + 1) * 6 * sizeof(double));
    if (n <= 0)
        return wi;
    const struct nbr_list *l = nbr_list(g);
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
    eng_launch(g, k, (size_t)n);
    eng_read_reals(g, e->virial, 6 * (size_t)n, wi);
    return wi;
}

/* w = the sum of the n particles' virials wi, in tag order over every
 * rank's atoms */
static void virial_sum(struct gravel *g, const double *wi, int n, double w[6])
{
    struct engine *e = g->eng;
    const int *order = eng_tag_order(g);
    for (int d = 0; d < 6; d++) {
        struct par_sum s = {0};
        for (int k2 = 0; k2 < n; k2++)
            par_sum_add(g, &s, e->tag_seen[order[k2]], wi[6 * order[k2] + d]);
        w[d] = par_sum_total(g, &s);
    }
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
    int n = e->a.n;
    if (n <= 0 && !par_on(g)) /* a rank without atoms still joins the sum */
        return;
    double *wi = virial_of_atoms(g, n);
    virial_sum(g, wi, n, w);
    free(wi);
}

void pressure_virial_atoms(struct gravel *g, double *w)
{
    struct engine *e = g->eng;
    int n = e && e->active ? e->a.n : 0;
    if (n > 0 && e->virial_snap_step == g->step && e->virial_snap_atoms) {
        memcpy(w, e->virial_snap_atoms, 6 * (size_t)n * sizeof(double));
        return;
    }
    double *wi = virial_of_atoms(g, n);
    for (size_t k = 0; k < 6 * (size_t)g->atoms.n; k++)
        w[k] = wi && k < 6 * (size_t)n ? wi[k] : 0.0;
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
    int n = e->a.n;
    free(e->virial_snap_atoms); /* per particle too, for compute stress/atom */
    e->virial_snap_atoms = virial_of_atoms(g, n);
    for (int d = 0; d < 6; d++)
        e->virial_snap[d] = 0.0;
    if (e->virial_snap_atoms && (n > 0 || par_on(g)))
        virial_sum(g, e->virial_snap_atoms, n, e->virial_snap);
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
