/* compute_rdf.c - `compute ID group rdf Nbin [itype1 jtype1 ...] [cutoff
 * Rc]`: the radial distribution function g(r) and the coordination number
 * of each I,J type-range pair, as LAMMPS's compute rdf. Nbin bins of width
 * Rc / Nbin out to Rc (the pair style's cut-off, LAMMPS 2021's `cutforce`,
 * when no cutoff is given); both atoms in the group, every pair within Rc
 * that the neighbor lists would hold (neigh_modify exclude applies), counted
 * once as I-J and once as J-I where the types match. Per histogram m:
 *   g(r) = hist / (vfrac normfac icount),   coord(r) = sum of g vfrac normfac
 * with vfrac the bin's shell volume over the box's (area in 2d), icount and
 * jcount the group's atoms of the I and J types, normfac = jcount -
 * duplicates / icount (duplicates: atoms of a type in both ranges). A global
 * array of Nbin rows: the bin centre, then g and coord of each pair (one
 * pair 1*N 1*N, all types, when none is given). Pairs from a host cell
 * search at the evaluation (src/contact/host_pairs.c); orthogonal boxes, Rc
 * at most half a periodic length. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "compute.h"
#include "error.h"
#include "host_pairs.h"

struct rdf {
    int nbin, npairs;
    int *ilo, *ihi, *jlo, *jhi;     /* [npairs] type ranges */
    double cut_user;                /* > 0: the cutoff keyword's */
    double *hist;                   /* [npairs * nbin] */
};

static void rdf_destroy(struct compute *c)
{
    struct rdf *r = c->data;
    if (!r)
        return;
    free(r->ilo);
    free(r->hist);
    free(r);
    c->data = NULL;
}

static void rdf_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "compute rdf needs the number of bins");
    struct rdf *r = gr_calloc(g, 1, sizeof *r);
    c->data = r;
    r->nbin = arg_int_range(g, argv[0], 1, 1 << 24, "compute rdf bins");
    int first_kw = 1;
    while (first_kw < argc && strcmp(argv[first_kw], "cutoff"))
        first_kw++;
    int npairarg = first_kw - 1;
    for (int i = first_kw; i < argc; i += 2) {
        arg_need(g, argc, i, 1, "cutoff");
        r->cut_user = arg_double(g, argv[i + 1], "compute rdf cutoff"); /* <= 0: the pair's */
    }
    if (npairarg % 2)
        gr_error(g, "compute rdf: type ranges come in I J pairs, got %d", npairarg);
    r->npairs = npairarg ? npairarg / 2 : 1;
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    r->ilo = gr_malloc(g, 4 * (size_t)r->npairs * sizeof(int));
    r->ihi = r->ilo + r->npairs;
    r->jlo = r->ihi + r->npairs;
    r->jhi = r->jlo + r->npairs;
    for (int m = 0; m < r->npairs; m++) {
        if (!npairarg) {
            r->ilo[m] = r->jlo[m] = 1;
            r->ihi[m] = r->jhi[m] = nt;
        } else {
            arg_type_range(g, argv[1 + 2 * m], nt, &r->ilo[m], &r->ihi[m]);
            arg_type_range(g, argv[2 + 2 * m], nt, &r->jlo[m], &r->jhi[m]);
        }
    }
    r->hist = gr_calloc(g, (size_t)r->npairs * r->nbin, sizeof *r->hist);
    c->array_flag = 1;
    c->size_array_cols = 1 + 2 * r->npairs;
    c->extarray = 0;
}

static int in_range(int t, int lo, int hi)
{
    return t >= lo && t <= hi;
}

/* the cut-off Rc: the keyword's, else the pair style's; at most half a
 * periodic box length, within which a pair has one image closer than Rc
 * (beyond it LAMMPS's ghosts count several) */
static double rdf_cut(struct gravel *g, const struct rdf *r)
{
    double cut;
    if (r->cut_user > 0) {
        cut = r->cut_user;
    } else {
        if (!g->styles.pair)
            gr_error(g, "compute rdf requires a pair style be defined or cutoff specified");
        cut = host_pairs_cutforce(g, "compute rdf");
    }
    for (int q = 0; q < g->dom.dimension; q++) {
        double half = 0.5 * (g->dom.hi[q] - g->dom.lo[q]);
        if (g->dom.periodic[q] && cut > half)
            gr_error(g, "compute rdf: cut-off %g exceeds half the periodic box length in %c "
                        "(%g): pairs would count through several images, which gravel does "
                        "not do", cut, "xyz"[q], half);
    }
    return cut;
}

static void rdf_init(struct gravel *g, struct compute *c)
{
    rdf_cut(g, c->data);
}

static void rdf_array(struct gravel *g, struct compute *c)
{
    struct rdf *r = c->data;
    const struct atoms *a = &g->atoms;
    const double cut = rdf_cut(g, r), delr = cut / r->nbin, delrinv = 1.0 / delr;
    memset(r->hist, 0, (size_t)r->npairs * r->nbin * sizeof *r->hist);
    struct host_pair *p;
    int np = host_pairs_find(g, cut, c->groupbit, c->groupbit, &p, "compute rdf");
    for (int k = 0; k < np; k++) {
        int i = p[k].i, j = p[k].j;
        if (!(a->mask[i] & c->groupbit) || !(a->mask[j] & c->groupbit) ||
            host_pairs_excluded(g, i, j))
            continue;
        int ibin = (int)(sqrt(p[k].rsq) * delrinv);
        if (ibin >= r->nbin)
            continue;
        int ti = a->type[i], tj = a->type[j];
        for (int m = 0; m < r->npairs; m++) { /* as I-J, then as J-I */
            if (in_range(ti, r->ilo[m], r->ihi[m]) && in_range(tj, r->jlo[m], r->jhi[m]))
                r->hist[(size_t)m * r->nbin + ibin] += 1.0;
            if (in_range(tj, r->ilo[m], r->ihi[m]) && in_range(ti, r->jlo[m], r->jhi[m]))
                r->hist[(size_t)m * r->nbin + ibin] += 1.0;
        }
    }
    free(p);
    int nt = a->ntypes > 0 ? a->ntypes : 1;
    int *typecount = gr_calloc(g, (size_t)nt + 1, sizeof *typecount);
    for (int i = 0; i < a->n; i++)
        if ((a->mask[i] & c->groupbit) && a->type[i] >= 1 && a->type[i] <= nt)
            typecount[a->type[i]]++;
    const int cols = 1 + 2 * r->npairs, dim3 = g->dom.dimension == 3;
    double *out = compute_array_rows(g, c, r->nbin);
    double vol = 1;
    for (int q = 0; q < (dim3 ? 3 : 2); q++)
        vol *= g->dom.hi[q] - g->dom.lo[q];
    const double constant = dim3 ? 4.0 * M_PI / (3.0 * vol) : M_PI / vol;
    for (int ibin = 0; ibin < r->nbin; ibin++)
        out[(size_t)ibin * cols] = (ibin + 0.5) * delr;
    for (int m = 0; m < r->npairs; m++) {
        long icount = 0, jcount = 0, dup = 0;
        for (int t = 1; t <= nt; t++) {
            icount += in_range(t, r->ilo[m], r->ihi[m]) ? typecount[t] : 0;
            jcount += in_range(t, r->jlo[m], r->jhi[m]) ? typecount[t] : 0;
            dup += in_range(t, r->ilo[m], r->ihi[m]) && in_range(t, r->jlo[m], r->jhi[m])
                       ? typecount[t]
                       : 0;
        }
        const double normfac = icount > 0 ? (double)jcount - (double)dup / icount : 0.0;
        double ncoord = 0.0;
        for (int ibin = 0; ibin < r->nbin; ibin++) {
            const double rl = ibin * delr, ru = (ibin + 1) * delr;
            const double vfrac = dim3 ? constant * (ru * ru * ru - rl * rl * rl)
                                      : constant * (ru * ru - rl * rl);
            const double gr = vfrac * normfac != 0.0
                                  ? r->hist[(size_t)m * r->nbin + ibin] / (vfrac * normfac * icount)
                                  : 0.0;
            if (icount != 0)
                ncoord += gr * vfrac * normfac;
            out[(size_t)ibin * cols + 1 + 2 * m] = gr;
            out[(size_t)ibin * cols + 2 + 2 * m] = ncoord;
        }
    }
    free(typecount);
}

const struct compute_style compute_style_rdf = {
    .name = "rdf",
    .ranks = COMPUTE_RANKS_GATHER, /* every rank's atoms, gathered: the same pairs */
    .create = rdf_create,
    .init = rdf_init,
    .array = rdf_array,
    .destroy = rdf_destroy,
};
