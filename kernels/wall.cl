/* wall.cl - the wall stage of the contact pipeline: walls as contact
 * sources (host side src/wall.c; front-ends fix wall/gran and wall/pair).
 *
 * A wall is a set of elements; a geometry kind is a small pure function
 * that answers, for element e and a sphere at x, whether e acts on it and
 * the closest point as del = x - p (from the wall to the particle), the
 * curvature radius rwall of the surface there (0 = flat, < 0 concave: the
 * inside of a cylinder) and the velocity of the surface at p. The contact
 * is then built by contact_make (common.cl), exactly as for two particles,
 * with the wall as partner j (radj = 0, omj = 0, meff = m_i) and
 *   reff = radi (flat) or radi rwall / (rwall + radi) (LAMMPS' choice).
 * Contact history is kept per (particle, wall element): 3 REAL per element
 * per atom, zeroed while the element does not touch the particle.
 *
 * Kinds (WALL_*, src/wall.h):
 *   plane pair   elements lo face (0) and hi face (1) normal to `axis`; as in
 *                LAMMPS fix wall/gran only the nearer face acts:
 *                del = (x_a - lo) e_a, or -(hi - x_a) e_a
 *   zcylinder    element 0, axis z through x = y = 0, radius R:
 *                del = -(R - |x_xy|) x_xy / |x_xy|, rwall = -2R inside,
 *                +2R outside; with azimuthal shear the surface moves at
 *                vshear (y, -x) / |x_xy|
 * Room for region surfaces and mesh triangles: a kind answers the same
 * question for its elements. */

#define WALL_PLANE 0
#define WALL_ZCYLINDER 1

struct wall_geom {
    int kind, axis;
    REAL lo, hi, radius;
    REAL3 v;                /* translational velocity of the surface */
    int cyl_shear;          /* zcylinder: azimuthal surface speed vshear */
    REAL vshear;
};

/* Closest point of element e to a sphere at x (radius radi): 1 when e may
 * touch it, with del, rwall and the surface velocity vwall filled. */
static inline int wall_point(const struct wall_geom *w, const int e, const REAL3 x,
                             const REAL radi, REAL3 *del, REAL *rwall, REAL3 *vwall)
{
    *vwall = w->v;
    *rwall = 0;
    if (w->kind == WALL_PLANE) {
        const REAL xa = w->axis == 0 ? x.x : w->axis == 1 ? x.y : x.z;
        const REAL del1 = xa - w->lo, del2 = w->hi - xa;
        const int nearer = del1 < del2 ? 0 : 1;
        if (e != nearer)
            return 0;
        const REAL d = nearer == 0 ? del1 : -del2;
        *del = (REAL3)(w->axis == 0 ? d : 0, w->axis == 1 ? d : 0, w->axis == 2 ? d : 0);
        return 1;
    }
    /* WALL_ZCYLINDER */
    const REAL delxy = sqrt(x.x * x.x + x.y * x.y);
    const REAL delr = w->radius - delxy;
    if (delr > radi)
        return 0;
    *del = (REAL3)(-delr / delxy * x.x, -delr / delxy * x.y, 0);
    *rwall = delxy < w->radius ? -2 * w->radius : 2 * w->radius;
    if (w->cyl_shear) {
        vwall->x += w->vshear * x.y / delxy;
        vwall->y += -w->vshear * x.x / delxy;
        vwall->z = 0;
    }
    return 1;
}

/* One work-item per atom of the group: every element of the wall is a
 * contact source evaluated through EVAL; forces and torques are added to f
 * and torque in element order. The parameters are one packed set (by_type
 * 0) or the pair style's set of type pair (t_i, t_i). inclusive: a contact
 * at exactly |del| = radi counts (LAMMPS fix wall/gran); else it does not
 * (the pair contract of fix wall/pair). */
#define WALL_KERNEL(NAME, EVAL)                                                                \
    __kernel void NAME(                                                                        \
        const int n, const uint groupbit, __global const uint *mask, __global const REAL *x,   \
        __global const REAL *v, __global const REAL *omega, __global const REAL *radius,       \
        __global const REAL *rmass, __global const int *type, __global REAL *f,                \
        __global REAL *torque, __global REAL *history, const int has_history,                  \
        __global const REAL *param, const int ntypes, const int nparam, const int by_type,     \
        const int nelem, const int kind, const int axis, const REAL lo, const REAL hi,         \
        const REAL wradius, const REAL vwx, const REAL vwy, const REAL vwz,                    \
        const int cyl_shear, const REAL vshear, const REAL dt, const int shearupdate,          \
        const int inclusive)                                                                   \
    {                                                                                          \
        const int i = get_global_id(0);                                                        \
        if (i >= n || !(mask[i] & groupbit))                                                   \
            return;                                                                            \
        struct wall_geom w;                                                                    \
        w.kind = kind;                                                                         \
        w.axis = axis;                                                                         \
        w.lo = lo;                                                                             \
        w.hi = hi;                                                                             \
        w.radius = wradius;                                                                    \
        w.v = (REAL3)(vwx, vwy, vwz);                                                          \
        w.cyl_shear = cyl_shear;                                                               \
        w.vshear = vshear;                                                                     \
        const REAL3 xi = vload3(i, x);                                                         \
        const REAL radi = radius[i];                                                           \
        const int ti = type[i] - 1;                                                            \
        __global const REAL *p =                                                               \
            by_type ? param + (size_t)(ti * ntypes + ti) * nparam : param;                     \
        REAL3 fsum = vload3(i, f), tsum = (REAL3)(0);                                          \
        for (int e = 0; e < nelem; e++) {                                                      \
            const size_t slot = (size_t)i * nelem + e;                                         \
            REAL3 del, vwall;                                                                  \
            REAL rwall;                                                                        \
            const int acts = wall_point(&w, e, xi, radi, &del, &rwall, &vwall);                \
            const REAL rsq = del.x * del.x + del.y * del.y + del.z * del.z;                    \
            if (!acts || (inclusive ? rsq > radi * radi : rsq >= radi * radi)) {               \
                if (has_history)                                                               \
                    vstore3((REAL3)(0), slot, history);                                        \
                continue;                                                                      \
            }                                                                                  \
            WALL_OMEGA(omi, omega, i);                                                         \
            struct contact c = contact_make(                                                   \
                del, radi, 0, rwall == (REAL)0 ? radi : radi * rwall / (rwall + radi),         \
                vload3(i, v) - vwall, omi, (REAL3)(0), rmass[i]);                              \
            c.dt = dt;                                                                         \
            c.shearupdate = shearupdate;                                                       \
            REAL3 sh = has_history ? vload3(slot, history) : (REAL3)(0);                       \
            struct contact_force cf;                                                           \
            EVAL(&c, p, &sh, &cf);                                                             \
            if (has_history)                                                                   \
                vstore3(sh, slot, history);                                                    \
            fsum += cf.f;                                                                      \
            tsum += contact_torque_i(&c, &cf);                                                 \
        }                                                                                      \
        vstore3(fsum, i, f);                                                                   \
        WALL_ADD_TORQUE(torque, i, tsum);                                                      \
    }

#ifdef HAS_ROTATION
#define WALL_OMEGA(name, omega, i) const REAL3 name = vload3(i, omega)
#define WALL_ADD_TORQUE(torque, i, t) vstore3(vload3(i, torque) + (t), i, torque)
#else
#define WALL_OMEGA(name, omega, i) const REAL3 name = (REAL3)(0)
#define WALL_ADD_TORQUE(torque, i, t) (void)(t)
#endif

/* fix wall/pair: the active pair style's law */
#ifdef PAIR_EVAL
WALL_KERNEL(wall_pair, PAIR_EVAL)
#endif
