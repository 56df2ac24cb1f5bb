/* fix_enforce2d.cl - planar motion (LAMMPS fix_enforce2d.cpp): vz = fz = 0,
 * and with rotation omega_x = omega_y = torque_x = torque_y = 0. */

__kernel void enforce2d_post_force(const int n, const uint groupbit, __global const uint *mask,
                                   __global REAL *v, __global REAL *f, __global REAL *omega,
                                   __global REAL *torque)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    v[3 * i + 2] = (REAL)0;
    f[3 * i + 2] = (REAL)0;
#ifdef HAS_ROTATION
    omega[3 * i] = omega[3 * i + 1] = (REAL)0;
    torque[3 * i] = torque[3 * i + 1] = (REAL)0;
#endif
}
