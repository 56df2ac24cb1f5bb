/* box_change.c - box changes during a run (box_change.h). */
#include "box_change.h"

#include <math.h>

#include "domain.h"
#include "device.h"
#include "error.h"
#include "neighbor.h"
#include "output.h"
#include "pair_energy.h"
#include "pressure.h"

void box_current(const struct gravel *g, struct box_target *b)
{
    for (int q = 0; q < 3; q++) {
        b->lo[q] = g->dom.lo[q];
        b->hi[q] = g->dom.hi[q];
    }
    b->xy = g->dom.xy;
    b->xz = g->dom.xz;
    b->yz = g->dom.yz;
}

void box_change_rates(struct gravel *g)
{
    struct engine *e = g->eng;
    if (e && e->active && e->hrate)
        eng_write_reals(g, e->hrate, 6, g->dom.h_rate);
}

void box_change_apply(struct gravel *g, const struct box_target *b, enum box_remap remap,
                      unsigned groupbit)
{
    struct domain *d = &g->dom;
    struct engine *e = g->eng;
    if (!e || !e->active)
        gr_error(g, "internal error: box_change_apply outside a run");
    for (int q = 0; q < 3; q++)
        if (!(b->lo[q] < b->hi[q]) || !isfinite(b->lo[q]) || !isfinite(b->hi[q]))
            gr_error(g, "the box change gives %c bounds %g %g (lo must be below hi) at step %lld",
                     "xyz"[q], b->lo[q], b->hi[q], (long long)g->step);
    if (!d->triclinic && (b->xy != 0 || b->xz != 0 || b->yz != 0))
        gr_error(g, "internal error: a tilt for an orthogonal box");
    /* the pressure printed this step is that of the forces, before the change */
    if (!e->setup && output_due(g, g->step)) {
        pressure_virial_snapshot(g);
        pair_energy_snapshot(g);
    }
    double olo[3], hinv[6], h0[6];
    for (int q = 0; q < 3; q++)
        olo[q] = d->lo[q];
    domain_h_inv(g, hinv);
    domain_h(g, h0);
    for (int q = 0; q < 3; q++) {
        d->lo[q] = b->lo[q];
        d->hi[q] = b->hi[q];
    }
    d->xy = b->xy;
    d->xz = b->xz;
    d->yz = b->yz;
    domain_check_tilt(g);
    if (remap == BOX_REMAP_X && e->a.n > 0) {
        double h[6];
        domain_h(g, h);
        cl_kernel k = e->k_box_remap;
        int a = 0;
        eng_arg_int(g, k, a++, e->a.n);
        eng_arg_mem(g, k, a++, e->a.x);
        eng_arg_mem(g, k, a++, e->a.mask);
        eng_arg_uint(g, k, a++, groupbit);
        for (int q = 0; q < 3; q++)
            eng_arg_coord(g, k, a++, q, olo[q]);
        for (int q = 0; q < 6; q++)
            eng_arg_real(g, k, a++, hinv[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_coord(g, k, a++, q, d->lo[q]);
        for (int q = 0; q < 6; q++)
            eng_arg_real(g, k, a++, h[q]);
        for (int q = 0; q < 6; q++)
            eng_arg_real(g, k, a++, h[q] - h0[q]);
        for (int q = 0; q < 3; q++)
            eng_arg_real(g, k, a++, d->lo[q] - olo[q]);
        eng_arg_pos_lo(g, k, a);
        eng_launch(g, k, (size_t)e->a.n);
    }
    nbr_box_changed(g);
}

void box_change_flip(struct gravel *g, const struct box_target *b, int fxy, int fxz, int fyz)
{
    struct engine *e = g->eng;
    box_change_apply(g, b, BOX_REMAP_NONE, 0);
    if (e->a.n == 0 || (!fxy && !fxz && !fyz))
        return;
    cl_kernel k = e->k_box_flip;
    eng_arg_int(g, k, 0, e->a.n);
    eng_arg_mem(g, k, 1, e->a.image);
    eng_arg_int(g, k, 2, fxy);
    eng_arg_int(g, k, 3, fxz);
    eng_arg_int(g, k, 4, fyz);
    eng_launch(g, k, (size_t)e->a.n);
}
