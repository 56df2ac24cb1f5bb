/* balance_weight.c - the weight and out keywords of balance and fix balance
 * (balance_weight.h). */
#include "balance_weight.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_custom.h"
#include "comm.h"
#include "decomp.h"
#include "domain.h"
#include "error.h"
#include "fileio.h"
#include "group.h"
#include "variable.h"

static double positive_factor(struct gravel *g, const char *s, const char *who,
                              const char *what)
{
    double f = arg_double(g, s, what);
    if (!(f > 0) || !isfinite(f))
        gr_error(g, "%s weight %s factor must be > 0, got %s", who, what, s);
    return f;
}

/* The index of d_name for weight store, or an error naming who. */
static int store_check(struct gravel *g, const char *name, const char *who)
{
    const struct atoms *a = &g->atoms;
    int k = custom_find(a, name);
    if (k < 0)
        gr_error(g, "%s weight store: custom vector d_%s does not exist (define it with fix "
                    "property/atom d_%s; the name is given without d_)", who, name, name);
    if (a->cus.p[k].isint || a->cus.p[k].cols) {
        char have[GR_CUSTOMLEN + 4];
        gr_error(g, "%s weight store: %s is not a floating-point vector (d_%s)", who,
                 custom_prefixed(a, k, have), name);
    }
    return k;
}

int bal_weight_parse(struct gravel *g, struct bal_weight *w, int argc, char **argv, int i,
                     const char *who)
{
    if (!strcmp(argv[i], "out")) {
        if (i + 1 >= argc)
            gr_error(g, "%s out needs a file name", who);
        free(w->out);
        w->out = gr_strdup(g, argv[i + 1]);
        return i + 2;
    }
    if (i + 1 >= argc)
        gr_error(g, "%s weight needs a style (group, neigh, time, var)", who);
    const char *st = argv[i + 1];
    w->on = 1;
    unsigned given = w->ngroup ? BW_GROUP : 0;
    given |= w->var ? BW_VAR : 0;
    given |= w->time_factor > 0 ? BW_TIME : 0;
    given |= w->neigh_factor > 0 ? BW_NEIGH : 0;
    if (!strcmp(st, "group")) {
        if (i + 2 >= argc)
            gr_error(g, "%s weight group needs N and N group/factor pairs", who);
        int n = arg_int(g, argv[i + 2], "weight group N");
        if (n < 1 || n > BW_MAXGROUP)
            gr_error(g, "%s weight group N must be 1 .. %d, got %s", who, BW_MAXGROUP,
                     argv[i + 2]);
        if (i + 3 + 2 * n > argc)
            gr_error(g, "%s weight group %d needs %d group/factor pairs", who, n, n);
        for (int k = 0; k < n; k++) {
            const char *name = argv[i + 3 + 2 * k];
            int id = group_find(g, name);
            if (id < 0)
                gr_error(g, "%s weight group: no group '%s'", who, name);
            if (w->ngroup == BW_MAXGROUP)
                gr_error(g, "%s weight group: at most %d groups", who, BW_MAXGROUP);
            w->gid[w->ngroup] = id;
            w->gfac[w->ngroup++] = positive_factor(g, argv[i + 4 + 2 * k], who, "group");
        }
        return i + 3 + 2 * n;
    }
    if (!strcmp(st, "var")) {
        if (i + 2 >= argc)
            gr_error(g, "%s weight var needs an atom-style variable name", who);
        var_check_atom(g, argv[i + 2], "balance weight var");
        free(w->var);
        w->var = gr_strdup(g, argv[i + 2]);
        return i + 3;
    }
    if (!strcmp(st, "time") || !strcmp(st, "neigh")) {
        if (i + 2 >= argc)
            gr_error(g, "%s weight %s needs a factor", who, st);
        double f = positive_factor(g, argv[i + 2], who, st);
        if (st[0] == 't')
            w->time_factor = f;
        else
            w->neigh_factor = f;
        return i + 3;
    }
    if (!strcmp(st, "store")) { /* LAMMPS: store name, the d_ vector without prefix */
        if (i + 2 >= argc)
            gr_error(g, "%s weight store needs the name of a fix property/atom d_ vector", who);
        store_check(g, argv[i + 2], who);
        if (w->store)
            gr_error(g, "%s weight store given twice", who);
        w->store = gr_strdup(g, argv[i + 2]);
        w->store_before = given;
        return i + 3;
    }
    gr_error(g, "%s weight style '%s' is not supported (group, neigh, time, var, store)", who,
             st);
}

void bal_weight_free(struct bal_weight *w)
{
    free(w->var);
    free(w->store);
    free(w->out);
    if (w->fp)
        fclose(w->fp);
    memset(w, 0, sizeof *w);
}

/* LAMMPS's per-rank style: each rank's cost over its atoms, stretched from
 * the lowest to factor times the highest when factor != 1 (ranks without
 * atoms left out); every atom of rank r gets wr[r]. 0: no cost yet. */
static int rank_weights(const double *cost, const long *nown, int P, double factor, double *wr)
{
    double maxcost = 0;
    for (int r = 0; r < P; r++)
        maxcost = fmax(maxcost, cost[r]);
    if (!(maxcost > 0))
        return 0;
    double lo = INFINITY, hi = 0;
    for (int r = 0; r < P; r++) {
        wr[r] = nown[r] > 0 ? cost[r] / (double)nown[r] : 0;
        if (nown[r] > 0) {
            lo = fmin(lo, wr[r]);
            hi = fmax(hi, wr[r]);
        }
    }
    if (factor != 1.0 && hi > lo)
        for (int r = 0; r < P; r++)
            if (nown[r] > 0)
                wr[r] = lo + (wr[r] - lo) / (hi - lo) * (hi * factor - lo);
    return 1;
}

double *bal_weight_compute(struct gravel *g, const struct bal_weight *w, int n,
                           const int *owner, const double *cost_time,
                           const double *cost_neigh, const long *nown)
{
    if (!w || !w->on)
        return NULL;
    struct atoms *a = &g->atoms;
    double *wt = gr_malloc(g, ((size_t)n + 1) * sizeof *wt);
    /* with store: the product of the styles before it, in this fixed order
     * (the styles multiply, so the order changes no more than round-off) */
    double *st = w->store ? gr_malloc(g, ((size_t)n + 1) * sizeof *st) : NULL;
    for (int i = 0; i < n; i++) {
        double v = 1.0;
        for (int k = 0; k < w->ngroup; k++)
            if (a->mask[i] & group_bit(w->gid[k]))
                v *= w->gfac[k];
        wt[i] = v;
        if (st)
            st[i] = w->store_before & BW_GROUP ? v : 1.0;
    }
    if (w->var) {
        double *val = var_atom_values(g, w->var);
        for (int i = 0; i < n; i++) {
            if (!(val[i] > 0)) {
                long long tag = (long long)a->tag[i];
                double bad = val[i];
                free(val);
                free(wt);
                free(st);
                gr_error(g, "balance weight var %s: atom %lld has weight %g (must be > 0)",
                         w->var, tag, bad);
            }
            wt[i] *= val[i];
            if (st && (w->store_before & BW_VAR))
                st[i] *= val[i];
        }
        free(val);
    }
    int P = comm_size(), me = comm_rank();
    double *wr = gr_malloc(g, (size_t)P * sizeof *wr);
    const double *costs[2] = {cost_time, cost_neigh};
    const double factors[2] = {w->time_factor, w->neigh_factor};
    const unsigned bits[2] = {BW_TIME, BW_NEIGH};
    for (int s = 0; s < 2; s++) {
        if (!(factors[s] > 0) || !costs[s] || !rank_weights(costs[s], nown, P, factors[s], wr))
            continue;
        for (int i = 0; i < n; i++) {
            wt[i] *= wr[owner ? owner[i] : me];
            if (st && (w->store_before & bits[s]))
                st[i] *= wr[owner ? owner[i] : me];
        }
    }
    free(wr);
    if (st) { /* LAMMPS's ImbalanceStore: the property must still be a d_ vector */
        struct custom_ref ref = {store_check(g, w->store, "balance"), 0};
        for (int i = 0; i < n; i++)
            *custom_at(a, ref, i) = st[i];
        free(st);
    }
    return wt;
}

void bal_weight_out(struct gravel *g, struct bal_weight *w, const struct decomp *dc, bigint step)
{
    if (!w->out)
        return;
    if (!w->fp) {
        int err;
        const char *why;
        w->fp = fio_open_write_checked(w->out, 0, &err, &why);
        if (!w->fp)
            gr_error(g, "balance out: cannot open '%s': %s", w->out, why ? why : "error");
    }
    const struct domain *dm = &g->dom;
    int P = comm_size(), d2 = dm->dimension == 2, nc = d2 ? 4 : 8;
    FILE *fp = w->fp;
    fprintf(fp, "ITEM: TIMESTEP\n%lld\nITEM: NUMBER OF NODES\n%d\nITEM: BOX BOUNDS\n",
            (long long)step, nc * P);
    for (int q = 0; q < 3; q++)
        fprintf(fp, "%g %g\n", dm->lo[q], dm->hi[q]);
    fprintf(fp, "ITEM: NODES\n");
    /* the corners' order: around the lower face, then the upper one
     * (orthogonal), or lamda's binary order (triclinic), as LAMMPS */
    static const int ortho[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    static const int tri[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
    int m = 0;
    for (int r = 0; r < P; r++) {
        double lo[3], hi[3];
        decomp_box(dc, r, lo, hi);
        for (int c = 0; c < nc; c++) {
            const int *k = dm->triclinic ? tri[c] : ortho[c];
            double f[3], x[3];
            for (int q = 0; q < 3; q++)
                f[q] = k[q] ? hi[q] : lo[q];
            if (dm->triclinic) {
                domain_lamda2x(g, f, x);
            } else {
                for (int q = 0; q < 3; q++)
                    x[q] = dm->lo[q] + f[q] * (dm->hi[q] - dm->lo[q]);
            }
            if (d2)
                x[2] = 0.0;
            fprintf(fp, "%d %d %g %g %g\n", ++m, 1, x[0], x[1], x[2]);
        }
    }
    fprintf(fp, "ITEM: TIMESTEP\n%lld\nITEM: NUMBER OF %s\n%d\nITEM: %s\n", (long long)step,
            d2 ? "SQUARES" : "CUBES", P, d2 ? "SQUARES" : "CUBES");
    for (int r = 0; r < P; r++) {
        fprintf(fp, "%d %d", r + 1, 1);
        for (int c = 1; c <= nc; c++)
            fprintf(fp, " %d", nc * r + c);
        fprintf(fp, "\n");
    }
    fflush(fp);
}
