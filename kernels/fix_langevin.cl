/* fix_langevin.cl - LAMMPS's fix langevin (post_force): each atom of the
 * group gets the drag gamma1 v and the random force fran the host drew
 * (LAMMPS's RanMars stream, in atom-ID order): f += gamma1 v + fran, then
 * with zero yes f -= the group's mean random force (fsum). gamma1 =
 * -m / damp / ratio_type, computed here as LAMMPS does. With omega, the
 * same for the torque: torque += gamma1r omega + tran, gamma1r = -c1r I /
 * damp / ratio (I = 0.4 m r^2; c1r LAMMPS's 10/3 or 1), for r > 0. With
 * tally, flan receives the translational force added (for the host's
 * energy tally). */

__kernel void langevin_post_force(const int n, const uint groupbit, __global const uint *mask,
                                  __global const int *type, __global const REAL *rmass,
                                  __global const REAL *radius, __global const REAL *v,
                                  __global const REAL *omega, __global REAL *f,
                                  __global REAL *torque, __global const REAL *fran,
                                  __global const REAL *ratio, const REAL t_period,
                                  const int zero, const REAL fsx, const REAL fsy, const REAL fsz,
                                  const int oflag, const REAL c1r, const int tally,
                                  __global REAL *flan)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL rt = ratio[type[i] - 1];
    REAL gamma1 = -rmass[i] / t_period;
    gamma1 *= (REAL)1 / rt;
    REAL3 fl = gamma1 * vload3(i, v) + vload3(2 * i, fran);
    REAL3 fi = vload3(i, f) + fl;
    if (zero) {
        fi -= (REAL3)(fsx, fsy, fsz);
        fl -= (REAL3)(fsx, fsy, fsz);
    }
    vstore3(fi, i, f);
    if (tally)
        vstore3(fl, i, flan);
#ifdef HAS_ROTATION
    if (oflag && radius[i] > (REAL)0) {
        const REAL inertia = (REAL)0.4 * radius[i] * radius[i] * rmass[i];
        REAL g1 = -c1r * inertia / t_period;
        g1 *= (REAL)1 / rt;
        vstore3(vload3(i, torque) + (g1 * vload3(i, omega) + vload3(2 * i + 1, fran)), i, torque);
    }
#else
    (void)radius;
    (void)omega;
    (void)torque;
    (void)oflag;
    (void)c1r;
#endif
}
