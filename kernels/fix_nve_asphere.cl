/* fix_nve_asphere.cl - velocity Verlet for aspherical particles (LAMMPS
 * fix_nve_asphere.cpp with MathExtra's richardson): translation as fix nve
 * (dtf = dt/2 ftm2v), the space-frame angular momentum kicked by the torque,
 *   initial: v += dtf/m f; x += dt v; L += dtf T;
 *            q advanced a full step by Richardson iteration of
 *            dq/dt = 1/2 (0, w) q with w from L, q and the principal moments
 *   final:   v += dtf/m f; L += dtf T.
 * Quaternions are (w, i, j, k) in s0..s3, body to space. Pure functions
 * first, in LAMMPS's operation order. */

/* q / |q| */
static inline REAL4 asph_qnormalize(REAL4 q)
{
    const REAL norm = (REAL)1 / sqrt(q.s0 * q.s0 + q.s1 * q.s1 + q.s2 * q.s2 + q.s3 * q.s3);
    return q * norm;
}

/* (0, a) * b, the quaternion product of a pure vector with b */
static inline REAL4 asph_vecquat(const REAL3 a, const REAL4 b)
{
    return (REAL4)(-a.x * b.s1 - a.y * b.s2 - a.z * b.s3, b.s0 * a.x + a.y * b.s3 - a.z * b.s2,
                   b.s0 * a.y + a.z * b.s1 - a.x * b.s3, b.s0 * a.z + a.x * b.s2 - a.y * b.s1);
}

/* The space-frame angular velocity of angular momentum m for orientation q
 * and principal moments (a zero moment gives no rotation about its axis). */
static inline REAL3 asph_mq_to_omega(const REAL3 m, const REAL4 q, const REAL3 moments)
{
    const REAL w2 = q.s0 * q.s0, i2 = q.s1 * q.s1, j2 = q.s2 * q.s2, k2 = q.s3 * q.s3;
    const REAL twoij = (REAL)2 * q.s1 * q.s2, twoik = (REAL)2 * q.s1 * q.s3;
    const REAL twojk = (REAL)2 * q.s2 * q.s3, twoiw = (REAL)2 * q.s1 * q.s0;
    const REAL twojw = (REAL)2 * q.s2 * q.s0, twokw = (REAL)2 * q.s3 * q.s0;
    const REAL3 r0 = (REAL3)(w2 + i2 - j2 - k2, twoij - twokw, twojw + twoik);
    const REAL3 r1 = (REAL3)(twoij + twokw, w2 - i2 + j2 - k2, twojk - twoiw);
    const REAL3 r2 = (REAL3)(twoik - twojw, twojk + twoiw, w2 - i2 - j2 + k2);
    REAL3 wb = (REAL3)(r0.x * m.x + r1.x * m.y + r2.x * m.z, r0.y * m.x + r1.y * m.y + r2.y * m.z,
                       r0.z * m.x + r1.z * m.y + r2.z * m.z);
    wb.x = moments.x == (REAL)0 ? (REAL)0 : wb.x / moments.x;
    wb.y = moments.y == (REAL)0 ? (REAL)0 : wb.y / moments.y;
    wb.z = moments.z == (REAL)0 ? (REAL)0 : wb.z / moments.z;
    return (REAL3)(r0.x * wb.x + r0.y * wb.y + r0.z * wb.z, r1.x * wb.x + r1.y * wb.y + r1.z * wb.z,
                   r2.x * wb.x + r2.y * wb.y + r2.z * wb.z);
}

/* One full step dtq = dt/2 of dq/dt = 1/2 w q: a full Euler step and two
 * half steps (the second with w re-evaluated at the half-step orientation),
 * combined as 2 q_half - q_full (Richardson extrapolation), normalized. */
static inline REAL4 asph_richardson(const REAL4 q, const REAL3 m, const REAL3 moments,
                                    const REAL dtq)
{
    REAL3 w = asph_mq_to_omega(m, q, moments);
    REAL4 wq = asph_vecquat(w, q);
    const REAL4 qfull = asph_qnormalize(q + dtq * wq);
    REAL4 qhalf = asph_qnormalize(q + (REAL)0.5 * dtq * wq);
    w = asph_mq_to_omega(m, qhalf, moments);
    wq = asph_vecquat(w, qhalf);
    qhalf = asph_qnormalize(qhalf + (REAL)0.5 * dtq * wq);
    return asph_qnormalize((REAL)2 * qhalf - qfull);
}

__kernel void nve_asphere_initial(const int n, const uint groupbit, __global const uint *mask,
                                  __global REAL *x, __global REAL *v, __global const REAL *f,
                                  __global const REAL *torque, __global const REAL *rmass,
                                  __global REAL *quat, __global REAL *angmom,
                                  __global const REAL *inertia, const REAL dtv, const REAL dtf,
                                  const REAL dtq POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL dtfm = dtf / rmass[i];
    REAL3 vi = vload3(i, v);
    vi += dtfm * vload3(i, f);
    vstore3(vi, i, v);
    REAL3 hi = vload3(i, x), lo = POS_LOAD_LO(i);
    pos_add(&hi, &lo, dtv * vi);
    vstore3(hi, i, x);
    POS_STORE_LO(lo, i);
    const REAL3 m = vload3(i, angmom) + dtf * vload3(i, torque);
    vstore3(m, i, angmom);
    vstore4(asph_richardson(vload4(i, quat), m, vload3(i, inertia), dtq), i, quat);
}

__kernel void nve_asphere_final(const int n, const uint groupbit, __global const uint *mask,
                                __global REAL *v, __global const REAL *f,
                                __global const REAL *torque, __global const REAL *rmass,
                                __global REAL *angmom, const REAL dtf)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL dtfm = dtf / rmass[i];
    vstore3(vload3(i, v) + dtfm * vload3(i, f), i, v);
    vstore3(vload3(i, angmom) + dtf * vload3(i, torque), i, angmom);
}
