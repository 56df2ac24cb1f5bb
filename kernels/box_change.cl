/* box_change.cl - atoms remapped by a box change during a run
 * (src/engine/box_change.c): the atoms of groupbit keep their lamda coordinates.
 *
 * Without SPLIT_POS this is LAMMPS's x2lamda with the old box (lower
 * corner olo, inverse shape hinv = h_inv[0..5]) and lamda2x with the new
 * one (nlo, h = h[0..5]), operation for operation, so a double-precision run
 * has LAMMPS's bits. With SPLIT_POS the displacement (h_new - h_old) lamda +
 * (nlo - olo) = dh lamda + dlo is added to the split position (pos_add):
 * the atom keeps its low bits. */
__kernel void box_remap(const int n, __global REAL *x, __global const uint *mask,
                        const uint groupbit, const REAL olox, const REAL oloy, const REAL oloz,
                        const REAL hi0, const REAL hi1, const REAL hi2, const REAL hi3,
                        const REAL hi4, const REAL hi5, const REAL nlox, const REAL nloy,
                        const REAL nloz, const REAL h0, const REAL h1, const REAL h2,
                        const REAL h3, const REAL h4, const REAL h5, const REAL dh0,
                        const REAL dh1, const REAL dh2, const REAL dh3, const REAL dh4,
                        const REAL dh5, const REAL dlox, const REAL dloy,
                        const REAL dloz POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    REAL3 xi = vload3(i, x), xl = POS_LOAD_LO(i);
    const REAL3 p = xi + xl;
    const REAL dx = p.x - olox, dy = p.y - oloy, dz = p.z - oloz;
    const REAL l0 = hi0 * dx + hi5 * dy + hi4 * dz;
    const REAL l1 = hi1 * dy + hi3 * dz;
    const REAL l2 = hi2 * dz;
#ifdef SPLIT_POS
    pos_add(&xi, &xl, (REAL3)(dh0 * l0 + dh5 * l1 + dh4 * l2 + dlox, dh1 * l1 + dh3 * l2 + dloy,
                              dh2 * l2 + dloz));
    POS_STORE_LO(xl, i);
    (void)h0;
    (void)h1;
    (void)h2;
    (void)h3;
    (void)h4;
    (void)h5;
    (void)nlox;
    (void)nloy;
    (void)nloz;
#else
    xi.x = h0 * l0 + h5 * l1 + h4 * l2 + nlox;
    xi.y = h1 * l1 + h3 * l2 + nloy;
    xi.z = h2 * l2 + nloz;
    (void)dh0;
    (void)dh1;
    (void)dh2;
    (void)dh3;
    (void)dh4;
    (void)dh5;
    (void)dlox;
    (void)dloy;
    (void)dloz;
#endif
    vstore3(xi, i, x);
}

/* Image flags after a box flip (src/engine/box_change.c box_change_flip): the new
 * edge vectors are b' = b + fxy a, c' = c + fyz b + fxz a (LAMMPS's flips),
 * and an atom keeps its unwrapped position:
 * iy' = iy - fyz iz, ix' = ix - fxz iz - fxy iy'. */
__kernel void box_image_flip(const int n, __global int *image, const int fxy, const int fxz,
                             const int fyz)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    int3 im = vload3(i, image);
    im.y -= fyz * im.z;
    im.x -= fxz * im.z + fxy * im.y;
    vstore3(im, i, image);
}
