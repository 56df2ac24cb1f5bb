/* wall.c - host side of the wall stage of the contact pipeline
 * (kernels/wall.cl): element counts, and where the wall kernels' arguments
 * are bound (the atoms and the law shared by every kind) and launched. */
#include "wall.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "mesh.h"
#include "neighbor.h"
#include "ocl.h"
#include "pair.h"

int wall_elements(const struct wall_geom *w) { return w->kind == WALL_PLANE ? 2 : 1; }

size_t wall_peratom_bytes(struct gravel *g, const struct wall_geom *w, const struct wall_law *law)
{
    return (size_t)wall_elements(w) * (size_t)law->history * g->eng->rsz;
}

struct wall_atoms_args wall_atoms_args(struct gravel *g)
{
    struct engine *e = g->eng;
    struct dev_atoms *a = eng_atoms(g);
    return (struct wall_atoms_args){
        .n = a->n,
        .mask = a->mask,
        .x = a->x,
        .v = a->v,
        .omega = e->rotation ? a->omega : a->v,
        .radius = a->radius,
        .rmass = e->contact_mass ? e->contact_mass : a->rmass, /* meff */
        .type = a->type,
        .f = a->f,
        .torque = e->rotation ? a->torque : a->f,
        .acc = acc_wall_rec(g),
        .astep = acc_wall_step(g),
        .step = acc_step(g),
        .temp = e->heat ? a->temperature : a->v,
        .heatflow = e->heat ? a->heatflow : a->f,
    };
}

struct wall_own_args wall_own_args(struct gravel *g, struct fix *f, const struct wall_law *law)
{
    return (struct wall_own_args){
        .groupbit = f->groupbit,
        .history = law->history ? f->peratom : eng_atoms(g)->f,
        .has_history = law->history,
        .acode = acc_wall_code(g, f),
        .wheat = g->eng->heat && law->heat,
        .twall = law->twall,
        .contacts = law->contacts_on ? law->contacts : eng_atoms(g)->f,
        .want_contacts = law->contacts_on,
    };
}

struct wall_law_args wall_law_args(struct gravel *g, const struct wall_law *law)
{
    return (struct wall_law_args){
        .param = law->param,
        .ntypes = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1,
        .nparam = !law->by_type ? 0 : law->nparam ? law->nparam : g->styles.pair->caps.nparam,
        .by_type = law->by_type,
    };
}

void wall_apply(struct gravel *g, struct fix *f, const struct wall_geom *w,
                const struct wall_law *law)
{
    struct wall_kernel_args ka = {
        .wall_atoms = wall_atoms_args(g),
        .wall_own = wall_own_args(g, f, law),
        .wall_law = wall_law_args(g, law),
        .nelem = wall_elements(w),
        .kind = (int)w->kind,
        .axis = w->axis,
        .wradius = w->radius,
        .vw = {w->v[0], w->v[1], w->v[2]},
        .cyl_shear = w->cyl_shear,
        .vshear = w->vshear,
        .dt = g->dt,
        .shearupdate = !eng_in_setup(g),
        .inclusive = law->inclusive,
    };
    if (w->kind == WALL_CYLINDER) { /* the axis (cx, cy) relative to the origin */
        ka.lo = ka_coord(g, (w->axis + 1) % 3, w->cx);
        ka.hi = ka_coord(g, (w->axis + 2) % 3, w->cy);
    } else {
        ka.lo = ka_coord(g, w->axis, w->lo);
        ka.hi = ka_coord(g, w->axis, w->hi);
    }
    nbr_halt_args(g, &ka.halt);
    ka_bind_wall_kernel(g, law->kernel, 0, &ka);
    eng_launch(g, law->kernel, (size_t)ka.wall_atoms.n);
}

/* ---- mesh walls -------------------------------------------------------------------- */

void wall_mesh_upload(struct gravel *g, struct wall_mesh *wm, const struct mesh *m,
                      const double *normal, double reach, double lskin, const char *who)
{
    wall_mesh_release(wm);
    struct mesh_bins b;
    char err[256];
    reach += lskin;
    if (mesh_bin(m, reach, &b, err, sizeof err))
        gr_error(g, "%s: %s", who, err);
    int nt = m->ntri, ncell = b.n[0] * b.n[1] * b.n[2];
    double *tri = malloc((size_t)nt * 12 * sizeof(double));
    if (!tri) {
        mesh_bins_free(&b);
        gr_error(g, "%s: out of memory for %d triangles", who, nt);
    }
    for (int t = 0; t < nt; t++) {
        for (int k = 0; k < 3; k++)
            memcpy(tri + 12 * t + 3 * k, m->vert + 3 * m->tri[3 * t + k], 3 * sizeof(double));
        memcpy(tri + 12 * t + 9, normal + 3 * t, 3 * sizeof(double));
    }
    size_t rsz = g->eng->rsz;
    int nlist = b.start[ncell];
    wm->tri = eng_alloc(g, (size_t)nt * 12 * rsz, "mesh triangles");
    wm->triv = eng_alloc(g, (size_t)nt * 3 * sizeof(int), "mesh vertex ids");
    wm->cstart = eng_alloc(g, ((size_t)ncell + 1) * sizeof(int), "mesh bins");
    wm->ctri = eng_alloc(g, (size_t)(nlist ? nlist : 1) * sizeof(int), "mesh bin lists");
    wm->pose = eng_alloc(g, POSE_N * rsz, "mesh pose");
    eng_write_reals(g, wm->tri, (size_t)nt * 12, tri);
    eng_write(g, wm->triv, 0, (size_t)nt * 3 * sizeof(int), m->tri);
    eng_write(g, wm->cstart, 0, ((size_t)ncell + 1) * sizeof(int), b.start);
    eng_write(g, wm->ctri, 0, (size_t)nlist * sizeof(int), b.list);
    free(tri);
    wm->ntri = nt;
    wm->reach = reach;
    wm->lskin = lskin;
    wm->mscale = 0;
    for (int v = 0; v < m->nvert; v++) {
        const double *p = m->vert + 3 * v;
        double l1 = fabs(p[0]) + fabs(p[1]) + fabs(p[2]);
        wm->mscale = l1 > wm->mscale ? l1 : wm->mscale;
    }
    memcpy(wm->gn, b.n, sizeof wm->gn);
    memcpy(wm->glo, b.lo, sizeof wm->glo);
    wm->h = b.h;
    mesh_bins_free(&b);
}

void wall_mesh_release(struct wall_mesh *wm)
{
    for (int k = 0; k < 2; k++) {
        if (wm->pose_ev[k]) {
            clWaitForEvents(1, &wm->pose_ev[k]);
            clReleaseEvent(wm->pose_ev[k]);
            wm->pose_ev[k] = NULL;
        }
        free(wm->pose_host[k]);
        wm->pose_host[k] = NULL;
    }
    cl_mem *m[] = {&wm->tri, &wm->triv, &wm->cstart, &wm->ctri, &wm->pose, &wm->mlist,
                   &wm->mlpos};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++)
        if (*m[i]) {
            clReleaseMemObject(*m[i]);
            *m[i] = NULL;
        }
    wm->lcap = 0;
    wm->pose_ok = 0;
}

/* The per-atom triangle lists for n atoms: zero (no tag is 0: every entry
 * stale) when they are (re)allocated; kept otherwise, as an entry names
 * its atom and the point it was built at. */
static void mesh_lists_reserve(struct gravel *g, struct wall_mesh *wm, int n)
{
    if (wm->mlist && wm->lcap >= (size_t)n)
        return;
    cl_mem *m[] = {&wm->mlist, &wm->mlpos};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++)
        if (*m[i]) {
            clReleaseMemObject(*m[i]);
            *m[i] = NULL;
        }
    size_t cap = (size_t)n + 64;
    wm->mlist = eng_alloc(g, cap * MESH_LIST_W * sizeof(int), "mesh triangle lists");
    wm->mlpos = eng_alloc(g, cap * MESH_LPOS_W * g->eng->rsz, "mesh triangle lists");
    eng_fill_zero(g, wm->mlist, cap * MESH_LIST_W * sizeof(int));
    eng_fill_zero(g, wm->mlpos, cap * MESH_LPOS_W * g->eng->rsz);
    wm->lcap = cap;
}

/* The pose to the device when it differs from the one there (a mesh that
 * does not move is written once), without waiting for the queue: the
 * write is ordered before the mesh kernel, and its host copy is kept until
 * it has completed (the copy's previous write is waited for, long done). */
static void mesh_pose_upload(struct gravel *g, struct wall_mesh *wm, const double *pose)
{
    if (wm->pose_ok && !memcmp(wm->pose_up, pose, sizeof wm->pose_up))
        return;
    int k = wm->pose_k = !wm->pose_k;
    if (wm->pose_ev[k]) {
        OCL_CHECK(g, clWaitForEvents(1, &wm->pose_ev[k]));
        clReleaseEvent(wm->pose_ev[k]);
        wm->pose_ev[k] = NULL;
    }
    if (!wm->pose_host[k])
        wm->pose_host[k] = gr_malloc(g, POSE_N * sizeof(double));
    if (g->eng->single)
        for (int q = 0; q < POSE_N; q++)
            ((float *)wm->pose_host[k])[q] = (float)pose[q];
    else
        memcpy(wm->pose_host[k], pose, POSE_N * sizeof(double));
    OCL_CHECK(g, clEnqueueWriteBuffer(g->eng->ocl.queue, wm->pose, CL_FALSE, 0,
                                      POSE_N * g->eng->rsz, wm->pose_host[k], 0, NULL,
                                      &wm->pose_ev[k]));
    memcpy(wm->pose_up, pose, sizeof wm->pose_up);
    wm->pose_ok = 1;
}

void wall_mesh_apply(struct gravel *g, struct fix *f, struct wall_mesh *wm,
                     const struct wall_law *law, const double R[9], const double d[3],
                     const double V0[3], const double omega[3], const double ref[3], int moving,
                     int hstride, int hoff, cl_mem fmesh, cl_mem mstress)
{
    struct dev_atoms *a = eng_atoms(g);
    double pose[POSE_N];
    memcpy(pose + POSE_R, R, 9 * sizeof(double));
    memcpy(pose + POSE_D, d, 3 * sizeof(double));
    memcpy(pose + POSE_V0, V0, 3 * sizeof(double));
    memcpy(pose + POSE_OMEGA, omega, 3 * sizeof(double));
    memcpy(pose + POSE_GLO, wm->glo, 3 * sizeof(double));
    pose[POSE_GINV] = 1.0 / wm->h;
    memcpy(pose + POSE_REF, ref, 3 * sizeof(double));
    /* device positions are relative to the origin: so are the pose's
     * translation and reference point, and a static mesh takes the moving
     * path (R = 1) when the origin is not 0 */
    const double *o = g->eng->origin;
    if (!moving && (o[0] != 0 || o[1] != 0 || o[2] != 0)) {
        static const double unit[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        memcpy(pose + POSE_R, unit, sizeof unit);
        memset(pose + POSE_D, 0, 3 * sizeof(double));
        moving = 1;
    }
    for (int q = 0; q < 3; q++) {
        pose[POSE_D + q] -= o[q];
        pose[POSE_REF + q] -= o[q];
    }
    mesh_pose_upload(g, wm, pose);
    mesh_lists_reserve(g, wm, a->n);
    struct mesh_kernel_args ka = {
        .wall_atoms = wall_atoms_args(g),
        .wall_own = wall_own_args(g, f, law),
        .hstride = hstride,
        .hoff = hoff,
        .wall_law = wall_law_args(g, law),
        .tri = wm->tri,
        .triv = wm->triv,
        .cstart = wm->cstart,
        .ctri = wm->ctri,
        .pose = wm->pose,
        .gn = {wm->gn[0], wm->gn[1], wm->gn[2]},
        .moving = moving,
        .fmesh = fmesh ? fmesh : a->f,
        .want_fmesh = fmesh != NULL,
        .mstress = mstress ? mstress : a->f,
        .want_mstress = mstress != NULL,
        .dt = g->dt,
        .shearupdate = !eng_in_setup(g),
        .inclusive = law->inclusive,
        .tag = a->tag,
        .mlist = wm->mlist,
        .mlpos = wm->mlpos,
        .lskin = wm->lskin,
        .lreach = wm->reach,
        .mscale = wm->mscale,
    };
    nbr_halt_args(g, &ka.halt);
    ka_bind_mesh_kernel(g, law->kernel, 0, &ka);
    eng_launch(g, law->kernel, (size_t)a->n);
}
