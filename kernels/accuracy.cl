/* accuracy.cl - collision resolution and overlap of the contacts that
 * happen during a run (host side src/contact/accuracy.c).
 *
 * Every contact law has a collision-time function <eval>_tcol(c, param, vn):
 * the duration of an isolated two-body collision of this contact's m* and
 * R* at relative normal speed vn > 0 (0: none, e.g. cohesion or an
 * overdamped dashpot), which calls the law's formula in
 * kernels/collision_time.h (the host calls the same one, src/style/pair.h).
 * TCOL_OF(EVAL) names it for an evaluator EVAL (a macro such as PAIR_EVAL is
 * expanded first).
 *
 * Records (widths and offsets ACC_* of kernels/wall_layout.h), float in both
 * precisions (a diagnostic: 4 bytes a value), written only by the work-item
 * that owns them (no atomics):
 *   pair contact c   acc[2c] = largest dt / t_col seen, acc[2c + 1] = the
 *                    squared normal speed then; astep[c] = step (since the run's
 *                    first) it was seen
 *   particle i       ACC_WALL_W floats: the largest dt / t_col of its wall
 *   (walls)          and mesh contacts, the largest wall overlap / radius,
 *                    the key of the contact that gave the first (wall code,
 *                    normal speed, R*, m*) and the key of the last contact
 *                    evaluated that did not beat it; astep[i] the step
 * acc_reduce reduces them by chunks in index order (ties: the lowest index),
 * so the result does not depend on the work split. */

#define TCOL_PASTE(e) e##_tcol
#define TCOL_OF(e) TCOL_PASTE(e)

/* The laws' collision-time formulas (tcol_linear, tcol_hertz, ...) are in
 * kernels/collision_time.h, shared with the host. */

/* A record's upper bound of the speed, rounded up to float: the contact that
 * set it does not beat it again at the same speed. */
#define ACC_UP(x) convert_float_rtp(x)

/* The notes are taken by the contact body (kernels/contact.cl); TCOL is the
 * law's collision time. Note a pair contact: the record keeps the fastest
 * impact; dt / t_col grows with vn for a given contact, so the law is
 * evaluated only when the speed beats the record. */
#define ACC_NOTE_PAIR(TCOL, c, k, p, acc, astep, step)                                         \
    do {                                                                                       \
        const REAL dv_ = (k)->vdel;                                                            \
        const REAL vn2_ = dv_ * dv_ / (k)->rsq;                                                \
        if (vn2_ > (REAL)(acc)[ACC_PAIR_W * (c) + ACC_PAIR_VN2]) {                             \
            const REAL tc_ = TCOL(k, p, sqrt(vn2_));                                           \
            if (tc_ > (REAL)0) {                                                               \
                (acc)[ACC_PAIR_W * (c) + ACC_PAIR_Q] = (float)((k)->dt / tc_);                 \
                (acc)[ACC_PAIR_W * (c) + ACC_PAIR_VN2] = ACC_UP(vn2_);                         \
                (astep)[c] = step;                                                             \
            }                                                                                  \
        }                                                                                      \
    } while (0)

/* Note a wall contact of particle i with wall `code` (the work-item of i).
 * Every law's dt / t_col is non-decreasing in vn for a given wall, R* and
 * m* (t_col is constant or falls with vn), so a contact that matches the
 * record's wall, R* and m* at no higher speed cannot beat it; nor can one
 * that matches the last evaluation that did not beat the record (the
 * particle's other wall: records only grow until acc_collect clears both).
 * The law's collision time (a fifth root for the Hertz laws) is evaluated only
 * otherwise, and the record is the one the full test would keep (to the
 * floats' rounding of the speeds, upward). */
#define ACC_WALL_MATCH(rec, c, code, vn, k)                                                    \
    ((rec)[(c) + ACC_KEY_CODE] == (float)(code) && (vn) <= (REAL)(rec)[(c) + ACC_KEY_VN] &&     \
     (rec)[(c) + ACC_KEY_REFF] == (float)(k)->reff && (rec)[(c) + ACC_KEY_MEFF] == (float)(k)->meff)
#define ACC_WALL_KEEP(rec, c, code, vn, k)                                                     \
    do {                                                                                       \
        (rec)[(c) + ACC_KEY_CODE] = (float)(code);                                             \
        (rec)[(c) + ACC_KEY_VN] = ACC_UP(vn);                                                  \
        (rec)[(c) + ACC_KEY_REFF] = (float)(k)->reff;                                          \
        (rec)[(c) + ACC_KEY_MEFF] = (float)(k)->meff;                                          \
    } while (0)
#define ACC_NOTE_WALL(TCOL, i, k, p, code, acc, astep, step)                                   \
    do {                                                                                       \
        __global float *rec_ = (acc) + ACC_WALL_W * (i);                                       \
        const REAL r_ = sqrt((k)->rsq);                                                        \
        const REAL vn_ = fabs((k)->vdel) / r_;                                                 \
        const REAL ov_ = ((k)->radi - r_) / (k)->radi;                                         \
        if (ov_ > (REAL)rec_[ACC_WALL_OV])                                                     \
            rec_[ACC_WALL_OV] = ACC_UP(ov_);                                                   \
        if (vn_ > (REAL)0 && !ACC_WALL_MATCH(rec_, ACC_WALL_KEY, code, vn_, k) &&               \
            !ACC_WALL_MATCH(rec_, ACC_WALL_LAST, code, vn_, k)) {                              \
            const REAL tc_ = TCOL(k, p, vn_);                                                  \
            const float q_ = tc_ > (REAL)0 ? (float)((k)->dt / tc_) : 0.0f;                     \
            if (q_ > rec_[ACC_WALL_Q]) { /* as floats: ties keep the first */                  \
                rec_[ACC_WALL_Q] = q_;                                                         \
                ACC_WALL_KEEP(rec_, ACC_WALL_KEY, code, vn_, k);                               \
                (astep)[i] = step;                                                             \
            } else if (tc_ > (REAL)0) {                                                        \
                ACC_WALL_KEEP(rec_, ACC_WALL_LAST, code, vn_, k);                              \
            }                                                                                  \
        }                                                                                      \
    } while (0)

/* Per chunk of `chunk` records of `stride` REAL: the largest value at
 * offset 0 (and at offset ovoff >= 0) with its record index, the lowest
 * index on ties. out[2k], out[2k + 1]: the two maxima; idx[2k], idx[2k + 1]
 * their indices (-1: none above 0). */
__kernel void acc_reduce(const int n, const int chunk, const int stride, const int ovoff,
                         __global const float *acc, __global float *out, __global int *idx)
{
    const int k = get_global_id(0);
    const int i0 = k * chunk;
    if (k > 0 && i0 >= n)
        return;
    const int i1 = min(i0 + chunk, n);
    float bq = 0, bo = 0;
    int iq = -1, io = -1;
    for (int i = i0; i < i1; i++) {
        const float q = acc[(size_t)i * stride];
        if (q > bq) {
            bq = q;
            iq = i;
        }
        if (ovoff >= 0) {
            const float o = acc[(size_t)i * stride + ovoff];
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
