/* pair_colloid.cl - LAMMPS pair colloid (styles/pair/pair_colloid.c): integrated
 * Lennard-Jones spheres (Everaers and Ejtehadi 2003), three forms chosen per
 * type pair on the host (COL_FORM):
 *   COL_SS  small-small: LJ 4 eps ((s/r)^12 - (s/r)^6), eps = A / 144;
 *   COL_SL  colloid of radius a2 and a point LJ particle;
 *   COL_LL  two colloids of radii a1 (the owner's type) and a2.
 * The force on i is fpair del (del = x_i - x_j); zero at and beyond the
 * cut-off (rsq >= cutsq). The arithmetic is LAMMPS's, operation for
 * operation, so forces agree to round-off. Energies (pair_energy,
 * kernels/pair_loop.cl) subtract the offset of pair_modify shift yes.
 * Overlapping particles (r <= a2 for COL_SL, r <= a1 + a2 for COL_LL, inside
 * the cut-off) are an error in LAMMPS ("Overlapping small/large in pair
 * colloid"); here their force is NaN, so the run's non-finite check stops
 * at the next step and names the overlap (pair_caps.nonfinite_cause). No
 * torque, no history. */

/* x^-7 as LAMMPS's MathSpecial::powint(x, -7): repeated squaring, then 1/y */
static inline REAL colloid_pow_m7(const REAL x)
{
    const REAL x2 = x * x;
    const REAL x3 = x * x2;
    const REAL x4 = x2 * x2;
    return (REAL)1 / (x3 * x4);
}

/* fpair (force on i = fpair del) of a pair at squared distance rsq < cutsq */
static inline REAL colloid_fpair(const REAL rsq, __global const REAL *p)
{
    const int form = (int)p[COL_FORM];
    if (form == COL_SS) {
        const REAL r2inv = (REAL)1 / rsq;
        const REAL r6inv = r2inv * r2inv * r2inv;
        const REAL forcelj = r6inv * (p[COL_LJ1] * r6inv - p[COL_LJ2]);
        return forcelj * r2inv;
    }
    if (form == COL_SL) {
        const REAL c2 = p[COL_A2];
        const REAL k1 = c2 * c2, k2 = rsq, k0 = k1 - rsq, k4 = rsq * rsq;
        if (rsq <= k1)
            return (REAL)NAN; /* LAMMPS: Overlapping small/large in pair colloid */
        REAL k3 = k1 - k2;
        k3 *= k3 * k3;
        const REAL k6 = k3 * k3;
        const REAL fR = p[COL_SIGMA3] * p[COL_A12] * c2 * k1 / k3;
        return (REAL)4.0 / (REAL)15.0 * fR *
               ((REAL)2.0 * (k1 + k2) * (k1 * ((REAL)5.0 * k1 + (REAL)22.0 * k2) + (REAL)5.0 * k4) *
                    p[COL_SIGMA6] / k6 -
                (REAL)5.0) /
               k0;
    }
    const REAL r = sqrt(rsq);
    const REAL c1 = p[COL_A1], c2 = p[COL_A2];
    const REAL K0 = c1 * c2, K1 = c1 + c2, K2 = c1 - c2;
    if (r <= K1)
        return (REAL)NAN; /* LAMMPS: Overlapping large/large in pair colloid */
    const REAL K3 = K1 + r, K4 = K1 - r, K5 = K2 + r, K6 = K2 - r;
    const REAL K7 = (REAL)1.0 / (K3 * K4), K8 = (REAL)1.0 / (K5 * K6);
    REAL g0 = colloid_pow_m7(K3), g1 = colloid_pow_m7(K4);
    REAL g2 = colloid_pow_m7(K5), g3 = colloid_pow_m7(K6);
    const REAL h0 = ((K3 + (REAL)5.0 * K1) * K3 + (REAL)30.0 * K0) * g0;
    const REAL h1 = ((K4 + (REAL)5.0 * K1) * K4 + (REAL)30.0 * K0) * g1;
    const REAL h2 = ((K5 + (REAL)5.0 * K2) * K5 - (REAL)30.0 * K0) * g2;
    const REAL h3 = ((K6 + (REAL)5.0 * K2) * K6 - (REAL)30.0 * K0) * g3;
    g0 *= (REAL)42.0 * K0 / K3 + (REAL)6.0 * K1 + K3;
    g1 *= (REAL)42.0 * K0 / K4 + (REAL)6.0 * K1 + K4;
    g2 *= (REAL)-42.0 * K0 / K5 + (REAL)6.0 * K2 + K5;
    g3 *= (REAL)-42.0 * K0 / K6 + (REAL)6.0 * K2 + K6;
    const REAL a12 = p[COL_A12];
    const REAL fR = a12 * p[COL_SIGMA6] / r / (REAL)37800.0;
    const REAL evdwl = fR * (h0 - h1 - h2 + h3);
    const REAL dUR = evdwl / r + (REAL)5.0 * fR * (g0 + g1 - g2 - g3);
    const REAL dUA = -a12 / (REAL)3.0 * r *
                     (((REAL)2.0 * K0 * K7 + (REAL)1.0) * K7 + ((REAL)2.0 * K0 * K8 - (REAL)1.0) * K8);
    return (dUR + dUA) / r;
}

/* The pair energy at squared distance rsq (0 at and beyond the cut-off). */
static inline REAL colloid_energy(const REAL rsq, __global const REAL *p)
{
    if (rsq >= p[COL_CUTSQ])
        return (REAL)0;
    const int form = (int)p[COL_FORM];
    if (form == COL_SS) {
        const REAL r2inv = (REAL)1 / rsq;
        const REAL r6inv = r2inv * r2inv * r2inv;
        return r6inv * (r6inv * p[COL_LJ3] - p[COL_LJ4]) - p[COL_OFFSET];
    }
    if (form == COL_SL) {
        const REAL c2 = p[COL_A2];
        const REAL k1 = c2 * c2, k2 = rsq, k4 = rsq * rsq;
        REAL k3 = k1 - k2;
        k3 *= k3 * k3;
        const REAL k6 = k3 * k3;
        const REAL fR = p[COL_SIGMA3] * p[COL_A12] * c2 * k1 / k3;
        return (REAL)2.0 / (REAL)9.0 * fR *
                   ((REAL)1.0 - (k1 * (k1 * (k1 / (REAL)3.0 + (REAL)3.0 * k2) + (REAL)4.2 * k4) +
                                 k2 * k4) *
                                    p[COL_SIGMA6] / k6) -
               p[COL_OFFSET];
    }
    const REAL r = sqrt(rsq);
    const REAL c1 = p[COL_A1], c2 = p[COL_A2];
    const REAL K0 = c1 * c2, K1 = c1 + c2, K2 = c1 - c2;
    const REAL K3 = K1 + r, K4 = K1 - r, K5 = K2 + r, K6 = K2 - r;
    const REAL K7 = (REAL)1.0 / (K3 * K4), K8 = (REAL)1.0 / (K5 * K6);
    const REAL g0 = colloid_pow_m7(K3), g1 = colloid_pow_m7(K4);
    const REAL g2 = colloid_pow_m7(K5), g3 = colloid_pow_m7(K6);
    const REAL h0 = ((K3 + (REAL)5.0 * K1) * K3 + (REAL)30.0 * K0) * g0;
    const REAL h1 = ((K4 + (REAL)5.0 * K1) * K4 + (REAL)30.0 * K0) * g1;
    const REAL h2 = ((K5 + (REAL)5.0 * K2) * K5 - (REAL)30.0 * K0) * g2;
    const REAL h3 = ((K6 + (REAL)5.0 * K2) * K6 - (REAL)30.0 * K0) * g3;
    const REAL a12 = p[COL_A12];
    const REAL fR = a12 * p[COL_SIGMA6] / r / (REAL)37800.0;
    REAL e = fR * (h0 - h1 - h2 + h3);
    e += a12 / (REAL)6.0 * ((REAL)2.0 * K0 * (K7 + K8) - log(K8 / K7)) - p[COL_OFFSET];
    return e;
}

static inline void colloid_eval(const struct contact *c, __global const REAL *param,
                                REAL3 *shear, struct contact_force *out)
{
    (void)shear;
    out->f = out->tc = out->tr = (REAL3)(0);
    if (c->rsq >= param[COL_CUTSQ])
        return;
    const REAL fpair = colloid_fpair(c->rsq, param);
    out->f = (REAL3)(c->del.x * fpair, c->del.y * fpair, c->del.z * fpair);
}

/* collision time (kernels/accuracy.cl): a soft potential, no contact collision */
static inline REAL colloid_eval_tcol(const struct contact *c, __global const REAL *param,
                                     const REAL vn)
{
    (void)c;
    (void)param;
    (void)vn;
    return (REAL)0;
}
