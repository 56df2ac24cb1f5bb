/* test_contact.c - the engine's pair styles (gran/hooke, gran/hooke/history,
 * gran/hertz/history) and fix wall/gran (same three models, zplane) against
 * the independent reference of contact_ref.h, head-on and oblique with spin.
 *
 * Each case runs the deck of contact_cases.h in gravel for a time T at
 * dt = 1e-4 and dt = 5e-5 and compares positions, velocities and spins of
 * every sphere with the GSL rk8pd solution of the same contact law.
 * Error measure: max over components of |gravel - ref| / max(1, |ref|).
 * Tolerances: 4e-3 at dt = 1e-4 (a collision lasts 400-600 steps; LAMMPS'
 * integrator and its shear update are first order in dt), and the error must
 * shrink by at least 1.3x when dt halves (first-order convergence towards the
 * reference, measured ratios 1.5-4: the contact onset falls between steps at
 * a dt-dependent phase; at dt = 1e-6 LAMMPS and the reference agree to ~1e-6).
 * Head-on Hooke contacts are also checked against the closed-form restitution
 * coefficient exp(-gamman pi / (2 wd)) to 1e-3, and the undamped head-on Hertz
 * contact against its closed-form duration (Beta function) to 2e-3. */
#include <stdlib.h>

#include "test.h"
#include "atoms.h"
#include "contact_cases.h"

static char deck[16384];

/* Run the case in gravel; copy the final state of tag b+1 into out[b]. */
static int run_case(const struct cref_system *s, double dt, double T, struct cref_body *out)
{
    long nsteps = lround(T / dt);
    cref_deck(s, dt, nsteps, deck, sizeof deck);
    struct gravel *g = test_engine();
    g->logfile = NULL;
    int rc = test_script(g, deck);
    if (rc != GR_OK) {
        printf("  gravel failed: %s\n", g->err.msg);
        gr_destroy(g);
        return -1;
    }
    for (int b = 0; b < s->nbody; b++) {
        int i = atoms_find_tag(&g->atoms, b + 1);
        if (i < 0) {
            gr_destroy(g);
            return -1;
        }
        out[b] = s->b[b];
        for (int k = 0; k < 3; k++) {
            out[b].x[k] = g->atoms.x[3 * i + k];
            out[b].v[k] = g->atoms.v[3 * i + k];
            out[b].w[k] = g->atoms.omega[3 * i + k];
        }
    }
    gr_destroy(g);
    return 0;
}

static double state_error(const struct cref_system *ref, const struct cref_body *got)
{
    double worst = 0.0;
    for (int b = 0; b < ref->nbody; b++)
        for (int k = 0; k < 3; k++) {
            const double a[3] = {got[b].x[k], got[b].v[k], got[b].w[k]};
            const double r[3] = {ref->b[b].x[k], ref->b[b].v[k], ref->b[b].w[k]};
            for (int q = 0; q < 3; q++) {
                double e = fabs(a[q] - r[q]) / fmax(1.0, fabs(r[q]));
                if (e > worst) worst = e;
            }
        }
    return worst;
}

/* One case: reference at T, gravel at dt and dt/2, tolerance and convergence. */
static void check_case(struct cref_system s, double T, const char *what)
{
    struct cref_system ref = s;
    CHECK(cref_solve(&ref, T, 1e-3) == 0);
    CHECK(ref.ncontact_steps > 0); /* the case does collide */
    struct cref_body g1[2], g2[2];
    if (run_case(&s, 1e-4, T, g1) || run_case(&s, 5e-5, T, g2)) {
        CHECK(!"gravel run failed");
        return;
    }
    double e1 = state_error(&ref, g1), e2 = state_error(&ref, g2);
    printf("  %-34s error %.3g (dt 1e-4)  %.3g (dt 5e-5)  ratio %.2f\n", what, e1, e2, e1 / e2);
    CHECK(e1 <= 4e-3);
    CHECK(e2 * 1.3 <= e1);
}

static void pair_case(enum cref_model m, int oblique)
{
    struct cref_system s;
    cref_case_pair(&s, m, oblique);
    char what[96];
    snprintf(what, sizeof what, "pair gran/%s %s", cref_model_name(m),
             oblique ? "oblique" : "head-on");
    check_case(s, 0.12, what);
}

static void wall_case(enum cref_model m, int oblique)
{
    struct cref_system s;
    cref_case_wall(&s, m, oblique);
    char what[96];
    snprintf(what, sizeof what, "wall/gran %s %s", cref_model_name(m),
             oblique ? "oblique" : "head-on");
    check_case(s, 0.15, what);
}

TEST(pair_hooke_vs_reference)
{
    pair_case(CREF_HOOKE, 0);
    pair_case(CREF_HOOKE, 1);
}
TEST(pair_hooke_history_vs_reference)
{
    pair_case(CREF_HOOKE_HISTORY, 0);
    pair_case(CREF_HOOKE_HISTORY, 1);
}
TEST(pair_hertz_history_vs_reference)
{
    pair_case(CREF_HERTZ_HISTORY, 0);
    pair_case(CREF_HERTZ_HISTORY, 1);
}
TEST(wall_hooke_vs_reference)
{
    wall_case(CREF_HOOKE, 0);
    wall_case(CREF_HOOKE, 1);
}
TEST(wall_hooke_history_vs_reference)
{
    wall_case(CREF_HOOKE_HISTORY, 0);
    wall_case(CREF_HOOKE_HISTORY, 1);
}
TEST(wall_hertz_history_vs_reference)
{
    wall_case(CREF_HERTZ_HISTORY, 0);
    wall_case(CREF_HERTZ_HISTORY, 1);
}

/* Head-on Hooke pair: the normal relative velocity after the contact is -e
 * times the one before, e from the closed form. */
TEST(pair_hooke_restitution_closed_form)
{
    struct cref_system s;
    cref_case_pair(&s, CREF_HOOKE, 0);
    double meff = s.b[0].m * s.b[1].m / (s.b[0].m + s.b[1].m);
    double e = cref_hooke_restitution(s.kn, s.gamman, meff);
    struct cref_body g[2];
    if (run_case(&s, 2e-5, 0.1, g)) {
        CHECK(!"gravel run failed");
        return;
    }
    double v0 = s.b[0].v[0] - s.b[1].v[0], v1 = g[0].v[0] - g[1].v[0];
    printf("  restitution %.6f, closed form %.6f\n", -v1 / v0, e);
    CHECK_NEAR(-v1 / v0, e, 1e-3);
}

/* Head-on Hooke wall without gravity: rebound speed e v0, meff = m. */
TEST(wall_hooke_restitution_closed_form)
{
    struct cref_system s;
    cref_case_wall(&s, CREF_HOOKE, 0);
    s.grav[2] = 0.0;
    double e = cref_hooke_restitution(s.kn, s.gamman, s.b[0].m);
    struct cref_body g[1];
    if (run_case(&s, 2e-5, 0.15, g)) {
        CHECK(!"gravel run failed");
        return;
    }
    printf("  wall restitution %.6f, closed form %.6f\n", g[0].v[2] / -s.b[0].v[2], e);
    CHECK_NEAR(g[0].v[2] / -s.b[0].v[2], e, 1e-3);
}

/* Undamped head-on Hertz pair: elastic, and the contact lasts
 * 2 (dmax/v0) (2/5) B(2/5, 1/2) (closed form), measured from the separation
 * after the contact. */
TEST(pair_hertz_contact_time_closed_form)
{
    struct cref_system s;
    cref_case_pair(&s, CREF_HERTZ_HISTORY, 0);
    s.gamman = s.gammat = 0.0;
    double meff = s.b[0].m * s.b[1].m / (s.b[0].m + s.b[1].m);
    double reff = s.b[0].rad * s.b[1].rad / (s.b[0].rad + s.b[1].rad);
    double v0 = s.b[0].v[0] - s.b[1].v[0];
    double gap = (s.b[1].x[0] - s.b[0].x[0]) - (s.b[0].rad + s.b[1].rad);
    double t0 = gap / v0, tc = cref_hertz_contact_time(s.kn, reff, meff, v0);
    double T = t0 + 1.5 * tc;
    struct cref_body g[2];
    if (run_case(&s, 2e-5, T, g)) {
        CHECK(!"gravel run failed");
        return;
    }
    double v1 = g[1].v[0] - g[0].v[0];
    double sep = (g[1].x[0] - g[0].x[0]) - (s.b[0].rad + s.b[1].rad);
    double tc_meas = T - t0 - sep / v1;
    printf("  hertz contact time %.6g, closed form %.6g; restitution %.6f\n", tc_meas, tc, v1 / v0);
    CHECK_NEAR(v1 / v0, 1.0, 1e-4);
    CHECK_NEAR(tc_meas / tc, 1.0, 2e-3);
}

int main(void)
{
    RUN(pair_hooke_vs_reference);
    RUN(pair_hooke_history_vs_reference);
    RUN(pair_hertz_history_vs_reference);
    RUN(wall_hooke_vs_reference);
    RUN(wall_hooke_history_vs_reference);
    RUN(wall_hertz_history_vs_reference);
    RUN(pair_hooke_restitution_closed_form);
    RUN(wall_hooke_restitution_closed_form);
    RUN(pair_hertz_contact_time_closed_form);
    return 0;
}
