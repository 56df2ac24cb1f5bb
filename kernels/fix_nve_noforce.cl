/* fix_nve_noforce.cl - LAMMPS's fix nve/noforce: the drift alone, x += dt v; the
 * velocity is kept (the forces are not applied). */
__kernel void nve_noforce_initial(const int n, const uint groupbit, __global const uint *mask,
                                  __global REAL *x, __global const REAL *v,
                                  const REAL dtv POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    REAL3 hi = vload3(i, x), lo = POS_LOAD_LO(i);
    pos_add(&hi, &lo, dtv * vload3(i, v));
    vstore3(hi, i, x);
    POS_STORE_LO(lo, i);
}
