/* rcb.c - recursive coordinate bisection of the ranks' tiles (rcb.h). */
#include "rcb.h"

#include <stdlib.h>

/* the split of ranks lo .. hi: ranks lo .. mid-1 below the cut (LAMMPS's procmid) */
static int split_rank(int lo, int hi) { return lo + (hi - lo) / 2 + 1; }

static int sort_dim; /* qsort has no context argument in C11 */
static int rec = 3;  /* doubles per particle: 3 fractions, and its weight (rcb_compute_w) */

static int cmp_triple(const void *a, const void *b)
{
    const double *u = a, *v = b;
    double x = u[sort_dim], y = v[sort_dim];
    if (x != y || rec == 3)
        return (x > y) - (x < y);
    for (int q = 0; q < rec; q++) /* weighted: ties in a fixed order (the prefix sums) */
        if (u[q] != v[q])
            return (u[q] > v[q]) - (u[q] < v[q]);
    return 0;
}

/* the first m whose particles before it weigh at least the share nlo / np
 * of the range (unweighted: its count share) */
static long share_index(const double *s, long n, int nlo, int np)
{
    if (rec == 3)
        return (long)((double)n * nlo / np);
    double w = 0, acc = 0;
    for (long i = 0; i < n; i++)
        w += s[rec * i + 3];
    double target = w * nlo / np;
    long m = 0;
    while (m < n && acc < target)
        acc += s[rec * m++ + 3];
    return m;
}

/* The cut in dimension d of the n particles s (sorted here by d) that
 * gives the lower part nlo of np ranks its share of the particles, m;
 * particles at the same coordinate (a lattice's layer) stay together,
 * below or above the cut, whichever leaves the lower part nearer m (below
 * on a tie); the cut halfway between the last particle below and the
 * first above, every tile keeping a width (1e-6 of the box per rank). */
static double cut_in(double *s, long n, int d, int nlo, int np, const double lo[3],
                     const double hi[3])
{
    sort_dim = d;
    qsort(s, (size_t)n, (size_t)rec * sizeof *s, cmp_triple);
    long m = share_index(s, n, nlo, np), k = m;
    if (m > 0 && m < n && s[rec * (m - 1) + d] == s[rec * m + d]) {
        long i0 = m - 1, i1 = m + 1;
        while (i0 > 0 && s[rec * (i0 - 1) + d] == s[rec * m + d])
            i0--;
        while (i1 < n && s[rec * i1 + d] == s[rec * m + d])
            i1++;
        k = m - i0 <= i1 - m ? i0 : i1;
    }
    double v = n == 0 ? lo[d] + (hi[d] - lo[d]) * nlo / np
             : k <= 0 ? 0.5 * (lo[d] + s[d]) : k >= n ? 0.5 * (s[rec * (n - 1) + d] + hi[d])
             : 0.5 * (s[rec * (k - 1) + d] + s[rec * k + d]);
    double a = lo[d] + 1e-6 * nlo, b = hi[d] - 1e-6 * (np - nlo);
    if (!(a < b))
        return lo[d] + (hi[d] - lo[d]) * nlo / np;
    return v < a ? a : v > b ? b : v;
}

static void bisect(struct rcb *t, int plo, int phi, double *s, long n, double lo[3],
                   double hi[3], const double len[3], int nd)
{
    if (plo >= phi)
        return;
    int mid = split_rank(plo, phi), np = phi - plo + 1, nlo = mid - plo;
    /* LAMMPS's choice: the dimension whose cut leaves the larger of the two
     * smaller sides (tiles as cube-ish as possible; the first of equals) */
    int d = 0;
    double v = 0, best = -1;
    for (int q = 0; q < nd; q++) {
        double c = cut_in(s, n, q, nlo, np, lo, hi);
        double small = (c - lo[q] < hi[q] - c ? c - lo[q] : hi[q] - c) * len[q];
        if (small > best) {
            best = small;
            d = q;
            v = c;
        }
    }
    if (d != nd - 1) { /* the particles sorted by d again */
        sort_dim = d;
        qsort(s, (size_t)n, (size_t)rec * sizeof *s, cmp_triple);
    }
    t->dim[mid] = d;
    t->cut[mid] = v;
    long k = 0;
    while (k < n && s[rec * k + d] < v)
        k++;
    double h2[3] = {hi[0], hi[1], hi[2]}, l2[3] = {lo[0], lo[1], lo[2]};
    h2[d] = v;
    l2[d] = v;
    bisect(t, plo, mid - 1, s, k, lo, h2, len, nd);
    bisect(t, mid, phi, s + rec * k, n - k, l2, hi, len, nd);
}

void rcb_compute(struct rcb *t, int nranks, double *s, long n, const double len[3], int nd)
{
    rcb_free(t);
    t->dim = calloc((size_t)nranks + 1, sizeof *t->dim);
    t->cut = calloc((size_t)nranks + 1, sizeof *t->cut);
    if (!t->dim || !t->cut) {
        rcb_free(t);
        return;
    }
    t->n = nranks;
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    bisect(t, 0, nranks - 1, s, n, lo, hi, len, nd);
}

void rcb_compute_w(struct rcb *t, int nranks, double *s, long n, const double len[3], int nd)
{
    rec = 4;
    rcb_compute(t, nranks, s, n, len, nd);
    rec = 3;
}

int rcb_owner(const struct rcb *t, const double s[3])
{
    int lo = 0, hi = t->n - 1;
    while (lo < hi) {
        int mid = split_rank(lo, hi);
        if (s[t->dim[mid]] < t->cut[mid])
            hi = mid - 1;
        else
            lo = mid;
    }
    return lo;
}

void rcb_box(const struct rcb *t, int r, double lo[3], double hi[3])
{
    for (int q = 0; q < 3; q++) {
        lo[q] = 0;
        hi[q] = 1;
    }
    int a = 0, b = t->n - 1;
    while (a < b) {
        int mid = split_rank(a, b), d = t->dim[mid];
        if (r < mid) {
            hi[d] = t->cut[mid];
            b = mid - 1;
        } else {
            lo[d] = t->cut[mid];
            a = mid;
        }
    }
}

void rcb_free(struct rcb *t)
{
    free(t->dim);
    free(t->cut);
    t->dim = NULL;
    t->cut = NULL;
    t->n = 0;
}
