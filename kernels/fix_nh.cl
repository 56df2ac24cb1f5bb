/* fix_nh.cl - the per-atom work of the Nose-Hoover integrators (fix nvt,
 * npt, nph and their /sphere forms; host side styles/fix/fix_nh.c). Each kernel
 * does exactly LAMMPS FixNH's arithmetic, in its order, for the atoms of the
 * fix group (groupbit).
 *
 * Flags (bit mask `ops`, in the order applied):
 *   NH_TEMP    v *= fe (and omega *= fe with NH_SPHERE)   nh_v_temp
 *   NH_PRESS   v_d *= fp_d, twice                          nh_v_press
 *   NH_KICK    v += dtf/m f (omega += dtf/(I r^2 m) torque) nve_v
 *   NH_DRIFT   x += dtv v                                  nve_x
 * final_integrate is NH_KICK then NH_PRESS: nh_final orders them so. The
 * box dilation between the kick and the drift and after the drift is the
 * box change's (src/engine/box_change.c). */

#define NH_TEMP 1
#define NH_PRESS 2
#define NH_KICK 4
#define NH_DRIFT 16
#define NH_SPHERE 64

static inline REAL3 nh_kick(const REAL3 v, const REAL3 f, const REAL dtfm)
{
    return (REAL3)(v.x + dtfm * f.x, v.y + dtfm * f.y, v.z + dtfm * f.z);
}

static inline REAL3 nh_press(REAL3 v, const REAL3 fp)
{
    v = (REAL3)(v.x * fp.x, v.y * fp.y, v.z * fp.z);
    return (REAL3)(v.x * fp.x, v.y * fp.y, v.z * fp.z);
}

/* The atom work of initial_integrate, or of a part of it (ops). */
__kernel void nh_initial(const int n, const uint groupbit, const int ops,
                         __global const uint *mask, __global REAL *x,
                         __global REAL *v, __global const REAL *f, __global REAL *omega,
                         __global const REAL *torque, __global const REAL *radius,
                         __global const REAL *rmass, const REAL fe, const REAL fpx,
                         const REAL fpy, const REAL fpz, const REAL dtv, const REAL dtf,
                         const REAL dtfrot POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    REAL3 vi = vload3(i, v);
#ifdef HAS_ROTATION
    REAL3 wi = vload3(i, omega);
#endif
    if (ops & (NH_TEMP | NH_PRESS | NH_KICK)) {
        if (ops & NH_TEMP) {
            vi = (REAL3)(vi.x * fe, vi.y * fe, vi.z * fe);
#ifdef HAS_ROTATION
            if (ops & NH_SPHERE)
                wi = (REAL3)(wi.x * fe, wi.y * fe, wi.z * fe);
#endif
        }
        if (ops & NH_PRESS)
            vi = nh_press(vi, (REAL3)(fpx, fpy, fpz));
        if (ops & NH_KICK) {
            vi = nh_kick(vi, vload3(i, f), dtf / rmass[i]);
#ifdef HAS_ROTATION
            if (ops & NH_SPHERE) {
                const REAL r = radius[i];
                wi = nh_kick(wi, vload3(i, torque), dtfrot / (r * r * rmass[i]));
            }
#endif
        }
        vstore3(vi, i, v);
#ifdef HAS_ROTATION
        if (ops & NH_SPHERE)
            vstore3(wi, i, omega);
#endif
    }
    if (ops & NH_DRIFT) {
        REAL3 hi = vload3(i, x), lo = POS_LOAD_LO(i);
        pos_add(&hi, &lo, dtv * vi);
        vstore3(hi, i, x);
        POS_STORE_LO(lo, i);
    }
}

/* final_integrate's atom work: nve_v, then nh_v_press (NH_PRESS). */
__kernel void nh_final(const int n, const uint groupbit, const int ops,
                       __global const uint *mask, __global REAL *v, __global const REAL *f,
                       __global REAL *omega, __global const REAL *torque,
                       __global const REAL *radius, __global const REAL *rmass,
                       const REAL fpx, const REAL fpy, const REAL fpz, const REAL dtf,
                       const REAL dtfrot)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    REAL3 vi = nh_kick(vload3(i, v), vload3(i, f), dtf / rmass[i]);
    if (ops & NH_PRESS)
        vi = nh_press(vi, (REAL3)(fpx, fpy, fpz));
    vstore3(vi, i, v);
#ifdef HAS_ROTATION
    if (ops & NH_SPHERE) {
        const REAL r = radius[i];
        vstore3(nh_kick(vload3(i, omega), vload3(i, torque), dtfrot / (r * r * rmass[i])), i,
                omega);
    }
#endif
}

/* Per-atom kinetic terms of the fix's temperature, for host sums in tag
 * order (LAMMPS compute temp and temp/sphere): out[8i ..] = m v.v, I m r^2
 * w.w (sphere), m vx vx, m vy vy, m vz vz, I m r^2 wx wx, .. wy wy, .. wz wz;
 * zero outside the group. */
__kernel void nh_mvv(const int n, const uint groupbit, const int sphere,
                     __global const uint *mask, __global const REAL *v,
                     __global const REAL *omega, __global const REAL *radius,
                     __global const REAL *rmass, const REAL inertia, __global REAL *out)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    REAL o[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    if (mask[i] & groupbit) {
        const REAL3 vi = vload3(i, v);
        const REAL m = rmass[i];
        o[0] = (vi.x * vi.x + vi.y * vi.y + vi.z * vi.z) * m;
        o[2] = m * vi.x * vi.x;
        o[3] = m * vi.y * vi.y;
        o[4] = m * vi.z * vi.z;
#ifdef HAS_ROTATION
        if (sphere) {
            const REAL3 w = vload3(i, omega);
            const REAL r = radius[i];
            o[1] = (w.x * w.x + w.y * w.y + w.z * w.z) * inertia * r * r * m;
            const REAL im = inertia * m * r * r;
            o[5] = im * w.x * w.x;
            o[6] = im * w.y * w.y;
            o[7] = im * w.z * w.z;
        }
#endif
    }
    for (int q = 0; q < 8; q++)
        out[8 * (size_t)i + q] = o[q];
}
