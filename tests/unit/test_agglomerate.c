/* test_agglomerate.c - compute agglomerate: the minimum enclosing sphere of
 * spheres (closed forms and random sets against an independent numerical
 * minimisation) and the cluster statistics of hand-made scenes (chains, two
 * clusters, a single particle, a cluster wrapped across a periodic face,
 * effect overlap that is not contact, minsize, argument errors). */
#include <stdlib.h>

#include "compute.h"
#include "compute_agglomerate_mes.h"
#include "test.h"

static double enclose_radius(int n, const double *p, const double *r, const double c[3])
{
    double R = 0;
    for (int i = 0; i < n; i++) {
        double dx = p[3 * i] - c[0], dy = p[3 * i + 1] - c[1], dz = p[3 * i + 2] - c[2];
        double d = sqrt(dx * dx + dy * dy + dz * dz) + r[i];
        R = d > R ? d : R;
    }
    return R;
}

/* Independent reference: minimise max_i |c - p_i| + r_i by compass search
 * from the centroid, steps halving down to 1e-13. */
static double reference_radius(int n, const double *p, const double *r)
{
    double c[3] = {0, 0, 0};
    for (int i = 0; i < n; i++)
        for (int d = 0; d < 3; d++)
            c[d] += p[3 * i + d] / n;
    double best = enclose_radius(n, p, r, c), step = 1.0;
    while (step > 1e-13) {
        int improved = 0;
        for (int d = 0; d < 3; d++)
            for (int s = -1; s <= 1; s += 2) {
                double t[3] = {c[0], c[1], c[2]};
                t[d] += s * step;
                double v = enclose_radius(n, p, r, t);
                if (v < best) {
                    best = v;
                    memcpy(c, t, sizeof c);
                    improved = 1;
                }
            }
        /* diagonal moves help along ridges of the max function */
        for (int a = -1; a <= 1 && !improved; a++)
            for (int b = -1; b <= 1; b++)
                for (int e = -1; e <= 1; e++) {
                    double t[3] = {c[0] + a * step, c[1] + b * step, c[2] + e * step};
                    double v = enclose_radius(n, p, r, t);
                    if (v < best) {
                        best = v;
                        memcpy(c, t, sizeof c);
                        improved = 1;
                    }
                }
        if (!improved)
            step *= 0.5;
    }
    return best;
}

/* Optimality certificate, independent of the algorithm: c minimises
 * max_i |c - p_i| + r_i iff 0 lies in the convex hull of the unit vectors
 * (c - p_i)/|c - p_i| of the active spheres (those touching the bound from
 * inside). Returns the distance of the hull from 0 (Gilbert's algorithm). */
static double kkt_residual(int n, const double *p, const double *r, const double c[3], double R)
{
    double u[20][3];
    int k = 0;
    double rmax = 0;
    for (int i = 0; i < n; i++)
        rmax = r[i] > rmax ? r[i] : rmax;
    for (int i = 0; i < n; i++) {
        double d[3] = {c[0] - p[3 * i], c[1] - p[3 * i + 1], c[2] - p[3 * i + 2]};
        double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (fabs(len + r[i] - R) > 1e-9 * R)
            continue;
        if (len < 1e-12)
            return fabs(R - rmax); /* one sphere holds all: optimal iff it is the largest */
        for (int q = 0; q < 3; q++)
            u[k][q] = d[q] / len;
        k++;
    }
    if (k == 0)
        return 1;
    double x[3] = {u[0][0], u[0][1], u[0][2]};
    for (int it = 0; it < 200000; it++) {
        int j = 0;
        double best = INFINITY;
        for (int i = 0; i < k; i++) {
            double v = u[i][0] * x[0] + u[i][1] * x[1] + u[i][2] * x[2];
            if (v < best) {
                best = v;
                j = i;
            }
        }
        double xx = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        if (xx - best < 1e-20)
            break;
        double dd[3] = {u[j][0] - x[0], u[j][1] - x[1], u[j][2] - x[2]};
        double den = dd[0] * dd[0] + dd[1] * dd[1] + dd[2] * dd[2];
        double t = den > 0 ? -(x[0] * dd[0] + x[1] * dd[1] + x[2] * dd[2]) / den : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        for (int q = 0; q < 3; q++)
            x[q] += t * dd[q];
    }
    return sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

TEST(mes_closed_forms)
{
    int work[8];
    double c[3], R;
    /* two unequal touching spheres r 1 and 0.5 at distance 1.4 */
    double p2[] = {0, 0, 0, 1.4, 0, 0}, r2[] = {1, 0.5};
    CHECK(agg_min_sphere(2, p2, r2, c, &R, work));
    CHECK_NEAR(R, 1.45, 1e-14);
    CHECK_NEAR(c[0], 0.45, 1e-14);
    /* equilateral triangle of side s: circumradius s / sqrt 3, plus r */
    double s = 0.98, p3[] = {0, 0, 0, s, 0, 0, 0.5 * s, s * sqrt(3) / 2, 0}, r3[] = {.5, .5, .5};
    CHECK(agg_min_sphere(3, p3, r3, c, &R, work));
    CHECK_NEAR(R, s / sqrt(3) + 0.5, 1e-14);
    /* regular tetrahedron (edge 2 sqrt 2 h): circumradius h sqrt 3 */
    double h = s / sqrt(2);
    double p4[] = {h, h, h, h, -h, -h, -h, h, -h, -h, -h, h};
    /* vertices at distance h sqrt 3 from the origin */
    double r4[] = {.5, .5, .5, .5};
    CHECK(agg_min_sphere(4, p4, r4, c, &R, work));
    CHECK_NEAR(R, h * sqrt(3) + 0.5, 1e-13);
    /* a big sphere swallowing a small one: the big one alone */
    double p5[] = {0, 0, 0, 0.2, 0, 0}, r5[] = {1, 0.3};
    CHECK(agg_min_sphere(2, p5, r5, c, &R, work));
    CHECK_NEAR(R, 1.0, 1e-14);
    /* single sphere */
    CHECK(agg_min_sphere(1, p5 + 3, r5 + 1, c, &R, work));
    CHECK_NEAR(R, 0.3, 0);
}

TEST(mes_random_sets_match_reference)
{
    srand(12345);
    int worst_n = 0;
    double worst = 0;
    for (int trial = 0; trial < 60; trial++) {
        int n = 2 + trial % 19;
        double p[3 * 20], r[20], c[3], R;
        int work[20];
        int equal = trial % 3 == 0;
        for (int i = 0; i < n; i++) {
            for (int d = 0; d < 3; d++)
                p[3 * i + d] = (double)rand() / RAND_MAX * 4 - 2;
            r[i] = equal ? 0.5 : 0.1 + (double)rand() / RAND_MAX;
        }
        int exact = agg_min_sphere(n, p, r, c, &R, work);
        double enc = enclose_radius(n, p, r, c);
        double ref = reference_radius(n, p, r);
        CHECK(exact);
        CHECK(enc <= R * (1 + 1e-12));           /* encloses */
        CHECK(R <= ref * (1 + 1e-9));            /* no larger than a direct search */
        double dev = kkt_residual(n, p, r, c, R); /* and provably optimal */
        if (dev > worst) {
            worst = dev;
            worst_n = n;
        }
    }
    CHECK(worst < 1e-6);
    if (worst >= 1e-6)
        printf("  worst optimality residual %.3g (n = %d)\n", worst, worst_n);
}

static const double *agg_vector(struct gravel *g)
{
    struct compute *c = compute_find(g, "ag");
    return c ? compute_vector(g, c) : NULL;
}

static const char *HEAD = "units lj\natom_style sphere\nboundary p f f\n"
                          "region box block 0 10 -5 5 -5 5\ncreate_box 1 box\n";

TEST(clusters_hand_made)
{
    struct gravel *g = test_engine();
    char s[2048];
    snprintf(s, sizeof s,
             "%s"
             "create_atoms 1 single 2 0 0\ncreate_atoms 1 single 2.99 0 0\n"
             "create_atoms 1 single 3.98 0 0\n"                        /* chain of 3 */
             "create_atoms 1 single 6 2 0\ncreate_atoms 1 single 6 2.99 0\n" /* pair */
             "create_atoms 1 single 6 -3 0\n"                          /* single */
             "create_atoms 1 single 0.2 -3 3\ncreate_atoms 1 single 9.3 -3 3\n" /* wrap */
             "create_atoms 1 single 8 3 -3\ncreate_atoms 1 single 8 4.2 -3\n" /* effect only */
             "set atom * diameter 1 density 1\ncompute ag all agglomerate\n",
             HEAD);
    CHECK(test_script(g, s) == GR_OK);
    const double *v = agg_vector(g);
    CHECK(v != NULL);
    if (v) {
        double v3 = 1 - 3 * 0.125 / pow(1.49, 3), v2 = 1 - 2 * 0.125 / pow(0.995, 3);
        double vw = 1 - 2 * 0.125 / pow(0.95, 3);
        /* sizes 3, 2, 1, 2 (wrapped), 1, 1 (effect distance only) */
        CHECK_NEAR(v[0], 6, 0);
        CHECK_NEAR(v[1], 10.0 / 6, 1e-15);
        double mean = 10.0 / 6, var = 0;
        int sz[] = {3, 2, 1, 2, 1, 1};
        for (int i = 0; i < 6; i++)
            var += (sz[i] - mean) * (sz[i] - mean) / 6;
        CHECK_NEAR(v[2], sqrt(var), 1e-14);
        CHECK_NEAR(v[3], 3, 0);
        CHECK_NEAR(v[4], (v3 + v2 + vw) / 6, 1e-14);
    }
    /* same step, grown radii: the cached result must be recomputed (atoms 9
     * and 10, 1.2 apart, now touch) */
    CHECK(test_script(g, "set atom 9 diameter 1.3\nset atom 10 diameter 1.3\n") == GR_OK);
    v = agg_vector(g);
    if (v) {
        CHECK_NEAR(v[0], 5, 0);
        CHECK_NEAR(v[1], 2, 0);
    }
    CHECK(test_script(g, "set atom 9 diameter 1\nset atom 10 diameter 1\n") == GR_OK);
    /* minsize 2: only the three real agglomerates */
    CHECK(test_script(g, "uncompute ag\ncompute ag all agglomerate minsize 2\n") == GR_OK);
    v = agg_vector(g);
    if (v) {
        CHECK_NEAR(v[0], 3, 0);
        CHECK_NEAR(v[1], 7.0 / 3, 1e-15);
        CHECK_NEAR(v[3], 3, 0);
    }
    gr_destroy(g);
}

TEST(cluster_groups_and_empty)
{
    struct gravel *g = test_engine();
    char s[1024];
    snprintf(s, sizeof s,
             "%s"
             "create_atoms 1 single 2 0 0\ncreate_atoms 1 single 2.9 0 0\n"
             "set atom * diameter 1 density 1\ngroup one id 1\n"
             "compute ag one agglomerate\n",
             HEAD);
    CHECK(test_script(g, s) == GR_OK);
    const double *v = agg_vector(g);
    if (v) {
        /* only atom 1 is in the group: one agglomerate of size 1 */
        CHECK_NEAR(v[0], 1, 0);
        CHECK_NEAR(v[3], 1, 0);
        CHECK_NEAR(v[4], 0, 0);
    }
    gr_destroy(g);
}

TEST(argument_errors)
{
    char s[1024];
    snprintf(s, sizeof s, "%screate_atoms 1 single 2 0 0\ncompute ag all agglomerate bins 3\n",
             HEAD);
    CHECK_ERROR(s, "unknown compute agglomerate keyword 'bins'", 7);
    snprintf(s, sizeof s, "%screate_atoms 1 single 2 0 0\ncompute ag all agglomerate minsize 0\n",
             HEAD);
    CHECK_ERROR(s, "minsize", 7);
    snprintf(s, sizeof s, "%screate_atoms 1 single 2 0 0\ncompute ag all agglomerate file\n",
             HEAD);
    CHECK_ERROR(s, "file", 7);
    snprintf(s, sizeof s,
             "%screate_atoms 1 single 2 0 0\ncompute ag all agglomerate file /nonexistent/h\n",
             HEAD);
    CHECK_ERROR(s, "cannot open histogram file", 7);
}

int main(void)
{
    RUN(mes_closed_forms);
    RUN(mes_random_sets_match_reference);
    RUN(clusters_hand_made);
    RUN(cluster_groups_and_empty);
    RUN(argument_errors);
    return 0;
}
