/* pair_gran_lanes.cl - the pair stage of the contact pipeline for the gran
 * laws in lanes (PAIR_LW > 1; kernels/pair_loop.cl's pair_contacts is the
 * one-contact-per-work-item form of the same stage). Work-item g takes the
 * PAIR_LW contacts PAIR_LW g .. PAIR_LW g + PAIR_LW - 1: their particles'
 * data are gathered per lane, then the contact body's steps run in lane
 * arithmetic (kernels/lanes.cl): the reach gate, the contact's build
 * (contact_build: geometry, relative motion, effective mass), the
 * kinematics the gran laws read (contact_kinematics), the law at width
 * PAIR_LW (PAIR_EVAL_LANES, kernels/gran_law.cl), the accuracy note's test,
 * history zeroing and the torques (contact_out_set); then each lane's
 * history and records are stored (none for a contact apart now
 * and when last evaluated: quiet[c], as pair_loop.cl). A group none of
 * whose contacts touches stops after the gate (pair_lane_apart): the
 * apart pairs of a flowing bed or a gas cost about what they cost one per
 * work-item. Every operation is the
 * one-contact body's, in its order, so the results are bit-identical to
 * PAIR_LW = 1 (tests/scripts/determinism.py).
 *
 * The host takes this form only for a scene it covers (src/engine/engine.c,
 * pair_lanes): no cohesion, approach, velocity remap or triclinic box, split
 * positions only with double support (the overlap in double lanes, as
 * contact_refine), and a 3-REAL history. */

#if defined(PAIR_LW) && PAIR_LW > 1
#if defined(HAS_COHESION) || defined(PAIR_APPROACH) || defined(VREMAP) || defined(TRICLINIC) ||  \
    (defined(SPLIT_POS) && !defined(HAS_FP64)) || defined(PAIR_EVAL_ROW) ||                    \
    !defined(HAS_ROTATION) || HIST_N != 3
#error "pair_gran_lanes.cl: a scene the lane form does not cover (src/engine/engine.c)"
#endif

#define LSTORE(v, t) LANE_CAT(vstore, PAIR_LW)(v, 0, t)
#define LSELW(a, b, m) select((a), (b), (m))
typedef LANE_CAT(REAL, PAIR_LW) lreal_w;
#ifdef USE_DOUBLE
typedef LANE_CAT(long, PAIR_LW) lmask_w; /* a comparison of two lreal_w */
#else
typedef LANE_CAT(int, PAIR_LW) lmask_w;
#endif
#ifdef SPLIT_POS /* single precision: overlaps in double lanes (HAS_FP64: src/engine/engine.c) */
typedef LANE_CAT(double, PAIR_LW) ldouble_w;
#define LTO_DOUBLE(v) LANE_CAT(convert_double, PAIR_LW)(v)
#define LTO_REAL(v) LANE_CAT(convert_float, PAIR_LW)(v)
#endif

/* min_image (kernels/common.cl) of each lane */
static inline lreal_w lane_min_image(const lreal_w d, const REAL L)
{
    return LANE_MIN_IMAGE(lreal_w, d, L);
}
#ifdef PERIODIC_X
#define LMINIMG_X(d, L) lane_min_image(d, L)
#else
#define LMINIMG_X(d, L) (d)
#endif
#ifdef PERIODIC_Y
#define LMINIMG_Y(d, L) lane_min_image(d, L)
#else
#define LMINIMG_Y(d, L) (d)
#endif
#ifdef PERIODIC_Z
#define LMINIMG_Z(d, L) lane_min_image(d, L)
#else
#define LMINIMG_Z(d, L) (d)
#endif

/* A contact that does not touch (pair_loop.cl's pair_contacts for it): if
 * it acted when last evaluated, a nonzero history is zeroed, it writes zero
 * records and turns quiet; else (quiet) its history and records are zero
 * already and nothing is read. */
static inline void pair_lane_apart(const int c, __global REAL *shear, __global uchar *quiet,
                                   __global REAL *rec)
{
    if (quiet[c])
        return;
#ifdef HAS_HISTORY
    const REAL h0[3] = {0, 0, 0};
    contact_hist_store(shear + (size_t)c * 3, h0, 3, 0);
#else
    (void)shear;
#endif
    quiet[c] = 1;
    const REAL3 f = (REAL3)(0);
    vstore3(f, 0, rec + REC_F(c));
    vstore3(f, 0, rec + REC_T(c));
#ifndef PAIR_TC
    vstore3(f, 0, rec + REC_TJ(c));
#endif
}

/* arguments: KARGS_pair_contacts (kernels/kernel_args.h) */
__kernel void pair_contacts(KA_KERNEL(pair_contacts))
{
    KA_UNPACK(pair_contacts);
    if (KA_HALTED())
        return;
    const int c0 = get_global_id(0) * PAIR_LW;
    if (c0 >= ncontact)
        return;
    (void)hrate;
    (void)vgroup;
    (void)xy;
    (void)xz;
    (void)yz;
    /* the lanes' contacts and particles: a lane past the last contact repeats
     * the last one (stored by nobody) */
    int cc[PAIR_LW], ii[PAIR_LW], jj[PAIR_LW];
    __global const REAL *pp[PAIR_LW];
    for (int l = 0; l < PAIR_LW; l++) {
        cc[l] = min(c0 + l, ncontact - 1);
        ii[l] = ci[cc[l]];
        jj[l] = cj[cc[l]];
        pp[l] = ntypes == 1 ? param /* one set: no type to load */
                            : param + (size_t)((type[ii[l]] - 1) * ntypes + (type[jj[l]] - 1)) *
                                          nparam;
    }
    /* gathered straight into lanes (LG(F): F(0), ..., F(PAIR_LW - 1); no
     * round trip through private memory) */
#define G_XI(l) x[3 * (size_t)ii[l]]
#define G_YI(l) x[3 * (size_t)ii[l] + 1]
#define G_ZI(l) x[3 * (size_t)ii[l] + 2]
#define G_XJ(l) x[3 * (size_t)jj[l]]
#define G_XLI(l) xlo[3 * (size_t)ii[l]]
#define G_YLI(l) xlo[3 * (size_t)ii[l] + 1]
#define G_ZLI(l) xlo[3 * (size_t)ii[l] + 2]
#define G_XLJ(l) xlo[3 * (size_t)jj[l]]
#define G_YLJ(l) xlo[3 * (size_t)jj[l] + 1]
#define G_ZLJ(l) xlo[3 * (size_t)jj[l] + 2]
#define G_YJ(l) x[3 * (size_t)jj[l] + 1]
#define G_ZJ(l) x[3 * (size_t)jj[l] + 2]
#define G_VIX(l) v[3 * (size_t)ii[l]]
#define G_VIY(l) v[3 * (size_t)ii[l] + 1]
#define G_VIZ(l) v[3 * (size_t)ii[l] + 2]
#define G_VJX(l) v[3 * (size_t)jj[l]]
#define G_VJY(l) v[3 * (size_t)jj[l] + 1]
#define G_VJZ(l) v[3 * (size_t)jj[l] + 2]
#define G_OIX(l) omega[3 * (size_t)ii[l]]
#define G_OIY(l) omega[3 * (size_t)ii[l] + 1]
#define G_OIZ(l) omega[3 * (size_t)ii[l] + 2]
#define G_OJX(l) omega[3 * (size_t)jj[l]]
#define G_OJY(l) omega[3 * (size_t)jj[l] + 1]
#define G_OJZ(l) omega[3 * (size_t)jj[l] + 2]
#define G_RADI(l) radius[ii[l]]
#define G_RADJ(l) radius[jj[l]]
#define G_MI(l) rmass[ii[l]]
#define G_MJ(l) rmass[jj[l]]
#define G_FI(l) ((mask[ii[l]] & freezebit) ? (REAL)1 : (REAL)0)
#define G_FJ(l) ((mask[jj[l]] & freezebit) ? (REAL)1 : (REAL)0)
#define G_S1(l) shear[3 * (size_t)cc[l]]
#define G_S2(l) shear[3 * (size_t)cc[l] + 1]
#define G_S3(l) shear[3 * (size_t)cc[l] + 2]
#define G_REC(l) ((REAL)acc[ACC_PAIR_W * cc[l] + ACC_PAIR_VN2])
#define G_KN(l) pp[l][GRAN_KN]
#define G_KT(l) pp[l][GRAN_KT]
#define G_GN(l) pp[l][GRAN_GAMMAN]
#define G_GT(l) pp[l][GRAN_GAMMAT]
#define G_XMU(l) pp[l][GRAN_XMU]
#define G_LIM(l) pp[l][GRAN_LIMIT]
#define LG(F) ((lreal_w)LANE_CAT(LANES_, PAIR_LW)(F))

    /* the gate and the contact's build (contact_gate, contact_build) */
    const lreal_w radi = LG(G_RADI), radj = LG(G_RADJ);
    struct gran_in_w k;
    const lreal_w dhx = LMINIMG_X(LG(G_XI) - LG(G_XJ), Lx);
    const lreal_w dhy = LMINIMG_Y(LG(G_YI) - LG(G_YJ), Ly);
    const lreal_w dhz = LMINIMG_Z(LG(G_ZI) - LG(G_ZJ), Lz);
    const lreal_w reach = radi + radj;
    const lreal_w radsum = radi + radj;
#ifdef SPLIT_POS /* the gate on hi + lo, the overlap in double (contact_refine) */
    const lreal_w dlx = LG(G_XLI) - LG(G_XLJ), dly = LG(G_YLI) - LG(G_YLJ);
    const lreal_w dlz = LG(G_ZLI) - LG(G_ZLJ);
    k.del = lr3_of_w(dhx + dlx, dhy + dly, dhz + dlz);
    const lreal_w rsqt = k.del.x * k.del.x + k.del.y * k.del.y + k.del.z * k.del.z;
    const ldouble_w ddx = LTO_DOUBLE(dhx) + LTO_DOUBLE(dlx);
    const ldouble_w ddy = LTO_DOUBLE(dhy) + LTO_DOUBLE(dly);
    const ldouble_w ddz = LTO_DOUBLE(dhz) + LTO_DOUBLE(dlz);
    const ldouble_w rd = sqrt(ddx * ddx + ddy * ddy + ddz * ddz);
    k.r = LTO_REAL(rd);
    k.delta = LTO_REAL((LTO_DOUBLE(radi) + LTO_DOUBLE(radj)) - rd);
    const lreal_w rsq = k.r * k.r;
    const lmask_w acts = (rsqt < reach * reach) & (k.delta > (lreal_w)0);
#else
    k.del = lr3_of_w(dhx, dhy, dhz);
    const lreal_w rsq = k.del.x * k.del.x + k.del.y * k.del.y + k.del.z * k.del.z;
    const lmask_w acts = rsq < reach * reach;
    k.r = sqrt(rsq);
    k.delta = radsum - k.r;
#endif
    if (!any(acts)) { /* no lane touches: only history to forget and records to clear */
        for (int l = 0; l < PAIR_LW && c0 + l < ncontact; l++)
            pair_lane_apart(c0 + l, shear, quiet, rec);
        return;
    }
    k.reff = radi * radj / (radi + radj);
    k.vr = lr3_of_w(LG(G_VIX) - LG(G_VJX), LG(G_VIY) - LG(G_VJY),
                    LG(G_VIZ) - LG(G_VJZ));
    const lreal_w mi = LG(G_MI), mj = LG(G_MJ);
    const lreal_w mij = mi * mj / (mi + mj);
    k.meff = freezebit ? LSELW(LSELW(mij, mj, LG(G_FI) != (lreal_w)0), mi, LG(G_FJ) != (lreal_w)0)
                       : mij; /* no freeze group: no mask to load */
    /* the kinematics the gran laws and the note read (contact_kinematics) */
    k.rinv = (lreal_w)1 / k.r;
    k.rsqinv = (lreal_w)1 / rsq;
    k.vdel = k.vr.x * k.del.x + k.vr.y * k.del.y + k.vr.z * k.del.z;
    k.w = lr3_of_w(radi * LG(G_OIX) + radj * LG(G_OJX),
                   radi * LG(G_OIY) + radj * LG(G_OJY),
                   radi * LG(G_OIZ) + radj * LG(G_OJZ));
    k.dt = dt;
    k.shearupdate = shearupdate;

    /* the law */
    struct gran_par_w par;
    if (ntypes == 1) { /* one set for every lane */
        par.kn = (lreal_w)param[GRAN_KN];
        par.kt = (lreal_w)param[GRAN_KT];
        par.gamman = (lreal_w)param[GRAN_GAMMAN];
        par.gammat = (lreal_w)param[GRAN_GAMMAT];
        par.xmu = (lreal_w)param[GRAN_XMU];
        par.limit = (lreal_w)param[GRAN_LIMIT];
    } else {
        par.kn = LG(G_KN);
        par.kt = LG(G_KT);
        par.gamman = LG(G_GN);
        par.gammat = LG(G_GT);
        par.xmu = LG(G_XMU);
        par.limit = LG(G_LIM);
    }
#ifdef HAS_HISTORY
    struct lr3_w sh = lr3_of_w(LG(G_S1), LG(G_S2), LG(G_S3));
#else
    struct lr3_w sh = lr3_of_w((lreal_w)0, (lreal_w)0, (lreal_w)0);
#endif
    struct gran_out_w o;
    LANE_CAT(PAIR_EVAL_LANES, _w)(&k, &par, &sh, &o);

    /* a contact that does not act: no force, its history forgotten */
    const lreal_w zero = (lreal_w)0;
    const lreal_w fx = LSELW(zero, o.f.x, acts), fy = LSELW(zero, o.f.y, acts);
    const lreal_w fz = LSELW(zero, o.f.z, acts);
    /* torques (contact_out_set, tr = 0): on i -radi tc - 0, on j -radj tc + 0 */
    const lreal_w tix = LSELW(zero, -radi * o.tc.x - zero, acts);
    const lreal_w tiy = LSELW(zero, -radi * o.tc.y - zero, acts);
    const lreal_w tiz = LSELW(zero, -radi * o.tc.z - zero, acts);
    const lreal_w tjx = LSELW(zero, -radj * o.tc.x + zero, acts);
    const lreal_w tjy = LSELW(zero, -radj * o.tc.y + zero, acts);
    const lreal_w tjz = LSELW(zero, -radj * o.tc.z + zero, acts);
    const lreal_w tcx = LSELW(zero, o.tc.x, acts), tcy = LSELW(zero, o.tc.y, acts);
    const lreal_w tcz = LSELW(zero, o.tc.z, acts);
    /* the accuracy note's test (ACC_NOTE_PAIR): an acting contact overlapping
     * at a normal speed above its record */
    const lreal_w vn2 = k.vdel * k.vdel / rsq;
    const lmask_w note = acts & (rsq < radsum * radsum) & (vn2 > LG(G_REC));
    const lreal_w shx = LSELW(zero, sh.x, acts), shy = LSELW(zero, sh.y, acts);
    const lreal_w shz = LSELW(zero, sh.z, acts);
    const lreal_w actsw = LSELW(zero, (lreal_w)1, acts), notew = LSELW(zero, (lreal_w)1, note);
    const lreal_w meffw = k.meff, reffw = k.reff;
    /* back per lane (a constant lane index once unrolled: an extract) */
#pragma unroll
    for (int l = 0; l < PAIR_LW; l++) {
        const int c = c0 + l;
        if (c >= ncontact)
            break;
        if (LANE_OF(notew, l) != (REAL)0) { /* ACC_NOTE_PAIR's record (kernels/accuracy.cl) */
            struct contact kc;
            kc.meff = LANE_OF(meffw, l);
            kc.reff = LANE_OF(reffw, l);
            const REAL tc = TCOL_OF(PAIR_EVAL)(&kc, pp[l], sqrt(LANE_OF(vn2, l)));
            if (tc > (REAL)0) {
                acc[ACC_PAIR_W * c + ACC_PAIR_Q] = (float)(dt / tc);
                acc[ACC_PAIR_W * c + ACC_PAIR_VN2] = ACC_UP(LANE_OF(vn2, l));
                astep[c] = step;
            }
        }
        if (LANE_OF(actsw, l) == (REAL)0) { /* its selects left zeros: as an apart group's */
            pair_lane_apart(c, shear, quiet, rec);
            continue;
        }
#ifdef HAS_HISTORY /* contact_hist_store of an acting contact: the whole row */
        vstore3((REAL3)(LANE_OF(shx, l), LANE_OF(shy, l), LANE_OF(shz, l)), c, shear);
#endif
        if (quiet[c])
            quiet[c] = 0;
        const REAL3 f = (REAL3)(LANE_OF(fx, l), LANE_OF(fy, l), LANE_OF(fz, l));
        vstore3(f, 0, rec + REC_F(c));
#ifdef PAIR_TC /* the torque record is tc (pair_loop.cl) */
        vstore3((REAL3)(LANE_OF(tcx, l), LANE_OF(tcy, l), LANE_OF(tcz, l)), 0, rec + REC_T(c));
#else
        vstore3((REAL3)(LANE_OF(tix, l), LANE_OF(tiy, l), LANE_OF(tiz, l)), 0, rec + REC_T(c));
        vstore3((REAL3)(LANE_OF(tjx, l), LANE_OF(tjy, l), LANE_OF(tjz, l)), 0, rec + REC_TJ(c));
#endif
    }
}
#endif /* PAIR_LW > 1 */
