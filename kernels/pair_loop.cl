/* pair_loop.cl - the one neighbor loop: for each particle i, gather the
 * force and torque of every contact in its full neighbor list through the
 * active evaluator PAIR_EVAL (no atomics: each work-item writes only i).
 * This kernel also clears the force: f and torque are written, not added.
 *
 * History (HAS_HISTORY): shear[3 (i maxn + k) ..] belongs to the contact in
 * slot k of i's list; it is zeroed when the pair is not touching (LAMMPS). The
 * entry of j for the same pair holds exactly minus i's entry.
 * meff = mi mj / (mi + mj); when one particle is in the freeze group
 * (freezebit), meff is the other particle's mass (LAMMPS pair gran). */

#ifdef PAIR_EVAL
__kernel void pair_loop(const int n, __global const REAL *x, __global const REAL *v,
                        __global const REAL *omega, __global const REAL *radius,
                        __global const REAL *rmass, __global const int *type,
                        __global const uint *mask, __global const int *nlist,
                        __global const int *ncount, const int maxn, __global REAL *shear,
                        __global const REAL *param, const int ntypes, const int nparam,
                        const uint freezebit, const REAL dt, const int shearupdate,
                        const REAL Lx, const REAL Ly, const REAL Lz, __global REAL *f,
                        __global REAL *torque)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const REAL3 xi = vload3(i, x);
    const REAL3 vi = vload3(i, v);
#ifdef HAS_ROTATION
    const REAL3 omi = vload3(i, omega);
#else
    const REAL3 omi = (REAL3)(0);
#endif
    const REAL radi = radius[i];
    const REAL mi = rmass[i];
    const int ti = type[i];
    const uint maski = mask[i];
    REAL3 fsum = (REAL3)(0), tsum = (REAL3)(0);
    const int cnt = ncount[i];
    const size_t row = (size_t)i * (size_t)maxn;
    for (int k = 0; k < cnt; k++) {
        const int j = nlist[row + k];
        const REAL3 xj = vload3(j, x);
        REAL3 del = xi - xj;
        del.x = MINIMG_X(del.x, Lx);
        del.y = MINIMG_Y(del.y, Ly);
        del.z = MINIMG_Z(del.z, Lz);
        const REAL rsq = del.x * del.x + del.y * del.y + del.z * del.z;
        const REAL radj = radius[j];
        const REAL radsum = radi + radj;
#ifndef HAS_COHESION /* cohesion acts beyond body contact: every listed pair goes to
                        * PAIR_EVAL, whose terms gate themselves (pair_hybrid_overlay.cl) */
        if (rsq >= radsum * radsum) {
#ifdef HAS_HISTORY
            /* reset the history of a separated pair; most are zero already and
             * stay clean in the cache */
            const REAL3 old = vload3(row + k, shear);
            if (old.x != (REAL)0 || old.y != (REAL)0 || old.z != (REAL)0)
                vstore3((REAL3)(0), row + k, shear);
#endif
            continue;
        }
#endif
        struct contact c;
        c.del = del;
        c.rsq = rsq;
        c.radi = radi;
        c.radj = radj;
        c.radsum = radsum;
        c.reff = radi * radj / radsum;
        c.vr = vi - vload3(j, v);
        c.omi = omi;
#ifdef HAS_ROTATION
        c.omj = vload3(j, omega);
#else
        c.omj = (REAL3)(0);
#endif
        const REAL mj = rmass[j];
        REAL meff = mi * mj / (mi + mj);
        if (maski & freezebit)
            meff = mj;
        if (mask[j] & freezebit)
            meff = mi;
        c.meff = meff;
        c.dt = dt;
        c.shearupdate = shearupdate;
        __global const REAL *p = param + (size_t)((ti - 1) * ntypes + (type[j] - 1)) * nparam;
        REAL3 sh, fi, tq;
#ifdef HAS_HISTORY
        sh = vload3(row + k, shear);
#else
        sh = (REAL3)(0);
#endif
        PAIR_EVAL(&c, p, &sh, &fi, &tq);
#ifdef HAS_HISTORY
        vstore3(sh, row + k, shear);
#endif
        fsum += fi;
        tsum += tq;
    }
    vstore3(fsum, i, f);
#ifdef HAS_ROTATION
    vstore3(tsum, i, torque);
#endif
}
#endif /* PAIR_EVAL */

/* Zero the force (and torque) when no pair style computes them. */
__kernel void force_clear(const int n, __global REAL *f, __global REAL *torque)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    vstore3((REAL3)(0), i, f);
#ifdef HAS_ROTATION
    vstore3((REAL3)(0), i, torque);
#endif
}
