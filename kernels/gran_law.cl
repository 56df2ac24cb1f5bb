/* gran_law.cl - the LAMMPS gran laws (pair gran/hooke, gran/hooke/history,
 * gran/hertz/history, 2021 semantics; and fix wall/gran through them),
 * written once in lane-generic form (kernels/lanes.cl: a template added per
 * lane width). Width 1 serves every contact source through the adapters of
 * kernels/gran_common.cl; the pair kernel evaluates PAIR_LW contacts per
 * work-item at the device's width (kernels/pair_loop.cl).
 *
 * Operations are written in the order of LAMMPS's pair_gran_*.cpp so
 * results match LAMMPS bit for bit, and every term is exactly antisymmetric
 * under i <-> j: del, vr, vtr, the shear and F_t change sign, every product
 * and sum is formed the same way from both sides.
 *
 * Normal:  ccel = poly (kn delta / r - meff gamman (vr.del) / r^2),
 *          F_n = del ccel; poly = 1 (Hooke) or sqrt(delta reff) (Hertz);
 *          limit_damping clamps a net attractive ccel to 0.
 * Tangent: hooke: velocity damping capped by Coulomb,
 *          |F_t| = min(xmu |F_n|, meff gammat |vtr|);
 *          history: shear s += vtr dt (not during setup), rotated into the
 *          tangent plane; F_t = -poly (kt s + meff gammat vtr), rescaled to
 *          the Coulomb limit xmu |F_n| with s reset consistently.
 * Torque:  tc = (del x F_t) / r: on i -radi tc, on j -radj tc. */

/* What a gran law reads of LW contacts (struct contact's fields) */
struct LN(gran_in) {
    struct LN(lr3) del;     /* x_i - x_j */
    struct LN(lr3) vr;      /* v_i - v_j */
    struct LN(lr3) w;       /* radi omi + radj omj */
    LR r, rinv, rsqinv;     /* |del|, 1 / r, 1 / r^2 */
    LR delta;               /* overlap */
    LR reff;                /* effective radius */
    LR vdel;                /* vr . del */
    LR meff;                /* effective mass */
    REAL dt;                /* the step (the same for every lane) */
    int shearupdate;        /* 0 during setup: the shear is not advanced */
};

/* a type pair's coefficients (param layout GRAN_*, kernels/param_layout.h) */
struct LN(gran_par) {
    LR kn, kt, gamman, gammat, xmu, limit;
};

/* the force on i and the lever-arm torque (struct contact_force's f, tc) */
struct LN(gran_out) {
    struct LN(lr3) f, tc;
};

/* The tangential relative velocity of the contact points in LAMMPS pair
 * gran's form: vtr = vt - del x wr, vt = vr - del (vr.del) / r^2,
 * wr = (radi omi + radj omj) / r (formed from del, not from the unit
 * normal, to stay bit for bit with LAMMPS). */
static inline struct LN(lr3) LN(gran_vtr)(const struct LN(gran_in) *c)
{
    const LR delx = c->del.x, dely = c->del.y, delz = c->del.z;
    const LR vn1 = delx * c->vdel * c->rsqinv;
    const LR vn2 = dely * c->vdel * c->rsqinv;
    const LR vn3 = delz * c->vdel * c->rsqinv;
    const LR vt1 = c->vr.x - vn1, vt2 = c->vr.y - vn2, vt3 = c->vr.z - vn3;
    const LR wr1 = c->w.x * c->rinv;
    const LR wr2 = c->w.y * c->rinv;
    const LR wr3 = c->w.z * c->rinv;
    return LN(lr3_of)(vt1 - (delz * wr2 - dely * wr3), vt2 - (delx * wr3 - delz * wr1),
                      vt3 - (dely * wr1 - delx * wr2));
}

/* Normal force per unit del (ccel, F_n = del ccel) */
static inline LR LN(gran_normal)(const struct LN(gran_in) *c, const struct LN(gran_par) *p,
                                 const LR poly)
{
    const LR damp = c->meff * p->gamman * c->vdel * c->rsqinv;
    LR ccel = p->kn * c->delta * c->rinv - damp;
    ccel *= poly;
    return LSEL(ccel, (LR)0, (p->limit != (LR)0) & (ccel < (LR)0));
}

/* hooke: velocity damping capped by Coulomb */
static inline struct LN(lr3) LN(gran_damped_tangential)(const struct LN(gran_in) *c,
                                                        const struct LN(gran_par) *p,
                                                        const struct LN(lr3) vtr,
                                                        const LR ccel)
{
    const LR vrel = sqrt(vtr.x * vtr.x + vtr.y * vtr.y + vtr.z * vtr.z);
    const LR fn = p->xmu * fabs(ccel * c->r);
    const LR fs = c->meff * p->gammat * vrel;
    const LR ft = LSEL((LR)0, fmin(fn, fs) / vrel, vrel != (LR)0);
    return LN(lr3_of)(-ft * vtr.x, -ft * vtr.y, -ft * vtr.z);
}

/* history: the shear spring, rescaled to the Coulomb limit; updates *s */
static inline struct LN(lr3) LN(gran_history_tangential)(const struct LN(gran_in) *c,
                                                         const struct LN(gran_par) *p,
                                                         const struct LN(lr3) vtr,
                                                         const LR ccel, const LR poly,
                                                         struct LN(lr3) *s)
{
    const LR delx = c->del.x, dely = c->del.y, delz = c->del.z;
    const LR meff = c->meff, kt = p->kt, gammat = p->gammat;
    LR s1 = s->x, s2 = s->y, s3 = s->z;
    if (c->shearupdate) {
        s1 += vtr.x * c->dt;
        s2 += vtr.y * c->dt;
        s3 += vtr.z * c->dt;
    }
    const LR shrmag = sqrt(s1 * s1 + s2 * s2 + s3 * s3);

    LR rsht = s1 * delx + s2 * dely + s3 * delz;
    rsht *= c->rsqinv;
    if (c->shearupdate) {
        s1 -= rsht * delx;
        s2 -= rsht * dely;
        s3 -= rsht * delz;
    }

    const LR fs1 = -poly * (kt * s1 + meff * gammat * vtr.x);
    const LR fs2 = -poly * (kt * s2 + meff * gammat * vtr.y);
    const LR fs3 = -poly * (kt * s3 + meff * gammat * vtr.z);

    /* beyond the Coulomb limit: the spring's shear rescaled, or no force
     * at all without shear (both arms computed; the lanes pick) */
    const LR fs = sqrt(fs1 * fs1 + fs2 * fs2 + fs3 * fs3);
    const LR fn = p->xmu * fabs(ccel * c->r);
    const LRI slip = fs > fn, sheared = shrmag != (LR)0;
    const LRI rescale = slip & sheared;
    const LR q = fn / fs;
    s->x = LSEL(s1, q * (s1 + meff * gammat * vtr.x / kt) - meff * gammat * vtr.x / kt, rescale);
    s->y = LSEL(s2, q * (s2 + meff * gammat * vtr.y / kt) - meff * gammat * vtr.y / kt, rescale);
    s->z = LSEL(s3, q * (s3 + meff * gammat * vtr.z / kt) - meff * gammat * vtr.z / kt, rescale);
    return LN(lr3_of)(LSEL(fs1, LSEL((LR)0, fs1 * q, sheared), slip),
                      LSEL(fs2, LSEL((LR)0, fs2 * q, sheared), slip),
                      LSEL(fs3, LSEL((LR)0, fs3 * q, sheared), slip));
}

/* F = del ccel + F_t, tc = (del x F_t) / r */
static inline void LN(gran_apply)(const struct LN(gran_in) *c, const LR ccel,
                                  const struct LN(lr3) ft, struct LN(gran_out) *o)
{
    const LR delx = c->del.x, dely = c->del.y, delz = c->del.z;
    o->f = LN(lr3_of)(delx * ccel + ft.x, dely * ccel + ft.y, delz * ccel + ft.z);
    o->tc = LN(lr3_of)(c->rinv * (dely * ft.z - delz * ft.y), c->rinv * (delz * ft.x - delx * ft.z),
                       c->rinv * (delx * ft.y - dely * ft.x));
}

/* The three laws; the shear s is left alone by gran_hooke */
static inline void LN(gran_hooke)(const struct LN(gran_in) *c, const struct LN(gran_par) *p,
                                  struct LN(lr3) *s, struct LN(gran_out) *o)
{
    (void)s;
    const struct LN(lr3) vtr = LN(gran_vtr)(c);
    const LR ccel = LN(gran_normal)(c, p, (LR)1);
    LN(gran_apply)(c, ccel, LN(gran_damped_tangential)(c, p, vtr, ccel), o);
}

static inline void LN(gran_hooke_history)(const struct LN(gran_in) *c,
                                          const struct LN(gran_par) *p, struct LN(lr3) *s,
                                          struct LN(gran_out) *o)
{
    const struct LN(lr3) vtr = LN(gran_vtr)(c);
    const LR ccel = LN(gran_normal)(c, p, (LR)1);
    LN(gran_apply)(c, ccel, LN(gran_history_tangential)(c, p, vtr, ccel, (LR)1, s), o);
}

static inline void LN(gran_hertz_history)(const struct LN(gran_in) *c,
                                          const struct LN(gran_par) *p, struct LN(lr3) *s,
                                          struct LN(gran_out) *o)
{
    const struct LN(lr3) vtr = LN(gran_vtr)(c);
    const LR polyhertz = sqrt(c->delta * c->reff);
    const LR ccel = LN(gran_normal)(c, p, polyhertz);
    LN(gran_apply)(c, ccel, LN(gran_history_tangential)(c, p, vtr, ccel, polyhertz, s), o);
}
