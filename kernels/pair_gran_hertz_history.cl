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
                                           REAL3 *shear, REAL3 *force_i, REAL3 *torque_i)
{
    const REAL kn = param[0], kt = param[1], gamman = param[2], gammat = param[3];
    const REAL xmu = param[4], limit = param[5];
    const REAL delx = c->del.x, dely = c->del.y, delz = c->del.z;
    const REAL rsq = c->rsq;
    const REAL r = sqrt(rsq);
    const REAL rinv = (REAL)1 / r;
    const REAL rsqinv = (REAL)1 / rsq;

    const REAL vr1 = c->vr.x, vr2 = c->vr.y, vr3 = c->vr.z;
    const REAL vnnr = vr1 * delx + vr2 * dely + vr3 * delz;
    const REAL vn1 = delx * vnnr * rsqinv;
    const REAL vn2 = dely * vnnr * rsqinv;
    const REAL vn3 = delz * vnnr * rsqinv;
    const REAL vt1 = vr1 - vn1, vt2 = vr2 - vn2, vt3 = vr3 - vn3;

    const REAL wr1 = (c->radi * c->omi.x + c->radj * c->omj.x) * rinv;
    const REAL wr2 = (c->radi * c->omi.y + c->radj * c->omj.y) * rinv;
    const REAL wr3 = (c->radi * c->omi.z + c->radj * c->omj.z) * rinv;

    const REAL meff = c->meff;
    const REAL damp = meff * gamman * vnnr * rsqinv;
    REAL ccel = kn * (c->radsum - r) * rinv - damp;
    const REAL polyhertz = sqrt((c->radsum - r) * c->reff);
    ccel *= polyhertz;
    if (limit != (REAL)0 && ccel < (REAL)0)
        ccel = 0;

    const REAL vtr1 = vt1 - (delz * wr2 - dely * wr3);
    const REAL vtr2 = vt2 - (delx * wr3 - delz * wr1);
    const REAL vtr3 = vt3 - (dely * wr1 - delx * wr2);

    REAL s1 = shear->x, s2 = shear->y, s3 = shear->z;
    if (c->shearupdate) {
        s1 += vtr1 * c->dt;
        s2 += vtr2 * c->dt;
        s3 += vtr3 * c->dt;
    }
    const REAL shrmag = sqrt(s1 * s1 + s2 * s2 + s3 * s3);

    REAL rsht = s1 * delx + s2 * dely + s3 * delz;
    rsht *= rsqinv;
    if (c->shearupdate) {
        s1 -= rsht * delx;
        s2 -= rsht * dely;
        s3 -= rsht * delz;
    }

    REAL fs1 = -polyhertz * (kt * s1 + meff * gammat * vtr1);
    REAL fs2 = -polyhertz * (kt * s2 + meff * gammat * vtr2);
    REAL fs3 = -polyhertz * (kt * s3 + meff * gammat * vtr3);

    const REAL fs = sqrt(fs1 * fs1 + fs2 * fs2 + fs3 * fs3);
    const REAL fn = xmu * fabs(ccel * r);
    if (fs > fn) {
        if (shrmag != (REAL)0) {
            s1 = (fn / fs) * (s1 + meff * gammat * vtr1 / kt) - meff * gammat * vtr1 / kt;
            s2 = (fn / fs) * (s2 + meff * gammat * vtr2 / kt) - meff * gammat * vtr2 / kt;
            s3 = (fn / fs) * (s3 + meff * gammat * vtr3 / kt) - meff * gammat * vtr3 / kt;
            fs1 *= fn / fs;
            fs2 *= fn / fs;
            fs3 *= fn / fs;
        } else {
            fs1 = fs2 = fs3 = 0;
        }
    }
    shear->x = s1;
    shear->y = s2;
    shear->z = s3;

    force_i->x = delx * ccel + fs1;
    force_i->y = dely * ccel + fs2;
    force_i->z = delz * ccel + fs3;

    const REAL tor1 = rinv * (dely * fs3 - delz * fs2);
    const REAL tor2 = rinv * (delz * fs1 - delx * fs3);
    const REAL tor3 = rinv * (delx * fs2 - dely * fs1);
    torque_i->x = -c->radi * tor1;
    torque_i->y = -c->radi * tor2;
    torque_i->z = -c->radi * tor3;
}
