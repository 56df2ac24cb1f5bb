/* fix_move.cl - fix move (styles/fix/fix_move.c): prescribed motion of a
 * group, LAMMPS's fix_move.cpp operation for operation. x0 (and x0lo, the
 * low parts when positions are split) holds each atom's unwrapped position
 * when the fix was defined, by atom ID, relative to the run's origin
 * (ntab IDs; an atom beyond them has no origin and is left alone).
 *
 * move_initial, per component d of an atom of the group: with bit d of
 * pset, x_d = x0_d + disp_d (then taken to the periodic image nearest its
 * position before, LAMMPS's Domain::remap_near); with bit d of vset, v_d =
 * vel_d; a component in neither is integrated (v += dt/2 f/m, x += dt v);
 * one in vset only drifts at the set velocity. style 2 (rotate) sets every
 * component: about the axis runit through point, by the angle whose cosine
 * and sine are given, v = w runit x (the rotated offset) and omega = w
 * runit. move_final kicks the components of bit d of nve. */

#define MOVE_ROTATE 2

/* The image of coordinate (h, l) nearest xold in a periodic dimension of
 * length L (LAMMPS's remap_near: whole periods, one at a time). */
static inline void move_remap_near(REAL *h, REAL *l, const REAL xold, const int periodic,
                                   const REAL L)
{
    if (!periodic)
        return;
    const REAL semi = (REAL)0.5 * L;
    while (*h + *l - xold > semi)
        pos_add1(h, l, -L);
    while (xold - (*h + *l) > semi)
        pos_add1(h, l, L);
}

__kernel void move_initial(const int n, const uint groupbit, __global const uint *mask,
                           __global const long *tag, const long ntab,
                           __global const REAL *x0, __global const REAL *x0lo,
                           __global REAL *x, __global REAL *v, __global REAL *omega,
                           __global const REAL *f, __global const REAL *rmass,
                           __global const REAL *radius, const int style, const int pset,
                           const int vset, const int aset, __global const REAL *pa,
                           const REAL dispx, const REAL dispy,
                           const REAL dispz, const REAL velx, const REAL vely,
                           const REAL velz, const REAL px, const REAL py, const REAL pz,
                           const REAL rx, const REAL ry, const REAL rz, const REAL w,
                           const REAL cosine, const REAL sine, const int perx,
                           const int pery, const int perz, const REAL Lx, const REAL Ly,
                           const REAL Lz, const REAL dtv, const REAL dtf POS_LO_PARAM)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const long t = tag[i];
    if (t < 0 || t >= ntab)
        return;
    REAL3 hi = vload3(i, x), lo = POS_LOAD_LO(i);
    const REAL3 xold = hi + lo;
    REAL3 vi = vload3(i, v);
    const REAL3 o = vload3(t, x0);
#ifdef SPLIT_POS
    const REAL3 olo = vload3(t, x0lo);
#else
    const REAL3 olo = (REAL3)(0);
    (void)x0lo;
#endif
    REAL h[3] = {hi.x, hi.y, hi.z}, l[3] = {lo.x, lo.y, lo.z}, vv[3] = {vi.x, vi.y, vi.z};
    const REAL oh[3] = {o.x, o.y, o.z}, ol[3] = {olo.x, olo.y, olo.z};
    const REAL xo[3] = {xold.x, xold.y, xold.z}, L[3] = {Lx, Ly, Lz};
    const int per[3] = {perx, pery, perz};
    if (style == MOVE_ROTATE) {
        const REAL r[3] = {rx, ry, rz}, p[3] = {px, py, pz};
        REAL d[3], c[3], a[3], b[3], disp[3];
        for (int q = 0; q < 3; q++)
            d[q] = (oh[q] - p[q]) + ol[q];
        const REAL ddotr = d[0] * r[0] + d[1] * r[1] + d[2] * r[2];
        for (int q = 0; q < 3; q++) {
            c[q] = ddotr * r[q];
            a[q] = d[q] - c[q];
        }
        b[0] = r[1] * a[2] - r[2] * a[1];
        b[1] = r[2] * a[0] - r[0] * a[2];
        b[2] = r[0] * a[1] - r[1] * a[0];
        for (int q = 0; q < 3; q++)
            disp[q] = a[q] * cosine + b[q] * sine;
        for (int q = 0; q < 3; q++) {
            h[q] = p[q];
            l[q] = 0;
            pos_add1(&h[q], &l[q], c[q]);
            pos_add1(&h[q], &l[q], disp[q]);
        }
        vv[0] = w * (r[1] * disp[2] - r[2] * disp[1]);
        vv[1] = w * (r[2] * disp[0] - r[0] * disp[2]);
        vv[2] = w * (r[0] * disp[1] - r[1] * disp[0]);
#ifdef HAS_ROTATION
        if (radius[i] > 0)
            vstore3((REAL3)(w * rx, w * ry, w * rz), i, omega);
#else
        (void)omega;
        (void)radius;
#endif
        for (int q = 0; q < 3; q++)
            move_remap_near(&h[q], &l[q], xo[q], per[q], L[q]);
    } else {
        REAL disp[3] = {dispx, dispy, dispz}, vel[3] = {velx, vely, velz};
        for (int q = 0; q < 3; q++) { /* atom-style variables: the atom's own values */
            if ((aset >> q) & 1)
                disp[q] = pa[6 * i + q];
            if ((aset >> (3 + q)) & 1)
                vel[q] = pa[6 * i + 3 + q];
        }
        const REAL fi[3] = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
        const REAL dtfm = dtf / rmass[i];
        for (int q = 0; q < 3; q++) {
            const int ps = (pset >> q) & 1, vs = (vset >> q) & 1;
            if (vs)
                vv[q] = vel[q];
            if (ps) {
                h[q] = oh[q];
                l[q] = ol[q];
                pos_add1(&h[q], &l[q], disp[q]);
            } else {
                if (!vs)
                    vv[q] += dtfm * fi[q];
                pos_add1(&h[q], &l[q], dtv * vv[q]);
            }
            move_remap_near(&h[q], &l[q], xo[q], per[q], L[q]);
        }
#ifndef HAS_ROTATION
        (void)omega;
        (void)radius;
#endif
    }
    vstore3((REAL3)(h[0], h[1], h[2]), i, x);
    POS_STORE_LO(((REAL3)(l[0], l[1], l[2])), i);
    vstore3((REAL3)(vv[0], vv[1], vv[2]), i, v);
}

__kernel void move_final(const int n, const uint groupbit, __global const uint *mask,
                         __global const long *tag, const long ntab, __global REAL *v,
                         __global const REAL *f, __global const REAL *rmass, const int nve,
                         const REAL dtf)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit) || tag[i] < 0 || tag[i] >= ntab)
        return;
    const REAL dtfm = dtf / rmass[i];
    for (int q = 0; q < 3; q++)
        if ((nve >> q) & 1)
            v[3 * i + q] += dtfm * f[3 * i + q];
}
