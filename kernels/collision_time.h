/* collision_time.h - the collision time of each contact law, written once.
 *
 * Pure functions of a law's coefficients, the effective mass m*, the
 * effective radius R* and the normal speed vn (> 0), in plain C that is
 * valid C11 and OpenCL C: the host includes this file (styles/pair_*.c: the
 * run-start time-step report, the -check accuracy map, the energy-drift
 * footer; src/style/pair.h's collision-time contract) and the engine prepends it
 * to every program, where each law's <eval>_tcol(c, param, vn) calls the
 * same function with the contact's m* and R* (kernels/accuracy.cl reads
 * those for the collision-resolution records; the Hertz laws' fifth root,
 * tcol_root5, agrees with the host's pow within 2e-12). On the host TCOL_REAL is
 * double; in a program it is the build's REAL. Zero means "no collision
 * time" (overdamped, no stiffness); host callers turn it into INFINITY.
 *
 * Two host estimates of the Hertz laws are not yet the device's formula
 * (tcol_hertz_secant, tcol_hertz_es below): they are kept, side by side with
 * tcol_hertz, because the run logs print both values and must not change.
 * Retiring them is a one-line change per style plus new reference logs. */
#ifndef GR_COLLISION_TIME_H
#define GR_COLLISION_TIME_H

#ifdef __OPENCL_VERSION__
#define TCOL_REAL REAL
#else
#include <math.h>
#define TCOL_REAL double
#endif

/* Linear spring kn with a dashpot of rate gamma (force m* gamma vn), the
 * hooke laws (gran/hooke, gran/hooke/history, fix wall/gran hooke*, pair and
 * wall granular hooke): half the damped period, pi / sqrt(kn / m* -
 * gamma^2 / 4); 0 when overdamped. */
static inline TCOL_REAL tcol_linear(const TCOL_REAL kn, const TCOL_REAL gamma,
                                    const TCOL_REAL meff)
{
    const TCOL_REAL w2 = kn / meff - (TCOL_REAL)0.25 * gamma * gamma;
    return w2 > (TCOL_REAL)0 ? (TCOL_REAL)M_PI / sqrt(w2) : (TCOL_REAL)0;
}

/* x^(1/5) for x >= 0. The host: pow. A program: no pow (PoCL's pow, double
 * or float, is a software routine of extended precision, the wall kernels'
 * largest cost in small scenes): x = f 2^e with f in [0.5, 1) and e = 5 q + r
 * (0 <= r < 5), x^(1/5) = f^(1/5) 2^(r/5) 2^q, f^(1/5) from a quadratic
 * (within 7e-4) and two Newton steps (within 2e-12 of pow). */
static inline TCOL_REAL tcol_root5(const TCOL_REAL x)
{
#ifdef __OPENCL_VERSION__
    if (!(x > (TCOL_REAL)0))
        return x == (TCOL_REAL)0 ? (TCOL_REAL)0 : x;
    int e;
    const TCOL_REAL f = frexp(x, &e);
    const int q = e >= 0 ? e / 5 : -((4 - e) / 5);
    const TCOL_REAL two_r5[5] = {1, 1.148698354997035, 1.3195079107728942, 1.515716566510398,
                                 1.7411011265922482}; /* 2^(r/5) */
    TCOL_REAL y = (TCOL_REAL)0.6730036087985899 +
                  f * ((TCOL_REAL)0.46586223882538375 - (TCOL_REAL)0.1392227139959569 * f);
    for (int k = 0; k < 2; k++) {
        const TCOL_REAL y2 = y * y;
        y = (TCOL_REAL)0.8 * y + (TCOL_REAL)0.2 * f / (y2 * y2);
    }
    return ldexp(y * two_r5[e - 5 * q], q);
#else
    return pow(x, 0.2);
#endif
}

/* Hertz, F = 4/3 E* sqrt(R*) d^1.5 = K sqrt(R*) d^1.5 (K = 4/3 E*),
 * undamped: t_col = 2.868 (m*^2 / (R* E*^2 vn))^(1/5) (Johnson 1985, 11.2).
 * The device records of gran/hertz/history, hertz/mindlin and the granular
 * hertz walls. */
static inline TCOL_REAL tcol_hertz(const TCOL_REAL K, const TCOL_REAL reff,
                                   const TCOL_REAL meff, const TCOL_REAL vn)
{
    const TCOL_REAL es = (TCOL_REAL)0.75 * K;
    return (TCOL_REAL)2.868 * tcol_root5(meff * meff / (reff * es * es * vn));
}

/* linear/restitution (000 eq. 2.15): spring ke whose dashpot gives the
 * restitution coefficient e: sqrt(m* / ke) sqrt(pi^2 + ln(e)^2). The kernel
 * reads it as LR_CTCOL sqrt(m*), LR_CTCOL = tcol_restitution(ke, e, 1)
 * packed by the host (the same function: t_col scales as sqrt(m*)). */
static inline TCOL_REAL tcol_restitution(const TCOL_REAL ke, const TCOL_REAL e,
                                         const TCOL_REAL meff)
{
    const TCOL_REAL l = log(e);
    return sqrt(meff / ke) * sqrt((TCOL_REAL)M_PI * (TCOL_REAL)M_PI + l * l);
}

/* Host estimate of gran/hertz/history (run-start report): tcol_linear at
 * the secant stiffness kn sqrt(R*) sqrt(d_max) of an undamped impact at vn,
 * with the law's dashpot gamma; 0 when overdamped. */
static inline TCOL_REAL tcol_hertz_secant(const TCOL_REAL kn, const TCOL_REAL gamma,
                                          const TCOL_REAL reff, const TCOL_REAL meff,
                                          const TCOL_REAL vn)
{
    const TCOL_REAL k = kn * sqrt(reff);
    const TCOL_REAL dmax = pow((TCOL_REAL)1.25 * meff * vn * vn / k, (TCOL_REAL)0.4);
    return tcol_linear(k * sqrt(dmax), gamma, meff);
}

/* Host estimate of hertz/mindlin (run-start report): Johnson's formula from
 * E* itself with the constant rounded to 2.87. */
static inline TCOL_REAL tcol_hertz_es(const TCOL_REAL es, const TCOL_REAL reff,
                                      const TCOL_REAL meff, const TCOL_REAL vn)
{
    return (TCOL_REAL)2.87 * pow(meff * meff / (reff * es * es * vn), (TCOL_REAL)0.2);
}

#endif
