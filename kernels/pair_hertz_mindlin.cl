/* pair_hertz_mindlin.cl - Hertz-Mindlin contact with Tsuji-type damping
 * (source document 003 sec. 4.3-4.5; host side styles/pair/pair_hertz_mindlin.c).
 *
 * n = del / r (from j to i), delta = radsum - r, R* = reff, m* = meff,
 * a = sqrt(R* delta), vr_n = vr.n, v_t = contact-point relative velocity:
 *   F_n = kn a delta - cd sqrt(1.5 kn a m*) vr_n          (kn = 4/3 E*,
 *                                   S_n = 2 E* a = 1.5 kn a, cd = 2 sqrt(5/6) beta)
 *         integrated over each step as a two-body impulse (contact_normal.cl:
 *         U = 0.4 kn sqrt(R*) delta^2.5, H = 0.8 cd sqrt(1.5 kn sqrt(R*) m*)
 *         delta^1.25; exact energy for the spring, exact impulse for the
 *         dashpot, at the partial first and last steps of a contact too)
 *   s  += v_t dt (not during setup), projected onto the tangent plane
 *   F_t = -(kt a) s - cd sqrt(kt a m*) v_t,  rescaled to mu max(F_n, 0) when larger
 *         (the dashpot makes F_n tensile late in a contact: no load, no friction)
 *         (in slip the spring is reset to carry F_t alone: s = -F_t/S_t)
 *   tangential thesis (003 sec. 4.3, kt = 8 G): s = v_t dt afresh each step, nothing
 *         stored: F_t = -(kt a dt + cd sqrt(kt a m*)) v_t, rescaled to mu max(F_n, 0)
 *         when larger; no force when v_t = 0 (no static friction)
 *   torque_i = -radi n x F_t  - mu_r R* max(F_n, 0) w/|w|,  w = omega_i - omega_j
 *   torque_j = -radj n x F_t  + mu_r R* max(F_n, 0) w/|w|
 * Param layout HM_*: kn kt cd mu mu_r tthesis. [SI or any consistent units.]
 * Antisymmetric under i <-> j: n, vr, v_t, s, F and w flip sign. */

/* R* enters the law: the pair loop must fill c->reff (kernels/pair_loop.cl) */
static inline void hertz_mindlin_eval(const struct contact *c, __global const REAL *param,
                                      REAL3 *shear, struct contact_force *out)
{
    const REAL kn = param[HM_KN], kt = param[HM_KT], cd = param[HM_CDAMP], mu = param[HM_MU];
    const REAL mur = param[HM_MUR];
    const REAL3 n = c->n;
    const REAL delta = c->delta;
    const REAL a = sqrt(c->reff * delta);
    const REAL meff = c->meff;

    const REAL vn = c->vn;
    const REAL sr = sqrt(c->reff);
    const REAL fnmag = contact_normal_force(NORMAL_HERTZ, (REAL)0.4 * kn * sr,
                                            (REAL)0.8 * cd * sqrt((REAL)1.5 * kn * sr * meff),
                                            delta, -vn, meff, c->dt);

    const REAL3 vt = c->vtr; /* the contact points' relative velocity */

    const int thesis = param[HM_TTHESIS] != (REAL)0;
    REAL3 s = thesis ? vt * c->dt : *shear; /* thesis: one step's displacement */
    if (c->shearupdate && !thesis)
        s += vt * c->dt;
    s -= dot(s, n) * n;     /* keep the spring in the current tangent plane */

    const REAL st = kt * a;
    const REAL dt_coef = cd * sqrt(st * meff);
    REAL3 ft = -st * s - dt_coef * vt;
    const REAL ftmag = length(ft);
    const REAL flim = mu * fmax(fnmag, (REAL)0); /* no friction under tension */
    if (ftmag > flim) {
        if (thesis || st > (REAL)0) {
            /* sliding: F_t = flim ft/|ft|; the spring alone carries it
             * (verify: LAMMPS' mapping s = -(F_t + d_t v_t)/S_t stores the
             * damping share too, which grows as delta^(-1/4) at contact
             * start because d_t/S_t does, leaves a spring of the wrong sign
             * that later pushes along the slip, and has no dt -> 0 limit);
             * thesis: nothing is stored */
            ft *= flim / ftmag;
            if (!thesis)
                s = -ft / st;
        } else {
            ft = (REAL3)(0);
        }
    }
    if (c->shearupdate && !thesis)
        *shear = s;
    out->f = fnmag * n + ft;

    out->tc = cross(n, ft);
    out->tr = (REAL3)(0);
    if (mur > (REAL)0) {
        const REAL3 wrel = c->omi - c->omj;
        const REAL wmag = length(wrel);
        if (wmag > (REAL)0)
            out->tr = (mur * c->reff * fmax(fnmag, (REAL)0) / wmag) * wrel;
    }
}

/* collision time (kernels/accuracy.cl): Hertz, undamped */
static inline REAL hertz_mindlin_eval_tcol(const struct contact *c, __global const REAL *param,
                                           const REAL vn)
{
    return tcol_hertz(param[HM_KN], c->reff, c->meff, vn);
}
