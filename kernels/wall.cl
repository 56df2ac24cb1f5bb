/* wall.cl - the wall stage of the contact pipeline: walls as contact
 * sources (host side src/contact/wall.c; front-ends fix wall/gran and wall/pair).
 *
 * A wall is a set of elements; a geometry kind is a small pure function
 * that answers, for element e and a sphere at x, whether e acts on it and
 * the closest point as del = x - p (from the wall to the particle), the
 * curvature radius rwall of the surface there (0 = flat, < 0 concave: the
 * inside of a cylinder) and the velocity of the surface at p. The contact
 * is then evaluated by the one contact body (kernels/contact.cl), exactly as
 * for two particles, with the wall as partner j (radj = 0, omj = the wall's
 * angular velocity, meff = m_i, reff = wall_reff(radi, rwall)).
 * Contact history is kept per (particle, wall element): 3 REAL per element
 * per atom, zeroed while the element does not touch the particle. Each
 * contact also updates the particle's accuracy record (acc, astep; wall
 * code acode; kernels/accuracy.cl).
 *
 * Kinds (enum wall_kind, kernels/wall_layout.h):
 *   plane pair   elements lo face (0) and hi face (1) normal to `axis`; as in
 *                LAMMPS fix wall/gran only the nearer face acts:
 *                del = (x_a - lo) e_a, or -(hi - x_a) e_a
 *   cylinder     element 0, axis along `axis` a through (lo, hi) in the
 *                dimensions (a + 1, a + 2) mod 3 (relative to the device
 *                origin), radius R; r the particle's offset from the axis:
 *                del = -(R - |r|) r / |r|, rwall = -2R inside, +2R outside;
 *                sheared across its axis the surface moves at speed vshear
 *                (LAMMPS's zcylinder: vshear (y, -x) / |r|) or turns at
 *                vshear about it (LIGGGHTS: vshear e_a x r)
 *   triangle     mesh walls (MESH_KERNEL below): the elements are the
 *                triangles of a fix mesh/surface, binned in the mesh's own
 *                frame, history in slots keyed by triangle id
 *   region       region surfaces (kernels/wall_region.cl REGION_KERNEL): the
 *                contacts of a LAMMPS region, history slots keyed by wall id */


struct wall_geom {
    int kind, axis;
    REAL lo, hi, radius;
    REAL3 v;                /* translational velocity of the surface */
    int cyl_shear;          /* cylinder sheared across its axis: CYL_SHEAR_* */
    REAL vshear;
};

static inline struct wall_geom wall_geom_of(const int kind, const int axis, const REAL lo,
                                            const REAL hi, const REAL radius, const REAL vwx,
                                            const REAL vwy, const REAL vwz, const int cyl_shear,
                                            const REAL vshear)
{
    struct wall_geom w;
    w.kind = kind;
    w.axis = axis;
    w.lo = lo;
    w.hi = hi;
    w.radius = radius;
    w.v = (REAL3)(vwx, vwy, vwz);
    w.cyl_shear = cyl_shear;
    w.vshear = vshear;
    return w;
}

/* Component q of p, and the vector with s at component q (0 elsewhere). */
static inline REAL comp3(const REAL3 p, const int q) { return q == 0 ? p.x : q == 1 ? p.y : p.z; }
static inline REAL3 unit3(const int q, const REAL s)
{
    return (REAL3)(q == 0 ? s : 0, q == 1 ? s : 0, q == 2 ? s : 0);
}

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
    /* WALL_CYLINDER about axis a: its axis at (lo, hi) in the dimensions b =
     * a + 1, c = a + 2 (mod 3; LIGGGHTS's order: z through (x, y), x through
     * (y, z), y through (z, x)), relative to the device origin */
    const int a = w->axis, b = (a + 1) % 3, c = (a + 2) % 3;
    const REAL u = comp3(xp, b) - w->lo, v = comp3(xp, c) - w->hi;
    const REAL delxy = sqrt(u * u + v * v);
    const REAL delr = w->radius - delxy;
    if (delr > radi)
        return 0;
    *del = unit3(b, -delr / delxy * u) + unit3(c, -delr / delxy * v);
    *rwall = delxy < w->radius ? -2 * w->radius : 2 * w->radius;
    if (w->cyl_shear == CYL_SHEAR_SPEED) { /* LAMMPS: speed vshear, clockwise about a */
        *vwall += unit3(b, w->vshear * v / delxy) + unit3(c, -w->vshear * u / delxy);
        *vwall -= unit3(a, comp3(*vwall, a));
    } else if (w->cyl_shear == CYL_SHEAR_OMEGA) { /* LIGGGHTS: vshear e_a x (0, u, v) */
        *vwall = unit3(b, -w->vshear * v) + unit3(c, w->vshear * u);
    }
    return 1;
}

/* WALL_HMAX: kernels/wall_layout.h */
#define WALL_ROW_N(ROW) ((ROW) ? WALL_HMAX : 3)


/* The site of a wall contact of particle i (radius radi) before its
 * geometry is found: a refined, exclusive, noted contact that forgets hw
 * REAL of history when it does not act. */
static inline struct contact_site wall_site(const int i, const REAL radi, const REAL reach,
                                            const int hw, const int acode)
{
    struct contact_site s;
    s.del = s.del_lo = (REAL3)(0);
    s.radi = radi;
    s.radj = 0;
    s.rwall = 0;
    s.rgiven = -1;
    s.reach = reach;
    s.acts = 1;
    s.gated = 0;
    s.refine = 1;
    s.approach = 0;
    s.inclusive = 0;
    s.hold = -1;
    s.hzero = hw;
    s.note = 1;
    s.note_idx = i;
    s.acode = acode;
    return s;
}

/* A history row of hw REAL into the private row h of hmax (zero beyond hw) */
static inline void contact_hist_load(REAL *h, __global const REAL *row, const int hw,
                                     const int hmax)
{
    for (int q = 0; q < hmax; q++)
        h[q] = q < hw ? row[q] : (REAL)0;
}

/* The wall's parameter set for type t_i: one packed set (by_type 0), the
 * pair style's set of type pair (t_i, t_i) (by_type > 0), or the set of
 * (t_i, T - 1) of a table by type pair for a wall of type T (by_type = -T:
 * fix wall/gran model ... primitive type T). */
static inline __global const REAL *wall_param(__global const REAL *param, const int by_type,
                                              const int ti, const int ntypes, const int nparam)
{
    if (by_type < 0)
        return param + (size_t)(ti * ntypes + (-by_type - 1)) * nparam;
    return by_type ? param + (size_t)(ti * ntypes + ti) * nparam : param;
}

#ifdef HAS_ROTATION
#define WALL_ADD_TORQUE(torque, i, t) vstore3(vload3(i, torque) + (t), i, torque)
#else
#define WALL_ADD_TORQUE(torque, i, t) (void)(t)
#endif

/* Heat conduction through wall contacts (HAS_HEAT; LAMMPS fix wall/gran's
 * `heat` sub-model with `temperature T`): each contact's heat q into the
 * atom (the law's, kernels/gran_heat.cl, with the wall at twall) is summed
 * over the wall's elements in their order and added to the atom's heat
 * flow of the step, after the pair gather wrote it, when the wall conducts
 * (wheat: fix wall/gran with a heat model; never fix wall/pair, whose pair
 * law may carry one). Without HAS_HEAT the arguments are unused. */
#ifdef HAS_HEAT
#define WALL_HEAT_BEGIN(a)                                                                     \
    contact_atoms_heat(a, temp);                                                               \
    REAL qsum_ = 0
#define WALL_HEAT_PARTNER(pj) ((pj).twall = twall)
#define WALL_HEAT_ADD(o) (qsum_ += (o).q)
#define WALL_HEAT_STORE(i)                                                                     \
    if (wheat)                                                                                 \
    heatflow[i] += qsum_
#else
#define WALL_HEAT_BEGIN(a) (void)temp, (void)heatflow, (void)wheat, (void)twall
#define WALL_HEAT_PARTNER(pj) (void)0
#define WALL_HEAT_ADD(o) (void)0
#define WALL_HEAT_STORE(i) (void)0
#endif

/* The reach of a wall contact (radi; a jkr wall's: WALL_REACH_1) and the row
 * index of its touch flag (WALL_HOLD_1; -1: none), both defined where a jkr
 * kernel is instantiated (kernels/fix_wall_gran.cl). */
#define WALL_REACH(JKR, p, radi) WALL_REACH_PASTE(JKR)(p, radi)
#define WALL_REACH_PASTE(JKR) WALL_REACH_##JKR
#define WALL_REACH_0(p, radi) (radi)
#define WALL_HOLD(JKR, p) WALL_HOLD_PASTE(JKR)(p)
#define WALL_HOLD_PASTE(JKR) WALL_HOLD_##JKR
#define WALL_HOLD_0(p) (-1)

/* Plane and cylinder walls: one work-item per atom of the group; every
 * element of the wall is a contact site (wall_point) run through the law's
 * contact body; forces and torques are added to f and torque in element
 * order. History: has_history REAL per element per atom. inclusive: a
 * contact at exactly |del| = radi counts (LAMMPS fix wall/gran); else it
 * does not (the pair contract of fix wall/pair).
 * BODY: a CONTACT_BODY instance; ROW its form. APPROACH 1: also planes the
 * sphere is apart from that one drift at its normal rate brings into or out
 * of contact (pair_style approach, linear/restitution with fix wall/pair,
 * which has no cylinder: a cylinder acts only on spheres it touches). JKR 1:
 * a jkr wall: the contact reaches to WALL_REACH beyond touch and is held
 * there only once it has touched; 0 folds either away. Arguments:
 * KARGS_wall_kernel (kernels/kernel_args.h). */
/* fix wall/gran's `contacts` records (WALL_CONTACT_W, kernels/wall_layout.h):
 * cleared for every atom at each launch, the acting contact's written */
#define WALL_CONTACT_CLEAR(i)                                                                  \
    if (want_contacts)                                                                         \
        for (int q_ = 0; q_ < WALL_CONTACT_W; q_++)                                            \
            contacts[(size_t)(i) * WALL_CONTACT_W + q_] = 0;
#define WALL_CONTACT_PUT(i, F, XC, RAD)                                                        \
    if (want_contacts) {                                                                       \
        __global REAL *cr_ = contacts + (size_t)(i) * WALL_CONTACT_W;                          \
        const REAL3 xc_ = (XC);                                                                \
        cr_[0] = 1;                                                                            \
        vstore3((F), 0, cr_ + 1);                                                              \
        cr_[4] = xc_.x;                                                                        \
        cr_[5] = xc_.y;                                                                        \
        cr_[6] = xc_.z;                                                                        \
        cr_[7] = (RAD);                                                                        \
    }

#define WALL_KERNEL(NAME, BODY, ROW, APPROACH, JKR)                                            \
    __kernel void NAME(KA_KERNEL(wall_kernel))                                                 \
    {                                                                                          \
        KA_UNPACK(wall_kernel);                                                                \
        if (KA_HALTED())                                                                       \
            return;                                                                            \
        const int i = get_global_id(0);                                                        \
        if (i >= n)                                                                            \
            return;                                                                            \
        WALL_CONTACT_CLEAR(i);                                                                 \
        if (!(mask[i] & groupbit))                                                             \
            return;                                                                            \
        const struct wall_geom w = wall_geom_of(kind, axis, lo, hi, wradius, vwx, vwy, vwz,    \
                                                cyl_shear, vshear);                            \
        struct contact_atoms a =                                                               \
            contact_atoms_of(v, omega, rmass, dt, shearupdate, acc, astep, step);              \
        WALL_HEAT_BEGIN(a);                                                                    \
        __global const REAL *p = wall_param(param, by_type, type[i] - 1, ntypes, nparam);      \
        struct contact_site s =                                                                \
            wall_site(i, radius[i], WALL_REACH(JKR, p, radius[i]), has_history, acode);        \
        s.inclusive = inclusive;                                                               \
        s.approach = APPROACH;                                                                 \
        s.hold = WALL_HOLD(JKR, p);                                                            \
        const REAL3 xi = vload3(i, x), xil = POS_LOAD_LO(i);                                   \
        REAL3 fsum = vload3(i, f), tsum = (REAL3)(0);                                          \
        for (int e = 0; e < nelem; e++) {                                                      \
            __global REAL *hrow = history + ((size_t)i * nelem + e) * (size_t)has_history;     \
            struct contact_partner pj;                                                         \
            pj.omwall = (REAL3)(0);                                                            \
            WALL_HEAT_PARTNER(pj);                                                             \
            s.acts = wall_point(&w, e, xi, s.radi, &s.del, &s.rwall, &pj.vwall);               \
            s.del_lo = wall_gap_lo(s.del, xil);                                                \
            REAL h[WALL_ROW_N(ROW)];                                                           \
            contact_hist_load(h, hrow, has_history, WALL_ROW_N(ROW));                          \
            struct contact_out o;                                                              \
            const int acted = BODY(CONTACT_WALL, i, &s, &pj, &a, p, h, &o);                    \
            contact_hist_store(hrow, h, has_history, acted);                                   \
            if (acted) {                                                                       \
                fsum += o.f;                                                                   \
                tsum += o.ti;                                                                  \
                WALL_HEAT_ADD(o);                                                              \
                WALL_CONTACT_PUT(i, o.f, xi + xil - s.del, s.radi);                            \
            }                                                                                  \
        }                                                                                      \
        vstore3(fsum, i, f);                                                                   \
        WALL_ADD_TORQUE(torque, i, tsum);                                                      \
        WALL_HEAT_STORE(i);                                                                    \
    }

/* fix wall/pair: the active pair style's law (the pair kernel's,
 * kernels/pair_loop.cl, against a wall). In
 * the row form (pair granular) the law's history row is the wall's. */
#if defined(PAIR_EVAL) || defined(PAIR_EVAL_ROW)
#ifdef PAIR_EVAL_ROW
CONTACT_BODY(wall_pair_body, PAIR_EVAL_ROW, 1, TCOL_OF(PAIR_EVAL_ROW))
#define WALL_PAIR_ROW 1
#else
CONTACT_BODY(wall_pair_body, PAIR_EVAL, 0, TCOL_OF(PAIR_EVAL))
#define WALL_PAIR_ROW 0
#endif
#ifdef PAIR_APPROACH
#define WALL_PAIR_APPROACH 1
#else
#define WALL_PAIR_APPROACH 0
#endif
WALL_KERNEL(wall_pair, wall_pair_body, WALL_PAIR_ROW, WALL_PAIR_APPROACH, 0)
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
/* MESH_SLOTS: kernels/wall_layout.h */

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
        vb = mat_tmul(pose, vi - (vload3(POSE_V0 / 3, pose) +
                                 cross(vload3(POSE_OMEGA / 3, pose), xi - dw)));
    }
    return wall_within_drift(vb, del, rsq, radi, dt);
}

/* The atom at xi in the mesh's frame: xb = R^T (x - d) */
static inline REAL3 mesh_frame(__global const REAL *pose, const int moving, const REAL3 xi)
{
    return moving ? mat_tmul(pose, xi - vload3(POSE_D / 3, pose)) : xi;
}

/* The first triangle-list entry of xb's bin and the one after it (both 0
 * outside the grid) */
static inline int2 mesh_bin_range(__global const int *cstart, __global const REAL *pose,
                                  const int gnx, const int gny, const int gnz, const REAL3 xb)
{
    const REAL ginv = pose[POSE_GINV];
    const int cx = (int)floor((xb.x - pose[POSE_GLO]) * ginv);
    const int cy = (int)floor((xb.y - pose[POSE_GLO + 1]) * ginv);
    const int cz = (int)floor((xb.z - pose[POSE_GLO + 2]) * ginv);
    if (cx >= 0 && cy >= 0 && cz >= 0 && cx < gnx && cy < gny && cz < gnz) {
        const int cell = (cz * gny + cy) * gnx + cx;
        return (int2)(cstart[cell], cstart[cell + 1]);
    }
    return (int2)(0, 0);
}

/* Triangle t against the sphere at xb (radius radi): appended to the
 * candidates (tc, rc, dc, qc; at most MESH_MAXC) when it touches (with
 * approach: or one drift at the normal rate brings it into or out of
 * contact). Returns its squared distance. Always inlined: it runs in two
 * loops, and without approach its drift test folds away. */
static inline __attribute__((always_inline)) REAL
mesh_take(__global const REAL *tri, __global const REAL *pose, const int t, const int moving,
          const REAL3 xi, const REAL3 xb, const REAL3 vi, const REAL radi, const int inclusive,
          const int approach, const REAL dt, int *nc, int *tc, int *rc, REAL3 *dc, REAL *qc)
{
    REAL3 del;
    const int region = tri_closest(tri, t, xb, &del);
    const REAL rsq = del.x * del.x + del.y * del.y + del.z * del.z;
    if ((inclusive ? rsq > radi * radi : rsq >= radi * radi) &&
        !(approach && mesh_within_drift(pose, moving, xi, vi, del, rsq, radi, dt)))
        return rsq;
    if (*nc < MESH_MAXC) {
        tc[*nc] = t;
        rc[*nc] = region;
        dc[*nc] = del;
        qc[*nc] = rsq;
        (*nc)++;
    }
    return rsq;
}

/* One contact per physical contact: the edge and vertex contacts among the
 * nc candidates that a nearer feature holds are dropped (rc negative). */
static inline void mesh_drop_shadowed(__global const int *triv, const int nc, const int *tc,
                                      int *rc, const REAL *qc)
{
    for (int c = 0; c < nc; c++) {
        if (rc[c] == MESH_FACE)
            continue;
        const int k = rc[c] >= MESH_VERTEX ? rc[c] - MESH_VERTEX : rc[c] - MESH_EDGE;
        const int va = triv[3 * tc[c] + k];
        const int vb = rc[c] >= MESH_VERTEX ? va : triv[3 * tc[c] + (k + 1) % 3];
        for (int o = 0; o < nc; o++) {
            if (o == c) /* dropped ones count too: the nearest of a cluster stays */
                continue;
            if (!tri_has(triv, tc[o], va) && !tri_has(triv, tc[o], vb))
                continue;
            if (qc[o] < qc[c] || (qc[o] == qc[c] && tc[o] < tc[c])) {
                rc[c] = -1 - rc[c]; /* dropped */
                break;
            }
        }
    }
}

/* ---- the per-atom triangle lists of a mesh (no approach) ----
 *
 * Testing every triangle of the atom's bin each step costs some ten
 * triangle tests per atom; most atoms touch one triangle or none. So each
 * atom keeps a list (MESH_LIST_* of kernels/wall_layout.h): the triangles
 * within rl of the point xref (mesh frame) where it was built, in ascending
 * triangle id, and every other triangle is at least rl from xref. While
 * the atom is within (rl - radi) / 2 of xref (less the round-off bound tol),
 * every triangle it touches is listed, and the listed ones that touch, in
 * list order, are exactly the bin's touching triangles in bin order (a bin
 * lists its triangles in ascending id too). The contacts, their order and
 * so every sum are the bin search's: the list only saves the tests of the
 * far triangles. An atom that has moved further, or whose entry belongs to
 * another atom (the tag: the atoms are re-sorted at rebuilds), searches its
 * bin, which lists every triangle within the bins' reach, and builds its
 * list on the way with rl = radi + lskin (lskin <= reach - radi), shrunk
 * when more than MESH_LIST_K triangles are that near; an entry whose
 * margin is not above the round-off bound is left stale (n = -1): the bin
 * search then runs every step. The approach kernels also take triangles
 * one drift from contact, at most D = mesh_drift_reach away beyond the
 * radius: their lists are fresh while the atom is within (rl - radi) / 2 - D
 * of xref (every unlisted triangle is then more than radi + D away). */
#ifdef USE_DOUBLE
#define MESH_EPS DBL_EPSILON
#else
#define MESH_EPS FLT_EPSILON
#endif

/* The round-off bound of a distance from tri_closest near xb: the
 * coordinates involved are at most |xb|_1 + mscale (mscale: the largest
 * |vertex|_1 of the mesh) */
static inline REAL mesh_list_tol(const REAL3 xb, const REAL mscale)
{
    return (REAL)64 * MESH_EPS * (fabs(xb.x) + fabs(xb.y) + fabs(xb.z) + mscale);
}

/* A bound on how far beyond its radius a triangle that one drift brings
 * into or out of contact can be from the atom at xi (mesh_within_drift:
 * the gap is below |v_rel| dt, v_rel the atom's velocity less the mesh
 * surface's at the triangle's closest point p, |p - xi| <= radi + D), with
 * a relative margin for rounding; -1 when none holds (omega dt >= 1/2). */
static inline REAL mesh_drift_reach(__global const REAL *pose, const int moving, const REAL3 xi,
                                    const REAL3 vi, const REAL radi, const REAL dt)
{
    if (!moving)
        return length(vi) * dt * (REAL)(1 + 1e-6);
    const REAL3 om = vload3(POSE_OMEGA / 3, pose);
    const REAL w = length(om) * dt;
    if (!(w < (REAL)0.5))
        return (REAL)-1;
    /* |v_rel| <= |vi - (V0 + om x xi)| + |om| |p - xi| */
    const REAL a = length(vi - (vload3(POSE_V0 / 3, pose) + cross(om, xi)));
    return (a * dt + w * radi) / ((REAL)1 - w) * (REAL)(1 + 1e-6);
}

/* 1 when atom i's list holds every triangle it can touch at xb, and every
 * one within drift beyond its radius (drift >= 0) */
static inline int mesh_list_fresh(__global const int *lt, __global const REAL *lx,
                                  const long tagi, const REAL3 xb, const REAL radi,
                                  const REAL mscale, const REAL drift)
{
    if (lt[MESH_LIST_TAGLO] != (int)(tagi & 0xffffffff) ||
        lt[MESH_LIST_TAGHI] != (int)(tagi >> 32) || lt[MESH_LIST_N] < 0)
        return 0;
    const REAL room = (REAL)0.5 * (lx[MESH_LPOS_RL] - radi) - drift;
    if (!(room > mesh_list_tol(xb, mscale)))
        return 0;
    const REAL3 dx = xb - (REAL3)(lx[0], lx[1], lx[2]);
    return dx.x * dx.x + dx.y * dx.y + dx.z * dx.z < room * room;
}

/* Add triangle t at squared distance rsq to the list being built (ln
 * entries lt_ / lq_ of at most MESH_LIST_K, rl2 the squared radius); when
 * full, rl2 shrinks to the largest distance among them and t, and the
 * triangles that far leave. Every triangle seen and not listed is then at
 * least sqrt(rl2) away. */
static inline void mesh_list_note(const int t, const REAL rsq, int *ln, int *lt_, REAL *lq_,
                                  REAL *rl2)
{
    if (!(rsq < *rl2))
        return;
    if (*ln < MESH_LIST_K) {
        lt_[*ln] = t;
        lq_[*ln] = rsq;
        (*ln)++;
        return;
    }
    REAL qmax = rsq;
    for (int k = 0; k < *ln; k++)
        qmax = fmax(qmax, lq_[k]);
    *rl2 = qmax;
    int m = 0;
    for (int k = 0; k < *ln; k++)
        if (lq_[k] < qmax) {
            lt_[m] = lt_[k];
            lq_[m] = lq_[k];
            m++;
        }
    *ln = m;
    if (rsq < qmax) {
        lt_[m] = t;
        lq_[m] = rsq;
        (*ln)++;
    }
}

/* Store the list built at xb (rl2: its squared radius) as atom i's */
static inline void mesh_list_store(__global int *lt, __global REAL *lx, const long tagi,
                                   const REAL3 xb, const REAL radi, const REAL mscale,
                                   const int ln, const int *lt_, const REAL rl2)
{
    const REAL rl = sqrt(rl2);
    const int ok = (REAL)0.5 * (rl - radi) > mesh_list_tol(xb, mscale);
    lt[MESH_LIST_TAGLO] = (int)(tagi & 0xffffffff);
    lt[MESH_LIST_TAGHI] = (int)(tagi >> 32);
    lt[MESH_LIST_N] = ok ? ln : -1;
    for (int k = 0; ok && k < ln; k++)
        lt[MESH_LIST_T + k] = lt_[k];
    lx[0] = xb.x;
    lx[1] = xb.y;
    lx[2] = xb.z;
    lx[MESH_LPOS_RL] = rl;
}

/* The triangles of a mesh that touch the sphere at xi (radius radi; with
 * approach, also those one drift at its normal rate brings into or out of
 * contact), at most MESH_MAXC, in bin order: tc the triangle, rc its
 * Voronoi region (negative: dropped, a nearer feature holds the contact),
 * dc the separation in the mesh frame, qc its square. Returns how many.
 * The atom's list (lt, lx: its entries) stands in for its bin while it is
 * fresh, and is rebuilt by the bin search when it is not. */
static inline int mesh_candidates(__global const REAL *tri, __global const int *triv,
                                  __global const int *cstart, __global const int *ctri,
                                  __global const REAL *pose, const int gnx, const int gny,
                                  const int gnz, const int moving, const REAL3 xi,
                                  const REAL3 vi, const REAL radi, const int inclusive,
                                  const int approach, const REAL dt, __global int *lt,
                                  __global REAL *lx, const long tagi, const REAL lskin,
                                  const REAL lreach, const REAL mscale, int *tc, int *rc,
                                  REAL3 *dc, REAL *qc)
{
    const REAL3 xb = mesh_frame(pose, moving, xi);
    const REAL drift = approach ? mesh_drift_reach(pose, moving, xi, vi, radi, dt) : (REAL)0;
    int nc = 0;
    if (drift >= (REAL)0 && mesh_list_fresh(lt, lx, tagi, xb, radi, mscale, drift)) {
        const int ln = lt[MESH_LIST_N];
        for (int k = 0; k < ln; k++)
            mesh_take(tri, pose, lt[MESH_LIST_T + k], moving, xi, xb, vi, radi, inclusive,
                      approach, dt, &nc, tc, rc, dc, qc);
    } else {
        const int2 r = mesh_bin_range(cstart, pose, gnx, gny, gnz, xb);
        int ln = 0, lt_[MESH_LIST_K];
        REAL lq_[MESH_LIST_K];
        const REAL rl = radi + fmin(lskin, lreach - radi);
        REAL rl2 = rl * rl;
        for (int k = r.x; k < r.y; k++) {
            const int t = ctri[k];
            const REAL rsq = mesh_take(tri, pose, t, moving, xi, xb, vi, radi, inclusive,
                                       approach, dt, &nc, tc, rc, dc, qc);
            mesh_list_note(t, rsq, &ln, lt_, lq_, &rl2);
        }
        mesh_list_store(lt, lx, tagi, xb, radi, mscale, ln, lt_, rl2);
    }
    mesh_drop_shadowed(triv, nc, tc, rc, qc);
    return nc;
}

/* The history slot of a contact with triangle t: the slot keyed by t, else
 * the slot of a triangle that no longer counts and shares a vertex with t
 * (the shear follows a particle sliding across an edge); -1: none (a new
 * contact). okey: the old slots' keys (triangle + 1, 0 free). */
static inline int mesh_slot_find(const REAL *okey, const int t, const int nc, const int *tc,
                                 const int *rc, __global const int *triv)
{
    int found = -1;
    for (int s = 0; s < MESH_SLOTS; s++)
        if (okey[s] == (REAL)(t + 1))
            found = s;
    for (int s = 0; found < 0 && s < MESH_SLOTS; s++) {
        if (okey[s] <= 0)
            continue;
        const int ot = (int)okey[s] - 1;
        int live = 0;
        for (int o = 0; o < nc; o++)
            live |= rc[o] >= 0 && tc[o] == ot;
        if (!live && tri_touch(triv, ot, t))
            found = s;
    }
    return found;
}

/* Mesh walls: one work-item per atom of the group, one launch per mesh.
 * The mesh is rigid: its triangles and their bins stay in the mesh's own
 * frame and the atom is taken there, xb = R^T (x - d) (the pose, layout
 * POSE_* of kernels/wall_layout.h); the atom's bin lists every triangle
 * that may touch it, and the atom's own list (mesh_candidates) the few
 * near it, so the cost grows with the triangles near the atom, not with
 * the mesh size. fmesh (want_fmesh): per atom the force on the
 * mesh (3) and its torque about the reference point (3), for f_ID output.
 * mstress (want_mstress, fix mesh/surface/stress): per atom MESH_SLOTS
 * contact records (MESH_SREC_*, kernels/wall_layout.h) for the per-triangle
 * stress and wear the host sums in tag order.
 * BODY: a CONTACT_BODY instance; ROW its form; APPROACH as WALL_KERNEL
 * (fix mesh/surface then bins the triangles with the neighbor skin added).
 * The contacts found by mesh_candidates are run through the body in bin
 * order; history slots are kept as mesh_slot_find says (1 + hw REAL each:
 * the key, then the law's hw = 3 REAL of shear, or for ROW 1 the
 * has_history REAL of pair granular's sub-models, kernels/fix_wall_gran.cl).
 * Arguments: KARGS_mesh_kernel (kernels/kernel_args.h). */
#define MESH_KERNEL(NAME, BODY, ROW, APPROACH)                                                 \
    __kernel void NAME(KA_KERNEL(mesh_kernel))                                                 \
    {                                                                                          \
        KA_UNPACK(mesh_kernel);                                                                \
        if (KA_HALTED())                                                                       \
            return;                                                                            \
        const int i = get_global_id(0);                                                        \
        if (i >= n)                                                                            \
            return;                                                                            \
        __global REAL *srec = mstress + (size_t)i * (MESH_SLOTS * MESH_SREC_W);                \
        if (want_mstress)                                                                      \
            srec[MESH_SREC_KEY] = 0; /* no record yet */                                       \
        if (!(mask[i] & groupbit)) {                                                           \
            if (want_fmesh) {                                                                  \
                vstore3((REAL3)(0), 2 * i, fmesh);                                             \
                vstore3((REAL3)(0), 2 * i + 1, fmesh);                                         \
            }                                                                                  \
            return;                                                                            \
        }                                                                                      \
        const REAL3 xi = vload3(i, x) + POS_LOAD_LO(i);                                        \
        const REAL radi = radius[i];                                                           \
        int tc[MESH_MAXC], rc[MESH_MAXC];                                                      \
        REAL3 dc[MESH_MAXC];                                                                   \
        REAL qc[MESH_MAXC];                                                                    \
        const int nc = mesh_candidates(tri, triv, cstart, ctri, pose, gnx, gny, gnz, moving,   \
                                       xi, vload3(i, v), radi, inclusive, APPROACH, dt,        \
                                       mlist + (size_t)i * MESH_LIST_W,                        \
                                       mlpos + (size_t)i * MESH_LPOS_W, tag[i], lskin, lreach, \
                                       mscale, tc, rc, dc, qc);                                \
        const int hw = ROW ? has_history : 3; /* history REAL per slot (after its key) */      \
        /* the slots' keys (okey: 0 once taken; okey0: as loaded). The slots                   \
         * in use come first (they are written so, below): the keys are read                   \
         * up to the first free one, and a slot's history only when a                          \
         * contact takes it. */                                                                \
        REAL okey[MESH_SLOTS], okey0[MESH_SLOTS];                                              \
        __global REAL *hist = has_history ? history + (size_t)i * hstride + hoff : history;    \
        int more = has_history;                                                                \
        for (int s = 0; s < MESH_SLOTS; s++) {                                                 \
            okey[s] = okey0[s] = more ? hist[(1 + hw) * s] : (REAL)0;                          \
            more = okey[s] != (REAL)0;                                                         \
        }                                                                                      \
        REAL nkey[MESH_SLOTS], nsh[MESH_SLOTS][WALL_ROW_N(ROW)];                               \
        int nnew = 0;                                                                          \
        struct contact_atoms a =                                                               \
            contact_atoms_of(v, omega, rmass, dt, shearupdate, acc, astep, step);              \
        WALL_HEAT_BEGIN(a);                                                                    \
        __global const REAL *p = p_of(param, by_type, type[i] - 1, ntypes, nparam);            \
        struct contact_site s = wall_site(i, radi, radi, 0, acode);                            \
        s.gated = 1; /* mesh_candidates decided */                                             \
        s.refine = 0;                                                                          \
        s.approach = APPROACH;                                                                 \
        struct contact_partner pj;                                                             \
        pj.omwall = moving ? vload3(POSE_OMEGA / 3, pose) : (REAL3)(0);                        \
        WALL_HEAT_PARTNER(pj);                                                                 \
        REAL3 fsum = vload3(i, f), tsum = (REAL3)(0), fm = (REAL3)(0), tm = (REAL3)(0);        \
        const REAL3 rref = (REAL3)(pose[POSE_REF], pose[POSE_REF + 1], pose[POSE_REF + 2]);    \
        int nrec = 0;                                                                          \
        for (int c = 0; c < nc; c++) {                                                         \
            if (rc[c] < 0)                                                                     \
                continue;                                                                      \
            const int t = tc[c];                                                               \
            s.del = moving ? mat_mul(pose, dc[c]) : dc[c];                                     \
            const REAL3 cpt = xi - s.del;                                                      \
            pj.vwall = moving ? vload3(POSE_V0 / 3, pose) + cross(pj.omwall, cpt) : (REAL3)(0);\
            REAL h[WALL_ROW_N(ROW)];                                                           \
            for (int q = 0; q < WALL_ROW_N(ROW); q++)                                          \
                h[q] = 0;                                                                      \
            const int found = has_history ? mesh_slot_find(okey, t, nc, tc, rc, triv) : -1;    \
            if (found >= 0) {                                                                  \
                for (int q = 0; q < hw; q++)                                                   \
                    h[q] = hist[(1 + hw) * found + 1 + q];                                     \
                okey[found] = 0; /* taken */                                                   \
            }                                                                                  \
            struct contact_out o;                                                              \
            BODY(CONTACT_WALL, i, &s, &pj, &a, p, h, &o);                                      \
            if (has_history && nnew < MESH_SLOTS) {                                            \
                nkey[nnew] = (REAL)(t + 1);                                                    \
                for (int q = 0; q < hw; q++)                                                   \
                    nsh[nnew][q] = h[q];                                                       \
                nnew++;                                                                        \
            }                                                                                  \
            if (want_mstress && nrec < MESH_SLOTS) {                                          \
                __global REAL *r = srec + nrec * MESH_SREC_W;                                  \
                const REAL3 vrel = vload3(i, v) - pj.vwall;                                    \
                r[MESH_SREC_KEY] = (REAL)(t + 1);                                              \
                vstore3(-o.f, 0, r + MESH_SREC_F);                                             \
                vstore3(vrel, 0, r + MESH_SREC_V);                                             \
                r[MESH_SREC_CV] = -dot(s.del, vrel);                                           \
                if (++nrec < MESH_SLOTS)                                                       \
                    srec[nrec * MESH_SREC_W + MESH_SREC_KEY] = 0;                              \
            }                                                                                  \
            fsum += o.f;                                                                       \
            tsum += o.ti;                                                                      \
            WALL_HEAT_ADD(o);                                                                  \
            fm -= o.f;                                                                         \
            tm -= cross(cpt - rref, o.f);                                                      \
        }                                                                                      \
        /* the new slots in order, then zeros where a slot was in use (a free                  \
         * slot is all zero already) */                                                        \
        for (int s = 0; has_history && s < MESH_SLOTS; s++) {                                  \
            const int used = s < nnew;                                                         \
            if (!used && okey0[s] == (REAL)0)                                                  \
                continue;                                                                      \
            hist[(1 + hw) * s] = used ? nkey[s] : (REAL)0;                                     \
            for (int q = 0; q < hw; q++)                                                       \
                hist[(1 + hw) * s + 1 + q] = used ? nsh[s][q] : (REAL)0;                       \
        }                                                                                      \
        vstore3(fsum, i, f);                                                                   \
        WALL_ADD_TORQUE(torque, i, tsum);                                                      \
        WALL_HEAT_STORE(i);                                                                    \
        if (want_fmesh) {                                                                      \
            vstore3(fm, 2 * i, fmesh);                                                         \
            vstore3(tm, 2 * i + 1, fmesh);                                                     \
        }                                                                                      \
    }

/* fix wall/pair ... mesh: the active pair style's law against triangles */
#if defined(PAIR_EVAL) || defined(PAIR_EVAL_ROW)
MESH_KERNEL(mesh_pair, wall_pair_body, WALL_PAIR_ROW, WALL_PAIR_APPROACH)
#endif
