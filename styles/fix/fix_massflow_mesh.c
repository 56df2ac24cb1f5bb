/* fix_massflow_mesh.c - LIGGGHTS's `fix ID group massflow/mesh mesh MESH
 * vec_side vx vy vz [count once|multiple] [file F | append F] [writeTime]
 * [screen yes|no]`: the mass and number of particles of the group that pass
 * through the planar face of a fix mesh/surface towards vec_side (LIGGGHTS
 * 3.8 fix_massflow_mesh.cpp, reproduced). Global vector (f_ID[1..6]):
 *   1 mass through the face    2 particles through it
 *   3 mass flow rate           4 particle rate (both over the time since the
 *                                 last output that read the vector)
 *   5 mass deleted, 6 particles deleted (0: delete_atoms is not supported)
 *
 * Each particle carries a counter, kept by atom ID: -1 until it is first
 * near the face, then 0 on the face's back side, 1 on the vec_side side, 2
 * once counted with count once. Near: within r + skin/2 (r + skin for a
 * moving face) of a triangle by LIGGGHTS's neighbour test (the distance to
 * the triangle's plane and to each edge's outward plane), evaluated at every
 * neighbor rebuild as LIGGGHTS's mesh neighbour lists are. At every step,
 * for each triangle in turn and each particle near it: the first time, the
 * counter takes the particle's side; after, a particle on the vec_side side
 * (dot((x - p0), n) > 0, p0 triangle 0's first vertex, n its normal turned
 * towards vec_side) whose centre projects into the triangle (LIGGGHTS's
 * barycentric test, tolerance 1e-8 / (2 r_bound)) is counted if its counter
 * was 0, and its counter becomes 1 (2 with count once); a particle on the
 * back side resets it to 0. With file/append each counted particle writes
 * a line (ID, [time,] diameter, position, velocity) as LIGGGHTS, with screen
 * yes the same to the screen; the velocity is the half-step one LIGGGHTS's
 * post_integrate sees, v - dt f / 2m. Evaluated at the end of each step (LIGGGHTS:
 * post_integrate; the positions are the same); on several MPI ranks on
 * every rank's atoms gathered. The state (sums and every counter) is in
 * restart files. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "ave_common.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "fix_mesh_surface.h"
#include "log.h"
#include "par.h"

#define WHO "fix massflow/mesh"
#define MF_PRECISION 1e-8 /* LIGGGHTS's EPSILON_PRECISION of a mesh */

/* One triangle at the current pose, with what LIGGGHTS's TriMesh derives. */
struct mf_tri {
    double node[3][3], ev[3][3], len[3], normal[3], center[3], en[3][3], rbound;
};

struct massflow {
    char mesh[GR_NAMELEN];
    double side[3];
    int once, screen, write_time;
    struct ave_file af;             /* af.fp NULL: no file */
    double nvec[3], pref[3];        /* the face's reference point and normal towards side */
    double mass, np, mass_last, np_last, t_count, delta_t;
    int reset_t;                    /* LIGGGHTS's reset_t_count_ */
    signed char *counter;           /* by tag: -1, 0, 1, 2 */
    int64_t ncounter;
    int64_t *near, *near_start;     /* tags near each triangle: near[near_start[t] ..) */
    int *where;                     /* [nwhere] host index by tag (-1: none), each step */
    int64_t nwhere;
    int have_near;
};

static void mf_destroy(struct fix *f)
{
    struct massflow *m = f->data;
    if (m) {
        ave_file_close(&m->af);
        free(m->counter);
        free(m->near);
        free(m->near_start);
        free(m->where);
    }
    free(m);
    f->data = NULL;
}

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double mag(const double a[3]) { return sqrt(dot(a, a)); }

/* Triangle t of mesh ms at pose p, as LIGGGHTS's SurfaceMesh computes it */
static void tri_at(const struct mesh_surface *ms, const struct mesh_pose *p, int t,
                   struct mf_tri *T)
{
    for (int k = 0; k < 3; k++)
        mesh_pose_point(p, ms->m.vert + 3 * (size_t)ms->m.tri[3 * t + k], T->node[k]);
    for (int k = 0; k < 3; k++) {
        for (int d = 0; d < 3; d++)
            T->ev[k][d] = T->node[(k + 1) % 3][d] - T->node[k][d];
        T->len[k] = mag(T->ev[k]);
        for (int d = 0; d < 3; d++)
            T->ev[k][d] /= T->len[k];
    }
    cross(T->ev[0], T->ev[1], T->normal); /* the readers refuse degenerate triangles */
    const double nn = mag(T->normal);
    for (int d = 0; d < 3; d++)
        T->normal[d] /= nn;
    for (int k = 0; k < 3; k++) {
        cross(T->ev[k], T->normal, T->en[k]);
        const double e = mag(T->en[k]);
        for (int d = 0; d < 3; d++)
            T->en[k][d] /= e;
    }
    for (int d = 0; d < 3; d++)
        T->center[d] = (T->node[0][d] + T->node[1][d] + T->node[2][d]) / 3.0;
    T->rbound = 0;
    for (int k = 0; k < 3; k++) {
        double v[3] = {T->center[0] - T->node[k][0], T->center[1] - T->node[k][1],
                       T->center[2] - T->node[k][2]};
        T->rbound = fmax(T->rbound, mag(v));
    }
}

/* LIGGGHTS's resolveTriSphereNeighbuild: a sphere of radius r at x may come
 * within thr of triangle T */
static int tri_near(const struct mf_tri *T, const double *x, double r, double thr)
{
    const double maxd = r + thr;
    double v[3] = {x[0] - T->center[0], x[1] - T->center[1], x[2] - T->center[2]};
    if (fabs(dot(v, T->normal)) > maxd)
        return 0;
    for (int k = 0; k < 3; k++) {
        double w[3] = {x[0] - T->node[k][0], x[1] - T->node[k][1], x[2] - T->node[k][2]};
        const double d = dot(w, T->en[k]);
        if (d > 0 && d * d > maxd * maxd)
            return 0;
    }
    return 1;
}

/* LIGGGHTS's barySign of x on T (calcBaryTriCoords and its tolerance): 7
 * when the point projects into the triangle */
static int bary_sign(const struct mf_tri *T, const double *x)
{
    double ap[3] = {x[0] - T->node[0][0], x[1] - T->node[0][1], x[2] - T->node[0][2]};
    const double a = dot(ap, T->ev[0]), b = dot(ap, T->ev[2]), c = dot(T->ev[0], T->ev[2]);
    const double one_c2 = 1 - c * c;
    double bary[3];
    bary[1] = (a - b * c) / (T->len[0] * one_c2);
    bary[2] = (a * c - b) / (T->len[2] * one_c2);
    bary[0] = 1. - bary[1] - bary[2];
    const double tol = -MF_PRECISION * (1. / (2. * T->rbound));
    return (bary[0] > tol) + 2 * (bary[1] > tol) + 4 * (bary[2] > tol);
}

static void ref_point(struct gravel *g, struct massflow *m, const struct mesh_surface *ms,
                      const struct mesh_pose *p);

static void mf_create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct massflow *m = gr_calloc(g, 1, sizeof *m);
    f->data = m;
    const char *file = NULL;
    int append = 0, have_side = 0;
    for (int i = 0; i < argc; i++) {
        const char *kw = argv[i];
        if (!strcmp(kw, "vec_side")) {
            arg_need(g, argc, i, 3, kw);
            for (int d = 0; d < 3; d++)
                m->side[d] = arg_double(g, argv[i + 1 + d], "vec_side");
            if (mag(m->side) == 0.)
                gr_error(g, WHO ": vec_side > 0 required");
            have_side = 1;
            i += 3;
        } else if (!strcmp(kw, "mesh")) {
            arg_need(g, argc, i, 1, kw);
            mesh_surface_get(g, argv[++i], WHO);
            snprintf(m->mesh, sizeof m->mesh, "%s", argv[i]);
        } else if (!strcmp(kw, "count")) {
            arg_need(g, argc, i, 1, kw);
            if (!strcmp(argv[i + 1], "once"))
                m->once = 1;
            else if (!strcmp(argv[i + 1], "multiple"))
                m->once = 0;
            else
                gr_error(g, WHO ": expecting 'once' or 'multiple' after 'count'");
            i++;
        } else if (!strcmp(kw, "writeTime")) {
            m->write_time = 1;
        } else if (!strcmp(kw, "file") || !strcmp(kw, "append")) {
            arg_need(g, argc, i, 1, kw);
            file = argv[++i];
            append = kw[0] == 'a';
        } else if (!strcmp(kw, "screen")) {
            arg_need(g, argc, i, 1, kw);
            m->screen = arg_yesno(g, argv[++i], "screen");
        } else if (!strcmp(kw, "delete_atoms")) {
            arg_need(g, argc, i, 1, kw);
            if (arg_yesno(g, argv[++i], "delete_atoms"))
                gr_error(g, WHO ": delete_atoms yes is not supported (delete_atoms no)");
        } else if (!strcmp(kw, "point_at_outlet") || !strcmp(kw, "inside_out") ||
                   !strcmp(kw, "sum_property")) {
            gr_error(g, WHO ": keyword '%s' is not supported (mesh, vec_side, count, file, "
                        "append, writeTime, screen)", kw);
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s'", kw);
        }
    }
    if (!have_side)
        gr_error(g, WHO ": expecting keyword 'vec_side'");
    if (!m->mesh[0])
        gr_error(g, WHO ": expecting keyword 'mesh'");
    if (file) {
        ave_file_open(g, &m->af, file, append, WHO);
        fprintf(m->af.fp, "# ID%s diameter x y z u v w  (ex ey ez, color)\n",
                m->write_time ? " time " : "");
        ave_file_header_done(g, &m->af, WHO);
    }
    struct mesh_pose p; /* LIGGGHTS checks vec_side at once */
    mesh_surface_pose(g, m->mesh, &p);
    ref_point(g, m, mesh_surface_get(g, m->mesh, WHO), &p);
    m->reset_t = 1;
    f->hooks = HOOK_END_OF_STEP;
    f->size_vector = 6;
}

/* LIGGGHTS's setRefPoint: triangle 0's first vertex and its normal, turned
 * towards vec_side */
static void ref_point(struct gravel *g, struct massflow *m, const struct mesh_surface *ms,
                      const struct mesh_pose *p)
{
    struct mf_tri T;
    tri_at(ms, p, 0, &T);
    memcpy(m->pref, T.node[0], sizeof m->pref);
    memcpy(m->nvec, T.normal, sizeof m->nvec);
    const double d = dot(m->nvec, m->side);
    if (fabs(d) < 1e-6)
        gr_error(g, WHO ": need to change 'vec_side', it is currently in or too close to the "
                    "mesh plane (a moving mesh turns the face, not vec_side)");
    if (d < 0.)
        for (int k = 0; k < 3; k++)
            m->nvec[k] = -m->nvec[k];
}

static void mf_init(struct gravel *g, struct fix *f)
{
    struct massflow *m = f->data;
    struct mesh_surface *ms = mesh_surface_get(g, m->mesh, WHO);
    if (mesh_planar_check(&ms->m, mesh_surface_cos_tol(ms)) >= 0)
        gr_error(g, WHO ": requires a planar face mass flow measurement (mesh %s is not planar)",
                 m->mesh);
    struct mesh_pose p;
    mesh_surface_pose(g, m->mesh, &p);
    ref_point(g, m, ms, &p);
    m->have_near = 0;
}

/* room for tags up to top in the counters (new ones -1) */
static void counters_room(struct gravel *g, struct massflow *m, int64_t top)
{
    if (top < m->ncounter)
        return;
    int64_t n = top + 1 > 2 * m->ncounter ? top + 1 : 2 * m->ncounter;
    signed char *c = realloc(m->counter, (size_t)n);
    if (!c)
        gr_error(g, WHO ": out of memory for %lld counters", (long long)n);
    memset(c + m->ncounter, -1, (size_t)(n - m->ncounter));
    m->counter = c;
    m->ncounter = n;
}

/* every rank's atoms on several ranks (collective), the host arrays current */
static int host_begin(struct gravel *g)
{
    run_sync_host(g);
    const int gather = par_on(g) && !par_gathered(g);
    if (gather)
        par_gather_begin(g);
    return gather;
}

/* The tags near each triangle (LIGGGHTS's mesh neighbour lists), from the
 * host atoms: at every rebuild */
static void build_near(struct gravel *g, struct fix *f, struct massflow *m)
{
    const struct mesh_surface *ms = mesh_surface_get(g, m->mesh, WHO);
    struct mesh_pose p;
    mesh_surface_pose(g, m->mesh, &p);
    const double thr = p.moving ? g->neigh.skin : 0.5 * g->neigh.skin;
    const struct atoms *a = &g->atoms;
    const int *order = atoms_tag_order(g);
    const int nt = ms->m.ntri;
    free(m->near_start);
    m->near_start = gr_malloc(g, ((size_t)nt + 1) * sizeof *m->near_start);
    size_t cap = 16, n = 0;
    free(m->near);
    m->near = gr_malloc(g, cap * sizeof *m->near);
    for (int t = 0; t < nt; t++) {
        struct mf_tri T;
        tri_at(ms, &p, t, &T);
        m->near_start[t] = (int64_t)n;
        for (int q = 0; q < a->n; q++) {
            const int i = order[q];
            if (!(a->mask[i] & f->groupbit) || !tri_near(&T, a->x + 3 * (size_t)i, a->radius[i], thr))
                continue;
            if (n == cap) {
                cap *= 2;
                int64_t *r = realloc(m->near, cap * sizeof *r);
                if (!r)
                    gr_error(g, WHO ": out of memory for the face's neighbours");
                m->near = r;
            }
            m->near[n++] = a->tag[i];
        }
    }
    m->near_start[nt] = (int64_t)n;
    m->have_near = 1;
}

static void mf_post_neighbor(struct gravel *g, struct fix *f)
{
    const int gather = host_begin(g);
    build_near(g, f, f->data);
    if (gather)
        par_gather_end(g);
}

/* one counted particle's line (LIGGGHTS's format) */
static void report(struct gravel *g, struct massflow *m, int i)
{
    const struct atoms *a = &g->atoms;
    const double *x = a->x + 3 * (size_t)i, *f = a->f + 3 * (size_t)i;
    double v[3]; /* LIGGGHTS's post_integrate sees the half-step velocity */
    for (int d = 0; d < 3; d++)
        v[d] = a->v[3 * (size_t)i + d] - 0.5 * g->dt * f[d] / a->rmass[i];
    char line[256];
    int k = snprintf(line, sizeof line, "%lld", (long long)a->tag[i]);
    if (m->write_time)
        k += snprintf(line + k, sizeof line - (size_t)k, "  %4.4g ", g->dt * (double)g->step);
    snprintf(line + k, sizeof line - (size_t)k, " %4.4g %4.4g %4.4g %4.4g %4.4g %4.4g %4.4g",
             2. * a->radius[i], x[0], x[1], x[2], v[0], v[1], v[2]);
    if (m->screen)
        gr_print(g, " %s \n ", line);
    if (m->af.fp) {
        ave_file_begin(&m->af);
        fprintf(m->af.fp, "%s\n", line);
    }
}

static void mf_end_of_step(struct gravel *g, struct fix *f)
{
    struct massflow *m = f->data;
    const int gather = host_begin(g);
    if (!m->have_near)
        build_near(g, f, m);
    const struct mesh_surface *ms = mesh_surface_get(g, m->mesh, WHO);
    struct mesh_pose p;
    mesh_surface_pose(g, m->mesh, &p);
    if (p.moving)
        ref_point(g, m, ms, &p);
    m->t_count += g->dt;
    if (!m->reset_t) {
        m->np_last = m->np;
        m->mass_last = m->mass;
        m->reset_t = 1;
    }
    const struct atoms *a = &g->atoms;
    int64_t top = 0;
    for (int i = 0; i < a->n; i++)
        top = a->tag[i] > top ? a->tag[i] : top;
    counters_room(g, m, top);
    if (top + 1 > m->nwhere) { /* grown, never shrunk: no allocation per step */
        free(m->where);
        m->where = gr_malloc(g, ((size_t)top + 1) * sizeof *m->where);
        m->nwhere = top + 1;
    }
    int *where = m->where;
    for (int64_t t = 0; t <= top; t++)
        where[t] = -1;
    for (int i = 0; i < a->n; i++)
        where[a->tag[i]] = i;
    double mass_this = 0, np_this = 0;
    int reported = 0;
    for (int t = 0; t < ms->m.ntri; t++) {
        struct mf_tri T;
        tri_at(ms, &p, t, &T);
        for (int64_t q = m->near_start[t]; q < m->near_start[t + 1]; q++) {
            const int64_t tag = m->near[q];
            const int i = tag <= top ? where[tag] : -1;
            if (i < 0 || !(a->mask[i] & f->groupbit) || m->counter[tag] == 2)
                continue;
            const double *x = a->x + 3 * (size_t)i;
            const int sign = bary_sign(&T, x);
            double delta[3] = {x[0] - m->pref[0], x[1] - m->pref[1], x[2] - m->pref[2]};
            const double d = dot(delta, m->nvec);
            if (m->counter[tag] == -1) { /* first time near: its side */
                m->counter[tag] = d <= 0. ? 0 : 1;
                continue;
            }
            if (d > 0. && sign == 7) {
                if (m->counter[tag] == 0) {
                    mass_this += a->rmass[i];
                    np_this += 1.;
                    if (m->screen || m->af.fp) {
                        report(g, m, i);
                        reported = 1;
                    }
                }
                m->counter[tag] = m->once ? 2 : 1;
            } else if (d <= 0.) {
                m->counter[tag] = 0;
            }
        }
    }
    m->mass += mass_this;
    m->np += np_this;
    if (reported && m->af.fp)
        ave_file_end(g, &m->af, WHO, f->id);
    if (gather)
        par_gather_end(g);
}

static double mf_vector(struct gravel *g, struct fix *f, int i)
{
    (void)g;
    struct massflow *m = f->data;
    if (m->reset_t) { /* the first read since the last step's sums */
        m->delta_t = m->t_count;
        m->t_count = 0.;
        m->reset_t = 0;
    }
    switch (i) {
    case 1: return m->mass;
    case 2: return m->np;
    case 3: return m->delta_t == 0. ? 0. : (m->mass - m->mass_last) / m->delta_t;
    case 4: return m->delta_t == 0. ? 0. : (m->np - m->np_last) / m->delta_t;
    default: return 0.;
    }
}

/* restart: the sums, the rate state and every counter by tag */
#define MF_NSTATE 8
static size_t mf_write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const struct massflow *m = f->data;
    const size_t need = MF_NSTATE * sizeof(double) + sizeof(int64_t) + (size_t)m->ncounter;
    if (!buf || cap < need)
        return need;
    const double s[MF_NSTATE] = {m->mass, m->np, m->mass_last, m->np_last, m->t_count,
                                 m->delta_t, (double)m->reset_t, 0.};
    memcpy(buf, s, sizeof s);
    memcpy(buf + sizeof s, &m->ncounter, sizeof m->ncounter);
    if (m->ncounter)
        memcpy(buf + sizeof s + sizeof m->ncounter, m->counter, (size_t)m->ncounter);
    return need;
}

static void mf_read_restart(struct gravel *g, struct fix *f, const unsigned char *buf,
                            size_t len)
{
    struct massflow *m = f->data;
    double s[MF_NSTATE];
    int64_t n;
    if (len < sizeof s + sizeof n)
        gr_error(g, WHO " %s: restart state of %zu bytes is too short", f->id, len);
    memcpy(s, buf, sizeof s);
    memcpy(&n, buf + sizeof s, sizeof n);
    if (n < 0 || len != sizeof s + sizeof n + (size_t)n)
        gr_error(g, WHO " %s: restart state of %zu bytes does not hold %lld counters", f->id,
                 len, (long long)n);
    m->mass = s[0], m->np = s[1], m->mass_last = s[2], m->np_last = s[3];
    m->t_count = s[4], m->delta_t = s[5], m->reset_t = s[6] != 0.;
    free(m->counter);
    m->counter = NULL;
    m->ncounter = 0;
    if (n) {
        counters_room(g, m, n - 1);
        memcpy(m->counter, buf + sizeof s + sizeof n, (size_t)n);
    }
}

const struct fix_style fix_style_massflow_mesh = {
    .name = "massflow/mesh",
    .flags = FIX_OUTPUT,
    .create = mf_create,
    .init = mf_init,
    .end_of_step = mf_end_of_step,
    .post_neighbor = mf_post_neighbor,
    .destroy = mf_destroy,
    .size_vector = 6,
    .vector = mf_vector,
    .write_restart = mf_write_restart,
    .read_restart = mf_read_restart,
};
