/* fix_lineforce.cl - LAMMPS's fix lineforce and fix planeforce (post_force):
 * with d the unit direction and dot = f . d, lineforce keeps only the force
 * along the line (f = dot d), planeforce removes it (f -= dot d, motion in
 * the plane normal to d). The torque is left as it is. */
__kernel void line_plane_force(const int n, const uint groupbit, __global const uint *mask,
                               __global REAL *f, const REAL dx, const REAL dy, const REAL dz,
                               const int plane)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    REAL3 fi = vload3(i, f);
    const REAL d = fi.x * dx + fi.y * dy + fi.z * dz;
    const REAL3 along = (REAL3)(d * dx, d * dy, d * dz);
    vstore3(plane ? fi - along : along, i, f);
}
