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
                                   REAL3 *shear, REAL3 *force_i, REAL3 *torque_i)
{
    (void)shear;
    const REAL kn = param[0], gamman = param[2], gammat = param[3];
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
    if (limit != (REAL)0 && ccel < (REAL)0)
        ccel = 0;

    const REAL vtr1 = vt1 - (delz * wr2 - dely * wr3);
    const REAL vtr2 = vt2 - (delx * wr3 - delz * wr1);
    const REAL vtr3 = vt3 - (dely * wr1 - delx * wr2);
    REAL vrel = vtr1 * vtr1 + vtr2 * vtr2 + vtr3 * vtr3;
    vrel = sqrt(vrel);

    const REAL fn = xmu * fabs(ccel * r);
    const REAL fs = meff * gammat * vrel;
    REAL ft;
    if (vrel != (REAL)0)
        ft = fmin(fn, fs) / vrel;
    else
        ft = 0;

    const REAL fs1 = -ft * vtr1;
    const REAL fs2 = -ft * vtr2;
    const REAL fs3 = -ft * vtr3;

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
