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

