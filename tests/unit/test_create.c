/* test_create.c - lattice command and create_atoms: lattice counts checked
 * against LAMMPS 29Sep2021 on the same scripts, single atoms, random
 * insertion with overlap (count, zero overlaps by brute force, seed
 * reproducibility), and validation errors. */
#include "test.h"

#include <stdlib.h>
#include <time.h>

#include "domain.h"

static int natoms_after(const char *script)
{
    struct gravel *g = test_engine();
    int rc = test_script(g, script);
    int n = rc == GR_OK ? g->atoms.n : -1;
    if (rc != GR_OK)
        printf("  script failed: %s\n", g->err.msg);
    gr_destroy(g);
    return n;
}

TEST(lattice_spacings)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "lattice fcc 0.8\n") == GR_OK);
    CHECK_NEAR(g->dom.lat.a[0], pow(4 / 0.8, 1.0 / 3.0), 1e-14);
    CHECK(test_script(g, "lattice hcp 0.8\n") == GR_OK); /* LAMMPS: 1.2091356 2.0942843 1.9745101 */
    CHECK_NEAR(g->dom.lat.a[0], 1.2091356, 1e-7);
    CHECK_NEAR(g->dom.lat.a[1], 2.0942843, 1e-7);
    CHECK_NEAR(g->dom.lat.a[2], 1.9745101, 1e-7);
    CHECK(test_script(g, "lattice sc 2.0 spacing 1 2 3\n") == GR_OK); /* 0.7937 1.5874 2.3811 */
    CHECK_NEAR(g->dom.lat.a[1], 1.5874011, 1e-7);
    CHECK_NEAR(g->dom.lat.prim[1], 0.79370053, 1e-8);
    CHECK(test_script(g, "units si\nlattice fcc 0.002 origin 0.5 0.5 0.5\n") == GR_OK);
    CHECK_NEAR(g->dom.lat.a[2], 0.002, 0); /* non-lj: scale is the lattice constant */
    CHECK(g->dom.lat.origin[0] == 0.5 && g->dom.lat.nbasis == 4);
    gr_destroy(g);
    CHECK_ERROR("lattice fcc -1\n", "lattice scale must be positive", 1);
    CHECK_ERROR("lattice sq 1\n", "incompatible with a 3d simulation", 1);
    CHECK_ERROR("dimension 2\nlattice fcc 1\n", "incompatible with a 2d simulation", 2);
    /* 2d, units lj: a = (nbasis / (rho* A))^(1/2), LAMMPS 2021's spacings */
    g = test_engine();
    CHECK(test_script(g, "dimension 2\nlattice sq 0.8\n") == GR_OK);
    CHECK_NEAR(g->dom.lat.a[0], 1.1180340, 1e-7);
    CHECK_NEAR(g->dom.lat.a[2], 1.1180340, 1e-7);
    CHECK(test_script(g, "lattice hex 0.8\n") == GR_OK); /* lmp: 1.2014057 2.0808957 1.2014057 */
    CHECK_NEAR(g->dom.lat.a[0], 1.2014057, 1e-7);
    CHECK_NEAR(g->dom.lat.a[1], 2.0808957, 1e-7);
    CHECK(g->dom.lat.nbasis == 2 && g->dom.lat.basis[1][1] == 0.5);
    CHECK(test_script(g, "lattice sq2 0.5\n") == GR_OK); /* (2 / 0.5)^(1/2) */
    CHECK_NEAR(g->dom.lat.a[1], 2.0, 1e-15);
    gr_destroy(g);
    CHECK_ERROR("lattice foo 1\n", "unknown lattice style 'foo'", 1);
    CHECK_ERROR("lattice fcc 1 origin 0 0 1\n", "origin values must be in [0, 1)", 1);
    CHECK_ERROR("lattice fcc 1 orient x 1 1 0\n", "only the default orientation", 1);
    CHECK_ERROR("lattice fcc 1 spacing 1 1\n", "keyword 'spacing' needs 3 values", 1);
}

TEST(lattice_counts)
{
    /* fcc 0.8 in a 10x10x10-cell periodic box: 4000 (issue), the others as
     * LAMMPS creates them in the same 17.0998^3 box */
    const char *box = "lattice fcc 0.8\nregion b block 0 10 0 10 0 10\ncreate_box 1 b\n";
    char s[512];
    snprintf(s, sizeof s, "%screate_atoms 1 box\n", box);
    CHECK(natoms_after(s) == 4000);
    snprintf(s, sizeof s, "%slattice hcp 0.8\ncreate_atoms 1 box\n", box);
    CHECK(natoms_after(s) == 4311);
    snprintf(s, sizeof s, "%slattice diamond 0.8\ncreate_atoms 1 box\n", box);
    CHECK(natoms_after(s) == 4096);
    snprintf(s, sizeof s, "%slattice bcc 0.8\ncreate_atoms 1 box\n", box);
    CHECK(natoms_after(s) == 4394);
    snprintf(s, sizeof s, "%slattice bcc 0.8\nregion s sphere 5 5 5 3\ncreate_atoms 1 region s\n",
             box);
    CHECK(natoms_after(s) == 259);
    CHECK(natoms_after("lattice sc 1.0\nregion b block 0 10 0 10 0 10\ncreate_box 1 b\n"
                       "create_atoms 1 box\n") == 1000);
    /* non-periodic: points on the upper face belong to the box only with 's'
     * (which moved the face out by small) */
    CHECK(natoms_after("boundary f f f\nlattice sc 1.0\nregion b block 0 10 0 10 0 10\n"
                       "create_box 1 b\ncreate_atoms 1 box\n") == 1000);
    CHECK(natoms_after("boundary s s s\nlattice sc 1.0\nregion b block 0 10 0 10 0 10\n"
                       "create_box 1 b\ncreate_atoms 1 box\n") == 1331);
}

TEST(lattice_positions_and_defaults)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "lattice fcc 0.8\nregion b block 0 2 0 2 0 2\ncreate_box 2 b\n"
                         "region c block 0 1 0 1 0 1\ncreate_atoms 2 region c\n") == GR_OK);
    /* closed region block [0, a]^3 on the fcc lattice: 8 corners + 6 faces;
     * in the periodic box x = a is not the upper face, so all 14 are kept */
    CHECK(g->atoms.n == 14);
    double a = g->dom.lat.a[0];
    int corner = 0;
    for (int i = 0; i < g->atoms.n; i++) {
        CHECK(g->atoms.type[i] == 2);
        CHECK(g->atoms.radius[i] == 0.5);
        CHECK_NEAR(g->atoms.rmass[i], M_PI / 6.0, 1e-15); /* density 1, diameter 1 */
        if (fabs(g->atoms.x[3 * i] - a) < 1e-12 && fabs(g->atoms.x[3 * i + 1] - a) < 1e-12 &&
            fabs(g->atoms.x[3 * i + 2] - a) < 1e-12)
            corner++;
    }
    CHECK(corner == 1);
    CHECK(g->atoms.tag[13] == 14);
    gr_destroy(g);
    /* basis M itype: in bcc the body-center atoms get type 2 */
    g = test_engine();
    CHECK(test_script(g, "lattice bcc 1.0\nregion b block 0 3 0 3 0 3\ncreate_box 2 b\n"
                         "create_atoms 1 box basis 2 2\n") == GR_OK);
    int n1 = 0, n2 = 0;
    for (int i = 0; i < g->atoms.n; i++) {
        double fx = g->atoms.x[3 * i] / g->dom.lat.a[0];
        int center = fabs(fx - floor(fx) - 0.5) < 1e-9;
        n1 += g->atoms.type[i] == 1 && !center;
        n2 += g->atoms.type[i] == 2 && center;
    }
    CHECK(n1 == 27 && n2 == 27);
    gr_destroy(g);
    CHECK_ERROR("lattice bcc 1.0\nregion b block 0 3 0 3 0 3\ncreate_box 2 b\n"
                "create_atoms 1 box basis 3 2\n", "basis atom must be between 1 and 2", 4);
}

TEST(create_single)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "lattice sc 0.5\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\n"
                         "create_atoms 1 single 1 1 1\n"
                         "create_atoms 1 single 1.5 2.5 0.5 units box\n"
                         "create_atoms 1 single 9 1 1 units box remap yes\n") == GR_OK);
    double a = pow(2.0, 1.0 / 3.0); /* lj: (1 / 0.5)^(1/3) */
    CHECK(g->atoms.n == 3);
    CHECK_NEAR(g->atoms.x[0], a, 1e-14); /* lattice units by default */
    CHECK(g->atoms.x[3] == 1.5 && g->atoms.x[4] == 2.5);
    double L = 4 * a;
    CHECK_NEAR(g->atoms.x[6], 9 - L, 1e-12); /* L = 5.04: wrapped once */
    CHECK(g->atoms.image[6] == 1);
    gr_destroy(g);
    CHECK_ERROR("region b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 1 single 9 1 1\n",
                "is outside the box", 3);
    CHECK_ERROR("region b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 2 box\n",
                "atom type must be between 1 and 1", 3);
    CHECK_ERROR("region b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 1 box\n",
                "no lattice is defined", 3);
    /* phase errors: the message may come from the dispatcher or the handler */
    CHECK_ERROR("create_atoms 1 box\n", "", 1);
    CHECK_ERROR("region b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 1 blob\n",
                "unknown style 'blob'", 3);
    CHECK_ERROR("region b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 1 single 1 1\n",
                "keyword 'single' needs 3 values", 3);
    CHECK_ERROR("region b block 0 4 0 4 0 4\ncreate_box 1 b\n"
                "create_atoms 1 single 1 1 1 overlap 1\n", "overlap and maxtry apply only", 3);
}

/* Smallest center distance over all pairs (brute force, minimum image). */
static double min_distance(const struct gravel *g)
{
    double best = INFINITY;
    for (int i = 0; i < g->atoms.n; i++)
        for (int j = i + 1; j < g->atoms.n; j++) {
            double d[3];
            for (int k = 0; k < 3; k++)
                d[k] = g->atoms.x[3 * i + k] - g->atoms.x[3 * j + k];
            domain_minimum_image(g, d);
            best = fmin(best, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
        }
    return best;
}

TEST(random_overlap)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "boundary p p f\nregion b block 0 20 0 20 0 20 units box\n"
                         "create_box 1 b\nregion s sphere 10 10 10 8 units box\n"
                         "create_atoms 1 random 800 4711 s overlap 1.0\n"
                         "create_atoms 1 random 500 4712 NULL overlap 1.0 maxtry 100\n")
          == GR_OK);
    CHECK(g->atoms.n == 1300);
    CHECK(min_distance(g) >= 1.0);
    const double c[3] = {10, 10, 10};
    for (int i = 0; i < 800; i++) {
        double r2 = 0;
        for (int k = 0; k < 3; k++)
            r2 += pow(g->atoms.x[3 * i + k] - c[k], 2);
        CHECK(r2 <= 64.0);
    }
    double x0 = g->atoms.x[0];
    gr_destroy(g);
    /* same seed, same atoms */
    g = test_engine();
    CHECK(test_script(g, "boundary p p f\nregion b block 0 20 0 20 0 20 units box\n"
                         "create_box 1 b\nregion s sphere 10 10 10 8 units box\n"
                         "create_atoms 1 random 800 4711 s overlap 1.0\n") == GR_OK);
    CHECK(g->atoms.x[0] == x0);
    gr_destroy(g);
    /* a full box: fewer inserted, with a warning, no overlaps */
    g = test_engine();
    CHECK(test_script(g, "region b block 0 3 0 3 0 3 units box\ncreate_box 1 b\n"
                         "create_atoms 1 random 1000 5 NULL overlap 1.0 maxtry 50\n") == GR_OK);
    CHECK(g->atoms.n > 10 && g->atoms.n < 1000);
    CHECK(g->err.nwarn == 1);
    CHECK(min_distance(g) >= 1.0);
    gr_destroy(g);
    CHECK_ERROR("region b block 0 3 0 3 0 3\ncreate_box 1 b\ncreate_atoms 1 random 10 0 NULL\n",
                "seed must be a positive integer", 3);
    CHECK_ERROR("region b block 0 3 0 3 0 3\ncreate_box 1 b\ncreate_atoms 1 random -1 5 NULL\n",
                "number of random atoms must be between 0 and 1e8", 3);
    CHECK_ERROR("region b block 0 3 0 3 0 3\ncreate_box 1 b\n"
                "create_atoms 1 random 10 5 NULL overlap 0\n", "overlap must be positive", 3);
    CHECK_ERROR("region b block 0 3 0 3 0 3\ncreate_box 1 b\n"
                "create_atoms 1 random 10 5 NULL maxtry 0\n", "maxtry must be between", 3);
    CHECK_ERROR("region b block 0 3 0 3 0 3 units box\ncreate_box 1 b\n"
                "region far sphere 50 50 50 1 units box\ncreate_atoms 1 random 10 5 far\n",
                "does not overlap the box", 4);
}

/* Independent overlap check for many atoms: sort by unit-cell key, then
 * look up the 27 neighbor cells by binary search (periodic box assumed). */
struct keyed {
    long key;
    int i;
};
static int cmp_keyed(const void *p, const void *q)
{
    long a = ((const struct keyed *)p)->key, b = ((const struct keyed *)q)->key;
    return (a > b) - (a < b);
}
static long count_overlaps(const struct gravel *g, double cut)
{
    int n = g->atoms.n, nc[3];
    for (int d = 0; d < 3; d++)
        nc[d] = (int)floor((g->dom.hi[d] - g->dom.lo[d]) / cut);
    struct keyed *k = malloc((size_t)n * sizeof *k);
    int (*cell)[3] = malloc((size_t)n * sizeof *cell);
    for (int i = 0; i < n; i++) {
        for (int d = 0; d < 3; d++) {
            int c = (int)((g->atoms.x[3 * i + d] - g->dom.lo[d]) / (g->dom.hi[d] - g->dom.lo[d]) *
                          nc[d]);
            cell[i][d] = c < 0 ? 0 : c >= nc[d] ? nc[d] - 1 : c;
        }
        k[i].key = ((long)cell[i][2] * nc[1] + cell[i][1]) * nc[0] + cell[i][0];
        k[i].i = i;
    }
    qsort(k, (size_t)n, sizeof *k, cmp_keyed);
    long bad = 0;
    for (int i = 0; i < n; i++)
        for (int dz = -1; dz <= 1; dz++)
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int c[3] = {cell[i][0] + dx, cell[i][1] + dy, cell[i][2] + dz};
                    for (int d = 0; d < 3; d++)
                        c[d] = (c[d] + nc[d]) % nc[d];
                    struct keyed want = {((long)c[2] * nc[1] + c[1]) * nc[0] + c[0], 0};
                    struct keyed *hit = bsearch(&want, k, (size_t)n, sizeof *k, cmp_keyed);
                    if (!hit)
                        continue;
                    while (hit > k && hit[-1].key == want.key)
                        hit--;
                    for (; hit < k + n && hit->key == want.key; hit++) {
                        int j = hit->i;
                        if (j <= i)
                            continue;
                        double del[3];
                        for (int d = 0; d < 3; d++)
                            del[d] = g->atoms.x[3 * i + d] - g->atoms.x[3 * j + d];
                        domain_minimum_image(g, del);
                        if (del[0] * del[0] + del[1] * del[1] + del[2] * del[2] < cut * cut)
                            bad++;
                    }
                }
    free(k);
    free(cell);
    return bad;
}

TEST(random_many_fast)
{
    /* 2e5 non-overlapping unit spheres at volume fraction 0.2 under ASan:
     * the grid keeps it linear (the 1e6 timing is in tests/scripts). */
    struct gravel *g = test_engine();
    clock_t t0 = clock();
    CHECK(test_script(g, "region b block 0 80 0 80 0 80 units box\ncreate_box 1 b\n"
                         "create_atoms 1 random 200000 99 NULL overlap 1.0\n") == GR_OK);
    double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
    CHECK(g->atoms.n == 200000);
    CHECK(secs < 30);
    CHECK(count_overlaps(g, 1.0) == 0);
    CHECK(count_overlaps(g, 1.2) > 0); /* the checker itself sees close pairs */
    printf("  200000 insertions: %.2f s (ASan build)\n", secs);
    gr_destroy(g);
}

int main(void)
{
    RUN(lattice_spacings);
    RUN(lattice_counts);
    RUN(lattice_positions_and_defaults);
    RUN(create_single);
    RUN(random_overlap);
    RUN(random_many_fast);
    return 0;
}
