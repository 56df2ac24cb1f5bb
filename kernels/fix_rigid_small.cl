/* fix_rigid_small.cl - the device side of fix rigid/small
 * (styles/fix/fix_rigid_small.c): copy the members' forces and torques into a
 * compact buffer (member order), and write back the members' positions,
 * velocities and spins computed on the host. idx[k] = device index of
 * member k (-1: its atom is another MPI rank's; gathered as zeros, not
 * written). Positions arrive relative to the run's origin, split in hi + lo
 * parts with SPLIT_POS (xls), as eng_write_positions splits them. */

__kernel void rigid_gather(const int nm, __global const int *idx, __global const REAL *f,
                           __global const REAL *torque, const int hastorque,
                           __global REAL *out)
{
    const int k = get_global_id(0);
    if (k >= nm)
        return;
    const int i = idx[k];
    vstore3(i >= 0 ? vload3(i, f) : (REAL3)(0), 2 * k, out);
    vstore3(hastorque && i >= 0 ? vload3(i, torque) : (REAL3)(0), 2 * k + 1, out);
}

__kernel void rigid_scatter(const int nm, __global const int *idx, __global const REAL *xs,
                            __global const REAL *xls, __global const REAL *vs,
                            __global const REAL *ws, const int setx, const int setw,
                            __global REAL *x, __global REAL *v, __global REAL *omega POS_LO_PARAM)
{
    const int k = get_global_id(0);
    if (k >= nm)
        return;
    const int i = idx[k];
    if (i < 0)
        return;
    if (setx) {
        vstore3(vload3(k, xs), i, x);
#ifdef SPLIT_POS
        vstore3(vload3(k, xls), i, xlo);
#else
        (void)xls;
#endif
    }
    vstore3(vload3(k, vs), i, v);
    if (setw)
        vstore3(vload3(k, ws), i, omega);
}
