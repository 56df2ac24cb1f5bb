/* decomp.c - the processor grid and the bricks of the ranks. */
#include "decomp.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "domain.h"
#include "error.h"

static double cross_norm(const double a[3], const double b[3])
{
    double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                   a[0] * b[1] - a[1] * b[0]};
    return sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

void decomp_setup(struct gravel *g, struct decomp *d)
{
    const struct domain *dm = &g->dom;
    int n = comm_size(), was[3] = {d->p[0], d->p[1], d->p[2]};
    double L[3];
    for (int q = 0; q < 3; q++)
        L[q] = dm->hi[q] - dm->lo[q];
    double area[3] = {L[0] * L[1], L[0] * L[2], L[1] * L[2]};
    if (dm->triclinic) { /* LAMMPS's ProcMap::best_factors: the faces of the edge vectors */
        double h[6];
        domain_h(g, h);
        const double a[3] = {h[0], 0, 0}, b[3] = {h[5], h[1], 0}, c[3] = {h[4], h[3], h[2]};
        area[0] = cross_norm(a, b);
        area[1] = cross_norm(a, c);
        area[2] = cross_norm(b, c);
    }
    double best = INFINITY;
    int found = 0;
    /* LAMMPS's order: px ascending, then py ascending; the first smallest wins */
    for (int px = 1; px <= n; px++) {
        if (n % px)
            continue;
        for (int py = 1; py <= n / px; py++) {
            if ((n / px) % py)
                continue;
            int pz = n / px / py, f[3] = {px, py, pz};
            int ok = !(dm->dimension == 2 && pz != 1);
            for (int q = 0; q < 3; q++)
                ok = ok && (!d->user[q] || d->user[q] == f[q]);
            if (!ok)
                continue;
            double surf = area[0] / px / py + area[1] / px / pz + area[2] / py / pz;
            if (surf < best) {
                best = surf;
                memcpy(d->p, f, sizeof f);
                found = 1;
            }
        }
    }
    if (!found)
        gr_error(g, "processors %d %d %d (0 = *) does not factor the %d ranks%s", d->user[0],
                 d->user[1], d->user[2], n, dm->dimension == 2 ? " with Pz = 1 (2d)" : "");
    if (memcmp(was, d->p, sizeof was) != 0)
        for (int q = 0; q < 3; q++) { /* a new grid: even slabs again */
            free(d->cut[q]);
            d->cut[q] = NULL;
        }
    if (d->rcb.n && (d->rcb.n != n || !d->tiled))
        rcb_free(&d->rcb); /* tiles of another rank count, or comm_style brick */
    int r = comm_rank();
    d->me[0] = r % d->p[0];
    d->me[1] = r / d->p[0] % d->p[1];
    d->me[2] = r / (d->p[0] * d->p[1]);
}

void decomp_free(struct decomp *d)
{
    for (int q = 0; q < 3; q++) {
        free(d->cut[q]);
        d->cut[q] = NULL;
    }
    rcb_free(&d->rcb);
}

int decomp_tiled(const struct decomp *d) { return d->rcb.n > 0; }

void decomp_rcb(const struct gravel *g, struct decomp *d, double *s, long n, int weighted)
{
    const struct domain *dm = &g->dom;
    double len[3] = {1, 1, 1}; /* LAMMPS bisects a triclinic box in lamda */
    if (!dm->triclinic)
        for (int q = 0; q < 3; q++)
            len[q] = dm->hi[q] - dm->lo[q];
    int nd = dm->dimension == 2 ? 2 : 3;
    if (weighted)
        rcb_compute_w(&d->rcb, comm_size(), s, n, len, nd);
    else
        rcb_compute(&d->rcb, comm_size(), s, n, len, nd);
    if (d->rcb.n != comm_size())
        gr_error((struct gravel *)g, "out of memory tiling the box by rcb");
}

double *decomp_fractions(struct gravel *g, const double *x, int n, const double *wt, int q)
{
    int nf = q < 0 ? 3 : 1, rec = nf + (wt != NULL);
    double *s = gr_malloc(g, ((size_t)rec * n + 1) * sizeof *s);
    for (int k = 0; k < n; k++) {
        for (int f = 0; f < nf; f++)
            s[(size_t)rec * k + f] = decomp_fraction(g, q < 0 ? f : q, x + 3 * (size_t)k);
        if (wt)
            s[(size_t)rec * k + nf] = wt[k];
    }
    return s;
}

void decomp_box(const struct decomp *d, int r, double lo[3], double hi[3])
{
    if (d->rcb.n) {
        rcb_box(&d->rcb, r, lo, hi);
        return;
    }
    int c[3] = {r % d->p[0], r / d->p[0] % d->p[1], r / (d->p[0] * d->p[1])};
    for (int q = 0; q < 3; q++) {
        lo[q] = decomp_cut(d, q, c[q]);
        hi[q] = decomp_cut(d, q, c[q] + 1);
    }
}

double decomp_cut(const struct decomp *d, int q, int k)
{
    if (k <= 0)
        return 0.0;
    if (k >= d->p[q])
        return 1.0;
    return d->cut[q] ? d->cut[q][k] : (double)k / d->p[q];
}

/* brick index of the fraction s of the box in dimension q (decomp_fraction) */
static int slab(const struct decomp *d, int q, double s)
{
    int n = d->p[q];
    if (!d->cut[q]) {
        int k = (int)floor(s * n);
        return k < 0 ? 0 : k >= n ? n - 1 : k;
    }
    int lo = 0, hi = n - 1; /* the last slab whose lower cut is <= s */
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (d->cut[q][mid] <= s)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

int decomp_owner(const struct gravel *g, const struct decomp *d, const double x[3])
{
    double s[3];
    for (int q = 0; q < 3; q++)
        s[q] = decomp_fraction(g, q, x);
    if (d->rcb.n)
        return rcb_owner(&d->rcb, s);
    return slab(d, 0, s[0]) + d->p[0] * (slab(d, 1, s[1]) + d->p[1] * slab(d, 2, s[2]));
}

void decomp_brick(const struct gravel *g, const struct decomp *d, int r, double lo[3],
                  double hi[3])
{
    const struct domain *dm = &g->dom;
    double flo[3], fhi[3];
    decomp_box(d, r, flo, fhi);
    for (int q = 0; q < 3; q++) {
        double L = dm->hi[q] - dm->lo[q];
        lo[q] = dm->lo[q] + L * flo[q];
        hi[q] = fhi[q] >= 1.0 ? dm->hi[q] : dm->lo[q] + L * fhi[q];
    }
}

/* The unclamped fraction of position x in dimension q: (x - lo) / L, or the
 * lamda coordinate of a triclinic box; periodic: wrapped into [0, 1). */
double decomp_fraction_raw(const struct gravel *g, int q, const double x[3])
{
    const struct domain *d = &g->dom;
    double s;
    if (d->triclinic) {
        double lam[3];
        domain_x2lamda(g, x, lam);
        s = lam[q];
    } else {
        s = (x[q] - d->lo[q]) / (d->hi[q] - d->lo[q]);
    }
    if (d->periodic[q])
        s -= floor(s);
    return s;
}

double decomp_fraction(const struct gravel *g, int q, const double x[3])
{
    double s = decomp_fraction_raw(g, q, x);
    return s < 0 ? 0 : s > 1 ? 1 : s;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Cuts of dimension q at the quantiles of the n fractions s (sorted here); even
 * slabs where the atoms cannot separate them. */
static int cmp_pair(const void *a, const void *b)
{
    const double *u = a, *v = b;
    if (u[0] != v[0])
        return (u[0] > v[0]) - (u[0] < v[0]);
    return (u[1] > v[1]) - (u[1] < v[1]);
}

/* the cuts of dimension q from the sorted fractions (stride rec doubles;
 * rec 2: a weight after each, the cut where the weight below reaches its
 * share; rec 1: the count's share) */
static void quantile_cuts(struct decomp *dc, int q, const double *s, long n, int rec)
{
    int P = dc->p[q];
    if (P < 2)
        return;
    double *c = malloc(((size_t)P + 1) * sizeof *c);
    if (!c)
        return;
    c[0] = 0;
    c[P] = 1;
    double wsum = 0, acc = 0;
    long at = 0;
    for (long i = 0; rec == 2 && i < n; i++)
        wsum += s[2 * i + 1];
    for (int k = 1; k < P; k++) {
        long m = (long)((double)k * (double)n / P);
        if (rec == 2) { /* the first m with the weight of atoms 0 .. m-1 >= k / P of it */
            double target = wsum * k / P;
            while (at < n && acc < target)
                acc += s[2 * at++ + 1];
            m = at;
        }
        double v = n == 0 ? (double)k / P : m <= 0 ? s[0] : m >= n ? s[rec * (n - 1)]
                 : 0.5 * (s[rec * (m - 1)] + s[rec * m]);
        double floor_k = c[k - 1] + 1e-6; /* every slab keeps a width */
        c[k] = v > floor_k ? v : floor_k;
    }
    for (int k = P - 1; k >= 1; k--) /* and the last ones too */
        if (c[k] > c[k + 1] - 1e-6)
            c[k] = c[k + 1] - 1e-6;
    free(dc->cut[q]);
    dc->cut[q] = c;
}

void decomp_quantile_cuts(struct decomp *dc, int q, double *s, long n, int weighted)
{
    if (weighted)
        qsort(s, (size_t)n, 2 * sizeof *s, cmp_pair);
    else
        qsort(s, (size_t)n, sizeof *s, cmp_double);
    quantile_cuts(dc, q, s, n, weighted ? 2 : 1);
}

