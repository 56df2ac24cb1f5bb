/* fix_spring.cl - LAMMPS's fix spring (post_force): each atom of the group
 * takes the spring's force in proportion to its mass, f += m c1, and with
 * couple each atom of the second group f -= m c2 (c = the spring's force
 * over the group's mass, from the host). */
__kernel void spring_force(const int n, __global const uint *mask, __global const REAL *rmass,
                           __global REAL *f, const uint bit1, const REAL c1x, const REAL c1y,
                           const REAL c1z, const uint bit2, const REAL c2x, const REAL c2y,
                           const REAL c2z)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const REAL m = rmass[i];
    REAL3 fi = vload3(i, f);
    if (mask[i] & bit1)
        fi += (REAL3)(c1x * m, c1y * m, c1z * m);
    if (mask[i] & bit2)
        fi -= (REAL3)(c2x * m, c2y * m, c2z * m);
    vstore3(fi, i, f);
}
