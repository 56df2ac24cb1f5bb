/* fix_mesh_surface.c - `fix ID group mesh/surface file F type T [keywords]`:
 * a triangle mesh wall read from an STL (ASCII or binary) or legacy VTK
 * file (src/state/mesh.c: welding, validation, adjacency), LIGGGHTS syntax.
 *
 *   type T                 material type of the wall (required, 1..ntypes)
 *   scale s                multiply every coordinate by s
 *   move dx dy dz          translate
 *   rotate axis ax ay az angle deg   rotate about an axis through the origin
 *   precision tol          weld vertices closer than tol (default 1e-10 of the
 *                          bounding-box diagonal)
 *   reference_point x y z  point the mesh torque is taken about (default: the
 *                          origin of the first move/mesh rotate on the mesh,
 *                          else 0 0 0); it moves with the mesh
 *   temperature T0, curvature c, heal auto_remove_duplicates|no, verbose
 *   yes|no                 accepted as in LIGGGHTS (no effect here, but
 *                          curvature's angle on mesh/surface/planar)
 * scale, move and rotate apply in the order they are given, once, at the
 * command. The mesh acts on particles through `fix wall/gran ... mesh`,
 * moves with `fix move/mesh`, and is written by `dump mesh/vtk`.
 *
 * Global vector (thermo f_ID[i]), from the wall fix's contacts at the
 * current step: 1-3 force of the particles on the mesh, 4-6 its torque about
 * the reference point, 7 the power the mesh motion delivers to the
 * particles, -(F . v(ref) + T . omega) (for a mesh rotating about an axis
 * through ref: -T . omega, the drive's power draw). Sums run in tag order,
 * so they do not depend on the device order of the atoms.
 *
 * `fix ID group mesh/surface/planar ...` (same keywords): the same mesh,
 * which must be planar (LIGGGHTS's test: neighbours across an edge within
 * the curvature angle, default |n_a . n_b| > 1 - 1e-5), with LIGGGHTS's
 * lists of nearest active edges for fix insert/stream's all_in yes
 * (src/state/mesh_planar.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "fix_mesh_surface_stress.h"
#include "par_sum.h"
#include "pair.h"
#include "rigid_math.h"

double mesh_surface_tri_normal(const struct mesh *m, int t, double n[3])
{
    const double *a = m->vert + 3 * m->tri[3 * t], *b = m->vert + 3 * m->tri[3 * t + 1],
                 *c = m->vert + 3 * m->tri[3 * t + 2];
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double x[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    double len = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    for (int d = 0; d < 3; d++)
        n[d] = x[d] / len;
    return 0.5 * len;
}

void mesh_surface_normals(struct gravel *g, struct mesh_surface *ms)
{
    free(ms->normal);
    ms->normal = gr_malloc(g, (size_t)ms->m.ntri * 3 * sizeof(double));
    for (int t = 0; t < ms->m.ntri; t++)
        mesh_surface_tri_normal(&ms->m, t, ms->normal + 3 * t);
}

void mesh_surface_create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[0], "file") != 0)
        gr_error(g, "fix mesh/surface expects 'file F type T' (got %s)",
                 argc ? argv[0] : "nothing");
    const char *file = argv[1];
    int type = 0;
    double tol = 0;
    struct mesh_surface *ms = gr_calloc(g, 1, sizeof *ms);
    f->data = ms;   /* freed by destroy() if an error follows */
    /* first pass: options that the reading needs */
    for (int i = 2; i < argc; i++)
        if (!strcmp(argv[i], "precision") && i + 1 < argc)
            tol = arg_positive(g, argv[i + 1], "precision");
    char err[512];
    if (mesh_read(file, tol, &ms->m, err, sizeof err))
        gr_error(g, "fix mesh/surface: %s", err);
    int i = 2;
    while (i < argc) {
        const char *kw = argv[i];
        if (!strcmp(kw, "type")) {
            arg_need(g, argc, i, 1, kw);
            type = arg_int(g, argv[i + 1], "mesh type");
            if (type < 1 || (g->atoms.ntypes > 0 && type > g->atoms.ntypes))
                gr_error(g, "fix mesh/surface type %d is out of range 1..%d", type,
                         g->atoms.ntypes);
            i += 2;
        } else if (!strcmp(kw, "scale")) {
            arg_need(g, argc, i, 1, kw);
            mesh_scale(&ms->m, arg_positive(g, argv[i + 1], "scale factor"));
            i += 2;
        } else if (!strcmp(kw, "move")) {
            arg_need(g, argc, i, 3, kw);
            double d[3];
            for (int k = 0; k < 3; k++)
                d[k] = arg_double(g, argv[i + 1 + k], "move offset");
            mesh_move(&ms->m, d);
            i += 4;
        } else if (!strcmp(kw, "rotate")) {
            arg_need(g, argc, i, 6, kw);
            if (strcmp(argv[i + 1], "axis") || strcmp(argv[i + 5], "angle"))
                gr_error(g, "fix mesh/surface rotate expects 'axis ax ay az angle deg'");
            double a[3];
            for (int k = 0; k < 3; k++)
                a[k] = arg_double(g, argv[i + 2 + k], "rotate axis");
            if (rm_unit_axis(a, a))
                gr_error(g, "fix mesh/surface rotate axis is zero");
            mesh_rotate(&ms->m, a, arg_double(g, argv[i + 6], "rotate angle"));
            i += 7;
        } else if (!strcmp(kw, "precision") || !strcmp(kw, "temperature") ||
                   !strcmp(kw, "curvature")) {
            arg_need(g, argc, i, 1, kw);
            double v = arg_double(g, argv[i + 1], kw);
            if (!strcmp(kw, "temperature"))
                ms->temperature = v;
            else if (!strcmp(kw, "curvature"))
                ms->curvature = v;
            i += 2;
        } else if (!strcmp(kw, "heal")) {
            arg_need(g, argc, i, 1, kw);
            if (strcmp(argv[i + 1], "auto_remove_duplicates") && strcmp(argv[i + 1], "no"))
                gr_error(g, "fix mesh/surface heal expects auto_remove_duplicates or no, got "
                            "'%.64s'", argv[i + 1]);
            i += 2;
        } else if (!strcmp(kw, "verbose")) {
            arg_need(g, argc, i, 1, kw);
            arg_yesno(g, argv[i + 1], "verbose");
            i += 2;
        } else if (!strcmp(kw, "surface_vel")) {
            arg_need(g, argc, i, 3, kw);
            for (int k = 0; k < 3; k++)
                ms->surface_vel[k] = arg_double(g, argv[i + 1 + k], "surface_vel");
            ms->has_surface_vel = 1;
            i += 4;
        } else if (!strcmp(kw, "reference_point")) {
            arg_need(g, argc, i, 3, kw);
            for (int k = 0; k < 3; k++)
                ms->ref[k] = arg_double(g, argv[i + 1 + k], "reference point");
            ms->ref_set = 1;
            i += 4;
        } else {
            gr_error(g, "unknown fix mesh/surface keyword '%.64s' (expected type, scale, move, "
                        "rotate, precision, reference_point, surface_vel, temperature, curvature, "
                        "heal or verbose)", kw);
        }
    }
    if (!type)
        gr_error(g, "fix mesh/surface needs 'type T' (the wall's material type)");
    if (mesh_check_range(&ms->m, file, err, sizeof err))
        gr_error(g, "fix mesh/surface: %s", err);
    ms->type = type;
    ms->cache_step = -1;
    mesh_surface_normals(g, ms);
    /* LIGGGHTS gives each triangle surface_vel projected on its plane and scaled back to
     * |surface_vel|: one velocity for the mesh only when it lies in every triangle */
    for (int t = 0; ms->has_surface_vel && t < ms->m.ntri; t++) {
        const double *n = ms->normal + 3 * t, *v = ms->surface_vel;
        double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
        if (fabs(vn) > 1e-6 * sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]))
            gr_error(g, "fix mesh/surface: surface_vel is not in the plane of triangle %d (a "
                        "surface velocity that turns with the triangles is not supported)", t);
    }
    f->hooks = 0;
}

double mesh_surface_cos_tol(const struct mesh_surface *ms)
{
    const double c = ms->curvature;
    return c > 0. ? cos(c * M_PI / 180.) : 1. - 1e-5; /* LIGGGHTS's curvature_ */
}

static void create_planar(struct gravel *g, struct fix *f, int argc, char **argv)
{
    mesh_surface_create(g, f, argc, argv);
    struct mesh_surface *ms = f->data;
    double c = ms->curvature;
    if (c != 0. && !(c > 0. && c <= 60.))
        gr_error(g, "fix mesh/surface/planar: 0 < curvature <= 60 degrees required (got %g)", c);
    int t = mesh_planar_check(&ms->m, mesh_surface_cos_tol(ms));
    if (t >= 0)
        gr_error(g, "fix mesh/surface/planar: Face defined as planar face is in fact not planar "
                    "(triangle %d and a neighbour). You might want to check the 'curvature' "
                    "setting", t);
    if (mesh_planar_build(&ms->m, &ms->edges))
        gr_error(g, "fix mesh/surface/planar: out of memory");
    ms->planar = 1;
}

int fix_is_mesh_surface(const struct fix *f)
{
    return f->style == &fix_style_mesh_surface || f->style == &fix_style_mesh_surface_planar ||
           f->style == &fix_style_mesh_surface_stress;
}

void mesh_surface_free(struct mesh_surface *ms)
{
    mesh_free(&ms->m);
    mesh_planar_free(&ms->edges);
    free(ms->normal);
    ms->normal = NULL;
    free(ms->model);
    ms->model = NULL;
    if (ms->fmesh)
        clReleaseMemObject(ms->fmesh);
    ms->fmesh = NULL;
    mesh_stress_free(ms->stress);
    ms->stress = NULL;
}

void mesh_surface_destroy(struct fix *f)
{
    struct mesh_surface *ms = f->data;
    if (ms)
        mesh_surface_free(ms);
    free(ms);
    f->data = NULL;
}

struct mesh_surface *mesh_surface_get(struct gravel *g, const char *id, const char *who)
{
    struct fix *f = fix_find(g, id);
    if (!f)
        gr_error(g, "%s: no fix with ID '%.64s' (expected a fix mesh/surface)", who, id);
    if (!fix_is_mesh_surface(f))
        gr_error(g, "%s: fix %s is a %s fix, not mesh/surface", who, id, f->style->name);
    return f->data;
}

int mesh_surface_parse_list(struct gravel *g, int argc, char **argv, int i,
                            char (*ids)[GR_NAMELEN], int max, int *n, const char *who)
{
    if (i + 2 >= argc || strcmp(argv[i + 1], "n_meshes"))
        gr_error(g, "%s expects 'n_meshes N meshes ID ...'", who);
    *n = arg_int_range(g, argv[i + 2], 1, max, "n_meshes");
    if (i + 3 >= argc || strcmp(argv[i + 3], "meshes"))
        gr_error(g, "%s expects 'meshes' and %d mesh ID(s) after n_meshes", who, *n);
    if (i + 3 + *n >= argc)
        gr_error(g, "%s: n_meshes is %d but %d mesh ID(s) follow", who, *n, argc - i - 4);
    for (int m = 0; m < *n; m++) {
        const char *id = argv[i + 4 + m];
        mesh_surface_get(g, id, who);
        for (int q = 0; q < m; q++)
            if (!strcmp(ids[q], id))
                gr_error(g, "%s: mesh %s is listed twice", who, id);
        snprintf(ids[m], GR_NAMELEN, "%s", id);
    }
    return i + 4 + *n;
}

void mesh_surface_claim(struct gravel *g, struct mesh_surface *ms, const char *mesh_id,
                        const struct fix *f)
{
    for (int k = 0; ms->owner && ms->owner != f && k < g->styles.nfix; k++)
        if (g->styles.fix[k] == ms->owner)
            gr_error(g, "fix %s: mesh %s is already a wall of fix %s", f->id, mesh_id,
                     ms->owner->id);
    ms->owner = f;
    ms->fmesh_valid = 0;
}

void mesh_surface_filled(struct gravel *g, struct mesh_surface *ms)
{
    ms->fmesh_valid = 1;
    ms->fmesh_step = g->step;
}

void mesh_surface_fmesh_reserve(struct gravel *g, struct mesh_surface *ms, int n)
{
    if (ms->fmesh && ms->fmesh_cap >= (size_t)n)
        return;
    if (ms->fmesh)
        clReleaseMemObject(ms->fmesh);
    ms->fmesh = NULL;
    ms->fmesh_cap = (size_t)n + 64;
    ms->fmesh = eng_alloc(g, ms->fmesh_cap * 6 * eng_get(g)->rsz, "mesh force buffer");
}

size_t mesh_walls_init(struct gravel *g, struct fix *f, struct mesh_walls *mw, int history)
{
    double reach = eng_get(g)->insert_rmax; /* atoms fix pour may insert */
    for (int i = 0; i < g->atoms.n; i++)
        reach = g->atoms.radius[i] > reach ? g->atoms.radius[i] : reach;
    /* a pair style that takes contacts one drift away (linear/restitution)
     * needs the triangles within the skin of the atom's bin too; every atom
     * keeps a list of the triangles a skin beyond its radius (the neighbor
     * skin, or a tenth of the largest radius without one), which stands in
     * for its bin while it moves less than half that, less its drift
     * (kernels/wall.cl mesh_candidates) */
    int approach = g->styles.pair && g->styles.pair->caps.approach;
    if (approach)
        reach += g->neigh.skin;
    reach *= 1.0 + 1e-6;
    double lskin = g->neigh.skin > 0 ? g->neigh.skin : 0.1 * reach;
    char who[GR_NAMELEN + 32];
    snprintf(who, sizeof who, "fix %s (%s mesh)", f->id, f->style->name);
    for (int m = 0; m < mw->n; m++) {
        struct mesh_surface *ms = mw->own[m] ? mw->own[m] : mesh_surface_get(g, mw->id[m], who);
        if (!mw->own[m])
            mesh_surface_claim(g, ms, mw->id[m], f);
        wall_mesh_upload(g, &mw->wm[m], &ms->m, ms->normal, reach, lskin, who);
    }
    /* per mesh WALL_MESH_SLOTS slots of a key and the law's history REAL */
    return history ? (size_t)mw->n * WALL_MESH_SLOTS * (1 + history) * eng_get(g)->rsz : 0;
}

void mesh_walls_apply(struct gravel *g, struct fix *f, struct mesh_walls *mw,
                      struct wall_law *law, int pair_types)
{
    struct dev_atoms *a = eng_atoms(g);
    for (int m = 0; m < mw->n; m++) {
        struct mesh_surface *ms =
            mw->own[m] ? mw->own[m] : mesh_surface_get(g, mw->id[m], f->style->name);
        struct mesh_pose p;
        mesh_surface_pose_of(g, ms, mw->own[m] ? NULL : mw->id[m], &p);
        double ref[3];
        mesh_pose_point(&p, ms->ref, ref);
        mesh_surface_fmesh_reserve(g, ms, a->n);
        if (pair_types)
            law->by_type = ms->type;
        wall_mesh_apply(g, f, &mw->wm[m], law, p.R, p.d, p.V0, p.omega, ref, p.moving,
                        mw->n * WALL_MESH_SLOTS * (1 + law->history),
                        m * WALL_MESH_SLOTS * (1 + law->history), ms->fmesh,
                        mesh_stress_records(g, ms->stress, a->n));
        mesh_surface_filled(g, ms);
    }
}

void mesh_walls_release(struct mesh_walls *mw)
{
    for (int m = 0; m < mw->n; m++) {
        wall_mesh_release(&mw->wm[m]);
        if (mw->own[m]) {
            mesh_surface_free(mw->own[m]);
            free(mw->own[m]);
            mw->own[m] = NULL;
        }
    }
}

/* ---- pose ------------------------------------------------------------------------ */

static void mat_mul(const double A[9], const double B[9], double C[9])
{
    double T[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            T[3 * r + c] = A[3 * r] * B[c] + A[3 * r + 1] * B[3 + c] + A[3 * r + 2] * B[6 + c];
    memcpy(C, T, sizeof T);
}

static void mat_vec(const double A[9], const double v[3], double out[3])
{
    double t[3];
    for (int r = 0; r < 3; r++)
        t[r] = A[3 * r] * v[0] + A[3 * r + 1] * v[1] + A[3 * r + 2] * v[2];
    memcpy(out, t, sizeof t);
}

void mesh_surface_bake(struct gravel *g, const char *id)
{
    struct mesh_surface *ms = mesh_surface_get(g, id, "unfix");
    struct mesh_pose p;
    mesh_surface_pose(g, id, &p);
    for (int v = 0; v < ms->m.nvert; v++)
        mesh_pose_point(&p, ms->m.vert + 3 * v, ms->m.vert + 3 * v);
    for (int t = 0; t < ms->m.ntri; t++)
        mesh_pose_vector(&p, ms->normal + 3 * t, ms->normal + 3 * t);
    mesh_pose_point(&p, ms->ref, ms->ref);
}

void mesh_pose_vector(const struct mesh_pose *p, const double v0[3], double v[3])
{
    mat_vec(p->R, v0, v);
}

void mesh_pose_point(const struct mesh_pose *p, const double x0[3], double x[3])
{
    mat_vec(p->R, x0, x);
    for (int r = 0; r < 3; r++)
        x[r] += p->d[r];
}

void mesh_pose_velocity(const struct mesh_pose *p, const double x[3], double u[3])
{
    const double *om = p->omega;
    u[0] = p->V0[0] + om[1] * x[2] - om[2] * x[1];
    u[1] = p->V0[1] + om[2] * x[0] - om[0] * x[2];
    u[2] = p->V0[2] + om[0] * x[1] - om[1] * x[0];
}

void mesh_surface_pose(struct gravel *g, const char *id, struct mesh_pose *p)
{
    mesh_surface_pose_of(g, NULL, id, p);
}

void mesh_surface_pose_of(struct gravel *g, const struct mesh_surface *ms, const char *id,
                          struct mesh_pose *p)
{
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, Rd[9] = {0}, d[3] = {0}, dd[3] = {0};
    int moving = 0;
    const int nown = ms ? ms->nmotion : 0;
    for (int k = -nown; k < g->styles.nfix; k++) {
        const struct mesh_motion *mo;
        if (k < 0) {
            mo = &ms->motion[k + nown];
        } else {
            struct fix *f = g->styles.fix[k];
            if (!id || f->style != &fix_style_move_mesh ||
                strcmp(((struct mesh_motion *)f->data)->mesh, id))
                continue;
            mo = f->data;
        }
        double t = (double)(g->step - mo->time_origin) * g->dt;
        double Rk[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, Rdk[9] = {0}, dk[3] = {0}, ddk[3] = {0};
        if (mo->kind == MOVE_LINEAR) {
            for (int c = 0; c < 3; c++) {
                dk[c] = mo->v[c] * t;
                ddk[c] = mo->v[c];
            }
        } else if (mo->kind == MOVE_WIGGLE) {
            double w = 2.0 * M_PI / mo->period;
            for (int c = 0; c < 3; c++) {
                dk[c] = mo->v[c] * sin(w * t);
                ddk[c] = mo->v[c] * w * cos(w * t);
            }
        } else {
            double w = 2.0 * M_PI / mo->period;
            const double *a = mo->axis, *o = mo->origin;
            mesh_rotation_matrix(a, w * t, Rk);
            double W[9] = {0, -a[2] * w, a[1] * w, a[2] * w, 0, -a[0] * w, -a[1] * w, a[0] * w, 0};
            mat_mul(W, Rk, Rdk);
            double Ro[3], Rdo[3];
            mat_vec(Rk, o, Ro);
            mat_vec(Rdk, o, Rdo);
            for (int c = 0; c < 3; c++) {
                dk[c] = o[c] - Ro[c];
                ddk[c] = -Rdo[c];
            }
        }
        /* compose: T = T_k o T; R' = Rk R, Rd' = Rdk R + Rk Rd, d' = Rk d + dk,
         * dd' = Rdk d + Rk dd + ddk */
        double nR[9], a1[9], a2[9], nd[3], b1[3], b2[3], b3[3];
        mat_mul(Rk, R, nR);
        mat_mul(Rdk, R, a1);
        mat_mul(Rk, Rd, a2);
        mat_vec(Rk, d, nd);
        mat_vec(Rdk, d, b1);
        mat_vec(Rk, dd, b2);
        for (int c = 0; c < 3; c++) {
            b3[c] = b1[c] + b2[c] + ddk[c];
            nd[c] += dk[c];
        }
        memcpy(R, nR, sizeof R);
        for (int c = 0; c < 9; c++)
            Rd[c] = a1[c] + a2[c];
        memcpy(d, nd, sizeof d);
        memcpy(dd, b3, sizeof dd);
        moving = 1;
    }
    memset(p, 0, sizeof *p);
    memcpy(p->R, R, sizeof R);
    memcpy(p->d, d, sizeof d);
    p->moving = moving;
    const struct mesh_surface *sm = ms ? ms : mesh_surface_get(g, id, "mesh pose");
    if (sm->has_surface_vel) { /* the surface moves, the mesh stays (no move/mesh: create) */
        memcpy(p->V0, sm->surface_vel, sizeof p->V0);
        p->moving = 1;
        return;
    }
    if (!moving)
        return;
    /* [omega]x = Rd R^T */
    double W[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            W[3 * r + c] = Rd[3 * r] * R[3 * c] + Rd[3 * r + 1] * R[3 * c + 1] +
                           Rd[3 * r + 2] * R[3 * c + 2];
    p->omega[0] = 0.5 * (W[7] - W[5]);
    p->omega[1] = 0.5 * (W[2] - W[6]);
    p->omega[2] = 0.5 * (W[3] - W[1]);
    const double *om = p->omega;
    double oxd[3] = {om[1] * d[2] - om[2] * d[1], om[2] * d[0] - om[0] * d[2],
                     om[0] * d[1] - om[1] * d[0]};
    for (int c = 0; c < 3; c++)
        p->V0[c] = dd[c] - oxd[c];
}

/* ---- global vector ---------------------------------------------------------------- */

static const int64_t *sort_tag;
static int cmp_tag(const void *a, const void *b)
{
    int64_t x = sort_tag[*(const int *)a], y = sort_tag[*(const int *)b];
    return x < y ? -1 : x > y;
}

double mesh_surface_vector(struct gravel *g, struct fix *f, int i)
{
    struct mesh_surface *ms = f->data;
    if (ms->cache_step != g->step || !ms->fmesh_valid || ms->fmesh_step != g->step) {
        memset(ms->cache, 0, sizeof ms->cache);
        struct engine *e = g->eng;
        if (ms->fmesh_valid && ms->fmesh_step == g->step && e && e->active) {
            struct dev_atoms *a = eng_atoms(g);
            int n = a->n;
            double *fm = gr_malloc(g, (size_t)(n ? n : 1) * 6 * sizeof(double));
            int64_t *tag = gr_malloc(g, (size_t)(n ? n : 1) * sizeof(int64_t));
            int *idx = gr_malloc(g, (size_t)(n ? n : 1) * sizeof(int));
            eng_read_reals(g, ms->fmesh, (size_t)n * 6, fm);
            eng_read(g, a->tag, 0, (size_t)n * sizeof(int64_t), tag);
            for (int k = 0; k < n; k++)
                idx[k] = k;
            sort_tag = tag;
            qsort(idx, (size_t)n, sizeof *idx, cmp_tag);
            for (int c = 0; c < 6; c++) { /* every rank's atoms, in tag order */
                struct par_sum sum = {0};
                for (int k = 0; k < n; k++)
                    par_sum_add(g, &sum, tag[idx[k]], fm[6 * idx[k] + c]);
                ms->cache[c] = par_sum_total(g, &sum);
            }
            free(fm);
            free(tag);
            free(idx);
            struct mesh_pose p;
            mesh_surface_pose(g, f->id, &p);
            double ref[3], vref[3];
            mesh_pose_point(&p, ms->ref, ref);
            mesh_pose_velocity(&p, ref, vref);
            const double *om = p.omega;
            double pw = 0;
            for (int c = 0; c < 3; c++)
                pw += ms->cache[c] * vref[c] + ms->cache[3 + c] * om[c];
            ms->cache[6] = 0.0 - pw; /* +0 when nothing moves */
        }
        ms->cache_step = g->step;
    }
    return ms->cache[i - 1];
}

/* reset_timestep: the mesh force and its sums still describe the same
 * state, now labelled with the shifted step */
void mesh_surface_reset_step(struct gravel *g, struct fix *f, bigint shift)
{
    (void)g;
    struct mesh_surface *ms = f->data;
    if (ms->fmesh_valid)
        ms->fmesh_step += shift;
    if (ms->cache_step >= 0)
        ms->cache_step += shift;
}

const struct fix_style fix_style_mesh_surface = {
    .name = "mesh/surface",
    .reset_step = mesh_surface_reset_step,
    .create = mesh_surface_create,
    .destroy = mesh_surface_destroy,
    .size_vector = 7,
    .vector = mesh_surface_vector,
};

const struct fix_style fix_style_mesh_surface_planar = {
    .name = "mesh/surface/planar",
    .reset_step = mesh_surface_reset_step,
    .create = create_planar,
    .destroy = mesh_surface_destroy,
    .size_vector = 7,
    .vector = mesh_surface_vector,
};
