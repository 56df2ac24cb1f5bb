/* gran_common.cl - the gran laws (kernels/gran_law.cl, width 1) as contact
 * evaluators: struct contact and the type pair's GRAN_* coefficients in,
 * struct contact_force out (tr = 0). Used by pair_gran_*.cl (PAIR_EVAL) and
 * fix wall/gran's plane, region and mesh walls. Static inline: free when
 * unused. */

static inline struct gran_in_1 gran_in_of(const struct contact *c)
{
    struct gran_in_1 g;
    g.del = lr3_of_1(c->del.x, c->del.y, c->del.z);
    g.vr = lr3_of_1(c->vr.x, c->vr.y, c->vr.z);
    g.w = lr3_of_1(c->w.x, c->w.y, c->w.z);
    g.r = c->r;
    g.rinv = c->rinv;
    g.rsqinv = c->rsqinv;
    g.delta = c->delta;
    g.reff = c->reff;
    g.vdel = c->vdel;
    g.meff = c->meff;
    g.dt = c->dt;
    g.shearupdate = c->shearupdate;
    return g;
}

static inline struct gran_par_1 gran_par_of(__global const REAL *param)
{
    struct gran_par_1 p;
    p.kn = param[GRAN_KN];
    p.kt = param[GRAN_KT];
    p.gamman = param[GRAN_GAMMAN];
    p.gammat = param[GRAN_GAMMAT];
    p.xmu = param[GRAN_XMU];
    p.limit = param[GRAN_LIMIT];
    return p;
}

/* The evaluator of LAW (gran_hooke, gran_hooke_history, gran_hertz_history)
 * on one contact */
#define GRAN_EVAL(LAW, c, param, shear, out)                                                   \
    do {                                                                                       \
        const struct gran_in_1 in_ = gran_in_of(c);                                            \
        const struct gran_par_1 p_ = gran_par_of(param);                                       \
        struct lr3_1 s_ = lr3_of_1((shear)->x, (shear)->y, (shear)->z);                        \
        struct gran_out_1 o_;                                                                  \
        LAW##_1(&in_, &p_, &s_, &o_);                                                          \
        *(shear) = (REAL3)(s_.x, s_.y, s_.z);                                                  \
        (out)->f = (REAL3)(o_.f.x, o_.f.y, o_.f.z);                                            \
        (out)->tc = (REAL3)(o_.tc.x, o_.tc.y, o_.tc.z);                                        \
        (out)->tr = (REAL3)(0);                                                                \
    } while (0)

#if defined(PAIR_LW) && PAIR_LW > 1
#define LANE_PASTE(a, b) a##b
#define LANE_CAT(a, b) LANE_PASTE(a, b)
#define LLOAD(t) LANE_CAT(vload, PAIR_LW)(0, t)
#define LSTORE(v, t) LANE_CAT(vstore, PAIR_LW)(v, 0, t)

/* The law PAIR_EVAL_LANES (a gran law) on the pair kernel's PAIR_LW built
 * contacts k at once (kernels/pair_loop.cl): their fields and coefficients
 * into lanes, the law at width PAIR_LW, the force, torque and shear back
 * for the contacts that act (acted[l]); the others are left alone. */
enum gran_lane_field {
    GL_DELX, GL_DELY, GL_DELZ, GL_VRX, GL_VRY, GL_VRZ, GL_WX, GL_WY, GL_WZ, GL_R, GL_RINV,
    GL_RSQINV, GL_DELTA, GL_REFF, GL_VDEL, GL_MEFF, GL_S1, GL_S2, GL_S3, GL_PAR, GL_N = GL_PAR +
    GRAN_NPARAM
};

static inline void pair_lanes_eval(const struct contact *k, __global const REAL *const *p,
                                   REAL (*h)[3], const int *acted, struct contact_force *cf)
{
    REAL t[GL_N][PAIR_LW];
    for (int l = 0; l < PAIR_LW; l++) {
        if (!acted[l]) { /* a lane that computes nothing anyone reads */
            for (int q = 0; q < GL_N; q++)
                t[q][l] = 1;
            continue;
        }
        const struct contact *c = &k[l];
        t[GL_DELX][l] = c->del.x;
        t[GL_DELY][l] = c->del.y;
        t[GL_DELZ][l] = c->del.z;
        t[GL_VRX][l] = c->vr.x;
        t[GL_VRY][l] = c->vr.y;
        t[GL_VRZ][l] = c->vr.z;
        t[GL_WX][l] = c->w.x;
        t[GL_WY][l] = c->w.y;
        t[GL_WZ][l] = c->w.z;
        t[GL_R][l] = c->r;
        t[GL_RINV][l] = c->rinv;
        t[GL_RSQINV][l] = c->rsqinv;
        t[GL_DELTA][l] = c->delta;
        t[GL_REFF][l] = c->reff;
        t[GL_VDEL][l] = c->vdel;
        t[GL_MEFF][l] = c->meff;
        t[GL_S1][l] = h[l][0];
        t[GL_S2][l] = h[l][1];
        t[GL_S3][l] = h[l][2];
        for (int q = 0; q < GRAN_NPARAM; q++)
            t[GL_PAR + q][l] = p[l][q];
    }
    struct gran_in_w in;
    in.del = lr3_of_w(LLOAD(t[GL_DELX]), LLOAD(t[GL_DELY]), LLOAD(t[GL_DELZ]));
    in.vr = lr3_of_w(LLOAD(t[GL_VRX]), LLOAD(t[GL_VRY]), LLOAD(t[GL_VRZ]));
    in.w = lr3_of_w(LLOAD(t[GL_WX]), LLOAD(t[GL_WY]), LLOAD(t[GL_WZ]));
    in.r = LLOAD(t[GL_R]);
    in.rinv = LLOAD(t[GL_RINV]);
    in.rsqinv = LLOAD(t[GL_RSQINV]);
    in.delta = LLOAD(t[GL_DELTA]);
    in.reff = LLOAD(t[GL_REFF]);
    in.vdel = LLOAD(t[GL_VDEL]);
    in.meff = LLOAD(t[GL_MEFF]);
    in.dt = k[0].dt; /* the same in every built contact */
    in.shearupdate = k[0].shearupdate;
    for (int l = 1; l < PAIR_LW; l++)
        if (acted[l]) {
            in.dt = k[l].dt;
            in.shearupdate = k[l].shearupdate;
        }
    struct gran_par_w par;
    par.kn = LLOAD(t[GL_PAR + GRAN_KN]);
    par.kt = LLOAD(t[GL_PAR + GRAN_KT]);
    par.gamman = LLOAD(t[GL_PAR + GRAN_GAMMAN]);
    par.gammat = LLOAD(t[GL_PAR + GRAN_GAMMAT]);
    par.xmu = LLOAD(t[GL_PAR + GRAN_XMU]);
    par.limit = LLOAD(t[GL_PAR + GRAN_LIMIT]);
    struct lr3_w sh = lr3_of_w(LLOAD(t[GL_S1]), LLOAD(t[GL_S2]), LLOAD(t[GL_S3]));
    struct gran_out_w o;
    LANE_CAT(PAIR_EVAL_LANES, _w)(&in, &par, &sh, &o);
    REAL r[9][PAIR_LW];
    LSTORE(o.f.x, r[0]);
    LSTORE(o.f.y, r[1]);
    LSTORE(o.f.z, r[2]);
    LSTORE(o.tc.x, r[3]);
    LSTORE(o.tc.y, r[4]);
    LSTORE(o.tc.z, r[5]);
    LSTORE(sh.x, r[6]);
    LSTORE(sh.y, r[7]);
    LSTORE(sh.z, r[8]);
    for (int l = 0; l < PAIR_LW; l++)
        if (acted[l]) {
            cf[l].f = (REAL3)(r[0][l], r[1][l], r[2][l]);
            cf[l].tc = (REAL3)(r[3][l], r[4][l], r[5][l]);
            cf[l].tr = (REAL3)(0);
            h[l][0] = r[6][l];
            h[l][1] = r[7][l];
            h[l][2] = r[8][l];
        }
}
#endif
