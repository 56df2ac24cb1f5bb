/* pair_gran.cl - LIGGGHTS 3.8's granular contact models (`pair_style gran
 * model M tangential T [cohesion C] [rolling_friction R]`, and `fix wall/gran
 * model ...` through the same evaluator; host side styles/pair/pair_gran.c,
 * docs doc/styles/pair_gran_model.md), reproduced from LIGGGHTS's
 * surface_model_default.h, normal_model_*.h, tangential_model_*.h,
 * cohesion_model_sjkr*.h and rolling_model_cdt.h in their order of
 * operations. Param layout LG_* (kernels/param_layout.h), mixed on the host.
 *
 * en = del / r from j to i, deltan = radsum - r, vn = vr.en (< 0 closing),
 * reff = ri rj / (ri + rj) (ri for a wall), meff the reduced mass (mi: wall).
 * Contact-point lever arms cri = ri - deltan/2, crj = rj - deltan/2 (not
 * LAMMPS's ri, rj); vtr = vt + del x (cri omi + crj omj) / r.
 * Normal (Fn = kn deltan - gamman vn, clamped at 0 with limitForce):
 *   hertz   kn = 4/3 Y* sqrt(reff deltan), kt = 8 G* sqrt(reff deltan),
 *           gamman = -2 sqrt(5/6) beta sqrt(2 Y* sqrt(reff deltan) meff),
 *           gammat = -2 sqrt(5/6) beta sqrt(kt meff)
 *   hooke   kn = 16/15 sqrt(reff) Y* (15 meff v_c^2 / (16 sqrt(reff) Y*))^(1/5),
 *           kt = kn (2/7 kn with ktToKnUser), gamman = gammat =
 *           sqrt(4 meff kn ln^2 e / (ln^2 e + pi^2))
 *   hooke/hysteresis  hooke's kn, kt = kn, gamman = gammat = sqrt(4 meff kn / (1 +
 *           (pi / ln e)^2)); the elastic part follows Walton-Braun / Luding's
 *           hysteresis on the largest overlap dmax (history): loading kn delta,
 *           un/reloading k2 (delta - dmax) + kn dmax with k2 = kn + (k2max - kn)
 *           dmax / dlim (k2max beyond dlim = k2max/(k2max - kn) phiF 2 reff),
 *           bounded below by the adhesion -kc delta (dmax then moves on);
 *           k2max = kn coefficientMaxElasticStiffness, kc = kn
 *           coefficientAdhesionStiffness, phiF = coefficientPlasticityDepth
 *   luding  hooke/hysteresis's law with kn = LoadingStiffness (kt = kn),
 *           k2max = kn UnloadingStiffness, on the adhesion branch dmax =
 *           (k2 + kc)/(k2 - kn) delta; Fn = fHys - gamman vn + pullOffForce,
 *           set to 0 when negative with limitForce (on by default) only
 *           without adhesion (kc = 0, pullOffForce 0)
 *   thornton_ning  Fn from Thornton and Ning's adhesive elastic-plastic law
 *           (lg_thornton_ning: surfaceEnergy gamma_s, yield radius ri
 *           coefficientYieldRatio, its state in the history), hertz's kt,
 *           gammat = +2 sqrt(5/6) beta sqrt(kt meff) (LIGGGHTS's sign: < 0)
 *   hertz/stiffness  kn, kt, gamman meff, gammat meff, each x sqrt(reff deltan)
 *   hooke/stiffness  kn, kt, gamman meff, gammat meff (absolute_damping: no meff)
 *   (tangential_damping off: gammat = 0)
 * Tangential history: s += vtr dt, s -= (s.en) en (no rescale of |s|);
 *   Ft = -kt s; if kt |s| > mu |Fn|: Ft scaled to mu |Fn| and s = -Ft / kt,
 *   WITHOUT the dashpot (LAMMPS adds it before the Coulomb test), else
 *   Ft -= gammat vtr. no_history: Ft = -min(gammat, mu |Fn| / |vtr|) vtr.
 * Cohesion (in contact only): Fcoh = -ced A along en,
 *   sjkr  A = -pi/4 (r-ri-rj)(r+ri-rj)(r-ri+rj)(r+ri+rj) / r^2 (wall: pi (ri^2 - r^2)),
 *   sjkr2 A = 2 pi (2 ri rj / (ri + rj)) (ri + rj - r) (wall: 2 pi ri (ri - r)).
 * Rolling cdt: tr = mu_r kn deltan reff w/|w| without its en component
 *   (torsionTorque on: kept), w = omi - omj (wall: cri omi / r); on i -tr, on j +tr.
 * Rolling epsd, epsd2, epsd3 (rolling_model_epsd*.h; Ai et al. 2011): a
 *   spring torque M += kr dt wt (wt: w without its en component unless
 *   torsionTorque), kr = 2.25 kn mu_r^2 reff^2 (epsd3: rollingStiffness
 *   for 2.25; epsd2: kt reff^2), capped at mu_r |Fn| reff; the capped
 *   spring torque is the history (3 REAL); below the cap epsd and epsd3 add
 *   the dashpot eta_r 2 sqrt(I kr) wt, I = 1.4 (2d: 1.5) Ii Ij / (Ii + Ij),
 *   Ii = mi ri^2 (wall: mi ri^2).
 * Torques: on i -cri (en x Ft) - tr, on j -crj (en x Ft) + tr. */

#define LG_SQRT56 ((REAL)0.91287092917527685576161630466800355658790782499663875)

/* The normal model's result (LIGGGHTS's sidata.Fn, kn, kt, gamman, gammat) */
struct lg_normal_out {
    REAL Fn, kn, kt, gamman, gammat;
};

/* hooke/hysteresis's and luding's elastic force on the largest overlap *dmax:
 * loading kn delta, un/reloading k2 (delta - dmax) + kn dmax with k2 = kn +
 * (k2max - kn) dmax / dlim (k2max beyond dlim), never below the adhesion
 * -kc delta. *dmax is raised to deltan always; on the adhesion branch it
 * moves on: hooke/hysteresis to a root (when update), luding to (k2 + kc) /
 * (k2 - kn) delta (always, as LIGGGHTS). */
static inline REAL lg_hysteresis(__global const REAL *p, const REAL kn, const REAL reff,
                                 const REAL deltan, REAL *dmax, const int update,
                                 const int luding)
{
    const REAL k2Max = kn * p[LG_K2MAX];
    const REAL kc = kn * p[LG_KC];
    if (deltan > *dmax)
        *dmax = deltan;
    const REAL deltaMax = *dmax;
    const REAL deltaMaxLim = (k2Max / (k2Max - kn)) * p[LG_PHIF] * (REAL)2 * reff;
    REAL fHys = 0, k2;
    int adhesion = 0;
    if (deltaMax >= deltaMaxLim) {
        k2 = k2Max;
        const REAL fTmp = k2 * (deltan - deltaMaxLim) + kn * deltaMaxLim;
        if (fTmp >= -kc * deltan)
            fHys = fTmp;
        else
            adhesion = 1;
    } else {
        k2 = kn + (k2Max - kn) * deltaMax / deltaMaxLim;
        const REAL fTmp = k2 * (deltan - deltaMax) + kn * deltaMax;
        if (fTmp >= kn * deltan)
            fHys = kn * deltan;
        else if (fTmp > -kc * deltan)
            fHys = fTmp;
        else
            adhesion = 1;
    }
    if (adhesion) {
        fHys = -kc * deltan;
        if (luding)
            *dmax = ((k2 + kc) / (k2 - kn)) * deltan;
        else if (update)
            *dmax = (REAL)0.5 * (deltan + sqrt(deltan * deltan + (REAL)4 * ((kn + kc) * deltan *
                                                                  deltaMaxLim / (k2Max - kn))));
    }
    return fHys;
}

/* thornton_ning (LIGGGHTS normal_model_thornton_ning.h; Thornton and Ning
 * 1998): adhesive elastic-plastic loading along the largest overlap, JKR-like
 * unloading, detachment at -5/9 fc, in LIGGGHTS's order of operations.
 * fc = 3/2 pi gamma_s reff is the pull-off force of the surface energy. */
static inline REAL lg_tn_fl(const REAL force_old, const REAL fc, const int adhesion)
{
    /* LIGGGHTS takes the root as it is and goes NaN where round-off puts the
     * force a hair below -fc (at pull-off; a yielded contact's fc, recomputed
     * from a flattened radius that is reff again up to round-off), and fl,
     * (sqrt(force_old + fc) -+ sqrt(fc))^2 >= 0, can round below 0 too: both
     * held at 0, which changes nothing where LIGGGHTS's values are finite */
    const REAL root = sqrt(fmax(fc * (force_old + fc), (REAL)0));
    if (adhesion)
        return fmax(force_old + (REAL)2 * (fc - root), (REAL)0);
    return fmax(force_old + (REAL)2 * (fc + root), (REAL)0);
}

/* the contact radius at the equivalent Hertz load fl (or sqrt(R delta)
 * without adhesion) */
static inline REAL lg_tn_a(const REAL fl, const REAL E, const REAL R, const REAL delta,
                           const REAL gamma_s)
{
    if (gamma_s == (REAL)0)
        return sqrt(R * delta);
    return pow(((REAL)3. * R * fl) / ((REAL)4. * E), (REAL)(1. / 3.));
}

/* the elastic branch: *df the force change over dn, returns the force */
static inline REAL lg_tn_elastic(const REAL force_old, const REAL fc, const int adhesion,
                                 const REAL E, const REAL R, const REAL delta, const REAL dn,
                                 const REAL gamma_s, REAL *df)
{
    const REAL fl = lg_tn_fl(force_old, fc, adhesion);
    const REAL a = lg_tn_a(fl, E, R, delta, gamma_s);
    REAL d;
    if (fc != (REAL)0) {
        const REAL up = (REAL)3 * sqrt(fl) - (REAL)3 * sqrt(fc);
        const REAL down = (REAL)3 * sqrt(fl) - sqrt(fc);
        d = (REAL)2 * E * a * up / down;
    } else {
        d = (REAL)2 * E * a;
    }
    *df = d * dn;
    return force_old + *df;
}

/* The normal force of ri's contact at overlap delta; h the history row
 * (enum lg_tn_hist), updated. A yield stress <= 0 (LIGGGHTS stops: "Invalid
 * yield stress") gives NaN, which stops the run (the host checks the atoms
 * present at each run start: styles/pair/pair_gran.c). */
static inline REAL lg_thornton_ning(__global const REAL *p, const REAL ri, REAL reff,
                                    const REAL delta, REAL *h)
{
    const REAL E = p[LG_YEFF], gamma_s = p[LG_GSURF];
    int flags = (int)h[LG_TN_FLAGS];
    REAL delta_old = h[LG_TN_DELTA_OLD], delta_max = h[LG_TN_DELTA_MAX];
    REAL force_old = h[LG_TN_FORCE_OLD], force_max = h[LG_TN_FORCE_MAX];
    REAL detaching_delta = h[LG_TN_DETACH_DELTA], detaching_force = h[LG_TN_DETACH_FORCE];
    REAL fc = gamma_s * reff * (REAL)M_PI * ((REAL)3. / (REAL)2.);
    const REAL a_yield = ri * p[LG_YRATIO];
    const REAL yield_stress = (((REAL)2. * E * a_yield) / ((REAL)M_PI * reff)) -
                              sqrt((REAL)2. * gamma_s * E / ((REAL)M_PI * a_yield));
    if (!(yield_stress > (REAL)0))
        return NAN;
    const REAL limit_yield_stress = pow((REAL)2. * E * E * gamma_s /
                                            ((REAL)M_PI * (REAL)M_PI * reff),
                                        (REAL)(1. / 3.));
    const int plastic_from_start = yield_stress < limit_yield_stress;
    if (!(flags & LG_TN_VIRGIN)) { /* first touch */
        force_old = -((REAL)8. / (REAL)9.) * fc;
        delta_old = 0;
        flags = LG_TN_VIRGIN;
        force_max = force_old;
        delta_max = 0;
        detaching_delta = 0;
        detaching_force = -((REAL)5. / (REAL)9.) * fc;
    }
    REAL f, df = 0;
    if ((flags & LG_TN_DETACHING) && delta < detaching_delta) {
        f = 0;
    } else {
        if (flags & LG_TN_DETACHING) { /* reloads from where it detached */
            flags &= ~LG_TN_DETACHING;
            delta_old = detaching_delta;
            force_old = detaching_force;
        }
        const REAL dn = delta - delta_old;
        int adhesion = (flags & LG_TN_ADHESION) != 0;
        if (delta >= delta_max) { /* loading */
            delta_max = delta;
            const REAL fl = lg_tn_fl(force_old, fc, 0);
            const REAL a = lg_tn_a(fl, E, reff, delta, gamma_s);
            if (a >= a_yield)
                flags |= LG_TN_YIELDING;
            if (plastic_from_start || (flags & LG_TN_YIELDING)) {
                REAL d;
                if (fc != (REAL)0) {
                    const REAL up = (REAL)3 * (REAL)M_PI * reff * yield_stress * sqrt(fl) -
                                    (REAL)2 * a_yield * E * sqrt(fc);
                    const REAL down = (REAL)3 * sqrt(fl) - sqrt(fc);
                    d = up / down;
                } else {
                    d = (REAL)2 * E * a_yield;
                }
                df = d * dn;
                f = force_old + df;
            } else {
                f = lg_tn_elastic(force_old, fc, adhesion, E, reff, delta, dn, gamma_s, &df);
            }
        } else { /* unloading or reloading: a yielded contact's flattened radius */
            if (flags & LG_TN_YIELDING) {
                const REAL fl_max = lg_tn_fl(force_max, fc, 0);
                reff = reff * fl_max / (force_max + sqrt((REAL)4 * fc * fl_max));
                fc = ((REAL)3. / (REAL)2.) * (REAL)M_PI * gamma_s * reff;
            }
            f = lg_tn_elastic(force_old, fc, adhesion, E, reff, delta, dn, gamma_s, &df);
        }
        if (gamma_s == (REAL)0 && f < (REAL)0) { /* no adhesion: parts at zero force */
            f = 0;
            flags |= LG_TN_DETACHING;
            detaching_delta = delta;
            detaching_force = 0;
        }
        if (f < -fc) { /* past the pull-off force: the other branch */
            adhesion = 1 - adhesion;
            f = lg_tn_elastic(force_old, fc, adhesion, E, reff, delta, dn, gamma_s, &df);
        }
        if (adhesion && f + (REAL)3 * df >= -((REAL)5. / (REAL)9.) * fc) { /* detaches */
            f = 0;
            flags |= LG_TN_DETACHING;
            detaching_delta = delta_old;
            detaching_force = force_old;
        }
        flags = adhesion ? flags | LG_TN_ADHESION : flags & ~LG_TN_ADHESION;
    }
    h[LG_TN_FLAGS] = (REAL)flags;
    h[LG_TN_DELTA_OLD] = delta;
    h[LG_TN_DELTA_MAX] = delta_max;
    h[LG_TN_FORCE_OLD] = f;
    h[LG_TN_FORCE_MAX] = f > force_max ? f : force_max;
    h[LG_TN_DETACH_DELTA] = detaching_delta;
    h[LG_TN_DETACH_FORCE] = detaching_force;
    return f;
}

/* nh: the normal model's history (LG_NORMAL_HIST REAL; NULL without one);
 * radi: the contact's first particle (thornton_ning's yield radius) */
static inline struct lg_normal_out lg_normal(__global const REAL *p, const REAL radi,
                                             const REAL reff, const REAL meff,
                                             const REAL deltan, const REAL vn, REAL *nh,
                                             const int update)
{
    struct lg_normal_out o;
    const int nm = (int)p[LG_NMODEL];
    const int tdamp = p[LG_TDAMP] != (REAL)0;
    if (nm == LG_N_THORNTON_NING) { /* kt and gammat from Hertz; LIGGGHTS's gammat has the
                                     * sign of beta, and no tangential_damping switch */
        const REAL sqrtval = sqrt(reff * deltan);
        o.kn = o.gamman = 0;
        o.kt = (REAL)8. * p[LG_GEFF] * sqrtval;
        o.gammat = (REAL)2. * LG_SQRT56 * p[LG_BETA] * sqrt(o.kt * meff);
        o.Fn = nh ? lg_thornton_ning(p, radi, reff, deltan, nh) : (REAL)0;
        return o;
    }
    REAL *dmax = nh;
    if (nm == LG_N_LUDING) { /* kt = kn = LoadingStiffness; pullOffForce added */
        const REAL l = p[LG_LOGE];
        o.kn = o.kt = p[LG_KN];
        o.gamman = sqrt((REAL)4. * meff * o.kn / ((REAL)1. + ((REAL)M_PI / l) * ((REAL)M_PI / l)));
        o.gammat = tdamp ? o.gamman : (REAL)0;
        const REAL fHys = dmax ? lg_hysteresis(p, o.kn, reff, deltan, dmax, update, 1)
                               : o.kn * deltan;
        o.Fn = fHys + -o.gamman * vn + p[LG_FADH];
        if (p[LG_LIMIT] != (REAL)0 && o.Fn < (REAL)0 && p[LG_KC] == (REAL)0 &&
            p[LG_FADH] == (REAL)0)
            o.Fn = 0;
        return o;
    }
    if (nm == LG_N_HOOKE_HYSTERESIS) {
        const REAL Y = p[LG_YEFF], cv = p[LG_CHARV], l = p[LG_LOGE];
        const REAL sqrtval = sqrt(reff);
        o.kn = (REAL)16. / (REAL)15. * sqrtval * Y *
               pow((REAL)15. * meff * cv * cv / ((REAL)16. * sqrtval * Y), (REAL)0.2);
        o.kt = o.kn;
        o.gamman = sqrt((REAL)4. * meff * o.kn /
                        ((REAL)1. + ((REAL)M_PI / l) * ((REAL)M_PI / l)));
        o.gammat = tdamp ? o.gamman : (REAL)0;
        const REAL fHys = dmax ? lg_hysteresis(p, o.kn, reff, deltan, dmax, update, 0)
                               : o.kn * deltan;
        o.Fn = fHys + -o.gamman * vn;
        return o;
    }
    if (nm == LG_N_HERTZ) {
        const REAL Y = p[LG_YEFF], beta = p[LG_BETA];
        const REAL sqrtval = sqrt(reff * deltan);
        const REAL Sn = (REAL)2. * Y * sqrtval;
        const REAL St = (REAL)8. * p[LG_GEFF] * sqrtval;
        o.kn = (REAL)4. / (REAL)3. * Y * sqrtval;
        o.kt = St;
        o.gamman = (REAL)-2. * LG_SQRT56 * beta * sqrt(Sn * meff);
        o.gammat = tdamp ? (REAL)-2. * LG_SQRT56 * beta * sqrt(St * meff) : (REAL)0;
    } else if (nm == LG_N_HOOKE) {
        const REAL Y = p[LG_YEFF], cv = p[LG_CHARV], l = p[LG_LOGE];
        const REAL sqrtval = sqrt(reff);
        o.kn = (REAL)16. / (REAL)15. * sqrtval * Y *
               pow((REAL)15. * meff * cv * cv / ((REAL)16. * sqrtval * Y), (REAL)0.2);
        o.kt = o.kn;
        if (p[LG_KTTOKN] != (REAL)0)
            o.kt *= (REAL)0.285714286;
        const REAL l2 = l * l;
        o.gamman = sqrt((REAL)4. * meff * o.kn * l2 / (l2 + (REAL)M_PI * (REAL)M_PI));
        o.gammat = tdamp ? o.gamman : (REAL)0;
    } else if (nm == LG_N_HERTZ_STIFFNESS) {
        const REAL polyhertz = sqrt(reff * deltan);
        o.kn = polyhertz * p[LG_KN];
        o.kt = polyhertz * p[LG_KT];
        o.gamman = polyhertz * meff * p[LG_GN];
        o.gammat = tdamp ? polyhertz * meff * p[LG_GT] : (REAL)0;
    } else { /* LG_N_HOOKE_STIFFNESS */
        o.kn = p[LG_KN];
        o.kt = p[LG_KT];
        const int absd = p[LG_ABSDAMP] != (REAL)0;
        o.gamman = absd ? p[LG_GN] : meff * p[LG_GN];
        o.gammat = absd ? p[LG_GT] : meff * p[LG_GT];
        if (!tdamp)
            o.gammat = 0;
    }
    const REAL Fn_damping = -o.gamman * vn;
    const REAL Fn_contact = o.kn * deltan;
    o.Fn = Fn_damping + Fn_contact;
    if (p[LG_LIMIT] != (REAL)0 && o.Fn < (REAL)0)
        o.Fn = 0;
    return o;
}

/* cohesionEnergyDensity times the contact area, as a normal force along en
 * (negative: attractive) */
static inline REAL lg_cohesion(__global const REAL *p, const REAL r, const REAL ri,
                               const REAL rj, const int wall)
{
    const int cm = (int)p[LG_COH];
    REAL Acont;
    if (cm == LG_C_SJKR)
        Acont = wall ? (ri * ri - r * r) * (REAL)M_PI
                     : -(REAL)M_PI / (REAL)4 * ((r - ri - rj) * (r + ri - rj) * (r - ri + rj) *
                                                (r + ri + rj)) / (r * r);
    else
        Acont = wall ? (REAL)M_PI * (REAL)2. * ri * (ri - r)
                     : (REAL)M_PI * (REAL)2. * ((REAL)2. * ri * rj / (ri + rj)) * (ri + rj - r);
    return -p[LG_CED] * Acont;
}

/* history: the spring truncated at mu |Fn| without its dashpot; updates *s */
static inline REAL3 lg_tangential_history(const REAL3 en, const REAL3 vtr, const REAL kt,
                                          const REAL gammat, const REAL xmu, const REAL Fn,
                                          const REAL dt, const int update, REAL3 *s)
{
    REAL s0 = s->x, s1 = s->y, s2 = s->z;
    if (update) {
        s0 += vtr.x * dt;
        s1 += vtr.y * dt;
        s2 += vtr.z * dt;
        const REAL rsht = s0 * en.x + s1 * en.y + s2 * en.z;
        s0 -= rsht * en.x;
        s1 -= rsht * en.y;
        s2 -= rsht * en.z;
    }
    const REAL shrmag = sqrt(s0 * s0 + s1 * s1 + s2 * s2);
    REAL Ft1 = -(kt * s0), Ft2 = -(kt * s1), Ft3 = -(kt * s2);
    const REAL Ft_shear = kt * shrmag;
    const REAL Ft_friction = xmu * fabs(Fn);
    if (Ft_shear > Ft_friction) {
        if (shrmag != (REAL)0) {
            const REAL ratio = Ft_friction / Ft_shear;
            Ft1 *= ratio;
            Ft2 *= ratio;
            Ft3 *= ratio;
            if (update) {
                s0 = -Ft1 / kt;
                s1 = -Ft2 / kt;
                s2 = -Ft3 / kt;
            }
        } else {
            Ft1 = Ft2 = Ft3 = 0;
        }
    } else {
        Ft1 -= gammat * vtr.x;
        Ft2 -= gammat * vtr.y;
        Ft3 -= gammat * vtr.z;
    }
    if (update)
        *s = (REAL3)(s0, s1, s2);
    return (REAL3)(Ft1, Ft2, Ft3);
}

/* no_history: the dashpot capped by Coulomb */
static inline REAL3 lg_tangential_nohistory(const REAL3 vtr, const REAL gammat, const REAL xmu,
                                            const REAL Fn)
{
    const REAL vrel = sqrt(vtr.x * vtr.x + vtr.y * vtr.y + vtr.z * vtr.z);
    const REAL Ft_friction = xmu * fabs(Fn);
    const REAL gamma = Ft_friction < gammat * vrel ? Ft_friction / vrel : gammat;
    return (REAL3)(-gamma * vtr.x, -gamma * vtr.y, -gamma * vtr.z);
}

/* v without its component along en, unless torsionTorque (the rolling
 * models' torsion switch) */
static inline REAL3 lg_torsion_off(__global const REAL *p, const REAL3 v, const REAL3 en)
{
    if (p[LG_TORSION] != (REAL)0)
        return v;
    const REAL d = v.x * en.x + v.y * en.y + v.z * en.z;
    return (REAL3)(v.x - en.x * d, v.y - en.y * d, v.z - en.z * d);
}

/* rolling cdt: the torque subtracted on i (added on j); wr the relative
 * rotation (the wall's cri omi / r), Fel = kn deltan */
static inline REAL3 lg_rolling_cdt(__global const REAL *p, const REAL3 wr, const REAL3 en,
                                   const REAL Fel, const REAL reff, const int wall)
{
    const REAL rmu = p[LG_RMU];
    const REAL wrmag = sqrt(wr.x * wr.x + wr.y * wr.y + wr.z * wr.z);
    if (!(wrmag > (REAL)0))
        return (REAL3)(0);
    REAL3 t;
    if (wall) {
        t = (REAL3)(rmu * Fel * wr.x / wrmag * reff, rmu * Fel * wr.y / wrmag * reff,
                    rmu * Fel * wr.z / wrmag * reff);
    } else {
        const REAL f = rmu * Fel * reff / wrmag;
        t = (REAL3)(wr.x * f, wr.y * f, wr.z * f);
    }
    return lg_torsion_off(p, t, en);
}

/* rolling epsd, epsd2, epsd3: the torque subtracted on i (added on j); wr
 * the relative rotation (the wall's cri omi / r), *m the spring torque
 * (history; updated when update) */
static inline REAL3 lg_rolling_epsd(const struct contact *c, __global const REAL *p,
                                    const REAL3 wr, const REAL3 en,
                                    const struct lg_normal_out *nf, const REAL reff,
                                    const int wall, REAL3 *m)
{
    const REAL rmu = p[LG_RMU];
    const REAL3 wt = lg_torsion_off(p, wr, en);
    const REAL kr = (int)p[LG_ROLL] == LG_R_EPSD2 ? nf->kt * reff * reff
                                                   : p[LG_RSTIFF] * nf->kn * rmu * rmu * reff * reff;
    const REAL s = c->dt * kr;
    REAL3 t = (REAL3)(m->x + wt.x * s, m->y + wt.y * s, m->z + wt.z * s);
    const REAL tmag = sqrt(t.x * t.x + t.y * t.y + t.z * t.z);
    const REAL tmax = fabs(nf->Fn) * reff * rmu;
    const int update = c->shearupdate;
    if (tmag > tmax) { /* full mobilisation: no dashpot */
        const REAL factor = tmax / tmag;
        t = (REAL3)(t.x * factor, t.y * factor, t.z * factor);
        if (update)
            *m = t;
        return t;
    }
    if (update)
        *m = t;
    if ((int)p[LG_ROLL] == LG_R_EPSD2)
        return t;
    REAL inertia;
    if (wall) {
        inertia = p[LG_RINERTIA] * c->mi * reff * reff;
    } else {
        const REAL ii = c->mi * c->radi * c->radi, ij = c->mj * c->radj * c->radj;
        inertia = p[LG_RINERTIA] * ii * ij / (ii + ij);
    }
    const REAL coef = p[LG_RVISC] * (REAL)2 * sqrt(inertia * kr);
    return (REAL3)(t.x + coef * wt.x, t.y + coef * wt.y, t.z + coef * wt.z);
}

#ifdef HAS_HEAT
/* fix heat/gran's conduction (LIGGGHTS FixHeatGranCond::post_force_eval):
 * the heat flowing into i from j, (T_j - T_i) H sqrt(A), H = 4 k_i k_j /
 * (k_i + k_j) (p[LG_HC]); A the contact area: overlap, the circle where the
 * spheres' surfaces cross, -pi/4 (r-ri-rj)(r+ri-rj)(r-ri+rj)(r+ri+rj) / r^2
 * (pi min(ri, rj)^2 once one centre is inside the other sphere);
 * projection pi max(ri, rj)^2; constant p[LG_HAREA]. */
static inline REAL lg_conduction(__global const REAL *p, const REAL r, const REAL ri,
                                 const REAL rj, const REAL ti, const REAL tj)
{
    const int mode = (int)p[LG_HEAT];
    REAL area;
    if (mode == LG_H_NONE)
        return 0;
    if (mode == LG_H_OVERLAP) {
        if (r < fmax(ri, rj)) {
            area = fmin(ri, rj);
            area *= area * (REAL)M_PI;
        } else {
            area = -(REAL)M_PI / (REAL)4.0 *
                   ((r - ri - rj) * (r + ri - rj) * (r - ri + rj) * (r + ri + rj)) / (r * r);
        }
    } else if (mode == LG_H_PROJECTION) {
        const REAL rmax = fmax(ri, rj);
        area = (REAL)M_PI * rmax * rmax;
    } else {
        area = p[LG_HAREA];
    }
    return (tj - ti) * (p[LG_HC] * sqrt(area));
}
#endif

/* The composed law; nh: the normal model's history (lg_normal), roll: the
 * epsd models' spring torque (each NULL otherwise). The wall's set has
 * p[LG_WALL] = 1. */
static inline void gran_model_law(const struct contact *c, __global const REAL *p, REAL *nh,
                                  REAL3 *shear, REAL3 *roll, struct contact_force *out)
{
    const int wall = p[LG_WALL] != (REAL)0;
    const REAL3 en = c->n;
    const REAL3 del = c->del;
    const REAL rinv = c->rinv, r = c->r;
    const REAL radi = c->radi, radj = wall ? (REAL)0 : c->radj;
    const REAL deltan = c->delta;
    /* surface_model_default: relative velocities at the contact points */
    const REAL3 vr = c->vr;
    const REAL vn = vr.x * en.x + vr.y * en.y + vr.z * en.z;
    const REAL3 vt = (REAL3)(vr.x - vn * en.x, vr.y - vn * en.y, vr.z - vn * en.z);
    const REAL cri = radi - (REAL)0.5 * deltan;
    const REAL crj = radj - (REAL)0.5 * deltan;
    REAL3 wr;
    if (wall)
        wr = (REAL3)(cri * c->omi.x * rinv, cri * c->omi.y * rinv, cri * c->omi.z * rinv);
    else
        wr = (REAL3)((cri * c->omi.x + crj * c->omj.x) * rinv,
                     (cri * c->omi.y + crj * c->omj.y) * rinv,
                     (cri * c->omi.z + crj * c->omj.z) * rinv);
    const REAL3 vtr = (REAL3)(vt.x - (del.z * wr.y - del.y * wr.z),
                              vt.y - (del.x * wr.z - del.z * wr.x),
                              vt.z - (del.y * wr.x - del.x * wr.y));
    const REAL reff = wall ? radi : radi * radj / (radi + radj);

    const struct lg_normal_out nf = lg_normal(p, radi, reff, c->meff, deltan, vn, nh,
                                              c->shearupdate);
    REAL3 F = (REAL3)(nf.Fn * en.x, nf.Fn * en.y, nf.Fn * en.z);
    if ((int)p[LG_COH] != LG_C_NONE) {
        const REAL fc = lg_cohesion(p, r, radi, radj, wall);
        F += (REAL3)(fc * en.x, fc * en.y, fc * en.z);
    }
    REAL3 Ft;
    if (p[LG_TMODEL] != (REAL)0)
        Ft = lg_tangential_history(en, vtr, nf.kt, nf.gammat, p[LG_MU], nf.Fn, c->dt,
                                   c->shearupdate, shear);
    else
        Ft = lg_tangential_nohistory(vtr, nf.gammat, p[LG_MU], nf.Fn);
    out->f = F + Ft;
#ifdef HAS_HEAT
    out->q = wall ? (REAL)0 : lg_conduction(p, r, radi, radj, c->ti, c->tj);
#endif

    /* torques: on i -cri tor - rt, on j -crj tor + rt, written as the body's
     * -radi tc - tr, -radj tc + tr (tc = (r / radsum) tor) */
    const REAL3 tor = (REAL3)(en.y * Ft.z - en.z * Ft.y, en.z * Ft.x - en.x * Ft.z,
                              en.x * Ft.y - en.y * Ft.x);
    REAL3 rt = (REAL3)(0);
    const REAL3 wroll = wall ? wr : c->omi - c->omj; /* the rolling models' rotation */
    if ((int)p[LG_ROLL] == LG_R_CDT)
        rt = lg_rolling_cdt(p, wroll, en, deltan * nf.kn, reff, wall);
    else if (roll)
        rt = lg_rolling_epsd(c, p, wroll, en, &nf, reff, wall, roll);
    if (wall) {
        out->tc = tor;
        out->tr = (-(REAL)0.5 * deltan) * tor + rt;
        return;
    }
    const REAL radsum = radi + radj;
    out->tc = (r / radsum) * tor;
    out->tr = (deltan * (radi - radj) / ((REAL)2 * radsum)) * tor + rt;
}

/* PAIR_EVAL form: the models without a normal or rolling history */
static inline void gran_model_eval(const struct contact *c, __global const REAL *p,
                                   REAL3 *shear, struct contact_force *out)
{
    gran_model_law(c, p, 0, shear, 0, out);
}

/* PAIR_EVAL_ROW form (hooke/hysteresis, thornton_ning, the epsd rolling
 * models): h = [the normal model's history (LG_NORMAL_HIST)] shear [spring
 * torque (epsd*)] */
static inline void gran_model_eval_row(const struct contact *c, __global const REAL *p, REAL *h,
                                       struct contact_force *out)
{
    const int nh = LG_NORMAL_HIST((int)p[LG_NMODEL]);
    const int epsd = (int)p[LG_ROLL] >= LG_R_EPSD;
    REAL *hs = h + nh;
    REAL3 s = (REAL3)(hs[0], hs[1], hs[2]);
    REAL3 m = epsd ? (REAL3)(hs[3], hs[4], hs[5]) : (REAL3)(0);
    gran_model_law(c, p, nh ? h : 0, &s, epsd ? &m : 0, out);
    hs[0] = s.x;
    hs[1] = s.y;
    hs[2] = s.z;
    if (epsd) {
        hs[3] = m.x;
        hs[4] = m.y;
        hs[5] = m.z;
    }
}

/* collision time (kernels/accuracy.cl): hertz models Johnson's Hertz time
 * of kn = 4/3 Y*, hooke the linear spring's half period at its kn */
static inline REAL gran_model_eval_tcol(const struct contact *c, __global const REAL *p,
                                        const REAL vn)
{
    const int nm = (int)p[LG_NMODEL];
    const REAL reff = p[LG_WALL] != (REAL)0 ? c->radi : c->reff;
    if (nm == LG_N_HERTZ || nm == LG_N_THORNTON_NING) /* thornton_ning: its Hertz loading */
        return tcol_hertz((REAL)4. / (REAL)3. * p[LG_YEFF], reff, c->meff, vn);
    const struct lg_normal_out o = lg_normal(p, c->radi, reff, c->meff, (REAL)0, (REAL)0, 0, 0);
    if (nm == LG_N_HERTZ_STIFFNESS)
        return tcol_hertz(p[LG_KN], reff, c->meff, vn);
    return o.kn > (REAL)0 ? tcol_linear(o.kn, 0, c->meff) : (REAL)0;
}

static inline REAL gran_model_eval_row_tcol(const struct contact *c, __global const REAL *p,
                                            const REAL vn)
{
    return gran_model_eval_tcol(c, p, vn);
}
