/* accuracy_map.c - `gravel -check deck` and `run N accuracy`: what the
 * scene's time step costs in accuracy (doc/accuracy_map.md).
 *
 * The scene's own contact law (its pair_style and pair_coeff lines, replayed
 * verbatim), particle size and mass (the lightest particle), impact speed and
 * precision are put on isolated head-on collisions of two such particles in
 * a fresh gravel instance: NPHASE pairs whose contacts start at phases 0,
 * 1/NPHASE, ... of a step, run at a reference step (converged, REF_STEPS per
 * collision) and at the scene's dt times 0.5, 1 and 2. Each row reports the
 * worst over the phases of: the restitution against the reference's, the
 * largest overlap / radius (and its error), the contact duration's error, and
 * the cost of that dt relative to the scene's (steps per simulated time). The
 * physics is the engine's own: the replay runs the same kernels.
 *
 * The impact speed is twice the fastest particle's speed (two particles
 * approaching), or with everything at rest the free-fall speed over the box
 * height under fix gravity, else 1 (units of the scene). */
#include "accuracy_map.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "fileio.h"
#include "fix.h"
#include "gravel.h"
#include "input.h"
#include "log.h"
#include "pair.h"

enum { NPHASE = 4, REF_STEPS = 400 };

struct replay {
    double e;           /* worst (farthest from the reference) restitution */
    double ov;          /* largest overlap / radius */
    double tc;          /* contact duration (worst) */
    double e_all[NPHASE], tc_all[NPHASE];
    int ok;
};

static const char *units_name(const struct gravel *g)
{
    return g->dom.units == UNITS_SI ? "si" : g->dom.units == UNITS_CGS ? "cgs" : "lj";
}

/* The replay deck: NPHASE pairs along x, 20 r apart in y; pair k starts
 * (k / NPHASE + 0.5 ... ) of a step from contact. */
static char *replay_deck(const struct gravel *g, double r, double m, int type, double V,
                         double dt, double tcol)
{
    size_t cap = 16384 + strlen(g->styles.pair_cmds);
    char *s = malloc(cap);
    if (!s)
        return NULL;
    int n = 0, nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    double L = 4 * r, Y = 20 * r * NPHASE;
    n += snprintf(s + n, cap - n,
                  "units %s\natom_style sphere\nboundary f f f\n"
                  "region box block %.17g %.17g %.17g %.17g %.17g %.17g\ncreate_box %d box\n",
                  units_name(g), -L, L, -r * 4, Y, -L, L, nt);
    for (int k = 0; k < NPHASE; k++) {
        double gap = ((double)k / NPHASE + 0.5) * V * dt;
        n += snprintf(s + n, cap - n,
                      "create_atoms %d single %.17g %.17g 0\ncreate_atoms %d single %.17g %.17g 0\n",
                      type, -r - 0.5 * gap, 20 * r * k, type, r + 0.5 * gap, 20 * r * k);
    }
    n += snprintf(s + n, cap - n, "set atom * diameter %.17g\nset atom * mass %.17g\n", 2 * r, m);
    for (int k = 0; k < NPHASE; k++)
        n += snprintf(s + n, cap - n,
                      "group a%d id %d\ngroup b%d id %d\nvelocity a%d set %.17g 0 0\n"
                      "velocity b%d set %.17g 0 0\n"
                      "variable o%d equal %.17g-(x[%d]-x[%d])\nvariable u%d equal vx[%d]-vx[%d]\n",
                      k, 2 * k + 1, k, 2 * k + 2, k, 0.5 * V, k, -0.5 * V, k, 2 * r, 2 * k + 2,
                      2 * k + 1, k, 2 * k + 1, 2 * k + 2);
    n += snprintf(s + n, cap - n, "%s", g->styles.pair_cmds);
    n += snprintf(s + n, cap - n,
                  "neighbor %.17g bin\nneigh_modify every 1 delay 0 check no\n"
                  "fix accuracy_nve all nve/sphere\ntimestep %.17g\nthermo_style custom step",
                  0.5 * r, dt);
    for (int k = 0; k < NPHASE; k++)
        n += snprintf(s + n, cap - n, " v_o%d v_u%d", k, k);
    long steps = (long)ceil(4 * tcol / dt) + 8;
    n += snprintf(s + n, cap - n,
                  "\nthermo_modify format float %%.17g\nthermo 1\nrun %ld force yes\n", steps);
    return s;
}

/* Run the deck in a fresh instance; parse its thermo table. */
static void replay_run(struct gravel *g, const char *deck, double r, double V, double dt,
                       double eref, struct replay *out)
{
    memset(out, 0, sizeof *out);
    char *buf = NULL;
    size_t len = 0;
    FILE *ms = open_memstream(&buf, &len);
    struct gravel *c = gr_create();
    if (!c || !ms) {
        if (ms)
            fclose(ms);
        free(buf);
        if (c)
            gr_destroy(c);
        gr_error(g, "accuracy map: out of memory");
    }
    c->screen = ms;
    c->opt.quiet_screen = 0;
    c->opt.single = g->opt.single;
    snprintf(c->opt.device, sizeof c->opt.device, "%s", g->opt.device);
    int rc = inp_string(c, deck, "accuracy replay");
    gr_destroy(c);
    fclose(ms);
    /* rows: step o0 u0 o1 u1 ... after the "Step" header */
    double omax = 0, t_in[NPHASE], t_out[NPHASE], prev_o[NPHASE], u_last[NPHASE];
    int started[NPHASE] = {0}, ended[NPHASE] = {0}, have_prev = 0, nrow = 0;
    char *line = buf ? strstr(buf, "\nStep ") : NULL;
    for (char *p = line ? strchr(line + 1, '\n') : NULL; p && *p; p = strchr(p + 1, '\n')) {
        double v[1 + 2 * NPHASE];
        char *q = p + 1, *end;
        int k = 0;
        for (; k < 1 + 2 * NPHASE; k++) {
            v[k] = strtod(q, &end);
            if (end == q)
                break;
            q = end;
        }
        if (k < 1 + 2 * NPHASE)
            break;
        double t = v[0] * dt;
        for (int j = 0; j < NPHASE; j++) {
            double o = v[1 + 2 * j];
            omax = fmax(omax, o);
            if (have_prev && !started[j] && o > 0) {
                t_in[j] = t - dt * o / (o - prev_o[j]);
                started[j] = 1;
            } else if (have_prev && started[j] && !ended[j] && o <= 0) {
                t_out[j] = t - dt * o / (o - prev_o[j]);
                ended[j] = 1;
            }
            prev_o[j] = o;
            u_last[j] = v[2 + 2 * j];
        }
        have_prev = 1;
        nrow++;
    }
    free(buf);
    if (rc != 0 || nrow < 2) {
        out->ok = 0;
        return;
    }
    out->ok = 1;
    out->ov = omax / r;
    double worst = -1;
    for (int j = 0; j < NPHASE; j++) {
        out->e_all[j] = -u_last[j] / V;
        out->tc_all[j] = started[j] && ended[j] ? t_out[j] - t_in[j] : NAN;
        double d = eref > 0 ? fabs(out->e_all[j] / eref - 1) : 0;
        if (d > worst) {
            worst = d;
            out->e = out->e_all[j];
        }
    }
}

static double worst_tc_err(const struct replay *r, double tref)
{
    double w = 0;
    for (int j = 0; j < NPHASE; j++) {
        double d = isfinite(r->tc_all[j]) ? r->tc_all[j] / tref - 1 : INFINITY;
        if (fabs(d) > fabs(w))
            w = d;
    }
    return w;
}

static int have_gnuplot(void)
{
    return system("command -v gnuplot >/dev/null 2>&1") == 0;
}

void accuracy_map(struct gravel *g)
{
    const struct pair *p = g->styles.pair;
    struct pair_caps caps; /* before the run's set-up: the record as it stands */
    if (p)
        pair_describe(p, &caps);
    if (!p || !caps.collision_time) {
        gr_warn(g, "accuracy map: the scene has no contact law with a collision time");
        return;
    }
    if (!g->styles.pair_cmds) {
        gr_warn(g, "accuracy map: the pair commands of the scene are not known (read_restart); "
                   "give pair_style and pair_coeff in the script");
        return;
    }
    const struct atoms *a = &g->atoms;
    if (a->n == 0) {
        gr_warn(g, "accuracy map: no atoms");
        return;
    }
    double m = INFINITY, r = 0, vmax = 0;
    int type = 1;
    for (int i = 0; i < a->n; i++) {
        if (a->rmass[i] < m) {
            m = a->rmass[i];
            r = a->radius[i];
            type = a->type[i];
        }
        vmax = fmax(vmax, sqrt(a->v[3 * i] * a->v[3 * i] + a->v[3 * i + 1] * a->v[3 * i + 1] +
                               a->v[3 * i + 2] * a->v[3 * i + 2]));
    }
    double V = 2 * vmax;
    const char *why = "twice the fastest particle's speed";
    if (!(V > 0)) {
        struct fix *fg = fix_find_acceleration(g);
        double H = 0;
        for (int d = 0; d < 3; d++)
            H = fmax(H, g->dom.hi[d] - g->dom.lo[d]);
        if (fg && H > 0) {
            V = sqrt(2 * fg->style->acceleration(fg) * H);
            why = "free fall over the box under fix gravity (the scene starts at rest)";
        } else {
            V = 1;
            why = "1 (the scene starts at rest, no gravity)";
        }
    }
    double tcol = pair_collision_time(&caps, m, r, V);
    if (!isfinite(tcol) || !(tcol > 0)) {
        gr_warn(g, "accuracy map: %s has no collision time at these parameters (overdamped?)",
                p->style->name);
        return;
    }
    gr_print(g, "\nAccuracy map (%s, %s precision): head-on collisions of two particles of "
                "type %d, radius %g, mass %g at relative speed %g (%s); %d contact phases per "
                "time step, worst shown; reference: %d steps per collision\n",
             p->style->name, g->opt.single ? "single" : "double", type, r, m, V, why, NPHASE,
             REF_STEPS);
    const double fac[3] = {0.5, 1.0, 2.0};
    struct replay ref, row[3];
    double dtref = fmin(tcol / REF_STEPS, g->dt / 8);
    char *deck = replay_deck(g, r, m, type, V, dtref, tcol);
    if (!deck)
        gr_error(g, "accuracy map: out of memory");
    replay_run(g, deck, r, V, dtref, 0, &ref);
    free(deck);
    double eref = 0, tref = 0;
    for (int j = 0; j < NPHASE && ref.ok; j++) {
        eref += ref.e_all[j] / NPHASE;
        tref += ref.tc_all[j] / NPHASE;
    }
    if (!ref.ok || !isfinite(tref)) {
        gr_warn(g, "accuracy map: the reference replay failed (the contact law may need "
                   "settings the replay does not carry)");
        return;
    }
    gr_print(g, "%-12s %9s %10s %11s %11s %9s %11s %6s\n", "dt", "steps/col", "restitution",
             "rest. error", "overlap/r", "ov. error", "t_col error", "cost");
    gr_print(g, "%-12.4g %9.1f %10.6f %11s %11.4g %9s %11s %6.3g\n", dtref, tref / dtref, eref,
             "reference", ref.ov, "", "", g->dt / dtref);
    char dat[4096];
    int nd = 0;
    for (int k = 0; k < 3; k++) {
        double dt = fac[k] * g->dt;
        deck = replay_deck(g, r, m, type, V, dt, tcol);
        if (!deck)
            gr_error(g, "accuracy map: out of memory");
        replay_run(g, deck, r, V, dt, eref, &row[k]);
        free(deck);
        if (!row[k].ok) {
            gr_print(g, "%-12.4g  replay failed (time step too large for the contact?)\n", dt);
            continue;
        }
        double ee = eref > 0 ? row[k].e / eref - 1 : row[k].e - eref;
        double oe = row[k].ov / ref.ov - 1, te = worst_tc_err(&row[k], tref);
        char tes[32];
        if (isfinite(te))
            snprintf(tes, sizeof tes, "%+.3g %%", 100 * te);
        else
            snprintf(tes, sizeof tes, "no contact");
        gr_print(g, "%-12.4g %9.1f %10.6f %+10.3g%% %11.4g %+8.3g%% %11s %6.3g%s\n", dt,
                 tref / dt, row[k].e, 100 * ee, row[k].ov, 100 * oe, tes, g->dt / dt,
                 k == 1 ? "  <- the scene's time step" : "");
        nd += snprintf(dat + nd, sizeof dat - nd, "%.17g %.17g %.17g %.17g\n", tref / dt,
                       fabs(ee), fabs(oe), isfinite(te) ? fabs(te) : 1.0);
    }
    if (!have_gnuplot())
        return;
    int werr;
    const char *nowhy;
    FILE *f = fio_open_write_checked("accuracy_map.dat", 0, &werr, &nowhy);
    if (!f)
        return;
    fputs(dat, f);
    if (fclose(f) != 0 || werr)
        return; /* no data file, no plot */
    f = popen("gnuplot 2>/dev/null", "w");
    if (!f)
        return;
    fprintf(f, "set terminal png size 800,500\nset output 'accuracy_map.png'\n"
               "set logscale xy\nset xlabel 'steps per collision'\nset ylabel 'relative error'\n"
               "set title '%s: accuracy against the time step (x 0.5, 1, 2 of dt = %g)'\n"
               "set key top right\n"
               "plot 'accuracy_map.dat' u 1:($2+1e-16) w lp t 'restitution', "
               "'' u 1:($3+1e-16) w lp t 'max overlap', '' u 1:($4+1e-16) w lp t 'contact time'\n",
            p->style->name, g->dt);
    if (pclose(f) == 0)
        gr_print(g, "Accuracy map plot: accuracy_map.png (data accuracy_map.dat)\n");
}
