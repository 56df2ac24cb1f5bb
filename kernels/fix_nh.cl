/* fix_nh.cl - the per-atom work of the Nose-Hoover integrators (fix nvt,
 * npt, nph and their /sphere forms; host side styles/fix_nh.c). Each kernel
 * does exactly LAMMPS FixNH's arithmetic, in its order, for the atoms of the
 * fix group (groupbit); the box dilation for those of the dilate group.
 *
 * Flags (bit mask `ops`, in the order applied):
 *   NH_TEMP    v *= fe (and omega *= fe with NH_SPHERE)   nh_v_temp
 *   NH_PRESS   v_d *= fp_d, twice                          nh_v_press
 *   NH_KICK    v += dtf/m f (omega += dtf/(I r^2 m) torque) nve_v
 *   NH_REMAP1  x -> lamda in box A -> x in box B           remap
 *   NH_DRIFT   x += dtv v                                  nve_x
 *   NH_REMAP2  x -> lamda in box B -> x in box C           remap
 * final_integrate is NH_KICK then NH_PRESS: nh_final orders them so. */

#define NH_TEMP 1
#define NH_PRESS 2
#define NH_KICK 4
#define NH_REMAP1 8
#define NH_DRIFT 16
#define NH_REMAP2 32
#define NH_SPHERE 64

/* LAMMPS x2lamda then lamda2x of an orthogonal box, all three dimensions:
 * lamda = hinv (x - lo_a), x = h lamda + lo_b (device x relative to the
 * origin: lo_a, lo_b likewise). With split positions the change is added. */
static inline void nh_remap(REAL3 *hi, REAL3 *lo, const REAL3 lo_a, const REAL3 hinv_a,
                            const REAL3 lo_b, const REAL3 h_b)
{
#ifdef SPLIT_POS
    const REAL3 x = *hi + *lo;
    const REAL3 lam = hinv_a * (x - lo_a);
    pos_add(hi, lo, (h_b * lam + lo_b) - x);
#else
    (void)lo;
    const REAL3 lam = hinv_a * (*hi - lo_a);
    *hi = h_b * lam + lo_b;
#endif
}

static inline REAL3 nh_kick(const REAL3 v, const REAL3 f, const REAL dtfm)
{
    return (REAL3)(v.x + dtfm * f.x, v.y + dtfm * f.y, v.z + dtfm * f.z);
}

static inline REAL3 nh_press(REAL3 v, const REAL3 fp)
{
    v = (REAL3)(v.x * fp.x, v.y * fp.y, v.z * fp.z);
    return (REAL3)(v.x * fp.x, v.y * fp.y, v.z * fp.z);
}

/* The atom work of initial_integrate, or of a part of it (ops). box: lo_a,
 * hinv_a, lo_b, h_b for the first remap, lo_b, hinv_b, lo_c, h_c for the
 * second (x, y, z each). */
__kernel void nh_initial(const int n, const uint groupbit, const uint dilatebit,
                         const int ops, __global const uint *mask, __global REAL *x,
                         __global REAL *v, __global const REAL *f, __global REAL *omega,
                         __global const REAL *torque, __global const REAL *radius,
                         __global const REAL *rmass, const REAL fe, const REAL fpx,
                         const REAL fpy, const REAL fpz, const REAL dtv, const REAL dtf,
                         const REAL dtfrot, __global const REAL *box POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const uint mi = mask[i];
    const int in = (mi & groupbit) != 0, dil = (mi & dilatebit) != 0;
    if (!in && !dil)
        return;
    REAL3 vi = vload3(i, v);
#ifdef HAS_ROTATION
    REAL3 wi = vload3(i, omega);
#endif
    if (in) {
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
    if (!(ops & (NH_REMAP1 | NH_DRIFT | NH_REMAP2)))
        return;
    REAL3 hi = vload3(i, x), lo = POS_LOAD_LO(i);
    if ((ops & NH_REMAP1) && dil)
        nh_remap(&hi, &lo, vload3(0, box), vload3(1, box), vload3(2, box), vload3(3, box));
    if ((ops & NH_DRIFT) && in)
        pos_add(&hi, &lo, dtv * vi);
    if ((ops & NH_REMAP2) && dil)
        nh_remap(&hi, &lo, vload3(4, box), vload3(5, box), vload3(6, box), vload3(7, box));
    vstore3(hi, i, x);
    POS_STORE_LO(lo, i);
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
