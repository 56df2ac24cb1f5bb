/* velocity.c - `velocity group style args keyword value ...` (LAMMPS
 * velocity): create, set, scale, ramp, zero.
 *
 * create T seed: random velocities v = r / sqrt(m) with r uniform in
 * [-0.5, 0.5) (dist uniform, default) or standard normal (dist gaussian);
 * then, as LAMMPS, zero the total momentum (mom yes, default) and the angular
 * momentum (rot yes; default no), and rescale to temperature T in LAMMPS'
 * sense (compute temp): T = sum m v^2 / (dof kB) with dof = dim N - dim over the
 * group. The random numbers are LAMMPS's, bit for bit (src/core/random.c,
 * RanPark), so the velocities are those `lmp` gives on one process:
 *   loop all (default): one stream seeded with seed, three draws for every
 *     atom ID 1..N in ID order, kept for atoms in the group (IDs must be
 *     consecutive, as LAMMPS requires);
 *   loop local: one stream seeded with seed (+ the rank, 0), 100 warm-up
 *     draws, three draws per group atom in storage order;
 *   loop geom: per group atom, the stream is reseeded from seed and the
 *     atom's coordinates (RanPark::reset), so an atom's velocity (before
 *     momentum removal and scaling) depends only on where it is.
 * set/ramp values are in lattice units (multiplied by the lattice spacing)
 * unless `units box`, LAMMPS' default; set components may be v_name of an
 * equal- or atom-style variable (not scaled). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "compute.h"
#include "temperature.h"
#include "variable.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "random.h"

enum vloop { LOOP_ALL, LOOP_LOCAL, LOOP_GEOM };

struct vopts {
    int gaussian, sum, mom, rot, lattice_units;
    enum vloop loop;
    char temp[GR_NAMELEN];      /* temp ID: the temperature compute ("" none) */
    int bias;                   /* bias yes: its velocity bias kept */
};

/* Boltzmann constant in the unit system: LAMMPS's force->boltz values
 * (CODATA 2006, as LAMMPS 2021 update.cpp), not the exact SI 2019 value, so
 * that `velocity create` scales to LAMMPS's velocities. */
static double boltz(const struct gravel *g)
{
    switch (g->dom.units) {
    case UNITS_SI: return 1.3806504e-23;
    case UNITS_CGS: return 1.3806504e-16;
    default: return 1.0;
    }
}

/* Temperature of a group as LAMMPS compute temp: sum of m v.v in storage
 * order, times mvv2e / (dof kB) with dof = dim N - dim (LAMMPS's operation order,
 * so a rescale to T gives its factor to the bit). Returns -1 when dof <= 0. */
static double group_temp(const struct gravel *g, int ig)
{
    int dim = g->dom.dimension;
    double dof = (double)dim * (double)group_count(g, ig) - dim;
    if (dof <= 0)
        return -1;
    const struct atoms *a = &g->atoms;
    unsigned bit = group_bit(ig);
    double t = 0;
    for (int i = 0; i < a->n; i++)
        if (a->mask[i] & bit) {
            const double *v = a->v + 3 * i;
            t += (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * a->rmass[i];
        }
    return t * (1.0 / (dof * boltz(g)));
}

static void zero_momentum(struct gravel *g, int ig)
{
    double m = group_mass(g, ig), vcm[3];
    if (!(m > 0))
        return;
    group_vcm(g, ig, m, vcm);
    unsigned bit = group_bit(ig);
    for (int i = 0; i < g->atoms.n; i++)
        if (g->atoms.mask[i] & bit)
            for (int d = 0; d < 3; d++)
                g->atoms.v[3 * i + d] -= vcm[d];
}

static void zero_rotation(struct gravel *g, int ig)
{
    double m = group_mass(g, ig), xcm[3], L[3], I[3][3], w[3];
    if (!(m > 0))
        return;
    group_xcm(g, ig, m, xcm);
    group_angmom(g, ig, xcm, L);
    group_inertia(g, ig, xcm, I);
    group_omega(L, I, w);
    unsigned bit = group_bit(ig);
    struct atoms *a = &g->atoms;
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & bit))
            continue;
        double u[3];
        domain_unmap(g, a->x + 3 * i, a->image + 3 * i, u);
        double dx = u[0] - xcm[0], dy = u[1] - xcm[1], dz = u[2] - xcm[2];
        a->v[3 * i + 0] -= w[1] * dz - w[2] * dy;
        a->v[3 * i + 1] -= w[2] * dx - w[0] * dz;
        a->v[3 * i + 2] -= w[0] * dy - w[1] * dx;
    }
}

static void draw3(struct rng_park *rng, int gaussian, double r[3])
{
    for (int d = 0; d < 3; d++)
        r[d] = gaussian ? rng_park_gaussian(rng) : rng_park_uniform(rng) - 0.5;
}

/* v = r / sqrt(m); in 2d vz = 0 (the draw is made all the same, as LAMMPS). */
static void assign(struct atoms *a, int i, const double r[3], int dim)
{
    double f = 1.0 / sqrt(a->rmass[i]);
    for (int d = 0; d < 3; d++)
        a->v[3 * i + d] = d < dim ? r[d] * f : 0.0;
}

struct create_res {
    int *map;
    double *vsave;
    double *vbias;              /* bias yes: the bias taken out */
};

/* The temperature compute of `temp ID` (NULL without one); bias yes needs
 * one with a velocity bias */
static struct temp_state *velocity_temp(struct gravel *g, const struct vopts *o)
{
    if (!o->temp[0]) {
        if (o->bias)
            gr_error(g, "cannot use velocity bias command without temp keyword");
        return NULL;
    }
    struct compute *c = compute_get(g, o->temp, "velocity temp");
    if (!c->temp)
        gr_error(g, "velocity temperature ID %s does not compute temperature", o->temp);
    if (o->bias && !temp_has_bias(c->temp))
        gr_error(g, "velocity temperature ID %s does not compute a velocity bias (temp/com, "
                    "temp/partial, temp/region do)",
                 o->temp);
    return c->temp;
}

#define VELOCITY_WARMUP 100 /* LAMMPS velocity.cpp WARMUP, loop local */

static void do_create(struct gravel *g, int ig, double t_want, int seed,
                      const struct vopts *o, struct create_res *res)
{
    struct atoms *a = &g->atoms;
    unsigned bit = group_bit(ig);
    if (group_count(g, ig) < 2)
        gr_error(g, "group '%s' needs at least 2 atoms to define a temperature",
                 g->groups.name[ig]);
    for (int i = 0; i < a->n; i++)
        if ((a->mask[i] & bit) && !(a->rmass[i] > 0))
            gr_error(g, "atom %lld has mass %g: velocity create needs positive masses",
                     (long long)a->tag[i], a->rmass[i]);
    struct temp_state *tc = velocity_temp(g, o);
    if (o->sum) { /* LAMMPS: the velocities as they are, bias included */
        res->vsave = gr_malloc(g, (size_t)a->n * 3 * sizeof(double));
        memcpy(res->vsave, a->v, (size_t)a->n * 3 * sizeof(double));
    }
    if (o->bias) /* LAMMPS: the bias taken out before the velocities are made */
        res->vbias = temp_bias_remove(g, tc);
    struct rng_park rng;
    double r[3];
    if (o->loop == LOOP_GEOM) {
        rng_park_init(&rng, 1);
        for (int i = 0; i < a->n; i++) {
            if (!(a->mask[i] & bit))
                continue;
            rng_park_reset_coord(&rng, seed, a->x + 3 * i);
            draw3(&rng, o->gaussian, r);
            assign(a, i, r, g->dom.dimension);
        }
    } else if (o->loop == LOOP_LOCAL) {
        rng_park_init(&rng, seed);
        for (int k = 0; k < VELOCITY_WARMUP; k++)
            rng_park_uniform(&rng);
        for (int i = 0; i < a->n; i++) {
            if (!(a->mask[i] & bit))
                continue;
            draw3(&rng, o->gaussian, r);
            assign(a, i, r, g->dom.dimension);
        }
    } else {
        /* IDs 1..N: draws for every ID, assigned to the group's atoms */
        bigint n = a->n;
        int consecutive = n > 0;
        for (int i = 0; i < a->n && consecutive; i++)
            consecutive = a->tag[i] >= 1 && a->tag[i] <= n;
        if (consecutive) {
            res->map = gr_malloc(g, (size_t)(n + 1) * sizeof(int));
            for (bigint t = 0; t <= n; t++)
                res->map[t] = -1;
            for (int i = 0; i < a->n && consecutive; i++) {
                consecutive = res->map[a->tag[i]] < 0;
                res->map[a->tag[i]] = i;
            }
        }
        if (!consecutive)
            gr_error(g, "loop all needs atom IDs 1..N without gaps (as LAMMPS); "
                        "use loop geom or loop local");
        rng_park_init(&rng, seed);
        for (bigint t = 1; t <= n; t++) {
            draw3(&rng, o->gaussian, r);
            int i = res->map[t];
            if (a->mask[i] & bit)
                assign(a, i, r, g->dom.dimension);
        }
    }
    if (o->mom)
        zero_momentum(g, ig);
    if (o->rot)
        zero_rotation(g, ig);
    /* LAMMPS: with a bias, the plain temperature of the group's new velocities */
    double t = tc && !o->bias ? temp_scalar(g, tc) : group_temp(g, ig);
    if (!(t > 0))
        gr_error(g, "cannot rescale a zero temperature");
    double f = sqrt(t_want / t);
    for (int i = 0; i < a->n; i++)
        if (a->mask[i] & bit)
            for (int d = 0; d < 3; d++)
                a->v[3 * i + d] *= f;
    if (res->vbias) { /* LAMMPS: reapply_bias_all, restore_bias_all, then sum */
        temp_bias_reapply(g, tc);
        temp_bias_restore(g, tc, res->vbias);
        res->vbias = NULL;
    }
    for (int i = 0; res->vsave && i < a->n; i++)
        if (a->mask[i] & bit)
            for (int d = 0; d < 3; d++)
                a->v[3 * i + d] += res->vsave[3 * i + d];
}

static void parse_opts(struct gravel *g, int argc, char **argv, int start, struct vopts *o)
{
    o->gaussian = 0;
    o->sum = 0;
    o->mom = 1;
    o->rot = 0;
    o->lattice_units = 1;
    o->loop = LOOP_ALL; /* LAMMPS default */
    o->temp[0] = '\0';
    o->bias = 0;
    for (int i = start; i < argc; i++) {
        const char *kw = argv[i];
        arg_need(g, argc, i, 1, kw);
        const char *v = argv[++i];
        if (!strcmp(kw, "dist")) {
            if (!strcmp(v, "uniform"))
                o->gaussian = 0;
            else if (!strcmp(v, "gaussian"))
                o->gaussian = 1;
            else
                gr_error(g, "dist must be uniform or gaussian, got '%.32s'", v);
        } else if (!strcmp(kw, "sum")) {
            o->sum = arg_yesno(g, v, "sum");
        } else if (!strcmp(kw, "mom")) {
            o->mom = arg_yesno(g, v, "mom");
        } else if (!strcmp(kw, "rot")) {
            o->rot = arg_yesno(g, v, "rot");
        } else if (!strcmp(kw, "loop")) {
            if (!strcmp(v, "all"))
                o->loop = LOOP_ALL;
            else if (!strcmp(v, "local"))
                o->loop = LOOP_LOCAL;
            else if (!strcmp(v, "geom"))
                o->loop = LOOP_GEOM;
            else
                gr_error(g, "loop must be all, local or geom, got '%.32s'", v);
        } else if (!strcmp(kw, "units")) {
            o->lattice_units = domain_parse_units_kw(g, v);
        } else if (!strcmp(kw, "bias")) {
            o->bias = arg_yesno(g, v, "bias");
        } else if (!strcmp(kw, "temp")) {
            if (strlen(v) >= GR_NAMELEN)
                gr_error(g, "temp compute ID '%.64s...' is too long", v);
            strcpy(o->temp, v);
        } else if (!strcmp(kw, "rigid")) {
            gr_error(g, "keyword '%s' is not supported", kw);
        } else {
            gr_error(g, "unknown keyword '%.32s'", kw);
        }
    }
}

void cmd_velocity(struct gravel *g, int argc, char **argv)
{
    int ig = arg_group(g, argv[0]);
    const char *style = argv[1];
    struct atoms *a = &g->atoms;
    unsigned bit = group_bit(ig);
    struct vopts o;
    if (!strcmp(style, "create")) {
        arg_need(g, argc, 1, 2, "create");
        double t = arg_positive(g, argv[2], "temperature");
        int seed = arg_int(g, argv[3], "seed");
        if (seed <= 0)
            gr_error(g, "seed must be a positive integer, got %s", argv[3]);
        parse_opts(g, argc, argv, 4, &o);
        struct create_res res = {NULL, NULL, NULL};
        jmp_buf *outer = g->err.jmp, here;
        g->err.jmp = &here;
        if (setjmp(here)) {
            g->err.jmp = outer;
            free(res.map);
            free(res.vsave);
            free(res.vbias);
            if (outer)
                longjmp(*outer, 1);
            gr_report_error(g);
            exit(1);
        }
        do_create(g, ig, t, seed, &o, &res);
        g->err.jmp = outer;
        free(res.map);
        free(res.vsave);
    } else if (!strcmp(style, "set")) {
        arg_need(g, argc, 1, 3, "set");
        /* a component: a number (lattice-scaled unless units box), NULL, or
         * v_name of an equal- or atom-style variable (not scaled, as LAMMPS) */
        int has[3], isvar[3] = {0, 0, 0};
        double val[3] = {0, 0, 0};
        for (int d = 0; d < 3; d++) {
            const char *s = argv[2 + d];
            has[d] = strcmp(s, "NULL") != 0;
            if (has[d] && !strncmp(s, "v_", 2) && s[2]) {
                if (!var_exists(g, s + 2))
                    gr_error(g, "variable '%s' of velocity set does not exist", s + 2);
                isvar[d] = var_is_atom(g, s + 2) ? 2 : 1;
                if (isvar[d] == 1)
                    val[d] = var_compute_equal(g, s + 2);
            } else if (has[d]) {
                val[d] = arg_double(g, s, "velocity component");
            }
        }
        parse_opts(g, argc, argv, 5, &o);
        double sc[3];
        domain_unit_scale(g, o.lattice_units, sc);
        double *pv[3] = {NULL, NULL, NULL};
        for (int d = 0; d < 3; d++) {
            if (isvar[d])
                sc[d] = 1.0;
            if (isvar[d] == 2)
                pv[d] = var_atom_values(g, argv[2 + d] + 2);
        }
        for (int i = 0; i < a->n; i++)
            if (a->mask[i] & bit)
                for (int d = 0; d < 3; d++)
                    if (has[d])
                        a->v[3 * i + d] = (pv[d] ? pv[d][i] : val[d]) * sc[d] +
                                          (o.sum ? a->v[3 * i + d] : 0.0);
        for (int d = 0; d < 3; d++)
            free(pv[d]);
    } else if (!strcmp(style, "scale")) {
        arg_need(g, argc, 1, 1, "scale");
        double t_want = arg_nonneg(g, argv[2], "temperature");
        parse_opts(g, argc, argv, 3, &o);
        struct temp_state *tc = velocity_temp(g, &o);
        double t = tc ? temp_scalar(g, tc) : group_temp(g, ig);
        if (!(t > 0))
            gr_error(g, "cannot rescale a zero temperature");
        double f = sqrt(t_want / t);
        if (o.bias) { /* LAMMPS: the bias out, the group scaled, the bias back */
            temp_scale_thermal(g, tc, bit, f);
        } else {
            for (int i = 0; i < a->n; i++)
                if (a->mask[i] & bit)
                    for (int d = 0; d < 3; d++)
                        a->v[3 * i + d] *= f;
        }
    } else if (!strcmp(style, "ramp")) {
        arg_need(g, argc, 1, 6, "ramp");
        static const char *vd[3] = {"vx", "vy", "vz"}, *cd[3] = {"x", "y", "z"};
        int v_dim = -1, c_dim = -1;
        for (int d = 0; d < 3; d++) {
            if (!strcmp(argv[2], vd[d]))
                v_dim = d;
            if (!strcmp(argv[5], cd[d]))
                c_dim = d;
        }
        if (v_dim < 0)
            gr_error(g, "ramp velocity component must be vx, vy or vz, got '%.32s'", argv[2]);
        if (c_dim < 0)
            gr_error(g, "ramp coordinate must be x, y or z, got '%.32s'", argv[5]);
        double vlo = arg_double(g, argv[3], "vlo"), vhi = arg_double(g, argv[4], "vhi");
        double clo = arg_double(g, argv[6], "clo"), chi = arg_double(g, argv[7], "chi");
        if (!(clo < chi))
            gr_error(g, "ramp needs clo < chi, got %s %s", argv[6], argv[7]);
        parse_opts(g, argc, argv, 8, &o);
        double sc[3];
        domain_unit_scale(g, o.lattice_units, sc);
        vlo *= sc[v_dim];
        vhi *= sc[v_dim];
        clo *= sc[c_dim];
        chi *= sc[c_dim];
        for (int i = 0; i < a->n; i++) {
            if (!(a->mask[i] & bit))
                continue;
            double f = (a->x[3 * i + c_dim] - clo) / (chi - clo);
            f = fmin(fmax(f, 0.0), 1.0);
            double vr = vlo + f * (vhi - vlo);
            a->v[3 * i + v_dim] = vr + (o.sum ? a->v[3 * i + v_dim] : 0.0);
        }
    } else if (!strcmp(style, "zero")) {
        arg_need(g, argc, 1, 1, "zero");
        int linear = !strcmp(argv[2], "linear");
        if (!linear && strcmp(argv[2], "angular") != 0)
            gr_error(g, "zero must be linear or angular, got '%.32s'", argv[2]);
        parse_opts(g, argc, argv, 3, &o);
        if (linear)
            zero_momentum(g, ig);
        else
            zero_rotation(g, ig);
    } else {
        gr_error(g, "unknown style '%.32s': expected create, set, scale, ramp or zero", style);
    }
}
