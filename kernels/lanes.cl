/* lanes.cl - lane arithmetic, a template: LW contacts evaluated at once, one
 * per lane of an LR (REAL when LW = 1, a REAL vector of LW lanes otherwise).
 * The engine adds this file, and every lane-generic law after it, once per
 * width it needs, between a prologue that defines
 *   LW       the width;
 *   LR, LRI  the lane type and the type of a comparison of two LR (int for
 *            LW = 1, long/int lanes otherwise: -1 where true);
 *   LN(x)    the name of x at this width (x_1 or x_w);
 *   LSEL(a, b, m)  per lane: b where m is true, else a
 * and an epilogue that undefines them (src/engine/engine.c, add_lanes).
 * A law written with these types and helpers compiles to the same IEEE
 * operations, in the same order, at every width (FP_CONTRACT is off,
 * kernels/common.cl), so its results are bit-identical for every LW: a
 * branch becomes both arms and a LSEL. */

/* a 3-vector of lanes */
struct LN(lr3) {
    LR x, y, z;
};

static inline struct LN(lr3) LN(lr3_of)(const LR x, const LR y, const LR z)
{
    struct LN(lr3) v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}
