/* fix_spring_self.cl - fix spring/self (styles/fix/fix_spring_self.c):
 * each atom of the group is tied to its origin x0 (by atom ID, relative to
 * the run's origin, split in x0/x0lo when positions are) by a spring of
 * stiffness k in the flagged components, as LAMMPS's FixSpringSelf: with
 * d = x_unwrapped - x0 (LAMMPS's Domain::unmap), f -= k d and the atom's
 * k |d|^2 in e (half their sum is the spring energy). */
__kernel void spring_self(const int n, const uint groupbit, __global const uint *mask,
                          __global const long *tag, const long ntab, __global const REAL *x0,
                          __global const REAL *x0lo, __global const REAL *x,
                          __global const int *image, __global REAL *f, __global REAL *e,
                          const REAL k, const int flags, const REAL Lx, const REAL Ly,
                          const REAL Lz, const REAL xy, const REAL xz,
                          const REAL yz POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    e[i] = 0;
    if (!(mask[i] & groupbit) || tag[i] < 0 || tag[i] >= ntab)
        return;
    const long t = tag[i];
    const int3 im = vload3(i, image);
    const REAL3 xi = vload3(i, x), o = vload3(t, x0);
#ifdef SPLIT_POS
    const REAL3 lo = vload3(i, xlo) - vload3(t, x0lo);
#else
    const REAL3 lo = (REAL3)(0);
    (void)x0lo;
#endif
    /* LAMMPS's unmap: x + h image, then minus the origin */
    const REAL ux = xi.x + Lx * im.x + xy * im.y + xz * im.z;
    const REAL uy = xi.y + Ly * im.y + yz * im.z;
    const REAL uz = xi.z + Lz * im.z;
    const REAL dx = (flags & 1) ? (ux - o.x) + lo.x : 0;
    const REAL dy = (flags & 2) ? (uy - o.y) + lo.y : 0;
    const REAL dz = (flags & 4) ? (uz - o.z) + lo.z : 0;
    f[3 * i] -= k * dx;
    f[3 * i + 1] -= k * dy;
    f[3 * i + 2] -= k * dz;
    e[i] = k * (dx * dx + dy * dy + dz * dz);
}
