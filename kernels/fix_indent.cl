/* fix_indent.cl - LAMMPS's fix indent: a spherical, cylindrical or planar
 * indenter pushing the group's atoms with F(r) = K (r - R)^2 (side out: the
 * atoms within R of the centre or axis pushed out; side in: those beyond R
 * pushed in; a plane: those beyond it, lo or hi side, pushed back). Each
 * atom's record rec[4i ..]: the indenter's energy K/3 |dr|^3 from it and
 * the force on the indenter (minus the atom's), zeros when untouched; the
 * host sums them in tag order. style 0 sphere, 1 cylinder (axis cdim, its
 * coordinate ignored), 2 plane (normal cdim at that coordinate of c,
 * planeside -1 lo / +1 hi). c: relative to the run's origin, as x. Lx Ly
 * Lz: periodic lengths (0: not periodic) for the minimum image. */

__kernel void indent_post_force(const int n, const uint groupbit, __global const uint *mask,
                                __global const REAL *x, __global REAL *f, __global REAL *rec,
                                const int style, const int cdim, const int outside,
                                const int planeside, const REAL cx, const REAL cy,
                                const REAL cz, const REAL radius, const REAL k, const REAL Lx,
                                const REAL Ly, const REAL Lz POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    vstore4((REAL4)(0), i, rec);
    if (!(mask[i] & groupbit))
        return;
    const REAL3 xi = vload3(i, x) + POS_LOAD_LO(i);
    const REAL k3 = k / (REAL)3;
    if (style == 2) {
        const REAL side = (REAL)planeside;
        const REAL dr = cdim == 0   ? side * (cx - xi.x)
                        : cdim == 1 ? side * (cy - xi.y)
                                    : side * (cz - xi.z);
        if (dr >= (REAL)0)
            return;
        const REAL fatom = -side * k * dr * dr;
        REAL3 fi = vload3(i, f);
        if (cdim == 0)
            fi.x += fatom;
        else if (cdim == 1)
            fi.y += fatom;
        else
            fi.z += fatom;
        vstore3(fi, i, f);
        REAL4 r = (REAL4)(-k3 * dr * dr * dr, 0, 0, 0);
        if (cdim == 0)
            r.y = -fatom;
        else if (cdim == 1)
            r.z = -fatom;
        else
            r.w = -fatom;
        vstore4(r, i, rec);
        return;
    }
    REAL dx = xi.x - cx, dy = xi.y - cy, dz = xi.z - cz;
    if (style == 1) { /* cylinder: no component along the axis */
        if (cdim == 0)
            dx = 0;
        else if (cdim == 1)
            dy = 0;
        else
            dz = 0;
    }
    dx = min_image(dx, Lx);
    dy = min_image(dy, Ly);
    dz = min_image(dz, Lz);
    const REAL r = sqrt(dx * dx + dy * dy + dz * dz);
    REAL dr, fmag;
    if (outside) {
        dr = r - radius;
        fmag = k * dr * dr;
    } else {
        dr = radius - r;
        fmag = -k * dr * dr;
    }
    if (dr >= (REAL)0)
        return;
    const REAL fx = dx * fmag / r, fy = dy * fmag / r, fz = dz * fmag / r;
    vstore3(vload3(i, f) + (REAL3)(fx, fy, fz), i, f);
    vstore4((REAL4)(-k3 * dr * dr * dr, -fx, -fy, -fz), i, rec);
}
