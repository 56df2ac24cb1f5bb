/* fix_wall_reflect.cl - fix wall/reflect (styles/fix/fix_wall_reflect.c):
 * an atom of the group beyond the wall at coordinate `coord` of dimension
 * `dim` (side 0: below a lower wall, 1: above an upper one) is put back at
 * its mirror image, x = coord + (coord - x), and that velocity component
 * reversed, as LAMMPS's FixWallReflect::wall_particle. */
__kernel void wall_reflect(const int n, const uint groupbit, __global const uint *mask,
                           __global REAL *x, __global REAL *v, const int dim, const int side,
                           const REAL coord POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const size_t k = 3 * (size_t)i + dim;
#ifdef SPLIT_POS
    REAL h = x[k], l = xlo[k];
#else
    REAL h = x[k], l = 0;
#endif
    if (side == 0 ? !(h + l < coord) : !(h + l > coord))
        return;
    const REAL d = coord - (h + l); /* beyond by |d|: back inside by as much */
    h = coord;
    l = 0;
    pos_add1(&h, &l, d);
    x[k] = h;
#ifdef SPLIT_POS
    xlo[k] = l;
#endif
    v[k] = -v[k];
}
