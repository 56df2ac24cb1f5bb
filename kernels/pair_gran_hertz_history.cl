/* pair_gran_hertz_history.cl - Hertzian contact with shear history (LAMMPS
 * pair gran/hertz/history, 2021 semantics): the Hooke/history law with
 * normal and tangential forces scaled by polyhertz = sqrt(delta reff),
 * gran_hertz_history of kernels/gran_law.cl; param layout GRAN_*. */

static inline void gran_hertz_history_eval(const struct contact *c, __global const REAL *param,
                                           REAL3 *shear, struct contact_force *out)
{
    GRAN_EVAL(gran_hertz_history, c, param, shear, out);
}

/* collision time (kernels/accuracy.cl): Hertz at the impact speed vn */
static inline REAL gran_hertz_history_eval_tcol(const struct contact *c,
                                                __global const REAL *param, const REAL vn)
{
    return tcol_hertz(param[GRAN_KN], c->reff, c->meff, vn);
}
