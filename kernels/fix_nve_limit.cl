/* fix_nve_limit.cl - LAMMPS's fix nve/limit: velocity Verlet whose velocity
 * is capped after each kick so that no atom moves more than xmax in a step
 * (|v|^2 > vlimitsq: v scaled by sqrt(vlimitsq / |v|^2)); every capped
 * kick adds one to *count (an integer sum: the same in any order). */

static inline REAL3 nve_limit_kick(REAL3 v, const REAL3 f, const REAL dtfm, const REAL vlimitsq,
                                   __global int *count)
{
    v += dtfm * f;
    const REAL vsq = v.x * v.x + v.y * v.y + v.z * v.z;
    if (vsq > vlimitsq) {
        atomic_inc(count);
        v *= sqrt(vlimitsq / vsq);
    }
    return v;
}

__kernel void nve_limit_initial(const int n, const uint groupbit, __global const uint *mask,
                                __global REAL *x, __global REAL *v, __global const REAL *f,
                                __global const REAL *rmass, const REAL dtv, const REAL dtf,
                                const REAL vlimitsq, __global int *count POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL3 vi = nve_limit_kick(vload3(i, v), vload3(i, f), dtf / rmass[i], vlimitsq, count);
    vstore3(vi, i, v);
    REAL3 hi = vload3(i, x), lo = POS_LOAD_LO(i);
    pos_add(&hi, &lo, dtv * vi);
    vstore3(hi, i, x);
    POS_STORE_LO(lo, i);
}

__kernel void nve_limit_final(const int n, const uint groupbit, __global const uint *mask,
                              __global REAL *v, __global const REAL *f, __global const REAL *rmass,
                              const REAL dtf, const REAL vlimitsq, __global int *count)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    vstore3(nve_limit_kick(vload3(i, v), vload3(i, f), dtf / rmass[i], vlimitsq, count), i, v);
}
