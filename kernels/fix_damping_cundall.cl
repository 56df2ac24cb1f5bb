/* fix_damping_cundall.cl - Cundall's non-viscous damping (today's LAMMPS
 * fix damping/cundall, GRANULAR): each component of the force and of the
 * torque scaled by 1 - gamma s, s = +1 where it does work on the matching
 * velocity component (f_k v_k >= 0), -1 where it opposes it, so the
 * damping's power is never positive. gamma per type (gam[2 (t - 1)]: linear,
 * angular), or with a per-atom scale gamma = (gl, ga) x scale[i]. */

static inline REAL3 cundall_scale(const REAL3 f, const REAL3 v, const REAL gm)
{
    REAL3 out;
    out.x = f.x * ((REAL)1 - gm * (f.x * v.x >= (REAL)0 ? (REAL)1 : (REAL)-1));
    out.y = f.y * ((REAL)1 - gm * (f.y * v.y >= (REAL)0 ? (REAL)1 : (REAL)-1));
    out.z = f.z * ((REAL)1 - gm * (f.z * v.z >= (REAL)0 ? (REAL)1 : (REAL)-1));
    return out;
}

__kernel void damping_cundall_post_force(const int n, const uint groupbit,
                                         __global const uint *mask, __global const int *type,
                                         __global const REAL *v, __global const REAL *omega,
                                         __global REAL *f, __global REAL *torque,
                                         __global const REAL *gam, __global const REAL *scale,
                                         const int peratom, const REAL gl, const REAL ga)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL gli = peratom ? gl * scale[i] : gam[2 * (type[i] - 1)];
    vstore3(cundall_scale(vload3(i, f), vload3(i, v), gli), i, f);
#ifdef HAS_ROTATION
    const REAL gai = peratom ? ga * scale[i] : gam[2 * (type[i] - 1) + 1];
    vstore3(cundall_scale(vload3(i, torque), vload3(i, omega), gai), i, torque);
#else
    (void)omega;
    (void)torque;
    (void)ga;
#endif
}
