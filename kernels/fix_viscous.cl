/* fix_viscous.cl - velocity-proportional drag f -= gamma v (LAMMPS
 * fix_viscous.cpp; gamma per atom type, packed on the host). */

__kernel void viscous_post_force(const int n, const uint groupbit, __global const uint *mask,
                                 __global const int *type, __global const REAL *v,
                                 __global REAL *f, __global const REAL *gamma)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL gm = gamma[type[i] - 1];
    vstore3(vload3(i, f) - gm * vload3(i, v), i, f);
}
