/* pair_energy.c - the pair potential energy (pair_energy.h). */
#include "pair_energy.h"
#include "par.h"
#include "par_sum.h"

#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "device.h"
#include "error.h"
#include "neighbor.h"
#include "pair.h"
#include "pressure.h"

/* each device atom's half of its pairs' energies into ei[0 .. n) (device
 * order); returns n, or -1 when there is no energy to take (outside a run, no
 * pair style, a style without one): ei untouched */
static int atom_energies(struct gravel *g, double **ei_out)
{
    struct engine *e = g->eng;
    if (!e || !e->active || !e->k_energy || !g->styles.pair)
        return -1;
    const struct nbr_list *l = nbr_list(g);
    int n = e->a.n;
    double *ei = gr_malloc(g, ((size_t)n + 1) * sizeof(double));
    *ei_out = ei;
    if (n <= 0 && !par_on(g)) /* a rank without atoms still joins the sum */
        return 0;
    cl_mem out = pressure_scratch(g);
    cl_kernel k = e->k_energy;
    int a = 0;
    eng_arg_int(g, k, a++, n);
    eng_arg_mem(g, k, a++, l->nlist);
    eng_arg_int(g, k, a++, l->maxn);
    eng_arg_mem(g, k, a++, l->ioff);
    eng_arg_mem(g, k, a++, e->a.x);
    eng_arg_mem(g, k, a++, e->a.type);
    eng_arg_mem(g, k, a++, e->pair_param);
    eng_arg_int(g, k, a++, g->atoms.ntypes > 0 ? g->atoms.ntypes : 1);
    eng_arg_int(g, k, a++, g->styles.pair->caps.nparam);
    a = nbr_arg_box(g, k, a, l);
    eng_arg_mem(g, k, a++, out);
    if (n > 0)
        eng_launch(g, k, (size_t)n);
    eng_read_reals(g, out, (size_t)n, ei);
    return n;
}

double pair_energy(struct gravel *g)
{
    struct engine *e = g->eng;
    if (e && e->epair_snap_step == g->step && e->active)
        return e->epair_snap;
    double *ei = NULL;
    const int n = atom_energies(g, &ei);
    if (n < 0)
        return 0.0;
    const int *order = eng_tag_order(g); /* sum in tag order, every rank's atoms */
    struct par_sum s = {0};
    for (int i = 0; i < n; i++)
        par_sum_add(g, &s, e->tag_seen[order[i]], ei[order[i]]);
    free(ei);
    return par_sum_total(g, &s);
}

int pair_energy_atoms(struct gravel *g, double *out)
{
    double *ei = NULL;
    const int n = atom_energies(g, &ei);
    if (n < 0)
        return 0;
    memcpy(out, ei, (size_t)n * sizeof *out);
    free(ei);
    return 1;
}

void pair_energy_snapshot(struct gravel *g)
{
    struct engine *e = g->eng;
    if (!e || !e->active || !e->k_energy || e->epair_snap_step == g->step)
        return;
    e->epair_snap = pair_energy(g);
    e->epair_snap_step = g->step;
}
