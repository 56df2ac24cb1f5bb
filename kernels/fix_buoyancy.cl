/* fix_buoyancy.cl - LIGGGHTS's fix buoyancy (fix_buoyancy.cpp): each sphere
 * of the group takes -dir g rho_fluid V_immersed along the gravity axis
 * (kernels/buoyancy.h), at post_force. */

__kernel void buoyancy_post_force(const int n, const uint groupbit, __global const uint *mask,
                                  __global const REAL *x, __global const REAL *radius,
                                  __global REAL *f, const int dim, const REAL level,
                                  const REAL dir, const REAL gmag, const REAL rho POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL3 xi = vload3(i, x) + POS_LOAD_LO(i);
    const REAL xd = dim == 0 ? xi.x : dim == 1 ? xi.y : xi.z;
    const REAL vol = buoyancy_volume(xd, level, dir, radius[i]);
    if (vol == (REAL)0)
        return;
    REAL3 fi = vload3(i, f);
    const REAL fb = -dir * gmag * vol * rho;
    if (dim == 0)
        fi.x += fb;
    else if (dim == 1)
        fi.y += fb;
    else
        fi.z += fb;
    vstore3(fi, i, f);
}
