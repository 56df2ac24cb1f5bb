/* fix_viscous_nonlinear.cl - LAMMPS's fix viscous/nonlinear (2026,
 * GRANULAR fix_viscous_nonlinear.cpp): the Schiller-Naumann drag of a
 * uniform gas on a sphere of radius r,
 *   F = -1/2 Cd rho_g (pi r^2) |v_rel| v_rel,   v_rel = v - v_gas
 *   Cd = 24/Re (1 + 0.15 Re^0.687),   Re = rho_g |v_rel| 2r / mu_g
 * (Stokes' -6 pi mu_g r v_rel as Re -> 0); nothing at v_rel = 0. In LAMMPS's
 * order of operations. */

static inline REAL3 viscous_nonlinear_force(const REAL3 vrel, const REAL r, const REAL rho,
                                            const REAL mu)
{
    const REAL vmag = sqrt(vrel.x * vrel.x + vrel.y * vrel.y + vrel.z * vrel.z);
    if (vmag == (REAL)0)
        return (REAL3)(0);
    const REAL re = rho * vmag * ((REAL)2.0 * r) / mu;
    const REAL cd = ((REAL)24.0 / re) * ((REAL)1.0 + (REAL)0.15 * pow(re, (REAL)0.687));
    const REAL pref = (REAL)0.5 * cd * rho * (REAL)M_PI * r * r * vmag;
    return -pref * vrel;
}

__kernel void viscous_nonlinear_post_force(const int n, const uint groupbit,
                                           __global const uint *mask, __global const REAL *v,
                                           __global const REAL *radius, __global REAL *f,
                                           const REAL rho, const REAL mu, const REAL vgx,
                                           const REAL vgy, const REAL vgz)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL3 d = viscous_nonlinear_force(vload3(i, v) - (REAL3)(vgx, vgy, vgz), radius[i],
                                            rho, mu);
    REAL3 fi = vload3(i, f);
    fi.x += d.x; /* LAMMPS: f -= pref vrel, component by component */
    fi.y += d.y;
    fi.z += d.z;
    vstore3(fi, i, f);
}
