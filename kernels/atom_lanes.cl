/* atom_lanes.cl - pair_gather and fused_tail in lanes (ATOM_LW > 1; the
 * one-particle forms are kernels/pair_loop.cl's). Work-item g takes the
 * ATOM_LW particles ATOM_LW g .. ATOM_LW g + ATOM_LW - 1: each one's contact
 * sums as the one-particle form takes them (gather_sums, in row order),
 * then the fused post_force, final_integrate and end_of_step ops
 * (kernels/fused.cl) and, with look, the next step's opening
 * (kernels/atom_step.cl) in lane arithmetic: an op runs on every lane and
 * a select keeps its result where the particle is in the op's group; a
 * branch becomes both arms and a select. Every operation is the
 * one-particle form's, in its order (FP_CONTRACT is off), so the results
 * are bit-identical to ATOM_LW = 1 (tests/scripts/determinism.py). A last,
 * partial group runs the one-particle form.
 *
 * The host takes this form only for a scene it covers (src/engine/engine.c,
 * atom_lanes): no velocity remap or triclinic box. */

#if defined(ATOM_LW) && ATOM_LW > 1
#if defined(VREMAP) || defined(TRICLINIC)
#error "atom_lanes.cl: a scene the lane form does not cover (src/engine/engine.c)"
#endif

typedef LANE_CAT(REAL, ATOM_LW) areal;
typedef LANE_CAT(int, ATOM_LW) aint;
typedef LANE_CAT(uint, ATOM_LW) auint;
#ifdef USE_DOUBLE
typedef LANE_CAT(long, ATOM_LW) amask;             /* a comparison of two areal */
#define AMASK(m) LANE_CAT(convert_long, ATOM_LW)(m) /* an aint comparison as an amask */
#define AINT(m) LANE_CAT(convert_int, ATOM_LW)(m)   /* an amask as an aint comparison */
#else
typedef aint amask;
#define AMASK(m) (m)
#define AINT(m) (m)
#endif
#define AL(F) ((areal)LANE_CAT(LANES_, ATOM_LW)(F))
#define ALOAD(p, i0) LANE_CAT(vload, ATOM_LW)(0, (p) + (i0))
#define ALANES_DO(F) LANE_CAT(LANES_, ATOM_LW)(F) /* F(0), .., F(ATOM_LW - 1) */
/* the statement S(l) for each lane l */
#if ATOM_LW == 2
#define ALANES_EACH(S) S(0) S(1)
#elif ATOM_LW == 4
#define ALANES_EACH(S) S(0) S(1) S(2) S(3)
#elif ATOM_LW == 8
#define ALANES_EACH(S) S(0) S(1) S(2) S(3) S(4) S(5) S(6) S(7)
#else
#define ALANES_EACH(S)                                                                         \
    S(0) S(1) S(2) S(3) S(4) S(5) S(6) S(7) S(8) S(9) S(10) S(11) S(12) S(13) S(14) S(15)
#endif

/* three lanes: a 3-vector of each of the ATOM_LW particles */
struct a3 {
    areal x, y, z;
};

static inline struct a3 a3_sel(const struct a3 a, const struct a3 b, const amask m)
{
    struct a3 r;
    r.x = select(a.x, b.x, m);
    r.y = select(a.y, b.y, m);
    r.z = select(a.z, b.z, m);
    return r;
}

/* particles i0 .. i0 + ATOM_LW - 1 of an array of w REAL per particle,
 * their 3-vector at offset off */
static inline struct a3 a3_load_w(__global const REAL *p, const int i0, const int w,
                                  const int off)
{
    __global const REAL *q = p + (size_t)w * i0 + off;
#define A3X(l) q[w * (l)]
#define A3Y(l) q[w * (l) + 1]
#define A3Z(l) q[w * (l) + 2]
    struct a3 r;
    r.x = AL(A3X);
    r.y = AL(A3Y);
    r.z = AL(A3Z);
    return r;
#undef A3X
#undef A3Y
#undef A3Z
}

/* ... of a 3-REAL array */
static inline struct a3 a3_load(__global const REAL *p, const int i0)
{
    return a3_load_w(p, i0, 3, 0);
}

/* (lanes are read by subscript, a constant one once ALANES_DO expanded it) */
static inline void a3_store_lane(const struct a3 a, const int l, __global REAL *p, const int i)
{
    vstore3((REAL3)(a.x[l], a.y[l], a.z[l]), i, p);
}

static inline void a3_store(const struct a3 a, __global REAL *p, const int i0)
{
#define A3_STORE(l) a3_store_lane(a, l, p, i0 + l)
    ALANES_DO(A3_STORE);
#undef A3_STORE
}

/* pos_add1 (kernels/common.cl) of each lane */
static inline void apos_add1(areal *hi, areal *lo, const areal d)
{
#ifdef SPLIT_POS
    POS_TWOSUM(areal, hi, lo, d)
#else
    (void)lo;
    *hi = *hi + d;
#endif
}

/* pbc_wrap (kernels/common.cl) of each lane: both arms, then selects */
static inline void apbc_wrap(areal *h, areal *l, aint *im, const REAL lo, const REAL hi,
                             const REAL L)
{
    const amask below = *h + *l < (areal)lo;
    areal h1 = *h, l1 = *l;
    apos_add1(&h1, &l1, (areal)L);
    *h = select(*h, h1, below);
    *l = select(*l, l1, below);
    *im = *im + AINT(below); /* -1 where true: the decrement */
    const amask above = *h + *l >= (areal)hi;
    areal h2 = *h, l2 = *l;
    apos_add1(&h2, &l2, (areal)-L);
    const amask under = h2 + l2 < (areal)lo; /* rounding: stay inside */
    h2 = select(h2, (areal)lo, under);
    l2 = select(l2, (areal)0, under);
    *h = select(*h, h2, above);
    *l = select(*l, l2, above);
    *im = *im - AINT(above);
}

#ifdef PERIODIC_X
#define AMINIMG_X(d, L) LANE_MIN_IMAGE(areal, d, L)
#else
#define AMINIMG_X(d, L) (d)
#endif
#ifdef PERIODIC_Y
#define AMINIMG_Y(d, L) LANE_MIN_IMAGE(areal, d, L)
#else
#define AMINIMG_Y(d, L) (d)
#endif
#ifdef PERIODIC_Z
#define AMINIMG_Z(d, L) LANE_MIN_IMAGE(areal, d, L)
#else
#define AMINIMG_Z(d, L) (d)
#endif

/* struct fused_atom (kernels/fused.cl) in lanes */
struct atom_lanes {
    struct a3 x, xl, v, f, om, tq;
    areal m, r;
    __global const int *type; /* of the first particle */
    auint mask;
};

#ifdef HAS_ROTATION
/* nve/sphere's rotational kick omega += dtirotate torque, kept where on */
static inline void aomega_kick(struct atom_lanes *a, const areal dtirotate, const amask on)
{
    a->om.x = select(a->om.x, a->om.x + dtirotate * a->tq.x, on);
    a->om.y = select(a->om.y, a->om.y + dtirotate * a->tq.y, on);
    a->om.z = select(a->om.z, a->om.z + dtirotate * a->tq.z, on);
}
#endif

#ifdef FUSED_DRAG /* fix drag's ops in lanes: kernels/drag_law.cl's arithmetic */
/* flow_sincos of each lane; in single precision (the built-in sincos) and
 * with a lane out of its range, the one-value form lane by lane */
static inline areal aflow_sincos(const areal x, areal *c)
{
#ifdef USE_DOUBLE
    if (all(fabs(x) < (areal)823549.6)) {
        FLOW_SINCOS_CORE(areal, x, n, sn, cs)
        const amask q = LANE_CAT(convert_long, ATOM_LW)(n) & 3; /* (int)n & 3 */
        const amask q0 = q == 0, q1 = q == 1, q2 = q == 2;
        *c = select(select(select(sn, -cs, q2), -sn, q1), cs, q0);
        return select(select(select(-cs, -sn, q2), cs, q1), sn, q0);
    }
#endif
    areal s;
#define A_SINCOS(l)                                                                            \
    {                                                                                          \
        REAL c_;                                                                               \
        s[l] = flow_sincos(x[l], &c_);                                                         \
        (*c)[l] = c_;                                                                          \
    }
    ALANES_EACH(A_SINCOS)
#undef A_SINCOS
    return s;
}

/* drag_flow of each lane */
static inline struct a3 adrag_flow(const struct a3 x, const int flow, const REAL p0,
                                   const REAL p1, const REAL p2)
{
    struct a3 u;
    if (flow == 0) {
        u.x = (areal)p0;
        u.y = (areal)p1;
        u.z = (areal)p2;
        return u;
    }
    const REAL sh = (REAL)M_PI_2 / p1;
    const areal X = p1 * (x.x + sh), Y = p1 * (x.y + sh), Z = p1 * (x.z + sh);
    areal cx, cy, cz;
    const areal sx = aflow_sincos(X, &cx), sy = aflow_sincos(Y, &cy), sz = aflow_sincos(Z, &cz);
    TGV_FLOW(flow, p0, sx, cx, sy, cy, sz, cz, u.x, u.y, u.z)
    return u;
}

/* fused_drag_kick (kernels/fused.cl) of each lane: the new force; the
 * store (D, then u_f, 6 REAL per particle) written where on */
static inline struct a3 adrag_kick(const struct atom_lanes *a, __global const REAL *p,
                                   const int again, __global REAL *store, const int i0,
                                   const amask on)
{
    struct a3 uf, F = a->f;
    if (again) {
        uf = a3_load_w(store, i0, 6, 3);
        const struct a3 d0 = a3_load_w(store, i0, 6, 0);
        F.x = F.x - d0.x;
        F.y = F.y - d0.y;
        F.z = F.z - d0.z;
    } else {
        uf = adrag_flow(a->x, (int)p[1], p[2], p[3], p[4]);
#define A_STORE_UF(l) (on[l] ? a3_store_lane(uf, l, store + 6 * (size_t)(i0 + l) + 3, 0) : (void)0)
        ALANES_DO(A_STORE_UF);
#undef A_STORE_UF
    }
    const REAL h = p[6];
    const areal tau = a->m / DRAG_BETA(p[0], a->r);
    areal k = DRAG_KICK_FACTOR(h, tau);
    if ((int)p[5]) { /* exact: the built-in expm1 lane by lane */
#define A_EXPM1(l) k[l] = -expm1(-h / tau[l]);
        ALANES_EACH(A_EXPM1)
#undef A_EXPM1
    }
    const areal tm = tau / a->m, mh = a->m / h;
    struct a3 D;
    D.x = DRAG_KICK_D(F.x, uf.x, a->v.x, tm, k, mh);
    D.y = DRAG_KICK_D(F.y, uf.y, a->v.y, tm, k, mh);
    D.z = DRAG_KICK_D(F.z, uf.z, a->v.z, tm, k, mh);
#define A_STORE_D(l) (on[l] ? a3_store_lane(D, l, store + 6 * (size_t)(i0 + l), 0) : (void)0)
    ALANES_DO(A_STORE_D);
#undef A_STORE_D
    F.x = F.x + D.x;
    F.y = F.y + D.y;
    F.z = F.z + D.z;
    return F;
}
#endif

/* fused_apply (kernels/fused.cl) in lanes: each op's arithmetic on every
 * lane, kept where the particle is in the op's group; store: fix drag's
 * per-particle state (FUSED_DRAG) */
static inline __attribute__((always_inline)) void
alanes_apply(struct atom_lanes *a, __global const int *ops, const int first, const int count,
             __global const REAL *prm, __global REAL *store, const int i0)
{
    for (int k = first; k < first + count; k++) {
        const int kind = ops[FOP_W * k + FOP_KIND];
        const amask on = AMASK((a->mask & (auint)(uint)ops[FOP_W * k + FOP_GROUP]) != (auint)0);
        if (!any(on))
            continue;
        __global const REAL *p = prm + ops[FOP_W * k + FOP_PRM];
        if (kind == FOP_GRAVITY) {
            const areal m = a->m;
            a->f.x = select(a->f.x, a->f.x + m * p[0], on);
            a->f.y = select(a->f.y, a->f.y + m * p[1], on);
            a->f.z = select(a->f.z, a->f.z + m * p[2], on);
        } else if (kind == FOP_FREEZE) {
            const struct a3 zero = {(areal)0, (areal)0, (areal)0};
            a->f = a3_sel(a->f, zero, on);
            a->tq = a3_sel(a->tq, zero, on);
        } else if (kind == FOP_VISCOUS) {
#define AGAMMA(l) p[a->type[l] - 1]
            const areal g = AL(AGAMMA);
#undef AGAMMA
            a->f.x = select(a->f.x, a->f.x - g * a->v.x, on);
            a->f.y = select(a->f.y, a->f.y - g * a->v.y, on);
            a->f.z = select(a->f.z, a->f.z - g * a->v.z, on);
        } else if (kind == FOP_NVE_INITIAL || kind == FOP_NVE_SPHERE_INITIAL) {
            const areal dtfm = p[1] / a->m;
            struct a3 v, x = a->x, xl = a->xl;
            v.x = a->v.x + dtfm * a->f.x;
            v.y = a->v.y + dtfm * a->f.y;
            v.z = a->v.z + dtfm * a->f.z;
            apos_add1(&x.x, &xl.x, p[0] * v.x);
            apos_add1(&x.y, &xl.y, p[0] * v.y);
            apos_add1(&x.z, &xl.z, p[0] * v.z);
            a->v = a3_sel(a->v, v, on);
            a->x = a3_sel(a->x, x, on);
            a->xl = a3_sel(a->xl, xl, on);
#ifdef HAS_ROTATION
            if (kind == FOP_NVE_SPHERE_INITIAL) {
                aomega_kick(a, p[2] / (a->r * a->r * a->m), on); /* p[2]: dtf / I */
            }
#endif
        } else if (kind == FOP_NVE_FINAL || kind == FOP_NVE_SPHERE_FINAL) {
            const areal dtfm = p[0] / a->m;
            a->v.x = select(a->v.x, a->v.x + dtfm * a->f.x, on);
            a->v.y = select(a->v.y, a->v.y + dtfm * a->f.y, on);
            a->v.z = select(a->v.z, a->v.z + dtfm * a->f.z, on);
#ifdef HAS_ROTATION
            if (kind == FOP_NVE_SPHERE_FINAL) {
                aomega_kick(a, p[1] / (a->r * a->r * a->m), on); /* p[1]: dtf / I */
            }
#endif
        }
#ifdef FUSED_DRAG
        else if (kind == FOP_DRAG_EXPLICIT) { /* drag_explicit_force */
            const struct a3 uf = adrag_flow(a->x, (int)p[1], p[2], p[3], p[4]);
            const areal beta = DRAG_BETA(p[0], a->r);
            a->f.x = select(a->f.x, a->f.x + beta * (uf.x - a->v.x), on);
            a->f.y = select(a->f.y, a->f.y + beta * (uf.y - a->v.y), on);
            a->f.z = select(a->f.z, a->f.z + beta * (uf.z - a->v.z), on);
        } else if (kind == FOP_DRAG_KICK || kind == FOP_DRAG_KICK_AGAIN) {
            a->f = a3_sel(a->f, adrag_kick(a, p, kind == FOP_DRAG_KICK_AGAIN, store, i0, on), on);
        }
#else
        (void)store;
        (void)i0;
#endif
    }
}

/* atom_step (kernels/atom_step.cl) in lanes, for particles i0 .. */
static inline __attribute__((always_inline)) void
alanes_step(const int i0, struct atom_lanes *at, KA_PARAMS(atom_step), __global REAL *v,
            __global REAL *omega, __global const int *ops, __global const REAL *prm POS_LO_PARAM)
{
    if (ninit > 0) {
        /* no initial op keeps a store */
        alanes_apply(at, ops, 0, ninit, prm, (__global REAL *)0, i0);
        a3_store(at->x, x, i0);
#ifdef SPLIT_POS
        a3_store(at->xl, xlo, i0);
#endif
        a3_store(at->v, v, i0);
#ifdef HAS_ROTATION
        a3_store(at->om, omega, i0);
#else
        (void)omega;
#endif
    }
    struct a3 xi = at->x, xl = at->xl;
    const struct a3 vi = at->v;
#if defined(PERIODIC_X) || defined(PERIODIC_Y) || defined(PERIODIC_Z)
    __global const int *im0p = image + 3 * (size_t)i0;
#define AIMX(l) im0p[3 * (l)]
#define AIMY(l) im0p[3 * (l) + 1]
#define AIMZ(l) im0p[3 * (l) + 2]
    const aint imx0 = (aint)LANE_CAT(LANES_, ATOM_LW)(AIMX);
    const aint imy0 = (aint)LANE_CAT(LANES_, ATOM_LW)(AIMY);
    const aint imz0 = (aint)LANE_CAT(LANES_, ATOM_LW)(AIMZ);
#undef AIMX
#undef AIMY
#undef AIMZ
    aint imx = imx0, imy = imy0, imz = imz0;
#ifdef PERIODIC_X
    apbc_wrap(&xi.x, &xl.x, &imx, lox, hix, Lx);
#endif
#ifdef PERIODIC_Y
    apbc_wrap(&xi.y, &xl.y, &imy, loy, hiy, Ly);
#endif
#ifdef PERIODIC_Z
    apbc_wrap(&xi.z, &xl.z, &imz, loz, hiz, Lz);
#endif
    const aint moved = (imx != imx0) | (imy != imy0) | (imz != imz0);
    if (any(moved)) {
#ifdef SPLIT_POS
#define A_WRAPPED_LO(l) a3_store_lane(xl, l, xlo, i0 + l)
#else
#define A_WRAPPED_LO(l) (void)0
#endif
#define A_WRAPPED(l)                                                                           \
    (moved[l] ? (a3_store_lane(xi, l, x, i0 + l), A_WRAPPED_LO(l),                             \
                 vstore3((int3)(imx[l], imy[l], imz[l]), i0 + l, image))                       \
              : (void)0)
        ALANES_DO(A_WRAPPED);
#undef A_WRAPPED
#undef A_WRAPPED_LO
    }
#else
    (void)image;
    (void)lox;
    (void)loy;
    (void)loz;
    (void)hix;
    (void)hiy;
    (void)hiz;
#endif
    (void)hrate;
    (void)vgroup;
    (void)xy;
    (void)xz;
    (void)yz;
    const struct a3 h = a3_load(xhold, i0);
    const areal dx = AMINIMG_X(xi.x - h.x, Lx), dy = AMINIMG_Y(xi.y - h.y, Ly);
    const areal dz = AMINIMG_Z(xi.z - h.z, Lz);
    const areal rsq = dx * dx + dy * dy + dz * dz;
    if (any(rsq > (areal)trigsq))
        atomic_max(&flags[0], stamp);
    /* x - x is 0 for a finite x and NaN otherwise: one test for the six */
    const areal z = (xi.x - xi.x) + (xi.y - xi.y) + (xi.z - xi.z) + (vi.x - vi.x) +
                    (vi.y - vi.y) + (vi.z - vi.z);
    const amask bad = z != (areal)0;
    if (any(bad)) { /* the lowest such index: atomic_min of each */
        atomic_max(&flags[0], stamp); /* as atom_step.cl */
        const aint badi = AINT(bad);
#define A_BAD(l) (badi[l] ? (void)atomic_min(&flags[1], i0 + l) : (void)0)
        ALANES_DO(A_BAD);
#undef A_BAD
    }
}

/* gather_atom (kernels/pair_loop.cl) for the particles of work-item g */
static inline __attribute__((always_inline)) void gather_lanes(KA_PARAMS(pair_gather),
                                                               const int tail)
{
    const int i0 = (int)get_global_id(0) * ATOM_LW;
    if (i0 >= n)
        return;
    if (i0 + ATOM_LW > n) { /* the last, partial group */
        for (int i = i0; i < n; i++)
            gather_atom(KA_ARGS(pair_gather), tail, i);
        return;
    }
    struct atom_lanes at;
    const struct a3 zero = {(areal)0, (areal)0, (areal)0};
    at.f = at.tq = zero;
    /* each particle's sums into its lane, then, with nothing to apply, out */
#define A_SUMS(l)                                                                              \
    {                                                                                          \
        REAL3 fs_, ts_;                                                                        \
        gather_sums(i0 + l, tail, ioff, coff, pcon, quiet, rec, zidx, f, torque, radius, recq, \
                    heatflow, &fs_, &ts_);                                                     \
        at.f.x[l] = fs_.x;                                                                     \
        at.f.y[l] = fs_.y;                                                                     \
        at.f.z[l] = fs_.z;                                                                     \
        at.tq.x[l] = ts_.x;                                                                    \
        at.tq.y[l] = ts_.y;                                                                    \
        at.tq.z[l] = ts_.z;                                                                    \
    }
    ALANES_EACH(A_SUMS)
#undef A_SUMS
    if (npost + nfinal == 0 && !look) {
        a3_store(at.f, f, i0);
#ifdef HAS_ROTATION
        a3_store(at.tq, torque, i0);
#endif
        return;
    }
    at.x = at.xl = at.om = zero;
    at.v = a3_load(v, i0);
#ifdef HAS_ROTATION
    at.om = a3_load(omega, i0);
#endif
    at.m = ALOAD(rmass, i0);
    at.r = ALOAD(radius, i0);
    at.type = type + i0;
    at.mask = ALOAD(mask, i0);
#ifdef FUSED_DRAG /* fix drag's ops read the position */
    at.x = a3_load(x, i0);
#ifdef SPLIT_POS
    at.xl = a3_load(xlo, i0);
#endif
#endif
    alanes_apply(&at, ops, first, npost + nfinal, prm, store, i0);
    if (look) { /* alanes_step stores v and omega after its own ops */
#ifndef FUSED_DRAG
        at.x = a3_load(x, i0);
#ifdef SPLIT_POS
        at.xl = a3_load(xlo, i0);
#endif
#endif
        if (ninit == 0 && nfinal > 0) {
            a3_store(at.v, v, i0);
#ifdef HAS_ROTATION
            a3_store(at.om, omega, i0);
#endif
        }
        alanes_step(i0, &at, KA_ARGS(atom_step), v, omega, ops, prm POS_LO_ARG);
    } else if (nfinal > 0) {
        a3_store(at.v, v, i0);
#ifdef HAS_ROTATION
        a3_store(at.om, omega, i0);
#endif
    }
    a3_store(at.f, f, i0);
#ifdef HAS_ROTATION
    a3_store(at.tq, torque, i0);
#endif
}

/* arguments: KARGS_pair_gather (kernels/kernel_args.h) */
__kernel void pair_gather(KA_KERNEL(pair_gather))
{
    KA_UNPACK(pair_gather);
    if (KA_HALTED())
        return;
    gather_lanes(KA_ARGS(pair_gather), 0);
}

/* pair_loop.cl's fused_tail in lanes */
__kernel void fused_tail(KA_KERNEL(pair_gather))
{
    KA_UNPACK(pair_gather);
    if (KA_HALTED())
        return;
    gather_lanes(KA_ARGS(pair_gather), 1);
}
#endif /* ATOM_LW > 1 */
