/* accuracy.cl - collision resolution and overlap of the contacts that
 * happen during a run (host side src/accuracy.c).
 *
 * Every contact law has a collision-time function <eval>_tcol(c, param, vn):
 * the duration of an isolated two-body collision of this contact's m* and
 * R* at relative normal speed vn > 0 (0: none, e.g. cohesion or an
 * overdamped dashpot), which calls the law's formula in
 * kernels/collision_time.h (the host calls the same one, src/pair.h).
 * TCOL_OF(EVAL) names it for an evaluator EVAL (a macro such as PAIR_EVAL is
 * expanded first).
 *
 * Records, written only by the work-item that owns them (no atomics):
 *   pair contact c   acc[2c] = largest dt / t_col seen, acc[2c + 1] = the
 *                    squared normal speed then; astep[c] = step (since the run's
 *                    first) it was seen
 *   particle i       acc[4i] = largest dt / t_col of its wall and mesh
 *   (walls)          contacts, acc[4i + 1] its normal speed, acc[4i + 2] =
 *                    largest wall overlap / radius, acc[4i + 3] = the code
 *                    of the wall that gave acc[4i]; astep[i] its step
 * acc_reduce reduces them by chunks in index order (ties: the lowest index),
 * so the result does not depend on the work split. */

#define TCOL_PASTE(e) e##_tcol
#define TCOL_OF(e) TCOL_PASTE(e)

/* The laws' collision-time formulas (tcol_linear, tcol_hertz, ...) are in
 * kernels/collision_time.h, shared with the host. */

/* Note a pair contact: the record keeps the fastest impact; dt / t_col
 * grows with vn for a given contact, so the law is evaluated only when the
 * speed beats the record. */
#define ACC_NOTE_PAIR(EVAL, c, k, p, acc, astep, step)                                         \
    do {                                                                                       \
        const REAL dv_ = dot((k)->vr, (k)->del);                                               \
        const REAL vn2_ = dv_ * dv_ / (k)->rsq;                                                \
        if (vn2_ > (acc)[2 * (c) + 1]) {                                                       \
            const REAL tc_ = TCOL_OF(EVAL)(k, p, sqrt(vn2_));                                  \
            if (tc_ > (REAL)0) {                                                               \
                (acc)[2 * (c)] = (k)->dt / tc_;                                                \
                (acc)[2 * (c) + 1] = vn2_;                                                     \
                (astep)[c] = step;                                                             \
            }                                                                                  \
        }                                                                                      \
    } while (0)

/* Note a wall contact of particle i with wall `code` (the work-item of i). */
#define ACC_NOTE_WALL(EVAL, i, k, p, code, acc, astep, step)                                   \
    do {                                                                                       \
        const REAL r_ = sqrt((k)->rsq);                                                        \
        const REAL vn_ = fabs(dot((k)->vr, (k)->del)) / r_;                                    \
        const REAL ov_ = ((k)->radi - r_) / (k)->radi;                                         \
        if (ov_ > (acc)[4 * (i) + 2])                                                          \
            (acc)[4 * (i) + 2] = ov_;                                                          \
        if (vn_ > (REAL)0) {                                                                   \
            const REAL tc_ = TCOL_OF(EVAL)(k, p, vn_);                                         \
            if (tc_ > (REAL)0 && (k)->dt / tc_ > (acc)[4 * (i)]) {                             \
                (acc)[4 * (i)] = (k)->dt / tc_;                                                \
                (acc)[4 * (i) + 1] = vn_;                                                      \
                (acc)[4 * (i) + 3] = (REAL)(code);                                             \
                (astep)[i] = step;                                                             \
            }                                                                                  \
        }                                                                                      \
    } while (0)

/* Per chunk of `chunk` records of `stride` REAL: the largest value at
 * offset 0 (and at offset ovoff >= 0) with its record index, the lowest
 * index on ties. out[2k], out[2k + 1]: the two maxima; idx[2k], idx[2k + 1]
 * their indices (-1: none above 0). */
__kernel void acc_reduce(const int n, const int chunk, const int stride, const int ovoff,
                         __global const REAL *acc, __global REAL *out, __global int *idx)
{
    const int k = get_global_id(0);
    const int i0 = k * chunk;
    if (k > 0 && i0 >= n)
        return;
    const int i1 = min(i0 + chunk, n);
    REAL bq = 0, bo = 0;
    int iq = -1, io = -1;
    for (int i = i0; i < i1; i++) {
        const REAL q = acc[(size_t)i * stride];
        if (q > bq) {
            bq = q;
            iq = i;
        }
        if (ovoff >= 0) {
            const REAL o = acc[(size_t)i * stride + ovoff];
            if (o > bo) {
                bo = o;
                io = i;
            }
        }
    }
    out[2 * k] = bq;
    out[2 * k + 1] = bo;
    idx[2 * k] = iq;
    idx[2 * k + 1] = io;
}
