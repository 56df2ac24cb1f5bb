/* fix_wall_pair.cl - flat walls with the active pair style's contact law
 * (styles/fix_wall_pair.c). One work-item per atom; the nearer face of the
 * plane pair (lo, hi) along `dim` is the contact partner j:
 *   del = (x_dim - lo) e_dim for the lo face, -(hi - x_dim) e_dim for the hi
 *   face; contact while |del| < radi (radj = 0, radsum = reff = radi,
 *   vr = v_i, omj = 0, meff = m_i). Out of contact the history is zeroed.
 * Force and torque are added to f and torque. */

#ifdef PAIR_EVAL
__kernel void wall_pair(const int n, const uint groupbit, __global const uint *mask,
                        __global const REAL *x, __global const REAL *v,
                        __global const REAL *omega, __global const REAL *radius,
                        __global const REAL *rmass, __global const int *type,
                        __global REAL *f, __global REAL *torque, __global REAL *history,
                        __global const REAL *param, const int ntypes, const int nparam,
                        const int dim, const REAL lo, const REAL hi, const REAL dt,
                        const int shearupdate)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL3 xi = vload3(i, x);
    const REAL xa = dim == 0 ? xi.x : dim == 1 ? xi.y : xi.z;
    const REAL del1 = xa - lo, del2 = hi - xa;
    const REAL d = del1 < del2 ? del1 : -del2;
    const REAL radi = radius[i];
    if (d * d >= radi * radi) {
#ifdef HAS_HISTORY
        vstore3((REAL3)(0), i, history);
#endif
        return;
    }
    struct contact c;
    c.del = (REAL3)(dim == 0 ? d : 0, dim == 1 ? d : 0, dim == 2 ? d : 0);
    c.rsq = d * d;
    c.radi = radi;
    c.radj = 0;
    c.radsum = radi;
    c.reff = radi;
    c.vr = vload3(i, v);
#ifdef HAS_ROTATION
    c.omi = vload3(i, omega);
#else
    c.omi = (REAL3)(0);
#endif
    c.omj = (REAL3)(0);
    c.meff = rmass[i];
    c.dt = dt;
    c.shearupdate = shearupdate;
    const int ti = type[i] - 1;
    __global const REAL *p = param + (size_t)(ti * ntypes + ti) * nparam;
    REAL3 sh;
    struct contact_force cf;
#ifdef HAS_HISTORY
    sh = vload3(i, history);
#else
    sh = (REAL3)(0);
#endif
    PAIR_EVAL(&c, p, &sh, &cf);
#ifdef HAS_HISTORY
    vstore3(sh, i, history);
#endif
    vstore3(vload3(i, f) + cf.f, i, f);
#ifdef HAS_ROTATION
    vstore3(vload3(i, torque) + cf.ti, i, torque);
#endif
}
#endif
