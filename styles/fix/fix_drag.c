/* fix_drag.c - `fix ID group drag mu flow args [update explicit|implicit|exact]`:
 * Stokes drag of a fluid of dynamic viscosity mu on each particle (source
 * document 000 eq. 2.7-2.8; kernels in kernels/fix_drag.cl):
 *   F_d = m/tau_p (u_f(x) - v),  tau_p = rho_p d^2 / (18 mu)
 * so m/tau_p = 3 pi mu d: the drag coefficient follows from the diameter and
 * the particle's own density (mass / volume).
 *
 * Flows:
 *   uniform ux uy uz       u_f constant
 *   taylor_green A a       Taylor-Green vortex of 000 eq. 6.1-6.3
 *   taylor_green/demoranges A a   the vortex as 000's own code has it
 *                          (w with cos(a X) for sin(a X): compressible;
 *                          doc/agglomeration.md, Low Stokes number)
 *
 * Velocity update (`update`, default implicit):
 *   explicit   F_d added in post_force from the current (half-step) velocity;
 *              the integrator (nve, nve/sphere) sees it like any force.
 *   implicit   each half kick of the velocity-Verlet integrator becomes the
 *              backward-Euler step of 000 eq. 3.7-3.8 over h = dt/2:
 *                v' = v + h (u_f - v + tau F/m) / (tau + h)
 *              with F the other forces (treated as fixed over the kick).
 *   exact      each half kick solves dv/dt = F/m + (u_f - v)/tau exactly for
 *              fixed F and u_f:  v' = u_f + tau F/m + (v - u_f - tau F/m) e^(-h/tau)
 *
 * How implicit/exact act at the integration step through the fix hooks: the
 * fix adds an effective drag D = m (v' - v)/h - F to the force, so that the
 * integrator's ordinary kick v += h (F + D)/m lands exactly on v'. D is
 * computed in post_force (for the final kick, from v_{n+1/2}) and recomputed
 * in end_of_step (for the next step's initial kick, from v_{n+1}); the D in
 * the force is kept per atom (engine-managed, follows re-sorts) so that the
 * end_of_step update can take it out again. F is the force present when the
 * fix runs: fixes whose post_force comes later (defined after fix drag) are
 * treated explicitly, and init() warns about them. The position update stays
 * the integrator's x += dt v_{n+1/2}.
 *   trapezoidal  000's own scheme (eq. 3.8-3.9): a full-step backward-Euler
 *              velocity update from the forces at x_n and the trapezoidal
 *              position update x_{n+1} = x_n + dt (v_n + v_{n+1})/2; the
 *              opening kick lands on the mean of v_n and v_{n+1}, the closing
 *              kick on v_{n+1} (kernels/fix_drag.cl drag_trapezoid). */
#include <math.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fix_drag.h"
#include "fused.h"

/* the kernels' flow codes (kernels/drag_law.cl drag_flow) */
enum { FLOW_UNIFORM, FLOW_TAYLOR_GREEN, FLOW_TAYLOR_GREEN_DEMORANGES };
enum { UPD_EXPLICIT, UPD_IMPLICIT, UPD_EXACT, UPD_TRAPEZOIDAL };

struct drag {
    double mu;                  /* fluid dynamic viscosity */
    int flow;
    double p[3];                /* uniform: ux uy uz; taylor_green: A a - */
    int update;
    cl_kernel kexp, kimp, ktrap;
    double prm[7];              /* the fused ops' parameters (fuse) */
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, "fix drag expects mu and a flow (uniform ux uy uz | taylor_green A a | "
                    "taylor_green/demoranges A a) [update explicit|implicit|exact|trapezoidal]");
    struct drag *d = gr_calloc(g, 1, sizeof *d);
    f->data = d;
    d->mu = arg_positive(g, argv[0], "fluid viscosity mu");
    int i = 1;
    if (!strcmp(argv[i], "uniform")) {
        arg_need(g, argc, i, 3, "uniform");
        for (int k = 0; k < 3; k++)
            d->p[k] = arg_double(g, argv[i + 1 + k], "uniform flow velocity");
        d->flow = FLOW_UNIFORM;
        i += 4;
    } else if (!strcmp(argv[i], "taylor_green") || !strcmp(argv[i], "taylor_green/demoranges")) {
        arg_need(g, argc, i, 2, argv[i]);
        d->p[0] = arg_double(g, argv[i + 1], "Taylor-Green amplitude A");
        d->p[1] = arg_positive(g, argv[i + 2], "Taylor-Green wave number a");
        d->flow = strchr(argv[i], '/') ? FLOW_TAYLOR_GREEN_DEMORANGES : FLOW_TAYLOR_GREEN;
        i += 3;
    } else {
        gr_error(g, "unknown fix drag flow '%.64s' (expected uniform, taylor_green or "
                    "taylor_green/demoranges)", argv[i]);
    }
    d->update = UPD_IMPLICIT;
    for (; i < argc; i += 2) {
        if (strcmp(argv[i], "update"))
            gr_error(g, "unknown fix drag keyword '%.64s' (expected update)", argv[i]);
        arg_need(g, argc, i, 1, "update");
        const char *u = argv[i + 1];
        if (!strcmp(u, "explicit"))
            d->update = UPD_EXPLICIT;
        else if (!strcmp(u, "implicit"))
            d->update = UPD_IMPLICIT;
        else if (!strcmp(u, "exact"))
            d->update = UPD_EXACT;
        else if (!strcmp(u, "trapezoidal"))
            d->update = UPD_TRAPEZOIDAL;
        else
            gr_error(g, "fix drag update must be explicit, implicit or exact (or trapezoidal: "
                        "000 eq. 3.8-3.9), got '%.64s'", u);
    }
    f->hooks = HOOK_POST_FORCE | (d->update == UPD_EXPLICIT ? 0u : (unsigned)HOOK_END_OF_STEP);
    f->sources[f->nsources++] = "fix_drag.cl";
    if (d->update != UPD_TRAPEZOIDAL) /* its ops in the fused kernels (kernels/fused.cl) */
        snprintf(f->defines, sizeof f->defines, "FUSED_DRAG");
}

/* The explicit update advances the half-step velocity by forward Euler,
 * v += dt (u_f - v)/tau_p: the error is multiplied by 1 - dt/tau_p per step,
 * which decays only for dt < 2 tau_p (at 2 tau_p it flips sign undamped,
 * above it grows). Warn once per run when the smallest tau_p of the group
 * (the lightest/smallest particle: tau_p = m / (3 pi mu d)) is past it. */
static void check_explicit_limit(struct gravel *g, struct fix *f, const struct drag *d)
{
    const struct atoms *a = &g->atoms;
    double taumin = 0.0;
    int64_t tag = 0;
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & f->groupbit) || !(a->radius[i] > 0.0))
            continue;
        double tau = a->rmass[i] / (6.0 * M_PI * d->mu * a->radius[i]);
        if (tag == 0 || tau < taumin) {
            taumin = tau;
            tag = a->tag[i];
        }
    }
    if (tag != 0 && g->dt >= 2.0 * taumin * (1.0 - 1e-12))
        gr_warn(g, "fix %s drag update explicit: timestep %g is %.3g tau_p of atom %lld "
                   "(tau_p = %g, the smallest in the group): at or past the explicit limit 2 tau_p "
                   "the velocity oscillates without decay or grows; use update implicit or exact",
                f->id, g->dt, g->dt / taumin, (long long)tag, taumin);
}

static void init(struct gravel *g, struct fix *f)
{
    struct drag *d = f->data;
    if (d->update == UPD_EXPLICIT) {
        d->kexp = eng_kernel(g, "drag_explicit");
        check_explicit_limit(g, f, d);
        return;
    }
    if (d->update == UPD_TRAPEZOIDAL) {
        d->ktrap = eng_kernel(g, "drag_trapezoid");
        f->peratom_bytes = 6 * g->eng->rsz;     /* D and the opening kick's dv */
    } else {
        d->kimp = eng_kernel(g, "drag_implicit");
        f->peratom_bytes = 6 * g->eng->rsz;     /* D and the flow at the atom */
    }
    int self = -1;
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *o = g->styles.fix[i];
        if (o == f)
            self = i;
        else if (self >= 0 && (o->hooks & HOOK_POST_FORCE))
            gr_warn(g, "fix %s (%s) adds its force after fix %s drag: the %s drag update "
                       "treats it explicitly (define fix drag last to include it)",
                    o->id, o->style->name, f->id,
                    d->update == UPD_IMPLICIT ? "implicit"
                    : d->update == UPD_EXACT  ? "exact"
                                              : "trapezoidal");
    }
}

/* The flow field is evaluated at the device's coordinates: a shifted
 * device origin (single precision, a box far from 0) would move it. */
static void check_origin(struct gravel *g, struct fix *f)
{
    const struct drag *d = f->data;
    const double *o = g->eng->origin;
    if (d->flow && (o[0] != 0 || o[1] != 0 || o[2] != 0))
        gr_error(g, "fix %s: the taylor_green field is evaluated at lab coordinates, but in "
                    "single precision this box (centre %g %g %g, farther from 0 than its size) "
                    "is shifted on the device: run in double precision or centre the box "
                    "nearer 0", f->id, o[0], o[1], o[2]);
}

static void set_common(struct gravel *g, struct fix *f, cl_kernel k, int *i)
{
    struct drag *d = f->data;
    struct dev_atoms *a = eng_atoms(g);
    eng_arg_int(g, k, (*i)++, a->n);
    eng_arg_uint(g, k, (*i)++, f->groupbit);
    eng_arg_mem(g, k, (*i)++, a->mask);
    eng_arg_mem(g, k, (*i)++, a->x);
    eng_arg_mem(g, k, (*i)++, a->v);
    eng_arg_mem(g, k, (*i)++, a->f);
    eng_arg_mem(g, k, (*i)++, a->radius);
    eng_arg_mem(g, k, (*i)++, a->rmass);
    eng_arg_real(g, k, (*i)++, d->mu);
    eng_arg_int(g, k, (*i)++, d->flow);
    for (int q = 0; q < 3; q++)
        eng_arg_real(g, k, (*i)++, d->p[q]);
    check_origin(g, f);
}

static void apply_implicit(struct gravel *g, struct fix *f, int replace)
{
    struct drag *d = f->data;
    cl_kernel k = d->kimp;
    int i = 0;
    set_common(g, f, k, &i);
    eng_arg_mem(g, k, i++, f->peratom);
    eng_arg_int(g, k, i++, replace);
    eng_arg_int(g, k, i++, d->update == UPD_EXACT);
    eng_arg_real(g, k, i++, 0.5 * g->dt);
    eng_launch(g, k, (size_t)eng_atoms(g)->n);
}

/* update trapezoidal: opening kick (end_of_step, and the setup forces of a
 * run) or closing kick (post_force of a step); see kernels/fix_drag.cl. */
static void apply_trapezoid(struct gravel *g, struct fix *f, int replace, int closing)
{
    struct drag *d = f->data;
    cl_kernel k = d->ktrap;
    int i = 0;
    set_common(g, f, k, &i);
    eng_arg_mem(g, k, i++, f->peratom);
    eng_arg_int(g, k, i++, replace);
    eng_arg_int(g, k, i++, closing);
    eng_arg_real(g, k, i++, 0.5 * g->dt);
    eng_launch(g, k, (size_t)eng_atoms(g)->n);
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct drag *d = f->data;
    if (d->update == UPD_TRAPEZOIDAL) {
        apply_trapezoid(g, f, 0, !eng_in_setup(g));
        return;
    }
    if (d->update != UPD_EXPLICIT) {
        apply_implicit(g, f, 0);
        return;
    }
    int i = 0;
    set_common(g, f, d->kexp, &i);
    eng_launch(g, d->kexp, (size_t)eng_atoms(g)->n);
}

static void end_of_step(struct gravel *g, struct fix *f)
{
    struct drag *d = f->data;
    if (d->update == UPD_TRAPEZOIDAL) {
        apply_trapezoid(g, f, 1, 0);
        return;
    }
    apply_implicit(g, f, 1);
}

/* Fused (src/engine/fused.h): explicit and implicit/exact inside the
 * gather kernel, the same arithmetic (kernels/drag_law.cl); the
 * trapezoidal update's closing flag differs at setup, so it runs its own
 * kernel. prm: mu flow p0 p1 p2 exact h. */
static int fuse(struct gravel *g, struct fix *f, unsigned hook, struct fused_op *op)
{
    struct drag *d = f->data;
    if (d->update == UPD_TRAPEZOIDAL || (hook != HOOK_POST_FORCE && hook != HOOK_END_OF_STEP))
        return 0;
    check_origin(g, f);
    d->prm[0] = d->mu;
    d->prm[1] = d->flow;
    for (int q = 0; q < 3; q++)
        d->prm[2 + q] = d->p[q];
    d->prm[5] = d->update == UPD_EXACT;
    d->prm[6] = 0.5 * g->dt;
    op->prm = d->prm;
    if (d->update == UPD_EXPLICIT) {
        op->kind = FOP_DRAG_EXPLICIT;
        op->nprm = 5;
        return 1;
    }
    op->kind = hook == HOOK_POST_FORCE ? FOP_DRAG_KICK : FOP_DRAG_KICK_AGAIN;
    op->nprm = 7;
    op->store = 1;
    return 1;
}

const struct fix_style fix_style_drag = {
    .name = "drag",
    .create = create,
    .init = init,
    .post_force = post_force,
    .end_of_step = end_of_step,
    .fuse = fuse,
};

/* Scales of the flow for the Stokes number (used by pair_style cohesion's
 * run-setup report, styles/pair/pair_cohesion_numbers.c): viscosity, mean flow
 * speed (uniform: |u_f|; Taylor-Green: 0.7839 A, 000 sec. 6.1.2) and length
 * (Taylor-Green: vortex diameter pi / a; uniform: 0, none). */
int fix_drag_scales(const struct fix *f, double *mu, double *u0, double *l0)
{
    if (!f || strcmp(f->style->name, "drag"))
        return 0;
    const struct drag *d = f->data;
    *mu = d->mu;
    if (d->flow != FLOW_UNIFORM) {
        *u0 = 0.7839 * fabs(d->p[0]);
        *l0 = M_PI / d->p[1];
    } else {
        *u0 = sqrt(d->p[0] * d->p[0] + d->p[1] * d->p[1] + d->p[2] * d->p[2]);
        *l0 = 0;
    }
    return 1;
}
