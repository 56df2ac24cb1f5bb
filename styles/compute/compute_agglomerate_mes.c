/* compute_agglomerate_mes.c - minimum enclosing sphere of a set of spheres,
 * for the void fraction of an agglomerate (000 eq. 6.6: the bounding sphere
 * is the smallest sphere into which the agglomerate fits).
 *
 * Welzl's move-to-front algorithm carried over from points to spheres: the
 * current sphere is the smallest one internally tangent to the support set
 * (at most 4 spheres in 3-D); a sphere sticking out joins the support and the
 * prefix before it is redone. The basis sphere of support spheres B_1..B_k
 * (centres p_i, radii r_i) has its centre c = p_1 + sum_j l_j (p_j - p_1) in
 * the affine hull of the centres and radius R with |c - p_i| = R - r_i:
 * subtracting the first equation from the others gives a linear system for l
 * in terms of R (Gram matrix of q_j = p_j - p_1), and the first equation then
 * a quadratic in R whose smallest root R >= max r_i is taken. Equal radii
 * reduce exactly to Welzl on the centres. The input is visited in a fixed
 * pseudo-random order (expected linear time; 10^6 touching spheres: ~1 s). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "compute_agglomerate_mes.h"

struct ball {
    double c[3], R;
    int ok;
};

/* Solve the k x k system a x = b (k <= 3) by Gaussian elimination with
 * partial pivoting; 0 if singular. */
static int solve(int k, double a[3][3], double *b, double *x)
{
    double m[3][4];
    for (int i = 0; i < k; i++) {
        for (int j = 0; j < k; j++)
            m[i][j] = a[i][j];
        m[i][k] = b[i];
    }
    double scale = 0;
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++)
            scale = fmax(scale, fabs(a[i][j]));
    for (int col = 0; col < k; col++) {
        int piv = col;
        for (int i = col + 1; i < k; i++)
            if (fabs(m[i][col]) > fabs(m[piv][col]))
                piv = i;
        if (fabs(m[piv][col]) <= 1e-14 * scale)
            return 0;
        for (int j = 0; j <= k; j++) {
            double t = m[col][j];
            m[col][j] = m[piv][j];
            m[piv][j] = t;
        }
        for (int i = col + 1; i < k; i++) {
            double f = m[i][col] / m[col][col];
            for (int j = col; j <= k; j++)
                m[i][j] -= f * m[col][j];
        }
    }
    for (int i = k - 1; i >= 0; i--) {
        double s = m[i][k];
        for (int j = i + 1; j < k; j++)
            s -= m[i][j] * x[j];
        x[i] = s / m[i][i];
    }
    return 1;
}

/* Smallest sphere internally tangent to the k support spheres s[0..k). */
static struct ball basis(int k, const int *s, const double *p, const double *r)
{
    struct ball b = {{0, 0, 0}, -1, 0};
    if (k == 0)
        return b;
    const double *p1 = p + 3 * s[0];
    double r1 = r[s[0]];
    if (k == 1) {
        memcpy(b.c, p1, sizeof b.c);
        b.R = r1;
        b.ok = 1;
        return b;
    }
    int m = k - 1;
    double q[3][3], A[3][3], u[3], v[3], al[3], be[3];
    double rmax = r1;
    for (int j = 0; j < m; j++) {
        for (int d = 0; d < 3; d++)
            q[j][d] = p[3 * s[j + 1] + d] - p1[d];
        rmax = fmax(rmax, r[s[j + 1]]);
    }
    for (int i = 0; i < m; i++) {
        double ri = r[s[i + 1]];
        for (int j = 0; j < m; j++)
            A[i][j] = 2 * (q[i][0] * q[j][0] + q[i][1] * q[j][1] + q[i][2] * q[j][2]);
        u[i] = q[i][0] * q[i][0] + q[i][1] * q[i][1] + q[i][2] * q[i][2] - ri * ri + r1 * r1;
        v[i] = 2 * (ri - r1);
    }
    if (!solve(m, A, u, al) || !solve(m, A, v, be))
        return b;
    /* c - p1 = a + R bb */
    double a[3] = {0, 0, 0}, bb[3] = {0, 0, 0};
    for (int j = 0; j < m; j++)
        for (int d = 0; d < 3; d++) {
            a[d] += al[j] * q[j][d];
            bb[d] += be[j] * q[j][d];
        }
    double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    double ab = a[0] * bb[0] + a[1] * bb[1] + a[2] * bb[2];
    double b2 = bb[0] * bb[0] + bb[1] * bb[1] + bb[2] * bb[2];
    /* (b2 - 1) R^2 + 2 (ab + r1) R + (aa - r1^2) = 0 */
    double qa = b2 - 1, qb = 2 * (ab + r1), qc = aa - r1 * r1;
    double roots[2];
    int nr = 0;
    if (fabs(qa) < 1e-14) {
        if (fabs(qb) > 0)
            roots[nr++] = -qc / qb;
    } else {
        double disc = qb * qb - 4 * qa * qc;
        if (disc < 0)
            disc = 0; /* tangency under round-off */
        double sq = sqrt(disc);
        /* numerically stable pair */
        double t = -0.5 * (qb + (qb >= 0 ? sq : -sq));
        if (t != 0)
            roots[nr++] = qc / t;
        roots[nr++] = t / qa;
    }
    double best = INFINITY;
    for (int i = 0; i < nr; i++)
        if (isfinite(roots[i]) && roots[i] >= rmax * (1 - 1e-12) && roots[i] < best)
            best = roots[i];
    if (!isfinite(best))
        return b;
    for (int d = 0; d < 3; d++)
        b.c[d] = p1[d] + a[d] + best * bb[d];
    b.R = best;
    b.ok = 1;
    return b;
}

static int outside(const struct ball *b, const double *p, double r)
{
    if (!b->ok)
        return 1;
    double dx = p[0] - b->c[0], dy = p[1] - b->c[1], dz = p[2] - b->c[2];
    double d = sqrt(dx * dx + dy * dy + dz * dz) + r;
    return d > b->R + 1e-12 * (b->R > 1 ? b->R : 1);
}

/* Welzl with move-to-front over the list L[0..n) (indices), support s[0..k). */
static struct ball mtf(int *L, int n, int *s, int k, const double *p, const double *r)
{
    struct ball b = basis(k, s, p, r);
    if (k == 4)
        return b;
    for (int i = 0; i < n; i++) {
        int e = L[i];
        if (!outside(&b, p + 3 * e, r[e]))
            continue;
        s[k] = e;
        struct ball nb = mtf(L, i, s, k + 1, p, r);
        if (nb.ok) /* else keep: the final pass of agg_min_sphere encloses */
            b = nb;
        /* move e to the front */
        memmove(L + 1, L, (size_t)i * sizeof *L);
        L[0] = e;
    }
    return b;
}

int agg_min_sphere(int n, const double *p, const double *r, double c[3], double *R, int *work)
{
    /* a fixed pseudo-random order (deterministic results): Welzl's expected
     * linear time needs the input in random order, and agglomerate members
     * arrive in breadth-first, spatially coherent order, its worst case */
    uint64_t state = 0x9e3779b97f4a7c15ull ^ (uint64_t)n;
    for (int i = 0; i < n; i++)
        work[i] = i;
    for (int i = n - 1; i > 0; i--) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        int j = (int)((state >> 33) % (uint64_t)(i + 1));
        int t = work[i];
        work[i] = work[j];
        work[j] = t;
    }
    int s[4];
    struct ball b = mtf(work, n, s, 0, p, r);
    if (!b.ok) {
        /* degenerate everywhere: the largest sphere as a start */
        int big = 0;
        for (int i = 1; i < n; i++)
            if (r[i] > r[big])
                big = i;
        memcpy(b.c, p + 3 * big, sizeof b.c);
        b.R = r[big];
    }
    int exact = 1;
    for (int i = 0; i < n; i++) {
        double dx = p[3 * i] - b.c[0], dy = p[3 * i + 1] - b.c[1], dz = p[3 * i + 2] - b.c[2];
        double d = sqrt(dx * dx + dy * dy + dz * dz) + r[i];
        if (d > b.R) {
            if (d > b.R * (1 + 1e-12))
                exact = 0;
            b.R = d;
        }
    }
    memcpy(c, b.c, sizeof b.c);
    *R = b.R;
    return exact;
}
