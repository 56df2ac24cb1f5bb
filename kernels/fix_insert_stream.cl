/* fix_insert_stream.cl - the ballistic approach of fix insert/stream
 * (LIGGGHTS-PUBLIC 3.8 FixInsertStream::end_of_step): an atom inserted at
 * step i_step in the extruded volume moves at the constant velocity v_int
 * (the insertion velocity's part along the face normal), x = x_ins + (step
 * - i_step) dt v_int, with omega, force and torque zero, whatever the
 * integrator and the forces did during the step, until its release step
 * r_step (its centre reaches the face); at r_step it gets the release
 * velocity v_rel and omega_ins and moves freely from then on. An atom of a
 * clump (mask & clumpbit, fix multisphere's atoms) is left alone at r_step:
 * its body is released (LIGGGHTS FixInsertStream::end_of_step). 
 *
 * Per-atom state (the fix's peratom buffer, `stride` ints per atom): int
 * i_step, int r_step (i_step 0: not an atom of this fix), then REAL x_ins hi
 * [3], x_ins lo [3] (the split position, relative to the run's origin; lo
 * 0 without SPLIT_POS), v_int [3], v_rel [3]. */

__kernel void insert_stream_end_of_step(const int n, const uint groupbit,
                                        __global const uint *mask, const int stride,
                                        __global const int *state, const int step,
                                        const REAL dt, const REAL omx, const REAL omy,
                                        const REAL omz, __global REAL *x, __global REAL *v,
                                        __global REAL *f, __global REAL *omega,
                                        __global REAL *torque,
                                        const uint clumpbit POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    __global const int *s = state + (size_t)i * stride;
    const int i_step = s[0], r_step = s[1];
    if (i_step == 0 || step > r_step || (step == r_step && (mask[i] & clumpbit)))
        return;
    __global const REAL *d = (__global const REAL *)(s + 2);
    const REAL3 vint = vload3(2, d);
    REAL3 hi = vload3(0, d), lo = vload3(1, d);
    pos_add(&hi, &lo, vint * ((REAL)(step - i_step) * dt));
    vstore3(hi, i, x);
    POS_STORE_LO(lo, i);
    vstore3(step == r_step ? vload3(3, d) : vint, i, v);
    vstore3((REAL3)(0), i, f);
#ifdef HAS_ROTATION
    vstore3(step == r_step ? (REAL3)(omx, omy, omz) : (REAL3)(0), i, omega);
    vstore3((REAL3)(0), i, torque);
#else
    (void)omx, (void)omy, (void)omz, (void)omega, (void)torque;
#endif
}
