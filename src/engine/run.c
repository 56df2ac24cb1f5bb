/* run.c - `run` and `reset_timestep`: the Verlet loop on the device.
 *
 * Order per step (LAMMPS Verlet::run): initial_integrate fixes -> neighbor
 * decision (a fix's next_reneighbor forces it) -> on rebuild steps the
 * pre_exchange fixes (fix pour inserts atoms), then the rebuild (pbc,
 * shrink-wrap, re-sort) -> pair forces (the contact pipeline: pair_contacts,
 * then pair_gather, which also clears f and torque) -> post_force fixes -> final_integrate fixes -> end_of_step fixes
 * -> output. Per-particle fix work fuses into the check and gather kernels
 * where it can (src/engine/fused.h); the other fixes run from hook lists built once
 * per run. When every fix fused and no output is due, a step's pair_gather also
 * opens the next step (step_lookahead; kernels/atom_step.cl); with unfused
 * post_force fixes (walls) and the rest fused, the fused tail after them does
 * (fused.h). Setup (Verlet::setup) rebuilds the list and computes the step-0
 * forces with the history frozen (shearupdate = 0), then calls post_force of
 * every fix.
 *
 * The timing breakdown synchronizes the device after each section on every
 * 8th step and on rebuild steps only (see run_steps), so ordinary steps do
 * not wait on the host more than the neighbor decision requires. */
#include "comm.h"
#include "par.h"
#include "par_restart.h"
#include "run.h"

#include <math.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"
#include "accuracy_map.h"
#include "args.h"
#include "device.h"
#include "engine.h"
#include "error.h"
#include "fused.h"
#include "input.h"
#include "fix.h"
#include "kargs.h"
#include "lanes_tune.h"
#include "group.h"
#include "log.h"
#include "memfit.h"
#include "neighbor.h"
#include "output.h"
#include "pair.h"
#include "restart.h"
#include "wall_clock.h"

/* The loop's clocks: LAMMPS's timing breakdown (Pair, Neigh, Modify,
 * Output; Other is what the loop spent beyond them), in wall seconds.
 * The device is synchronized after each section only on sampled steps
 * (every TIME_SAMPLE-th) and on rebuild steps, so ordinary steps run
 * without host waits: rebuild steps are timed exactly, sampled ordinary
 * steps are scaled to all ordinary steps; the output is timed every step.
 * A sample's waits cost a threaded device's hand-off each (doc/opencl.md):
 * one step in 32 keeps them out of the steps decided on speculation. */
enum timer_phase { TM_PAIR, TM_NEIGH, TM_MODIFY, TM_OUTPUT, TM_N };
enum { TIME_SAMPLE = 32 };
struct run_timers {
    double exact[TM_N];         /* rebuild steps; the output of every step */
    double sampled[TM_N];       /* sampled ordinary steps */
    bigint nsamp, nplain;       /* sampled ordinary steps, all ordinary steps */
};

/* One step's section times (step[], output excluded) into the record. */
static void timers_step(struct run_timers *t, int rebuild, int sampled, const double *step)
{
    if (!rebuild)
        t->nplain++;
    if (!rebuild && !sampled)
        return;
    if (!rebuild)
        t->nsamp++;
    double *to = rebuild ? t->exact : t->sampled;
    for (int p = 0; p < TM_OUTPUT; p++)
        to[p] += step[p];
}

/* The loop's totals per phase (out[TM_N]): sampled times scaled to every
 * ordinary step, and never more section time than the loop spent outside
 * the output (sampled steps run a little slower, for their syncs). */
static void timers_total(const struct run_timers *t, double loop, double *out)
{
    double scale = t->nsamp ? (double)t->nplain / (double)t->nsamp : 0.0;
    for (int p = 0; p < TM_OUTPUT; p++)
        out[p] = t->exact[p] + t->sampled[p] * scale;
    out[TM_OUTPUT] = t->exact[TM_OUTPUT];
    double busy = out[TM_PAIR] + out[TM_NEIGH] + out[TM_MODIFY];
    double avail = loop - out[TM_OUTPUT];
    if (busy > avail && busy > 0)
        for (int p = 0; p < TM_OUTPUT; p++)
            out[p] *= avail / busy;
}

/* Pair + Neigh so far (balance weight time): as timers_total, unclamped. */
static double cost_so_far(const struct run_timers *t)
{
    double scale = t->nsamp ? (double)t->nplain / (double)t->nsamp : 0.0;
    return t->exact[TM_PAIR] + t->exact[TM_NEIGH] +
           (t->sampled[TM_PAIR] + t->sampled[TM_NEIGH]) * scale;
}

/* Pack and upload the per-type-pair parameters; create the pair kernels.
 * Before the fixes initialise: a fix that uses the pair law (fix wall/pair)
 * takes the parameter buffer in its init. */
static void pair_init(struct gravel *g)
{
    struct engine *e = g->eng;
    const struct pair *p = g->styles.pair;
    e->k_clear = eng_kernel(g, "force_clear");
    e->k_gather = eng_kernel(g, "pair_gather");
    e->k_tail = eng_kernel(g, "fused_tail");
    e->k_pair = e->k_virial = e->k_energy = NULL;
    e->k_pair1 = e->k_gather1 = e->k_tail1 = NULL;
    if (e->pair_param)
        clReleaseMemObject(e->pair_param);
    e->pair_param = NULL;
    if (!p || p->caps.host_forces) /* a host law: no device pair kernels */
        return;
    int nt, np = p->caps.nparam;
    double *par = pair_pack(g, &nt);
    e->pair_param = eng_alloc(g, (size_t)nt * nt * np * e->rsz, "pair parameters");
    eng_write_reals(g, e->pair_param, (size_t)nt * nt * np, par);
    free(par);
    e->k_pair = eng_kernel(g, "pair_contacts");
    if (e->pair_lw > 1) /* and its one-contact form (lanes_tune.h) */
        e->k_pair1 = eng_kernel(g, "pair_contacts_1");
    if (e->atom_lw > 1) {
        e->k_gather1 = eng_kernel(g, "pair_gather_1");
        e->k_tail1 = eng_kernel(g, "fused_tail_1");
    }
    e->k_virial = eng_kernel(g, "pair_virial");
    if (p->caps.energy)
        e->k_energy = eng_kernel(g, "pair_energy");
}

/* The box-deformation kernels and rates: after the fixes initialise (a
 * deforming fix's init sets the rates and the remap group). */
static void box_init(struct gravel *g)
{
    struct engine *e = g->eng;
    e->k_box_remap = eng_kernel(g, "box_remap");
    e->k_box_flip = eng_kernel(g, "box_image_flip");
    e->virial_snap_step = e->epair_snap_step = -1;
    if (!e->hrate)
        e->hrate = eng_alloc(g, 6 * e->rsz, "box deformation rates");
    eng_write_reals(g, e->hrate, 6, g->dom.h_rate);
    e->vgroup = g->dom.vremap_group;
}

/* The hook lists of a run (LAMMPS Modify::init): for each hook, the fixes
 * that set it and are not fused into the scene's kernels, in fix order,
 * with the function to call. Built once at run setup. */
static int hook_index(unsigned hook)
{
    return hook == HOOK_INITIAL_INTEGRATE ? 0 : hook == HOOK_POST_FORCE ? 1
         : hook == HOOK_FINAL_INTEGRATE   ? 2 : hook == HOOK_END_OF_STEP ? 3
         : hook == HOOK_PRE_EXCHANGE      ? 4 : hook == HOOK_PRE_FORCE ? 5 : 6;
}

static void build_hook_lists(struct gravel *g)
{
    struct hook_lists *h = &g->eng->hooks;
    const unsigned bits[NHOOK] = {HOOK_INITIAL_INTEGRATE, HOOK_POST_FORCE, HOOK_FINAL_INTEGRATE,
                                  HOOK_END_OF_STEP,       HOOK_PRE_EXCHANGE, HOOK_PRE_FORCE,
                                  HOOK_POST_INTEGRATE};
    for (int k = 0; k < NHOOK; k++) {
        free(h->call[k]);
        h->call[k] = gr_calloc(g, (size_t)g->styles.nfix + 1, sizeof *h->call[k]);
        h->n[k] = 0;
        for (int i = 0; i < g->styles.nfix; i++) {
            struct fix *f = g->styles.fix[i];
            if (!(f->hooks & bits[k]) || (f->fused_hooks & bits[k]))
                continue;
            void (*fn)(struct gravel *, struct fix *) =
                k == 0 ? f->style->initial_integrate : k == 1 ? f->style->post_force
              : k == 2 ? f->style->final_integrate   : k == 3 ? f->style->end_of_step
              : k == 4 ? f->style->pre_exchange      : k == 5 ? f->style->pre_force
                                                     : f->style->post_integrate;
            if (fn)
                h->call[k][h->n[k]++] = (struct hook_call){f, fn};
        }
    }
    free(h->force);
    h->force = gr_calloc(g, (size_t)g->styles.nfix + 1, sizeof *h->force);
    h->nforce = 0;
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->force_reneighbor)
            h->force[h->nforce++] = g->styles.fix[i];
}

const struct hook_call *run_post_force_calls(struct gravel *g, int *n)
{
    const struct hook_lists *h = &g->eng->hooks;
    *n = h->n[hook_index(HOOK_POST_FORCE)];
    return h->call[hook_index(HOOK_POST_FORCE)];
}

/* LAMMPS Neighbor::decide()'s must_check: some fix wants a rebuild now. */
static int forced_rebuild(struct gravel *g)
{
    const struct hook_lists *h = &g->eng->hooks;
    for (int i = 0; i < h->nforce; i++)
        if (h->force[i]->next_reneighbor == g->step)
            return 1;
    return 0;
}

/* Atoms fixes may insert during the next nsteps steps: the device capacity
 * holds them from the start and the neighbor cut-off covers their radii. */
static long insertions(struct gravel *g, bigint nsteps, double *rmax)
{
    long extra = 0;
    *rmax = 0;
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        double r = 0;
        if (f->style->reserve)
            extra += f->style->reserve(g, f, nsteps, &r);
        if (r > *rmax)
            *rmax = r;
    }
    return extra;
}

static void reserve_insertions(struct gravel *g, bigint nsteps)
{
    struct engine *e = g->eng;
    double rmax = 0;
    long extra = insertions(g, nsteps, &rmax);
    e->insert_rmax = rmax;
    if (extra > 200000000L - g->atoms.n)
        gr_error(g, "too many atoms to insert (%ld)", extra);
    mem_fit_run(g, g->atoms.n + (int)extra); /* before the first large allocation */
    if (extra)
        eng_reserve(g, g->atoms.n + (int)extra);
}

static void run_hook(struct gravel *g, unsigned hook)
{
    const struct hook_lists *h = &g->eng->hooks;
    int k = hook_index(hook);
    for (int i = 0; i < h->n[k]; i++)
        h->call[k][i].fn(g, h->call[k][i].fix);
}

/* Whether this step's pair_gather (or, with a tail, fused_tail) also runs
 * the next step's opening (kernels/atom_step.cl: its initial_integrate ops,
 * wrap and rebuild check; bit-identical to nbr_check at the next step's
 * start): when nothing reads or moves the particles after it, i.e. every
 * fix's per-step work is fused (no hook left to call but the post_force
 * ones before a tail; pre_exchange runs after the check), no output or
 * restart file is due, and the step is not the run's last. */
static int step_lookahead(struct gravel *g, int last)
{
    const struct engine *e = g->eng;
    if (!e->k_pair || !e->fused.lookahead || last || par_on(g) /* ghosts come between */ || output_due(g, g->step) ||
        restart_due(g, g->step))
        return 0;
    const int tail = e->fused.tpost + e->fused.tfinal > 0; /* opens after the post_force hooks */
    for (int k = 0; k < NHOOK; k++)
        if (e->hooks.n[k] > 0 && k != hook_index(HOOK_PRE_EXCHANGE) &&
            !(tail && k == hook_index(HOOK_POST_FORCE)))
            return 0;
    return 1;
}

/* Whether nothing but kernels that take the halt runs between this step's
 * rebuild decision and the next (nbr_decide's plain): its pair_gather (or
 * fused_tail) opens the next step, no fix calls in but those that halt
 * (struct fix, halts: fix wall/gran's post_force before a fused tail) and
 * no dynamic group is updated. */
static int plain_step(struct gravel *g, int last)
{
    if (!step_lookahead(g, last))
        return 0;
    const struct hook_lists *h = &g->eng->hooks; /* only a tail's post_force hooks are left */
    for (int i = 0; i < h->n[hook_index(HOOK_POST_FORCE)]; i++)
        if (!h->call[hook_index(HOOK_POST_FORCE)][i].fix->halts)
            return 0;
    for (int ig = 1; ig < g->groups.n; ig++)
        if (g->groups.used[ig] && g->groups.dyn[ig].on)
            return 0;
    return 1;
}

/* LAMMPS's post_neighbor: the fixes that follow the atoms' device order. */
static void post_neighbor(struct gravel *g)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->style->post_neighbor)
            g->styles.fix[i]->style->post_neighbor(g, g->styles.fix[i]);
}

/* HAS_HEAT: the heat records of ncontact contacts (one each, the owner's
 * heat: kernels/pair_loop.cl), grown as the contacts grow; without heat the
 * force records stand in (never read). */
static cl_mem heat_records(struct gravel *g, size_t ncontact)
{
    struct engine *e = g->eng;
    if (!e->heat)
        return nbr_list(g)->rec;
    size_t need = (ncontact + 1) * e->rsz;
    if (!e->recq || need > e->recq_cap) {
        if (e->recq)
            clReleaseMemObject(e->recq);
        e->recq_cap = need + need / 8 + 64 * e->rsz;
        e->recq = eng_alloc(g, e->recq_cap, "contact heat records");
    }
    return e->recq;
}

/* Force computation: pair (or clear), then every post_force fix; their
 * wall times are added to t[TM_PAIR] and t[TM_MODIFY]. */
static void compute_forces(struct gravel *g, unsigned freezebit, int timed, double *t, int look)
{
    struct engine *e = g->eng;
    struct dev_atoms *a = &e->a;
    const int tail = e->fused.tpost + e->fused.tfinal > 0; /* fused.h: the fused tail */
    struct pair_gather_args tail_args = {0};
    double t0 = wall_clock();
    if (e->k_pair) {
        /* the contact pipeline: each contact once, then each particle's sum */
        const struct nbr_list *l = nbr_list(g);
        acc_reserve(g);
        cl_mem recq = heat_records(g, (size_t)l->ncontact);
        struct pair_contacts_args pc = {
            .ncontact = l->ncontact,
            .ci = l->ci,
            .cj = l->cj,
            .x = a->x,
            .v = a->v,
            .omega = e->rotation ? a->omega : a->v,
            .radius = a->radius,
            .rmass = e->contact_mass ? e->contact_mass : a->rmass, /* meff */
            .type = a->type,
            .mask = a->mask,
            .shear = e->history ? l->shear : l->ci,
            .param = e->pair_param,
            .ntypes = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1,
            .nparam = g->styles.pair->caps.nparam,
            .freezebit = freezebit,
            .dt = g->dt,
            .shearupdate = e->setup ? 0 : 1,
            .rec = l->rec,
            .acc = acc_pair_rec(g),
            .astep = acc_pair_step(g),
            .step = acc_step(g),
            .hrate = e->hrate,
            .vgroup = e->vgroup,
            .temp = e->heat ? a->temperature : a->v,
            .recq = recq,
            .quiet = l->quiet,
        };
        nbr_list_box(l, pc.box);
        nbr_halt_args(g, &pc.halt);
        /* PAIR_LW contacts per work-item (kernels/pair_gran_lanes.cl), or one */
        size_t w;
        if (!e->setup)
            lanes_step(g);
        cl_kernel kp = lanes_pair_kernel(g, &w);
        ka_bind_pair_contacts(g, kp, 0, &pc);
        eng_launch(g, kp, ((size_t)l->ncontact + w - 1) / w);
        lanes_done(g, LANES_PAIR);
        /* new forces: a virial or energy taken before is stale */
        e->virial_snap_step = e->epair_snap_step = -1;
        /* fused post_force ops, and the final kick except at setup */
        struct pair_gather_args pg = {
            .n = a->n,
            .ioff = l->ioff,
            .coff = l->coff,
            .pcon = l->pcon,
            .rec = l->rec,
            .zidx = l->ncontact,
            .f = a->f,
            .torque = e->rotation ? a->torque : a->f,
            .ops = e->fused.ops,
            .first = e->fused.ninit,
            .npost = e->fused.npost,
            .nfinal = e->setup ? 0 : e->fused.nfinal + e->fused.neos,
            .prm = e->fused.prm,
            .store = e->fused.store_fix ? e->fused.store_fix->peratom : a->f,
            .v = a->v,
            .omega = e->rotation ? a->omega : a->v,
            .rmass = a->rmass,
            .radius = a->radius,
            .type = a->type,
            .mask = a->mask,
            .recq = recq,
            .heatflow = e->heat ? a->heatflow : a->f,
            .quiet = l->quiet,
            .look = look && !tail,
            .halt = pc.halt,
        };
        nbr_step_args(g, &pg.atom_step, pg.look);
        cl_kernel kg = lanes_gather_kernel(g, 0, &w);
        ka_bind_pair_gather(g, kg, 0, &pg);
        eng_launch(g, kg, ((size_t)a->n + w - 1) / w);
        lanes_done(g, LANES_ATOM);
        tail_args = pg;
    } else {
        acc_reserve(g); /* the wall records */
        const struct force_clear_args fc = {
            .n = a->n, .f = a->f, .torque = e->rotation ? a->torque : a->f,
            .heatflow = e->heat ? a->heatflow : a->f};
        ka_bind_force_clear(g, e->k_clear, 0, &fc);
        eng_launch(g, e->k_clear, (size_t)a->n);
        const struct pair *hp = g->styles.pair;
        if (hp && hp->caps.host_forces)
            hp->caps.host_forces(g, hp);
    }
    if (timed)
        eng_finish(g);
    double t1 = wall_clock();
    t[TM_PAIR] += t1 - t0;
    run_hook(g, HOOK_POST_FORCE);
    if (e->k_pair && tail) { /* the fused ops after the unfused post_force fixes */
        tail_args.first = e->fused.tfirst;
        tail_args.npost = e->fused.tpost;
        tail_args.nfinal = e->setup ? 0 : e->fused.tfinal;
        tail_args.look = look;
        nbr_step_args(g, &tail_args.atom_step, look);
        size_t w;
        cl_kernel kt = lanes_gather_kernel(g, 1, &w);
        ka_bind_pair_gather(g, kt, 0, &tail_args);
        eng_launch(g, kt, ((size_t)a->n + w - 1) / w);
    }
    if (timed)
        eng_finish(g);
    t[TM_MODIFY] += wall_clock() - t1;
}

/* Log the collision time of the contact model against the time step:
 * warning under ~10 steps per collision; error under 2 unless the run was
 * given `force yes` (DESIGN: Precision and the speed/accuracy trade). */
static void timestep_report(struct gravel *g, int force)
{
    const struct pair *p = g->styles.pair;
    if (!p || !p->caps.collision_time || g->atoms.n == 0)
        return;
    double m = INFINITY, r = 0, vmax = 0;
    for (int i = 0; i < g->atoms.n; i++) {
        if (g->atoms.rmass[i] < m) {
            m = g->atoms.rmass[i];
            r = g->atoms.radius[i];
        }
        for (int d = 0; d < 3; d++)
            vmax = fmax(vmax, fabs(g->atoms.v[3 * i + d]));
    }
    double tc = pair_collision_time(&p->caps, m, r, vmax > 0 ? 2 * vmax : 0);
    if (!isfinite(tc)) {
        gr_print(g, "Contact model %s: overdamped or zero stiffness, no collision time\n",
                 p->style->name);
        return;
    }
    double steps = tc / g->dt;
    gr_print(g, "Contact model %s: collision time %.4g = %.1f steps of %g (lightest particle)\n",
             p->style->name, tc, steps, g->dt);
    /* verify: below 2 steps a contact can be missed or explode */
    if (steps < 2 && !force)
        gr_error(g, "time step %g exceeds half the %s collision time %.4g (%.2f steps per "
                    "collision): contacts are not resolved; reduce the time step or add "
                    "'force yes' to run", g->dt, p->style->name, tc, steps);
    if (steps < 10)
        gr_warn(g, "time step %g resolves a %s collision with only %.1f steps (at least ~10 "
                   "are needed for accuracy)", g->dt, p->style->name, steps);
}

/* verify: single precision keeps positions as hi + lo float pairs relative
 * to the device origin (kernels/common.cl, "Positions"): a coordinate x
 * resolves to about |x - origin| 2^-47. Warn at setup when that exceeds
 * 1e-6 of the smallest radius: overlaps (fractions of a radius) would lose
 * digits that double keeps. Called after the upload (the origin is set). */
static void precision_report(struct gravel *g)
{
    const struct atoms *a = &g->atoms;
    const double *o = g->eng->origin;
    if (!g->eng->single || a->n == 0)
        return;
    double xmax = 0, rmin = INFINITY;
    for (int i = 0; i < a->n; i++) {
        for (int d = 0; d < 3; d++)
            xmax = fmax(xmax, fabs(a->x[3 * i + d] - o[d]));
        rmin = fmin(rmin, a->radius[i]);
    }
    double ulp = xmax * 0x1p-47;
    if (ulp > 1e-6 * rmin)
        gr_warn(g, "single precision: coordinates up to %g from the device origin resolve "
                   "only %.3g, %.3g of the smallest radius %g; overlaps lose precision (use "
                   "-precision double or a smaller box)", xmax, ulp, ulp / rmin, rmin);
}

static void check_atoms(struct gravel *g)
{
    const struct atoms *a = &g->atoms;
    for (int i = 0; i < a->n; i++) {
        if (!(a->rmass[i] > 0) || !(a->radius[i] > 0))
            gr_error(g, "atom %lld has radius %g and mass %g: granular runs need positive "
                        "radius and mass (set diameter/density or mass)",
                     (long long)a->tag[i], a->radius[i], a->rmass[i]);
        if (a->type[i] < 1 || a->type[i] > a->ntypes)
            gr_error(g, "atom %lld has type %d outside 1..%d", (long long)a->tag[i], a->type[i],
                     a->ntypes);
    }
}

/* Run setup up to the first force computation: device program, upload,
 * fix init and per-atom state, pair, neighbor and hook lists, reports.
 * Returns the freeze group bit. */
static unsigned run_begin(struct gravel *g, bigint nsteps, int force)
{
    check_atoms(g);
    ocl_mem_reset_peak();
    double rmax; /* the first run chooses the device by its size */
    eng_open(g, (g->atoms.n + insertions(g, nsteps, &rmax)) / comm_size());
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->style->prepare)
            g->styles.fix[i]->style->prepare(g, g->styles.fix[i]);
    eng_prepare(g);
    struct engine *e = g->eng;
    e->active = 0;
    restart_adopt_ranks(g); /* several ranks: read_restart's state goes by tag */
    par_run_begin(g);       /* several ranks: this rank's atoms only from here */
    reserve_insertions(g, nsteps);
    eng_upload(g);
    memset(&e->st, 0, sizeof e->st);
    e->contact_mass = NULL; /* a fix (rigid/small) sets it again in init */
    g->firststep = g->step; /* the fixes' init may read the run's span (fix deform) */
    g->laststep = g->step + nsteps;
    g->beginstep = g->run_start >= 0 ? g->run_start : g->step; /* LAMMPS's elaplong origin */
    g->endstep = g->run_stop >= 0 ? g->run_stop : g->laststep; /* ramp()'s end */
    g->run_start = g->run_stop = -1; /* used once: only cmd_run sets them */
    g->running = 1;
    memset(g->dom.h_rate, 0, sizeof g->dom.h_rate); /* a deforming fix's init sets them */
    g->dom.vremap_group = 0;
    pair_init(g); /* the pair parameters first: fixes may use them in init */
    lanes_begin(g, nsteps);
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (f->style->init)
            f->style->init(g, f);
    }
    eng_fix_state(g, 1); /* fixes may have declared per-atom state in init */
    par_fix_state_restore(g); /* several ranks: the state of the last run */
    box_init(g);
    nbr_setup(g);
    fused_setup(g);
    build_hook_lists(g);
    unsigned freezebit = fix_frozen_groupbit(g);
    timestep_report(g, force);
    precision_report(g);
    acc_begin(g, force); /* collision resolution of the contacts that happen */
    return freezebit;
}

/* A decomposed run's footer spreads over the ranks: the sections' times,
 * owned atoms, neighbor pairs; the loop time becomes the ranks' mean and
 * Other the loop's mean minus the sections' means, as LAMMPS prints them.
 * Before ranks_stats sums the counts. */
static void spreads(struct gravel *g, struct run_stats *st)
{
    double mine[RUN_ROW_N], *all = NULL;
    run_stats_row(st, mine);
    size_t bytes = comm_allgatherv(mine, sizeof mine, (void **)&all);
    if (bytes == (size_t)-1)
        gr_error(g, "out of memory gathering the run's timings");
    struct rank_spread loop;
    run_stats_spread(st, all, (int)(bytes / sizeof mine), &loop);
    free(all);
    st->t_total = loop.avg;
    st->t_other = 0;
    st->ranks_spread = 1;
}

/* A decomposed run's statistics over the ranks: atoms, neighbors and
 * contacts summed; the largest overlap and the worst resolved collision
 * over all (ties: the lowest rank's). */
static void ranks_stats(struct gravel *g, struct run_stats *st)
{
    double c[4];
    comm_counters(c); /* this run's, before the statistics' own */
    double per = st->nsteps > 0 ? 1.0 / ((double)st->nsteps * comm_size()) : 0;
    long long sum[4];
    for (int k = 0; k < 4; k++)
        sum[k] = comm_sum_ll((long long)c[k]);
    st->comm_bytes = (double)sum[0] * per;
    st->comm_msgs = (double)sum[1] * per;
    st->coll_bytes = (double)sum[2] * per;
    st->coll_calls = (double)sum[3] * per;
    st->natoms = (int)comm_sum_ll(st->natoms);
    st->total_neighbors = (double)comm_sum_ll((long long)st->total_neighbors);
    st->ncontact = (int)comm_sum_ll(st->ncontact);
    double lo = 0, hi = st->max_overlap_frac;
    comm_minmax(&lo, &hi, 1);
    st->max_overlap_frac = hi;
    struct run_stats *all = NULL;
    size_t bytes = comm_allgatherv(st, sizeof *st, (void **)&all);
    if (bytes == (size_t)-1)
        gr_error(g, "out of memory gathering the run's statistics");
    int best = 0;
    for (int r = 1; r < (int)(bytes / sizeof *st); r++)
        if (all[r].res_q > all[best].res_q)
            best = r;
    st->res_q = all[best].res_q;
    st->res_vn = all[best].res_vn;
    st->res_step = all[best].res_step;
    st->res_tag_i = all[best].res_tag_i;
    st->res_tag_j = all[best].res_tag_j;
    memcpy(st->res_wall, all[best].res_wall, sizeof st->res_wall);
    free(all);
}

/* Statistics of a finished run (or rerun) and its footer. */
static void run_end(struct gravel *g, bigint nsteps, double ttot, const double *t,
                    double maxov, int post);

/* An exact continuation's setup computes the forces for the virial and
 * energies of its thermo row only: the contacts' tangential history (pairs,
 * and the fixes' per-atom state such as wall history), which the setup
 * would rescale to the friction limit with the written step's full-step
 * velocities, is held on the host meanwhile, and the written step's forces
 * (computed with its half-step velocities) go back on the device. */
struct held {
    unsigned char *shear, **fix; /* fix: one per fix, NULL without state */
    size_t shear_bytes, force_bytes;
    unsigned char *f, *torque;   /* one process: the device's forces (the file's) */
};

static void hold_history(struct gravel *g, struct held *h)
{
    struct engine *e = g->eng;
    const struct nbr_list *l = nbr_list(g);
    memset(h, 0, sizeof *h);
    h->shear_bytes = e->history && l->shear ? (size_t)l->ncontact * e->hist_n * e->rsz : 0;
    if (h->shear_bytes) {
        h->shear = gr_malloc(g, h->shear_bytes);
        eng_read(g, l->shear, 0, h->shear_bytes, h->shear);
    }
    if (!par_on(g)) { /* no setup rebuild: the uploaded forces are the file's */
        h->force_bytes = 3 * (size_t)e->a.n * e->rsz;
        h->f = gr_malloc(g, h->force_bytes + 1);
        eng_read(g, e->a.f, 0, h->force_bytes, h->f);
        if (e->a.torque) {
            h->torque = gr_malloc(g, h->force_bytes + 1);
            eng_read(g, e->a.torque, 0, h->force_bytes, h->torque);
        }
    }
    h->fix = gr_calloc(g, (size_t)g->styles.nfix + 1, sizeof *h->fix);
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *f = g->styles.fix[i];
        size_t bytes = (size_t)e->a.n * f->peratom_bytes;
        if (f->peratom && bytes) {
            h->fix[i] = gr_malloc(g, bytes);
            eng_read(g, f->peratom, 0, bytes, h->fix[i]);
        }
    }
}

/* ... and back, with the written step's forces */
static void restore_history(struct gravel *g, struct held *h)
{
    struct engine *e = g->eng;
    if (h->shear_bytes)
        eng_write(g, nbr_list(g)->shear, 0, h->shear_bytes, h->shear);
    free(h->shear);
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *f = g->styles.fix[i];
        if (h->fix[i])
            eng_write(g, f->peratom, 0, (size_t)e->a.n * f->peratom_bytes, h->fix[i]);
        free(h->fix[i]);
    }
    free(h->fix);
    if (par_on(g)) {
        par_resume_forces(g); /* by tag: the setup exchange moved the atoms */
    } else {
        eng_write(g, e->a.f, 0, h->force_bytes, h->f);
        if (h->torque)
            eng_write(g, e->a.torque, 0, h->force_bytes, h->torque);
    }
    free(h->f);
    free(h->torque);
}

/* The whole run: setup, loop, footer. */
static void run_steps(struct gravel *g, bigint nsteps, int force, int post)
{
    unsigned freezebit = run_begin(g, nsteps, force);
    struct engine *e = g->eng;

    g->firststep = g->step;
    g->laststep = g->step + nsteps;
    double tsetup[TM_N] = {0}; /* not reported: LAMMPS times the loop only */
    /* setup: list, step-0 forces without history update, post_force fixes */
    e->setup = 1;
    /* after read_restart: restored list/history/fix state; 2 = the step's forces too */
    int resumed = restart_resume(g);
    group_dynamic_update(g, -1); /* dynamic groups at setup */
    if (resumed < 1 || par_on(g)) { /* several ranks: the setup exchange */
        nbr_rebuild(g);
        post_neighbor(g);
    }
    e->st.nbuilds = 0;
    nbr_quiet_reset(g); /* a restored list's records are unknown */
    run_hook(g, HOOK_PRE_FORCE); /* LAMMPS's setup_pre_force */
    if (resumed < 2) {
        compute_forces(g, freezebit, 1, tsetup, 0);
    } else { /* the setup's virial and energies; then the written step's forces */
        struct held h;
        hold_history(g, &h);
        compute_forces(g, freezebit, 1, tsetup, 0);
        restore_history(g, &h);
    }
    for (int i = 0; i < g->styles.nfix; i++) /* LAMMPS Modify::setup: after the forces */
        if (g->styles.fix[i]->style->setup)
            g->styles.fix[i]->style->setup(g, g->styles.fix[i]);
    e->setup = 0;
    double maxov = nbr_max_overlap(g);
    output_setup(g);
    /* Timing (struct run_timers): the decision read syncs every step. */
    struct run_timers tm = {0};
    e->st.nlaunch = 0;
    nbr_step_reset(g);
    comm_counters_reset(); /* the loop's communication (the footer's per-step figures) */
    double t0 = wall_clock();
    for (bigint s = 0; s < nsteps; s++) {
        g->step++;
        /* `time` is the step's time throughout the step, as LAMMPS's
         * atime + (ntimestep - atimestep) dt: a region moved by a variable
         * of time is where step n puts it when step n's forces see it */
        g->time += g->dt;
        int sampled = s % TIME_SAMPLE == 0;
        if (sampled)
            eng_finish(g); /* the previous step's work is not this step's */
        double a0 = wall_clock();
        run_hook(g, HOOK_INITIAL_INTEGRATE);
        run_hook(g, HOOK_POST_INTEGRATE); /* LAMMPS's post_integrate (fix wall/reflect) */
        if (sampled)
            eng_finish(g);
        double a1 = wall_clock();
        /* a step decided on speculation that failed puts g->step back */
        int rebuild = nbr_decide(g, forced_rebuild(g), plain_step(g, s + 1 == nsteps));
        s = g->step - g->firststep - 1;
        if (!rebuild && par_on(g))
            par_forward(g); /* the ghosts' x, v, omega of this step */
        group_dynamic_update(g, g->step); /* LAMMPS' post_integrate */
        double tx = 0; /* pre_exchange (fix pour inserts here): Modify, as LAMMPS */
        if (rebuild) {
            acc_collect(g); /* the records are per contact and atom: before renumbering */
            double p0 = wall_clock();
            run_hook(g, HOOK_PRE_EXCHANGE);
            tx = wall_clock() - p0;
            nbr_rebuild(g);
            post_neighbor(g);
            eng_finish(g);
        }
        double p1 = wall_clock();
        run_hook(g, HOOK_PRE_FORCE); /* counted as Modify, like pre_exchange */
        double a2 = wall_clock();
        tx += a2 - p1;
        int timed = sampled || rebuild;
        double step[TM_N] = {0};
        const int look = step_lookahead(g, s + 1 == nsteps);
        compute_forces(g, freezebit, timed, step, look);
        double b0 = wall_clock();
        run_hook(g, HOOK_FINAL_INTEGRATE);
        run_hook(g, HOOK_END_OF_STEP);
        if (timed)
            eng_finish(g);
        double b1 = wall_clock();
        step[TM_NEIGH] = a2 - a1 - tx;
        step[TM_MODIFY] = (a1 - a0) + step[TM_MODIFY] + (b1 - b0) + tx;
        timers_step(&tm, rebuild, sampled, step);
        if (par_on(g))
            g->par->run_cost = cost_so_far(&tm); /* fix balance's weight time */
        if (!look && output_due(g, g->step)) { /* look: none was due */
            acc_collect(g);
            double ov = nbr_max_overlap(g);
            if (ov > maxov)
                maxov = ov;
            output_step(g);
        }
        restart_step(g); /* `restart N file`: written when the step is a multiple of N */
        tm.exact[TM_OUTPUT] += wall_clock() - b1;
        if (g->halt) { /* fix halt: the run ends after this step (LAMMPS's timeout) */
            nsteps = g->step - g->firststep;
            break;
        }
    }
    double t[TM_N];
    timers_total(&tm, wall_clock() - t0, t);
    double ttot = wall_clock() - t0;
    run_end(g, nsteps, ttot, t, maxov, post);
    if (g->halt == HALT_CONTINUE) /* fix halt ... error continue: later runs go on */
        g->halt = 0;
}

static void run_end(struct gravel *g, bigint nsteps, double ttot, const double *t,
                    double maxov, int post)
{
    struct engine *e = g->eng;
    acc_collect(g);
    const struct acc_worst *worst = acc_worst(g);
    maxov = fmax(maxov, worst->wall_ov); /* walls and meshes: every step */
    run_sync_host(g);
    struct run_stats st = e->st;
    st.nsteps = nsteps;
    st.natoms = e->a.n;
    st.t_total = ttot;
    st.t_pair = t[TM_PAIR];
    st.t_neigh = t[TM_NEIGH];
    st.t_modify = t[TM_MODIFY];
    st.t_output = t[TM_OUTPUT];
    st.t_other = fmax(0.0, ttot - st.t_pair - st.t_neigh - st.t_modify - st.t_output);
    st.total_neighbors = nbr_total(g);
    st.max_overlap_frac = maxov;
    st.res_q = worst->q;
    st.res_vn = worst->vn;
    st.res_step = worst->step;
    st.res_tag_i = worst->tag_i;
    st.res_tag_j = worst->tag_j;
    snprintf(st.res_wall, sizeof st.res_wall, "%s", worst->wall);
    st.ncontact = e->k_pair ? nbr_list(g)->ncontact : 0; /* no pair style: none evaluated */
    st.mem_peak = (double)ocl_mem_peak();
    if (par_on(g)) {
        g->par->last_cost = st.t_pair + st.t_neigh; /* balance's weight time, neigh */
        g->par->last_neigh = st.total_neighbors;
        spreads(g, &st);
        ranks_stats(g, &st);
        par_run_end(g); /* every rank's host holds every atom again */
    }
    e->active = 0;
    if (post)
        output_finish(g, &st);
    else /* run ... post no: only the "Loop time" line, as LAMMPS */
        output_finish_brief(g, &st);
    /* verify: Hertz/linear contact laws assume small overlaps */
    if (maxov > 0.1)
        gr_warn(g, "largest overlap reached %.1f %% of a radius (pairs sampled at output "
                   "steps, walls and meshes at every step): "
                   "impacts too fast or contacts too soft for the contact model",
                100 * maxov);
    g->running = 0;
}

/* rerun's core: the run setup once, then for each snapshot (load() puts it
 * into the host atoms and sets the step; -1 ends) the setup forces without
 * integration or history update (LAMMPS's setup_minimal), the fixes' setup
 * and end_of_step work and the output due at that step (the first snapshot
 * prints the thermo header and its row); the last snapshot's thermo row is
 * always printed, then LAMMPS's footer counts the snapshots as steps. */
static void rerun_steps(struct gravel *g, bigint (*load)(struct gravel *, void *), void *ctx,
                        bigint firststep, bigint laststep, int post)
{
    unsigned freezebit = run_begin(g, 0, 0);
    struct engine *e = g->eng;
    g->firststep = firststep;
    g->laststep = laststep;
    g->beginstep = firststep;
    g->endstep = laststep;
    double t[TM_N] = {0}, maxov = 0; /* no Neigh: every snapshot rebuilds in setup */
    bigint ndump = 0;
    double t0 = wall_clock();
    for (int first = 1;; first = 0) {
        ndump++;
        e->setup = 1;
        group_dynamic_update(g, -1);
        nbr_rebuild(g);
        compute_forces(g, freezebit, 1, t, 0);
        for (int i = 0; i < g->styles.nfix; i++)
            if (g->styles.fix[i]->style->setup)
                g->styles.fix[i]->style->setup(g, g->styles.fix[i]);
        e->setup = 0;
        run_hook(g, HOOK_END_OF_STEP);
        eng_finish(g);
        double o0 = wall_clock();
        maxov = fmax(maxov, nbr_max_overlap(g));
        if (first)
            output_setup(g);
        else if (output_due(g, g->step))
            output_step(g);
        t[TM_OUTPUT] += wall_clock() - o0;
        run_sync_host(g);
        e->active = 0;
        par_rerun_gather(g); /* several ranks: the snapshot goes into every atom */
        bigint prev = g->step;
        if (load(g, ctx) < 0) {
            g->step = prev;
            par_rerun_keep(g);
            break;
        }
        check_atoms(g);
        par_rerun_scatter(g); /* ... and each rank keeps its brick's */
        eng_upload(g);
        par_fix_state_restore(g);
    }
    eng_upload(g); /* the host may have been read from: the device state again */
    double o0 = wall_clock();
    g->laststep = g->step; /* LAMMPS: thermo on the last snapshot */
    output_step(g);
    t[TM_OUTPUT] += wall_clock() - o0;
    double ttot = wall_clock() - t0;
    run_end(g, ndump, ttot, t, maxov, post);
}

/* body(g, ctx) under an error boundary: a run that stops on an error (lost
 * or non-finite atoms, a failed write, a fix) first ends its output
 * (output_abort: progress line erased before the message, append-mode dumps
 * completed with the snapshots written so far) and marks the engine idle,
 * then the error goes on to the command boundary. */
static void guarded(struct gravel *g, void (*body)(struct gravel *, void *), void *ctx)
{
    jmp_buf *outer = g->err.jmp, here;
    g->err.jmp = &here;
    if (setjmp(here)) {
        g->err.jmp = outer;
        output_abort(g);
        if (g->eng)
            g->eng->active = 0;
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    body(g, ctx);
    g->err.jmp = outer;
}

struct run_args {
    bigint n;
    int force, post;
};

static void run_body(struct gravel *g, void *ctx)
{
    const struct run_args *r = ctx;
    run_steps(g, r->n, r->force, r->post);
}

static void run_guarded(struct gravel *g, bigint n, int force, int post)
{
    struct run_args r = {n, force, post};
    guarded(g, run_body, &r);
}

struct rerun_args {
    bigint (*load)(struct gravel *, void *);
    void *ctx;
    bigint first, last;
};

static void rerun_body(struct gravel *g, void *ctx)
{
    const struct rerun_args *r = ctx;
    rerun_steps(g, r->load, r->ctx, r->first, r->last, 1);
}

void run_rerun(struct gravel *g, bigint (*load)(struct gravel *, void *), void *ctx,
               bigint firststep, bigint laststep)
{
    struct rerun_args r = {load, ctx, firststep, laststep};
    guarded(g, rerun_body, &r);
}

/* The commands of `run ... every` as script lines, with g->in_run_every
 * raised meanwhile (restored on an error too). */
static int every_commands(struct gravel *g, int ncmd, char **cmds)
{
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        g->in_run_every--;
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    g->in_run_every++;
    int rc = inp_run_commands(g, ncmd, cmds);
    g->in_run_every--;
    g->err.jmp = outer;
    return rc;
}

/* run N [upto] [start N] [stop N] [pre yes|no] [post yes|no]
 *       [every M "cmd" ... | every M NULL]
 * `every` (last, as in LAMMPS) splits the run into runs of M steps (the last
 * may be shorter), each a complete run with its own thermo header and loop
 * summary, and after each executes the commands as script lines. */
void cmd_run(struct gravel *g, int argc, char **argv)
{
    bigint n = arg_bigint(g, argv[0], "number of steps");
    bigint nevery = 0;
    int ncmd = 0;
    char **cmds = NULL;
    int upto = 0;
    bigint start = -1, stop = -1;
    int have_start = 0, have_stop = 0, force = 0, post = 1, accuracy = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "upto")) {
            upto = 1;
        } else if (!strcmp(argv[i], "start")) {
            arg_need(g, argc, i, 1, "start");
            start = arg_bigint(g, argv[++i], "start step");
            have_start = 1;
        } else if (!strcmp(argv[i], "stop")) {
            arg_need(g, argc, i, 1, "stop");
            stop = arg_bigint(g, argv[++i], "stop step");
            have_stop = 1;
        } else if (!strcmp(argv[i], "force")) {
            /* verify: allow a time step above half the collision time */
            arg_need(g, argc, i, 1, "force");
            force = arg_yesno(g, argv[++i], "force");
        } else if (!strcmp(argv[i], "accuracy")) {
            accuracy = 1; /* the accuracy map first (src/contact/accuracy_map.h) */
        } else if (!strcmp(argv[i], "pre")) {
            /* every run sets up fully (pre no is a LAMMPS speed hint) */
            arg_need(g, argc, i, 1, argv[i]);
            (void)arg_yesno(g, argv[i + 1], argv[i]);
            i++;
        } else if (!strcmp(argv[i], "post")) {
            arg_need(g, argc, i, 1, argv[i]);
            post = arg_yesno(g, argv[i + 1], argv[i]);
            i++;
        } else if (!strcmp(argv[i], "every")) {
            arg_need(g, argc, i, 1, "every");
            nevery = arg_bigint(g, argv[i + 1], "every interval");
            if (nevery <= 0)
                gr_error(g, "run every needs a positive interval, got %s", argv[i + 1]);
            cmds = argv + i + 2;
            ncmd = argc - i - 2;
            if (ncmd == 1 && !strcmp(cmds[0], "NULL"))
                ncmd = 0;
            break;
        } else {
            gr_error(g, "unknown run keyword '%.64s' (expected upto, start, stop, pre, post, "
                        "force, accuracy, every)",
                     argv[i]);
        }
    }
    if (upto) {
        n -= g->step;
        if (n < 0)
            gr_error(g, "run upto %lld: the current step %lld is already past it",
                     (long long)(n + g->step), (long long)g->step);
    }
    if (n < 0)
        gr_error(g, "number of steps must be >= 0, got %lld", (long long)n);
    if (n > ((bigint)1 << 62) - g->step) /* step + n, without overflowing near 2^63 */
        gr_error(g, "too many timesteps: step %lld + %lld steps passes 2^62",
                 (long long)g->step, (long long)n);
    if (have_start && start > g->step)
        gr_error(g, "run start %lld is after the first step %lld of the run", (long long)start,
                 (long long)g->step);
    if (have_stop && stop < g->step + n)
        gr_error(g, "run stop %lld is before the last step %lld of the run", (long long)stop,
                 (long long)(g->step + n));
    if (accuracy || g->opt.check)
        accuracy_map(g);
    if (g->opt.check) { /* gravel -check: the map instead of the run */
        gr_print(g, "(-check: run %lld not performed)\n", (long long)n);
        return;
    }
    if (g->halt) /* fix halt ... error soft ended an earlier run: LAMMPS skips this one */
        return;
    if (g->atoms.n == 0)
        gr_warn(g, "running with no atoms");
    bigint run_start = have_start ? start : -1; /* each (sub-)run's elaplong origin */
    bigint run_stop = have_stop ? stop : -1;    /* and ramp()'s end */
    if (!nevery) {
        g->run_start = run_start;
        g->run_stop = run_stop;
        run_guarded(g, n, force, post);
        return;
    }
    bigint left = n;
    for (int iter = 0; (left > 0 || iter == 0) && !g->halt; iter++) {
        bigint chunk = left < nevery ? left : nevery;
        g->run_start = run_start;
        g->run_stop = run_stop;
        run_guarded(g, chunk, force, post);
        left -= chunk;
        g->running = 1; /* the commands run inside the run, as LAMMPS's (whichflag) */
        int rc = ncmd ? every_commands(g, ncmd, cmds) : 0;
        g->running = 0;
        if (rc == GR_QUIT)
            return;
    }
}

/* reset_timestep N */
void cmd_reset_timestep(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    bigint n = arg_bigint(g, argv[0], "timestep");
    if (n < 0)
        gr_error(g, "timestep must be >= 0, got %lld", (long long)n);
    fix_check_time_reset(g);
    /* the motions timed from their own start (fix move/mesh, wall/gran
     * wiggle) keep their clocks: continuous across the reset */
    fix_reset_step(g, n - g->step);
    g->step = n;
    g->laststep_reset = n;
}
