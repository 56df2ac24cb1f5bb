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
 * history and incidence records are stored. Every operation is the
 * one-contact body's, in its order, so the results are bit-identical to
 * PAIR_LW = 1 (tests/scripts/determinism.py).
 *
 * The host takes this form only for a scene it covers (src/engine/engine.c,
 * pair_lanes): no cohesion, approach, velocity remap, triclinic box or
 * split positions, and a 3-REAL history. */

#if defined(PAIR_LW) && PAIR_LW > 1
#if defined(HAS_COHESION) || defined(PAIR_APPROACH) || defined(VREMAP) || defined(TRICLINIC) ||  \
    defined(SPLIT_POS) || defined(PAIR_EVAL_ROW) || !defined(HAS_ROTATION) || HIST_N != 3
#error "pair_gran_lanes.cl: a scene the lane form does not cover (src/engine/engine.c)"
#endif

#define LANE_PASTE(a, b) a##b
#define LANE_CAT(a, b) LANE_PASTE(a, b)
#define LLOAD(t) LANE_CAT(vload, PAIR_LW)(0, t)
#define LSTORE(v, t) LANE_CAT(vstore, PAIR_LW)(v, 0, t)
#define LSELW(a, b, m) select((a), (b), (m))
typedef LANE_CAT(REAL, PAIR_LW) lreal_w;
#ifdef USE_DOUBLE
typedef LANE_CAT(long, PAIR_LW) lmask_w; /* a comparison of two lreal_w */
#else
typedef LANE_CAT(int, PAIR_LW) lmask_w;
#endif

/* min_image (kernels/common.cl) of each lane */
static inline lreal_w lane_min_image(const lreal_w d, const REAL L)
{
    const lreal_w up = (lreal_w)((REAL)0.5 * L), down = (lreal_w)((REAL)-0.5 * L);
    return L > (REAL)0 ? LSELW(LSELW(d, d + (lreal_w)L, d < down), d - (lreal_w)L, d > up) : d;
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

/* the per-lane data gathered from the particles, REAL fields first */
enum pair_lane_field {
    PL_XI, PL_YI, PL_ZI, PL_XJ, PL_YJ, PL_ZJ, PL_VIX, PL_VIY, PL_VIZ, PL_VJX, PL_VJY, PL_VJZ,
    PL_OIX, PL_OIY, PL_OIZ, PL_OJX, PL_OJY, PL_OJZ, PL_RADI, PL_RADJ, PL_MI, PL_MJ, PL_FI, PL_FJ,
    PL_S1, PL_S2, PL_S3, PL_VN2REC, PL_PAR, PL_N = PL_PAR + GRAN_NPARAM
};

/* arguments: KARGS_pair_contacts (kernels/kernel_args.h) */
__kernel void pair_contacts(KA_PARAMS(pair_contacts))
{
    const int c0 = get_global_id(0) * PAIR_LW;
    if (c0 >= ncontact)
        return;
    (void)hrate;
    (void)vgroup;
    (void)xy;
    (void)xz;
    (void)yz;
    /* gather: a lane past the last contact repeats the last one (stored by nobody) */
    REAL t[PL_N][PAIR_LW];
    for (int l = 0; l < PAIR_LW; l++) {
        const int c = min(c0 + l, ncontact - 1);
        const int i = ci[c], j = cj[c];
        const REAL3 xi = vload3(i, x), xj = vload3(j, x);
        const REAL3 vi = vload3(i, v), vj = vload3(j, v);
        const REAL3 oi = vload3(i, omega), oj = vload3(j, omega);
        t[PL_XI][l] = xi.x;
        t[PL_YI][l] = xi.y;
        t[PL_ZI][l] = xi.z;
        t[PL_XJ][l] = xj.x;
        t[PL_YJ][l] = xj.y;
        t[PL_ZJ][l] = xj.z;
        t[PL_VIX][l] = vi.x;
        t[PL_VIY][l] = vi.y;
        t[PL_VIZ][l] = vi.z;
        t[PL_VJX][l] = vj.x;
        t[PL_VJY][l] = vj.y;
        t[PL_VJZ][l] = vj.z;
        t[PL_OIX][l] = oi.x;
        t[PL_OIY][l] = oi.y;
        t[PL_OIZ][l] = oi.z;
        t[PL_OJX][l] = oj.x;
        t[PL_OJY][l] = oj.y;
        t[PL_OJZ][l] = oj.z;
        t[PL_RADI][l] = radius[i];
        t[PL_RADJ][l] = radius[j];
        t[PL_MI][l] = rmass[i];
        t[PL_MJ][l] = rmass[j];
        t[PL_FI][l] = (mask[i] & freezebit) ? 1 : 0;
        t[PL_FJ][l] = (mask[j] & freezebit) ? 1 : 0;
#ifdef HAS_HISTORY
        t[PL_S1][l] = shear[(size_t)c * 3];
        t[PL_S2][l] = shear[(size_t)c * 3 + 1];
        t[PL_S3][l] = shear[(size_t)c * 3 + 2];
#else
        t[PL_S1][l] = t[PL_S2][l] = t[PL_S3][l] = 0;
#endif
        t[PL_VN2REC][l] = acc[ACC_PAIR_W * c + ACC_PAIR_VN2];
        __global const REAL *p = param + (size_t)((type[i] - 1) * ntypes + (type[j] - 1)) * nparam;
        for (int q = 0; q < GRAN_NPARAM; q++)
            t[PL_PAR + q][l] = p[q];
    }

    /* the gate and the contact's build (contact_gate, contact_build) */
    const lreal_w radi = LLOAD(t[PL_RADI]), radj = LLOAD(t[PL_RADJ]);
    struct gran_in_w k;
    k.del = lr3_of_w(LMINIMG_X(LLOAD(t[PL_XI]) - LLOAD(t[PL_XJ]), Lx),
                     LMINIMG_Y(LLOAD(t[PL_YI]) - LLOAD(t[PL_YJ]), Ly),
                     LMINIMG_Z(LLOAD(t[PL_ZI]) - LLOAD(t[PL_ZJ]), Lz));
    const lreal_w rsq = k.del.x * k.del.x + k.del.y * k.del.y + k.del.z * k.del.z;
    const lreal_w reach = radi + radj;
    const lmask_w acts = rsq < reach * reach;
    const lreal_w radsum = radi + radj;
    k.r = sqrt(rsq);
    k.delta = radsum - k.r;
    k.reff = radi * radj / (radi + radj);
    k.vr = lr3_of_w(LLOAD(t[PL_VIX]) - LLOAD(t[PL_VJX]), LLOAD(t[PL_VIY]) - LLOAD(t[PL_VJY]),
                    LLOAD(t[PL_VIZ]) - LLOAD(t[PL_VJZ]));
    const lreal_w mi = LLOAD(t[PL_MI]), mj = LLOAD(t[PL_MJ]);
    k.meff = LSELW(LSELW(mi * mj / (mi + mj), mj, LLOAD(t[PL_FI]) != (lreal_w)0), mi,
                   LLOAD(t[PL_FJ]) != (lreal_w)0);
    /* the kinematics the gran laws and the note read (contact_kinematics) */
    k.rinv = (lreal_w)1 / k.r;
    k.rsqinv = (lreal_w)1 / rsq;
    k.vdel = k.vr.x * k.del.x + k.vr.y * k.del.y + k.vr.z * k.del.z;
    k.w = lr3_of_w(radi * LLOAD(t[PL_OIX]) + radj * LLOAD(t[PL_OJX]),
                   radi * LLOAD(t[PL_OIY]) + radj * LLOAD(t[PL_OJY]),
                   radi * LLOAD(t[PL_OIZ]) + radj * LLOAD(t[PL_OJZ]));
    k.dt = dt;
    k.shearupdate = shearupdate;

    /* the law */
    struct gran_par_w par;
    par.kn = LLOAD(t[PL_PAR + GRAN_KN]);
    par.kt = LLOAD(t[PL_PAR + GRAN_KT]);
    par.gamman = LLOAD(t[PL_PAR + GRAN_GAMMAN]);
    par.gammat = LLOAD(t[PL_PAR + GRAN_GAMMAT]);
    par.xmu = LLOAD(t[PL_PAR + GRAN_XMU]);
    par.limit = LLOAD(t[PL_PAR + GRAN_LIMIT]);
    struct lr3_w sh = lr3_of_w(LLOAD(t[PL_S1]), LLOAD(t[PL_S2]), LLOAD(t[PL_S3]));
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
    /* the accuracy note's test (ACC_NOTE_PAIR): an acting contact overlapping
     * at a normal speed above its record */
    const lreal_w vn2 = k.vdel * k.vdel / rsq;
    const lmask_w note = acts & (rsq < radsum * radsum) & (vn2 > LLOAD(t[PL_VN2REC]));
    REAL r[PL_N][PAIR_LW]; /* back per lane: force, torques, shear, note */
    LSTORE(fx, r[0]);
    LSTORE(fy, r[1]);
    LSTORE(fz, r[2]);
    LSTORE(tix, r[3]);
    LSTORE(tiy, r[4]);
    LSTORE(tiz, r[5]);
    LSTORE(tjx, r[6]);
    LSTORE(tjy, r[7]);
    LSTORE(tjz, r[8]);
    LSTORE(LSELW(zero, sh.x, acts), r[9]);
    LSTORE(LSELW(zero, sh.y, acts), r[10]);
    LSTORE(LSELW(zero, sh.z, acts), r[11]);
    LSTORE(LSELW(zero, (lreal_w)1, acts), r[12]);
    LSTORE(LSELW(zero, (lreal_w)1, note), r[13]);
    LSTORE(vn2, r[14]);
    LSTORE(k.meff, r[15]);
    LSTORE(k.reff, r[16]);

    for (int l = 0; l < PAIR_LW; l++) {
        const int c = c0 + l;
        if (c >= ncontact)
            break;
        if (r[13][l] != (REAL)0) { /* ACC_NOTE_PAIR's record (kernels/accuracy.cl) */
            struct contact kc;
            kc.meff = r[15][l];
            kc.reff = r[16][l];
            const REAL tc = TCOL_OF(PAIR_EVAL)(&kc, param + (size_t)((type[ci[c]] - 1) * ntypes +
                                                                     (type[cj[c]] - 1)) * nparam,
                                               sqrt(r[14][l]));
            if (tc > (REAL)0) {
                acc[ACC_PAIR_W * c + ACC_PAIR_Q] = dt / tc;
                acc[ACC_PAIR_W * c + ACC_PAIR_VN2] = r[14][l];
                astep[c] = step;
            }
        }
#ifdef HAS_HISTORY /* contact_hist_store */
        __global REAL *row = shear + (size_t)c * 3;
        for (int q = 0; q < 3; q++)
            if (r[12][l] != (REAL)0 || row[q] != r[9 + q][l])
                row[q] = r[9 + q][l];
#endif
        const REAL3 f = (REAL3)(r[0][l], r[1][l], r[2][l]);
        const size_t si = (size_t)cslot[2 * c], sj = (size_t)cslot[2 * c + 1];
        vstore3(f, si, recf);
        vstore3(-f, sj, recf);
        vstore3((REAL3)(r[3][l], r[4][l], r[5][l]), si, rect);
        vstore3((REAL3)(r[6][l], r[7][l], r[8][l]), sj, rect);
    }
}
#endif /* PAIR_LW > 1 */
