/* wall_region.cl - geometry kind "region" of the wall stage (kernels/wall.cl;
 * host side src/contact/wall_region.c; front-end fix wall/gran/region): the surface
 * contacts of a LAMMPS region, as LAMMPS computes them (Region::surface,
 * surface_interior / surface_exterior of block, sphere, cylinder, cone and
 * plane, union and intersect of those), as pure functions of the particle.
 *
 * A region is up to RG_MAXNODE primitive nodes of RG_NODE REAL each
 * (layout RG_* of kernels/wall_layout.h, filled by src/contact/wall_region.c
 * every step) and a combinator: 0 a single primitive (node 0), 1 union, 2
 * intersect of the nodes, with the compound's side. Each node carries its own side, open faces and motion:
 * the particle is taken into the node's static frame (subtract d, rotate by
 * -theta about P), the contacts found there, and each contact point taken
 * back (rotate by theta, add d), as Region::surface does. A contact is its
 * distance r, curvature radius (0 flat, < 0 concave), del = x - contact
 * point, and a wall id (iwall) that keys its history. Coordinates are the
 * device's (relative to the run's origin: the host shifts the nodes). */

/* RG_* (node layout, primitives, RG_MAXNODE, RG_MAXC): kernels/wall_layout.h */
#define RG_BIG ((REAL)1.0e20)

struct rg_contact {
    REAL r, radius;
    REAL3 del;
    int iwall, node;
};

static inline REAL3 rg_vec(__global const REAL *nd, const int k)
{
    return (REAL3)(nd[k], nd[k + 1], nd[k + 2]);
}

/* Region::rotate: about the axis through P by the angle of (s, c) */
static inline REAL3 rg_rotate(__global const REAL *nd, const REAL3 x, const REAL s, const REAL c)
{
    const REAL3 p = rg_vec(nd, RG_POINT), u = rg_vec(nd, RG_RUNIT);
    const REAL3 d = x - p;
    const REAL dot = d.x * u.x + d.y * u.y + d.z * u.z;
    const REAL3 cc = dot * u;
    const REAL3 a = d - cc;
    const REAL3 b = (REAL3)(u.y * a.z - u.z * a.y, u.z * a.x - u.x * a.z, u.x * a.y - u.y * a.x);
    return p + cc + (a * c + b * s);
}

static inline REAL3 rg_inverse(__global const REAL *nd, REAL3 x)
{
    if (nd[RG_MOVE] != 0)
        x -= rg_vec(nd, RG_D);
    if (nd[RG_ROT] != 0)
        x = rg_rotate(nd, x, -nd[RG_SIN], nd[RG_COS]);
    return x;
}

static inline REAL3 rg_forward(__global const REAL *nd, REAL3 x)
{
    if (nd[RG_ROT] != 0)
        x = rg_rotate(nd, x, nd[RG_SIN], nd[RG_COS]);
    if (nd[RG_MOVE] != 0)
        x += rg_vec(nd, RG_D);
    return x;
}

static inline REAL rg_comp(const REAL3 v, const int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

static inline REAL3 rg_set(REAL3 v, const int k, const REAL a)
{
    if (k == 0)
        v.x = a;
    else if (k == 1)
        v.y = a;
    else
        v.z = a;
    return v;
}

/* a point from its axial coordinate and two transverse ones (LAMMPS c1, c2
 * order: y z for axis x, x z for y, x y for z) */
static inline REAL3 rg_axial(const int ax, const REAL a, const REAL t1, const REAL t2)
{
    return ax == 0 ? (REAL3)(a, t1, t2) : ax == 1 ? (REAL3)(t1, a, t2) : (REAL3)(t1, t2, a);
}

static inline REAL rg_t1(const int ax, const REAL3 x) { return ax == 0 ? x.y : x.x; }
static inline REAL rg_t2(const int ax, const REAL3 x) { return ax == 2 ? x.y : x.z; }

/* geometric interior (inclusive), in the node's frame */
static inline int rg_inside(__global const REAL *nd, const REAL3 x)
{
    __global const REAL *p = nd + RG_P;
    const int kind = (int)nd[RG_KIND], ax = (int)nd[RG_AXIS];
    if (kind == RG_BLOCK)
        return x.x >= p[0] && x.x <= p[1] && x.y >= p[2] && x.y <= p[3] && x.z >= p[4] &&
               x.z <= p[5];
    if (kind == RG_SPHERE) {
        const REAL3 d = x - (REAL3)(p[0], p[1], p[2]);
        return sqrt(d.x * d.x + d.y * d.y + d.z * d.z) <= p[3];
    }
    if (kind == RG_PLANE)
        return (x.x - p[0]) * p[3] + (x.y - p[1]) * p[4] + (x.z - p[2]) * p[5] >= 0;
    const REAL a = rg_comp(x, ax), d1 = rg_t1(ax, x) - p[0], d2 = rg_t2(ax, x) - p[1];
    const REAL dist = sqrt(d1 * d1 + d2 * d2);
    if (kind == RG_CYLINDER)
        return dist <= p[2] && a >= p[3] && a <= p[4];
    /* cone: c1 c2 radlo radhi lo hi */
    const REAL rad = p[2] + (a - p[4]) * (p[3] - p[2]) / (p[5] - p[4]);
    return dist <= rad && a >= p[4] && a <= p[5];
}

/* Region::match of a node, y the point in the node's frame (flip: the side
 * inverted) */
static inline int rg_match_at(__global const REAL *nd, const REAL3 y, const int flip)
{
    if (nd[RG_OPENFLAG] != 0)
        return 1;
    return rg_inside(nd, y) == (((int)nd[RG_INTERIOR]) ^ flip);
}

/* the same for x in the compound's frame */
static inline int rg_match(__global const REAL *nd, const REAL3 x, const int flip)
{
    return rg_match_at(nd, rg_inverse(nd, x), flip);
}

static inline int rg_open(__global const REAL *nd, const int face)
{
    return ((int)nd[RG_OPEN] >> face) & 1;
}

static inline void rg_put(struct rg_contact *c, const REAL r, const REAL3 del, const REAL radius,
                          const int iwall)
{
    c->r = r;
    c->del = del;
    c->radius = radius;
    c->iwall = iwall;
}

/* Region::add_contact: from the surface point xp */
static inline void rg_add(struct rg_contact *c, const REAL3 x, const REAL3 xp)
{
    const REAL3 d = x - xp;
    c->del = d;
    c->r = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    c->radius = 0;
    c->iwall = 0;
}

/* Region::point_on_line_segment: nearest point to c on segment ab */
static inline REAL3 rg_segment(const REAL3 a, const REAL3 b, const REAL3 c)
{
    const REAL3 ba = b - a, ca = c - a;
    const REAL t =
        (ca.x * ba.x + ca.y * ba.y + ca.z * ba.z) / (ba.x * ba.x + ba.y * ba.y + ba.z * ba.z);
    if (t <= 0)
        return a;
    if (t >= 1)
        return b;
    return a + t * ba;
}

static inline REAL rg_dsq(const REAL3 a, const REAL3 b)
{
    const REAL3 d = a - b;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

/* ---- surface_interior: contacts with the inner faces, 0 <= r < cutoff ----
 * One function per primitive, x in the node's frame, contacts into c;
 * each returns how many. */
static inline int rg_interior_block(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                    struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    if (x.x < p[0] || x.x > p[1] || x.y < p[2] || x.y > p[3] || x.z < p[4] || x.z > p[5])
        return 0;
    int n = 0;
    for (int f = 0; f < 6; f++) {
        const int k = f >> 1;
        const REAL delta = (f & 1) ? p[f] - rg_comp(x, k) : rg_comp(x, k) - p[f];
        if (delta < cutoff && !rg_open(nd, f)) {
            rg_put(&c[n], delta, rg_set((REAL3)(0), k, (f & 1) ? -delta : delta), 0, f);
            n++;
        }
    }
    return n;
}

static inline int rg_interior_sphere(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                     struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    const REAL3 d = x - (REAL3)(p[0], p[1], p[2]);
    const REAL r = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (r > p[3] || r == 0)
        return 0;
    const REAL delta = p[3] - r;
    if (delta < cutoff) {
        rg_put(&c[0], delta, d * (1 - p[3] / r), -p[3], 0);
        return 1;
    }
    return 0;
}

static inline int rg_interior_plane(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                    struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    const REAL dot = (x.x - p[0]) * p[3] + (x.y - p[1]) * p[4] + (x.z - p[2]) * p[5];
    if (dot < cutoff && dot >= 0) {
        rg_put(&c[0], dot, (REAL3)(dot * p[3], dot * p[4], dot * p[5]), 0, 0);
        return 1;
    }
    return 0;
}

/* the end caps lo and hi of a cylinder or cone (faces 0 and 1) after its
 * n side contacts */
static inline int rg_interior_caps(__global const REAL *nd, const REAL a, const REAL lo,
                                   const REAL hi, const REAL cutoff, struct rg_contact *c, int n)
{
    const int ax = (int)nd[RG_AXIS];
    REAL delta = a - lo;
    if (delta < cutoff && !rg_open(nd, 0)) {
        rg_put(&c[n], delta, rg_set((REAL3)(0), ax, delta), 0, 0);
        n++;
    }
    delta = hi - a;
    if (delta < cutoff && !rg_open(nd, 1)) {
        rg_put(&c[n], delta, rg_set((REAL3)(0), ax, -delta), 0, 1);
        n++;
    }
    return n;
}

static inline int rg_interior_cylinder(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                       struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    const int ax = (int)nd[RG_AXIS];
    const REAL a = rg_comp(x, ax), d1 = rg_t1(ax, x) - p[0], d2 = rg_t2(ax, x) - p[1];
    const REAL r = sqrt(d1 * d1 + d2 * d2);
    const REAL rad = p[2], lo = p[3], hi = p[4];
    if (r > rad || a < lo || a > hi)
        return 0;
    int n = 0;
    const REAL delta = rad - r;
    if (delta < cutoff && r > 0 && !rg_open(nd, 2)) {
        rg_put(&c[n], delta, rg_axial(ax, 0, d1 * (1 - rad / r), d2 * (1 - rad / r)), -2 * rad,
               2);
        n++;
    }
    return rg_interior_caps(nd, a, lo, hi, cutoff, c, n);
}

/* cone: c1 c2 radlo radhi lo hi */
static inline int rg_interior_cone(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                   struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    const int ax = (int)nd[RG_AXIS];
    const REAL a = rg_comp(x, ax), d1 = rg_t1(ax, x) - p[0], d2 = rg_t2(ax, x) - p[1];
    const REAL r = sqrt(d1 * d1 + d2 * d2);
    const REAL rlo = p[2], rhi = p[3], lo = p[4], hi = p[5];
    const REAL cur = rlo + (a - lo) * (rhi - rlo) / (hi - lo);
    if (r > cur || a < lo || a > hi)
        return 0;
    int n = 0;
    if (r > 0 && !rg_open(nd, 2)) {
        const REAL3 slo = rg_axial(ax, lo, p[0] + d1 * rlo / r, p[1] + d2 * rlo / r);
        const REAL3 shi = rg_axial(ax, hi, p[0] + d1 * rhi / r, p[1] + d2 * rhi / r);
        const REAL3 xs = rg_segment(slo, shi, x);
        const REAL3 del = x - xs;
        const REAL dist = sqrt(del.x * del.x + del.y * del.y + del.z * del.z);
        if (dist < cutoff) {
            rg_put(&c[n], dist, del, -2 * (rlo + (rg_comp(xs, ax) - lo) * (rhi - rlo) / (hi - lo)),
                   2);
            n++;
        }
    }
    return rg_interior_caps(nd, a, lo, hi, cutoff, c, n);
}

static inline int rg_interior(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                              struct rg_contact *c)
{
    switch ((int)nd[RG_KIND]) {
    case RG_BLOCK:
        return rg_interior_block(nd, x, cutoff, c);
    case RG_SPHERE:
        return rg_interior_sphere(nd, x, cutoff, c);
    case RG_PLANE:
        return rg_interior_plane(nd, x, cutoff, c);
    case RG_CYLINDER:
        return rg_interior_cylinder(nd, x, cutoff, c);
    default:
        return rg_interior_cone(nd, x, cutoff, c);
    }
}

/* ---- surface_exterior: the one nearest outer surface point, r < cutoff ----
 * One function per primitive, x in the node's frame, the contact into c[0];
 * each returns 1 when there is one. */
static inline int rg_exterior_block(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                    struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    const int openflag = nd[RG_OPENFLAG] != 0;
    if (x.x <= p[0] - cutoff || x.x >= p[1] + cutoff || x.y <= p[2] - cutoff ||
        x.y >= p[3] + cutoff || x.z <= p[4] - cutoff || x.z >= p[5] + cutoff)
        return 0;
    if (x.x > p[0] && x.x < p[1] && x.y > p[2] && x.y < p[3] && x.z > p[4] && x.z < p[5])
        return 0;
    const REAL3 lo = (REAL3)(p[0], p[2], p[4]), hi = (REAL3)(p[1], p[3], p[5]);
    REAL3 xp = clamp(x, lo, hi);
    if (openflag) { /* nearest point of the closed faces (each a clamped rectangle) */
        REAL best = RG_BIG;
        for (int f = 0; f < 6; f++) {
            if (rg_open(nd, f))
                continue;
            const REAL3 q = rg_set(clamp(x, lo, hi), f >> 1, p[f]);
            const REAL dsq = rg_dsq(x, q);
            if (dsq < best) {
                best = dsq;
                xp = q;
            }
        }
    }
    rg_add(&c[0], x, xp);
    return c[0].r < cutoff;
}

static inline int rg_exterior_sphere(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                     struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    const REAL3 d = x - (REAL3)(p[0], p[1], p[2]);
    const REAL r = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (r < p[3])
        return 0;
    const REAL delta = r - p[3];
    if (delta < cutoff) {
        rg_put(&c[0], delta, d * (1 - p[3] / r), p[3], 0);
        return 1;
    }
    return 0;
}

static inline int rg_exterior_plane(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                    struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    const REAL dot = -((x.x - p[0]) * p[3] + (x.y - p[1]) * p[4] + (x.z - p[2]) * p[5]);
    if (dot < cutoff && dot >= 0) {
        rg_put(&c[0], dot, (REAL3)(-dot * p[3], -dot * p[4], -dot * p[5]), 0, 0);
        return 1;
    }
    return 0;
}

static inline int rg_exterior_cylinder(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                       struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    const int ax = (int)nd[RG_AXIS];
    const int openflag = nd[RG_OPENFLAG] != 0;
    const REAL a = rg_comp(x, ax), d1 = rg_t1(ax, x) - p[0], d2 = rg_t2(ax, x) - p[1];
    const REAL r = sqrt(d1 * d1 + d2 * d2);
    const REAL rad = p[2], lo = p[3], hi = p[4];
    if (r >= rad + cutoff || a <= lo - cutoff || a >= hi + cutoff)
        return 0;
    if (r < rad && a > lo && a < hi)
        return 0;
    REAL crad = 0, ap, t1, t2;
    if (!openflag) {
        if (r > rad) {
            t1 = p[0] + d1 * rad / r;
            t2 = p[1] + d2 * rad / r;
            crad = 2 * rad;
        } else {
            t1 = rg_t1(ax, x);
            t2 = rg_t2(ax, x);
        }
        ap = a < lo ? lo : a > hi ? hi : a;
    } else {
        const REAL dr = r - rad, dr2 = dr * dr;
        REAL d2prev = RG_BIG, dd;
        ap = a;
        t1 = rg_t1(ax, x);
        t2 = rg_t2(ax, x);
        if (!rg_open(nd, 2)) {
            t1 = p[0] + d1 * rad / r;
            t2 = p[1] + d2 * rad / r;
            REAL dx;
            if (a < lo) {
                dx = lo - a;
                ap = lo;
            } else if (a > hi) {
                dx = a - hi;
                ap = hi;
            } else {
                dx = 0;
                ap = a;
            }
            d2prev = dr2 + dx * dx;
        }
        /* a cap's nearest point: above the atom inside the radius, on the
         * rim outside it (LAMMPS 2026; LAMMPS 2021 kept the curved face's
         * point there, the atom's own when that face is open) */
        const int rim = r >= rad && !(((int)nd[RG_OPEN] >> RG_OPEN_RIM2021) & 1);
        for (int f = 0; f < 2; f++) {
            if (rg_open(nd, f))
                continue;
            const REAL dx = (f ? hi : lo) - a;
            dd = r < rad ? dx * dx : dr2 + dx * dx;
            if (dd < d2prev) {
                ap = f ? hi : lo;
                if (r < rad) {
                    t1 = rg_t1(ax, x);
                    t2 = rg_t2(ax, x);
                } else if (rim) {
                    t1 = p[0] + d1 * rad / r;
                    t2 = p[1] + d2 * rad / r;
                }
                d2prev = dd;
            }
        }
    }
    rg_add(&c[0], x, rg_axial(ax, ap, t1, t2));
    c[0].radius = crad;
    return c[0].r < cutoff;
}

/* cone: c1 c2 radlo radhi lo hi, then the larger radius */
static inline int rg_exterior_cone(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                                   struct rg_contact *c)
{
    __global const REAL *p = nd + RG_P;
    const int ax = (int)nd[RG_AXIS];
    const REAL a = rg_comp(x, ax), d1 = rg_t1(ax, x) - p[0], d2 = rg_t2(ax, x) - p[1];
    const REAL r = sqrt(d1 * d1 + d2 * d2);
    const REAL rlo = p[2], rhi = p[3], lo = p[4], hi = p[5], rmax = p[6];
    const REAL cur = rlo + (a - lo) * (rhi - rlo) / (hi - lo);
    if (r >= rmax + cutoff || a <= lo - cutoff || a >= hi + cutoff)
        return 0;
    if (r < cur && a > lo && a < hi)
        return 0;
    const REAL3 c1 = rg_axial(ax, lo, p[0] + d1 * rlo / r, p[1] + d2 * rlo / r);
    const REAL3 c2 = rg_axial(ax, hi, p[0] + d1 * rhi / r, p[1] + d2 * rhi / r);
    const REAL3 c3 = rg_axial(ax, lo, p[0], p[1]), c4 = rg_axial(ax, hi, p[0], p[1]);
    REAL best = RG_BIG, crad = 0;
    REAL3 nearest = x;
    if (!rg_open(nd, 2)) {
        const REAL3 q = rg_segment(c1, c2, x);
        const REAL dsq = rg_dsq(x, q);
        if (dsq < best) {
            best = dsq;
            nearest = q;
        }
        crad = -2 * (rlo + (rg_comp(nearest, ax) - lo) * (rhi - rlo) / (hi - lo));
    }
    for (int f = 0; f < 2; f++) {
        if (rg_open(nd, f))
            continue;
        const REAL3 q = f == 0 ? rg_segment(c1, c3, x) : rg_segment(c2, c4, x);
        const REAL dsq = rg_dsq(x, q);
        if (dsq < best) {
            best = dsq;
            nearest = q;
            crad = 0;
        }
    }
    if (best == RG_BIG)
        return 0;
    rg_add(&c[0], x, nearest);
    c[0].radius = crad;
    return c[0].r < cutoff;
}

static inline int rg_exterior(__global const REAL *nd, const REAL3 x, const REAL cutoff,
                              struct rg_contact *c)
{
    switch ((int)nd[RG_KIND]) {
    case RG_BLOCK:
        return rg_exterior_block(nd, x, cutoff, c);
    case RG_SPHERE:
        return rg_exterior_sphere(nd, x, cutoff, c);
    case RG_PLANE:
        return rg_exterior_plane(nd, x, cutoff, c);
    case RG_CYLINDER:
        return rg_exterior_cylinder(nd, x, cutoff, c);
    default:
        return rg_exterior_cone(nd, x, cutoff, c);
    }
}

/* Region::surface of one node (flip: side inverted, as union / intersect do
 * for their exterior) for xorig, x its point in the node's frame; contacts
 * written from c[0]; returns how many. */
static inline int rg_surface_at(__global const REAL *nd, const int node, const REAL3 xorig,
                                const REAL3 x, const REAL cutoff, const int flip,
                                struct rg_contact *c)
{
    int n;
    if (nd[RG_OPENFLAG] == 0)
        n = (((int)nd[RG_INTERIOR]) ^ flip) ? rg_interior(nd, x, cutoff, c)
                                             : rg_exterior(nd, x, cutoff, c);
    else { /* one of the two finds nothing */
        n = rg_exterior(nd, x, cutoff, c);
        n += rg_interior(nd, x, cutoff, c + n);
    }
    for (int k = 0; k < n; k++) {
        c[k].node = node;
        if (nd[RG_ROT] != 0)
            c[k].del = xorig - rg_forward(nd, x - c[k].del);
    }
    return n;
}

/* the same with the node's frame found here */
static inline int rg_surface(__global const REAL *nd, const int node, const REAL3 xorig,
                             const REAL cutoff, const int flip, struct rg_contact *c)
{
    return rg_surface_at(nd, node, xorig, rg_inverse(nd, xorig), cutoff, flip, c);
}

/* The point a region's own tests take: x in its node's frame for a single
 * primitive (comb 0; computed once for match and surface), else x. */
static inline REAL3 region_frame(__global const REAL *nodes, const int comb, const REAL3 x)
{
    return comb == 0 ? rg_inverse(nodes, x) : x;
}

/* Region::match of the whole region (xf: region_frame's point) */
static inline int region_match(__global const REAL *nodes, const int nnode, const int comb,
                               const int interior, const REAL3 x, const REAL3 xf)
{
    if (comb == 0)
        return rg_match_at(nodes, xf, 0);
    int any = 0, all = 1;
    for (int k = 0; k < nnode; k++) {
        const int m = rg_match(nodes + k * RG_NODE, x, 0);
        any |= m;
        all &= m;
    }
    return (comb == 1 ? any : all) == interior;
}

/* Region::surface of the whole region: up to RG_MAXC contacts into c. A
 * union keeps a sub-region's contact whose point lies in no other (closed)
 * sub-region, an intersect one whose point lies in all others; the side out
 * of both works on the inverted sub-regions (LAMMPS RegUnion, RegIntersect).
 * xf: region_frame's point. */
static inline int region_surface(__global const REAL *nodes, const int nnode, const int comb,
                                 const int interior, const REAL3 x, const REAL3 xf,
                                 const REAL cutoff, struct rg_contact *c)
{
    if (comb == 0)
        return rg_surface_at(nodes, 0, x, xf, cutoff, 0, c);
    const int flip = !interior;
    int n = 0;
    for (int k = 0; k < nnode && n < RG_MAXC; k++) {
        __global const REAL *nd = nodes + k * RG_NODE;
        struct rg_contact s[RG_MAXC]; /* an open face point on the surface: 1 + 6 */
        const int ns = rg_surface(nd, k, x, cutoff, flip, s);
        for (int m = 0; m < ns && n < RG_MAXC; m++) {
            const REAL3 xs = x - s[m].del;
            int keep = 1;
            for (int j = 0; j < nnode; j++) {
                if (j == k)
                    continue;
                __global const REAL *nj = nodes + j * RG_NODE;
                const int mj = rg_match(nj, xs, flip);
                /* union in / intersect out: drop when another contains it;
                 * intersect in / union out: drop when another does not */
                const int drop = (comb == 1) == (interior != 0)
                                     ? (mj && (comb == 2 || nj[RG_OPENFLAG] == 0))
                                     : !mj;
                if (drop) {
                    keep = 0;
                    break;
                }
            }
            if (!keep)
                continue;
            c[n] = s[m];
            c[n].iwall = interior ? s[m].iwall + (int)nd[RG_WALLOFF] : k;
            n++;
        }
    }
    return n;
}

/* surface velocity of node nd at contact point xc (Region::velocity_contact) */
static inline REAL3 region_velocity(__global const REAL *nd, const REAL3 xc)
{
    REAL3 v = (REAL3)(0);
    if (nd[RG_MOVE] != 0)
        v = rg_vec(nd, RG_V);
    if (nd[RG_ROT] != 0) {
        const REAL3 w = rg_vec(nd, RG_OMEGA), rp = rg_vec(nd, RG_RPOINT);
        v.x += w.y * (xc.z - rp.z) - w.z * (xc.y - rp.y);
        v.y += w.z * (xc.x - rp.x) - w.x * (xc.z - rp.z);
        v.z += w.x * (xc.y - rp.y) - w.y * (xc.x - rp.x);
    }
    return v;
}

/* The wall-id bookkeeping of an atom's region contacts, as LAMMPS
 * FixWallGranRegion::update_contacts: hist = the contact count, `slots`
 * wall ids, then hw REAL of history per slot. Slots of walls no longer
 * touched are replaced by the last one, new walls appended with zero
 * history; c2r[k] = the slot of contact k (LAMMPS's c2r). Returns 0 when
 * the atom has no contact now (its count is reset). */
static inline int region_slots(__global REAL *hist, const int slots, const int hw,
                               const struct rg_contact *c, const int nc, int *c2r)
{
    int ncont = (int)hist[0];
    __global REAL *walls = hist + 1, *sh = hist + 1 + slots;
    if (nc == 0) {
        hist[0] = 0;
        return 0;
    }
    if (nc == 1 && ncont == 0) {
        c2r[0] = 0;
        ncont = 1;
        walls[0] = (REAL)c[0].iwall;
        for (int q = 0; q < hw; q++)
            sh[q] = 0;
    } else if (nc == 1 && ncont == 1 && (int)walls[0] == c[0].iwall) {
        c2r[0] = 0;
    } else {
        int iold = 0;
        while (iold < ncont) {
            int m = 0;
            while (m < nc && c[m].iwall != (int)walls[iold])
                m++;
            if (m >= nc) {
                const int last = ncont - 1;
                for (int q = 0; q < hw; q++)
                    sh[hw * iold + q] = sh[hw * last + q];
                walls[iold] = walls[last];
                ncont--;
            } else
                iold++;
        }
        const int nold = ncont;
        for (int inew = 0; inew < nc; inew++) {
            int m = 0;
            while (m < nold && (int)walls[m] != c[inew].iwall)
                m++;
            if (m < nold)
                c2r[m] = inew;
            else {
                c2r[ncont] = inew;
                for (int q = 0; q < hw; q++)
                    sh[hw * ncont + q] = 0;
                walls[ncont] = (REAL)c[inew].iwall;
                ncont++;
            }
        }
    }
    hist[0] = (REAL)ncont;
    return 1;
}

/* Region walls (fix wall/gran/region): one work-item per atom, the set's
 * nwall walls in turn (RS_* of kernels/wall_layout.h: the walls of one law
 * whose post_force calls follow each other, src/contact/wall_region.c), each
 * as its own launch would be: an atom out of the wall's group or not
 * matched by its region is skipped, its history kept; otherwise its
 * contacts (region_surface) run through the law's contact body in region
 * order, each with its slot (region_slots; per atom 1 + (1 + hw) slots
 * REAL, hw the wall's history width), the forces summed onto f and each
 * wall's torque sum added to torque, in wall order (the sums of separate
 * launches, bit for bit). A wall's surface moves with the velocity of the
 * contact's node when RS_DYNAMIC (0: at rest; the host gives 0 for union /
 * intersect, as LAMMPS 2021). BODY: a CONTACT_BODY instance; ROW its form.
 * JKR 1 (a jkr wall, kernels/wall.cl WALL_REACH): the region is searched to
 * the reach, and a contact beyond touch not touched yet is skipped with the
 * history of slot 0 zeroed, as LAMMPS 2021 FixWallGranRegion does.
 * Arguments: KARGS_region_kernel (kernels/kernel_args.h). */
#define RS_PICK(a, w) ((w) == 0 ? a##0 : (w) == 1 ? a##1 : (w) == 2 ? a##2 : a##3)
#define REGION_KERNEL(NAME, BODY, ROW, JKR)                                                    \
    __kernel void NAME(KA_KERNEL(region_kernel))                                               \
    {                                                                                          \
        KA_UNPACK(region_kernel);                                                              \
        const int i = get_global_id(0);                                                        \
        if (i >= n)                                                                            \
            return;                                                                            \
        const REAL3 xi = vload3(i, x) + POS_LOAD_LO(i);                                        \
        const REAL radi = radius[i];                                                           \
        REAL3 fsum = vload3(i, f);                                                             \
        struct contact_atoms a =                                                               \
            contact_atoms_of(v, omega, rmass, dt, shearupdate, acc, astep, step);              \
        for (int w = 0; w < nwall; w++) {                                                      \
            __global const REAL *ws = set + w * RS_HEAD;                                       \
            const int want_contacts = ws[RS_CONTACTS] != 0, wheat = ws[RS_WHEAT] != 0;         \
            const REAL twall = ws[RS_TWALL];                                                   \
            __global REAL *contacts = RS_PICK(contacts, w);                                    \
            WALL_CONTACT_CLEAR(i);                                                             \
            if (!(mask[i] & (uint)ws[RS_GROUPBIT]))                                            \
                continue;                                                                      \
            __global const REAL *nodes = set + RS_NODES(w);                                    \
            const int nnode = ws[RS_NNODE], comb = ws[RS_COMB], rinterior = ws[RS_INTERIOR];   \
            const REAL3 xf = region_frame(nodes, comb, xi);                                    \
            if (!region_match(nodes, nnode, comb, rinterior, xi, xf))                          \
                continue;                                                                      \
            const int hw = ws[RS_HW], slots = ws[RS_SLOTS]; /* history REAL per slot */        \
            __global const REAL *p = wall_param(RS_PICK(param, w), ws[RS_BYTYPE], type[i] - 1, \
                                                ntypes, ws[RS_NPARAM]);                        \
            struct rg_contact c[RG_MAXC];                                                      \
            int nc = region_surface(nodes, nnode, comb, rinterior, xi, xf,                     \
                                    WALL_REACH(JKR, p, radi), c);                              \
            if (nc > slots)                                                                    \
                nc = slots;                                                                    \
            __global REAL *hist = RS_PICK(hist, w);                                            \
            if (hw)                                                                            \
                hist += (size_t)i * (1 + (1 + hw) * slots);                                    \
            int c2r[RG_MAXC];                                                                  \
            for (int k = 0; k < RG_MAXC; k++)                                                  \
                c2r[k] = k;                                                                    \
            if (hw && !region_slots(hist, slots, hw, c, nc, c2r))                              \
                continue;                                                                      \
            WALL_HEAT_BEGIN(a);                                                                \
            struct contact_site s = wall_site(i, radi, radi, hw, ws[RS_ACODE]);                \
            s.gated = 1; /* region_surface decided */                                          \
            s.refine = 0;                                                                      \
            s.hold = WALL_HOLD(JKR, p);                                                        \
            struct contact_partner pj;                                                         \
            pj.omwall = (REAL3)(0);                                                            \
            WALL_HEAT_PARTNER(pj);                                                             \
            REAL3 tsum = (REAL3)(0);                                                           \
            for (int ic = 0; ic < nc; ic++) {                                                  \
                __global REAL *hs = hw ? hist + 1 + slots + hw * c2r[ic] : hist;               \
                s.del = c[ic].del;                                                             \
                s.rwall = c[ic].radius;                                                        \
                s.rgiven = c[ic].r;                                                            \
                pj.vwall = ws[RS_DYNAMIC] != 0                                                 \
                               ? region_velocity(nodes + c[ic].node * RG_NODE, xi - s.del)     \
                               : (REAL3)(0);                                                   \
                REAL h[WALL_ROW_N(ROW)];                                                       \
                contact_hist_load(h, hs, hw, WALL_ROW_N(ROW));                                 \
                struct contact_out o;                                                          \
                if (!BODY(CONTACT_WALL, i, &s, &pj, &a, p, h, &o)) {                           \
                    contact_hist_store(hist + 1 + slots, h, hw, 0); /* LAMMPS 2021: slot 0 */  \
                    continue;                                                                  \
                }                                                                              \
                contact_hist_store(hs, h, hw, 1);                                              \
                fsum += o.f;                                                                   \
                tsum += o.ti;                                                                  \
                WALL_HEAT_ADD(o);                                                              \
                WALL_CONTACT_PUT(i, o.f, xi - s.del, radi);                                    \
            }                                                                                  \
            WALL_ADD_TORQUE(torque, i, tsum);                                                  \
            WALL_HEAT_STORE(i);                                                                \
        }                                                                                      \
        vstore3(fsum, i, f);                                                                   \
    }

/* The contacts REGION_KERNEL finds for each atom, written out for the host
 * (fix granular/mdr's walls, styles/fix/fix_granular_mdr.c): per atom
 * RG_PROBE_W REAL, the count nc (0 for an atom out of the group or not
 * matched), then per contact r, del and iwall; the reach is the radius, at
 * most `slots` contacts (as REGION_KERNEL for a law held only in touch). */
__kernel void region_probe(KA_KERNEL(region_probe))
{
    KA_UNPACK(region_probe);
    const int i = get_global_id(0);
    if (i >= n)
        return;
    __global REAL *o = out + (size_t)i * RG_PROBE_W;
    o[0] = 0;
    if (!(mask[i] & groupbit))
        return;
    const REAL3 xi = vload3(i, x) + POS_LOAD_LO(i);
    const REAL3 xf = region_frame(nodes, comb, xi);
    if (!region_match(nodes, nnode, comb, rinterior, xi, xf))
        return;
    struct rg_contact c[RG_MAXC];
    int nc = region_surface(nodes, nnode, comb, rinterior, xi, xf, radius[i], c);
    if (nc > slots)
        nc = slots;
    o[0] = (REAL)nc;
    for (int k = 0; k < nc; k++) {
        __global REAL *q = o + 1 + RG_PROBE_C * k;
        q[0] = c[k].r;
        q[1] = c[k].del.x;
        q[2] = c[k].del.y;
        q[3] = c[k].del.z;
        q[4] = (REAL)c[k].iwall;
    }
}
