/* pair_gran_hooke.cl - Hookean contact without shear history (LAMMPS pair
 * gran/hooke, 2021 semantics): the law is gran_hooke of kernels/gran_law.cl;
 * param layout GRAN_* (kn kt gamman gammat xmu limit_damping). */

static inline void gran_hooke_eval(const struct contact *c, __global const REAL *param,
                                   REAL3 *shear, struct contact_force *out)
{
    GRAN_EVAL(gran_hooke, c, param, shear, out);
}

/* collision time (kernels/accuracy.cl): the damped linear spring */
static inline REAL gran_hooke_eval_tcol(const struct contact *c, __global const REAL *param,
                                        const REAL vn)
{
    (void)vn;
    return tcol_linear(param[GRAN_KN], param[GRAN_GAMMAN], c->meff);
}
