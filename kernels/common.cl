/* common.cl - types shared by every kernel.
 *
 * Build options (set by the engine): REAL=float|double (with USE_DOUBLE for
 * double), HAS_ROTATION (omega/torque arrays exist), HAS_HISTORY (per-contact
 * shear history, HIST_N REAL per contact, 3 unless set), PAIR_EVAL=<ident>_eval
 * (the active pair evaluator).
 * Contraction of a*b+c into fma is switched off so that results match the
 * host compilers LAMMPS is built with and the pair terms stay exactly
 * antisymmetric. PERIODIC_X/Y/Z mark periodic dimensions: the minimum-image
 * correction is compiled only for those (MINIMG_X/Y/Z). TRICLINIC: the box
 * is tilted (see "Triclinic boxes" below). SPLIT_POS (single
 * precision): positions are split into two arrays, see "Positions" below. */
#ifndef REAL
#define REAL double
#define USE_DOUBLE 1
#endif
#if defined(USE_DOUBLE) || defined(HAS_FP64)
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif
#pragma OPENCL FP_CONTRACT OFF

/* REALs of contact history per contact (pair granular sets more) */
#ifndef HIST_N
#define HIST_N 3
#endif
/* the slots a separated pair clears: all but a trailing HIST_OWNER slot
 * (-compat lammps2021, kernels/neighbor.cl) */
#ifndef HIST_ZERO_N
#define HIST_ZERO_N HIST_N
#endif

#define REAL3 CAT3(REAL)
#define CAT3(t) CAT3_(t)
#define CAT3_(t) t##3
#define REAL4 CAT4(REAL)
#define CAT4(t) CAT4_(t)
#define CAT4_(t) t##4

/* Minimum image of one component for a periodic length L (0 = not periodic). */
static inline REAL min_image(REAL d, REAL L)
{
    if (L > (REAL)0) {
        if (d > (REAL)0.5 * L)
            d -= L;
        else if (d < (REAL)-0.5 * L)
            d += L;
    }
    return d;
}

/* Lanes (kernels/pair_gran_lanes.cl, kernels/atom_lanes.cl): a vector type
 * of W REAL holds W contacts or particles, one per lane. LANES_W(F) is the
 * vector literal (F(0), .., F(W - 1)); LANE_OF(v, l) lane l of v (a constant
 * l once unrolled: an extract); LANE_MIN_IMAGE(T, d, L) min_image of each
 * lane of d (type T), the same comparisons and arithmetic. */
#define LANE_PASTE(a, b) a##b
#define LANE_CAT(a, b) LANE_PASTE(a, b)
#define LANES_2(F) (F(0), F(1))
#define LANES_4(F) (F(0), F(1), F(2), F(3))
#define LANES_8(F) (F(0), F(1), F(2), F(3), F(4), F(5), F(6), F(7))
#define LANES_16(F)                                                                            \
    (F(0), F(1), F(2), F(3), F(4), F(5), F(6), F(7), F(8), F(9), F(10), F(11), F(12), F(13),   \
     F(14), F(15))
#define LANE_OF(v, l) (((const REAL *)&(v))[l])
#define LANE_MIN_IMAGE(T, d, L)                                                                \
    ((L) > (REAL)0 ? select(select((d), (d) + (T)(L), (d) < (T)((REAL)-0.5 * (L))),           \
                            (d) - (T)(L), (d) > (T)((REAL)0.5 * (L)))                         \
                   : (d))

#ifdef PERIODIC_X
#define MINIMG_X(d, L) min_image(d, L)
#else
#define MINIMG_X(d, L) (d)
#endif
#ifdef PERIODIC_Y
#define MINIMG_Y(d, L) min_image(d, L)
#else
#define MINIMG_Y(d, L) (d)
#endif
#ifdef PERIODIC_Z
#define MINIMG_Z(d, L) min_image(d, L)
#else
#define MINIMG_Z(d, L) (d)
#endif

/* Triclinic boxes. Every kernel that takes separations or wraps receives
 * the periodic lengths Lx Ly Lz (0 = not periodic) followed by the tilt
 * factors xy xz yz (LAMMPS's edge vectors a = (Lx,0,0), b = (xy,Ly,0),
 * c = (xz,yz,Lz)); the tilts are read only with TRICLINIC. MINIMG3(d)
 * replaces the REAL3 separation d by its minimum image: z first (an image
 * in z shifts by c), then y (by b), then x (by a), as LAMMPS's
 * Domain::minimum_image. */
#ifdef TRICLINIC
static inline REAL3 minimg_tri(REAL3 d, const REAL Lx, const REAL Ly, const REAL Lz,
                               const REAL xy, const REAL xz, const REAL yz)
{
#ifdef PERIODIC_Z
    if (d.z > (REAL)0.5 * Lz) {
        d.z -= Lz;
        d.y -= yz;
        d.x -= xz;
    } else if (d.z < (REAL)-0.5 * Lz) {
        d.z += Lz;
        d.y += yz;
        d.x += xz;
    }
#endif
#ifdef PERIODIC_Y
    if (d.y > (REAL)0.5 * Ly) {
        d.y -= Ly;
        d.x -= xy;
    } else if (d.y < (REAL)-0.5 * Ly) {
        d.y += Ly;
        d.x += xy;
    }
#endif
#ifdef PERIODIC_X
    d.x = min_image(d.x, Lx);
#endif
    (void)Lx;
    (void)Ly;
    (void)Lz;
    (void)xz;
    (void)yz;
    (void)xy;
    return d;
}
#define MINIMG3(d) ((d) = minimg_tri((d), Lx, Ly, Lz, xy, xz, yz))
#else
#define MINIMG3(d)                                                                             \
    {                                                                                          \
        (d).x = MINIMG_X((d).x, Lx);                                                           \
        (d).y = MINIMG_Y((d).y, Ly);                                                           \
        (d).z = MINIMG_Z((d).z, Lz);                                                           \
        (void)xy;                                                                              \
        (void)xz;                                                                              \
        (void)yz;                                                                              \
    }
#endif

/* Velocity remap (VREMAP, fix deform remap v): hrate = LAMMPS's h_rate
 * (d/dt of Lx Ly Lz yz xz xy); an atom of the group vgroup seen through a
 * periodic image n (n_a whole periods along a, b, c) moves with
 * v + n . h_rate: the image's streaming velocity. */
static inline REAL3 image_velocity(const int3 n, __global const REAL *hrate)
{
    return (REAL3)(n.x * hrate[0] + n.y * hrate[5] + n.z * hrate[4], n.y * hrate[1] + n.z * hrate[3],
                   n.z * hrate[2]);
}

/* The periods n a minimum image moved the partner by: raw - del = n_x a +
 * n_y b + n_z c (raw = x_i - x_j before MINIMG3, del after). */
static inline int3 image_count(const REAL3 raw, const REAL3 del, const REAL Lx, const REAL Ly,
                               const REAL Lz, const REAL xy, const REAL xz, const REAL yz)
{
    const REAL3 s = raw - del;
    const int nz = Lz > (REAL)0 ? (int)round(s.z / Lz) : 0;
    const int ny = Ly > (REAL)0 ? (int)round((s.y - nz * yz) / Ly) : 0;
    const int nx = Lx > (REAL)0 ? (int)round((s.x - ny * xy - nz * xz) / Lx) : 0;
    return (int3)(nx, ny, nz);
}

/* Box coordinates of a position relative to the lower corner d = x - lo:
 * u = L lamda per dimension (the lamda coordinates scaled by the lengths;
 * u = d in an orthogonal box). A periodic image moves u by exactly one
 * length, so cells of u wrap as in an orthogonal box. Lengths may be 0 for
 * dimensions without tilt across them. */
static inline REAL3 box_u(REAL3 d, const REAL Ly, const REAL Lz, const REAL xy, const REAL xz,
                          const REAL yz)
{
#ifdef TRICLINIC
    const REAL lz = Lz > (REAL)0 ? d.z / Lz : (REAL)0;
    d.y -= yz * lz;
    const REAL ly = Ly > (REAL)0 ? d.y / Ly : (REAL)0;
    d.x -= xy * ly + xz * lz;
#else
    (void)Ly;
    (void)Lz;
    (void)xy;
    (void)xz;
    (void)yz;
#endif
    return d;
}

/* How much wider than a separation's length its u components can be
 * (|du_q| <= fac_q |d|): the norms of the rows of L h^-1 (1 when
 * orthogonal). Cells of u are this much wider than the cut-off. */
static inline REAL3 box_ufac(const REAL Ly, const REAL Lz, const REAL xy, const REAL xz,
                             const REAL yz)
{
#ifdef TRICLINIC
    const REAL by = Ly > (REAL)0 ? xy / Ly : (REAL)0;
    const REAL cz = Lz > (REAL)0 ? (xy * (Ly > (REAL)0 ? yz / Ly : (REAL)0) - xz) / Lz : (REAL)0;
    const REAL cy = Lz > (REAL)0 ? yz / Lz : (REAL)0;
    return (REAL3)(sqrt((REAL)1 + by * by + cz * cz), sqrt((REAL)1 + cy * cy), (REAL)1);
#else
    (void)Ly;
    (void)Lz;
    (void)xy;
    (void)xz;
    (void)yz;
    return (REAL3)(1);
#endif
}

/* Positions. With SPLIT_POS (every single-precision run) a coordinate is the
 * unevaluated sum hi + lo of two floats, hi in x and lo in xlo (the kernel's
 * last argument, POS_LO_PARAM), relative to the run's origin (the box centre,
 * src/engine/engine.c): 48 significant bits, so a drift below half the float spacing
 * still moves the particle and a contact's separation is resolved as in
 * double. Drifts go through pos_add, contact separations and overlaps through
 * contact_refine (below) from the hi and lo differences; binning and the
 * rebuild test read hi alone (off by at most one float
 * spacing of a box-relative coordinate). Without SPLIT_POS there is one array
 * and these reduce to the plain arithmetic. */
#ifdef SPLIT_POS
#define POS_LO_PARAM , __global REAL *xlo
#define POS_LO_ARG , xlo
#define POS_LOAD_LO(i) vload3(i, xlo)
#define POS_STORE_LO(val, i) vstore3(val, i, xlo)
/* *hi + *lo += d for values of type T (REAL, REAL3, lanes), renormalised
 * (TwoSum, then Fast2Sum): exact to the last bit of lo */
#define POS_TWOSUM(T, hi, lo, d)                                                               \
    {                                                                                          \
        const T s_ = *(hi) + (d), bb_ = s_ - *(hi);                                            \
        const T t_ = ((*(hi) - (s_ - bb_)) + ((d) - bb_)) + *(lo);                             \
        *(hi) = s_ + t_;                                                                       \
        *(lo) = t_ - (*(hi) - s_);                                                             \
    }
static inline void pos_add1(REAL *hi, REAL *lo, const REAL d) POS_TWOSUM(REAL, hi, lo, d)
static inline void pos_add(REAL3 *hi, REAL3 *lo, const REAL3 d) POS_TWOSUM(REAL3, hi, lo, d)
#else
#define POS_LO_PARAM
#define POS_LO_ARG
#define POS_LOAD_LO(i) ((REAL3)(0))
#define POS_STORE_LO(val, i) ((void)0)
static inline void pos_add1(REAL *hi, REAL *lo, const REAL d)
{
    (void)lo;
    *hi += d;
}
static inline void pos_add(REAL3 *hi, REAL3 *lo, const REAL3 d)
{
    (void)lo;
    *hi = *hi + d;
}
#endif

/* Periodic wrap of one coordinate (hi h, lo l) into [lo, hi) of period L,
 * one period at most (LAMMPS Domain::pbc); the image flag follows. */
static inline void pbc_wrap(REAL *h, REAL *l, int *im, const REAL lo, const REAL hi,
                            const REAL L)
{
    if (*h + *l < lo) {
        pos_add1(h, l, L);
        (*im)--;
    }
    if (*h + *l >= hi) {
        pos_add1(h, l, -L);
        if (*h + *l < lo) { /* rounding: stay inside */
            *h = lo;
            *l = 0;
        }
        (*im)++;
    }
}

#ifdef TRICLINIC
/* Periodic wrap of a position (hi h, lo l) in a tilted box, one period at
 * most per dimension: z against [loz, hiz) (an image shifts by c), then y
 * against the face through the wrapped z (by b), then x against the faces
 * through y and z (by a); the decisions are LAMMPS's lamda tests
 * 0 <= lamda < 1, with L lamda = the u of box_u. A shift that would put the
 * atom past the opposite face is not made: the atom sits on a face to
 * round-off (its u a few ulps outside [0, L), as after change_box ... remap
 * of a lattice atom on a tilted face); LAMMPS's MAX(lamda, lo) keeps such an
 * atom there too, and box_inside accepts it. */
static inline void pbc_wrap_tri(REAL3 *h, REAL3 *l, int3 *im, const REAL3 lo, const REAL3 hi,
                                const REAL xy, const REAL xz, const REAL yz)
{
    const REAL3 L = hi - lo;
#ifdef PERIODIC_Z
    {
        const REAL z = h->z + l->z;
        const int dn = z < lo.z ? -1 : z >= hi.z ? 1 : 0;
        if (dn) {
            REAL3 h2 = *h, l2 = *l;
            pos_add(&h2, &l2, (REAL3)(-dn * xz, -dn * yz, -dn * L.z));
            const REAL z2 = h2.z + l2.z;
            if (z2 >= lo.z && z2 < hi.z) {
                *h = h2;
                *l = l2;
                im->z += dn;
            }
        }
    }
#endif
    const REAL lz = ((h->z + l->z) - lo.z) / L.z;
#ifdef PERIODIC_Y
    {
        const REAL uy = ((h->y + l->y) - lo.y) - yz * lz;
        const int dn = uy < 0 ? -1 : uy >= L.y ? 1 : 0;
        if (dn) {
            REAL3 h2 = *h, l2 = *l;
            pos_add(&h2, &l2, (REAL3)(-dn * xy, -dn * L.y, 0));
            const REAL uy2 = ((h2.y + l2.y) - lo.y) - yz * lz;
            if (uy2 >= 0 && uy2 < L.y) {
                *h = h2;
                *l = l2;
                im->y += dn;
            }
        }
    }
#endif
    const REAL ly = (((h->y + l->y) - lo.y) - yz * lz) / L.y;
#ifdef PERIODIC_X
    {
        const REAL ux = ((h->x + l->x) - lo.x) - xy * ly - xz * lz;
        const int dn = ux < 0 ? -1 : ux >= L.x ? 1 : 0;
        if (dn) {
            REAL3 h2 = *h, l2 = *l;
            pos_add(&h2, &l2, (REAL3)(-dn * L.x, 0, 0));
            const REAL ux2 = ((h2.x + l2.x) - lo.x) - xy * ly - xz * lz;
            if (ux2 >= 0 && ux2 < L.x) {
                *h = h2;
                *l = l2;
                im->x += dn;
            }
        }
    }
#endif
    (void)ly;
}

/* Whether u (box_u of a position) lies in the tilted box [0, L) per
 * dimension; in a periodic dimension a margin of round-off (BOX_UTOL of L)
 * either side admits an atom pbc_wrap_tri left on a face. Outside by more,
 * an atom crossed a fixed face or moved more than a box length. */
#ifdef USE_DOUBLE
#define BOX_UTOL ((REAL)1e-12)
#else
#define BOX_UTOL ((REAL)1e-5)
#endif
static inline int box_inside1(const REAL u, const REAL L, const int periodic)
{
    const REAL m = periodic ? BOX_UTOL * L : (REAL)0;
    return u >= -m && (periodic ? u < L + m : u < L);
}
static inline int box_inside(const REAL3 u, const REAL3 L)
{
#ifdef PERIODIC_X
    const int px = 1;
#else
    const int px = 0;
#endif
#ifdef PERIODIC_Y
    const int py = 1;
#else
    const int py = 0;
#endif
#ifdef PERIODIC_Z
    const int pz = 1;
#else
    const int pz = 0;
#endif
    return box_inside1(u.x, L.x, px) && box_inside1(u.y, L.y, py) && box_inside1(u.z, L.z, pz);
}
#endif
