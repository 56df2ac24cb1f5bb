/* pair_loop.cl - the particle-particle stage of the contact pipeline.
 *
 * Contacts (built at each neighbor rebuild, kernels/neighbor.cl): contact c
 * joins its owner ci[c] (the partner with the lower tag) and cj[c]; with
 * history, shear[3c ..] is its tangential history, seen from the owner. Each
 * contact is evaluated once, by pair_contacts, through the active evaluator
 * PAIR_EVAL (PAIR_EVAL_ROW: an evaluator taking the contact's whole history
 * row of HIST_N REAL, pair granular), which writes what each side receives into that side's
 * incidence record (force in recf, torque in rect): cslot[2c] (owner: F,
 * -radi tc - tr) and cslot[2c + 1] (partner: -F, -radj tc + tr). A particle's incidences ioff[i] ..
 * ioff[i + 1] - 1 follow its row, in ascending partner tag; pair_gather sums
 * them in that order (a stream), so a particle's sum depends on the
 * particles only, never on memory order, the cell sort, the rebuild
 * schedule or the work split. No atomics; the two sides' forces are exact
 * negatives.
 *
 * acc/astep: the contact's collision-resolution record (kernels/accuracy.cl).
 *
 * meff = mi mj / (mi + mj); when one particle is in the freeze group
 * (freezebit), meff is the other particle's mass (LAMMPS pair gran). */

#if defined(PAIR_EVAL) || defined(PAIR_EVAL_ROW)
/* The contact between i and j as the evaluators see it (del = x_i - x_j,
 * already computed: the rest is loaded only for pairs that interact). */
static inline struct contact pair_contact(const int i, const int j, const REAL3 del,
                                          const REAL radi, const REAL radj,
                                          __global const REAL *v, __global const REAL *omega,
                                          __global const REAL *rmass, __global const uint *mask,
                                          const uint freezebit)
{
#ifdef HAS_ROTATION
    const REAL3 omi = vload3(i, omega), omj = vload3(j, omega);
#else
    const REAL3 omi = (REAL3)(0), omj = (REAL3)(0);
#endif
    const REAL mi = rmass[i], mj = rmass[j];
    REAL meff = mi * mj / (mi + mj);
    if (mask[i] & freezebit)
        meff = mj;
    if (mask[j] & freezebit)
        meff = mi;
    return contact_make(del, radi, radj, radi * radj / (radi + radj), vload3(i, v) - vload3(j, v),
                        omi, omj, meff);
}

#ifdef PAIR_APPROACH
/* |normal rate| dt > gap: the next drift at this rate closes the gap, or
 * the last one opened it (the pair is apart: rsq >= radsum^2) */
static inline int pair_within_drift(const int i, const int j, const REAL3 del, const REAL rsq,
                                    const REAL radsum, __global const REAL *v, const REAL dt)
{
    const REAL dv = fabs(dot(vload3(i, v) - vload3(j, v), del)) * dt;
    /* r (r - radsum) >= (rsq - radsum^2) / 2: most pairs leave without the sqrt */
    if (dv <= (REAL)0.5 * (rsq - radsum * radsum))
        return 0;
    const REAL r = sqrt(rsq);
    return dv > r * (r - radsum);
}
#endif

__kernel void pair_contacts(const int ncontact, __global const int *ci, __global const int *cj,
                            __global const int *cslot,
                            __global const REAL *x, __global const REAL *v,
                            __global const REAL *omega, __global const REAL *radius,
                            __global const REAL *rmass, __global const int *type,
                            __global const uint *mask, __global REAL *shear,
                            __global const REAL *param, const int ntypes, const int nparam,
                            const uint freezebit, const REAL dt, const int shearupdate,
                            const REAL Lx, const REAL Ly, const REAL Lz, const REAL xy,
                            const REAL xz, const REAL yz, __global REAL *recf,
                            __global REAL *rect, __global REAL *acc, __global int *astep,
                            const int step, __global const REAL *hrate,
                            const uint vgroup POS_LO_PARAM)
{
    const int c = get_global_id(0);
    if (c >= ncontact)
        return;
    const int i = ci[c], j = cj[c];
    REAL3 del = vload3(i, x) - vload3(j, x);
#ifdef VREMAP
    const REAL3 raw = del;
#else
    (void)hrate;
    (void)vgroup;
#endif
    MINIMG3(del);
#ifdef SPLIT_POS /* the low parts: refined by contact_refine (kernels/common.cl) */
    const REAL3 del_lo = vload3(i, xlo) - vload3(j, xlo);
    const REAL3 dtest = del + del_lo;
#else
    const REAL3 del_lo = (REAL3)(0);
    const REAL3 dtest = del;
#endif
    const REAL radi = radius[i], radj = radius[j];
    struct contact_force out;
    out.f = out.tc = out.tr = (REAL3)(0);
    struct contact k;
    int touch = 0;
#ifdef HAS_COHESION /* cohesion acts beyond body contact: every listed pair goes to
                      * PAIR_EVAL, whose terms gate themselves (pair_hybrid_overlay.cl) */
    k = pair_contact(i, j, del, radi, radj, v, omega, rmass, mask, freezebit);
    contact_refine(&k, del_lo);
    touch = 1;
#else
    const REAL radsum = radi + radj;
    const REAL rsq = dtest.x * dtest.x + dtest.y * dtest.y + dtest.z * dtest.z;
    if (rsq < radsum * radsum) {
        k = pair_contact(i, j, del, radi, radj, v, omega, rmass, mask, freezebit);
        touch = contact_refine(&k, del_lo);
    }
#ifdef PAIR_APPROACH /* also pairs apart that one drift at their normal rate
                      * brings into or out of contact (contact_normal_linear) */
    if (!touch && pair_within_drift(i, j, dtest, rsq, radsum, v, dt)) {
        k = pair_contact(i, j, del, radi, radj, v, omega, rmass, mask, freezebit);
        contact_refine(&k, del_lo);
        touch = 1;
    }
#endif
#endif
#ifdef VREMAP /* the partner's image streams with the box (LAMMPS's ghost velocities) */
    if (touch && (mask[j] & vgroup))
        k.vr -= image_velocity(image_count(raw, del, Lx, Ly, Lz, xy, xz, yz), hrate);
#endif
    if (!touch) {
#ifdef HAS_HISTORY
        /* a separated pair forgets its history; most are zero already */
        __global REAL *hrow = shear + (size_t)c * HIST_N;
        int any = 0;
        for (int q = 0; q < HIST_ZERO_N; q++)
            any |= hrow[q] != (REAL)0;
        if (any)
            for (int q = 0; q < HIST_ZERO_N; q++)
                hrow[q] = 0;
#endif
    } else {
        k.dt = dt;
        k.shearupdate = shearupdate;
#if defined(PAIR_APPROACH) && !defined(HAS_COHESION)
        k.approach = 1;
#endif
        __global const REAL *p = param + (size_t)((type[i] - 1) * ntypes + (type[j] - 1)) * nparam;
#ifdef PAIR_EVAL_ROW /* history of any width: the evaluator takes the whole row */
        REAL h[HIST_N];
#ifdef HAS_HISTORY
        for (int q = 0; q < HIST_N; q++)
            h[q] = shear[(size_t)c * HIST_N + q];
#endif
        PAIR_EVAL_ROW(&k, p, h, &out);
#ifdef HAS_HISTORY
        for (int q = 0; q < HIST_N; q++)
            shear[(size_t)c * HIST_N + q] = h[q];
#endif
#else
#ifdef HAS_HISTORY
        REAL3 sh = vload3(c, shear);
#else
        REAL3 sh = (REAL3)(0);
#endif
        PAIR_EVAL(&k, p, &sh, &out);
        /* collision resolution of the contacts that happen (accuracy.cl) */
        if (k.rsq < k.radsum * k.radsum)
            ACC_NOTE_PAIR(PAIR_EVAL, c, &k, p, acc, astep, step);
#ifdef HAS_HISTORY
        vstore3(sh, c, shear);
#endif
#endif
    }
    const size_t si = (size_t)cslot[2 * c], sj = (size_t)cslot[2 * c + 1];
    vstore3(out.f, si, recf);
    vstore3(-out.f, sj, recf);
#ifdef HAS_ROTATION
    vstore3(-radi * out.tc - out.tr, si, rect);
    vstore3(-radj * out.tc + out.tr, sj, rect);
#endif
}
#endif /* PAIR_EVAL || PAIR_EVAL_ROW */

/* f_i (and torque_i) = the sum of i's incidence records in row order;
 * written, not added (this also clears the force of the step). Then the
 * fused post_force ops [first, first + npost) and final_integrate ops
 * [first + npost, first + npost + nfinal) of kernels/fused.cl, which may
 * change f, torque, v and omega. */
__kernel void pair_gather(const int n, __global const int *ioff, __global const REAL *recf,
                          __global const REAL *rect,
                          __global REAL *f, __global REAL *torque, __global const int *ops,
                          const int first, const int npost, const int nfinal,
                          __global const REAL *prm, __global REAL *v, __global REAL *omega,
                          __global const REAL *rmass, __global const REAL *radius,
                          __global const int *type, __global const uint *mask)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    REAL3 fs = (REAL3)(0), ts = (REAL3)(0);
    for (int s = ioff[i], e = ioff[i + 1]; s < e; s++) {
        fs += vload3((size_t)s, recf);
#ifdef HAS_ROTATION
        ts += vload3((size_t)s, rect);
#endif
    }
    if (npost + nfinal > 0) {
        struct fused_atom at;
        at.f = fs;
        at.tq = ts;
        at.v = vload3(i, v);
#ifdef HAS_ROTATION
        at.om = vload3(i, omega);
#endif
        at.m = rmass[i];
        at.r = radius[i];
        at.type = type[i];
        at.mask = mask[i];
        fused_apply(&at, ops, first, npost + nfinal, prm);
        fs = at.f;
        ts = at.tq;
        if (nfinal > 0) {
            vstore3(at.v, i, v);
#ifdef HAS_ROTATION
            vstore3(at.om, i, omega);
#endif
        }
    }
    vstore3(fs, i, f);
#ifdef HAS_ROTATION
    vstore3(ts, i, torque);
#endif
}

/* The pair virial of the step, per particle, for the pressure (run only on
 * the steps that print it, after the step's pair_contacts): w_i = 1/2 sum
 * over i's incidence records, in row order, of the tensor del_a F_b in
 * LAMMPS's order xx yy zz xy xz yz (6 REAL per particle), del = x_i - x_j
 * (minimum image), F what i receives. A contact's two sides give the same
 * product, so sum_i w_i = sum over contacts of del F, LAMMPS's
 * ev_tally_xyz virial. Positions have not moved since the forces
 * (final_integrate changes velocities only). */
__kernel void pair_virial(const int n, __global const int *nlist, const int maxn,
                          __global const int *ioff, __global const REAL *recf,
                          __global const REAL *x, const REAL Lx, const REAL Ly, const REAL Lz,
                          const REAL xy, const REAL xz, const REAL yz, __global REAL *w)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const REAL3 xi = vload3(i, x);
    REAL3 s = (REAL3)(0), o = (REAL3)(0);
    const int s0 = ioff[i], cnt = ioff[i + 1] - s0;
    for (int k = 0; k < cnt; k++) {
        const int j = nlist[(size_t)i * maxn + k];
        REAL3 del = xi - vload3(j, x);
        MINIMG3(del);
        const REAL3 f = vload3((size_t)(s0 + k), recf);
        s += del * f;
        o += (REAL3)(del.x * f.y, del.x * f.z, del.y * f.z);
    }
    vstore3((REAL)0.5 * s, 2 * i, w);
    vstore3((REAL)0.5 * o, 2 * i + 1, w);
}

#ifdef PAIR_ENERGY
/* The pair energy of the step, per particle (a potential's style only; run
 * on the steps that print it): e_i = 1/2 sum over i's row, in row order, of
 * PAIR_ENERGY(rsq, param of (type i, type j)), which is 0 beyond the type
 * pair's cut-off. The two sides of a pair give the same energy, so sum_i e_i
 * is the per-pair sum, LAMMPS's eng_vdwl. */
__kernel void pair_energy(const int n, __global const int *nlist, const int maxn,
                          __global const int *ioff, __global const REAL *x,
                          __global const int *type, __global const REAL *param,
                          const int ntypes, const int nparam, const REAL Lx, const REAL Ly,
                          const REAL Lz, const REAL xy, const REAL xz, const REAL yz,
                          __global REAL *e)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const REAL3 xi = vload3(i, x);
    const int ti = type[i];
    REAL s = 0;
    const int cnt = ioff[i + 1] - ioff[i];
    for (int k = 0; k < cnt; k++) {
        const int j = nlist[(size_t)i * maxn + k];
        REAL3 del = xi - vload3(j, x);
        MINIMG3(del);
        const REAL rsq = del.x * del.x + del.y * del.y + del.z * del.z;
        s += PAIR_ENERGY(rsq, param + (size_t)((ti - 1) * ntypes + (type[j] - 1)) * nparam);
    }
    e[i] = (REAL)0.5 * s;
}
#endif

/* Zero the force (and torque) when no pair style computes them. */
__kernel void force_clear(const int n, __global REAL *f, __global REAL *torque)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    vstore3((REAL3)(0), i, f);
#ifdef HAS_ROTATION
    vstore3((REAL3)(0), i, torque);
#endif
}
