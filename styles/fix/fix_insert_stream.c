/* fix_insert_stream.c - `fix ID group insert/stream seed S
 * distributiontemplate D nparticles N | mass M  particlerate R | massrate Q
 * insertion_face MESH extrude_length L | insert_every N [duration K] ...`:
 * a stream of particles through the planar face of a fix mesh/surface
 * (LIGGGHTS-PUBLIC 3.8 FixInsertStream).
 *
 * Geometry (each run): n = the unit normal of the face's triangle 0
 * (normalised edges 0 and 1 crossed, LIGGGHTS's surfaceNorm), flipped so
 * that v . n > 0 for the insertion velocity v; v_n = (v . n) n; p_ref =
 * vertex 0 of triangle 0. extrude_length L gives insert_every = int((L +
 * 1e-14) / (dt |v_n|)); insert_every N gives L = K dt |v_n| (K = duration,
 * default N). Counts as insert/rate/region: R N dt particles per insertion
 * step (int(. + u)), nparticles or int((M + 1e-14) / E[mass]) in all.
 *
 * Positions (generate_random): a triangle drawn by area, a point in it by
 * barycentric draws (u, v until u + v <= 1: (1-u-v) p0 + v p1 + u p2),
 * both from the face mesh's stream (Park-Miller seeded 179424799, as
 * LIGGGHTS's TriMesh); then moved back along -n by u L + r (overlapcheck
 * yes) or u (L - 2r) + r (no), u from the fix's stream. A try outside the
 * box or within r of a box face is redrawn. Before the split of each
 * insertion step (at the first only, unless a boundary is shrink-wrapped)
 * ntry_mc such points, extruded by u L, give the share of the volume in the
 * box (LIGGGHTS's insertion_fraction; its draws advance both streams).
 * Atoms for the overlap check: those within -(L + 3 r_max) .. r_max of the
 * face plane whose projection lies on the face (LIGGGHTS's is_nearby).
 *
 * Placed atoms move at v_n, untouched by forces, until their centre
 * reaches the face (release step = insertion step + int((distance to the
 * face plane + 1e-14) / (|v_n| dt))); there they get v (vel uniform |
 * gaussian: drawn at insertion, in tag order, from the fix's stream) and
 * omega (kernels/fix_insert_stream.cl, end_of_step). A clump of fix
 * multisphere (constant vel only, as LIGGGHTS) is released as a body: its
 * atoms take the release step of its centre of mass (int(distance / (|v_n|
 * dt)), LIGGGHTS's Multisphere::calc_n_steps), the body drifts at v_n
 * untouched by forces until then and takes v after it (fix_rigid_small.h,
 * rigid_small_stream); its atoms follow the approach above but at the
 * release step, where the body moves them. These steps are
 * counted on the fix's clock, step - clock_shift, which reset_timestep does
 * not move: the approach goes on across a reset. The insertion step
 * itself: fix_insert.c. Full contract: doc/styles/fix_insert_stream.md. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fix_insert.h"
#include "fix_mesh_surface.h"
#include "fix_rigid_small.h"
#include "mesh_planar.h"

#define WHO "fix insert/stream"
#define TINY 1e-14          /* LIGGGHTS's FIX_INSERT_STREAM_TINY */
#define MESH_SEED 179424799 /* LIGGGHTS's MultiNodeMesh random_ */
#define PLANAR_TOL 1e-8     /* relative: normals parallel, vertices on the plane */

/* The insertion face: the style's own state beside struct insert. */
struct stream {
    struct insert in;               /* first: the fix's data is this */
    char face_id[GR_NAMELEN];
    int every_given, duration, parallel, frac_done;
    double extrude_given;
    /* geometry of the run */
    int ntri;
    double *tri;                    /* 9 per triangle: vertices 0 1 2 */
    double *acc;                    /* accumulated areas */
    double normal[3], p_ref[3], v_normal[3], vn_mag;
    double extrude, ext_min, ext_max, vol_lo[3], vol_hi[3];
    double frac;
    const struct mesh *face;        /* all_in: the face (fix mesh/surface/planar) and */
    const struct mesh_planar *edges;/*   its nearest active edges */
    cl_kernel eos;
};

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* LIGGGHTS's surfaceNorm of a triangle: its normalised edges 0 -> 1 and
 * 1 -> 2 crossed, normalised. */
static void tri_normal(const double *p, double nrm[3])
{
    double e[2][3];
    for (int k = 0; k < 2; k++) {
        double len = 0;
        for (int d = 0; d < 3; d++) {
            e[k][d] = p[3 * (k + 1) + d] - p[3 * k + d];
            len += e[k][d] * e[k][d];
        }
        len = sqrt(len);
        for (int d = 0; d < 3; d++)
            e[k][d] /= len;
    }
    cross3(e[0], e[1], nrm);
    double m = sqrt(dot3(nrm, nrm));
    for (int d = 0; d < 3; d++)
        nrm[d] /= m;
}

/* 1 if the projection of x on the plane of triangle t lies in it
 * (LIGGGHTS's isInElement: barycentric coordinates from dot products,
 * 1e-10 of slack). */
static int in_triangle(const double *p, const double x[3])
{
    double v0[3], v1[3], v2[3];
    for (int d = 0; d < 3; d++) {
        v0[d] = p[6 + d] - p[d];
        v1[d] = p[3 + d] - p[d];
        v2[d] = x[d] - p[d];
    }
    double d00 = dot3(v0, v0), d01 = dot3(v0, v1), d02 = dot3(v0, v2), d11 = dot3(v1, v1),
           d12 = dot3(v1, v2), inv = 1. / (d00 * d11 - d01 * d01);
    double u = (d11 * d02 - d01 * d12) * inv, v = (d00 * d12 - d01 * d02) * inv;
    return u > -1e-10 && v > -1e-10 && u + v < 1. + 1e-10;
}

static int on_face(const struct stream *s, const double x[3])
{
    for (int t = 0; t < s->ntri; t++)
        if (in_triangle(s->tri + 9 * t, x))
            return 1;
    return 0;
}

/* A random point of the face (TriMesh::generateRandomOwnedGhost); returns
 * its triangle. */
static int face_point(struct stream *s, double x[3])
{
    struct rng_park *rng = &s->in.rrng;
    double r = rng_park_uniform(rng) * s->acc[s->ntri - 1];
    int lo = 0, hi = s->ntri - 1;
    while (lo < hi) { /* the first triangle whose accumulated area reaches r */
        int mid = (lo + hi) / 2;
        if (s->acc[mid] >= r)
            hi = mid;
        else
            lo = mid + 1;
    }
    double u, v;
    do {
        u = rng_park_uniform(rng);
        v = rng_park_uniform(rng);
    } while (u + v > 1);
    const double *p = s->tri + 9 * lo, b0 = 1. - u - v;
    for (int d = 0; d < 3; d++)
        x[d] = b0 * p[d] + v * p[3 + d] + u * p[6 + d];
    return lo;
}

/* all_in yes: a random point of the face at least r from its border as
 * LIGGGHTS tests it (TriMeshPlanar::generateRandomOwnedGhostWithin: its
 * triangle's stored nearest active edges, at most MESH_PLANAR_MAXTRY draws,
 * then a warning and the last point). */
static void face_point_within(struct gravel *g, struct stream *s, double r, double x[3])
{
    for (int ntry = 1;; ntry++) {
        int t = face_point(s, x);
        if (mesh_planar_far(s->face, s->edges, t, x, r))
            return;
        if (ntry == MESH_PLANAR_MAXTRY) {
            gr_warn(g, "'All_in yes' did not succeed");
            return;
        }
    }
}

static void extrude(const struct stream *s, double len, double x[3])
{
    for (int d = 0; d < 3; d++)
        x[d] += s->normal[d] * len;
}

/* ---- geometry, each run ------------------------------------------------- */

static void geometry(struct gravel *g, struct stream *s)
{
    struct insert *in = &s->in;
    const struct mesh_surface *ms = mesh_surface_get(g, s->face_id, WHO);
    struct mesh_pose pose;
    mesh_surface_pose(g, s->face_id, &pose);
    if (pose.moving)
        gr_error(g, WHO ": cannot translate, rotate, scale mesh which is used for particle "
                    "insertion (%s moves)", s->face_id);
    if (in->all_in && !ms->planar)
        gr_error(g, WHO ": using all_in yes requires you to use a fix mesh/surface/planar");
    const struct mesh *m = &ms->m;
    s->face = m;
    s->edges = in->all_in ? &ms->edges : NULL;
    s->ntri = m->ntri;
    s->tri = gr_realloc(g, s->tri, 9 * (size_t)m->ntri * sizeof *s->tri);
    s->acc = gr_realloc(g, s->acc, (size_t)m->ntri * sizeof *s->acc);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int t = 0; t < m->ntri; t++)
        for (int k = 0; k < 3; k++)
            for (int d = 0; d < 3; d++) {
                double c = m->vert[3 * m->tri[3 * t + k] + d];
                s->tri[9 * t + 3 * k + d] = c;
                lo[d] = c < lo[d] ? c : lo[d];
                hi[d] = c > hi[d] ? c : hi[d];
            }
    /* planar: every triangle's normal parallel to triangle 0's, every vertex on its plane */
    double n0[3], diag = 0;
    tri_normal(s->tri, n0);
    for (int d = 0; d < 3; d++)
        diag += (hi[d] - lo[d]) * (hi[d] - lo[d]);
    diag = sqrt(diag);
    for (int t = 0; t < m->ntri; t++) {
        double nt[3], rel[3];
        tri_normal(s->tri + 9 * t, nt);
        int ok = fabs(dot3(nt, n0)) > 1. - PLANAR_TOL;
        for (int k = 0; k < 3 && ok; k++) {
            for (int d = 0; d < 3; d++)
                rel[d] = s->tri[9 * t + 3 * k + d] - s->tri[d];
            ok = fabs(dot3(rel, n0)) <= PLANAR_TOL * diag;
        }
        if (!ok)
            gr_error(g, WHO ": command requires a planar face for insertion (mesh %s, triangle "
                        "%d is not in the plane of triangle 0)", s->face_id, t);
        double e1[3], e2[3], c[3];
        for (int d = 0; d < 3; d++) {
            e1[d] = s->tri[9 * t + 3 + d] - s->tri[9 * t + d];
            e2[d] = s->tri[9 * t + 6 + d] - s->tri[9 * t + d];
        }
        cross3(e1, e2, c);
        s->acc[t] = 0.5 * sqrt(dot3(c, c)) + (t ? s->acc[t - 1] : 0.);
    }
    /* normal along the insertion velocity, its normal part */
    memcpy(s->normal, n0, sizeof n0);
    if (dot3(in->v, s->normal) < 0)
        for (int d = 0; d < 3; d++)
            s->normal[d] = -s->normal[d];
    double vn = dot3(in->v, s->normal);
    for (int d = 0; d < 3; d++)
        s->v_normal[d] = s->normal[d] * vn;
    s->vn_mag = sqrt(dot3(s->v_normal, s->v_normal));
    if (s->vn_mag < 1e-3)
        gr_error(g, WHO ": insertion velocity projected on face normal is < 1e-3");
    memcpy(s->p_ref, s->tri, sizeof s->p_ref);
    if (sqrt(dot3(in->v, in->v)) < 1e-5)
        gr_error(g, WHO ": insertion velocity too low");
    /* insert_every <-> extrude_length */
    if (s->every_given == -1 && s->extrude_given == 0.)
        gr_error(g, WHO ": must define either 'insert_every' or 'extrude_length'");
    if (s->every_given > -1 && s->extrude_given > 0.)
        gr_error(g, WHO ": must not provide both 'insert_every' and 'extrude_length'");
    if (s->extrude_given > 0. && s->duration > 0)
        gr_error(g, WHO ": must not provide both 'extrude_length' and 'duration'");
    double rmax = in->dist->maxrad, dt = g->dt;
    if (s->every_given == -1) {
        if (s->extrude_given < 3. * rmax)
            gr_error(g, WHO ": 'extrude_length' is too small (%g < 3 x the largest radius %g)",
                     s->extrude_given, rmax);
        double n = (s->extrude_given + TINY) / (dt * s->vn_mag);
        if (!(n < 2147483647.0))
            gr_error(g, WHO ": insertion velocity too low or extrude_length too high");
        in->insert_every = (int)n;
        if (in->insert_every == 0)
            gr_error(g, WHO ": insertion velocity too high or extrude_length too low");
        s->extrude = s->extrude_given;
    } else {
        if (s->every_given < 1)
            gr_error(g, WHO ": 'insert_every' must be > 0");
        int dur = s->duration ? s->duration : s->every_given;
        if (dur > s->every_given)
            gr_error(g, WHO ": 'duration' > 'insert_every' not allowed");
        in->insert_every = s->every_given;
        s->extrude = (double)dur * dt * s->vn_mag;
        if (s->extrude < 3. * rmax)
            gr_error(g, WHO ": 'insert_every' or 'vel' is too small, or radius of inserted "
                        "particles too large");
    }
    s->ext_min = 0.;
    s->ext_max = s->extrude;
    for (int d = 0; d < 3; d++) {
        double a = lo[d] - s->normal[d] * s->extrude, b = hi[d] - s->normal[d] * s->extrude;
        s->vol_lo[d] = a < lo[d] ? a : lo[d];
        s->vol_hi[d] = b > hi[d] ? b : hi[d];
    }
}

/* ---- the insert_ops ------------------------------------------------------ */

static int keyword(struct gravel *g, struct insert *in, int argc, char **argv, int i)
{
    struct stream *s = (struct stream *)in;
    const char *k = argv[i];
    if (!strcmp(k, "insertion_face")) {
        arg_need(g, argc, i, 1, k);
        mesh_surface_get(g, argv[i + 1], WHO);
        snprintf(s->face_id, sizeof s->face_id, "%s", argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "extrude_length")) {
        arg_need(g, argc, i, 1, k);
        s->extrude_given = arg_double(g, argv[i + 1], k);
        if (!(s->extrude_given >= 0.) || !isfinite(s->extrude_given))
            gr_error(g, WHO ": invalid extrude_length %s", argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "duration")) {
        arg_need(g, argc, i, 1, k);
        s->duration = arg_int(g, argv[i + 1], k);
        if (s->duration < 1)
            gr_error(g, WHO ": 'duration' can not be < 1, got %s", argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "parallel")) {
        arg_need(g, argc, i, 1, k);
        if (strcmp(argv[i + 1], "yes") && strcmp(argv[i + 1], "no"))
            gr_error(g, WHO ": expecting 'yes' or 'no' for 'parallel', got '%.64s'",
                     argv[i + 1]);
        s->parallel = !strcmp(argv[i + 1], "yes");
        return 2;
    }
    if (!strcmp(k, "ntry_mc"))
        return insert_region_keyword(g, in, argc, argv, i);
    return 0;
}

static void properties(struct gravel *g, struct insert *in)
{
    struct stream *s = (struct stream *)in;
    if (!s->face_id[0])
        gr_error(g, WHO ": must define an insertion face");
    geometry(g, s);
    insert_rate_counts(g, in, TINY);
}

/* The share of the extruded volume in the box, ntry_mc points
 * (calc_ins_fraction); with parallel yes also the extrusion range the box
 * cuts out. */
static double fraction(struct gravel *g, struct insert *in)
{
    struct stream *s = (struct stream *)in;
    if (s->frac_done && !insert_box_changes(g))
        return s->frac;
    s->frac_done = 1;
    long n_in = 0;
    for (int i = 0; i < in->ntry_mc; i++) {
        double x[3];
        face_point(s, x);
        extrude(s, -(rng_park_uniform(&in->rng) * s->extrude), x);
        n_in += insert_in_subdomain(g, x);
    }
    s->frac = (double)n_in / (double)in->ntry_mc;
    if (s->parallel) {
        double mn = s->extrude, mx = 0.;
        for (int c = 0; c < 8; c++) {
            double e[3];
            for (int d = 0; d < 3; d++)
                e[d] = ((c >> d) & 1 ? g->dom.hi[d] : g->dom.lo[d]) - s->p_ref[d];
            double t = -dot3(e, s->normal);
            if (t > 0. && t < s->extrude) {
                mx = t > mx ? t : mx;
                mn = t < mn ? t : mn;
            } else if (t < 0.)
                mn = 0.;
            else if (t >= s->extrude)
                mx = s->extrude;
        }
        s->ext_min = mn == s->extrude ? 0. : mn;
        s->ext_max = mx == 0. ? s->extrude : mx;
    }
    return s->frac;
}

static int ninsert_this(struct gravel *g, struct insert *in)
{
    struct stream *s = (struct stream *)in;
    int inside = 1;
    for (int d = 0; d < 3; d++)
        inside &= s->vol_lo[d] >= g->dom.lo[d] && s->vol_lo[d] <= g->dom.hi[d] &&
                  s->vol_hi[d] >= g->dom.lo[d] && s->vol_hi[d] <= g->dom.hi[d];
    if (!inside)
        gr_warn(g, "Fix insert/stream: Extruded insertion face extends outside domain, may not "
                   "insert all particles correctly");
    return insert_ninsert_rate(g, in);
}

static int reserve(struct gravel *g, struct insert *in, bigint nsteps)
{
    (void)nsteps;
    struct stream *s = (struct stream *)in;
    if (!s->face_id[0])
        gr_error(g, WHO ": must define an insertion face");
    geometry(g, s); /* insert_every, which the caller reads next */
    return insert_rate_reserve(g, in);
}

static void point(struct gravel *g, struct insert *in, double r, double x[3])
{
    struct stream *s = (struct stream *)in;
    if (in->all_in)
        face_point_within(g, s, r, x);
    else
        face_point(s, x);
    double u = rng_park_uniform(&in->rng);
    if (in->check_ol)
        extrude(s, -(u * s->ext_max + r + s->ext_min), x);
    else
        extrude(s, -(u * (s->ext_max - 2. * r) + r + s->ext_min), x);
}

static int redraw(const struct gravel *g, const struct insert *in, const double x[3], double r)
{
    (void)in;
    return !insert_in_subdomain(g, x) || insert_dist_box(g, x) < r;
}

static int nearby(const struct gravel *g, const struct insert *in, const double x[3], double r)
{
    (void)g, (void)r;
    const struct stream *s = (const struct stream *)in;
    double rel[3], proj[3];
    for (int d = 0; d < 3; d++)
        rel[d] = x[d] - s->p_ref[d];
    double dn = dot3(rel, s->normal);
    if (dn > in->maxrad || dn < -(s->extrude + 3. * in->maxrad))
        return 0;
    for (int d = 0; d < 3; d++)
        proj[d] = x[d] - s->normal[d] * dn;
    return on_face(s, proj);
}

static void velocity(struct insert *in, double v[3])
{
    const struct stream *s = (const struct stream *)in;
    memcpy(v, s->v_normal, 3 * sizeof *v);
}

/* Per-atom state: int i_step, r_step; REAL x_ins hi[3], lo[3], v_int[3],
 * v_rel[3] (kernels/fix_insert_stream.cl). */
static size_t state_bytes(const struct gravel *g)
{
    return 2 * sizeof(int) + 12 * g->eng->rsz;
}

static void finalize(struct gravel *g, struct fix *f, int first, int n)
{
    struct stream *s = f->data;
    struct insert *in = &s->in;
    if (n <= 0)
        return;
    const struct atoms *a = &g->atoms;
    const struct engine *e = g->eng;
    size_t bytes = state_bytes(g);
    struct fix *ms = fix_find_style(g, "multisphere");
    const unsigned clumps = ms ? rigid_small_member_bits(ms) : 0;
    unsigned char *buf = gr_calloc(g, (size_t)n, bytes);
    /* the release velocities of every particle placed this step, in tag order
     * (drawn on every rank alike; this rank's atoms take theirs by ID) */
    double *vdraw = NULL;
    if (in->vstyle != INS_V_CONSTANT) {
        vdraw = gr_malloc(g, 3 * (size_t)(in->nplaced + 1) * sizeof(double));
        for (int k = 0; k < in->nplaced; k++)
            for (int d = 0; d < 3; d++)
                vdraw[3 * k + d] = in->vstyle == INS_V_UNIFORM
                    ? in->v[d] + in->vfluct[d] * 2.0 * (rng_park_uniform(&in->rng) - 0.50)
                    : in->v[d] + in->vfluct[d] * rng_park_gaussian(&in->rng);
    }
    for (int k = 0; k < n; k++) {
        int i = first + k;
        const double *x = a->x + 3 * i;
        double rel[3], vals[12];
        for (int d = 0; d < 3; d++)
            rel[d] = s->p_ref[d] - x[d];
        double steps = (dot3(rel, s->normal) + TINY) / (s->vn_mag * g->dt);
        steps = steps > 0 ? floor(steps) : 0;
        if (ms && (a->mask[i] & clumps)) /* a clump's atom: its body's release step */
            steps = (double)(rigid_small_stream(g, ms, (int)a->mol[i] - 1, s->p_ref, s->normal,
                                                s->v_normal, in->v) - g->step);
        bigint clock = g->step - in->clock_shift;
        if (!(clock > 0 && (double)clock + steps < 2147483647.0))
            gr_error(g, WHO " %s: release step %g is out of the range of the release clock",
                     f->id, (double)clock + steps);
        int head[2] = {(int)clock, (int)clock + (int)steps};
        double vrel[3];
        memcpy(vrel, in->v, sizeof vrel);
        if (vdraw) {
            int64_t q = a->tag[i] - in->tag_first;
            if (q < 0 || q >= in->nplaced)
                gr_error(g, "internal error: " WHO " %s: atom %lld is not one of the %d just "
                            "placed", f->id, (long long)a->tag[i], in->nplaced);
            memcpy(vrel, vdraw + 3 * q, sizeof vrel);
        }
        for (int d = 0; d < 3; d++) {
            double p = x[d] - e->origin[d];
            vals[d] = e->single ? (double)(float)p : p;
            vals[3 + d] = e->single ? p - vals[d] : 0.;
            vals[6 + d] = s->v_normal[d];
            vals[9 + d] = vrel[d];
        }
        unsigned char *row = buf + (size_t)k * bytes;
        memcpy(row, head, sizeof head);
        for (int q = 0; q < 12; q++) {
            if (e->single) {
                float fv = (float)vals[q];
                memcpy(row + sizeof head + q * sizeof fv, &fv, sizeof fv);
            } else
                memcpy(row + sizeof head + q * sizeof vals[q], &vals[q], sizeof vals[q]);
        }
    }
    eng_write(g, f->peratom, (size_t)first * bytes, (size_t)n * bytes, buf);
    free(buf);
    free(vdraw);
}

static const struct insert_ops ops = {
    .who = WHO,
    .keyword = keyword,
    .properties = properties,
    .ninsert_this = ninsert_this,
    .maxtry = insert_maxtry,
    .reserve = reserve,
    .point = point,
    .redraw = redraw,
    .nearby = nearby,
    .velocity = velocity,
    .fraction = fraction,
    .finalize = finalize,
};

/* ---- the fix --------------------------------------------------------------- */

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct stream *s = gr_calloc(g, 1, sizeof *s);
    f->data = s;
    insert_create(g, f, argc, argv, &ops);
    struct insert *in = &s->in;
    s->every_given = in->insert_every;
    if (in->insert_every == 0)
        gr_error(g, WHO ": 'insert_every' must be > 0");
    in->rrng_seed = MESH_SEED;
    rng_park_init(&in->rrng, MESH_SEED);
    f->hooks |= HOOK_END_OF_STEP;
    f->sources[f->nsources++] = "fix_insert_stream.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct stream *s = f->data;
    if (!s->face_id[0])
        gr_error(g, WHO ": must define an insertion face");
    geometry(g, s);
    insert_init(g, f);
    f->peratom_bytes = state_bytes(g);
    s->eos = eng_kernel(g, "insert_stream_end_of_step");
}

static void end_of_step(struct gravel *g, struct fix *f)
{
    struct stream *s = f->data;
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = s->eos;
    int rot = g->eng->rotation;
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_int(g, k, 3, (int)(f->peratom_bytes / sizeof(int)));
    eng_arg_mem(g, k, 4, f->peratom);
    eng_arg_int(g, k, 5, (int)(g->step - s->in.clock_shift));
    eng_arg_real(g, k, 6, g->dt);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, 7 + d, s->in.omega[d]);
    eng_arg_mem(g, k, 10, a->x);
    eng_arg_mem(g, k, 11, a->v);
    eng_arg_mem(g, k, 12, a->f);
    eng_arg_mem(g, k, 13, rot ? a->omega : a->v);
    eng_arg_mem(g, k, 14, rot ? a->torque : a->f);
    struct fix *ms = fix_find_style(g, "multisphere");
    eng_arg_uint(g, k, 15, ms ? rigid_small_member_bits(ms) : 0u);
    eng_arg_pos_lo(g, k, 16);
    eng_launch(g, k, (size_t)a->n);
}

static void destroy(struct fix *f)
{
    struct stream *s = f->data;
    if (s) {
        free(s->tri);
        free(s->acc);
    }
    insert_destroy(f);
}

const struct fix_style fix_style_insert_stream = {
    .name = "insert/stream",
    .create = create,
    .init = init,
    .pre_exchange = insert_pre_exchange,
    .end_of_step = end_of_step,
    .reserve = insert_reserve,
    .destroy = destroy,
    .write_restart = insert_write_restart,
    .read_restart = insert_read_restart,
    .reset_step = insert_reset_step,
    .size_vector = 2,
    .vector = insert_vector,
};
