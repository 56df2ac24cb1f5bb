/* pair_gran_hooke.cl - Hookean contact without shear history
 * (LAMMPS pair gran/hooke, 2021 semantics).
 *
 * Normal:  ccel = kn (radsum - r)/r - meff gamman (vr.del)/r^2, F = del ccel
 *          (limit_damping clamps ccel >= 0).
 * Tangent: pure velocity damping, F_t = -min(xmu |F_n|, meff gammat |vtr|)
 *          vtr/|vtr|; kt is not used.
 * Torque on i: -radi (del x F_t) / r. `shear` is ignored.
 * Param layout (GRAN_*): kn kt gamman gammat xmu limit_damping. */

static inline void gran_hooke_eval(const struct contact *c, __global const REAL *param,
                                   REAL3 *shear, struct contact_force *out)
{
    (void)shear;
    const REAL kn = param[GRAN_KN], gamman = param[GRAN_GAMMAN], gammat = param[GRAN_GAMMAT];
    const REAL xmu = param[GRAN_XMU], limit = param[GRAN_LIMIT];
    const struct gran_kin k = gran_kinematics(c);
    const REAL ccel = gran_normal(c, &k, kn, gamman, (REAL)1, limit);

    /* velocity damping capped by Coulomb: |F_t| = min(xmu |F_n|, meff gammat |vtr|) */
    const REAL vrel = sqrt(k.vtr1 * k.vtr1 + k.vtr2 * k.vtr2 + k.vtr3 * k.vtr3);
    const REAL fn = xmu * fabs(ccel * k.r);
    const REAL fs = c->meff * gammat * vrel;
    const REAL ft = vrel != (REAL)0 ? fmin(fn, fs) / vrel : (REAL)0;
    gran_apply(c, &k, ccel, (REAL3)(-ft * k.vtr1, -ft * k.vtr2, -ft * k.vtr3), out);
}

/* collision time (kernels/accuracy.cl): the damped linear spring */
static inline REAL gran_hooke_eval_tcol(const struct contact *c, __global const REAL *param,
                                        const REAL vn)
{
    (void)vn;
    return tcol_linear(param[GRAN_KN], param[GRAN_GAMMAN], c->meff);
}
