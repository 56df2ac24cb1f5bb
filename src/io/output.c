/* output.c - what is written when during a run: the thermo schedule, dumps,
 * the progress line, and the LAMMPS-style footer after each run.
 *
 * Schedule (LAMMPS Output): output_setup writes the dumps due at the first
 * step, then the thermo header and first line. After each step, dumps at
 * multiples of their N, and a thermo line at multiples of `thermo N` (or at
 * the step an equal-style variable returns for `thermo v_name`) and always
 * at the run's last step. */
#include "comm.h"
#include "output.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "compute.h"
#include "domain.h"
#include "dump.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "lanes_tune.h"
#include "log.h"
#include "pair.h"
#include "progress.h"
#include "thermo.h"
#include "variable.h"
#include "wall_clock.h"

static void emit(struct gravel *g, const char *text)
{
    progress_clear(g); /* stdout and stderr may share the terminal */
    gr_print(g, "%s", text);
    gr_thermolog_write(g, text);
    if (g->thermo.flush) {
        if (g->screen)
            fflush(g->screen);
        if (g->logfile)
            fflush(g->logfile);
    }
    gr_log_check(g); /* a run whose log cannot be written stops */
}

/* dump_modify every v_name: the dumps whose next step is still to be
 * evaluated (-1, set by dump.c at the run's setup and after each snapshot)
 * get their variable's value, which must be a later step (LAMMPS: "Dump
 * every variable returned a bad timestep"). Here, not in dump.c, so that
 * the dumps stay below the variable language in the include layers. */
static void dump_every_var(struct gravel *g)
{
    for (int i = 0; i < g->styles.ndump; i++) {
        struct dump *d = g->styles.dump[i];
        if (!d->every_var || d->next_dump >= 0)
            continue;
        char who[GR_NAMELEN + 32];
        snprintf(who, sizeof who, "dump %s: every variable", d->id);
        d->next_dump = var_next_step(g, d->every_var, g->step, who);
    }
}

/* Next step with a thermo line after `step`. */
static bigint next_thermo(struct gravel *g, bigint step)
{
    struct thermo_settings *t = &g->thermo;
    bigint next;
    if (t->every_var) {
        next = var_next_step(g, t->every_var, step, "thermo: variable");
    } else if (t->every > 0) {
        next = (step / t->every) * t->every + t->every;
    } else {
        next = g->laststep;
    }
    return next < g->laststep ? next : g->laststep;
}

static void thermo_print(struct gravel *g)
{
    struct output_state *st = output_state(g);
    emit(g, thermo_line_text(g));
    st->last_thermo = g->step;
}

/* Kinetic energy, translational and rotational (solid spheres), of the host
 * copy of the atoms. */
static double kinetic_energy(const struct gravel *g)
{
    const struct atoms *a = &g->atoms;
    double e = 0.0;
    for (int i = 0; i < a->n; i++) {
        const double *v = a->v + 3 * i;
        e += 0.5 * a->rmass[i] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (a->omega) {
            const double *w = a->omega + 3 * i;
            e += 0.2 * a->rmass[i] * a->radius[i] * a->radius[i] *
                 (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        }
    }
    return e;
}

/* Elastic energy stored in the particle contacts (host copy; each pair once,
 * nearest periodic image), binned in cells of at least the largest contact
 * distance. */
static double contact_energy(struct gravel *g)
{
    const struct atoms *a = &g->atoms;
    const struct domain *dm = &g->dom;
    const struct pair *p = g->styles.pair;
    double rmax = 0.0, len[3];
    int nc[3];
    for (int i = 0; i < a->n; i++)
        rmax = fmax(rmax, a->radius[i]);
    if (!(rmax > 0.0))
        return 0.0;
    size_t ncell = 1;
    double f[3]; /* a tilted box: cells of L lamda, f wider (domain_ufac) */
    domain_ufac(dm, f);
    for (int d = 0; d < 3; d++) {
        len[d] = dm->hi[d] - dm->lo[d];
        double n = floor(len[d] / (2.0 * rmax * f[d]));
        nc[d] = n < 1.0 ? 1 : n > 64.0 ? 64 : (int)n;
        if (dm->periodic[d] && nc[d] < 3)
            nc[d] = 1;          /* offsets -1..1 would visit one cell twice */
        ncell *= (size_t)nc[d];
    }
    int *head = gr_malloc(g, ncell * sizeof *head), *next = gr_malloc(g, (size_t)a->n * sizeof *next);
    int *cell = gr_malloc(g, (size_t)a->n * sizeof *cell);
    for (size_t c = 0; c < ncell; c++)
        head[c] = -1;
    for (int i = 0; i < a->n; i++) {
        int c = 0;
        double lam[3];
        domain_x2lamda(g, a->x + 3 * i, lam);
        for (int d = 2; d >= 0; d--) {
            int k = (int)floor((dm->triclinic ? lam[d] : (a->x[3 * i + d] - dm->lo[d]) / len[d]) *
                               nc[d]);
            k = k < 0 ? 0 : k >= nc[d] ? nc[d] - 1 : k;
            c = c * nc[d] + k;
        }
        cell[i] = c;
        next[i] = head[c];
        head[c] = i;
    }
    double e = 0.0;
    for (int i = 0; i < a->n; i++) {
        int ci[3] = {cell[i] % nc[0], cell[i] / nc[0] % nc[1], cell[i] / (nc[0] * nc[1])};
        for (int oz = -1; oz <= 1; oz++)
            for (int oy = -1; oy <= 1; oy++)
                for (int ox = -1; ox <= 1; ox++) {
                    int o[3] = {ox, oy, oz}, k[3], skip = 0;
                    for (int d = 0; d < 3 && !skip; d++) {
                        if (nc[d] == 1 && o[d] != 0)
                            skip = 1;
                        k[d] = ci[d] + o[d];
                        if (k[d] < 0 || k[d] >= nc[d]) {
                            if (dm->periodic[d])
                                k[d] = (k[d] + nc[d]) % nc[d];
                            else
                                skip = 1;
                        }
                    }
                    if (skip)
                        continue;
                    for (int j = head[(k[2] * nc[1] + k[1]) * nc[0] + k[0]]; j >= 0; j = next[j]) {
                        if (j <= i)
                            continue;
                        double rsq = 0.0, del[3];
                        for (int d = 0; d < 3; d++)
                            del[d] = a->x[3 * i + d] - a->x[3 * j + d];
                        if (dm->triclinic)
                            domain_minimum_image(g, del);
                        for (int d = 0; d < 3; d++) {
                            double dx = del[d];
                            if (dm->periodic[d] && !dm->triclinic)
                                dx -= len[d] * nearbyint(dx / len[d]);
                            rsq += dx * dx;
                        }
                        double rs = a->radius[i] + a->radius[j];
                        if (rsq < rs * rs)
                            e += p->caps.contact_energy(p->caps.energy_of, rs - sqrt(rsq),
                                                          a->radius[i] * a->radius[j] / rs);
                    }
                }
    }
    free(head);
    free(next);
    free(cell);
    return e;
}

/* Energy is conserved (issue 13 item 6) when the pair style says so for its
 * coefficients and every fix only integrates or holds atoms: no gravity
 * (its potential energy is not counted), walls, drag or damping. Then the
 * kinetic plus contact elastic energy at the start and end of the run
 * measure the integrator's drift. */
static int conserving_scene(const struct gravel *g)
{
    const struct pair *p = g->styles.pair;
    if (!p || !p->caps.conservative || !p->caps.contact_energy || g->atoms.n == 0)
        return 0;
    return fix_all_conserving(g);
}

/* Collision time of the lightest particle (as the setup line of run.c). */
static double scene_collision_time(const struct gravel *g)
{
    const struct pair *p = g->styles.pair;
    double m = INFINITY, r = 0, vmax = 0;
    for (int i = 0; i < g->atoms.n; i++) {
        if (g->atoms.rmass[i] < m) {
            m = g->atoms.rmass[i];
            r = g->atoms.radius[i];
        }
        for (int d = 0; d < 3; d++)
            vmax = fmax(vmax, fabs(g->atoms.v[3 * i + d]));
    }
    return pair_collision_time(&p->caps, m, r, vmax > 0 ? 2 * vmax : 0);
}

void output_setup(struct gravel *g)
{
    struct output_state *st = output_state(g);
    st->active = 1;
    st->wall0 = wall_clock();
    st->firstflag = 1;
    st->last_thermo = -1;
    compute_init_all(g);
    thermo_init(g);
    dump_setup_all(g);
    dump_every_var(g);
    emit(g, thermo_header_text(g));
    thermo_print(g);
    st->drift_on = conserving_scene(g);
    if (st->drift_on) {
        run_sync_host(g);
        st->drift_e0 = kinetic_energy(g) + contact_energy(g);
        st->drift_t0 = g->time;
        st->drift_tcol = scene_collision_time(g);
    }
    st->firstflag = 0;
    st->next_thermo = g->laststep > g->step ? next_thermo(g, g->step) : g->step;
    progress_begin(g);
}

int output_due(struct gravel *g, bigint step)
{
    struct output_state *st = output_state(g);
    if (step == g->laststep || step == st->next_thermo)
        return 1;
    return dump_due(g, step) || progress_due(g);
}

void output_step(struct gravel *g)
{
    struct output_state *st = output_state(g);
    dump_step_all(g);
    dump_every_var(g);
    if (g->step >= st->next_thermo && st->last_thermo != g->step) {
        thermo_print(g);
        if (g->step < g->laststep)
            st->next_thermo = next_thermo(g, g->step);
    } else if (g->step == g->laststep && st->last_thermo != g->step) {
        thermo_print(g);
    }
    progress_update(g);
}

/* One row of LAMMPS' "MPI task timing breakdown" table (one process:
 * min = avg = max, no variation). */
static void timing_row(struct gravel *g, const char *label, const struct rank_spread *s,
                       double total)
{
    gr_print(g, "%-8s| %-10.5g | %-10.5g | %-10.5g |%6.1f |%6.2f\n", label, s->min, s->avg,
             s->max, s->varavg, total > 0 ? 100.0 * s->avg / total : 0.0);
}

/* LAMMPS 2021 formats these with fmt's "{:W.N}" on a double: "%#W.Ng"
 * (trailing zeros kept), and a result ending in a bare '.' gets a "0"
 * appended after the padding: "    115133.0" (12 wide), as `lmp` prints. */
static void showpoint(char *buf, size_t n, int width, int prec, double v)
{
    snprintf(buf, n, "%#*.*g", width, prec, v);
    size_t len = strlen(buf);
    if (len > 0 && buf[len - 1] == '.' && len + 1 < n) {
        buf[len] = '0';
        buf[len + 1] = '\0';
    }
}

void rank_spread(const double *v, int n, struct rank_spread *s)
{
    rank_spread_strided(v, n, 1, s);
}

void rank_spread_strided(const double *v, int n, int stride, struct rank_spread *s)
{
    double sum = 0, sq = 0;
    s->min = s->max = v[0];
    for (int r = 0; r < n; r++) {
        double x = v[(size_t)r * stride];
        sum += x;
        sq += x * x;
        s->min = fmin(s->min, x);
        s->max = fmax(s->max, x);
    }
    s->avg = sum / n;
    double var = s->avg > 0 ? sq / n / s->avg - s->avg : 0;
    s->varavg = s->avg > 0.001 && var > 1e-10 ? 100.0 * sqrt(var) : 0.0;
    memset(s->histo, 0, sizeof s->histo);
    double del = s->max - s->min;
    for (int r = 0; r < n; r++) {
        int m = del == 0.0 ? 0 : (int)((v[(size_t)r * stride] - s->min) / del * 10);
        s->histo[m > 9 ? 9 : m]++;
    }
}

/* "Nlocal: ..." over the ranks and its histogram, as LAMMPS prints them. */
static void stat_row(struct gravel *g, const char *label, const struct rank_spread *s)
{
    char ave[64];
    showpoint(ave, sizeof ave, 11, 6, s->avg);
    gr_print(g, "%-10s %s ave %11.6g max %11.6g min\nHistogram:", label, ave, s->max, s->min);
    for (int k = 0; k < 10; k++)
        gr_print(g, " %d", s->histo[k]);
    gr_print(g, "\n");
}

void output_abort(struct gravel *g)
{
    struct output_state *st = output_state(g);
    progress_end(g);
    dump_free_pending(g);
    st->active = 0;
}

/* Housekeeping at the end of a run and the "Loop time" line. */
static void finish_common(struct gravel *g, const struct run_stats *s)
{
    struct output_state *st = output_state(g);
    progress_end(g);
    dump_run_end(g);
    st->active = 0;
    gr_print(g, "Loop time of %.6g on %d procs for %lld steps with %d atoms\n\n", s->t_total,
             comm_size(), (long long)s->nsteps, s->natoms);
}

void output_finish_brief(struct gravel *g, const struct run_stats *s)
{
    finish_common(g, s);
    if (g->screen)
        fflush(g->screen);
    if (g->logfile)
        fflush(g->logfile);
}

void run_stats_row(const struct run_stats *st, double row[RUN_ROW_N])
{
    const double v[RUN_ROW_N] = {st->t_pair, st->t_neigh, st->t_output, st->t_modify,
                                 st->t_total, (double)st->natoms, st->total_neighbors / 2};
    memcpy(row, v, sizeof v);
}

void run_stats_spread(struct run_stats *st, const double *rows, int n, struct rank_spread *loop)
{
    struct rank_spread *to[RUN_ROW_N] = {&st->sec[RUN_SEC_PAIR], &st->sec[RUN_SEC_NEIGH],
                                         &st->sec[RUN_SEC_OUTPUT], &st->sec[RUN_SEC_MODIFY],
                                         loop, &st->atoms, &st->neighs};
    for (int q = 0; q < RUN_ROW_N; q++)
        rank_spread_strided(rows + q, n, RUN_ROW_N, to[q]);
}

/* One process: its own values as spreads of one rank. */
static void spreads_one(const struct run_stats *s, struct run_stats *o)
{
    *o = *s;
    double row[RUN_ROW_N];
    struct rank_spread loop;
    run_stats_row(s, row);
    run_stats_spread(o, row, 1, &loop);
}

void output_finish(struct gravel *g, const struct run_stats *given)
{
    struct run_stats one;
    const struct run_stats *s = given;
    if (!given->ranks_spread) {
        spreads_one(given, &one);
        s = &one;
    }
    finish_common(g, s);
    double t = s->t_total;
    if (s->nsteps > 0 && t > 0) {
        double step_s = (double)s->nsteps / t;
        double atom_steps = step_s * s->natoms; /* Cundall number */
        char perf[128];
        if (g->dom.units == UNITS_LJ)
            snprintf(perf, sizeof perf, "%.3f tau/day, ", 86400.0 * step_s * g->dt);
        else /* si, cgs: simulated seconds per day */
            snprintf(perf, sizeof perf, "%.6g s/day, ", 86400.0 * step_s * g->dt);
        if (atom_steps >= 1e6)
            gr_print(g, "Performance: %s%.3f timesteps/s, %.3f Matom-step/s\n", perf, step_s,
                     atom_steps * 1e-6);
        else
            gr_print(g, "Performance: %s%.3f timesteps/s, %.3f katom-step/s\n", perf, step_s,
                     atom_steps * 1e-3);
    }

    const struct rank_spread *sec = s->sec;
    double other = s->t_other;
    if (other <= 0) {
        other = t - (sec[RUN_SEC_PAIR].avg + sec[RUN_SEC_NEIGH].avg + sec[RUN_SEC_OUTPUT].avg +
                     sec[RUN_SEC_MODIFY].avg);
        if (other < 0)
            other = 0;
    }
    gr_print(g, "\nMPI task timing breakdown:\n"
                "Section |  min time  |  avg time  |  max time  |%%varavg| %%total\n"
                "---------------------------------------------------------------\n");
    timing_row(g, "Pair", &sec[RUN_SEC_PAIR], t);
    timing_row(g, "Neigh", &sec[RUN_SEC_NEIGH], t);
    timing_row(g, "Output", &sec[RUN_SEC_OUTPUT], t);
    timing_row(g, "Modify", &sec[RUN_SEC_MODIFY], t);
    gr_print(g, "Other   |            | %-10.4g |            |       |%6.2f\n", other,
             t > 0 ? 100.0 * other / t : 0.0);

    gr_print(g, "\n");
    stat_row(g, "Nlocal:", &s->atoms);
    /* gravel's lists are full (each pair twice); LAMMPS reports its half
     * list, each pair once: print pairs so the numbers compare */
    double pairs = s->total_neighbors / 2;
    stat_row(g, "Neighs:", &s->neighs);
    gr_print(g, "\nTotal # of neighbors = %.8g\n", pairs);
    if (s->natoms > 0) {
        char ave[64];
        showpoint(ave, sizeof ave, 0, 8, pairs / s->natoms);
        gr_print(g, "Ave neighs/atom = %s\n", ave);
    }
    gr_print(g, "Neighbor list builds = %lld\n", (long long)s->nbuilds);
    if (g->neigh.check)
        gr_print(g, "Dangerous builds = %lld\n", (long long)s->ndanger);
    else
        gr_print(g, "Dangerous builds not checked\n");
    gr_print(g, "Largest overlap / radius = %.6g\n", s->max_overlap_frac);
    if (s->res_q > 0) {
        char who[128];
        if (s->res_tag_j)
            snprintf(who, sizeof who, "atoms %lld and %lld", s->res_tag_i, s->res_tag_j);
        else
            snprintf(who, sizeof who, "atom %lld and wall %s", s->res_tag_i, s->res_wall);
        gr_print(g, "Collision resolution = %.4g steps per collision at worst (step %lld, %s, "
                    "normal speed %.4g)\n",
                 1.0 / s->res_q, (long long)s->res_step, who, s->res_vn);
    } else if (s->nsteps > 0) {
        gr_print(g, "Collision resolution: no collisions\n");
    }
    if (s->nsteps > 0)
        gr_print(g, "Contacts = %d (each evaluated once); kernel launches per step = %.2f\n",
                 s->ncontact, (double)s->nlaunch / (double)s->nsteps);
    if (lanes_report(g))
        gr_print(g, "%s\n", lanes_report(g));
    if (s->nspec > 0)
        gr_print(g, "Rebuild decisions on speculation = %lld (%lld steps gone back)\n",
                 (long long)s->nspec, (long long)s->nspec_back);
    if (comm_size() > 1 && s->nsteps > 0)
        gr_print(g, "Communication per rank and step = %.6g bytes in %.4g messages to other "
                    "ranks, %.6g bytes into %.4g collectives (mean over %d ranks)\n",
                 s->comm_bytes, s->comm_msgs, s->coll_bytes, s->coll_calls, comm_size());
    if (s->natoms > 0)
        gr_print(g, "Device memory = %.4g Mbytes at most (%.0f bytes per atom)\n",
                 s->mem_peak / 1e6, s->mem_peak / s->natoms);
    struct output_state *st = output_state(g);
    double ncol = st->drift_on && st->drift_tcol > 0 ? (g->time - st->drift_t0) / st->drift_tcol : 0;
    if (ncol > 0 && st->drift_e0 > 0) {
        double e1 = kinetic_energy(g) + contact_energy(g);
        gr_print(g, "Energy drift (energy-conserving run) = %+.4g per collision time "
                    "(kinetic + contact energy %.10g -> %.10g over %.4g collision times of "
                    "%.4g)\n",
                 (e1 - st->drift_e0) / st->drift_e0 / ncol, st->drift_e0, e1, ncol,
                 st->drift_tcol);
    }
    if (g->screen)
        fflush(g->screen);
    if (g->logfile)
        fflush(g->logfile);
}
