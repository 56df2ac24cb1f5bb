/* fix_check_timestep_gran.c - LIGGGHTS's `fix ID group check/timestep/gran
 * N fraction_r fraction_h [warn yes|no] [error yes|no] [vmax v]` (the
 * LIGGGHTS 3.8 fix_check_timestep_gran.cpp estimates, reproduced): every N
 * steps (end_of_step) the time step as a fraction of
 *   the Rayleigh time  min over the group of pi r sqrt(rho / G) / (0.1631 nu + 0.8766),
 *                      G = Y / (2 (1 + nu)) of the atom's type;
 *   the Hertz time     min over the group of 2.87 (m^2 / (r/2 Y*^2 v))^(1/5),
 *                      m = 4/3 pi r^3 rho (the whole mass, as LIGGGHTS), Y* of
 *                      (type, type), v = max(2 vmax, vmax + the largest node
 *                      speed of a moving mesh of the last wall/gran mesh fix),
 *                      vmax the largest particle speed or the vmax keyword;
 *                      no estimate (and a fraction of dt / 1e6) when v = 0;
 *   the skin           v dt / skin.
 * f_ID[1], f_ID[2], f_ID[3] give the three fractions (0 until the first
 * check). Above fraction_r, fraction_h or 1 (skin), and when atoms travel more
 * than the smallest radius in a step, it warns (warn yes, the default) or
 * stops (error yes) with LIGGGHTS's messages. Needs pair_style gran and the
 * youngsModulus and poissonsRatio properties. On several MPI ranks the
 * minima and maxima run over every rank's atoms (one process's values). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "comm.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "fix_mesh_surface.h"
#include "fix_property_global.h"
#include "pair.h"
#include "par.h"

struct cts {
    int nevery;
    double lim_r, lim_h, vmax_user;
    int warn, err;
    double frac[3];             /* rayleigh, hertz, skin */
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "fix check/timestep/gran expects N fraction_rayleigh fraction_hertz");
    struct cts c = {0};
    c.warn = 1;
    int i = 0;
    if (!strcmp(argv[0], "check_every_time")) /* LIGGGHTS's older spelling */
        i = 1;
    arg_need(g, argc, i, 2, "check/timestep/gran");
    c.nevery = arg_int(g, argv[i], "fix check/timestep/gran N");
    if (c.nevery < 1)
        gr_error(g, "fix check/timestep/gran: N must be >= 1, got %d", c.nevery);
    c.lim_r = arg_positive(g, argv[i + 1], "fix check/timestep/gran fraction_rayleigh");
    c.lim_h = arg_positive(g, argv[i + 2], "fix check/timestep/gran fraction_hertz");
    for (i += 3; i < argc; i += 2) {
        arg_need(g, argc, i, 1, argv[i]);
        if (!strcmp(argv[i], "warn"))
            c.warn = arg_yesno(g, argv[i + 1], "warn");
        else if (!strcmp(argv[i], "error"))
            c.err = arg_yesno(g, argv[i + 1], "error");
        else if (!strcmp(argv[i], "vmax"))
            c.vmax_user = arg_double(g, argv[i + 1], "vmax");
        else
            gr_error(g, "unknown fix check/timestep/gran keyword '%.64s' (expected warn, error "
                        "or vmax)", argv[i]);
    }
    struct cts *d = gr_malloc(g, sizeof *d);
    *d = c;
    f->data = d;
    f->hooks = HOOK_END_OF_STEP;
}

static void init(struct gravel *g, struct fix *f)
{
    (void)f;
    if (!g->styles.pair || strcmp(g->styles.pair->style->name, "gran"))
        gr_error(g, "Fix check/timestep/gran can only be used together with: gran");
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    (void)fpg_pertype(g, "youngsModulus", nt, "fix check/timestep/gran");
    (void)fpg_pertype(g, "poissonsRatio", nt, "fix check/timestep/gran");
}

/* The largest squared node speed of the moving meshes of the last fix
 * wall/gran that owns a mesh (LIGGGHTS's fwg). */
static double mesh_vmax_sq(struct gravel *g)
{
    int last = -1; /* the wall fix's position in the fix list */
    for (int k = 0; k < g->styles.nfix; k++) {
        const struct fix *m = g->styles.fix[k];
        if (fix_is_mesh_surface(m) && ((const struct mesh_surface *)m->data)->owner &&
            !strcmp(((const struct mesh_surface *)m->data)->owner->style->name, "wall/gran"))
            for (int q = 0; q < g->styles.nfix; q++)
                if (g->styles.fix[q] == ((const struct mesh_surface *)m->data)->owner && q > last)
                    last = q;
    }
    double vmax = 0;
    if (last < 0)
        return 0;
    for (int k = 0; k < g->styles.nfix; k++) {
        const struct fix *m = g->styles.fix[k];
        if (!fix_is_mesh_surface(m))
            continue;
        const struct mesh_surface *ms = m->data;
        if (ms->owner != g->styles.fix[last])
            continue;
        struct mesh_pose p;
        mesh_surface_pose(g, m->id, &p);
        if (!p.moving || ms->has_surface_vel) /* LIGGGHTS: isMoving(), not a conveyor's */
            continue;
        for (int v = 0; v < ms->m.nvert; v++) {
            const double *x0 = ms->m.vert + 3 * (size_t)v;
            double x[3], u[3];
            mesh_pose_point(&p, x0, x);
            mesh_pose_velocity(&p, x, u);
            double s = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
            if (s > vmax)
                vmax = s;
        }
    }
    return vmax;
}

static void check(struct gravel *g, struct fix *f)
{
    struct cts *c = f->data;
    if (g->step % c->nevery)
        return;
    run_sync_host(g);
    const struct atoms *a = &g->atoms;
    int nt = a->ntypes > 0 ? a->ntypes : 1;
    const char *who = "fix check/timestep/gran";
    const double *Y = fpg_pertype(g, "youngsModulus", nt, who);
    const double *nu = fpg_pertype(g, "poissonsRatio", nt, who);
    double rayleigh = DBL_MAX, rmin = DBL_MAX, vmax_sqr = 0;
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & f->groupbit))
            continue;
        const double rad = a->radius[i];
        const int t = a->type[i] - 1;
        const double density = a->rmass[i] / (4.0 * M_PI / 3.0 * rad * rad * rad);
        const double shear_mod = Y[t] / (2. * (nu[t] + 1.));
        const double tr = M_PI * rad * sqrt(density / shear_mod) / (0.1631 * nu[t] + 0.8766);
        if (tr < rayleigh)
            rayleigh = tr;
        const double *v = a->v + 3 * (size_t)i;
        const double s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (s > vmax_sqr)
            vmax_sqr = s;
        if (rad < rmin)
            rmin = rad;
    }
    if (par_on(g)) { /* every rank's atoms: minima and maxima, the same bits in any order */
        double lo[2] = {rayleigh, rmin}, hi[2] = {vmax_sqr, 0};
        comm_minmax(lo, hi, 2);
        rayleigh = lo[0], rmin = lo[1], vmax_sqr = hi[0];
    }
    if (c->vmax_user * c->vmax_user > vmax_sqr)
        vmax_sqr = c->vmax_user * c->vmax_user;
    const double vm = mesh_vmax_sq(g);
    const double vrel = fmax(2. * sqrt(vmax_sqr), sqrt(vmax_sqr) + sqrt(vm));
    double hertz = 1000000.;
    if (vrel != 0.0) {
        for (int i = 0; i < a->n; i++) {
            if (!(a->mask[i] & f->groupbit))
                continue;
            const int t = a->type[i] - 1;
            const double Eeff = 1. / ((1. - pow(nu[t], 2.)) / Y[t] + (1. - pow(nu[t], 2.)) / Y[t]);
            const double r = a->radius[i];
            const double density = a->rmass[i] / (4.0 * M_PI / 3.0 * r * r * r);
            const double meff = 4. * r * r * r * M_PI / 3. * density;
            const double reff = r / 2.;
            const double th = 2.87 * pow(meff * meff / (reff * Eeff * Eeff * vrel), 0.2);
            if (th < hertz)
                hertz = th;
        }
    }
    if (par_on(g)) {
        double lo[1] = {hertz}, hi[1] = {0};
        comm_minmax(lo, hi, 1);
        hertz = lo[0];
    }
    const double dt = g->dt, skin = g->neigh.skin;
    c->frac[0] = dt / rayleigh;
    c->frac[1] = dt / hertz;
    c->frac[2] = vrel * dt / skin;
    if (!(c->err || c->warn))
        return;
    char msg[256];
    for (int k = 0; k < 4; k++) {
        msg[0] = '\0';
        if (k == 0 && c->frac[0] > c->lim_r)
            snprintf(msg, sizeof msg, "time-step is %f %% of rayleigh time", c->frac[0] * 100.);
        if (k == 1 && c->frac[1] > c->lim_h)
            snprintf(msg, sizeof msg, "time-step is %f %% of hertz time", c->frac[1] * 100.);
        if (k == 2 && c->frac[2] > 1)
            snprintf(msg, sizeof msg, "time step too large or skin too small - particles may "
                     "relatively travel a distance of %f per time-step, but skin is %f",
                     vrel * dt, skin);
        if (k == 3 && vrel * dt > rmin)
            snprintf(msg, sizeof msg, "time step way too large - particles relativley move "
                     "further than the minimum radius in one step");
        if (!msg[0])
            continue;
        if (c->err)
            gr_error(g, "fix %s (check/timestep/gran): %s", f->id, msg);
        gr_warn(g, "%s", msg);
    }
}

static double vector(struct gravel *g, struct fix *f, int i)
{
    (void)g;
    return ((const struct cts *)f->data)->frac[i - 1];
}

const struct fix_style fix_style_check_timestep_gran = {
    .name = "check/timestep/gran",
    .create = create,
    .init = init,
    .end_of_step = check,
    .size_vector = 3,
    .vector = vector,
};
