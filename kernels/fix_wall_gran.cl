/* fix_wall_gran.cl - granular walls (LAMMPS fix wall/gran, 2021 semantics).
 *
 * One work-item per atom. The wall is treated as contact partner j with
 * radj = 0, omj = 0, meff = m_i, and the pair evaluators of
 * pair_gran_hooke.cl / pair_gran_hooke_history.cl / pair_gran_hertz_history.cl
 * compute the force and torque, so the wall physics is the pair physics.
 *
 * Geometry (style 0/1/2 = xplane/yplane/zplane, 3 = zcylinder):
 *   plane: del1 = x - lo, del2 = hi - x; the nearer face is the contact:
 *          del = +del1 (lo face) or -del2 (hi face) along the axis.
 *   zcylinder (axis z through the origin, radius R): delr = R - |x_xy|;
 *          del = -delr x_xy/|x_xy|; for Hertz reff = radi rwall/(rwall + radi)
 *          with rwall = -2R inside, +2R outside (LAMMPS' choice).
 *   contact when |del| <= radi (LAMMPS: rsq > rad^2 is no contact); out of
 *   contact the per-atom shear history is zeroed.
 * Wall velocity (wiggle/shear) comes from the host; for zcylinder with
 * tangential shear (axis x or y) the wall moves azimuthally with speed
 * vshear at the contact: vwall += vshear (y, -x)/|x_xy|, per atom. */

#define WALL_GRAN_KERNEL(NAME, EVAL)                                                          \
    __kernel void NAME(                                                                        \
        const int n, const uint groupbit, __global const uint *mask, __global const REAL *x,   \
        __global const REAL *v, __global const REAL *omega, __global const REAL *radius,       \
        __global const REAL *rmass, __global REAL *f, __global REAL *torque,                   \
        __global REAL *history, const int has_history, __global const REAL *param,             \
        const int style, const REAL lo, const REAL hi, const REAL cylradius,                    \
        const REAL vwx, const REAL vwy, const REAL vwz, const int cyl_shear,                  \
        const REAL vshear, const REAL dt, const int shearupdate)                             \
    {                                                                                          \
        const int i = get_global_id(0);                                                        \
        if (i >= n || !(mask[i] & groupbit))                                                   \
            return;                                                                            \
        const REAL3 xi = vload3(i, x);                                                         \
        const REAL radi = radius[i];                                                           \
        REAL3 del = (REAL3)(0);                                                                \
        REAL3 vwall = (REAL3)(vwx, vwy, vwz);                                                  \
        REAL rwall = 0;                                                                        \
        if (style <= 2) {                                                                      \
            const REAL xa = style == 0 ? xi.x : style == 1 ? xi.y : xi.z;                      \
            const REAL del1 = xa - lo, del2 = hi - xa;                                         \
            const REAL d = del1 < del2 ? del1 : -del2;                                         \
            if (style == 0)                                                                    \
                del.x = d;                                                                     \
            else if (style == 1)                                                               \
                del.y = d;                                                                     \
            else                                                                               \
                del.z = d;                                                                     \
        } else {                                                                               \
            const REAL delxy = sqrt(xi.x * xi.x + xi.y * xi.y);                                \
            const REAL delr = cylradius - delxy;                                               \
            if (delr > radi) {                                                                 \
                del.z = cylradius;                                                             \
            } else {                                                                           \
                del.x = -delr / delxy * xi.x;                                                  \
                del.y = -delr / delxy * xi.y;                                                  \
                rwall = delxy < cylradius ? -2 * cylradius : 2 * cylradius;                    \
                if (cyl_shear) {                                                               \
                    vwall.x += vshear * xi.y / delxy;                                          \
                    vwall.y += -vshear * xi.x / delxy;                                         \
                    vwall.z = 0;                                                               \
                }                                                                              \
            }                                                                                  \
        }                                                                                      \
        const REAL rsq = del.x * del.x + del.y * del.y + del.z * del.z;                        \
        if (rsq > radi * radi) {                                                               \
            if (has_history)                                                                   \
                vstore3((REAL3)(0), i, history);                                               \
            return;                                                                            \
        }                                                                                      \
        struct contact c;                                                                      \
        c.del = del;                                                                           \
        c.rsq = rsq;                                                                           \
        c.radi = radi;                                                                         \
        c.radj = 0;                                                                            \
        c.radsum = radi;                                                                       \
        c.reff = rwall == (REAL)0 ? radi : radi * rwall / (rwall + radi);                      \
        c.vr = vload3(i, v) - vwall;                                                           \
        c.omi = vload3(i, omega);                                                              \
        c.omj = (REAL3)(0);                                                                    \
        c.meff = rmass[i];                                                                     \
        c.dt = dt;                                                                             \
        c.shearupdate = shearupdate;                                                           \
        REAL3 sh = has_history ? vload3(i, history) : (REAL3)(0);                              \
        struct contact_force cf;                                                               \
        EVAL(&c, param, &sh, &cf);                                                             \
        const REAL3 fi = cf.f, ti = cf.ti;                                                     \
        if (has_history)                                                                       \
            vstore3(sh, i, history);                                                           \
        vstore3(vload3(i, f) + fi, i, f);                                                      \
        vstore3(vload3(i, torque) + ti, i, torque);                                            \
    }

WALL_GRAN_KERNEL(wall_gran_hooke, gran_hooke_eval)
WALL_GRAN_KERNEL(wall_gran_hooke_history, gran_hooke_history_eval)
WALL_GRAN_KERNEL(wall_gran_hertz_history, gran_hertz_history_eval)
