/* contact_cases.h - the collision cases shared by the reference self-test and
 * the engine contact tests, and the gravel deck that sets each one up.
 *
 * Pair cases: sphere 1 (diameter 1, density 1.5) and sphere 2 (diameter 0.8,
 * density 2.5), 0.05 apart, closing at 2 (head-on along x), or offset in y and
 * z, with extra tangential velocity and spin (oblique). Wall cases: the
 * sphere 1 falling onto the floor z = -1 under gravity 1, straight down
 * (head-on) or with horizontal velocity and spin (oblique).
 * Coefficients follow LAMMPS' NULL defaults: kt = 2/7 kn, gammat = gamman/2
 * (dampflag 1) for gran/hooke; for the history models the oblique cases use
 * dampflag 0 (gammat = 0) and xmu = 0.3 so they stick and then slide. */
#ifndef CONTACT_CASES_H
#define CONTACT_CASES_H

#include <stdio.h>
#include "contact_ref.h"

static inline double cref_sphere_mass(double diameter, double density)
{
    return 4.0 / 3.0 * M_PI * pow(0.5 * diameter, 3) * density;
}

static void cref_coeffs(struct cref_system *s, enum cref_model m, int oblique)
{
    s->model = m;
    s->kn = m == CREF_HERTZ_HISTORY ? 20000.0 : 2000.0;
    s->gamman = m == CREF_HERTZ_HISTORY ? 500.0 : 50.0;
    s->kt = 2.0 / 7.0 * s->kn;
    s->gammat = 0.5 * s->gamman;
    s->xmu = 0.5;
    if (m != CREF_HOOKE && oblique) {
        s->gammat = 0.0; /* dampflag 0 */
        s->xmu = 0.3;
    }
}

static void cref_case_pair(struct cref_system *s, enum cref_model m, int oblique)
{
    memset(s, 0, sizeof *s);
    cref_coeffs(s, m, oblique);
    s->nbody = 2;
    s->b[0] = (struct cref_body){{-0.5, 0, 0}, {1, 0, 0}, {0, 0, 0}, 0.5, cref_sphere_mass(1.0, 1.5)};
    s->b[1] = (struct cref_body){{0.45, 0, 0}, {-1, 0, 0}, {0, 0, 0}, 0.4, cref_sphere_mass(0.8, 2.5)};
    if (oblique) {
        s->b[1].x[0] = 0.45;
        s->b[1].x[1] = 0.3;
        s->b[1].x[2] = 0.05;
        s->b[0].v[1] = 0.1;
        s->b[1].v[2] = 0.2;
        s->b[0].w[0] = 0.5;
        s->b[1].w[2] = 3.0;
    }
}

static void cref_case_wall(struct cref_system *s, enum cref_model m, int oblique)
{
    memset(s, 0, sizeof *s);
    cref_coeffs(s, m, oblique);
    s->nbody = 1;
    s->wall_z = -1.0;
    s->grav[2] = -1.0;
    s->b[0] = (struct cref_body){{0.3, -0.2, -0.45}, {0, 0, -1}, {0, 0, 0}, 0.5, cref_sphere_mass(1.0, 1.5)};
    if (oblique) {
        s->b[0].v[0] = 0.8;
        s->b[0].v[1] = 0.3;
        s->b[0].w[0] = 1.0;
        s->b[0].w[1] = -2.0;
        s->b[0].w[2] = 0.5;
    }
}

static const char *cref_model_name(enum cref_model m)
{
    return m == CREF_HOOKE ? "hooke" : m == CREF_HOOKE_HISTORY ? "hooke/history" : "hertz/history";
}

/* The gravel (and LAMMPS) deck for case s run for nsteps of dt. Returns the
 * length written (truncation is a test bug). */
static int cref_deck(const struct cref_system *s, double dt, long nsteps, char *buf, size_t n)
{
    int len = 0;
#define EMIT(...) len += snprintf(buf + len, len < (int)n ? n - len : 0, __VA_ARGS__)
    const char *name = cref_model_name(s->model);
    int dampflag = s->gammat > 0.0;
    EMIT("units lj\natom_style sphere\nboundary f f f\ncomm_modify vel yes\n"
         "region box block -4 4 -4 4 -4 4\ncreate_box 1 box\n");
    for (int b = 0; b < s->nbody; b++)
        EMIT("create_atoms 1 single %.17g %.17g %.17g units box\n", s->b[b].x[0], s->b[b].x[1],
             s->b[b].x[2]);
    for (int b = 0; b < s->nbody; b++) {
        double dens = s->b[b].m / (4.0 / 3.0 * M_PI * pow(s->b[b].rad, 3));
        EMIT("set atom %d diameter %.17g density %.17g\n", b + 1, 2.0 * s->b[b].rad, dens);
        EMIT("group g%d id %d\n", b + 1, b + 1);
        EMIT("velocity g%d set %.17g %.17g %.17g units box\n", b + 1, s->b[b].v[0], s->b[b].v[1],
             s->b[b].v[2]);
        EMIT("set atom %d omega %.17g %.17g %.17g\n", b + 1, s->b[b].w[0], s->b[b].w[1],
             s->b[b].w[2]);
    }
    EMIT("pair_style gran/%s %.17g %.17g %.17g %.17g %.17g %d\npair_coeff * *\n", name, s->kn,
         s->kt, s->gamman, dampflag ? s->gammat : 0.0, s->xmu, dampflag);
    EMIT("neighbor 0.2 bin\ntimestep %.17g\nfix 1 all nve/sphere\n", dt);
    if (s->nbody == 1) {
        EMIT("fix 2 all gravity %.17g vector 0 0 -1\n", -s->grav[2]);
        EMIT("fix 3 all wall/gran %s %.17g %.17g %.17g %.17g %.17g %d zplane %.17g NULL\n", name,
             s->kn, s->kt, s->gamman, dampflag ? s->gammat : 0.0, s->xmu, dampflag, s->wall_z);
    }
    EMIT("thermo 0\nrun %ld\n", nsteps);
#undef EMIT
    return len;
}

#endif
