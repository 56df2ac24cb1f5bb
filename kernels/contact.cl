/* contact.cl - one contact, whatever made it: the contact record the laws
 * read, and the one body that evaluates a contact for every source
 * (particle pairs, kernels/pair_loop.cl; plane and cylinder walls and mesh
 * triangles, kernels/wall.cl; region surfaces, kernels/wall_region.cl).
 *
 * A source only finds the geometry of a possible contact of particle i (a
 * struct contact_site: the separation del from the partner's closest point,
 * the partner's radius or the wall's curvature, whether it may act) and
 * says where the partner's motion comes from (struct contact_partner). The
 * body then does, in this order, for every source alike:
 *   1. the reach gate: |del| < reach (<= for an inclusive wall), a jkr
 *      contact held beyond touch only once it has touched, and with
 *      approach a contact apart that one drift at its normal rate closes
 *      or opens (contact_normal_linear);
 *   2. building the contact (contact_make) and refining its overlap from
 *      the split position parts (contact_refine, SPLIT_POS);
 *   3. the contact's kinematics (contact_kinematics: normal, normal rate,
 *      tangential and contact-point velocities), computed once and read by
 *      every law and by the accuracy notes; then
 *      the law's evaluation, in its 3-vector (REAL3 shear) or history-row
 *      form, on the contact's history row held in private memory;
 *   4. the accuracy note (kernels/accuracy.cl): the pair record of the
 *      contact, or the wall record of particle i;
 *   5. history zeroing of a contact that does not act;
 *   6. the force and the torques on both sides (struct contact_out).
 * The source keeps the history slot: it loads the row before the body and
 * stores it after (contact_hist_store).
 *
 * Laws are pure functions <law>_eval(c, param, shear or row, out) with a
 * collision time <law>_eval_tcol(c, param, vn) (kernels/accuracy.cl);
 * CONTACT_BODY instantiates the body for one law. */

/* One contact between particle i and particle (or wall) j, as the pair
 * evaluators see it. Sign convention: del = x_i - x_j, vr = v_i - v_j. */
struct contact {
    REAL3 del;          /* x_i - x_j (minimum image) */
    REAL rsq;           /* |del|^2 */
    REAL r;             /* |del| */
    REAL delta;         /* overlap radsum - r (the laws read r and delta from here:
                         * with SPLIT_POS contact_refine computes them from the
                         * split positions) */
    REAL radi, radj;    /* radii (radj = 0 for a flat wall) */
    REAL radsum;        /* radi + radj */
    REAL reff;          /* radi radj / radsum (radi for a wall) */
    REAL3 vr;           /* v_i - v_j */
    REAL3 omi, omj;     /* angular velocities (omj = 0 for a wall) */
    REAL meff;          /* effective mass (LAMMPS: frozen partner -> other mass) */
    REAL mi, mj;        /* the masses of i and j (mj = 0 for a wall; LIGGGHTS's epsd
                         * rolling inertia) */
    REAL dt;            /* time step */
    int shearupdate;    /* 0 during setup: history is not advanced */
    int approach;       /* 1: the caller also evaluates pairs apart that one
                         * drift at their normal rate brings into or out of
                         * contact (PAIR_APPROACH, contact_normal_linear) */
    /* The kinematics, computed once per contact by contact_kinematics (the
     * body, after refinement and the velocity remap) and read by the laws
     * and the accuracy notes: */
    REAL rinv, rsqinv;  /* 1 / r, 1 / rsq */
    REAL3 n;            /* del / r: the unit normal, from j to i */
    REAL vn;            /* vr . n: the normal rate (> 0 apart) */
    REAL vdel;          /* vr . del */
    REAL3 w;            /* radi omi + radj omj */
    REAL3 vt;           /* vr - vn n: the tangential relative velocity of the centres */
    REAL3 vtr;          /* vt + n x w: the relative velocity of the contact points */
#ifdef HAS_HEAT
    REAL ti, tj;        /* temperatures of i and of the partner (a wall's own) */
#endif
};

/* What an evaluator returns for one contact: the force on i (the force on j
 * is exactly -f) and the torques in two parts, a lever-arm part tc and an
 * antisymmetric part tr (rolling resistance; zero for most laws):
 *   torque on i = -radi tc - tr,   torque on j = -radj tc + tr
 * (LAMMPS' newton-pair update, bit for bit what j's own evaluation of the
 * reversed contact gives). */
struct contact_force {
    REAL3 f;
    REAL3 tc, tr;
#ifdef HAS_HEAT
    REAL q;             /* heat flowing into i (into j: exactly -q); 0 without a heat model */
#endif
};

static inline REAL3 contact_torque_i(const struct contact *c, const struct contact_force *o)
{
    return -c->radi * o->tc - o->tr;
}

/* The one way a contact is built, for a particle partner (pair_loop.cl) and
 * for a wall element (wall.cl, radj = 0, omj = 0): geometry and relative
 * motion at the contact; dt and shearupdate are set by the caller. */
static inline struct contact contact_make(const REAL3 del, const REAL radi, const REAL radj,
                                          const REAL reff, const REAL3 vr, const REAL3 omi,
                                          const REAL3 omj, const REAL meff)
{
    struct contact c;
    c.del = del;
    c.rsq = del.x * del.x + del.y * del.y + del.z * del.z;
    c.radi = radi;
    c.radj = radj;
    c.radsum = radi + radj;
    c.r = sqrt(c.rsq);
    c.delta = c.radsum - c.r;
    c.reff = reff;
    c.vr = vr;
    c.omi = omi;
    c.omj = omj;
    c.meff = meff;
    c.approach = 0;
    return c;
}

#ifdef SPLIT_POS
/* The refined length *r and overlap *delta of a split separation del +
 * del_lo between spheres of radii radi, radj (contact_refine's arithmetic,
 * shared with the history transfer's overlap test, contact_pair_overlaps). */
static inline void contact_split_r(const REAL3 del, const REAL3 del_lo, const REAL radi,
                                   const REAL radj, REAL *r, REAL *delta)
{
#ifdef HAS_FP64
    const double dx = (double)del.x + (double)del_lo.x;
    const double dy = (double)del.y + (double)del_lo.y;
    const double dz = (double)del.z + (double)del_lo.z;
    const double rd = sqrt(dx * dx + dy * dy + dz * dz);
    *r = (REAL)rd;
    *delta = (REAL)(((double)radi + (double)radj) - rd);
#else
    const REAL3 d = del + del_lo;
    *r = sqrt(dot(d, d));
    *delta = (radi + radj) - *r;
#endif
}
#endif

/* The separation and overlap of contact c from the split parts: del_lo is
 * the low part of x_i - x_j (SPLIT_POS). With double support they are
 * evaluated in double ((radi + radj) - |del + del_lo|), so an overlap far
 * below a float spacing of the radius keeps its digits; else in REAL.
 * Returns 0 when the refined overlap is not positive (no contact). */
static inline int contact_refine(struct contact *c, const REAL3 del_lo)
{
#ifdef SPLIT_POS
    contact_split_r(c->del, del_lo, c->radi, c->radj, &c->r, &c->delta);
    c->del = c->del + del_lo;
    c->rsq = c->r * c->r;
    return c->delta > (REAL)0;
#else
    (void)c;
    (void)del_lo;
    return 1;
#endif
}

/* The effective radius of a sphere against a wall of curvature radius
 * rwall at the contact (0 flat: radi; < 0 concave; LAMMPS's choice). */
static inline REAL wall_reff(const REAL radi, const REAL rwall)
{
    return rwall == (REAL)0 ? radi : radi * rwall / (rwall + radi);
}

/* The low part of the gap del of the sphere's hi part (SPLIT_POS): the normal
 * component of the position's low part xl, so a flat or curved wall sees the
 * particle's 48-bit position (contact_refine); tangential parts do not
 * change the gap. */
static inline REAL3 wall_gap_lo(const REAL3 del, const REAL3 xl)
{
#ifdef SPLIT_POS
    const REAL dd = dot(del, del);
    return dd > (REAL)0 ? (dot(xl, del) / dd) * del : (REAL3)(0);
#else
    (void)del;
    (void)xl;
    return (REAL3)(0);
#endif
}

/* The contact sources (the body's `kind`, a constant at every call site) */
#define CONTACT_PAIR 0  /* particle i with particle j */
#define CONTACT_WALL 1  /* particle i with a wall element: plane, cylinder, region, triangle */

/* What a source found: one possible contact of particle i. */
struct contact_site {
    REAL3 del;      /* x_i - the partner's closest point (hi part; minimum image for pairs) */
    REAL3 del_lo;   /* the low part of del (SPLIT_POS; 0 otherwise) */
    REAL radi;      /* particle i's radius */
    REAL radj;      /* the partner's radius (0: a wall) */
    REAL rwall;     /* a wall's curvature radius at the point (0 flat, < 0 concave) */
    REAL rgiven;    /* >= 0: the source's own |del| (a region surface: LAMMPS's r) */
    REAL reach;     /* the contact acts while |del| < reach (<= with inclusive) */
    int acts;       /* 0: the element cannot act (the far face of a plane pair ...) */
    int gated;      /* 1: the source has decided that it acts (mesh, region; cohesion) */
    int refine;     /* 1: overlap from the split position parts (contact_refine) */
    int approach;   /* also contacts apart that one drift at their normal rate
                     * brings into or out of contact (PAIR_APPROACH) */
    int inclusive;  /* |del| = reach acts (LAMMPS fix wall/gran) */
    int hold;       /* >= 0: the row index of a jkr touch flag: beyond touch
                     * the contact acts only once it has touched */
    int hzero;      /* history REAL a contact that does not act forgets */
    int note;       /* 1: write the accuracy record (note_idx: pair contact
                     * or particle; acode: the wall's code) */
    int note_idx, acode;
};

/* Where the partner's motion comes from; loaded only for a contact that
 * passes the gate. */
struct contact_partner {
    int j;                          /* CONTACT_PAIR: the partner particle */
    uint freezebit;                 /* a partner in this group lends its mass: meff = m_other */
    __global const uint *mask;
    REAL3 vwall, omwall;            /* CONTACT_WALL: the surface's velocity at the
                                     * point and its angular velocity */
    int vremap;                     /* VREMAP: the partner's image streams with the box */
    REAL3 vimage;                   /* ... at this velocity (kernels/common.cl image_velocity) */
#ifdef HAS_HEAT
    REAL twall;                     /* CONTACT_WALL: the wall's temperature */
#endif
};

/* The particle arrays and step data every body reads. */
struct contact_atoms {
    __global const REAL *v, *omega, *rmass;
    REAL dt;
    int shearupdate;
    __global float *acc;            /* accuracy records (kernels/accuracy.cl) */
    __global int *astep;
    int step;
#ifdef HAS_HEAT
    __global const REAL *temp;      /* the atoms' temperatures (contact_atoms_heat) */
#endif
};

/* The particle arrays and step data of a kernel's contacts */
static inline struct contact_atoms contact_atoms_of(__global const REAL *v,
                                                   __global const REAL *omega,
                                                   __global const REAL *rmass, const REAL dt,
                                                   const int shearupdate, __global float *acc,
                                                   __global int *astep, const int step)
{
    struct contact_atoms a;
    a.v = v;
    a.omega = omega;
    a.rmass = rmass;
    a.dt = dt;
    a.shearupdate = shearupdate;
    a.acc = acc;
    a.astep = astep;
    a.step = step;
    return a;
}

/* With HAS_HEAT (fix property/atom temperature heatflow): the atoms'
 * temperatures the contacts read. */
#ifdef HAS_HEAT
#define contact_atoms_heat(a, t) ((a).temp = (t))
#else
#define contact_atoms_heat(a, t) (void)(t)
#endif

/* What a contact gives: the force on i (on j: exactly -f) and the torques
 * on i and j (struct contact_force's two parts); with HAS_HEAT the heat
 * flowing into i (into j: -q). */
struct contact_out {
    REAL3 f, ti, tj;
    REAL3 tc;           /* the law's tc: with tr = 0, ti = -radi tc and tj = -radj tc */
#ifdef HAS_HEAT
    REAL q;
#endif
};

/* |normal rate| dt > gap of a pair apart (rsq >= radsum^2): the next drift
 * at this rate closes the gap, or the last one opened it */
static inline int pair_within_drift(const REAL3 vr, const REAL3 del, const REAL rsq,
                                    const REAL radsum, const REAL dt)
{
    const REAL dv = fabs(dot(vr, del)) * dt;
    /* r (r - radsum) >= (rsq - radsum^2) / 2: most pairs leave without the sqrt */
    if (dv <= (REAL)0.5 * (rsq - radsum * radsum))
        return 0;
    const REAL r = sqrt(rsq);
    return dv > r * (r - radsum);
}

/* the same for a sphere apart from a wall element (gap |dtest| - radi > 0) */
static inline int wall_within_drift(const REAL3 vrel, const REAL3 dtest, const REAL rsq,
                                    const REAL radi, const REAL dt)
{
    const REAL r = sqrt(rsq);
    return fabs(dot(vrel, dtest)) * dt > r * (r - radi);
}

/* The contact of i with its partner: geometry and relative motion. */
static inline struct contact contact_build(const int kind, const int i,
                                           const struct contact_site *s,
                                           const struct contact_partner *pj,
                                           const struct contact_atoms *a)
{
#ifdef HAS_ROTATION
    const REAL3 omi = vload3(i, a->omega);
#else
    const REAL3 omi = (REAL3)(0);
#endif
    if (kind == CONTACT_PAIR) {
        const int j = pj->j;
#ifdef HAS_ROTATION
        const REAL3 omj = vload3(j, a->omega);
#else
        const REAL3 omj = (REAL3)(0);
#endif
        const REAL mi = a->rmass[i], mj = a->rmass[j];
        REAL meff = mi * mj / (mi + mj);
        if (pj->mask[i] & pj->freezebit)
            meff = mj;
        if (pj->mask[j] & pj->freezebit)
            meff = mi;
        struct contact k = contact_make(s->del, s->radi, s->radj,
                                        s->radi * s->radj / (s->radi + s->radj),
                                        vload3(i, a->v) - vload3(j, a->v), omi, omj, meff);
        k.mi = mi;
        k.mj = mj;
#ifdef HAS_HEAT
        k.ti = a->temp[i];
        k.tj = a->temp[j];
#endif
        return k;
    }
    struct contact k = contact_make(s->del, s->radi, 0, wall_reff(s->radi, s->rwall),
                                    vload3(i, a->v) - pj->vwall, omi, pj->omwall, a->rmass[i]);
    k.mi = k.meff;
    k.mj = 0;
#ifdef HAS_HEAT
    k.ti = a->temp[i];
    k.tj = pj->twall;
#endif
    if (s->rgiven >= (REAL)0) { /* LAMMPS: rsq = r^2, then r = sqrt(rsq) */
        k.rsq = s->rgiven * s->rgiven;
        k.r = sqrt(k.rsq);
        k.delta = k.radsum - k.r;
    }
    return k;
}

/* The gate's |del|^2 (del: the whole separation, hi + lo parts) */
static inline REAL contact_gate_rsq(const REAL3 d)
{
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

/* Whether two particles overlap as a pair contact's gate decides it
 * (contact_gate for a pair site that is neither gated nor approaching:
 * |del| < radi + radj, then with SPLIT_POS the refined overlap > 0), from the
 * minimum-image separation del and its low part del_lo. The history
 * transfer at a rebuild keeps a contact's history by this very test
 * (kernels/neighbor.cl, hist_transfer), so a rebuild forgets exactly the
 * histories the pair kernel would zero at that step: results do not depend
 * on the rebuild schedule. */
static inline int contact_pair_overlaps(const REAL3 del, const REAL3 del_lo, const REAL radi,
                                        const REAL radj)
{
    const REAL reach = radi + radj;
#ifdef SPLIT_POS
    if (!(contact_gate_rsq(del + del_lo) < reach * reach))
        return 0;
    REAL r, delta;
    contact_split_r(del, del_lo, radi, radj, &r, &delta);
    return delta > (REAL)0;
#else
    (void)del_lo;
    return contact_gate_rsq(del) < reach * reach;
#endif
}

/* Steps 1 and 2 of the body: 1 when the site acts, with *k built. */
static inline int contact_gate(const int kind, const int i, const struct contact_site *s,
                               const struct contact_partner *pj, const struct contact_atoms *a,
                               const REAL *h, struct contact *k)
{
#ifdef SPLIT_POS
    const REAL3 dtest = s->del + s->del_lo;
#else
    const REAL3 dtest = s->del;
#endif
    const REAL rsq = s->rgiven >= (REAL)0 ? s->rgiven * s->rgiven : contact_gate_rsq(dtest);
    if (kind == CONTACT_PAIR) {
        if (s->gated) { /* cohesion reaches beyond contact: every pair within reach */
            if (rsq >= s->reach * s->reach)
                return 0;
            *k = contact_build(kind, i, s, pj, a);
            contact_refine(k, s->del_lo);
            return 1;
        }
        int touch = 0;
        if (rsq < s->reach * s->reach) {
            *k = contact_build(kind, i, s, pj, a);
            touch = contact_refine(k, s->del_lo);
        }
        if (s->approach && !touch &&
            pair_within_drift(vload3(i, a->v) - vload3(pj->j, a->v), dtest, rsq, s->reach, a->dt)) {
            *k = contact_build(kind, i, s, pj, a);
            contact_refine(k, s->del_lo);
            touch = 1;
        }
        return touch;
    }
    int touch = s->gated || (s->acts && (s->inclusive ? rsq <= s->reach * s->reach
                                                      : rsq < s->reach * s->reach));
    if (s->hold >= 0 && touch && h[s->hold] == (REAL)0 && rsq > s->radi * s->radi)
        touch = 0; /* not touched yet: no hold beyond touch */
    const int near_ = s->approach && s->acts && !touch &&
                      wall_within_drift(vload3(i, a->v) - pj->vwall, dtest, rsq, s->radi, a->dt);
    if (!touch && !near_)
        return 0;
    *k = contact_build(kind, i, s, pj, a);
    if (s->refine)
        return contact_refine(k, s->del_lo) || s->approach || s->hold >= 0;
    return 1;
}

/* The normal/tangential kinematics of a built contact (struct contact's
 * last fields), in the order every law reads them. */
static inline void contact_kinematics(struct contact *k)
{
    k->rinv = (REAL)1 / k->r;
    k->rsqinv = (REAL)1 / k->rsq;
    k->n = k->del * k->rinv;
    k->vn = dot(k->vr, k->n);
    k->vdel = dot(k->vr, k->del);
    k->w = k->radi * k->omi + k->radj * k->omj;
    k->vt = k->vr - k->vn * k->n;
    k->vtr = k->vt + cross(k->n, k->w);
}

/* Step 6: the force and both torques (LAMMPS's newton-pair update) */
static inline void contact_out_set(const struct contact *k, const struct contact_force *cf,
                                   struct contact_out *o)
{
    o->f = cf->f;
    o->ti = contact_torque_i(k, cf);
    o->tj = -k->radj * cf->tc + cf->tr;
    o->tc = cf->tc;
#ifdef HAS_HEAT
    o->q = cf->q;
#endif
}

/* A contact's history row back to its slot: all n REAL when it acted; when
 * it did not, the forgotten ones (zero in h), written only where the slot
 * is not zero already (most are). */
static inline void contact_hist_store(__global REAL *row, const REAL *h, const int n,
                                      const int acted)
{
    for (int q = 0; q < n; q++)
        if (acted || row[q] != h[q])
            row[q] = h[q];
}

/* The law's evaluation on the private row h: ROW 0 an evaluator of a
 * 3-REAL shear (REAL3 *), ROW 1 one of the whole row (REAL *). */
#define CONTACT_CALL(ROW, EVAL, k, p, h, cf) CONTACT_CALL_PASTE(ROW)(EVAL, k, p, h, cf)
#define CONTACT_CALL_PASTE(ROW) CONTACT_CALL_##ROW
#define CONTACT_CALL_0(EVAL, k, p, h, cf)                                                      \
    do {                                                                                       \
        REAL3 s3_ = (REAL3)((h)[0], (h)[1], (h)[2]);                                           \
        EVAL(k, p, &s3_, cf);                                                                  \
        (h)[0] = s3_.x;                                                                        \
        (h)[1] = s3_.y;                                                                        \
        (h)[2] = s3_.z;                                                                        \
    } while (0)
#define CONTACT_CALL_1(EVAL, k, p, h, cf) EVAL(k, p, h, cf)

#ifdef VREMAP /* the partner's image streams with the box (LAMMPS's ghost velocities) */
#define CONTACT_VREMAP(kind, pj, k)                                                            \
    if ((kind) == CONTACT_PAIR && (pj)->vremap)                                                \
    (k).vr -= (pj)->vimage
#else
#define CONTACT_VREMAP(kind, pj, k) (void)0
#endif

/* Steps 1-3 of the body, before the law: 1 when the contact acts, with *k
 * built and its kinematics, step data and approach set; 0 when it does not
 * (h's first site->hzero REAL zeroed). */
static inline int contact_begin(const int kind, const int i, const struct contact_site *s,
                                const struct contact_partner *pj, const struct contact_atoms *a,
                                REAL *h, struct contact *k)
{
    if (!contact_gate(kind, i, s, pj, a, h, k)) {
        for (int q = 0; q < s->hzero; q++)
            h[q] = 0;
        return 0;
    }
    CONTACT_VREMAP(kind, pj, *k);
    contact_kinematics(k);
    k->dt = a->dt;
    k->shearupdate = a->shearupdate;
    k->approach = s->approach;
    return 1;
}

/* Steps 4 and 6 of the body, after the law's force cf: the accuracy note
 * (TCOL: the law's collision time) and the force and torques in *o. */
#define CONTACT_END(kind, TCOL, i, s, a, k, p, cf, o)                                          \
    do {                                                                                       \
        if ((kind) == CONTACT_PAIR && (s)->note && (k)->rsq < (k)->radsum * (k)->radsum)       \
            ACC_NOTE_PAIR(TCOL, (s)->note_idx, k, p, (a)->acc, (a)->astep, (a)->step);         \
        if ((kind) == CONTACT_WALL && (s)->note && (!(s)->approach || (k)->delta > (REAL)0))   \
            ACC_NOTE_WALL(TCOL, i, k, p, (s)->acode, (a)->acc, (a)->astep, (a)->step);         \
        contact_out_set(k, cf, o);                                                             \
    } while (0)

#ifdef HAS_HEAT
#define CONTACT_HEAT_ZERO(cf) ((cf).q = 0)
#else
#define CONTACT_HEAT_ZERO(cf) (void)0
#endif

/* The one contact body, instantiated for one law: NAME(kind, i, site,
 * partner, atoms, param, h, out) runs steps 1-6 above on the private history
 * row h and returns 1 when the contact acted (out filled), 0 when it did
 * not (h's first site->hzero REAL zeroed). EVAL: the law; ROW: its form;
 * TCOL: its collision time. kind is a constant at every call site, so each
 * source compiles only its own branches. The pair kernel runs the same
 * steps on several contacts at once (kernels/pair_loop.cl, PAIR_LW). */
#define CONTACT_BODY(NAME, EVAL, ROW, TCOL)                                                    \
    static inline int NAME(const int kind, const int i, const struct contact_site *s,          \
                           const struct contact_partner *pj, const struct contact_atoms *a,    \
                           __global const REAL *p, REAL *h, struct contact_out *o)             \
    {                                                                                          \
        struct contact k;                                                                      \
        if (!contact_begin(kind, i, s, pj, a, h, &k))                                          \
            return 0;                                                                          \
        struct contact_force cf; /* a law may leave it (granular's jkr beyond reach) */        \
        cf.f = cf.tc = cf.tr = (REAL3)(0);                                                     \
        CONTACT_HEAT_ZERO(cf);                                                                 \
        CONTACT_CALL(ROW, EVAL, &k, p, h, &cf);                                                \
        CONTACT_END(kind, TCOL, i, s, a, &k, p, &cf, o);                                       \
        return 1;                                                                              \
    }

