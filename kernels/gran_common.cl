/* gran_common.cl - the pieces every LAMMPS granular evaluator shares
 * (gran/hooke, gran/hooke/history, gran/hertz/history, and fix wall/gran
 * through them). Operations are written in the order of LAMMPS'
 * pair_gran_*.cpp so results match LAMMPS bit for bit, and every term is
 * exactly antisymmetric under i <-> j. Static inline: free when unused. */

/* Relative motion at the contact in LAMMPS pair gran's form: vnnr = vr.del,
 * and the tangential relative velocity of the contact points
 * vtr = vt - del x wr, wr = (radi omi + radj omj)/r, formed from del (not
 * from the unit normal as the contact's vt and vtr are, kernels/contact.cl)
 * to stay bit for bit with LAMMPS; 1/r, 1/rsq, vr.del and radi omi + radj
 * omj are the contact's. */
struct gran_kin {
    REAL r, rinv, rsqinv;
    REAL vnnr;
    REAL vtr1, vtr2, vtr3;
};

static inline struct gran_kin gran_kinematics(const struct contact *c)
{
    struct gran_kin k;
    const REAL delx = c->del.x, dely = c->del.y, delz = c->del.z;
    k.r = c->r;
    k.rinv = c->rinv;
    k.rsqinv = c->rsqinv;

    const REAL vr1 = c->vr.x, vr2 = c->vr.y, vr3 = c->vr.z;
    k.vnnr = c->vdel;
    const REAL vn1 = delx * k.vnnr * k.rsqinv;
    const REAL vn2 = dely * k.vnnr * k.rsqinv;
    const REAL vn3 = delz * k.vnnr * k.rsqinv;
    const REAL vt1 = vr1 - vn1, vt2 = vr2 - vn2, vt3 = vr3 - vn3;

    const REAL wr1 = c->w.x * k.rinv;
    const REAL wr2 = c->w.y * k.rinv;
    const REAL wr3 = c->w.z * k.rinv;

    k.vtr1 = vt1 - (delz * wr2 - dely * wr3);
    k.vtr2 = vt2 - (delx * wr3 - delz * wr1);
    k.vtr3 = vt3 - (dely * wr1 - delx * wr2);
    return k;
}

/* Normal force per unit del: ccel = poly (kn (radsum - r)/r - meff gamman vnnr/r^2),
 * F_n = del ccel; poly = 1 (Hooke) or sqrt(delta reff) (Hertz); with
 * limit_damping a net attractive ccel is clamped to 0. */
static inline REAL gran_normal(const struct contact *c, const struct gran_kin *k, REAL kn,
                               REAL gamman, REAL poly, REAL limit)
{
    const REAL damp = c->meff * gamman * k->vnnr * k->rsqinv;
    REAL ccel = kn * c->delta * k->rinv - damp;
    ccel *= poly;
    if (limit != (REAL)0 && ccel < (REAL)0)
        ccel = 0;
    return ccel;
}

/* Tangential force with shear history (LAMMPS hooke/history, hertz/history):
 * s += vtr dt (not during setup), rotated into the tangent plane;
 * F_t = -poly (kt s + meff gammat vtr), rescaled to the Coulomb limit
 * xmu |F_n| with s reset consistently. Updates *shear, returns F_t. */
static inline REAL3 gran_history_tangential(const struct contact *c, const struct gran_kin *k,
                                            REAL kt, REAL gammat, REAL xmu, REAL ccel,
                                            REAL poly, REAL3 *shear)
{
    const REAL delx = c->del.x, dely = c->del.y, delz = c->del.z;
    const REAL vtr1 = k->vtr1, vtr2 = k->vtr2, vtr3 = k->vtr3;
    const REAL meff = c->meff;
    REAL s1 = shear->x, s2 = shear->y, s3 = shear->z;
    if (c->shearupdate) {
        s1 += vtr1 * c->dt;
        s2 += vtr2 * c->dt;
        s3 += vtr3 * c->dt;
    }
    const REAL shrmag = sqrt(s1 * s1 + s2 * s2 + s3 * s3);

    REAL rsht = s1 * delx + s2 * dely + s3 * delz;
    rsht *= k->rsqinv;
    if (c->shearupdate) {
        s1 -= rsht * delx;
        s2 -= rsht * dely;
        s3 -= rsht * delz;
    }

    REAL fs1 = -poly * (kt * s1 + meff * gammat * vtr1);
    REAL fs2 = -poly * (kt * s2 + meff * gammat * vtr2);
    REAL fs3 = -poly * (kt * s3 + meff * gammat * vtr3);

    const REAL fs = sqrt(fs1 * fs1 + fs2 * fs2 + fs3 * fs3);
    const REAL fn = xmu * fabs(ccel * k->r);
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
    return (REAL3)(fs1, fs2, fs3);
}

/* Force on i = del ccel + F_t; lever-arm torque tc = (del x F_t) / r, so
 * the torque on i is -radi tc and on j -radj tc (struct contact_force). */
static inline void gran_apply(const struct contact *c, const struct gran_kin *k, REAL ccel,
                              REAL3 ft, struct contact_force *out)
{
    const REAL delx = c->del.x, dely = c->del.y, delz = c->del.z;
    out->f.x = delx * ccel + ft.x;
    out->f.y = dely * ccel + ft.y;
    out->f.z = delz * ccel + ft.z;

    const REAL tor1 = k->rinv * (dely * ft.z - delz * ft.y);
    const REAL tor2 = k->rinv * (delz * ft.x - delx * ft.z);
    const REAL tor3 = k->rinv * (delx * ft.y - dely * ft.x);
    out->tc = (REAL3)(tor1, tor2, tor3);
    out->tr = (REAL3)(0);
}
