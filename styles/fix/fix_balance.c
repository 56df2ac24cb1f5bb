/* fix_balance.c - `fix ID group balance Nfreq thresh shift dimstr Niter
 * stopthresh` and `... Nfreq thresh rcb`: LAMMPS's dynamic load balance of
 * a decomposed run (bin/gravel-mpi, doc/parallel.md).
 * shift: every Nfreq steps it forces a neighbor rebuild; there, when the
 * largest rank holds more than thresh times the mean, the grid's slab cuts
 * in dimstr move to the quantiles of the atoms (balance.h) before the atoms
 * move to their ranks. On one process there is nothing to balance: it
 * warns, and forces the same rebuilds (so a run gives the same bits on any
 * number of ranks).
 * rcb (comm_style tiled): the same forced rebuilds, where the box is tiled
 * again by bisecting the atoms (rcb.h). Nfreq 0: once, at the run's first
 * rebuild. As in LAMMPS, both styles force a rebuild every Nfreq steps.
 * `weight store name` writes the atoms' weights into d_name at those steps,
 * on one process too (the same values on any number of ranks). */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "balance.h"
#include "balance_weight.h"
#include "comm.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "par.h"

struct fix_balance {
    int nfreq;
    double thresh;
    unsigned dims; /* shift */
    int rcb;
    struct bal_weight w; /* weight and out keywords */
};

/* the keywords after the style's arguments (from argv[i]) */
static void keywords(struct gravel *g, struct fix_balance *b, int argc, char **argv, int i)
{
    while (i < argc) {
        if (strcmp(argv[i], "weight") && strcmp(argv[i], "out"))
            gr_error(g, "fix balance: unknown keyword '%s' (weight, out)", argv[i]);
        i = bal_weight_parse(g, &b->w, argc, argv, i, "fix balance");
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "fix balance needs Nfreq thresh style ... (LAMMPS syntax)");
    int nfreq = arg_int(g, argv[0], "Nfreq");
    double thresh = arg_double(g, argv[1], "thresh");
    if (nfreq < 0)
        gr_error(g, "fix balance Nfreq must be >= 0");
    if (!(thresh >= 1.0))
        gr_error(g, "fix balance thresh must be >= 1.0");
    if (!strcmp(argv[2], "rcb")) {
        if (comm_size() == 1) /* LAMMPS decks: nothing to balance, the same rebuilds */
            gr_warn(g, "fix %s balance: one process, there is nothing to balance", f->id);
        else if (!par_state(g)->dc.tiled)
            gr_error(g, "fix balance rcb needs comm_style tiled (LAMMPS: Fix balance rcb "
                        "cannot be used with comm_style brick)");
        struct fix_balance *b = gr_calloc(g, 1, sizeof *b);
        f->data = b;
        b->nfreq = nfreq;
        b->thresh = thresh;
        b->rcb = 1;
        keywords(g, b, argc, argv, 3);
        f->hooks = HOOK_PRE_EXCHANGE;
        return;
    }
    if (strcmp(argv[2], "shift") != 0)
        gr_error(g, "fix balance style '%s' is not supported (shift, rcb)", argv[2]);
    if (argc < 6)
        gr_error(g, "fix balance shift needs dimstr Niter stopthresh");
    struct fix_balance *b = gr_calloc(g, 1, sizeof *b);
    f->data = b;
    keywords(g, b, argc, argv, 6);
    b->nfreq = nfreq;
    b->thresh = thresh;
    b->dims = balance_dims(g, argv[3]);
    if (arg_int(g, argv[4], "fix balance Niter") < 1)
        gr_error(g, "fix balance Niter must be >= 1");
    if (!(arg_double(g, argv[5], "fix balance stopthresh") >= 1.0))
        gr_error(g, "fix balance stopthresh must be >= 1.0");
    if (comm_size() == 1)
        gr_warn(g, "fix %s balance: one process, there is nothing to balance", f->id);
    f->hooks = HOOK_PRE_EXCHANGE;
}

static double *weigh(struct gravel *g, void *ctx, int n, const double *cost_time,
                     const double *cost_neigh, const long *nown)
{
    struct fix_balance *b = ctx;
    return bal_weight_compute(g, &b->w, n, NULL, cost_time, cost_neigh, nown);
}

static void out(struct gravel *g, void *ctx)
{
    struct fix_balance *b = ctx;
    bal_weight_out(g, &b->w, &par_state(g)->dc, g->step);
}

/* the coming exchange balances with this fix's weights and out file */
static void hand_weights(struct par *p, struct fix_balance *b)
{
    p->balance_ctx = b;
    p->balance_weigh = b->w.on ? weigh : NULL;
    p->balance_out = b->w.out ? out : NULL;
}

static void init(struct gravel *g, struct fix *f)
{
    struct fix_balance *b = f->data;
    bigint n = b->nfreq;
    f->force_reneighbor = 1; /* on one process too: the same rebuilds, the same bits */
    f->next_reneighbor = n > 0 ? (g->step / n + 1) * n : g->step + 1;
}

/* A rebuild step: at the fix's steps, ask the coming exchange to balance. */
static void pre_exchange(struct gravel *g, struct fix *f)
{
    struct fix_balance *b = f->data;
    if (f->next_reneighbor != g->step)
        return;
    if (par_on(g)) {
        struct par *p = par_state(g);
        p->balance_rcb = b->rcb;
        p->balance_dims = b->rcb ? 0 : b->dims;
        p->balance_thresh = b->thresh;
        hand_weights(p, b);
    } else if (b->w.store) { /* one process: the weights only, for store */
        run_sync_host(g);
        free(bal_weight_compute(g, &b->w, g->atoms.n, NULL, NULL, NULL, NULL));
        eng_put_custom(g);
    }
    f->next_reneighbor = b->nfreq > 0 ? g->step + b->nfreq : 0;
}

static void destroy(struct fix *f)
{
    struct fix_balance *b = f->data;
    if (b)
        bal_weight_free(&b->w);
    free(b);
}

const struct fix_style fix_style_balance = {
    .name = "balance",
    .create = create,
    .init = init,
    .pre_exchange = pre_exchange,
    .destroy = destroy,
};
