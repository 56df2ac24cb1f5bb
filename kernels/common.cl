/* common.cl - types shared by every kernel.
 *
 * Build options (set by the engine): REAL=float|double (with USE_DOUBLE for
 * double), HAS_ROTATION (omega/torque arrays exist), HAS_HISTORY (per-contact
 * shear history, HIST_N REAL per contact, 3 unless set), PAIR_EVAL=<ident>_eval
 * (the active pair evaluator).
 * Contraction of a*b+c into fma is switched off so that results match the
 * host compilers LAMMPS is built with and the pair terms stay exactly
 * antisymmetric. PERIODIC_X/Y/Z mark periodic dimensions: the minimum-image
 * correction is compiled only for those (MINIMG_X/Y/Z). SPLIT_POS (single
 * precision): positions are split into two arrays, see "Positions" below. */
#ifndef REAL
#define REAL double
#define USE_DOUBLE 1
#endif
#if defined(USE_DOUBLE) || defined(HAS_FP64)
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif
#pragma OPENCL FP_CONTRACT OFF

/* REALs of contact history per contact (pair granular sets more) */
#ifndef HIST_N
#define HIST_N 3
#endif
/* the slots a separated pair clears: all but a trailing HIST_OWNER slot
 * (-compat lammps2021, kernels/neighbor.cl) */
#ifndef HIST_ZERO_N
#define HIST_ZERO_N HIST_N
#endif

#define REAL3 CAT3(REAL)
#define CAT3(t) CAT3_(t)
#define CAT3_(t) t##3

/* One contact between particle i and particle (or wall) j, as the pair
 * evaluators see it. Sign convention: del = x_i - x_j, vr = v_i - v_j. */
struct contact {
    REAL3 del;          /* x_i - x_j (minimum image) */
    REAL rsq;           /* |del|^2 */
    REAL r;             /* |del| */
    REAL delta;         /* overlap radsum - r (the laws read r and delta from here:
                         * with SPLIT_POS contact_refine computes them from the
                         * split positions) */
    REAL radi, radj;    /* radii (radj = 0 for a flat wall) */
    REAL radsum;        /* radi + radj */
    REAL reff;          /* radi radj / radsum (radi for a wall) */
    REAL3 vr;           /* v_i - v_j */
    REAL3 omi, omj;     /* angular velocities (omj = 0 for a wall) */
    REAL meff;          /* effective mass (LAMMPS: frozen partner -> other mass) */
    REAL dt;            /* time step */
    int shearupdate;    /* 0 during setup: history is not advanced */
    int approach;       /* 1: the caller also evaluates pairs apart that one
                         * drift at their normal rate brings into or out of
                         * contact (PAIR_APPROACH, contact_normal_linear) */
};

/* What an evaluator returns for one contact: the force on i (the force on j
 * is exactly -f) and the torques in two parts, a lever-arm part tc and an
 * antisymmetric part tr (rolling resistance; zero for most laws):
 *   torque on i = -radi tc - tr,   torque on j = -radj tc + tr
 * (LAMMPS' newton-pair update, bit for bit what j's own evaluation of the
 * reversed contact gives). */
struct contact_force {
    REAL3 f;
    REAL3 tc, tr;
};

static inline REAL3 contact_torque_i(const struct contact *c, const struct contact_force *o)
{
    return -c->radi * o->tc - o->tr;
}

/* The one way a contact is built, for a particle partner (pair_loop.cl) and
 * for a wall element (wall.cl, radj = 0, omj = 0): geometry and relative
 * motion at the contact; dt and shearupdate are set by the caller. */
static inline struct contact contact_make(const REAL3 del, const REAL radi, const REAL radj,
                                          const REAL reff, const REAL3 vr, const REAL3 omi,
                                          const REAL3 omj, const REAL meff)
{
    struct contact c;
    c.del = del;
    c.rsq = del.x * del.x + del.y * del.y + del.z * del.z;
    c.radi = radi;
    c.radj = radj;
    c.radsum = radi + radj;
    c.r = sqrt(c.rsq);
    c.delta = c.radsum - c.r;
    c.reff = reff;
    c.vr = vr;
    c.omi = omi;
    c.omj = omj;
    c.meff = meff;
    c.approach = 0;
    return c;
}

/* Minimum image of one component for a periodic length L (0 = not periodic). */
static inline REAL min_image(REAL d, REAL L)
{
    if (L > (REAL)0) {
        if (d > (REAL)0.5 * L)
            d -= L;
        else if (d < (REAL)-0.5 * L)
            d += L;
    }
    return d;
}

#ifdef PERIODIC_X
#define MINIMG_X(d, L) min_image(d, L)
#else
#define MINIMG_X(d, L) (d)
#endif
#ifdef PERIODIC_Y
#define MINIMG_Y(d, L) min_image(d, L)
#else
#define MINIMG_Y(d, L) (d)
#endif
#ifdef PERIODIC_Z
#define MINIMG_Z(d, L) min_image(d, L)
#else
#define MINIMG_Z(d, L) (d)
#endif

/* Positions. With SPLIT_POS (every single-precision run) a coordinate is the
 * unevaluated sum hi + lo of two floats, hi in x and lo in xlo (the kernel's
 * last argument, POS_LO_PARAM), relative to the run's origin (the box centre,
 * src/engine.c): 48 significant bits, so a drift below half the float spacing
 * still moves the particle and a contact's separation is resolved as in
 * double. Drifts go through pos_add, contact separations and overlaps through
 * contact_refine (below) from the hi and lo differences; binning and the
 * rebuild test read hi alone (off by at most one float
 * spacing of a box-relative coordinate). Without SPLIT_POS there is one array
 * and these reduce to the plain arithmetic. */
#ifdef SPLIT_POS
#define POS_LO_PARAM , __global REAL *xlo
#define POS_LOAD_LO(i) vload3(i, xlo)
#define POS_STORE_LO(val, i) vstore3(val, i, xlo)
/* hi + lo += d, renormalised (TwoSum, then Fast2Sum): exact to the last bit of lo */
static inline void pos_add1(REAL *hi, REAL *lo, const REAL d)
{
    const REAL s = *hi + d, bb = s - *hi;
    const REAL t = ((*hi - (s - bb)) + (d - bb)) + *lo;
    *hi = s + t;
    *lo = t - (*hi - s);
}
static inline void pos_add(REAL3 *hi, REAL3 *lo, const REAL3 d)
{
    const REAL3 s = *hi + d, bb = s - *hi;
    const REAL3 t = ((*hi - (s - bb)) + (d - bb)) + *lo;
    *hi = s + t;
    *lo = t - (*hi - s);
}
#else
#define POS_LO_PARAM
#define POS_LOAD_LO(i) ((REAL3)(0))
#define POS_STORE_LO(val, i) ((void)0)
static inline void pos_add1(REAL *hi, REAL *lo, const REAL d)
{
    (void)lo;
    *hi += d;
}
static inline void pos_add(REAL3 *hi, REAL3 *lo, const REAL3 d)
{
    (void)lo;
    *hi = *hi + d;
}
#endif

/* Periodic wrap of one coordinate (hi h, lo l) into [lo, hi) of period L,
 * one period at most (LAMMPS Domain::pbc); the image flag follows. */
static inline void pbc_wrap(REAL *h, REAL *l, int *im, const REAL lo, const REAL hi,
                            const REAL L)
{
    if (*h + *l < lo) {
        pos_add1(h, l, L);
        (*im)--;
    }
    if (*h + *l >= hi) {
        pos_add1(h, l, -L);
        if (*h + *l < lo) { /* rounding: stay inside */
            *h = lo;
            *l = 0;
        }
        (*im)++;
    }
}

/* The separation and overlap of contact c from the split parts: del_lo is
 * the low part of x_i - x_j (SPLIT_POS). With double support they are
 * evaluated in double ((radi + radj) - |del + del_lo|), so an overlap far
 * below a float spacing of the radius keeps its digits; else in REAL.
 * Returns 0 when the refined overlap is not positive (no contact). */
static inline int contact_refine(struct contact *c, const REAL3 del_lo)
{
#ifdef SPLIT_POS
#ifdef HAS_FP64
    const double dx = (double)c->del.x + (double)del_lo.x;
    const double dy = (double)c->del.y + (double)del_lo.y;
    const double dz = (double)c->del.z + (double)del_lo.z;
    const double r = sqrt(dx * dx + dy * dy + dz * dz);
    c->r = (REAL)r;
    c->delta = (REAL)(((double)c->radi + (double)c->radj) - r);
#else
    const REAL3 d = c->del + del_lo;
    c->r = sqrt(dot(d, d));
    c->delta = c->radsum - c->r;
#endif
    c->del = c->del + del_lo;
    c->rsq = c->r * c->r;
    return c->delta > (REAL)0;
#else
    (void)c;
    (void)del_lo;
    return 1;
#endif
}
