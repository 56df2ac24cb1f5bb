/* pair_gran_hertz_history.cl - Hertzian contact with shear history
 * (LAMMPS pair gran/hertz/history, 2021 semantics): the Hooke/history
 * law with normal and tangential forces scaled by polyhertz = sqrt(delta reff).
 *
 * Normal:  F_n = (kn delta - meff gamman v_n) n   with delta = radsum - r,
 *          written as ccel = kn (radsum - r)/r - meff gamman (vr.del)/r^2,
 *          F = del ccel; limit_damping clamps ccel >= 0.
 * Tangent: shear displacement s += vtr dt (not during setup), rotated into
 *          the tangent plane; F_t = -(kt s + meff gammat vtr), rescaled to the
 *          Coulomb limit xmu |F_n| (s is reset consistently).
 * Torque on i: -radi (del x F_t) / r.
 * Param layout (GRAN_*): kn kt gamman gammat xmu limit_damping.
 * Exactly antisymmetric under i <-> j: del, vr, vtr, s and F_t change sign,
 * every product and sum is formed the same way from both sides. */

static inline void gran_hertz_history_eval(const struct contact *c, __global const REAL *param,
                                           REAL3 *shear, struct contact_force *out)
{
    const REAL kn = param[GRAN_KN], kt = param[GRAN_KT], gamman = param[GRAN_GAMMAN];
    const REAL gammat = param[GRAN_GAMMAT], xmu = param[GRAN_XMU], limit = param[GRAN_LIMIT];
    const struct gran_kin k = gran_kinematics(c);
    const REAL polyhertz = sqrt(c->delta * c->reff);
    const REAL ccel = gran_normal(c, &k, kn, gamman, polyhertz, limit);
    const REAL3 ft = gran_history_tangential(c, &k, kt, gammat, xmu, ccel, polyhertz, shear);
    gran_apply(c, &k, ccel, ft, out);
}
