/* pair_cohesion.cl - linear cohesion between effect surfaces (Andrews 2018,
 * source document 000, eq. 2.6, appendix A.2; styles/pair/pair_cohesion.c).
 *
 * With r = |del|, n = del / r (from j to i) and the effect distance
 *   d_e = (a_i + b_i radi) + (a_j + b_j radj)
 * (effect radii per side, host-packed), while the effect surfaces overlap:
 *   delta_e = d_e - r > 0,   F_i = -kc delta_e n      [force units]
 * i.e. an attraction along the line of centres that also acts in full body
 * contact. No torque, no history. A flat wall (radj = 0) exerts no cohesion.
 * Param layout COH_*: kc a_i b_i a_j b_j. Antisymmetric under i <-> j: the
 * packed sides swap, d_e is the same sum, del flips. */

static inline void cohesion_eval(const struct contact *c, __global const REAL *param,
                                 REAL3 *shear, struct contact_force *out)
{
    (void)shear;
    out->f = out->tc = out->tr = (REAL3)(0);
    if (c->radj == (REAL)0)
        return;
    const REAL ei = param[COH_AI] + param[COH_BI] * c->radi;
    const REAL ej = param[COH_AJ] + param[COH_BJ] * c->radj;
    const REAL de = ei + ej;
    if (c->rsq >= de * de)
        return;
    const REAL r = c->r;
    const REAL delta_e = de - r;
    out->f = (-param[COH_KC] * delta_e / r) * c->del;
}

/* collision time (kernels/accuracy.cl): cohesion alone has none */
static inline REAL cohesion_eval_tcol(const struct contact *c, __global const REAL *param,
                                      const REAL vn)
{
    (void)c;
    (void)param;
    (void)vn;
    return (REAL)0;
}
