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
 * per atom, zeroed while the element does not touch the particle. Each
 * contact also updates the particle's accuracy record (acc, astep; wall
 * code acode; kernels/accuracy.cl).
 *
 * Kinds (WALL_*, src/wall.h):
 *   plane pair   elements lo face (0) and hi face (1) normal to `axis`; as in
 *                LAMMPS fix wall/gran only the nearer face acts:
 *                del = (x_a - lo) e_a, or -(hi - x_a) e_a
 *   zcylinder    element 0, axis z through x = y = 0 (lo, hi: the axis
 *                relative to the device origin), radius R:
 *                del = -(R - |x_xy|) x_xy / |x_xy|, rwall = -2R inside,
 *                +2R outside; with azimuthal shear the surface moves at
 *                vshear (y, -x) / |x_xy|
 *   triangle     mesh walls (MESH_KERNEL below): the elements are the
 *                triangles of a fix mesh/surface, binned in the mesh's own
 *                frame, history in slots keyed by triangle id
 *   region       region surfaces (kernels/wall_region.cl REGION_KERNEL): the
 *                contacts of a LAMMPS region, history slots keyed by wall id */

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
static inline int wall_point(const struct wall_geom *w, const int e, const REAL3 xp,
                             const REAL radi, REAL3 *del, REAL *rwall, REAL3 *vwall)
{
    *vwall = w->v;
    *rwall = 0;
    if (w->kind == WALL_PLANE) {
        const REAL xa = w->axis == 0 ? xp.x : w->axis == 1 ? xp.y : xp.z;
        const REAL del1 = xa - w->lo, del2 = w->hi - xa;
        const int nearer = del1 < del2 ? 0 : 1;
        if (e != nearer)
            return 0;
        const REAL d = nearer == 0 ? del1 : -del2;
        *del = (REAL3)(w->axis == 0 ? d : 0, w->axis == 1 ? d : 0, w->axis == 2 ? d : 0);
        return 1;
    }
    /* WALL_ZCYLINDER: the axis at (lo, hi) (0, 0 but for the device origin) */
    const REAL3 x = (REAL3)(xp.x - w->lo, xp.y - w->hi, xp.z);
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

/* The low part of the gap del of the sphere's hi part (SPLIT_POS): the normal
 * component of the position's low part xl, so a flat or curved wall sees the
 * particle's 48-bit position (contact_refine); tangential parts do not
 * change the gap. */
static inline REAL3 wall_gap_lo(const REAL3 del, const REAL3 xl)
{
    const REAL dd = dot(del, del);
    return dd > (REAL)0 ? (dot(xl, del) / dd) * del : (REAL3)(0);
}

/* One work-item per atom of the group: every element of the wall is a
 * contact source evaluated through EVAL; forces and torques are added to f
 * and torque in element order. The parameters are one packed set (by_type
 * 0) or the pair style's set of type pair (t_i, t_i). inclusive: a contact
 * at exactly |del| = radi counts (LAMMPS fix wall/gran); else it does not
 * (the pair contract of fix wall/pair). */
/* The arguments every wall kernel starts with, in the order src/wall.c
 * (wall_bind_atoms) binds them: the atoms of the group, the wall's history
 * and the accuracy records (kernels/accuracy.cl). */
#define WALL_ATOM_ARGS                                                                         \
    const int n, const uint groupbit, __global const uint *mask, __global const REAL *x,       \
        __global const REAL *v, __global const REAL *omega, __global const REAL *radius,       \
        __global const REAL *rmass, __global const int *type, __global REAL *f,                \
        __global REAL *torque, __global REAL *history, const int has_history,                  \
        __global REAL *acc, __global int *astep, const int acode, const int step

#define WALL_KERNEL(NAME, EVAL) WALL_KERNEL_HW(NAME, EVAL, 0, 0, 0)
#define WALL_KERNEL_ROW(NAME, EVAL) WALL_KERNEL_HW(NAME, EVAL, 1, 0, 0)
/* APPROACH 1: EVAL also takes planes the sphere is apart from that one
 * drift at its normal rate brings into or out of contact (c.approach set;
 * pair_style approach, linear/restitution with fix wall/pair, which has no
 * cylinder: a cylinder acts only on spheres it touches). JKR 1: a jkr wall
 * (kernels/fix_wall_gran.cl WALL_JKR_1): the contact reaches to WALL_REACH
 * beyond touch and is held there only once it has touched (the touch flag of
 * its history row); 0 folds either away. */
#define WALL_KERNEL_HW(NAME, EVAL, ROW, APPROACH, JKR)                                         \
    __kernel void NAME(                                                                        \
        WALL_ATOM_ARGS,                                                                        \
        __global const REAL *param, const int ntypes, const int nparam, const int by_type,     \
        const int nelem, const int kind, const int axis, const REAL lo, const REAL hi,         \
        const REAL wradius, const REAL vwx, const REAL vwy, const REAL vwz,                    \
        const int cyl_shear, const REAL vshear, const REAL dt, const int shearupdate,          \
        const int inclusive POS_LO_PARAM)                                                      \
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
        const REAL3 xi = vload3(i, x), xil = POS_LOAD_LO(i);                                   \
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
            WALL_GAP_LO(del_lo, del, xil);                                                     \
            const REAL3 dtest = del + del_lo;                                                  \
            const REAL rsq = dtest.x * dtest.x + dtest.y * dtest.y + dtest.z * dtest.z;        \
            struct contact c;                                                                  \
            const REAL reach = WALL_REACH(JKR, p, radi);                                       \
            int touch = acts && (inclusive ? rsq <= reach * reach : rsq < reach * reach);      \
            __global REAL *hrow = history + slot * (size_t)has_history;                        \
            if (JKR && touch && !WALL_TOUCHED(JKR, p, hrow) && rsq > radi * radi)              \
                touch = 0; /* not touched yet: no hold beyond touch */                         \
            const int near_ = APPROACH && acts && !touch &&                                    \
                              wall_within_drift(vload3(i, v) - vwall, dtest, rsq, radi, dt);   \
            if (touch || near_) {                                                              \
                WALL_OMEGA(omi, omega, i);                                                     \
                c = contact_make(del, radi, 0,                                                 \
                                 rwall == (REAL)0 ? radi : radi * rwall / (rwall + radi),      \
                                 vload3(i, v) - vwall, omi, (REAL3)(0), rmass[i]);             \
                touch = contact_refine(&c, del_lo) || APPROACH || JKR;                         \
                c.approach = APPROACH;                                                         \
            }                                                                                  \
            if (!touch) {                                                                      \
                for (int q = 0; q < has_history; q++)                                          \
                    hrow[q] = 0;                                                               \
                continue;                                                                      \
            }                                                                                  \
            c.dt = dt;                                                                         \
            c.shearupdate = shearupdate;                                                       \
            struct contact_force cf;                                                           \
            WALL_CALL(ROW, EVAL, &c, p, hrow, has_history, &cf);                               \
            if (!APPROACH || c.delta > (REAL)0)                                                \
                ACC_NOTE_WALL(EVAL, i, &c, p, acode, acc, astep, step);                        \
            fsum += cf.f;                                                                      \
            tsum += contact_torque_i(&c, &cf);                                                 \
        }                                                                                      \
        vstore3(fsum, i, f);                                                                   \
        WALL_ADD_TORQUE(torque, i, tsum);                                                      \
    }

/* |normal rate| dt > gap for a sphere apart from its wall element (the gap
 * |dtest| - radi > 0): pair_within_drift's test */
static inline int wall_within_drift(const REAL3 vrel, const REAL3 dtest, const REAL rsq,
                                    const REAL radi, const REAL dt)
{
    const REAL r = sqrt(rsq);
    return fabs(dot(vrel, dtest)) * dt > r * (r - radi);
}
/* The reach of a wall contact (radi; a jkr wall's: WALL_REACH_1) and the
 * touch flag of its history row (WALL_TOUCHED_1), both defined where a jkr
 * kernel is instantiated (kernels/fix_wall_gran.cl). */
#define WALL_REACH(JKR, p, radi) WALL_REACH_PASTE(JKR)(p, radi)
#define WALL_REACH_PASTE(JKR) WALL_REACH_##JKR
#define WALL_REACH_0(p, radi) (radi)
#define WALL_TOUCHED(JKR, p, hrow) WALL_TOUCHED_PASTE(JKR)(p, hrow)
#define WALL_TOUCHED_PASTE(JKR) WALL_TOUCHED_##JKR
#define WALL_TOUCHED_0(p, hrow) 1

/* One evaluation with the contact's history row hrow of hw REAL (0: none):
 * ROW 0 an evaluator of a 3-REAL shear (REAL3 *), ROW 1 one of the whole
 * row (REAL *, up to WALL_HMAX, pair granular's sub-models). */
#define WALL_HMAX 10
#define WALL_CALL(ROW, EVAL, c, p, hrow, hw, cf) WALL_CALL_PASTE(ROW)(EVAL, c, p, hrow, hw, cf)
#define WALL_CALL_PASTE(ROW) WALL_CALL_##ROW
#define WALL_CALL_0(EVAL, c, p, hrow, hw, cf)                                                  \
    do {                                                                                       \
        REAL3 sh_ = (hw) ? vload3(0, hrow) : (REAL3)(0);                                       \
        EVAL(c, p, &sh_, cf);                                                                  \
        if (hw)                                                                                \
            vstore3(sh_, 0, hrow);                                                             \
    } while (0)
#define WALL_CALL_1(EVAL, c, p, hrow, hw, cf)                                                  \
    do {                                                                                       \
        REAL h_[WALL_HMAX];                                                                    \
        for (int q_ = 0; q_ < WALL_HMAX; q_++)                                                 \
            h_[q_] = q_ < (hw) ? (hrow)[q_] : (REAL)0;                                         \
        EVAL(c, p, h_, cf);                                                                    \
        for (int q_ = 0; q_ < (hw); q_++)                                                      \
            (hrow)[q_] = h_[q_];                                                               \
    } while (0)

#ifdef SPLIT_POS
#define WALL_GAP_LO(name, del, xl) const REAL3 name = wall_gap_lo(del, xl)
#else
#define WALL_GAP_LO(name, del, xl) const REAL3 name = (REAL3)(0)
#endif
#ifdef HAS_ROTATION
#define WALL_OMEGA(name, omega, i) const REAL3 name = vload3(i, omega)
#define WALL_ADD_TORQUE(torque, i, t) vstore3(vload3(i, torque) + (t), i, torque)
#else
#define WALL_OMEGA(name, omega, i) const REAL3 name = (REAL3)(0)
#define WALL_ADD_TORQUE(torque, i, t) (void)(t)
#endif

/* fix wall/pair: the active pair style's law */
#ifdef PAIR_EVAL
#ifdef PAIR_APPROACH
WALL_KERNEL_HW(wall_pair, PAIR_EVAL, 0, 1, 0)
#else
WALL_KERNEL(wall_pair, PAIR_EVAL)
#endif
#endif

/* ---- mesh walls: triangles (fix mesh/surface, fix wall/gran ... mesh) ------
 *
 * Geometry kind "triangle": the closest point of a triangle (a, b, c) to x,
 * by Voronoi region (Ericson, Real-Time Collision Detection 5.1.5): face,
 * edge k (vertices k, k+1 mod 3) or vertex k. Face contacts use the stored
 * unit normal, del = ((x - a).n) n, so an axis-aligned triangle gives the
 * very numbers of a plane wall. Region codes: 0 face, 1+k edge k, 4+k
 * vertex k. The surface is flat for the contact law (rwall = 0). */
#define MESH_FACE 0
#define MESH_EDGE 1
#define MESH_VERTEX 4

static inline int tri_closest(__global const REAL *tri, const int t, const REAL3 p, REAL3 *del)
{
    const REAL3 a = vload3(4 * t, tri), b = vload3(4 * t + 1, tri), c = vload3(4 * t + 2, tri);
    const REAL3 ab = b - a, ac = c - a, ap = p - a;
    const REAL d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) {
        *del = ap;
        return MESH_VERTEX + 0;
    }
    const REAL3 bp = p - b;
    const REAL d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) {
        *del = bp;
        return MESH_VERTEX + 1;
    }
    const REAL vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const REAL s = d1 / (d1 - d3);
        *del = p - (a + s * ab);
        return MESH_EDGE + 0;
    }
    const REAL3 cp = p - c;
    const REAL d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) {
        *del = cp;
        return MESH_VERTEX + 2;
    }
    const REAL vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const REAL s = d2 / (d2 - d6);
        *del = p - (a + s * ac);
        return MESH_EDGE + 2;
    }
    const REAL va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const REAL s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        *del = p - (b + s * (c - b));
        return MESH_EDGE + 1;
    }
    const REAL3 n = vload3(4 * t + 3, tri);
    const REAL h = ap.x * n.x + ap.y * n.y + ap.z * n.z;
    *del = (REAL3)(h * n.x, h * n.y, h * n.z);
    return MESH_FACE;
}

/* 1 when triangle t has welded vertex v */
static inline int tri_has(__global const int *triv, const int t, const int v)
{
    return triv[3 * t] == v || triv[3 * t + 1] == v || triv[3 * t + 2] == v;
}

/* 1 when triangles s and t share a welded vertex */
static inline int tri_touch(__global const int *triv, const int s, const int t)
{
    return tri_has(triv, t, triv[3 * s]) || tri_has(triv, t, triv[3 * s + 1]) ||
           tri_has(triv, t, triv[3 * s + 2]);
}

#define MESH_MAXC 16   /* touching triangles examined per atom per mesh */
#define MESH_SLOTS 4   /* history slots per atom per mesh: key (triangle + 1, 0 = free), shear */

static inline REAL3 mat_mul(__global const REAL *R, const REAL3 v)
{
    return (REAL3)(R[0] * v.x + R[1] * v.y + R[2] * v.z, R[3] * v.x + R[4] * v.y + R[5] * v.z,
                   R[6] * v.x + R[7] * v.y + R[8] * v.z);
}

static inline REAL3 mat_tmul(__global const REAL *R, const REAL3 v)
{
    return (REAL3)(R[0] * v.x + R[3] * v.y + R[6] * v.z, R[1] * v.x + R[4] * v.y + R[7] * v.z,
                   R[2] * v.x + R[5] * v.y + R[8] * v.z);
}

/* The parameter set of a mesh contact: one packed set (wall/gran), or
 * the pair style's set of type pair (t_i, T - 1) for a mesh of type T
 * (wall/pair: by_type = T). */
static inline __global const REAL *p_of(__global const REAL *param, const int by_type,
                                        const int ti, const int ntypes, const int nparam)
{
    return by_type ? param + (size_t)(ti * ntypes + (by_type - 1)) * nparam : param;
}

/* wall_within_drift for a triangle: del (mesh frame) from its closest
 * point, the surface velocity of a moving mesh taken there */
static inline int mesh_within_drift(__global const REAL *pose, const int moving, const REAL3 xi,
                                    const REAL3 vi, const REAL3 del, const REAL rsq,
                                    const REAL radi, const REAL dt)
{
    REAL3 vb = vi;
    if (moving) {
        const REAL3 dw = mat_mul(pose, del);
        vb = mat_tmul(pose, vi - (vload3(4, pose) + cross(vload3(5, pose), xi - dw)));
    }
    return wall_within_drift(vb, del, rsq, radi, dt);
}

/* One work-item per atom of the group, one launch per mesh. The mesh is
 * rigid: its triangles and their bins stay in the mesh's own frame and the
 * atom is taken there, xb = R^T (x - d) (pose: R row-major 0..8, d 9..11,
 * surface velocity V0 12..14 and omega 15..17 with v(p) = V0 + omega x p,
 * bin origin 18..20, 1 / bin size 21, torque reference point 22..24). The
 * atom's bin lists every triangle that may touch it, so the cost grows with
 * the triangles near the atom, not with the mesh size.
 *
 * One physical contact is counted once: a face contact always counts; an
 * edge or vertex contact is dropped when another touching triangle that has
 * a vertex of that edge or vertex is closer (ties: the lower triangle id
 * keeps it), i.e. the contact belongs to the nearest feature. History lives
 * in MESH_SLOTS slots per atom keyed by triangle (1 + hw REAL each: the key,
 * then the law's hw = 3 REAL of shear, or for ROW 1 the has_history REAL of
 * pair granular's sub-models, kernels/fix_wall_gran.cl); a contact whose triangle
 * has no slot takes over the slot of a triangle that no longer counts and
 * shares a vertex with it, so the shear follows a particle sliding from
 * triangle to triangle. fmesh (want_fmesh): per atom the force on the mesh
 * (3) and its torque about the reference point (3), for f_ID output. */
#define MESH_KERNEL(NAME, EVAL) MESH_KERNEL_HW(NAME, EVAL, 0, 0)
#define MESH_KERNEL_ROW(NAME, EVAL) MESH_KERNEL_HW(NAME, EVAL, 1, 0)
/* APPROACH 1: triangles the sphere is apart from that one drift at its
 * normal rate brings into or out of contact count too (as WALL_KERNEL_HW;
 * fix mesh/surface then bins the triangles with the neighbor skin added) */
#define MESH_KERNEL_HW(NAME, EVAL, ROW, APPROACH)                                              \
    __kernel void NAME(                                                                        \
        WALL_ATOM_ARGS,                                                                        \
        const int hstride, const int hoff, __global const REAL *param, const int ntypes,       \
        const int nparam, const int by_type, __global const REAL *tri,                         \
        __global const int *triv, __global const int *cstart, __global const int *ctri,        \
        __global const REAL *pose, const int gnx, const int gny, const int gnz,                \
        const int moving, __global REAL *fmesh, const int want_fmesh, const REAL dt,           \
        const int shearupdate, const int inclusive POS_LO_PARAM)                               \
    {                                                                                          \
        const int i = get_global_id(0);                                                        \
        if (i >= n)                                                                            \
            return;                                                                            \
        if (!(mask[i] & groupbit)) {                                                           \
            if (want_fmesh) {                                                                  \
                vstore3((REAL3)(0), 2 * i, fmesh);                                             \
                vstore3((REAL3)(0), 2 * i + 1, fmesh);                                         \
            }                                                                                  \
            return;                                                                            \
        }                                                                                      \
        const REAL3 xi = vload3(i, x) + POS_LOAD_LO(i);                                        \
        const REAL radi = radius[i];                                                           \
        const REAL3 xb = moving ? mat_tmul(pose, xi - vload3(3, pose)) : xi;                   \
        int tc[MESH_MAXC], rc[MESH_MAXC], nc = 0;                                              \
        REAL3 dc[MESH_MAXC];                                                                   \
        REAL qc[MESH_MAXC];                                                                    \
        const REAL ginv = pose[21];                                                            \
        const int cx = (int)floor((xb.x - pose[18]) * ginv);                                   \
        const int cy = (int)floor((xb.y - pose[19]) * ginv);                                   \
        const int cz = (int)floor((xb.z - pose[20]) * ginv);                                   \
        if (cx >= 0 && cy >= 0 && cz >= 0 && cx < gnx && cy < gny && cz < gnz) {              \
            const int cell = (cz * gny + cy) * gnx + cx;                                       \
            for (int k = cstart[cell]; k < cstart[cell + 1] && nc < MESH_MAXC; k++) {          \
                const int t = ctri[k];                                                         \
                REAL3 del;                                                                     \
                const int region = tri_closest(tri, t, xb, &del);                              \
                const REAL rsq = del.x * del.x + del.y * del.y + del.z * del.z;                \
                if ((inclusive ? rsq > radi * radi : rsq >= radi * radi) &&                    \
                    !(APPROACH && mesh_within_drift(pose, moving, xi, vload3(i, v), del, rsq,  \
                                                    radi, dt)))                                \
                    continue;                                                                  \
                tc[nc] = t;                                                                    \
                rc[nc] = region;                                                               \
                dc[nc] = del;                                                                  \
                qc[nc] = rsq;                                                                  \
                nc++;                                                                          \
            }                                                                                  \
        }                                                                                      \
        /* one contact per physical contact: drop edge/vertex contacts of a nearer feature */ \
        for (int c = 0; c < nc; c++) {                                                         \
            if (rc[c] == MESH_FACE)                                                            \
                continue;                                                                      \
            const int k = rc[c] >= MESH_VERTEX ? rc[c] - MESH_VERTEX : rc[c] - MESH_EDGE;      \
            const int va = triv[3 * tc[c] + k];                                                \
            const int vb = rc[c] >= MESH_VERTEX ? va : triv[3 * tc[c] + (k + 1) % 3];          \
            for (int o = 0; o < nc; o++) {                                                     \
                if (o == c) /* dropped ones count too: the nearest of a cluster stays */       \
                    continue;                                                                  \
                if (!tri_has(triv, tc[o], va) && !tri_has(triv, tc[o], vb))                    \
                    continue;                                                                  \
                if (qc[o] < qc[c] || (qc[o] == qc[c] && tc[o] < tc[c])) {                      \
                    rc[c] = -1 - rc[c]; /* dropped */                                          \
                    break;                                                                     \
                }                                                                              \
            }                                                                                  \
        }                                                                                      \
        const int hw = ROW ? has_history : 3; /* history REAL per slot (after its key) */     \
        REAL okey[MESH_SLOTS];                                                                 \
        REAL osh[MESH_SLOTS][MESH_HMAX(ROW)];                                                  \
        __global REAL *hist = has_history ? history + (size_t)i * hstride + hoff : history;     \
        if (has_history)                                                                       \
            for (int s = 0; s < MESH_SLOTS; s++) {                                             \
                okey[s] = hist[(1 + hw) * s];                                                  \
                for (int q = 0; q < hw; q++)                                                   \
                    osh[s][q] = hist[(1 + hw) * s + 1 + q];                                    \
            }                                                                                  \
        REAL nkey[MESH_SLOTS];                                                                 \
        REAL nsh[MESH_SLOTS][MESH_HMAX(ROW)];                                                  \
        int nnew = 0;                                                                          \
        REAL3 fsum = vload3(i, f), tsum = (REAL3)(0), fm = (REAL3)(0), tm = (REAL3)(0);         \
        const REAL3 rref = (REAL3)(pose[22], pose[23], pose[24]);                              \
        for (int c = 0; c < nc; c++) {                                                         \
            if (rc[c] < 0)                                                                     \
                continue;                                                                      \
            const int t = tc[c];                                                               \
            const REAL3 del = moving ? mat_mul(pose, dc[c]) : dc[c];                           \
            const REAL3 cpt = xi - del;                                                        \
            REAL3 vwall = (REAL3)(0);                                                          \
            if (moving)                                                                        \
                vwall = vload3(4, pose) + cross(vload3(5, pose), cpt);                         \
            REAL sh[MESH_HMAX(ROW)];                                                           \
            for (int q = 0; q < MESH_HMAX(ROW); q++)                                           \
                sh[q] = 0;                                                                     \
            if (has_history) {                                                                 \
                int found = -1;                                                                \
                for (int s = 0; s < MESH_SLOTS; s++)                                           \
                    if (okey[s] == (REAL)(t + 1))                                              \
                        found = s;                                                             \
                for (int s = 0; found < 0 && s < MESH_SLOTS; s++) {                            \
                    if (okey[s] <= 0)                                                          \
                        continue;                                                              \
                    const int ot = (int)okey[s] - 1;                                           \
                    int live = 0;                                                              \
                    for (int o = 0; o < nc; o++)                                               \
                        live |= rc[o] >= 0 && tc[o] == ot;                                     \
                    if (!live && tri_touch(triv, ot, t))                                       \
                        found = s;                                                             \
                }                                                                              \
                if (found >= 0) {                                                              \
                    for (int q = 0; q < hw; q++)                                               \
                        sh[q] = osh[found][q];                                                 \
                    okey[found] = 0; /* taken */                                               \
                }                                                                              \
            }                                                                                  \
            WALL_OMEGA(omi, omega, i);                                                         \
            struct contact ct = contact_make(del, radi, 0, radi, vload3(i, v) - vwall, omi,    \
                                             moving ? vload3(5, pose) : (REAL3)(0), rmass[i]); \
            ct.approach = APPROACH;                                                            \
            ct.dt = dt;                                                                        \
            ct.shearupdate = shearupdate;                                                      \
            struct contact_force cf;                                                           \
            __global const REAL *pc = p_of(param, by_type, type[i] - 1, ntypes, nparam);       \
            MESH_EVAL(ROW, EVAL, &ct, pc, sh, &cf);                                            \
            if (!APPROACH || ct.delta > (REAL)0)                                               \
                ACC_NOTE_WALL(EVAL, i, &ct, pc, acode, acc, astep, step);                      \
            if (has_history && nnew < MESH_SLOTS) {                                            \
                nkey[nnew] = (REAL)(t + 1);                                                    \
                for (int q = 0; q < hw; q++)                                                   \
                    nsh[nnew][q] = sh[q];                                                      \
                nnew++;                                                                        \
            }                                                                                  \
            fsum += cf.f;                                                                      \
            tsum += contact_torque_i(&ct, &cf);                                              \
            fm -= cf.f;                                                                        \
            tm -= cross(cpt - rref, cf.f);                                                     \
        }                                                                                      \
        if (has_history)                                                                       \
            for (int s = 0; s < MESH_SLOTS; s++) {                                             \
                const int used = s < nnew;                                                     \
                hist[(1 + hw) * s] = used ? nkey[s] : (REAL)0;                                 \
                for (int q = 0; q < hw; q++)                                                   \
                    hist[(1 + hw) * s + 1 + q] = used ? nsh[s][q] : (REAL)0;                   \
            }                                                                                  \
        vstore3(fsum, i, f);                                                                   \
        WALL_ADD_TORQUE(torque, i, tsum);                                                      \
        if (want_fmesh) {                                                                      \
            vstore3(fm, 2 * i, fmesh);                                                         \
            vstore3(tm, 2 * i + 1, fmesh);                                                     \
        }                                                                                      \
    }


/* A mesh contact's evaluation with its history sh (MESH_HMAX(ROW) REAL): ROW 0
 * a 3-REAL shear evaluator (REAL3 *), ROW 1 one of the whole row (pair
 * granular's sub-models, the wall's width). */
#define MESH_HMAX(ROW) MESH_HMAX_PASTE(ROW)
#define MESH_HMAX_PASTE(ROW) MESH_HMAX_##ROW
#define MESH_HMAX_0 3
#define MESH_HMAX_1 WALL_HMAX
#define MESH_EVAL(ROW, EVAL, c, p, sh, cf) MESH_EVAL_PASTE(ROW)(EVAL, c, p, sh, cf)
#define MESH_EVAL_PASTE(ROW) MESH_EVAL_##ROW
#define MESH_EVAL_0(EVAL, c, p, sh, cf)                                                        \
    do {                                                                                       \
        REAL3 s3_ = (REAL3)((sh)[0], (sh)[1], (sh)[2]);                                        \
        EVAL(c, p, &s3_, cf);                                                                  \
        (sh)[0] = s3_.x;                                                                       \
        (sh)[1] = s3_.y;                                                                       \
        (sh)[2] = s3_.z;                                                                       \
    } while (0)
#define MESH_EVAL_1(EVAL, c, p, sh, cf) EVAL(c, p, sh, cf)

/* fix wall/pair ... mesh: the active pair style's law against triangles */
#ifdef PAIR_EVAL
#ifdef PAIR_APPROACH
MESH_KERNEL_HW(mesh_pair, PAIR_EVAL, 0, 1)
#else
MESH_KERNEL(mesh_pair, PAIR_EVAL)
#endif
#endif
