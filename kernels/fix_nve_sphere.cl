/* fix_nve_sphere.cl - velocity Verlet for finite-size spheres (LAMMPS
 * fix_nve_sphere.cpp): dtf = dt/2 ftm2v, moment of inertia I m r^2 with
 * I = 0.4 (solid sphere) or 0.5 (`disc`, 2d); dtfrotate = dtf / I, from
 * the host.
 *   initial: v += dtf/m f; x += dt v; omega += dtf/(I m r^2) torque
 *   final:   v += dtf/m f;           omega += dtf/(I m r^2) torque
 * Omega is updated only when the run has rotation (HAS_ROTATION). */

__kernel void nve_sphere_initial(const int n, const uint groupbit, __global const uint *mask,
                                 __global REAL *x, __global REAL *v, __global const REAL *f,
                                 __global REAL *omega, __global const REAL *torque,
                                 __global const REAL *radius, __global const REAL *rmass,
                                 const REAL dtv, const REAL dtf,
                                 const REAL dtfrotate POS_LO_PARAM)
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
#ifdef HAS_ROTATION
    const REAL dtirotate = dtfrotate / (radius[i] * radius[i] * rmass[i]);
    vstore3(vload3(i, omega) + dtirotate * vload3(i, torque), i, omega);
#endif
}

__kernel void nve_sphere_final(const int n, const uint groupbit, __global const uint *mask,
                               __global REAL *v, __global const REAL *f, __global REAL *omega,
                               __global const REAL *torque, __global const REAL *radius,
                               __global const REAL *rmass, const REAL dtf, const REAL dtfrotate)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL dtfm = dtf / rmass[i];
    vstore3(vload3(i, v) + dtfm * vload3(i, f), i, v);
#ifdef HAS_ROTATION
    const REAL dtirotate = dtfrotate / (radius[i] * radius[i] * rmass[i]);
    vstore3(vload3(i, omega) + dtirotate * vload3(i, torque), i, omega);
#endif
}
