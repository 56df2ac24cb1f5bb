/* fused.cl - per-particle fix work fused into the scene's kernels (host
 * side src/engine/fused.c). Instead of one launch per fix and hook, the run passes
 * each stage's list of operations, in fix order, to a kernel that already
 * visits every particle:
 *   initial_integrate ops  -> nbr_check (before the wrap and the check)
 *   post_force ops         -> pair_gather (after the contact sum)
 *   final_integrate ops    -> pair_gather (after the post_force ops)
 * An op is (kind, group bit, offset of its parameters in prm). Each op does
 * exactly the arithmetic of its fix's own kernel (fix_gravity.cl,
 * fix_freeze.cl, fix_viscous.cl, fix_nve.cl, fix_nve_sphere.cl; fix drag's
 * laws are shared with fix_drag.cl through drag_law.cl), so fused and
 * separate runs agree bit for bit. The end_of_step ops follow the
 * final_integrate ops in pair_gather. */

/* The ops (enum fused_kind) and their layout: kernels/fused_layout.h */

/* The state an op may read or change, held in registers by the kernel. */
struct fused_atom {
    REAL3 x, xl, v, f, om, tq;  /* xl: low part of x (SPLIT_POS, kernels/common.cl) */
    REAL m, r;
    int type;
    uint mask;
};

#ifdef FUSED_DRAG /* a fix drag in the scene (styles/fix/fix_drag.c): its ops */
/* fix drag's kicks (FOP_DRAG_KICK*), as kernels/fix_drag.cl drag_implicit:
 * store[2i] the drag D in the force, store[2i + 1] the flow at x_i; returns
 * the new force. Out of line and by value: the particle's state stays in
 * registers in the kernels that never call it. */
static __attribute__((noinline)) REAL3 fused_drag_kick(const REAL3 f, const REAL3 x,
                                                       const REAL3 v, const REAL m, const REAL r,
                                                       __global const REAL *p, const int again,
                                                       __global REAL *store, const int i)
{
    REAL3 uf, F = f;
    if (again) {
        uf = vload3(2 * i + 1, store);
        F -= vload3(2 * i, store);
    } else {
        uf = drag_flow(x, (int)p[1], p[2], p[3], p[4]);
        vstore3(uf, 2 * i + 1, store);
    }
    const REAL3 D = drag_half_kick(F, uf, v, m, r, p[0], (int)p[5], p[6]);
    vstore3(D, 2 * i, store);
    return F + D;
}

/* fix drag's explicit force (FOP_DRAG_EXPLICIT), out of line as above */
static __attribute__((noinline)) REAL3 fused_drag_explicit(const REAL3 f, const REAL3 x,
                                                           const REAL3 v, const REAL r,
                                                           __global const REAL *p)
{
    return drag_explicit_force(f, drag_flow(x, (int)p[1], p[2], p[3], p[4]), v, r, p[0]);
}
#endif

/* The ops [first, first + count) on particle i; store: the fused fix's
 * per-atom state (kernels/fused_layout.h), unused by other ops. */
/* always inlined: a call would move the particle's state through memory
 * for every particle; fix drag's ops are compiled only in scenes with the
 * fix (FUSED_DRAG), out of line, so other scenes keep their registers */
static inline __attribute__((always_inline)) void
fused_apply(struct fused_atom *a, __global const int *ops, const int first, const int count,
            __global const REAL *prm, __global REAL *store, const int i)
{
    for (int k = first; k < first + count; k++) {
        const int kind = ops[FOP_W * k + FOP_KIND];
        if (!(a->mask & (uint)ops[FOP_W * k + FOP_GROUP]))
            continue;
        __global const REAL *p = prm + ops[FOP_W * k + FOP_PRM];
        if (kind == FOP_GRAVITY) {
            const REAL m = a->m;
            a->f.x += m * p[0];
            a->f.y += m * p[1];
            a->f.z += m * p[2];
        } else if (kind == FOP_FREEZE) {
            a->f = (REAL3)(0);
            a->tq = (REAL3)(0);
        } else if (kind == FOP_VISCOUS) {
            a->f = a->f - p[a->type - 1] * a->v;
        } else if (kind == FOP_NVE_INITIAL || kind == FOP_NVE_SPHERE_INITIAL) {
            const REAL dtfm = p[1] / a->m;
            a->v += dtfm * a->f;
            pos_add(&a->x, &a->xl, p[0] * a->v);
#ifdef HAS_ROTATION
            if (kind == FOP_NVE_SPHERE_INITIAL) {
                const REAL dtirotate = p[2] / (a->r * a->r * a->m); /* p[2]: dtf / I */
                a->om = a->om + dtirotate * a->tq;
            }
#endif
        } else if (kind == FOP_NVE_FINAL || kind == FOP_NVE_SPHERE_FINAL) {
            const REAL dtfm = p[0] / a->m;
            a->v = a->v + dtfm * a->f;
#ifdef HAS_ROTATION
            if (kind == FOP_NVE_SPHERE_FINAL) {
                const REAL dtirotate = p[1] / (a->r * a->r * a->m); /* p[1]: dtf / I */
                a->om = a->om + dtirotate * a->tq;
            }
#endif
        }
#ifdef FUSED_DRAG
        else if (kind == FOP_DRAG_EXPLICIT) {
            a->f = fused_drag_explicit(a->f, a->x, a->v, a->r, p);
        } else if (kind == FOP_DRAG_KICK || kind == FOP_DRAG_KICK_AGAIN) {
            a->f = fused_drag_kick(a->f, a->x, a->v, a->m, a->r, p, kind == FOP_DRAG_KICK_AGAIN,
                                   store, i);
        }
#else
        (void)store;
        (void)i;
#endif
    }
}
