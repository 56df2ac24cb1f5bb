/* fix_langevin.c - `fix ID group langevin Tstart Tstop damp seed [omega
 * yes|no] [scale type ratio] [zero yes|no] [tally yes|no] [angmom no] [gjf no]`:
 * LAMMPS's fix langevin, a Langevin thermostat: at post_force every atom of
 * the group gets the drag -m v / (damp ratio_type) and a random force of
 * uniform components gamma2 (u - 1/2), gamma2 = sqrt(m) sqrt(24 kB T /
 * damp / dt) / sqrt(ratio_type), T the target (Tstart to Tstop over the
 * run, an equal-style variable, or an atom-style variable: each atom's
 * own target, Tstop unused); zero yes removes the group's mean
 * random force; omega yes thermostats the spins of finite-size spheres the
 * same way (I = 0.4 m r^2 in place of m). The random numbers are LAMMPS's
 * RanMars stream (seed of rank 0) drawn on the host in atom-ID order, three
 * per atom, the translational ones of every atom first: LAMMPS's draws on
 * one process when its atoms keep their creation order (`atom_modify sort
 * 0 0.0`); with LAMMPS's default spatial sorting the stream meets the atoms
 * in another order, the same statistics. The forces are added on the
 * device (kernels/fix_langevin.cl). On MPI ranks every rank draws the
 * whole stream and takes its atoms' numbers by their place in ID order, so
 * the run is one process's (LAMMPS's ranks draw from streams of their
 * own). tally yes: the kernel keeps each atom's thermostat force
 * (translational, after zero's mean), and at end_of_step the host adds
 * dt sum F . v over the group in atom-ID order (every rank's atoms as one
 * process's); the scalar f_ID is minus that energy, taken back half a step
 * and restarted at each run's first step, as LAMMPS's compute_scalar. Not
 * yet: gjf, angmom (no ellipsoids here), fix_modify temp. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "par.h"
#include "par_sum.h"
#include "random.h"
#include "temperature.h"
#include "variable.h"

#define WHO "fix langevin"

struct langevin {
    double t_start, t_stop, t_period;
    char *tvar;                 /* Tstart as v_name (equal- or atom-style), else NULL */
    int tatom;                  /* tvar is atom-style: a target per atom */
    int seed, oflag, zero, tally;
    double energy, energy_onestep; /* tally: LAMMPS's running sum and the last step's term */
    double omega_c1, omega_c2;  /* LAMMPS's rotational drag and noise factors (10/3, 80) */
    int ntypes;
    double *ratio;              /* [ntypes] */
    struct rng_mars rng;
    cl_mem dratio, dfran, dflan; /* dflan: tally's thermostat force per atom (3 REAL) */
    size_t dfran_n, dflan_n;
    cl_kernel k;
};

static void destroy(struct fix *f)
{
    struct langevin *l = f->data;
    if (l) {
        if (l->dratio)
            clReleaseMemObject(l->dratio);
        if (l->dfran)
            clReleaseMemObject(l->dfran);
        if (l->dflan)
            clReleaseMemObject(l->dflan);
        free(l->ratio);
        free(l->tvar);
        free(l);
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, WHO " expects Tstart Tstop damp seed [keyword value ...], got %d arguments",
                 argc);
    if (g->atoms.ntypes < 1)
        gr_error(g, WHO " needs atom types (create the box first)");
    struct langevin *l = gr_calloc(g, 1, sizeof *l);
    f->data = l;
    if (!strncmp(argv[0], "v_", 2) && argv[0][2])
        l->tvar = gr_strdup(g, argv[0] + 2);
    else
        l->t_start = arg_double(g, argv[0], WHO " Tstart");
    l->t_stop = arg_double(g, argv[1], WHO " Tstop");
    l->t_period = arg_double(g, argv[2], WHO " damp");
    l->seed = arg_int(g, argv[3], WHO " seed");
    if (!(l->t_period > 0))
        gr_error(g, WHO ": damp must be > 0, got %g", l->t_period);
    if (l->seed <= 0 || l->seed > 900000000)
        gr_error(g, WHO ": seed must be in 1 .. 900000000, got %d", l->seed);
    l->ntypes = g->atoms.ntypes;
    l->ratio = gr_malloc(g, (size_t)l->ntypes * sizeof *l->ratio);
    for (int t = 0; t < l->ntypes; t++)
        l->ratio[t] = 1.0;
    l->omega_c1 = 10.0 / 3.0; /* LAMMPS: rotational diffusion of spheres (since 2020) */
    l->omega_c2 = 80.0;
    for (int i = 4; i < argc;) {
        const char *kw = argv[i];
        arg_need(g, argc, i, 1, kw);
        const char *v = argv[i + 1];
        if (!strcmp(kw, "omega")) {
            l->oflag = arg_yesno(g, v, "omega");
            i += 2;
        } else if (!strcmp(kw, "zero")) {
            l->zero = arg_yesno(g, v, "zero");
            i += 2;
        } else if (!strcmp(kw, "scale")) {
            arg_need(g, argc, i, 2, kw);
            const int t = arg_int_range(g, v, 1, l->ntypes, WHO " scale type");
            l->ratio[t - 1] = arg_double(g, argv[i + 2], WHO " scale ratio");
            i += 3;
        } else if (!strcmp(kw, "tally")) {
            l->tally = arg_yesno(g, v, "tally");
            i += 2;
        } else if (!strcmp(kw, "gjf") || !strcmp(kw, "angmom")) {
            if (strcmp(v, "no"))
                gr_error(g, WHO ": %s %s is not supported yet (only %s no)", kw, v, kw);
            i += 2;
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s' (omega, scale, zero, angmom, tally, gjf)",
                     kw);
        }
    }
    rng_mars_init(&l->rng, l->seed); /* LAMMPS: seed + rank, rank 0 */
    f->hooks = HOOK_POST_FORCE | (l->tally ? HOOK_END_OF_STEP : 0);
    f->sources[f->nsources++] = "fix_langevin.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct langevin *l = f->data;
    if (l->ntypes < g->atoms.ntypes)
        gr_error(g, "fix %s langevin was defined for %d atom types, now there are %d", f->id,
                 l->ntypes, g->atoms.ntypes);
    l->tatom = l->tvar && var_is_atom(g, l->tvar);
    if (l->tvar && !l->tatom && !var_is_equal(g, l->tvar))
        gr_error(g, WHO " %s: variable %s %s", f->id, l->tvar,
                 var_exists(g, l->tvar) ? "is neither equal- nor atom-style" : "does not exist");
    if (l->oflag && !g->eng->rotation)
        gr_error(g, WHO " %s: omega yes needs a run with rotation (atom_style sphere and a "
                    "pair style that turns the particles)", f->id);
    if (l->dratio)
        clReleaseMemObject(l->dratio);
    l->dratio = eng_alloc(g, (size_t)l->ntypes * g->eng->rsz, WHO " ratio");
    eng_write_reals(g, l->dratio, (size_t)l->ntypes, l->ratio);
    l->k = eng_kernel(g, "langevin_post_force");
}

/* the target temperature of this step (LAMMPS's compute_target; an
 * atom-style target: per atom, target_atoms) */
static double target(struct gravel *g, struct langevin *l)
{
    double t;
    if (l->tatom) {
        t = 1.0;
    } else if (l->tvar) {
        t = var_compute_equal(g, l->tvar);
        if (t < 0.0)
            gr_error(g, WHO ": variable %s returned a negative temperature %g at step %lld",
                     l->tvar, t, (long long)g->step);
    } else {
        double delta = (double)(g->step - g->beginstep);
        if (delta != 0.0)
            delta /= (double)(g->endstep - g->beginstep);
        t = l->t_start + delta * (l->t_stop - l->t_start);
    }
    return t;
}

/* An atom-style target: sqrt(T_i) of every atom (device order = host order
 * after the sync), the group's checked non-negative; NULL otherwise. Called
 * before post_force allocates, so an error leaves nothing behind. */
static double *target_atoms(struct gravel *g, struct fix *f, struct langevin *l)
{
    if (!l->tatom)
        return NULL;
    run_sync_host(g);
    const struct atoms *a = &g->atoms;
    double *t = var_atom_values(g, l->tvar);
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & f->groupbit))
            continue;
        if (t[i] < 0.0) {
            const double bad = t[i];
            free(t);
            gr_error(g, WHO ": variable %s returned a negative temperature %g for atom %lld at "
                        "step %lld", l->tvar, bad, (long long)a->tag[i], (long long)g->step);
        }
        t[i] = sqrt(t[i]);
    }
    return t;
}

static int by_tag(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The group's atoms of every rank in atom-ID order, as rows (tag, finite
 * sphere: 1 or 0) at *rows; returns their count. On one rank the local
 * atoms (ord: the device atoms by ID). */
static int group_by_tag(struct gravel *g, const int *ord, int n, const unsigned *mask,
                        const double *rad, unsigned groupbit, double **rows)
{
    struct engine *e = g->eng;
    double *r = gr_malloc(g, 2 * ((size_t)n + 1) * sizeof *r);
    int ng = 0;
    for (int q = 0; q < n; q++) {
        const int i = ord[q];
        if (!(mask[i] & groupbit))
            continue;
        r[2 * ng] = (double)e->tag_seen[i];
        r[2 * ng + 1] = rad[i] > 0.0;
        ng++;
    }
    if (par_on(g)) { /* several ranks: every rank's rows, then in ID order */
        ng = par_gather_rows(g, &r, ng, 2);
        qsort(r, (size_t)ng, 2 * sizeof *r, by_tag);
    }
    *rows = r;
    return ng;
}

/* the row of tag t in rows (ng of them, ascending tags) */
static int row_of(const double *rows, int ng, double t)
{
    int lo = 0, hi = ng - 1;
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (rows[2 * mid] < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct langevin *l = f->data;
    struct engine *e = g->eng;
    double *tatom = target_atoms(g, f, l); /* first: it may stop the run */
    struct dev_atoms *a = eng_atoms(g);
    const int n = a->n;
    const double tsqrt = sqrt(target(g, l)), boltz = temp_boltz(g), dt = g->dt;
    /* the atoms' mask, type, mass and radius in device order, visited by atom ID */
    const int *ord = eng_tag_order(g);
    unsigned *mask = gr_malloc(g, ((size_t)n + 1) * sizeof *mask);
    int *type = gr_malloc(g, ((size_t)n + 1) * sizeof *type);
    double *m = gr_malloc(g, ((size_t)n + 1) * sizeof *m);
    double *rad = gr_malloc(g, ((size_t)n + 1) * sizeof *rad);
    double *fran = gr_calloc(g, 6 * (size_t)n + 1, sizeof *fran);
    eng_read(g, a->mask, 0, (size_t)n * sizeof *mask, mask);
    eng_read(g, a->type, 0, (size_t)n * sizeof *type, type);
    eng_read_reals(g, a->rmass, (size_t)n, m);
    eng_read_reals(g, a->radius, (size_t)n, rad);
    const double c2 = sqrt(24.0 * boltz / l->t_period / dt), c2r = sqrt(l->omega_c2 * boltz /
                                                                         l->t_period / dt);
    /* The stream, one process's: three draws per group atom in ID order,
     * then three per finite sphere of the group; every rank draws them all
     * and takes its atoms' (row: the atom's place, spin: its sphere's). */
    double *rows;
    const int ng = group_by_tag(g, ord, n, mask, rad, f->groupbit, &rows);
    int *spin = gr_malloc(g, ((size_t)ng + 1) * sizeof *spin), ns = 0;
    for (int k = 0; k < ng; k++)
        spin[k] = l->oflag && rows[2 * k + 1] != 0.0 ? ns++ : -1;
    double *u = gr_malloc(g, 3 * ((size_t)ng + ns + 1) * sizeof *u);
    for (int k = 0; k < 3 * (ng + ns); k++)
        u[k] = rng_mars_uniform(&l->rng);
    struct par_sum fs[3] = {{0}}; /* the mean random force, summed in ID order */
    int next = 0; /* one rank: the rows are this loop's atoms, in its order */
    for (int q = 0; q < n; q++) {
        const int i = ord[q];
        if (!(mask[i] & f->groupbit))
            continue;
        const int k = par_on(g) ? row_of(rows, ng, (double)e->tag_seen[i]) : next++;
        const double ts = tatom ? tatom[i] : tsqrt;
        double gamma2 = sqrt(m[i]) * c2;
        gamma2 *= 1.0 / sqrt(l->ratio[type[i] - 1]) * ts;
        for (int d = 0; d < 3; d++) {
            fran[6 * (size_t)i + d] = gamma2 * (u[3 * k + d] - 0.5);
            par_sum_add(g, &fs[d], e->tag_seen[i], fran[6 * (size_t)i + d]);
        }
        if (spin[k] < 0)
            continue;
        const double inertia = 0.4 * rad[i] * rad[i] * m[i];
        double gamma2r = sqrt(inertia) * c2r;
        gamma2r *= 1.0 / sqrt(l->ratio[type[i] - 1]) * ts;
        for (int d = 0; d < 3; d++)
            fran[6 * (size_t)i + 3 + d] = gamma2r * (u[3 * (ng + spin[k]) + d] - 0.5);
    }
    double fsum[3];
    for (int d = 0; d < 3; d++)
        fsum[d] = par_sum_total(g, &fs[d]) / (ng > 0 ? (double)ng : 1.0);
    free(rows);
    free(spin);
    free(u);
    free(tatom);
    if (!l->dfran || l->dfran_n < (size_t)n) {
        if (l->dfran)
            clReleaseMemObject(l->dfran);
        l->dfran_n = (size_t)n + (size_t)n / 8 + 16;
        l->dfran = eng_alloc(g, 6 * l->dfran_n * e->rsz, WHO " random forces");
    }
    eng_write_reals(g, l->dfran, 6 * (size_t)n, fran);
    if (l->tally && (!l->dflan || l->dflan_n < (size_t)n)) {
        if (l->dflan)
            clReleaseMemObject(l->dflan);
        l->dflan_n = l->dfran_n;
        l->dflan = eng_alloc(g, 3 * l->dflan_n * e->rsz, WHO " thermostat forces");
    }
    free(mask);
    free(type);
    free(m);
    free(rad);
    free(fran);
    cl_kernel k = l->k;
    int p = 0;
    eng_arg_int(g, k, p++, n);
    eng_arg_uint(g, k, p++, f->groupbit);
    eng_arg_mem(g, k, p++, a->mask);
    eng_arg_mem(g, k, p++, a->type);
    eng_arg_mem(g, k, p++, a->rmass);
    eng_arg_mem(g, k, p++, a->radius);
    eng_arg_mem(g, k, p++, a->v);
    eng_arg_mem(g, k, p++, e->rotation ? a->omega : a->v);
    eng_arg_mem(g, k, p++, a->f);
    eng_arg_mem(g, k, p++, e->rotation ? a->torque : a->f);
    eng_arg_mem(g, k, p++, l->dfran);
    eng_arg_mem(g, k, p++, l->dratio);
    eng_arg_real(g, k, p++, l->t_period);
    eng_arg_int(g, k, p++, l->zero);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, p++, fsum[d]);
    eng_arg_int(g, k, p++, l->oflag);
    eng_arg_real(g, k, p++, l->omega_c1);
    eng_arg_int(g, k, p++, l->tally);
    eng_arg_mem(g, k, p++, l->tally ? l->dflan : l->dfran);
    eng_launch(g, k, (size_t)n);
}

/* tally: sum over the group of F . v, F the thermostat force of the last
 * post_force, v the velocities now; in atom-ID order over every rank's
 * atoms (collective). */
static double flan_dot_v(struct gravel *g, struct fix *f)
{
    struct langevin *l = f->data;
    struct engine *e = g->eng;
    struct dev_atoms *a = eng_atoms(g);
    const int n = a->n;
    struct par_sum s = {0};
    if (l->dflan && n > 0) {
        const int *ord = eng_tag_order(g);
        unsigned *mask = gr_malloc(g, (size_t)n * sizeof *mask);
        double *fl = gr_malloc(g, 3 * (size_t)n * sizeof *fl);
        double *v = gr_malloc(g, 3 * (size_t)n * sizeof *v);
        eng_read(g, a->mask, 0, (size_t)n * sizeof *mask, mask);
        eng_read_reals(g, l->dflan, 3 * (size_t)n, fl);
        eng_read_reals(g, a->v, 3 * (size_t)n, v);
        for (int q = 0; q < n; q++) {
            const int i = ord[q];
            if (!(mask[i] & f->groupbit))
                continue;
            const double *fi = fl + 3 * (size_t)i, *vi = v + 3 * (size_t)i;
            par_sum_add(g, &s, e->tag_seen[i], fi[0] * vi[0] + fi[1] * vi[1] + fi[2] * vi[2]);
        }
        free(mask);
        free(fl);
        free(v);
    }
    return par_sum_total(g, &s);
}

/* LAMMPS's end_of_step: the energy the reservoir took this step */
static void end_of_step(struct gravel *g, struct fix *f)
{
    struct langevin *l = f->data;
    l->energy_onestep = flan_dot_v(g, f);
    l->energy += l->energy_onestep * g->dt;
}

/* LAMMPS's compute_scalar: minus the energy added, at the last full step
 * (the running sum is half a step ahead); at a run's first step the sum
 * starts again from the setup force */
static double scalar(struct gravel *g, struct fix *f)
{
    struct langevin *l = f->data;
    if (!l->tally || !l->dflan)
        return 0.0;
    if (g->step == g->beginstep) {
        l->energy_onestep = flan_dot_v(g, f);
        l->energy = 0.5 * l->energy_onestep * g->dt;
    }
    return -(l->energy - 0.5 * l->energy_onestep * g->dt);
}

const struct fix_style fix_style_langevin = {
    .name = "langevin",
    .create = create,
    .init = init,
    .post_force = post_force,
    .end_of_step = end_of_step,
    .scalar = scalar,
    .ecouple = 1,
    .destroy = destroy,
};
