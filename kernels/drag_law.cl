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
static inline double flow_sincos(const double x, double *c)
{
    if (!(fabs(x) < 823549.6)) /* 2^19 pi/2 */
        return sincos(x, c);
    /* n = x / (pi/2) rounded to nearest (6755399441055744 = 1.5 2^52) */
    const double n = (x * 6.36619772367581382433e-01 + 6755399441055744.0) - 6755399441055744.0;
    const double r0 = x - n * 1.57079632673412561417e+00;
    const double w = n * 6.07710050650619224932e-11;
    const double r = r0 - w;
    const double rt = (r0 - r) - w; /* the reduction's tail */
    const double z = r * r;
    const double ps = z * (8.33333333332248946124e-03 +
                           z * (-1.98412698298579493134e-04 +
                                z * (2.75573137070700676789e-06 +
                                     z * (-2.50507602534068634195e-08 +
                                          z * 1.58969099521155010221e-10))));
    const double sn = r - ((z * (0.5 * rt - r * ps) - rt) - z * r * -1.66666666666666324348e-01);
    const double pc = z * z * (4.16666666666666019037e-02 +
                               z * (-1.38888888888741095749e-03 +
                                    z * (2.48015872894767294178e-05 +
                                         z * (-2.75573143513906633035e-07 +
                                              z * (2.08757232129817482790e-09 +
                                                   z * -1.13596475577881948265e-11)))));
    const double hz = 0.5 * z, wc = 1.0 - hz;
    const double cs = wc + (((1.0 - wc) - hz) + (pc - r * rt));
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
 * own code has it (DEMOranges kernels/get_vel_fluid/tgv.cl; compressible). */
static inline REAL3 drag_flow(const REAL3 x, const int flow, const REAL p0, const REAL p1,
                              const REAL p2)
{
    if (flow == 0)
        return (REAL3)(p0, p1, p2);
    const REAL sh = (REAL)M_PI_2 / p1;
    const REAL X = p1 * (x.x + sh), Y = p1 * (x.y + sh), Z = p1 * (x.z + sh);
    REAL cx, cy, cz;
    const REAL sx = flow_sincos(X, &cx), sy = flow_sincos(Y, &cy), sz = flow_sincos(Z, &cz);
    return (REAL3)(p0 * cx * sy * sz, p0 * sx * cy * sz,
                   (REAL)-2 * p0 * (flow == 2 ? cx : sx) * sy * cz);
}

/* update explicit: the force f plus the drag beta (u_f - v), beta = 3 pi mu d */
static inline REAL3 drag_explicit_force(const REAL3 f, const REAL3 uf, const REAL3 v,
                                        const REAL r, const REAL mu)
{
    const REAL beta = (REAL)6 * (REAL)M_PI * mu * r;
    return f + beta * (uf - v);
}

/* update implicit / exact: the effective drag D of one half kick of length
 * h under the other forces F (held fixed over the kick), so that the kick
 * v += h (F + D)/m lands on the backward-Euler (exact: the exponential)
 * velocity of dv/dt = F/m + (u_f - v)/tau, tau = m / (3 pi mu d). */
static inline REAL3 drag_half_kick(const REAL3 F, const REAL3 uf, const REAL3 v, const REAL m,
                                   const REAL r, const REAL mu, const int exact, const REAL h)
{
    const REAL tau = m / ((REAL)6 * (REAL)M_PI * mu * r);
    const REAL3 target = uf + (tau / m) * F;   /* steady state under fixed F */
    REAL3 dv;
    if (exact)
        dv = (target - v) * (-expm1(-h / tau));
    else
        dv = (target - v) * (h / (tau + h));
    return (m / h) * dv - F;
}
