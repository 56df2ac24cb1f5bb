/* test_contact_ref.c - checks the independent contact reference (contact_ref.h)
 * against closed forms and conservation laws, so that the engine tests that
 * compare with it compare with something verified.
 *
 * Run with arguments it prints a reference state instead:
 *     test_contact_ref MODEL pair|wall T
 * or the deck that sets up that case in gravel or LAMMPS:
 *     test_contact_ref deck MODEL pair|wall DT NSTEPS
 * MODEL = hooke | hooke/history | hertz/history; the initial state is the
 * oblique case of test_contact_pair.c / test_contact_wall.c (cref_case_*). */
#include <stdlib.h>

#include "test.h"
#include "contact_ref.h"
#include "contact_cases.h"

/* Two equal-velocity spheres head-on (no gravity): the normal relative
 * velocity after the contact is -e times the one before, with e and the
 * contact time from the damped-oscillator closed form. */
TEST(hooke_head_on_restitution)
{
    for (int hist = 0; hist < 2; hist++) {
        struct cref_system s;
        cref_case_pair(&s, hist ? CREF_HOOKE_HISTORY : CREF_HOOKE, 0);
        double meff = s.b[0].m * s.b[1].m / (s.b[0].m + s.b[1].m);
        double gap = (s.b[1].x[0] - s.b[0].x[0]) - (s.b[0].rad + s.b[1].rad);
        double v0 = s.b[0].v[0] - s.b[1].v[0];
        double t0 = gap / v0;
        double tc = cref_hooke_contact_time(s.kn, s.gamman, meff);
        double e = cref_hooke_restitution(s.kn, s.gamman, meff);
        /* mid-contact overlap */
        struct cref_system m = s;
        CHECK(cref_solve(&m, t0 + 0.3 * tc, 1e-3) == 0);
        double d = s.b[0].rad + s.b[1].rad - (m.b[1].x[0] - m.b[0].x[0]);
        CHECK_NEAR(d, cref_hooke_overlap(s.kn, s.gamman, meff, v0, 0.3 * tc), 1e-10);
        /* after the contact */
        CHECK(cref_solve(&s, t0 + 2.0 * tc, 1e-3) == 0);
        double v1 = s.b[0].v[0] - s.b[1].v[0];
        CHECK_NEAR(v1, -e * v0, 1e-9);
        /* separation grows at v1 from the end of the contact */
        double sep = (s.b[1].x[0] - s.b[0].x[0]) - (s.b[0].rad + s.b[1].rad);
        CHECK_NEAR(sep, -v1 * (2.0 * tc - tc), 1e-9);
        /* head-on: no spin, no tangential motion */
        CHECK_NEAR(s.b[0].w[2], 0.0, 1e-14);
        CHECK_NEAR(s.b[0].v[1], 0.0, 1e-14);
    }
}

/* Undamped Hertz head-on: elastic (e = 1) and the contact time of the closed form. */
TEST(hertz_head_on_contact_time)
{
    struct cref_system s;
    cref_case_pair(&s, CREF_HERTZ_HISTORY, 0);
    s.gamman = s.gammat = 0.0;
    double meff = s.b[0].m * s.b[1].m / (s.b[0].m + s.b[1].m);
    double reff = s.b[0].rad * s.b[1].rad / (s.b[0].rad + s.b[1].rad);
    double gap = (s.b[1].x[0] - s.b[0].x[0]) - (s.b[0].rad + s.b[1].rad);
    double v0 = s.b[0].v[0] - s.b[1].v[0];
    double tc = cref_hertz_contact_time(s.kn, reff, meff, v0);
    double tend = gap / v0 + 1.5 * tc;
    CHECK(cref_solve(&s, tend, 1e-3) == 0);
    double v1 = s.b[0].v[0] - s.b[1].v[0];
    CHECK_NEAR(v1, -v0, 1e-9);
    double sep = (s.b[1].x[0] - s.b[0].x[0]) - (s.b[0].rad + s.b[1].rad);
    /* sep = v0 (tend - t0 - tc) = v0 * 0.5 tc */
    CHECK_NEAR(sep, v0 * 0.5 * tc, 1e-9);
}

/* Undamped oblique Hooke/history impact that sticks: kinetic + rotational +
 * normal spring + tangential spring energy is conserved, linear momentum
 * exactly. */
TEST(history_oblique_energy)
{
    struct cref_system s;
    cref_case_pair(&s, CREF_HOOKE_HISTORY, 1);
    s.gamman = s.gammat = 0.0;
    s.xmu = 1e4;
    double p0[3] = {0, 0, 0}, e0 = 0.0;
    for (int b = 0; b < 2; b++) {
        double in = 0.4 * s.b[b].m * s.b[b].rad * s.b[b].rad;
        for (int k = 0; k < 3; k++) {
            p0[k] += s.b[b].m * s.b[b].v[k];
            e0 += 0.5 * s.b[b].m * s.b[b].v[k] * s.b[b].v[k] + 0.5 * in * s.b[b].w[k] * s.b[b].w[k];
        }
    }
    /* stop in mid-contact so the springs hold energy */
    double t = 0.07;
    CHECK(cref_solve(&s, t, 1e-3) == 0);
    CHECK(s.ncontact_steps > 0);
    double p1[3] = {0, 0, 0}, e1 = 0.0, del[3];
    for (int b = 0; b < 2; b++) {
        double in = 0.4 * s.b[b].m * s.b[b].rad * s.b[b].rad;
        for (int k = 0; k < 3; k++) {
            p1[k] += s.b[b].m * s.b[b].v[k];
            e1 += 0.5 * s.b[b].m * s.b[b].v[k] * s.b[b].v[k] + 0.5 * in * s.b[b].w[k] * s.b[b].w[k];
        }
    }
    for (int k = 0; k < 3; k++) del[k] = s.b[0].x[k] - s.b[1].x[k];
    double r = sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
    double d = s.b[0].rad + s.b[1].rad - r;
    CHECK(d > 0.0);
    e1 += 0.5 * s.kn * d * d;
    e1 += 0.5 * s.kt * (s.s[0] * s.s[0] + s.s[1] * s.s[1] + s.s[2] * s.s[2]);
    CHECK(s.s[0] * s.s[0] + s.s[1] * s.s[1] + s.s[2] * s.s[2] > 0.0);
    CHECK_NEAR(e1, e0, 1e-9 * e0);
    for (int k = 0; k < 3; k++) CHECK_NEAR(p1[k], p0[k], 1e-12);
    /* s stays in the tangent plane */
    CHECK_NEAR((s.s[0] * del[0] + s.s[1] * del[1] + s.s[2] * del[2]) / r, 0.0, 1e-10);
}

/* Sphere on a flat wall head-on: restitution with meff = m. */
TEST(wall_head_on_restitution)
{
    struct cref_system s;
    cref_case_wall(&s, CREF_HOOKE, 0);
    s.grav[2] = 0.0;
    double v0 = -s.b[0].v[2];
    double t0 = (s.b[0].x[2] - s.wall_z - s.b[0].rad) / v0;
    double tc = cref_hooke_contact_time(s.kn, s.gamman, s.b[0].m);
    CHECK(cref_solve(&s, t0 + 1.2 * tc, 1e-3) == 0);
    CHECK_NEAR(s.b[0].v[2], cref_hooke_restitution(s.kn, s.gamman, s.b[0].m) * v0, 1e-9);
}

static void print_state(const char *model, const char *kind, double t)
{
    enum cref_model m = !strcmp(model, "hooke") ? CREF_HOOKE
                        : !strcmp(model, "hooke/history") ? CREF_HOOKE_HISTORY
                                                          : CREF_HERTZ_HISTORY;
    struct cref_system s;
    if (!strcmp(kind, "wall")) cref_case_wall(&s, m, 1);
    else cref_case_pair(&s, m, 1);
    if (cref_solve(&s, t, 1e-3) != 0) {
        fprintf(stderr, "ODE solver failed\n");
        exit(1);
    }
    printf("# t = %.15g  max |Ft|/(mu |Fn|) = %.6g\n", t, s.max_slip_ratio);
    printf("# id x y z vx vy vz omegax omegay omegaz\n");
    for (int b = 0; b < s.nbody; b++)
        printf("%d %.15g %.15g %.15g %.15g %.15g %.15g %.15g %.15g %.15g\n", b + 1, s.b[b].x[0],
               s.b[b].x[1], s.b[b].x[2], s.b[b].v[0], s.b[b].v[1], s.b[b].v[2], s.b[b].w[0],
               s.b[b].w[1], s.b[b].w[2]);
}

int main(int argc, char **argv)
{
    if (argc == 6 && !strcmp(argv[1], "deck")) { /* deck MODEL pair|wall DT NSTEPS */
        enum cref_model m = !strcmp(argv[2], "hooke") ? CREF_HOOKE
                            : !strcmp(argv[2], "hooke/history") ? CREF_HOOKE_HISTORY
                                                                : CREF_HERTZ_HISTORY;
        struct cref_system s;
        if (!strcmp(argv[3], "wall")) cref_case_wall(&s, m, 1);
        else cref_case_pair(&s, m, 1);
        static char buf[8192];
        cref_deck(&s, atof(argv[4]), atol(argv[5]), buf, sizeof buf);
        fputs(buf, stdout);
        return 0;
    }
    if (argc == 4) {
        print_state(argv[1], argv[2], atof(argv[3]));
        return 0;
    }
    RUN(hooke_head_on_restitution);
    RUN(hertz_head_on_contact_time);
    RUN(history_oblique_energy);
    RUN(wall_head_on_restitution);
    return 0;
}
