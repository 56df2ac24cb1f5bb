/* drag_law.cl - Stokes drag as pure functions (source document 000 eq.
 * 2.7-2.8, the Taylor-Green vortex of eq. 6.1-6.3), read by fix drag's own
 * kernels (kernels/fix_drag.cl) and by its fused ops (kernels/fused.cl), so
 * fused and separate runs agree bit for bit. In every program, before
 * fused.cl; static inline, free in scenes without drag. */

#ifdef USE_DOUBLE
/* sin and cos of x in double, for |x| < 2^19 pi/2 (the flow's arguments are
 * a few radians; else the built-in sincos): within an ulp of glibc's on 10^7
 * samples of [-14, 14] (near a zero, 1e-20 absolute: the end of pi/2's two
 * parts). Why: PoCL's double sincos is a general routine (a fifth of the
 * agglomeration deck's time, three calls per particle and step); this is the
 * classical one, x reduced by multiples n of pi/2 in two parts (n pi/2's
 * leading 33 bits exact), then the minimax polynomials of sin and cos on
 * [-pi/4, pi/4] (Sun's fdlibm coefficients). */
/* The reduction and the polynomials for values of type T (double, or lanes
 * of double: kernels/atom_lanes.cl): the quadrant n and the sine sn and
 * cosine cs of x - n pi/2, declared as const T. */
#define FLOW_SINCOS_CORE(T, x, n, sn, cs)                                                      \
    /* n = x / (pi/2) rounded to nearest (6755399441055744 = 1.5 2^52) */                     \
    const T n = ((x) * 6.36619772367581382433e-01 + 6755399441055744.0) - 6755399441055744.0; \
    const T r0_ = (x) - n * 1.57079632673412561417e+00;                                        \
    const T w_ = n * 6.07710050650619224932e-11;                                               \
    const T r_ = r0_ - w_;                                                                     \
    const T rt_ = (r0_ - r_) - w_; /* the reduction's tail */                                  \
    const T z_ = r_ * r_;                                                                      \
    const T ps_ = z_ * (8.33333333332248946124e-03 +                                           \
                        z_ * (-1.98412698298579493134e-04 +                                    \
                              z_ * (2.75573137070700676789e-06 +                               \
                                    z_ * (-2.50507602534068634195e-08 +                        \
                                          z_ * 1.58969099521155010221e-10))));                 \
    const T sn =                                                                               \
        r_ - ((z_ * (0.5 * rt_ - r_ * ps_) - rt_) - z_ * r_ * -1.66666666666666324348e-01);    \
    const T pc_ = z_ * z_ * (4.16666666666666019037e-02 +                                      \
                             z_ * (-1.38888888888741095749e-03 +                               \
                                   z_ * (2.48015872894767294178e-05 +                          \
                                         z_ * (-2.75573143513906633035e-07 +                   \
                                               z_ * (2.08757232129817482790e-09 +              \
                                                     z_ * -1.13596475577881948265e-11)))));    \
    const T hz_ = 0.5 * z_, wc_ = 1.0 - hz_;                                                   \
    const T cs = wc_ + (((1.0 - wc_) - hz_) + (pc_ - r_ * rt_));

static inline double flow_sincos(const double x, double *c)
{
    if (!(fabs(x) < 823549.6)) /* 2^19 pi/2 */
        return sincos(x, c);
    FLOW_SINCOS_CORE(double, x, n, sn, cs)
    switch ((int)n & 3) {
    case 0: *c = cs; return sn;
    case 1: *c = -sn; return cs;
    case 2: *c = -cs; return -sn;
    default: *c = sn; return -cs;
    }
}
#else
#define flow_sincos sincos
#endif

/* Fluid velocity at x. flow 0: (p0, p1, p2); flow 1: Taylor-Green with
 * amplitude A = p0 and wave number a = p1:
 *   u =   A cos(a X) sin(a Y) sin(a Z)
 *   v =   A sin(a X) cos(a Y) sin(a Z)      X = x + pi/(2a), ...
 *   w = -2A sin(a X) sin(a Y) cos(a Z)
 * flow 2: the same with w = -2A cos(a X) sin(a Y) cos(a Z), as source 000's
 * own code has it (DEMOranges kernels/get_vel_fluid/tgv.cl; compressible).
 * TGV_FLOW: the three components from the sines and cosines, for REAL or
 * lanes (kernels/atom_lanes.cl). */
#define TGV_FLOW(flow, A, sx, cx, sy, cy, sz, cz, u, v, w)                                     \
    {                                                                                          \
        u = (A) * (cx) * (sy) * (sz);                                                          \
        v = (A) * (sx) * (cy) * (sz);                                                          \
        w = (REAL)-2 * (A) * ((flow) == 2 ? (cx) : (sx)) * (sy) * (cz);                        \
    }
static inline REAL3 drag_flow(const REAL3 x, const int flow, const REAL p0, const REAL p1,
                              const REAL p2)
{
    if (flow == 0)
        return (REAL3)(p0, p1, p2);
    const REAL sh = (REAL)M_PI_2 / p1;
    const REAL X = p1 * (x.x + sh), Y = p1 * (x.y + sh), Z = p1 * (x.z + sh);
    REAL cx, cy, cz;
    const REAL sx = flow_sincos(X, &cx), sy = flow_sincos(Y, &cy), sz = flow_sincos(Z, &cz);
    REAL3 u;
    TGV_FLOW(flow, p0, sx, cx, sy, cy, sz, cz, u.x, u.y, u.z)
    return u;
}

/* the drag coefficient beta = 3 pi mu d = 6 pi mu r (REAL or lanes) */
#define DRAG_BETA(mu, r) ((REAL)6 * (REAL)M_PI * (mu) * (r))

/* update explicit: the force f plus the drag beta (u_f - v) */
static inline REAL3 drag_explicit_force(const REAL3 f, const REAL3 uf, const REAL3 v,
                                        const REAL r, const REAL mu)
{
    const REAL beta = DRAG_BETA(mu, r);
    return f + beta * (uf - v);
}

/* update implicit / exact: the effective drag D of one half kick of length
 * h under the other forces F (held fixed over the kick), so that the kick
 * v += h (F + D)/m lands on the backward-Euler (exact: the exponential)
 * velocity of dv/dt = F/m + (u_f - v)/tau, tau = m / (3 pi mu d):
 * DRAG_KICK_FACTOR the factor k of dv = (target - v) k (implicit), and
 * DRAG_KICK_D one component of D, target = u_f + (tau / m) F the steady
 * state under fixed F (REAL or lanes). */
#define DRAG_KICK_FACTOR(h, tau) ((h) / ((tau) + (h)))
#define DRAG_KICK_D(F, uf, v, tm, k, mh) ((mh) * ((((uf) + (tm) * (F)) - (v)) * (k)) - (F))
static inline REAL3 drag_half_kick(const REAL3 F, const REAL3 uf, const REAL3 v, const REAL m,
                                   const REAL r, const REAL mu, const int exact, const REAL h)
{
    const REAL tau = m / DRAG_BETA(mu, r);
    const REAL k = exact ? -expm1(-h / tau) : DRAG_KICK_FACTOR(h, tau);
    const REAL tm = tau / m, mh = m / h;
    return (REAL3)(DRAG_KICK_D(F.x, uf.x, v.x, tm, k, mh), DRAG_KICK_D(F.y, uf.y, v.y, tm, k, mh),
                   DRAG_KICK_D(F.z, uf.z, v.z, tm, k, mh));
}
