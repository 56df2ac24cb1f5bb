/* balance.c - slab cuts or rcb tiles from the atoms' coordinates (balance.h). */
#include "balance.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "args.h"
#include "balance_weight.h"
#include "comm.h"
#include "decomp.h"
#include "error.h"
#include "log.h"
#include "par.h"

unsigned balance_dims(struct gravel *g, const char *dimstr)
{
    unsigned dims = 0;
    if (!*dimstr || strlen(dimstr) > 3)
        gr_error(g, "balance shift dimensions '%s' must be some of x, y, z", dimstr);
    for (const char *c = dimstr; *c; c++) {
        int q = *c == 'x' ? 0 : *c == 'y' ? 1 : *c == 'z' ? 2 : -1;
        if (q < 0 || dims & (1u << q))
            gr_error(g, "balance shift dimensions '%s' must be some of x, y, z, once each",
                     dimstr);
        if (q == 2 && g->dom.dimension == 2)
            gr_error(g, "balance shift z in a 2d simulation");
        dims |= 1u << q;
    }
    return dims;
}


/* largest rank's load and the imbalance (largest / mean) of n positions
 * (all atoms) under dc; the load is the atom count, or the weights' sum */
static double imbalance_of(struct gravel *g, const struct decomp *dc, const double *x, int n,
                           const double *wt, double *maxload)
{
    int P = dc->p[0] * dc->p[1] * dc->p[2];
    double *load = gr_calloc(g, (size_t)P, sizeof *load), mx = 0, total = 0;
    for (int i = 0; i < n; i++)
        load[decomp_owner(g, dc, x + 3 * (size_t)i)] += wt ? wt[i] : 1.0;
    for (int r = 0; r < P; r++) {
        mx = load[r] > mx ? load[r] : mx;
        total += load[r];
    }
    free(load);
    *maxload = mx;
    return total > 0 ? mx * P / total : 1.0;
}

/* The weights of every atom between runs (every rank holds them all): each
 * rank's cost of the last run (weight time, neigh) shared by the atoms the
 * current decomposition gives it. NULL without a weight keyword. */
static double *weights_between_runs(struct gravel *g, const struct decomp *dc,
                                    const struct bal_weight *w)
{
    if (!w->on)
        return NULL;
    const struct atoms *a = &g->atoms;
    struct par *p = par_state(g);
    int P = comm_size();
    int *owner = gr_malloc(g, ((size_t)a->n + 1) * sizeof *owner);
    long *nown = gr_calloc(g, (size_t)P, sizeof *nown);
    for (int i = 0; i < a->n; i++)
        nown[owner[i] = decomp_owner(g, dc, a->x + 3 * (size_t)i)]++;
    double mine[2] = {p->last_cost, p->last_neigh}, *all = NULL;
    size_t b = comm_allgatherv(mine, sizeof mine, (void **)&all);
    if (b != (size_t)P * sizeof mine)
        gr_error(g, "out of memory balancing");
    double *ct = gr_malloc(g, 2 * (size_t)P * sizeof *ct), *cn = ct + P;
    for (int r = 0; r < P; r++) {
        ct[r] = all[2 * r];
        cn[r] = all[2 * r + 1];
    }
    free(all);
    double *wt = bal_weight_compute(g, w, a->n, owner, ct, cn, nown);
    free(ct);
    free(owner);
    free(nown);
    return wt;
}

static void print_cuts(struct gravel *g, const struct decomp *dc)
{
    for (int q = 0; q < 3; q++) {
        gr_print(g, "  %c cuts:", "xyz"[q]);
        for (int k = 0; k <= dc->p[q]; k++)
            gr_print(g, " %#.8g", decomp_cut(dc, q, k));
        gr_print(g, "\n");
    }
}

/* each rank's rcb tile as fractions of the box */
static void print_tiles(struct gravel *g, const struct decomp *dc)
{
    for (int r = 0; r < comm_size(); r++) {
        double lo[3], hi[3];
        decomp_box(dc, r, lo, hi);
        gr_print(g, "  rank %d tile: x %#.6g %#.6g y %#.6g %#.6g z %#.6g %#.6g\n", r, lo[0],
                 hi[0], lo[1], hi[1], lo[2], hi[2]);
    }
}

void cmd_balance(struct gravel *g, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, "balance needs thresh and a style (x/y/z, shift or rcb), as LAMMPS");
    double thresh = arg_double(g, argv[0], "thresh");
    if (!(thresh >= 1.0))
        gr_error(g, "balance thresh must be >= 1.0, got %s", argv[0]);
    struct par *p = par_state(g);
    struct decomp *dc = &p->dc;
    decomp_setup(g, dc);
    /* the styles, checked before anything moves */
    double *user[3] = {NULL, NULL, NULL};
    int uniform[3] = {0, 0, 0}, rcb = 0, one_rcb = 0;
    unsigned shift = 0;
    struct bal_weight w = {0};
    int i = 1;
    while (i < argc) {
        const char *s = argv[i];
        if (!strcmp(s, "weight") || !strcmp(s, "out")) { /* keywords after the styles */
            i = bal_weight_parse(g, &w, argc, argv, i, "balance");
            continue;
        }
        int q = !strcmp(s, "x") ? 0 : !strcmp(s, "y") ? 1 : !strcmp(s, "z") ? 2 : -1;
        if (q >= 0) {
            if (i + 1 >= argc)
                gr_error(g, "balance %s needs uniform or %d cuts", s, dc->p[q] - 1);
            if (!strcmp(argv[i + 1], "uniform")) {
                uniform[q] = 1;
                i += 2;
                continue;
            }
            int P = dc->p[q];
            if (i + P - 1 > argc - 1)
                gr_error(g, "balance %s needs uniform or %d cuts for %d slabs", s, P - 1, P);
            free(user[q]);
            user[q] = gr_malloc(g, ((size_t)P + 1) * sizeof(double));
            user[q][0] = 0;
            user[q][P] = 1;
            for (int k = 1; k < P; k++) {
                user[q][k] = arg_double(g, argv[i + k], "balance cut");
                if (!(user[q][k] > user[q][k - 1]) || !(user[q][k] < 1))
                    gr_error(g, "balance %s cuts must increase strictly between 0 and 1", s);
            }
            i += P;
        } else if (!strcmp(s, "shift")) {
            if (i + 3 >= argc)
                gr_error(g, "balance shift needs dimstr Niter stopthresh");
            shift = balance_dims(g, argv[i + 1]);
            if (arg_int(g, argv[i + 2], "balance shift Niter") < 1)
                gr_error(g, "balance shift Niter must be >= 1");
            if (!(arg_double(g, argv[i + 3], "balance shift stopthresh") >= 1.0))
                gr_error(g, "balance shift stopthresh must be >= 1.0");
            i += 4;
        } else if (!strcmp(s, "rcb") && comm_size() == 1) {
            one_rcb = 1; /* nothing to balance; the keywords still parse */
            i++;
        } else if (!strcmp(s, "rcb")) {
            if (!dc->tiled)
                gr_error(g, "balance rcb needs comm_style tiled (LAMMPS: Balance rcb cannot be "
                            "used with comm_style brick)");
            if (i != 1)
                gr_error(g, "balance rcb takes no other style");
            rcb = 1;
            i++;
            if (i < argc && strcmp(argv[i], "weight") && strcmp(argv[i], "out"))
                gr_error(g, "balance rcb takes no other style, got '%s' (keywords: weight, out)",
                         argv[i]);
        } else {
            gr_error(g, "balance keyword '%s' is not supported (x, y, z, shift; keywords "
                        "weight, out)", s);
        }
    }
    if (one_rcb) { /* weight store still stores the weights (the same on any ranks) */
        gr_warn(g, "balance rcb: one process, there is nothing to balance");
        free(weights_between_runs(g, dc, &w));
        for (int q = 0; q < 3; q++)
            free(user[q]);
        bal_weight_free(&w);
        return;
    }
    clock_t t0 = clock();
    const struct atoms *a = &g->atoms; /* between runs: every atom on every rank */
    double maxinit, maxfinal;
    double *wt = weights_between_runs(g, dc, &w);
    double imbinit = imbalance_of(g, dc, a->x, a->n, wt, &maxinit);
    int niter = 0, tiled = decomp_tiled(dc);
    if (tiled && !rcb) /* a grid style after rcb: the grid again, balanced (LAMMPS) */
        rcb_free(&dc->rcb);
    if (rcb && imbinit > thresh) { /* tiles by bisecting every atom */
        double *s = decomp_fractions(g, a->x, a->n, wt, -1);
        decomp_rcb(g, dc, s, a->n, wt != NULL);
        free(s);
        niter = 1;
    } else if (!rcb && (imbinit > thresh || tiled)) {
        for (int q = 0; q < 3; q++) {
            if (uniform[q]) {
                free(dc->cut[q]);
                dc->cut[q] = NULL;
            } else if (user[q]) {
                free(dc->cut[q]);
                dc->cut[q] = user[q];
                user[q] = NULL;
            } else if (shift & (1u << q)) {
                double *s = decomp_fractions(g, a->x, a->n, wt, q);
                decomp_quantile_cuts(dc, q, s, a->n, wt != NULL);
                free(s);
            }
        }
        niter = 1;
    }
    for (int q = 0; q < 3; q++)
        free(user[q]);
    double imbfinal = imbalance_of(g, dc, a->x, a->n, wt, &maxfinal);
    free(wt);
    gr_print(g, "Balancing ...\n");
    gr_print(g, " rebalancing time: %.3f seconds\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    gr_print(g, "  iteration count = %d\n", niter);
    gr_print(g, "  initial/final maximal load/proc = %#.8g %#.8g\n", maxinit, maxfinal);
    gr_print(g, "  initial/final imbalance factor  = %#.8g %#.8g\n", imbinit, imbfinal);
    if (decomp_tiled(dc))
        print_tiles(g, dc);
    else
        print_cuts(g, dc);
    bal_weight_out(g, &w, dc, g->step);
    bal_weight_free(&w);
}
