/* fix_gravity.cl - f += m g for the group (LAMMPS fix_gravity.cpp with
 * per-atom rmass); (gx, gy, gz) = magnitude x unit direction, set on the host. */

__kernel void gravity_post_force(const int n, const uint groupbit, __global const uint *mask,
                                 __global const REAL *rmass, __global REAL *f, const REAL gx,
                                 const REAL gy, const REAL gz)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL m = rmass[i];
    REAL3 fi = vload3(i, f);
    fi.x += m * gx;
    fi.y += m * gy;
    fi.z += m * gz;
    vstore3(fi, i, f);
}
