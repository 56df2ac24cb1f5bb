/* test_neighbor.c - device neighbor machinery against host references:
 * prefix scan, sort by cell then tag, full list equal to brute force
 * (periodic, fixed, polydisperse, list growth), periodic crossing with image
 * flags, lost atoms, the non-finite stop message and the program cache. */
#include "core_fixture.h"

#include <unistd.h>

#include "error.h"
#include "input.h"

/* Engine ready for direct calls: program built, atoms uploaded, kernels. */
static void prepare(struct gravel *g)
{
    eng_prepare(g);
    eng_upload(g);
    nbr_setup(g);
}

/* a small periodic scene with its kernels set up, for the scan checks */
static struct gravel *scan_engine(void)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    fx_box(g, lo, hi, "ppp", 1);
    fx_spheres(g, 4, 4, 4, 2.5, 0.5, 0.5, 0, 1);
    prepare(g);
    return g;
}

TEST(scan_matches_host)
{
    struct gravel *g = scan_engine();
    /* both forms: one launch (the serial device's) and three chunked ones */
    int sizes[] = {1, 7, 64, 1000, 100003}, serial = g->eng->ocl.serial;
    for (size_t t = 0; t < 2 * sizeof sizes / sizeof *sizes; t++) {
        int m = sizes[t / 2];
        g->eng->ocl.serial = (int)(t % 2);
        int *in = malloc((size_t)m * sizeof(int)), *out = malloc((size_t)(m + 1) * sizeof(int));
        unsigned s = 7 + (unsigned)t;
        for (int i = 0; i < m; i++)
            in[i] = (int)(fx_rand(&s) * 20);
        cl_mem a = eng_alloc(g, (size_t)m * sizeof(int), "in");
        cl_mem b = eng_alloc(g, (size_t)(m + 1) * sizeof(int), "out");
        eng_write(g, a, 0, (size_t)m * sizeof(int), in);
        nbr_scan(g, a, b, m);
        eng_read(g, b, 0, (size_t)(m + 1) * sizeof(int), out);
        int acc = 0, bad = 0;
        for (int i = 0; i < m; i++) {
            bad += out[i] != acc;
            acc += in[i];
        }
        bad += out[m] != acc;
        CHECK(bad == 0);
        clReleaseMemObject(a);
        clReleaseMemObject(b);
        free(in);
        free(out);
    }
    g->eng->ocl.serial = serial;
    gr_destroy(g);
}

/* An argument set to the value it holds is not set again (device.c
 * set_arg): a kernel alternating between two inputs and two sizes must
 * read the one set last each time. */
TEST(kernel_arguments_reset_after_change)
{
    struct gravel *g = scan_engine();
    const int m = 50;
    int in1[50], in2[50], out[51];
    for (int i = 0; i < m; i++) {
        in1[i] = 1;
        in2[i] = 2;
    }
    cl_mem a = eng_alloc(g, sizeof in1, "in1"), b = eng_alloc(g, sizeof in2, "in2");
    cl_mem o = eng_alloc(g, sizeof out, "out");
    eng_write(g, a, 0, sizeof in1, in1);
    eng_write(g, b, 0, sizeof in2, in2);
    const int serial = g->eng->ocl.serial;
    for (int t = 0; t < 8; t++) {
        g->eng->ocl.serial = t / 4;
        const int two = t % 2, len = t % 4 < 2 ? m : m - 10;
        nbr_scan(g, two ? b : a, o, len);
        eng_read(g, o, 0, sizeof out, out);
        CHECK(out[len] == (two ? 2 : 1) * len);
        CHECK(out[len - 1] == (two ? 2 : 1) * (len - 1));
    }
    g->eng->ocl.serial = serial;
    clReleaseMemObject(a);
    clReleaseMemObject(b);
    clReleaseMemObject(o);
    gr_destroy(g);
}

/* Compare the device list of every atom with a brute-force host list. */
static int list_errors(struct gravel *g, int *total_out)
{
    const struct nbr_list *l = nbr_list(g);
    int n = g->atoms.n, maxn = l->maxn;
    int *cnt = malloc((size_t)n * sizeof(int)), *lst = malloc((size_t)n * maxn * sizeof(int));
    eng_read(g, l->ncount, 0, (size_t)n * sizeof(int), cnt);
    eng_read(g, l->nlist, 0, (size_t)n * maxn * sizeof(int), lst);
    int errors = 0, total = 0;
    char *mark = calloc((size_t)n, 1);
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < cnt[i]; k++)
            mark[lst[(size_t)i * maxn + k]]++;
        total += cnt[i];
        for (int j = 0; j < n; j++) {
            if (j == i) {
                errors += mark[j] != 0;
                continue;
            }
            double rsq = 0;
            for (int d = 0; d < 3; d++) {
                double del = g->atoms.x[3 * i + d] - g->atoms.x[3 * j + d];
                if (g->dom.periodic[d]) {
                    double L = g->dom.hi[d] - g->dom.lo[d];
                    del -= L * round(del / L);
                }
                rsq += del * del;
            }
            double cut = g->atoms.radius[i] + g->atoms.radius[j] + g->neigh.skin;
            int want = rsq < cut * cut;
            /* allow rounding ambiguity exactly at the cut-off */
            if (fabs(sqrt(rsq) - cut) < 1e-9)
                continue;
            errors += mark[j] != want;
        }
        for (int k = 0; k < cnt[i]; k++)
            mark[lst[(size_t)i * maxn + k]] = 0;
    }
    free(mark);
    free(cnt);
    free(lst);
    if (total_out)
        *total_out = total;
    return errors;
}

static void brute_force_case(const char *bnd, double skin, double rlo, double rhi)
{
    struct gravel *g = test_engine();
    double lo[3] = {-3, -2, 0}, hi[3] = {9, 10, 11};
    fx_box(g, lo, hi, bnd, 1);
    fx_spheres(g, 9, 9, 8, 1.3, rlo, rhi, 0, 11);
    /* push a few atoms just outside periodic faces: the rebuild wraps them */
    for (int d = 0; d < 3; d++)
        if (bnd[d] == 'p')
            g->atoms.x[3 * 5 + d] = hi[d] + 0.05;
    g->neigh.skin = skin;
    CHECK(test_script(g, "run 0\n") == GR_OK);
    int total = 0;
    CHECK(list_errors(g, &total) == 0);
    CHECK(total > 0);
    for (int i = 0; i < g->atoms.n; i++)
        for (int d = 0; d < 3; d++)
            if (bnd[d] == 'p')
                CHECK(g->atoms.x[3 * i + d] >= lo[d] && g->atoms.x[3 * i + d] < hi[d]);
    gr_destroy(g);
}

TEST(list_brute_force_periodic_polydisperse) { brute_force_case("ppp", 0.2, 0.3, 0.6); }
TEST(list_brute_force_fixed) { brute_force_case("fff", 0.3, 0.5, 0.5); }
TEST(list_brute_force_mixed) { brute_force_case("pfp", 0.3, 0.2, 0.65); }
/* a skin this large puts ~60 atoms in each list: the list must grow */
TEST(list_growth_keeps_every_pair) { brute_force_case("ppp", 2.0, 0.4, 0.6); }

TEST(sorted_by_cell_then_tag)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {12, 12, 12};
    fx_box(g, lo, hi, "ppp", 1);
    fx_spheres(g, 10, 10, 10, 1.2, 0.5, 0.5, 0, 3);
    /* reverse the tags so the sort has work to do */
    int n = g->atoms.n;
    for (int i = 0; i < n; i++)
        g->atoms.tag[i] = n - i;
    g->neigh.skin = 0.2;
    CHECK(test_script(g, "run 0\n") == GR_OK);
    double cut = 2 * 0.5 + 0.2;
    int nc = (int)(12 / cut);
    int prev_cell = -1, bad = 0;
    int64_t prev_tag = 0, tagsum = 0;
    for (int i = 0; i < n; i++) {
        int c[3];
        for (int d = 0; d < 3; d++) {
            c[d] = (int)(g->atoms.x[3 * i + d] / (12.0 / nc));
            if (c[d] >= nc)
                c[d] = nc - 1;
        }
        int cell = (c[2] * nc + c[1]) * nc + c[0];
        if (cell < prev_cell || (cell == prev_cell && g->atoms.tag[i] <= prev_tag))
            bad++;
        prev_cell = cell;
        prev_tag = g->atoms.tag[i];
        tagsum += g->atoms.tag[i];
    }
    CHECK(bad == 0);
    CHECK(tagsum == (int64_t)n * (n + 1) / 2);
    gr_destroy(g);
}

TEST(periodic_crossing_image_flags)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    fx_box(g, lo, hi, "ppp", 1);
    double x[3] = {9.5, 5, 5}, y[3] = {2, 2, 2};
    atoms_add(g, 0, 1, x, 0.5, 1.0);
    atoms_add(g, 0, 1, y, 0.5, 1.0);
    g->atoms.v[0] = 2.0;   /* +x: crosses hi twice in 10 time units */
    g->atoms.v[4] = -3.0;  /* -y for atom 2: crosses lo */
    g->dt = 0.01;
    g->neigh.skin = 0.3;
    CHECK(test_script(g, "fix 1 all nve\nrun 1000\n") == GR_OK);
    int i = fx_index_of(g, 1), j = fx_index_of(g, 2);
    CHECK_NEAR(g->atoms.x[3 * i] + 10.0 * g->atoms.image[3 * i], 9.5 + 20.0, 1e-9);
    CHECK(g->atoms.image[3 * i] == 2);
    CHECK_NEAR(g->atoms.x[3 * j + 1] + 10.0 * g->atoms.image[3 * j + 1], 2 - 30.0, 1e-9);
    CHECK(g->atoms.image[3 * j + 1] == -3);
    CHECK(g->atoms.x[3 * i] >= 0 && g->atoms.x[3 * i] < 10);
    gr_destroy(g);
}

static struct gravel *leaving_scene(enum thermo_lost lost)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    fx_box(g, lo, hi, "ppf", 1);
    double x[3] = {5, 5, 9}, y[3] = {2, 2, 2};
    atoms_add(g, 0, 1, x, 0.5, 1.0);
    atoms_add(g, 0, 1, y, 0.5, 1.0);
    g->atoms.v[2] = 5.0;
    g->dt = 0.01;
    g->thermo.lost = lost;
    return g;
}

TEST(lost_atoms_error)
{
    struct gravel *g = leaving_scene(LOST_ERROR);
    CHECK(test_script(g, "fix 1 all nve\nrun 100\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "Lost atoms: original 2 current 1") != NULL);
    CHECK(strstr(g->err.msg, "(test.in:2)") != NULL);
    gr_destroy(g);
    g = leaving_scene(LOST_IGNORE);
    CHECK(test_script(g, "fix 1 all nve\nrun 100\n") == GR_OK);
    CHECK(g->atoms.n == 1);
    CHECK(g->atoms.tag[0] == 2);
    gr_destroy(g);
}

TEST(nonfinite_stop_names_step_tag_and_cause)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    fx_box(g, lo, hi, "ppp", 1);
    /* two particles at the same place: the contact normal is 0/0 */
    double x[3] = {5, 5, 5};
    atoms_add(g, 0, 1, x, 0.5, 0.5);
    atoms_add(g, 0, 1, x, 0.5, 0.5);
    g->dt = 0.001;
    CHECK(test_script(g, "pair_style gran/hooke 1e6 NULL 0 NULL 0.5 0\npair_coeff * *\n"
                         "fix 1 all nve/sphere\nrun 200 force yes\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "non-finite position or velocity at step 1: atom 1 has") != NULL);
    /* what was seen, not the (resolved) time step */
    CHECK(strstr(g->err.msg, "atom 1 and atom 2 were at the same position (5, 5, 5)") != NULL);
    CHECK(strstr(g->err.msg, "probable cause") == NULL);
    gr_destroy(g);
    /* a time step far beyond the collision time throws atoms out of the box */
    g = test_engine();
    fx_box(g, lo, hi, "ppp", 1);
    double y[3] = {5.9, 5, 5};
    atoms_add(g, 0, 1, x, 0.5, 0.5);
    atoms_add(g, 0, 1, y, 0.5, 0.5);
    g->dt = 0.5;
    CHECK(test_script(g, "pair_style gran/hooke 1e6 NULL 0 NULL 0.5 0\npair_coeff * *\n"
                         "fix 1 all nve/sphere\nrun 200 force yes\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "Lost atoms: original 2 current 0") != NULL);
    CHECK(strstr(g->err.msg, "0.00314 steps per collision") != NULL);
    gr_destroy(g);
}

/* diag_nonfinite's rule by brute force: the nearest other atom (minimum
 * image per periodic dimension, lowest index on ties) at the same position
 * or overlapping by more than half the smaller radius. */
static int brute_near(const struct gravel *g, int i, int *jout, double *dout)
{
    const struct atoms *a = &g->atoms;
    int jmin = -1;
    double dmin = INFINITY;
    for (int j = 0; j < a->n; j++) {
        if (j == i)
            continue;
        double dx[3];
        for (int q = 0; q < 3; q++) {
            dx[q] = a->x[3 * j + q] - a->x[3 * i + q];
            double l = g->dom.hi[q] - g->dom.lo[q];
            if (g->dom.periodic[q] && l > 0)
                dx[q] -= l * round(dx[q] / l);
        }
        double dd = hypot(hypot(dx[0], dx[1]), dx[2]);
        if (dd < dmin) {
            dmin = dd;
            jmin = j;
        }
    }
    if (jmin < 0)
        return 0;
    double ri = a->radius[i], rj = a->radius[jmin], rs = fmin(ri, rj);
    *jout = jmin;
    *dout = dmin;
    return dmin <= 1e-12 * (ri + rj) || (rs > 0 && ri + rj - dmin > 0.5 * rs);
}

/* A random scene: n atoms in and around the box, radii rlo..rhi, every
 * seventh atom on or deep inside an earlier one. */
static void start_scene(struct gravel *g, const char *bnd, int n, double rlo, double rhi,
                        unsigned seed)
{
    double lo[3] = {0, 0, 0}, hi[3] = {10, 6, 4};
    fx_box(g, lo, hi, bnd, 1);
    unsigned s = seed;
    for (int k = 0; k < n; k++) {
        double x[3];
        for (int q = 0; q < 3; q++)
            x[q] = lo[q] - 2 + (hi[q] - lo[q] + 4) * fx_rand(&s); /* some outside */
        if (k % 7 == 6) {
            int m = (int)(fx_rand(&s) * k);
            for (int q = 0; q < 3; q++)
                x[q] = g->atoms.x[3 * m + q] + (k % 14 == 6 ? 0 : 0.2 * rhi * (fx_rand(&s) - 0.5));
        }
        atoms_add(g, 0, 1, x, rlo + (rhi - rlo) * fx_rand(&s), 1);
    }
}

TEST(start_scan_matches_brute_force)
{
    struct {
        const char *bnd;
        int n;
        double rlo, rhi;
    } cases[] = {{"ppp", 1500, 0.05, 0.5}, {"ffp", 1500, 0.05, 0.5}, {"pff", 800, 0.2, 0.2},
                 {"ppp", 600, 0, 0}, {"fff", 3, 0.3, 0.3}};
    for (size_t t = 0; t < sizeof cases / sizeof *cases; t++) {
        struct gravel *g = test_engine();
        start_scene(g, cases[t].bnd, cases[t].n, cases[t].rlo, cases[t].rhi, 17u + (unsigned)t);
        prepare(g);
        const struct start_copy *c = &g->eng->start;
        int k = 0, seen = 0;
        for (int i = 0; i < g->atoms.n; i++) {
            int j;
            double d;
            if (!brute_near(g, i, &j, &d))
                continue;
            seen++;
            CHECK(k < c->nnear);
            if (k >= c->nnear)
                break;
            CHECK(c->near[k].tag == g->atoms.tag[i] && c->near[k].other == g->atoms.tag[j]);
            CHECK(c->near[k].dist == d);
            k++;
        }
        CHECK(k == c->nnear);
        CHECK(seen >= cases[t].n / 14); /* the planted ones at least */
        gr_destroy(g);
    }
}

TEST(program_cache_hit)
{
    char dir[] = "/tmp/gravel-cache-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    setenv("GRAVEL_CACHE_DIR", dir, 1);
    setenv("GRAVEL_PROGRAM_CACHE", "1", 1); /* on even where PoCL caches its kernels */
    int hits[2];
    for (int k = 0; k < 2; k++) {
        struct gravel *g = test_engine();
        double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
        fx_box(g, lo, hi, "ppp", 1);
        fx_spheres(g, 2, 2, 2, 2.0, 0.5, 0.5, 0, 1);
        CHECK(test_script(g, "fix 1 all viscous 0.25\nfix 2 all nve\nrun 1\n") == GR_OK);
        hits[k] = g->eng->ocl.cache_hit;
        gr_destroy(g);
    }
    CHECK(hits[0] == 0);
    CHECK(hits[1] == 1);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
    unsetenv("GRAVEL_CACHE_DIR");
    unsetenv("GRAVEL_PROGRAM_CACHE");
}

/* A kernel that does not compile: the error names its file and line and
 * carries the compiler log. */
TEST(build_failure_names_source)
{
    struct gravel *g = test_engine();
    struct engine *e = eng_get(g);
    const char *names[2] = {"common.cl", "pair_broken.cl"};
    const char *texts[2] = {"#define REAL double\n", "\n\nvoid f(void) { undeclared_x = 1; }\n"};
    jmp_buf jb;
    g->err.jmp = &jb;
    int raised = 0;
    if (setjmp(jb) == 0)
        ocl_build(g, &e->ocl, 2, names, texts, "-D TEST_BROKEN");
    else
        raised = 1;
    g->err.jmp = NULL;
    CHECK(raised);
    CHECK(strstr(g->err.msg, "OpenCL program build failed") != NULL);
    CHECK(strstr(g->err.msg, "kernels/pair_broken.cl line 3") != NULL);
    CHECK(strstr(g->err.msg, "undeclared_x") != NULL);
    gr_destroy(g);
}

int main(void)
{
    RUN(scan_matches_host);
    RUN(kernel_arguments_reset_after_change);
    RUN(list_brute_force_periodic_polydisperse);
    RUN(list_brute_force_fixed);
    RUN(list_brute_force_mixed);
    RUN(list_growth_keeps_every_pair);
    RUN(sorted_by_cell_then_tag);
    RUN(periodic_crossing_image_flags);
    RUN(lost_atoms_error);
    RUN(nonfinite_stop_names_step_tag_and_cause);
    RUN(start_scan_matches_brute_force);
    RUN(program_cache_hit);
    RUN(build_failure_names_source);
    return 0;
}
