/* test_pair.c - the gran pair styles and the run loop on the device:
 * momentum conservation (pair forces sum to zero), bit-identical repeated
 * runs, contact history surviving forced rebuilds, a head-on Hooke collision
 * against its closed form, LAMMPS argument semantics and errors, and the
 * LAMMPS chute benchmark's step-100 numbers (784292.08 1571.0968). */
#include "core_fixture.h"

#include <stdio.h>
#include <unistd.h>

#include "error.h"
#include "input.h"
#include "collision_time.h"
#include "fix.h"
#include "pair.h"

/* A dense periodic pile of polydisperse spheres in contact; `pair` holds
 * the pair_style arguments, `coeff` the pair_coeff lines (NULL: "* *"). */
static struct gravel *pile_coeff(const char *pair, const char *coeff, int nx);

static struct gravel *pile(const char *pair, int nx)
{
    return pile_coeff(pair, NULL, nx);
}

static struct gravel *pile_coeff(const char *pair, const char *coeff, int nx)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {nx * 0.95, nx * 0.95, nx * 0.95};
    fx_box(g, lo, hi, "ppp", 1);
    fx_spheres(g, nx, nx, nx, 0.95, 0.45, 0.55, 2.0, 5);
    for (int i = 0; i < g->atoms.n; i++)
        for (int d = 0; d < 3; d++)
            g->atoms.omega[3 * i + d] = 0.5 * ((i * 7 + d * 3) % 5 - 2);
    g->dt = 1e-4;
    g->neigh.skin = 0.1;
    char buf[512];
    snprintf(buf, sizeof buf, "pair_style %s\n%s", pair, coeff ? coeff : "pair_coeff * *\n");
    CHECK(test_script(g, buf) == GR_OK);
    return g;
}

static void momentum_case(const char *pair)
{
    struct gravel *g = pile(pair, 8);
    CHECK(test_script(g, "fix 1 all nve/sphere\nrun 50\n") == GR_OK);
    double s[3], mag = 0;
    fx_sum3(g, g->atoms.f, s);
    for (int i = 0; i < 3 * g->atoms.n; i++)
        mag += fabs(g->atoms.f[i]);
    CHECK(mag > 1.0);
    for (int d = 0; d < 3; d++)
        CHECK(fabs(s[d]) <= 1e-12 * mag);
    gr_destroy(g);
}

TEST(momentum_hooke) { momentum_case("gran/hooke 2e5 NULL 50 NULL 0.5 1"); }
TEST(momentum_hooke_history) { momentum_case("gran/hooke/history 2e5 NULL 50 NULL 0.5 1"); }
TEST(momentum_hertz_history) { momentum_case("gran/hertz/history 2e5 NULL 50 NULL 0.5 1"); }

TEST(determinism_bit_identical)
{
    double *x[2];
    int n = 0;
    for (int k = 0; k < 2; k++) {
        struct gravel *g = pile("gran/hooke/history 2e5 NULL 50 NULL 0.5 1", 8);
        CHECK(test_script(g, "fix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0.3 0 -1\n"
                             "run 200\n") == GR_OK);
        n = g->atoms.n;
        x[k] = malloc((size_t)n * 9 * sizeof(double));
        for (int i = 0; i < n; i++) {
            int j = fx_index_of(g, i + 1);
            memcpy(x[k] + 9 * i, g->atoms.x + 3 * j, 3 * sizeof(double));
            memcpy(x[k] + 9 * i + 3, g->atoms.v + 3 * j, 3 * sizeof(double));
            memcpy(x[k] + 9 * i + 6, g->atoms.omega + 3 * j, 3 * sizeof(double));
        }
        gr_destroy(g);
    }
    CHECK(memcmp(x[0], x[1], (size_t)n * 9 * sizeof(double)) == 0);
    free(x[0]);
    free(x[1]);
}

/* Final state (by tag) after a sheared run with the given neigh settings. */
static double *history_run(int every, int check, double skin, bigint *builds)
{
    struct gravel *g = pile("gran/hooke/history 2e5 NULL 50 NULL 0.5 1", 6);
    g->neigh.every = every;
    g->neigh.check = check;
    g->neigh.skin = skin;
    CHECK(test_script(g, "fix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 1 0 -1\n"
                         "run 400\n") == GR_OK);
    *builds = g->eng->st.nbuilds;
    int n = g->atoms.n;
    double *out = malloc((size_t)n * 6 * sizeof(double));
    for (int i = 0; i < n; i++) {
        int j = fx_index_of(g, i + 1);
        memcpy(out + 6 * i, g->atoms.v + 3 * j, 3 * sizeof(double));
        memcpy(out + 6 * i + 3, g->atoms.omega + 3 * j, 3 * sizeof(double));
    }
    gr_destroy(g);
    return out;
}

TEST(history_survives_forced_rebuilds)
{
    bigint b1, b2;
    double *a = history_run(1, 0, 0.1, &b1);   /* rebuild every step */
    double *b = history_run(1, 1, 0.1, &b2);   /* rebuild when needed */
    CHECK(b1 == 400);
    CHECK(b2 < 100);
    double maxdiff = 0, maxv = 0;
    for (int i = 0; i < 6 * 216; i++) {
        maxdiff = fmax(maxdiff, fabs(a[i] - b[i]));
        maxv = fmax(maxv, fabs(a[i]));
    }
    /* only the force summation order differs */
    CHECK(maxv > 0.1);
    CHECK(maxdiff < 1e-9 * maxv);
    free(a);
    free(b);
}

/* run 300 == run 150 + run 150: contact history and list survive between
 * runs (only the force summation order may differ after the setup re-sort).
 * Without damping the setup forces of the second run do not depend on the
 * velocity half step, so the two agree to rounding (as in LAMMPS). */
TEST(two_runs_continue_one)
{
    double *st[2];
    int n = 0;
    for (int k = 0; k < 2; k++) {
        struct gravel *g = pile("gran/hertz/history 2e5 NULL 0 NULL 0.5 0", 6);
        CHECK(test_script(g, "fix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 1 0 -1\n") ==
              GR_OK);
        if (k == 0)
            CHECK(test_script(g, "run 300\n") == GR_OK);
        else
            CHECK(test_script(g, "run 150\nrun 150\n") == GR_OK);
        CHECK(g->step == 300);
        n = g->atoms.n;
        st[k] = malloc((size_t)n * 6 * sizeof(double));
        for (int i = 0; i < n; i++) {
            int j = fx_index_of(g, i + 1);
            memcpy(st[k] + 6 * i, g->atoms.v + 3 * j, 3 * sizeof(double));
            memcpy(st[k] + 6 * i + 3, g->atoms.omega + 3 * j, 3 * sizeof(double));
        }
        gr_destroy(g);
    }
    double maxdiff = 0, maxv = 0;
    for (int i = 0; i < 6 * n; i++) {
        maxdiff = fmax(maxdiff, fabs(st[0][i] - st[1][i]));
        maxv = fmax(maxv, fabs(st[0][i]));
    }
    CHECK(maxv > 0.1);
    CHECK(maxdiff < 1e-9 * maxv);
    free(st[0]);
    free(st[1]);
}

/* Head-on collision of two equal spheres, gran/hooke without damping and
 * friction: elastic; the contact lasts pi / sqrt(kn / meff). */
TEST(head_on_hooke_closed_form)
{
    struct gravel *g = test_engine();
    double lo[3] = {-10, -10, -10}, hi[3] = {10, 10, 10};
    fx_box(g, lo, hi, "fff", 1);
    double x1[3] = {-0.6, 0, 0}, x2[3] = {0.6, 0, 0};
    double m = 1.0;
    atoms_add(g, 0, 1, x1, 0.5, m);
    atoms_add(g, 0, 1, x2, 0.5, m);
    g->atoms.v[0] = 1.0;
    g->atoms.v[3] = -1.0;
    g->dt = 5e-5;
    g->neigh.skin = 0.1;
    CHECK(test_script(g, "pair_style gran/hooke 1e4 NULL 0 NULL 0 0\npair_coeff * *\n"
                         "fix 1 all nve/sphere\nrun 8000\n") == GR_OK);
    int i = fx_index_of(g, 1);
    CHECK_NEAR(g->atoms.v[3 * i], -1.0, 2e-5); /* energy error of the contact discretization */
    /* contact time pi/sqrt(kn/meff) with meff = m/2: position after t = 0.4 */
    double tc = M_PI / sqrt(1e4 / 0.5);
    double t_free = 0.4 - tc;                      /* time spent moving freely */
    double xexp = -0.6 + 0.1 - (t_free - 0.1) * 1.0; /* 0.1 to contact, then back */
    CHECK_NEAR(g->atoms.x[3 * i], xexp, 2e-4);
    gr_destroy(g);
}

#define BOX "atom_style sphere\nregion box block 0 1 0 1 0 1\ncreate_box 1 box\n"

TEST(gran_arguments)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    fx_box(g, lo, hi, "ppp", 2);
    CHECK(test_script(g, "pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0\n") ==
          GR_OK);
    const struct pair *p = g->styles.pair;
    double par[GRAN_NPARAM];
    p->style->pack(p, 1, 2, par);
    CHECK_NEAR(par[GRAN_KN], 2e5, 0);
    CHECK_NEAR(par[GRAN_KT], 2e5 * 2.0 / 7.0, 1e-9);
    CHECK_NEAR(par[GRAN_GAMMAN], 50, 0);
    CHECK_NEAR(par[GRAN_GAMMAT], 0, 0); /* dampflag 0 */
    CHECK_NEAR(par[GRAN_XMU], 0.5, 0);
    CHECK(test_script(g, "pair_style gran/hertz/history 1000 NULL 50 NULL 0.5 1 limit_damping\n")
          == GR_OK);
    p = g->styles.pair;
    p->style->pack(p, 1, 1, par);
    CHECK_NEAR(par[GRAN_GAMMAT], 25, 0);
    CHECK_NEAR(par[GRAN_LIMIT], 1, 0);
    gr_destroy(g);
    CHECK_ERROR("pair_style gran/hooke 1 2 3\n", "expects Kn Kt gamman", 1);
    CHECK_ERROR("pair_style gran/hooke 1 NULL 3 NULL 0.5 2\n", "dampflag", 1);
    CHECK_ERROR("pair_style gran/hooke 1 NULL 3 NULL 0.5 1 limit\n", "limit_damping", 1);
    CHECK_ERROR("pair_style gran/hooke -1 NULL 3 NULL 0.5 1\n", "Kn", 1);
    CHECK_ERROR("pair_style gran/hook 1 NULL 3 NULL 0.5 1\n", "unknown pair style", 1);
    CHECK_ERROR(BOX "pair_coeff * *\n", "before pair_style", 4);
}

TEST(fix_errors)
{
    CHECK_ERROR(BOX "fix 1 all gravity 1.0 sideways 3\n", "unknown fix gravity style", 4);
    CHECK_ERROR(BOX "fix 1 all nosuchfix\n", "unknown fix style", 4);
    CHECK_ERROR(BOX "fix 1 all nve extra\n", "takes no arguments", 4);
    CHECK_ERROR("unfix 7\n", "could not find fix ID", 1);
    CHECK_ERROR(BOX "fix 1 nogroup nve\n", "group", 4);
}

/* fix gravity chute 26: the direction LAMMPS uses (sin 26, 0, -cos 26). */
TEST(gravity_chute_direction)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    fx_box(g, lo, hi, "ppp", 1);
    double x[3] = {5, 5, 5};
    atoms_add(g, 0, 1, x, 0.5, 2.0);
    g->dt = 0.01;
    CHECK(test_script(g, "fix 1 all gravity 1.0 chute 26.0\nfix 2 all nve\nrun 100\n") ==
          GR_OK);
    double t = 1.0, d2r = M_PI / 180;
    CHECK_NEAR(g->atoms.v[0], t * sin(26 * d2r), 1e-12);
    CHECK_NEAR(g->atoms.v[2], -t * cos(26 * d2r), 1e-12);
    CHECK_NEAR(g->atoms.x[0], 5 + 0.5 * t * t * sin(26 * d2r), 1e-9);
    gr_destroy(g);
}

/* fix viscous: free particle, v(t) = v0 exp(-gamma t / m) (to the Verlet
 * error); scale changes gamma for one type. */
TEST(viscous_decay)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {100, 100, 100};
    fx_box(g, lo, hi, "ppp", 2);
    double x[3] = {50, 50, 50}, y[3] = {20, 20, 20};
    atoms_add(g, 0, 1, x, 0.5, 2.0);
    atoms_add(g, 0, 2, y, 0.5, 2.0);
    g->atoms.v[0] = 1.0;
    g->atoms.v[3] = 1.0;
    g->dt = 1e-3;
    CHECK(test_script(g, "fix 1 all viscous 0.5 scale 2 2.0\nfix 2 all nve\nrun 2000\n") ==
          GR_OK);
    int i = fx_index_of(g, 1), j = fx_index_of(g, 2);
    CHECK_NEAR(g->atoms.v[3 * i], exp(-0.5 * 2.0 / 2.0), 1e-3);
    CHECK_NEAR(g->atoms.v[3 * j], exp(-1.0 * 2.0 / 2.0), 1e-3);
    gr_destroy(g);
}

/* A sphere hitting a frozen sphere head-on (gran/hooke, no friction): LAMMPS
 * uses meff = mass of the moving sphere, so the rebound speed is
 * e v0 with e = exp(-gamman tc / 2), tc = pi / sqrt(kn/m - gamman^2/4);
 * the frozen sphere stays put. */
TEST(freeze_meff_restitution)
{
    struct gravel *g = test_engine();
    double lo[3] = {-10, -10, -10}, hi[3] = {10, 10, 10};
    fx_box(g, lo, hi, "fff", 2);
    double x1[3] = {-1.2, 0, 0}, x2[3] = {0, 0, 0};
    atoms_add(g, 0, 1, x1, 0.5, 1.0);
    atoms_add(g, 0, 2, x2, 0.5, 1.0);
    int wall = fx_group(g, "wall");
    g->atoms.mask[1] |= 1u << wall;
    g->atoms.v[0] = 1.0;
    g->dt = 1e-4;
    g->neigh.skin = 0.1;
    CHECK(test_script(g, "pair_style gran/hooke 1e4 NULL 20 NULL 0 0\npair_coeff * *\n"
                         "fix 1 wall freeze\ngroup mobile type 1\nfix 2 mobile nve/sphere\n"
                         "run 6000\n") == GR_OK);
    double kn = 1e4, gn = 20, m = 1.0;
    double tc = M_PI / sqrt(kn / m - 0.25 * gn * gn);
    double e = exp(-0.5 * gn * tc);
    int i = fx_index_of(g, 1), j = fx_index_of(g, 2);
    CHECK_NEAR(g->atoms.v[3 * i], -e, 2e-3);
    CHECK(g->atoms.x[3 * j] == 0.0 && g->atoms.v[3 * j] == 0.0);
    gr_destroy(g);
}

/* neigh_modify exclude type / group: excluded pairs never enter the list
 * (and so never interact), everything else within the cut-off does. */
TEST(exclusions_in_list)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {8, 8, 8};
    fx_box(g, lo, hi, "ppp", 3);
    fx_spheres(g, 8, 8, 8, 1.0, 0.45, 0.55, 0, 9);
    int ga = fx_group(g, "ga");
    for (int i = 0; i < g->atoms.n; i++) {
        g->atoms.type[i] = 1 + i % 3;
        if (i % 5 == 0)
            g->atoms.mask[i] |= 1u << ga;
    }
    g->neigh.skin = 0.3;
    g->neigh.exclude_type[0][0] = 1;
    g->neigh.exclude_type[0][1] = 2;
    g->neigh.nexclude_type = 1;
    g->neigh.exclude_group[0][0] = ga;
    g->neigh.exclude_group[0][1] = ga;
    g->neigh.nexclude = 1;
    CHECK(test_script(g, "run 0\n") == GR_OK);
    const struct nbr_list *l = nbr_list(g);
    int n = g->atoms.n, maxn = l->maxn;
    int *cnt = malloc((size_t)n * sizeof(int)), *lst = malloc((size_t)n * maxn * sizeof(int));
    eng_read(g, l->ncount, 0, (size_t)n * sizeof(int), cnt);
    eng_read(g, l->nlist, 0, (size_t)n * maxn * sizeof(int), lst);
    int bad = 0, total = 0, want_total = 0;
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < cnt[i]; k++) {
            int j = lst[(size_t)i * maxn + k];
            int ti = g->atoms.type[i], tj = g->atoms.type[j];
            if ((ti == 1 && tj == 2) || (ti == 2 && tj == 1))
                bad++;
            if ((g->atoms.mask[i] & (1u << ga)) && (g->atoms.mask[j] & (1u << ga)))
                bad++;
        }
        total += cnt[i];
        for (int j = 0; j < n; j++) {
            if (j == i)
                continue;
            int ti = g->atoms.type[i], tj = g->atoms.type[j];
            if ((ti == 1 && tj == 2) || (ti == 2 && tj == 1))
                continue;
            if ((g->atoms.mask[i] & (1u << ga)) && (g->atoms.mask[j] & (1u << ga)))
                continue;
            double rsq = 0;
            for (int d = 0; d < 3; d++) {
                double del = g->atoms.x[3 * i + d] - g->atoms.x[3 * j + d];
                del -= 8.0 * round(del / 8.0);
                rsq += del * del;
            }
            double cut = g->atoms.radius[i] + g->atoms.radius[j] + 0.3;
            want_total += rsq < cut * cut;
        }
    }
    CHECK(bad == 0);
    CHECK(total == want_total);
    CHECK(total > 0);
    free(cnt);
    free(lst);
    gr_destroy(g);
}

/* LAMMPS bench/in.chute on data.chute: KinEng and erotate/sphere at step 100. */
/* The build option NAME of a record, its value, or NULL. */
static const char *caps_def(const struct pair_caps *c, const char *name)
{
    for (int k = 0; k < c->ndef; k++)
        if (!strcmp(c->def[k].name, name))
            return c->def[k].value;
    return NULL;
}

/* Each style answers through one record; hybrid/overlay merges its terms';
 * the host collision time is the law's formula of collision_time.h. */
TEST(capabilities_records)
{
    struct gravel *g = pile("gran/hooke/history 2e5 NULL 50 NULL 0.5 1", 3);
    CHECK(test_script(g, "fix 1 all nve/sphere\nrun 0\n") == GR_OK);
    const struct pair_caps *c = &g->styles.pair->caps; /* filled by the run's set-up */
    CHECK(c->nsources == 1 && !strcmp(c->sources[0], "pair_gran_hooke_history.cl"));
    CHECK(c->eval && !strcmp(c->eval, "gran_hooke_history_eval") && !c->eval_row);
    CHECK(c->rotation == 1 && c->history == 1 && c->hist_n == 3 && c->nparam == GRAN_NPARAM);
    CHECK(!c->beyond && c->nreach == 0 && !c->type_cut && !c->approach && !c->energy);
    CHECK(c->conservative == 0 && c->contact_energy != NULL);
    /* m = 2, r = 0.5: m* = 1 */
    CHECK(pair_collision_time(c, 2.0, 0.5, 1.0) == tcol_linear(2e5, 50, 1.0));
    CHECK(pair_collision_time(c, 2.0, 0.5, 1.0) == M_PI / sqrt(2e5 - 0.25 * 50 * 50));
    gr_destroy(g);

    g = pile_coeff("hybrid/overlay linear/restitution 1e4 0.5 0.0 cohesion 50",
                   "pair_coeff * * linear/restitution\npair_coeff * * cohesion 0.05\n", 3);
    CHECK(test_script(g, "fix 1 all nve/sphere\nrun 0\n") == GR_OK);
    c = &g->styles.pair->caps;
    CHECK(c->nsources == 3 && !strcmp(c->sources[0], "pair_linear_restitution.cl") &&
          !strcmp(c->sources[1], "pair_cohesion.cl") &&
          !strcmp(c->sources[2], "pair_hybrid_overlay.cl"));
    CHECK(c->eval && !strcmp(c->eval, "hybrid_overlay_eval"));
    CHECK(caps_def(c, "PAIR_TERMS") && !strcmp(caps_def(c, "PAIR_TERMS"), "2"));
    CHECK(caps_def(c, "PAIR_TERM0") && !strcmp(caps_def(c, "PAIR_TERM0"),
                                               "linear_restitution_eval"));
    CHECK(caps_def(c, "PAIR_TERM0_CONTACT") && !strcmp(caps_def(c, "PAIR_TERM0_CONTACT"), "1"));
    CHECK(caps_def(c, "PAIR_TERM1_CONTACT") && !strcmp(caps_def(c, "PAIR_TERM1_CONTACT"), "0"));
    CHECK(c->beyond == 1 && c->nreach == 1 && c->reach_a[0] + c->reach_b[0] > 0);
    CHECK(!c->approach && !c->history && c->hist_n == 3 && !c->conservative);
    /* the contact law's collision time, cohesion has none */
    CHECK(c->tcol_of && !strcmp(c->tcol_of->style->name, "linear/restitution"));
    CHECK(pair_collision_time(c, 2.0, 0.5, 0.0) == tcol_restitution(1e4, 0.5, 1.0));
    CHECK(pair_reach(g, 1.0) == fmax(1.0, c->reach_a[0] + c->reach_b[0] * 1.0));
    CHECK(pair_reach(g, 0.0) == c->reach_a[0]); /* the effect reaches beyond touch */
    gr_destroy(g);
}

/* fix freeze declares its group held (FIX_FROZEN); the core asks the flag. */
TEST(frozen_flag)
{
    struct gravel *g = pile("gran/hooke 2e5 NULL 50 NULL 0.5 1", 3);
    CHECK(fix_frozen_groupbit(g) == 0 && fix_all_conserving(g));
    CHECK(test_script(g, "group low id 1 2\nfix 1 all nve/sphere\nfix 2 low freeze\n") ==
          GR_OK);
    CHECK(fix_frozen_groupbit(g) == fix_find(g, "2")->groupbit && fix_all_conserving(g));
    CHECK(test_script(g, "fix 3 all gravity 1.0 vector 0 0 -1\n") == GR_OK);
    CHECK(!fix_all_conserving(g));
    gr_destroy(g);
}

TEST(chute_step100_matches_lammps)
{
    const char *path = "/work/shared/peers/chute/data.chute";
    FILE *fp = fopen(path, "r");
    if (!fp) {
        printf("  %s not found\n", path);
        CHECK(0);
        return;
    }
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {40, 20, 37.2886};
    fx_box(g, lo, hi, "ppf", 2);
    g->dom.bnd[2][1] = 's';
    char line[512];
    int section = 0;
    while (fgets(line, sizeof line, fp)) {
        if (!strncmp(line, "Atoms", 5)) {
            section = 1;
            continue;
        }
        if (!strncmp(line, "Velocities", 10)) {
            section = 2;
            continue;
        }
        long long id;
        int type, ix, iy, iz;
        double dia, rho, x[3], v[6];
        if (section == 1 && sscanf(line, "%lld %d %lf %lf %lf %lf %lf %d %d %d", &id, &type, &dia,
                                   &rho, &x[0], &x[1], &x[2], &ix, &iy, &iz) == 10) {
            double r = 0.5 * dia;
            int i = atoms_add(g, id, type, x, r, 4.0 * M_PI / 3.0 * r * r * r * rho);
            g->atoms.image[3 * i] = ix;
            g->atoms.image[3 * i + 1] = iy;
            g->atoms.image[3 * i + 2] = iz;
        } else if (section == 2 && sscanf(line, "%lld %lf %lf %lf %lf %lf %lf", &id, &v[0], &v[1],
                                          &v[2], &v[3], &v[4], &v[5]) == 7) {
            int i = fx_index_of(g, id);
            for (int d = 0; d < 3; d++) {
                g->atoms.v[3 * i + d] = v[d];
                g->atoms.omega[3 * i + d] = v[3 + d];
            }
        }
    }
    fclose(fp);
    CHECK(g->atoms.n == 32000);
    /* shrink-wrap margin as read_data sets it, then the initial 's' face */
    g->dom.small[2] = 1e-4 * (hi[2] - lo[2]);
    g->dom.hi[2] += g->dom.small[2];
    int bottom = fx_group(g, "bottom"), active = fx_group(g, "active");
    for (int i = 0; i < g->atoms.n; i++)
        g->atoms.mask[i] |= g->atoms.type[i] == 2 ? 1u << bottom : 1u << active;
    g->neigh.skin = 0.1;
    g->neigh.exclude_group[0][0] = bottom;
    g->neigh.exclude_group[0][1] = bottom;
    g->neigh.nexclude = 1;
    g->dt = 0.0001;
    CHECK(test_script(g, "pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0\n"
                         "pair_coeff * *\nfix 1 all gravity 1.0 chute 26.0\n"
                         "fix 2 bottom freeze\nfix 3 active nve/sphere\nrun 100\n") == GR_OK);
    double ke = 0, erot = 0;
    for (int i = 0; i < g->atoms.n; i++) {
        double m = g->atoms.rmass[i], r = g->atoms.radius[i];
        for (int d = 0; d < 3; d++) {
            ke += 0.5 * m * g->atoms.v[3 * i + d] * g->atoms.v[3 * i + d];
            erot += 0.5 * 0.4 * m * r * r * g->atoms.omega[3 * i + d] * g->atoms.omega[3 * i + d];
        }
    }
    char buf[64];
    snprintf(buf, sizeof buf, "%.8g %.8g", ke, erot);
    printf("  chute step 100: %s (LAMMPS 784292.08 1571.0968)\n", buf);
    CHECK(strcmp(buf, "784292.08 1571.0968") == 0);
    double vol = (g->dom.hi[0] - g->dom.lo[0]) * (g->dom.hi[1] - g->dom.lo[1]) *
                 (g->dom.hi[2] - g->dom.lo[2]);
    printf("  volume %.8g (LAMMPS 29834.707)\n", vol);
    snprintf(buf, sizeof buf, "%.8g", vol);
    CHECK(strcmp(buf, "29834.707") == 0);
    CHECK(g->step == 100);
    gr_destroy(g);
}

int main(void)
{
    RUN(momentum_hooke);
    RUN(momentum_hooke_history);
    RUN(momentum_hertz_history);
    RUN(determinism_bit_identical);
    RUN(history_survives_forced_rebuilds);
    RUN(two_runs_continue_one);
    RUN(head_on_hooke_closed_form);
    RUN(gran_arguments);
    RUN(fix_errors);
    RUN(gravity_chute_direction);
    RUN(viscous_decay);
    RUN(freeze_meff_restitution);
    RUN(exclusions_in_list);
    RUN(capabilities_records);
    RUN(frozen_flag);
    RUN(chute_step100_matches_lammps);
    return 0;
}
