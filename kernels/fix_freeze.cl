/* fix_freeze.cl - zero force and torque of the group (LAMMPS fix_freeze.cpp).
 * Pair gran styles also read the freeze group bit for their meff. */

__kernel void freeze_post_force(const int n, const uint groupbit, __global const uint *mask,
                                __global REAL *f, __global REAL *torque)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    vstore3((REAL3)(0), i, f);
#ifdef HAS_ROTATION
    vstore3((REAL3)(0), i, torque);
#endif
}

/* The same, first keeping the force each atom had (LAMMPS's foriginal,
 * summed on the host for f_ID[1..3]). */
__kernel void freeze_post_force_keep(const int n, const uint groupbit, __global const uint *mask,
                                     __global REAL *f, __global REAL *torque,
                                     __global REAL *orig)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    vstore3(vload3(i, f), i, orig);
    vstore3((REAL3)(0), i, f);
#ifdef HAS_ROTATION
    vstore3((REAL3)(0), i, torque);
#endif
}
