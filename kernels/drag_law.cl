/* drag_law.cl - Stokes drag as pure functions (source document 000 eq.
 * 2.7-2.8, the Taylor-Green vortex of eq. 6.1-6.3), read by fix drag's own
 * kernels (kernels/fix_drag.cl) and by its fused ops (kernels/fused.cl), so
 * fused and separate runs agree bit for bit. In every program, before
 * fused.cl; static inline, free in scenes without drag. */

/* Fluid velocity at x. flow 0: (p0, p1, p2); flow 1: Taylor-Green with
 * amplitude A = p0 and wave number a = p1:
 *   u =   A cos(a X) sin(a Y) sin(a Z)
 *   v =   A sin(a X) cos(a Y) sin(a Z)      X = x + pi/(2a), ...
 *   w = -2A sin(a X) sin(a Y) cos(a Z)                                    */
static inline REAL3 drag_flow(const REAL3 x, const int flow, const REAL p0, const REAL p1,
                              const REAL p2)
{
    if (flow == 0)
        return (REAL3)(p0, p1, p2);
    const REAL sh = (REAL)M_PI_2 / p1;
    const REAL X = p1 * (x.x + sh), Y = p1 * (x.y + sh), Z = p1 * (x.z + sh);
    REAL cx, cy, cz;
    const REAL sx = sincos(X, &cx), sy = sincos(Y, &cy), sz = sincos(Z, &cz);
    return (REAL3)(p0 * cx * sy * sz, p0 * sx * cy * sz, (REAL)-2 * p0 * sx * sy * cz);
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
