/* pair_linear_restitution.cl - linear spring-dashpot with restitution-derived
 * damping and the "complex" friction model (Andrews 2018, source document 000,
 * eq. 2.1, 2.2, 2.4, 2.5, 2.14, 2.15, 2.17 and sec. 3.2.2). No history.
 *
 * With n = del / r (from j to i), delta = radsum - r, u_n = (vr.n) n,
 * u_t = vr - u_n (minus the rotational contact velocity when torque is on):
 *   eta   = ceta sqrt(m*),  t_col = ctcol sqrt(m*)     (host-precomputed)
 *   F_n   = (ke delta - eta vr.n) n                    [force units]
 * integrated exactly over each step for two bodies (kernels/contact_normal.cl,
 * contact_normal_linear: the closed-form solution, with a pre-contact kick on
 * pairs one drift from contact; c->approach, set by callers that evaluate
 * those pairs: the pair loop and fix wall/pair's plane and mesh kernels), else
 * (hybrid/overlay) as contact_normal_force's second-order two-body impulse.
 *   F_t   = -u_t/|u_t| min(kf |u_t| t_col, mu |F_n|)
 * The normal force is not clamped at zero: the analytic solution of 000 A.1
 * (and the restitution it returns) includes the attractive end of the dashpot.
 * Torque on i (torque yes): -radi (n x F_t), on j: -radj (n x F_t). Param layout LR_*: ke kf mu ceta
 * ctcol torque. Antisymmetric under i <-> j: del, vr, u_t and F_t flip sign,
 * magnitudes are formed from sign-symmetric products. */

static inline void linear_restitution_eval(const struct contact *c,
                                           __global const REAL *param, REAL3 *shear,
                                           struct contact_force *out)
{
    (void)shear;
    const REAL ke = param[LR_KE], kf = param[LR_KF], mu = param[LR_MU];
    const REAL ceta = param[LR_CETA], ctcol = param[LR_CTCOL], torque = param[LR_TORQUE];
    const REAL3 n = c->n;
    const REAL delta = c->delta;
    const REAL sm = sqrt(c->meff);
    const REAL eta = ceta * sm;
    const REAL tcol = ctcol * sm;

    const REAL vn = c->vn;
    const REAL fnmag =
        c->approach ? contact_normal_linear(eta, tcol, delta, -vn, c->meff, c->dt, c->radsum,
                                            !c->shearupdate)
                    : contact_normal_force(NORMAL_LINEAR, (REAL)0.5 * ke, eta, delta, -vn, c->meff,
                                           c->dt);
    /* with torque, the relative velocity of the contact points */
    const REAL3 ut = torque != (REAL)0 ? c->vtr : c->vt;
    const REAL utmag = length(ut);
    REAL3 ft = (REAL3)(0);
    if (utmag > (REAL)0) {
        const REAL fstatic = kf * utmag * tcol;
        const REAL fdyn = mu * fabs(fnmag);
        ft = -(fmin(fstatic, fdyn) / utmag) * ut;
    }
    out->f = fnmag * n + ft;
    out->tc = torque != (REAL)0 ? cross(n, ft) : (REAL3)(0);
    out->tr = (REAL3)(0);
}

/* collision time (kernels/accuracy.cl): t_col = ctcol sqrt(m*) */
static inline REAL linear_restitution_eval_tcol(const struct contact *c,
                                                __global const REAL *param, const REAL vn)
{
    (void)vn;
    return param[LR_CTCOL] * sqrt(c->meff);
}
