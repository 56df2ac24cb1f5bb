/* pair_loop.cl - the particle-particle stage of the contact pipeline.
 *
 * Contacts (built at each neighbor rebuild, kernels/neighbor.cl): contact c
 * joins its owner ci[c] (the partner with the lower tag) and cj[c]; with
 * history, shear[3c ..] is its tangential history, seen from the owner. Each
 * contact is evaluated once, by pair_contacts, through the active evaluator
 * PAIR_EVAL (PAIR_EVAL_ROW: an evaluator taking the contact's whole history
 * row of HIST_N REAL, pair granular), which writes the contact's record of
 * REC_W REAL at its own index c: the force F on the owner (the partner
 * receives -F), then with rotation the owner's torque -radi tc - tr and the
 * partner's -radj tc + tr, or, for a law without rolling torque (tr = 0,
 * PAIR_TC), tc alone, from which each side's gather takes -rad tc with its
 * own radius (the same products; a sum that starts at +0 is blind to the
 * sign of a zero term, so tr's +-0 is not missed). A particle's row holds
 * its partners in ascending tag: first those of lower tag (it is their
 * contact's partner: contact pcon[ioff[i] - coff[i] + k] for row slot k),
 * then those it owns (its contacts coff[i] .. coff[i + 1] - 1, in row
 * order); pair_gather sums the records in that order, so a particle's sum
 * depends on the particles only, never on memory order, the cell sort, the
 * rebuild schedule or the work split. No atomics; the two sides' forces are
 * exact negatives. The owned contacts' records are read as a stream, the
 * others' once each.
 *
 * acc/astep: the contact's collision-resolution record (kernels/accuracy.cl).
 * A contact that does not act writes zero records; one that did not act at
 * its last evaluation either (quiet[c], reset at every rebuild and run
 * start) skips those stores, and pair_gather reads a shared record of
 * zeros in place of its own (rec_take): most listed pairs of a flowing bed
 * are apart for many steps.
 *
 * meff = mi mj / (mi + mj); when one particle is in the freeze group
 * (freezebit), meff is the other particle's mass (LAMMPS pair gran). */

/* A contact's record (see the top): F; F tc (PAIR_TC); F ti tj */
#if defined(HAS_ROTATION) && defined(PAIR_TC)
#define REC_W 6
#elif defined(HAS_ROTATION)
#define REC_W 9
#else
#define REC_W 3
#endif
#define REC_F(c) ((size_t)(c) * REC_W)
#define REC_T(c) ((size_t)(c) * REC_W + 3)
#define REC_TJ(c) ((size_t)(c) * REC_W + 6)

#if defined(PAIR_EVAL) || defined(PAIR_EVAL_ROW)
/* the pair law's contact body (kernels/contact.cl), with its collision
 * time for the accuracy records (pair granular's row form too) */
#ifdef PAIR_EVAL_ROW
#define PAIR_ROW 1
CONTACT_BODY(pair_body, PAIR_EVAL_ROW, 1, TCOL_OF(PAIR_EVAL_ROW))
#else
#define PAIR_ROW 0
CONTACT_BODY(pair_body, PAIR_EVAL, 0, TCOL_OF(PAIR_EVAL))
#endif
#ifdef HAS_HISTORY
#define PAIR_HIST_N HIST_N
#else
#define PAIR_HIST_N 0
#endif

/* The one-contact kernel: pair_contacts, or pair_contacts_1 beside a lane
 * form of the stage (kernels/pair_gran_lanes.cl, PAIR_LW > 1), which a run
 * may time against it and take at any step (src/engine/lanes_tune.h): the
 * same bits either way. Arguments: KARGS_pair_contacts
 * (kernels/kernel_args.h). */
#if !defined(PAIR_LW) || PAIR_LW == 1
#define PAIR_CONTACTS_ONE pair_contacts
#else
#define PAIR_CONTACTS_ONE pair_contacts_1
#endif
__kernel void PAIR_CONTACTS_ONE(KA_KERNEL(pair_contacts))
{
    KA_UNPACK(pair_contacts);
    if (KA_HALTED())
        return;
    const int c = get_global_id(0);
    if (c >= ncontact)
        return;
    const int i = ci[c], j = cj[c];
    struct contact_site s;
    s.del = vload3(i, x) - vload3(j, x);
#ifdef VREMAP
    const REAL3 raw = s.del;
#else
    (void)hrate;
    (void)vgroup;
#endif
    MINIMG3(s.del);
#ifdef SPLIT_POS /* the low parts: refined by contact_refine (kernels/contact.cl) */
    s.del_lo = vload3(i, xlo) - vload3(j, xlo);
#else
    s.del_lo = (REAL3)(0);
#endif
    s.radi = radius[i];
    s.radj = radius[j];
    s.rwall = 0;
    s.rgiven = -1;
    s.reach = s.radi + s.radj;
    s.acts = 1;
    s.inclusive = 0;
    s.hold = -1;
#ifdef PAIR_HIST_KEEP /* LIGGGHTS's pair gran: a separated pair keeps its history */
    s.hzero = 0;
#else
    s.hzero = PAIR_HIST_N > 0 ? HIST_ZERO_N : 0;
#endif
    s.note = 1;
    s.note_idx = c;
    s.acode = 0;
    s.refine = 1;
#ifdef HAS_COHESION /* cohesion acts beyond body contact: every listed pair within
                      * the effect reach goes to the law, whose terms gate themselves
                      * (pair_hybrid_overlay.cl) */
    s.gated = 1;
    s.approach = 0;
#if !defined(PAIR_TYPECUT) && !defined(PAIR_EVAL_ROW)
    /* the list's bound on every term's reach, 1e-4 wider than any rounding of
     * a term's own test: a pair beyond it gets nothing from any term and its
     * history zeroed, the same bits as the laws' own evaluation gives */
    s.reach = fmax(s.reach, (REAL)COH_REACH_A + (REAL)COH_REACH_B * s.reach) * (REAL)1.0001;
#else /* a potential's type cut-off or pair granular's jkr hold: the law decides */
    s.reach = INFINITY;
#endif
#else
    s.gated = 0;
#ifdef PAIR_APPROACH
    s.approach = 1;
#else
    s.approach = 0;
#endif
#endif
    struct contact_partner pj;
    pj.j = j;
    pj.freezebit = freezebit;
    pj.mask = mask;
#ifdef VREMAP
    pj.vremap = (mask[j] & vgroup) != 0;
    pj.vimage = pj.vremap ? image_velocity(image_count(raw, s.del, Lx, Ly, Lz, xy, xz, yz), hrate)
                          : (REAL3)(0);
#endif
    struct contact_atoms a =
        contact_atoms_of(v, omega, rmass, dt, shearupdate, acc, astep, step);
    contact_atoms_heat(a, temp);
    REAL h[PAIR_ROW ? HIST_N : 3];
    __global REAL *hrow = shear + (size_t)c * HIST_N;
    for (int q = 0; q < (PAIR_ROW ? HIST_N : 3); q++)
        h[q] = q < PAIR_HIST_N ? hrow[q] : (REAL)0;
    __global const REAL *p = param + (size_t)((type[i] - 1) * ntypes + (type[j] - 1)) * nparam;
    struct contact_out o;
    o.f = o.ti = o.tj = o.tc = (REAL3)(0);
#ifdef HAS_HEAT
    o.q = 0;
#endif
    const int acted = pair_body(CONTACT_PAIR, i, &s, &pj, &a, p, h, &o);
    contact_hist_store(hrow, h, acted ? PAIR_HIST_N : s.hzero, acted);
    /* apart now and when last evaluated: its records hold these zeros already */
    const uchar was_quiet = quiet[c];
    if (!acted && was_quiet)
        return;
    if (was_quiet != !acted)
        quiet[c] = !acted;
    vstore3(o.f, 0, rec + REC_F(c));
#if defined(HAS_ROTATION) && defined(PAIR_TC)
    vstore3(o.tc, 0, rec + REC_T(c));
#elif defined(HAS_ROTATION)
    vstore3(o.ti, 0, rec + REC_T(c));
    vstore3(o.tj, 0, rec + REC_TJ(c));
#endif
#ifdef HAS_HEAT /* the heat record, as the force: the partner receives -q */
    recq[c] = o.q;
#else
    (void)temp;
    (void)recq;
#endif
}
#endif /* PAIR_EVAL || PAIR_EVAL_ROW */

/* What particle i receives from contact c's record (see the top), added to
 * its sums: partner, i is the contact's partner (-F and the partner's
 * torque); nr = -radius[i] (PAIR_TC: the torque -rad tc). A quiet contact's
 * record is zero (pair_contacts wrote it so and has not written it since):
 * the record zidx, zeros that stay in cache (src/engine/neighbor.c,
 * zero_record), is read in its place, so the same sums are taken
 * without a load of the contact's own. The choice is arithmetic on the
 * flag's byte q (0 or 1), not a branch: apart and touching contacts mix
 * unpredictably in a packing. */
static inline void rec_take(__global const REAL *rec, const int c, const int zidx,
                            const uint q, const int partner, const REAL nr, REAL3 *fs,
                            REAL3 *ts)
{
    const long own = (long)REC_F(c);
    __global const REAL *r = rec + (own + (long)q * ((long)REC_F(zidx) - own));
    const REAL3 f = vload3(0, r);
    *fs = partner ? *fs - f : *fs + f;
#if defined(HAS_ROTATION) && defined(PAIR_TC)
    const REAL3 t = nr * vload3(0, r + 3);
    *ts += t;
#elif defined(HAS_ROTATION)
    *ts += vload3(0, r + (partner ? 6 : 3));
#else
    (void)nr;
    (void)ts;
#endif
}

/* i's contact sums: the records of its contacts in row order (see the top:
 * the contacts i is the partner of, then its own) into *fs and *ts (from
 * zero), and with heat its heat flow of the step, stored; in the tail, f_i
 * and torque_i as they are. Shared by the one-particle and the lane forms
 * (kernels/atom_lanes.cl). */
static inline __attribute__((always_inline)) void
gather_sums(const int i, const int tail, __global const int *ioff, __global const int *coff,
            __global const int *pcon, __global const uchar *quiet, __global const REAL *rec,
            const int zidx, __global const REAL *f,
            __global const REAL *torque, __global const REAL *radius,
            __global const REAL *recq, __global REAL *heatflow, REAL3 *fs, REAL3 *ts)
{
    *fs = (REAL3)(0);
    *ts = (REAL3)(0);
    if (tail) {
        *fs = vload3(i, f);
#ifdef HAS_ROTATION
        *ts = vload3(i, torque);
#else
        (void)torque;
#endif
    } else {
        const int c0 = coff[i], c1 = coff[i + 1];
        const int p0 = ioff[i] - c0, p1 = ioff[i + 1] - c1; /* i's partner-side slots in pcon */
        const REAL nr = -radius[i];
        for (int s = p0; s < p1; s++) {
            const int c = pcon[s];
            rec_take(rec, c, zidx, quiet[c], 1, nr, fs, ts);
        }
        for (int c = c0; c < c1; c++)
            rec_take(rec, c, zidx, quiet[c], 0, nr, fs, ts);
#ifdef HAS_HEAT /* the step's heat flow: i's heat records in the same row order */
        REAL qs = 0;
        for (int s = p0; s < p1; s++)
            qs -= recq[pcon[s]];
        for (int c = c0; c < c1; c++)
            qs += recq[c];
        heatflow[i] = qs;
#endif
    }
#ifndef HAS_HEAT
    (void)recq;
    (void)heatflow;
#endif
}

/* f_i (and torque_i) = i's contact sums (gather_sums); written, not added
 * (this also clears the force of the step); in the tail, f_i as it is. Then
 * the fused post_force ops [first, first + npost) and final_integrate and
 * end_of_step ops [first + npost, first + npost + nfinal) of
 * kernels/fused.cl, which may change f, torque, v and omega (and the fused
 * fix's store); with look, the next step's opening
 * (kernels/atom_step.cl) on the state in registers. */
/* (tail: fused_tail below; the force so far is read, not gathered) */
static inline __attribute__((always_inline)) void gather_atom(KA_PARAMS(pair_gather),
                                                              const int tail, const int i)
{
    REAL3 fs, ts;
    gather_sums(i, tail, ioff, coff, pcon, quiet, rec, zidx, f, torque, radius, recq, heatflow,
                &fs, &ts);
    if (npost + nfinal > 0 || look) {
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
#ifdef FUSED_DRAG /* fix drag's ops read the position */
        at.x = vload3(i, x);
        at.xl = POS_LOAD_LO(i);
#endif
        fused_apply(&at, ops, first, npost + nfinal, prm, store, i);
        fs = at.f;
        ts = at.tq;
        if (look) { /* atom_step stores v and omega after its own ops */
#ifndef FUSED_DRAG
            at.x = vload3(i, x);
            at.xl = POS_LOAD_LO(i);
#endif
            if (ninit == 0 && nfinal > 0) {
                vstore3(at.v, i, v);
#ifdef HAS_ROTATION
                vstore3(at.om, i, omega);
#endif
            }
            atom_step(i, &at, KA_ARGS(atom_step), v, omega, ops, prm POS_LO_ARG);
        } else if (nfinal > 0) {
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

/* The one-particle kernels: pair_gather and fused_tail, or pair_gather_1
 * and fused_tail_1 beside their lane forms (kernels/atom_lanes.cl, ATOM_LW
 * > 1), as pair_contacts_1 above. Arguments: KARGS_pair_gather
 * (kernels/kernel_args.h). */
#if !defined(ATOM_LW) || ATOM_LW == 1
#define PAIR_GATHER_ONE pair_gather
#define FUSED_TAIL_ONE fused_tail
#else
#define PAIR_GATHER_ONE pair_gather_1
#define FUSED_TAIL_ONE fused_tail_1
#endif
__kernel void PAIR_GATHER_ONE(KA_KERNEL(pair_gather))
{
    KA_UNPACK(pair_gather);
    if (KA_HALTED())
        return;
    const int i = get_global_id(0);
    if (i < n)
        gather_atom(KA_ARGS(pair_gather), 0, i);
}

/* The fused tail (src/engine/fused.h): when the post_force stage fused only
 * a prefix, the fused ops of the post_force fixes after the last unfused
 * one and of final_integrate and end_of_step, on the force the unfused
 * fixes (walls) left in f and torque, after them; with look, the next
 * step's opening, as pair_gather's. Same arguments as pair_gather (the
 * contact ones unused). */
__kernel void FUSED_TAIL_ONE(KA_KERNEL(pair_gather))
{
    KA_UNPACK(pair_gather);
    if (KA_HALTED())
        return;
    const int i = get_global_id(0);
    if (i < n)
        gather_atom(KA_ARGS(pair_gather), 1, i);
}

/* The pair virial of the step, per particle, for the pressure (run only on
 * the steps that print it, after the step's pair_contacts): w_i = 1/2 sum
 * over i's row, in row order, of the tensor del_a F_b in LAMMPS's order xx
 * yy zz xy xz yz (6 REAL per particle), del = x_i - x_j (minimum image), F
 * what i receives from that contact (its record, or minus it on the
 * partner's side: see the top). A contact's two sides give the same
 * product, so sum_i w_i = sum over contacts of del F, LAMMPS's
 * ev_tally_xyz virial. Positions have not moved since the forces
 * (final_integrate changes velocities only). */
__kernel void pair_virial(const int n, __global const int *nlist, const int maxn,
                          __global const int *ioff, __global const int *coff,
                          __global const int *pcon, __global const REAL *rec,
                          __global const REAL *x, const REAL Lx, const REAL Ly, const REAL Lz,
                          const REAL xy, const REAL xz, const REAL yz, __global REAL *w)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const REAL3 xi = vload3(i, x);
    REAL3 s = (REAL3)(0), o = (REAL3)(0);
    const int cnt = ioff[i + 1] - ioff[i], c0 = coff[i];
    const int nlow = cnt - (coff[i + 1] - c0), p0 = ioff[i] - c0;
    for (int k = 0; k < cnt; k++) {
        const int j = nlist[(size_t)i * maxn + k];
        REAL3 del = xi - vload3(j, x);
        MINIMG3(del);
        const REAL3 f = k < nlow ? -vload3(0, rec + REC_F(pcon[p0 + k]))
                                 : vload3(0, rec + REC_F(c0 + k - nlow));
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
__kernel void force_clear(KA_KERNEL(force_clear))
{
    KA_UNPACK(force_clear);
    const int i = get_global_id(0);
    if (i >= n)
        return;
    vstore3((REAL3)(0), i, f);
#ifdef HAS_ROTATION
    vstore3((REAL3)(0), i, torque);
#endif
#ifdef HAS_HEAT
    heatflow[i] = 0;
#else
    (void)heatflow;
#endif
}
