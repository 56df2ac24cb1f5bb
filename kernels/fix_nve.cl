/* fix_nve.cl - velocity Verlet for point masses (LAMMPS fix_nve.cpp with
 * per-atom rmass): v += dt/2 f/m; x += dt v; ... v += dt/2 f/m. */

__kernel void nve_initial(const int n, const uint groupbit, __global const uint *mask,
                          __global REAL *x, __global REAL *v, __global const REAL *f,
                          __global const REAL *rmass, const REAL dtv, const REAL dtf POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL dtfm = dtf / rmass[i];
    REAL3 vi = vload3(i, v) + dtfm * vload3(i, f);
    vstore3(vi, i, v);
    REAL3 hi = vload3(i, x), lo = POS_LOAD_LO(i);
    pos_add(&hi, &lo, dtv * vi);
    vstore3(hi, i, x);
    POS_STORE_LO(lo, i);
}

__kernel void nve_final(const int n, const uint groupbit, __global const uint *mask,
                        __global REAL *v, __global const REAL *f, __global const REAL *rmass,
                        const REAL dtf)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL dtfm = dtf / rmass[i];
    vstore3(vload3(i, v) + dtfm * vload3(i, f), i, v);
}
