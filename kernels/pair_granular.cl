/* pair_granular.cl - LAMMPS `pair_style granular` (today's GranularModel;
 * p[GR_2021]: 29 Sep 2021's pair_granular.cpp compute() where they differ):
 * one small evaluator per sub-model, composed by granular_eval. Host side styles/pair/pair_granular.c; docs
 * doc/styles/pair_granular.md.
 *
 * Composition at program build time (styles/pair/pair_granular.c defines):
 *   GRN_USED, GRD_USED, GRT_USED, GRR_USED, GRW_USED  bit masks of the normal,
 *       damping, tangential, rolling and twisting models some type pair uses
 *       (bit = the GR_N_* ... value of param_layout.h); a model whose bit is
 *       clear is not compiled, a category with one bit needs no run-time test;
 *       GRN_HAS_JKR, GRN_HAS_DMT say the same to the preprocessor.
 *   GR_TANG_HISTORY  some pair has a tangential model with history (LAMMPS
 *       then runs every pair through the history branch, linear_nohistory too)
 *   GR_SYNC_USED  some pair has synchronized_verlet (p[GR_SYNC]; without it
 *       the half-step normal is not compiled)
 *   GR_H_A, GR_H_ROLL, GR_H_TWIST, GR_H_TOUCH, GR_H_DYN  offsets in the
 *       history row of the contact radius of the last step (mindlin_rescale),
 *       the rolling displacement (3), the twist angle, the JKR touch flag, the
 *       /static models' dynamic flag; GR_H_MDR the mdr block (enum mdr_hist of
 *       param_layout.h: its normal force, computed on the host by fix
 *       granular/mdr before the forces); HIST_N its width.
 * They fill a struct gr_layout (constants, folded away) for granular_eval;
 * fix wall/gran granular passes its own layout at run time to
 * granular_eval_l (kernels/fix_wall_gran.cl).
 * Param layout GR_* (param_layout.h), per type pair, host-mixed.
 *
 * Sign convention: n = del / r from j to i. The tangential history is
 * antisymmetric under i <-> j, the rolling and twisting histories and a are
 * symmetric (as LAMMPS computes them); contacts are always evaluated from the
 * owner (the lower tag), so the stored row is the owner's. */

#define GR_IS(used, m, sel) ((((used) >> (m)) & 1) && ((used) == (1 << (m)) || (sel) == (m)))

/* Which sub-models an evaluation may meet and where their history lies:
 * compile-time constants for the pair (folded away), run-time values for a
 * wall/gran granular wall (its own sub-models, kernels/fix_wall_gran.cl).
 * Offsets are -1 when absent; wall = 1: the wall's torque lever arm. */
struct gr_layout {
    int n, d, t, r, w;          /* bit masks of the models met */
    int tang_hist;              /* the tangential history branch */
    int ha, hroll, htwist, htouch, width;
    int wall;
    int hdyn;                   /* the /static models' static (0) / dynamic (1) flag */
    int hmdr;                   /* the mdr block (pairs only; -1 absent) */
};

/* ---- normal models: elastic force Fne, knfac (stiffness for tsuji), a ---- */

/* hooke: Fne = kn delta, a = sqrt(delta R) (for viscoelastic damping) */
static inline REAL grn_hooke(REAL kn, REAL delta, REAL dR, REAL *knfac, REAL *a)
{
    *knfac = kn;
    *a = sqrt(dR);
    return kn * delta;
}

/* hertz, hertz/material: Fne = kn a delta, a = sqrt(delta R), knfac = kn a */
static inline REAL grn_hertz(REAL kn, REAL delta, REAL dR, REAL *knfac, REAL *a)
{
    *a = sqrt(dR);
    *knfac = kn * *a;
    return kn * delta * *a;
}

/* dmt: hertz minus the pull-off 4 pi coh R */
static inline REAL grn_dmt(REAL kn, REAL coh, REAL Reff, REAL delta, REAL dR, REAL *knfac,
                           REAL *a)
{
    REAL fne = grn_hertz(kn, delta, dR, knfac, a);
    return fne - (REAL)4 * (REAL)M_PI * coh * Reff;
}

/* jkr: contact radius a from the overlap (closed-form root of the JKR
 * relation), Fne = kn a^3 / R - 2 pi a^2 sqrt(4 coh E / (pi a)), E = 3/4 kn */
static inline REAL grn_jkr(REAL kn, REAL E, REAL coh, REAL Reff, REAL dR, REAL *knfac, REAL *a)
{
    const REAL R2 = Reff * Reff, dR2 = dR * dR;
    const REAL t0 = coh * coh * R2 * R2 * E;
    const REAL t1 = (REAL)266.47931882941264802866 * t0; /* 27 pi^2 */
    const REAL t2 = (REAL)8 * dR * dR2 * E * E * E;
    const REAL t3 = (REAL)4 * dR2 * E;
    const REAL sqrt1 = fmax((REAL)0, t0 * (t1 + (REAL)2 * t2));
    const REAL t4 = cbrt(t1 + t2 + (REAL)5.19615242270663202362 * (REAL)M_PI * sqrt(sqrt1));
    const REAL t5 = t3 / t4 + t4 / E;
    const REAL sqrt2 = fmax((REAL)0, (REAL)2 * dR + t5);
    const REAL t6 = sqrt(sqrt2);
    const REAL sqrt3 = fmax((REAL)0, (REAL)4 * dR - t5 +
                                         (REAL)14.69693845669906728801 * coh * (REAL)M_PI * R2 /
                                             (E * t6));
    *a = (REAL)0.40824829046386307274 * (t6 + sqrt(sqrt3));
    const REAL a2 = *a * *a;
    *knfac = kn * *a;
    return *knfac * a2 / Reff - (REAL)2 * (REAL)M_PI * a2 * sqrt((REAL)4 * coh * E / ((REAL)M_PI * *a));
}

/* JKR pull-off overlap (negative: the contact holds beyond touch) */
static inline REAL grn_jkr_pulloff(REAL E, REAL coh, REAL Reff)
{
    const REAL a = cbrt((REAL)9.0 * (REAL)M_PI * coh * Reff * Reff / ((REAL)4 * E));
    return a * a / Reff - (REAL)2 * sqrt((REAL)M_PI * coh * a / E);
}

/* ---- damping models: the factor multiplying the damping coefficient ----
 * coeff_restitution (LAMMPS 2024, GranSubModDampingCoeffRestitution, a
 * GranSubModDampingTsuji with its own init): sqrt(m Fne / delta), 0 unless
 * delta > 0, i.e. sqrt(m kn) for hooke and sqrt(m kn a) for hertz and
 * hertz/material (the host turned e into damp, styles/pair/pair_granular.c; the
 * cohesive dmt and jkr are refused there). */
static inline REAL grd_factor(const int used, int model, REAL meff, REAL a, REAL knfac,
                              REAL Fne, REAL delta)
{
    if (GR_IS(used, GR_D_VELOCITY, model))
        return 1;
    if (GR_IS(used, GR_D_MASS_VELOCITY, model))
        return meff;
    if (GR_IS(used, GR_D_VISCOELASTIC, model))
        return a * meff;
    if (GR_IS(used, GR_D_TSUJI, model))
        return sqrt(meff * knfac);
    if (GR_IS(used, GR_D_COEFF_RESTITUTION, model))
        return delta > (REAL)0 ? sqrt(fmax((REAL)0, meff * Fne / delta)) : (REAL)0;
    return 0;
}

/* ---- tangential models ---- */

/* linear_nohistory (no history model in the scene): F_t = -min(mu Fn, gt |v|) v/|v| */
static inline REAL3 grt_nohistory(REAL3 vtr, REAL vrel, REAL damp_t, REAL Fscrit)
{
    const REAL fs = damp_t * vrel;
    const REAL Ft = vrel != (REAL)0 ? fmin(Fscrit, fs) / vrel : (REAL)0;
    return -Ft * vtr;
}

/* Rotate a history vector into the tangent plane keeping its magnitude
 * (LAMMPS: only when its normal part exceeds EPSILON of the limit). */
static inline void gr_frame(REAL *h, REAL3 n)
{
    const REAL dn = h[0] * n.x + h[1] * n.y + h[2] * n.z;
    const REAL mag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    h[0] -= dn * n.x;
    h[1] -= dn * n.y;
    h[2] -= dn * n.z;
    const REAL prj = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    const REAL s = prj > (REAL)0 ? mag / prj : (REAL)0;
    h[0] *= s;
    h[1] *= s;
    h[2] *= s;
}

/* gr_frame of a velocity (synchronized_verlet's damping velocity) */
static inline REAL3 gr_frame3(const REAL3 v, const REAL3 n)
{
    REAL t[3] = {v.x, v.y, v.z};
    gr_frame(t, n);
    return (REAL3)(t[0], t[1], t[2]);
}

/* synchronized_verlet (today's LAMMPS, GranularModel::calculate_forces for a
 * pair; Vyas et al 2025): when forces are computed the positions are at the
 * full step and the velocities at the half step, so the contact is taken at
 * the half step: the normal *n of del - dt/2 vr (normalized as LAMMPS's
 * norm3: times 1/|.|), and the normal rate *vn, the contact-point velocity
 * *vtr (vr - vn n + n x w) on it. Every law term then uses this normal, the
 * force direction and the torques too; the full-step normal c->n serves the
 * second history projection (grt_history, grr_sds). */
static inline void gr_half_step(const struct contact *c, REAL3 *n, REAL *vn, REAL3 *vtr)
{
    const REAL h = (REAL)0.5 * c->dt;
    const REAL3 d = (REAL3)(c->del.x - h * c->vr.x, c->del.y - h * c->vr.y,
                            c->del.z - h * c->vr.z);
    const REAL inv = (REAL)1 / sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    *n = (REAL3)(d.x * inv, d.y * inv, d.z * inv);
    *vn = c->vr.x * n->x + c->vr.y * n->y + c->vr.z * n->z;
    const REAL3 vt = (REAL3)(c->vr.x - *vn * n->x, c->vr.y - *vn * n->y,
                             c->vr.z - *vn * n->z);
    const REAL3 w = c->w;
    *vtr = (REAL3)(vt.x - (w.y * n->z - w.z * n->y), vt.y - (w.z * n->x - w.x * n->z),
                   vt.z - (w.x * n->y - w.y * n->x));
}

/* linear_history, mindlin, mindlin_rescale (displacement history, force =
 * -k s - g v) and mindlin/force, mindlin_rescale/force (elastic-force
 * history, force = s - g v); k = kt (linear) or kt a (mindlin). Coulomb
 * limit Fscrit with the history reset consistently. sync (synchronized_verlet,
 * n the half-step normal): the updated history is projected a second time,
 * onto the full-step normal nf, by the same test, and when that projection
 * happens the damping velocity is the contact velocity rotated the same way
 * (LAMMPS's vtr2, in the force and in the reset history). */
static inline REAL3 grt_history(const int used, const int ha, int model, REAL *h, REAL3 n,
                                REAL3 vtr, REAL k, REAL damp_t, REAL Fscrit, REAL a,
                                const struct contact *c, const int sync, const REAL3 nf)
{
    const int force_hist = GR_IS(used, GR_T_MINDLIN_FORCE, model) ||
                           GR_IS(used, GR_T_MINDLIN_RESCALE_FORCE, model) ||
                           GR_IS(used, GR_T_NOHISTORY, model);
    const int rescale = ha >= 0 && (GR_IS(used, GR_T_MINDLIN_RESCALE, model) ||
                                    GR_IS(used, GR_T_MINDLIN_RESCALE_FORCE, model));
    if (rescale && a < h[ha]) {
        const REAL factor = a / h[ha];
        h[0] *= factor;
        h[1] *= factor;
        h[2] *= factor;
    }
    int frame = 0;
    if (c->shearupdate) {
        const REAL rsht = h[0] * n.x + h[1] * n.y + h[2] * n.z;
        frame = force_hist ? fabs(rsht) > (REAL)1e-10 * Fscrit
                           : fabs(rsht) * k > (REAL)1e-10 * Fscrit;
        if (frame)
            gr_frame(h, n);
        if (!force_hist) {
            h[0] += vtr.x * c->dt;
            h[1] += vtr.y * c->dt;
            h[2] += vtr.z * c->dt;
        } else {
            h[0] -= k * vtr.x * c->dt;
            h[1] -= k * vtr.y * c->dt;
            h[2] -= k * vtr.z * c->dt;
        }
        if (rescale)
            h[ha] = a;
        if (sync) {
            const REAL rs2 = h[0] * nf.x + h[1] * nf.y + h[2] * nf.z;
            frame = force_hist ? fabs(rs2) > (REAL)1e-10 * Fscrit
                               : fabs(rs2) * k > (REAL)1e-10 * Fscrit;
            if (frame)
                gr_frame(h, nf);
        }
    }
    const REAL3 vd = sync && frame ? gr_frame3(vtr, nf) : vtr; /* the damping velocity */
    REAL3 fs;
    if (!force_hist)
        fs = (REAL3)(-k * h[0] - damp_t * vd.x, -k * h[1] - damp_t * vd.y,
                     -k * h[2] - damp_t * vd.z);
    else
        fs = (REAL3)(h[0] - damp_t * vd.x, h[1] - damp_t * vd.y, h[2] - damp_t * vd.z);
    const REAL fsm = sqrt(fs.x * fs.x + fs.y * fs.y + fs.z * fs.z);
    if (fsm > Fscrit) {
        const REAL shrmag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        if (shrmag != (REAL)0) {
            if (!force_hist) {
                h[0] = (REAL)-1.0 / k * (Fscrit * fs.x / fsm + damp_t * vd.x);
                h[1] = (REAL)-1.0 / k * (Fscrit * fs.y / fsm + damp_t * vd.y);
                h[2] = (REAL)-1.0 / k * (Fscrit * fs.z / fsm + damp_t * vd.z);
            } else {
                h[0] = Fscrit * fs.x / fsm + damp_t * vd.x;
                h[1] = Fscrit * fs.y / fsm + damp_t * vd.y;
                h[2] = Fscrit * fs.z / fsm + damp_t * vd.z;
            }
            fs *= Fscrit / fsm;
        } else {
            fs = (REAL3)(0);
        }
    }
    return fs;
}

/* linear_history/static and mindlin/static (today's LAMMPS,
 * GranSubModTangential*Static): linear_history's displacement history with
 * k = kt (kt a for mindlin/static), whose Coulomb limit is mu_s Fncrit while
 * the contact sticks and mu_d Fncrit once it slid: the limit reached
 * switches it to dynamic, a force within the dynamic limit back to static
 * (*dyn, kept in the history row). */
static inline REAL3 grt_static(REAL *h, REAL *dyn, REAL3 n, REAL3 vtr, REAL k, REAL damp_t,
                               REAL Fncrit, REAL mus, REAL mud, const struct contact *c)
{
    const int dynamic = (int)*dyn != 0;
    const REAL Fscrit = Fncrit * (dynamic ? mud : mus);
    if (c->shearupdate) {
        const REAL rsht = h[0] * n.x + h[1] * n.y + h[2] * n.z;
        if (fabs(rsht) * k > (REAL)1e-10 * Fscrit)
            gr_frame(h, n);
        h[0] += vtr.x * c->dt;
        h[1] += vtr.y * c->dt;
        h[2] += vtr.z * c->dt;
    }
    REAL3 fs = (REAL3)(-k * h[0] - damp_t * vtr.x, -k * h[1] - damp_t * vtr.y,
                       -k * h[2] - damp_t * vtr.z);
    const REAL fsm = sqrt(fs.x * fs.x + fs.y * fs.y + fs.z * fs.z);
    if (fsm > Fscrit) {
        const REAL shrmag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        if (shrmag != (REAL)0) {
            const REAL s = Fscrit / fsm;
            h[0] = (REAL)-1.0 / k * (s * fs.x + damp_t * vtr.x);
            h[1] = (REAL)-1.0 / k * (s * fs.y + damp_t * vtr.y);
            h[2] = (REAL)-1.0 / k * (s * fs.z + damp_t * vtr.z);
            fs *= s;
        } else {
            fs = (REAL3)(0);
        }
        if (!dynamic)
            *dyn = 1;
    } else if (dynamic) {
        *dyn = 0;
    }
    return fs;
}

/* linear_history_classic and mindlin_classic (LAMMPS 2023+,
 * GranSubModTangentialLinearHistoryClassic, the GranularModel form of
 * pair gran/hooke/history and gran/hertz/history): s += v_t dt first, its
 * magnitude taken, then projected onto the tangent plane without keeping
 * its magnitude (every update, no threshold); F_t = -k s - eta_t v_t with
 * k = kt (kt a for mindlin_classic); beyond F_scrit, F_t scaled to it and
 * s = -(F_t - F_damp) / k, or no force when the shear was 0 before the
 * projection. LAMMPS's order of operations. */
static inline REAL3 grt_classic(REAL *h, REAL3 n, REAL3 vtr, REAL k, REAL damp_t, REAL Fscrit,
                                const struct contact *c)
{
    if (c->shearupdate) {
        h[0] += c->dt * vtr.x;
        h[1] += c->dt * vtr.y;
        h[2] += c->dt * vtr.z;
    }
    const REAL shrmag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    if (c->shearupdate) {
        const REAL rsht = h[0] * n.x + h[1] * n.y + h[2] * n.z;
        h[0] -= rsht * n.x;
        h[1] -= rsht * n.y;
        h[2] -= rsht * n.z;
    }
    const REAL3 fdamp = (REAL3)(-damp_t * vtr.x, -damp_t * vtr.y, -damp_t * vtr.z);
    REAL3 fs = (REAL3)(-k * h[0] + fdamp.x, -k * h[1] + fdamp.y, -k * h[2] + fdamp.z);
    const REAL fsm = sqrt(fs.x * fs.x + fs.y * fs.y + fs.z * fs.z);
    if (fsm > Fscrit) {
        if (shrmag != (REAL)0) {
            const REAL q = Fscrit / fsm, kinv = (REAL)-1.0 / k;
            fs = (REAL3)(q * fs.x, q * fs.y, q * fs.z);
            h[0] = kinv * (fs.x - fdamp.x);
            h[1] = kinv * (fs.y - fdamp.y);
            h[2] = kinv * (fs.z - fdamp.z);
        } else {
            fs = (REAL3)(0);
        }
    }
    return fs;
}

/* ---- rolling: sds (spring-dashpot-slider on the rolling displacement) ----
 * sync (synchronized_verlet): the updated displacement projected a second
 * time, onto the full-step normal nf, by the same test (no rotated damping
 * velocity here, as LAMMPS's gran_rolling_sds) */
static inline REAL3 grr_sds(REAL *h, REAL3 n, REAL3 vrl, REAL kr, REAL gr, REAL Frcrit,
                            const struct contact *c, const int sync, const REAL3 nf)
{
    if (c->shearupdate) {
        const REAL dn = h[0] * n.x + h[1] * n.y + h[2] * n.z;
        if (fabs(dn) * kr > (REAL)1e-10 * Frcrit)
            gr_frame(h, n);
        h[0] += vrl.x * c->dt;
        h[1] += vrl.y * c->dt;
        h[2] += vrl.z * c->dt;
        if (sync) {
            const REAL dn2 = h[0] * nf.x + h[1] * nf.y + h[2] * nf.z;
            if (fabs(dn2) * kr > (REAL)1e-10 * Frcrit)
                gr_frame(h, nf);
        }
    }
    REAL3 fr = (REAL3)(-kr * h[0] - gr * vrl.x, -kr * h[1] - gr * vrl.y,
                       -kr * h[2] - gr * vrl.z);
    const REAL frm = sqrt(fr.x * fr.x + fr.y * fr.y + fr.z * fr.z);
    if (frm > Frcrit) {
        const REAL mag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        if (mag != (REAL)0) {
            h[0] = (REAL)-1.0 / kr * (Frcrit * fr.x / frm + gr * vrl.x);
            h[1] = (REAL)-1.0 / kr * (Frcrit * fr.y / frm + gr * vrl.y);
            h[2] = (REAL)-1.0 / kr * (Frcrit * fr.z / frm + gr * vrl.z);
            fr *= Frcrit / frm;
        } else {
            fr = (REAL3)(0);
        }
    }
    return fr;
}

/* ---- twisting: sds or marshall (coefficients from the tangential model) ---- */
static inline REAL grw_twist(REAL *h, REAL magtwist, REAL kw, REAL gw, REAL muw, REAL Fncrit,
                             const struct contact *c)
{
    if (c->shearupdate)
        *h += magtwist * c->dt;
    REAL m = -kw * *h - gw * magtwist;
    const REAL sign = (REAL)((magtwist > (REAL)0) - (magtwist < (REAL)0));
    const REAL Mtcrit = muw * Fncrit;
    if (fabs(m) > Mtcrit) {
        *h = (REAL)1.0 / kw * (Mtcrit * sign - gw * magtwist);
        m = -Mtcrit * sign;
    }
    return m;
}

/* The composed law. The torque of LAMMPS, -(rad - delta/2) (n x F_t) +
 * M_twist n + R* n x F_roll on i (the same lever on j, the other two terms
 * negated), is written as tc = (r / radsum) n x F_t and
 * tr = delta (radi - radj) / (2 radsum) n x F_t - (M_twist n + R* n x F_roll). */
static inline void granular_eval_l(const struct contact *c, __global const REAL *p, REAL *h,
                                   struct contact_force *out, const struct gr_layout L)
{
    const int nm = (int)p[GR_NMODEL];
    const REAL radsum = c->radsum, rsq = c->rsq, Reff = c->reff;
    REAL E = p[GR_KN];
    int touch = 1; /* a wall's kernel decides its touch (wall_jkr_reach) */
    const int jkr = L.htouch >= 0 && GR_IS(L.n, GR_N_JKR, nm);
    if (jkr)
        E *= (REAL)0.75;
    if (!L.wall) {
        if (jkr && h[L.htouch] != (REAL)0) {
            const REAL dist = radsum - grn_jkr_pulloff(E, p[GR_COH], Reff);
            touch = rsq < dist * dist;
        } else {
            touch = rsq < radsum * radsum;
        }
    }
    if (!touch) { /* reached only where a JKR pair makes the loop send every pair */
        for (int k = 0; k < L.width; k++)
            h[k] = 0;
        return;
    }
    REAL3 n = c->n; /* the contact's kinematics (kernels/contact.cl) */
    REAL vnnr = c->vn;
    REAL3 vtr = c->vtr; /* tangential relative velocity at the contact */
    int sync = 0;       /* synchronized_verlet: the half-step contact (pairs only) */
#ifdef GR_SYNC_USED
    if (!L.wall && p[GR_SYNC] != (REAL)0) {
        sync = 1;
        gr_half_step(c, &n, &vnnr, &vtr);
    }
#endif
    const REAL meff = c->meff;
    const REAL delta = c->delta, dR = delta * Reff;

    /* normal */
    REAL Fne, knfac, a;
    const int mdr = L.hmdr >= 0 && GR_IS(L.n, GR_N_MDR, nm);
    if (mdr) { /* the host's force (styles/fix/fix_granular_mdr.c); a for mindlin */
        Fne = h[L.hmdr + (L.wall ? MHW_FN : MH_FN)];
        a = sqrt(dR);
        knfac = 0;
    } else if (jkr) {
        h[L.htouch] = 1;
        Fne = grn_jkr(p[GR_KN], E, p[GR_COH], Reff, dR, &knfac, &a);
    } else if (GR_IS(L.n, GR_N_HOOKE, nm))
        Fne = grn_hooke(E, delta, dR, &knfac, &a);
    else if (GR_IS(L.n, GR_N_DMT, nm))
        Fne = grn_dmt(E, p[GR_COH], Reff, delta, dR, &knfac, &a);
    else
        Fne = grn_hertz(E, delta, dR, &knfac, &a);

    REAL damp_pref;
    if (mdr) { /* damping mdr: type 1 eta_n0 times the contact's damping scale, type 2
                * eta_n0 while the scale is not 0 (LAMMPS GranSubModDampingMDR) */
        const REAL sc = h[L.hmdr + (L.wall ? MHW_DAMP_SCALE : MH_DAMP_SCALE)];
        damp_pref = (int)p[GR_MDR_DTYPE] == 1 ? p[GR_DAMP] * sc
                                               : (sc == (REAL)0 ? (REAL)0 : p[GR_DAMP]);
    } else {
        damp_pref = p[GR_DAMP] * grd_factor(L.d, (int)p[GR_DMODEL], meff, a, knfac, Fne, delta);
    }
    REAL Fntot = Fne + -damp_pref * vnnr;
    if (p[GR_LIMIT] != (REAL)0 && Fntot < (REAL)0)
        Fntot = 0;

    const REAL vrel = sqrt(vtr.x * vtr.x + vtr.y * vtr.y + vtr.z * vtr.z);

    /* the normal load of the Coulomb limits: |Fne + 2 F_pulloff| for jkr;
     * for dmt LAMMPS 2021 forms F_pulloff from a cohesion variable it sets
     * only for jkr pairs (0 in a scene without jkr): |Fne| */
    REAL Fncrit = fabs(Fntot);
    if (jkr)
        Fncrit = fabs(Fne + (REAL)2 * ((REAL)3 * (REAL)M_PI * p[GR_COH] * Reff));
    if (GR_IS(L.n, GR_N_DMT, nm)) /* today's LAMMPS: |Fne + 2 F_pulloff|, F_pulloff = 4 pi coh R */
        Fncrit = p[GR_2021] != (REAL)0 ? fabs(Fne)
                                       : fabs(Fne + (REAL)2 * ((REAL)4 * (REAL)M_PI * p[GR_COH] *
                                                               Reff));
    const REAL Fscrit = p[GR_MU] * Fncrit;
    const int tm = (int)p[GR_TMODEL];
    REAL kt = p[GR_KT];
    const REAL damp_t = p[GR_GT] * damp_pref;
    REAL3 fs;
    if (L.hdyn >= 0 && (GR_IS(L.t, GR_T_HISTORY_STATIC, tm) ||
                        GR_IS(L.t, GR_T_MINDLIN_STATIC, tm))) {
        const REAL k = GR_IS(L.t, GR_T_MINDLIN_STATIC, tm) ? kt * a : kt;
        fs = grt_static(h, h + L.hdyn, n, vtr, k, damp_t, Fncrit, p[GR_MU], p[GR_MUD], c);
    } else if (L.tang_hist && (GR_IS(L.t, GR_T_HISTORY_CLASSIC, tm) ||
                               GR_IS(L.t, GR_T_MINDLIN_CLASSIC, tm))) {
        const REAL k = GR_IS(L.t, GR_T_MINDLIN_CLASSIC, tm) ? kt * a : kt;
        fs = grt_classic(h, n, vtr, k, damp_t, Fscrit, c);
    } else if (L.tang_hist) {
        if (GR_IS(L.t, GR_T_MINDLIN, tm) || GR_IS(L.t, GR_T_MINDLIN_FORCE, tm) ||
            GR_IS(L.t, GR_T_MINDLIN_RESCALE, tm) || GR_IS(L.t, GR_T_MINDLIN_RESCALE_FORCE, tm))
            kt *= a;
        fs = grt_history(L.t, L.ha, tm, h, n, vtr, kt, damp_t, Fscrit, a, c, sync, c->n);
    } else {
        fs = grt_nohistory(vtr, vrel, damp_t, Fscrit);
    }

    REAL3 tw = (REAL3)(0); /* M_twist n + R* n x F_roll (torque on i) */
    const REAL3 relrot = c->omi - c->omj;
    if (L.hroll >= 0 && GR_IS(L.r, GR_R_SDS, (int)p[GR_RMODEL])) {
        const REAL3 vrl = (REAL3)(Reff * (relrot.y * n.z - relrot.z * n.y),
                                  Reff * (relrot.z * n.x - relrot.x * n.z),
                                  Reff * (relrot.x * n.y - relrot.y * n.x));
        const REAL3 fr = grr_sds(h + L.hroll, n, vrl, p[GR_KR], p[GR_GR], p[GR_MUR] * Fncrit,
                                 c, sync, c->n);
        tw += (REAL3)(Reff * (n.y * fr.z - n.z * fr.y), Reff * (n.z * fr.x - n.x * fr.z),
                      Reff * (n.x * fr.y - n.y * fr.x));
    }
    if (L.htwist >= 0) {
        const int wm = (int)p[GR_WMODEL];
        const REAL magtwist = relrot.x * n.x + relrot.y * n.y + relrot.z * n.z;
        REAL kw = p[GR_KW], gw = p[GR_GW], muw = p[GR_MUW];
        int on = GR_IS(L.w, GR_W_SDS, wm);
        if (GR_IS(L.w, GR_W_MARSHALL, wm)) {
            /* Marshall eq. 32 with the tangential model's kt (today's LAMMPS:
             * unscaled; LAMMPS 2021: kt a for the mindlin models) */
            kw = (REAL)0.5 * (p[GR_2021] != (REAL)0 ? kt : p[GR_KT]) * a * a;
            gw = (REAL)0.5 * damp_t * a * a;
            muw = (REAL)(2.0 / 3.0) * a * p[GR_MU];
            on = 1;
        }
        if (on)
            tw += grw_twist(h + L.htwist, magtwist, kw, gw, muw, Fncrit, c) * n;
    }

#ifdef HAS_HEAT /* the heat sub-model (kernels/gran_heat.cl), on the contact radius a */
    out->q = gran_heat((int)p[GR_HMODEL], p[GR_HK], a, c->ti, c->tj);
#endif
    out->f = (REAL3)(n.x * Fntot + fs.x, n.y * Fntot + fs.y, n.z * Fntot + fs.z);
    const REAL3 tor = (REAL3)(n.y * fs.z - n.z * fs.y, n.z * fs.x - n.x * fs.z,
                              n.x * fs.y - n.y * fs.x);
    if (L.wall) { /* LAMMPS 2021 fix wall/gran: lever arm radi */
        out->tc = tor;
        out->tr = -tw;
        return;
    }
    out->tc = (c->r / radsum) * tor;
    out->tr = (delta * (c->radi - c->radj) / ((REAL)2 * radsum)) * tor - tw;
}

/* Collision time of a contact of this model (the accuracy records,
 * kernels/accuracy.cl; the host's model_tcol in styles/pair/pair_granular.c
 * is the same for two equal spheres): undamped, hooke the linear spring's
 * half period, hertz, hertz/material, dmt and jkr Johnson's Hertz time of kn
 * = 4/3 E*; 0 (no record) when kn = 0. Pair and wall/gran granular walls. */
static inline REAL granular_tcol(const struct contact *c, __global const REAL *p, const REAL vn)
{
    if (!(p[GR_KN] > (REAL)0))
        return 0;
    if ((int)p[GR_NMODEL] == GR_N_HOOKE)
        return tcol_linear(p[GR_KN], 0, c->meff);
    return tcol_hertz(p[GR_KN], c->reff, c->meff, vn);
}

/* The pair's evaluator: the layout of the build options (folded away). */
#ifdef GRN_USED
#ifndef GR_H_A
#define GR_H_A -1
#endif
#ifndef GR_H_ROLL
#define GR_H_ROLL -1
#endif
#ifndef GR_H_TWIST
#define GR_H_TWIST -1
#endif
#ifndef GR_H_TOUCH
#define GR_H_TOUCH -1
#endif
#ifndef GR_H_DYN
#define GR_H_DYN -1
#endif
#ifndef GR_H_MDR
#define GR_H_MDR -1
#endif
#ifdef GR_TANG_HISTORY
#define GR_TANG_HISTORY_ON 1
#else
#define GR_TANG_HISTORY_ON 0
#endif
#ifdef HAS_HISTORY
#define GR_WIDTH HIST_ZERO_N /* a trailing HIST_OWNER slot is not the law's */
#else
#define GR_WIDTH 0
#endif
static inline void granular_eval(const struct contact *c, __global const REAL *p, REAL *h,
                                 struct contact_force *out)
{
    const struct gr_layout L = {GRN_USED,   GRD_USED,  GRT_USED,   GRR_USED,
                                GRW_USED,   GR_TANG_HISTORY_ON,    GR_H_A,
                                GR_H_ROLL,  GR_H_TWIST, GR_H_TOUCH, GR_WIDTH, 0,
                                GR_H_DYN,   GR_H_MDR};
    granular_eval_l(c, p, h, out, L);
}
static inline REAL granular_eval_tcol(const struct contact *c, __global const REAL *p,
                                      const REAL vn)
{
    return granular_tcol(c, p, vn);
}
#endif
