/* mesh_planar.c - LIGGGHTS's planar meshes (TriMeshPlanar): planarity,
 * nearest active edge lists, the all_in distance test. The arithmetic
 * follows LIGGGHTS's (SurfaceMesh::calcEdgeVecLen, calcSurfaceNorm,
 * calcEdgeNormals, edgePointDist) operation by operation, so that a random
 * point is kept or redrawn exactly as there. Contract: mesh_planar.h. */
#include <math.h>
#include <stdlib.h>

#include "mesh_planar.h"

/* LIGGGHTS's per-triangle edge frame: unit edge vectors, lengths, the unit
 * surface normal (unit edges 0 and 1 crossed) and the in-plane edge normals
 * (edge x normal). */
struct tri_frame {
    const double *node[3];
    double vec[3][3], len[3], norm[3], enorm[3][3];
};

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double mag(const double v[3])
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

static void div_by(double v[3], double s)
{
    const double inv = 1. / s;
    for (int d = 0; d < 3; d++)
        v[d] = inv * v[d];
}

static void frame(const struct mesh *m, int t, struct tri_frame *f)
{
    for (int k = 0; k < 3; k++)
        f->node[k] = m->vert + 3 * m->tri[3 * t + k];
    for (int k = 0; k < 3; k++) {
        for (int d = 0; d < 3; d++)
            f->vec[k][d] = f->node[(k + 1) % 3][d] - f->node[k][d];
        f->len[k] = mag(f->vec[k]);
        div_by(f->vec[k], f->len[k]);
    }
    cross(f->vec[0], f->vec[1], f->norm);
    div_by(f->norm, mag(f->norm));
    for (int k = 0; k < 3; k++) {
        cross(f->vec[k], f->norm, f->enorm[k]);
        div_by(f->enorm[k], mag(f->enorm[k]));
    }
}

static double frame_edge_dist(const struct tri_frame *f, int k, const double x[3])
{
    double r[3];
    for (int d = 0; d < 3; d++)
        r[d] = x[d] - f->node[k][d];
    double dot = f->vec[k][0] * r[0] + f->vec[k][1] * r[1] + f->vec[k][2] * r[2];
    if (dot < 0)
        return mag(r);
    if (dot > f->len[k]) {
        for (int d = 0; d < 3; d++)
            r[d] = x[d] - f->node[(k + 1) % 3][d];
        return mag(r);
    }
    return fabs(f->enorm[k][0] * r[0] + f->enorm[k][1] * r[1] + f->enorm[k][2] * r[2]);
}

double mesh_edge_point_dist(const struct mesh *m, int t, int k, const double x[3])
{
    struct tri_frame f;
    frame(m, t, &f);
    return frame_edge_dist(&f, k, x);
}

int mesh_planar_check(const struct mesh *m, double cos_tol)
{
    for (int t = 0; t < m->ntri; t++) {
        struct tri_frame a;
        frame(m, t, &a);
        for (int k = 0; k < 3; k++) {
            int u = m->nbr[3 * t + k];
            if (u < 0)
                continue;
            struct tri_frame b;
            frame(m, u, &b);
            double dot = a.norm[0] * b.norm[0] + a.norm[1] * b.norm[1] + a.norm[2] * b.norm[2];
            if (!(fabs(dot) > cos_tol))
                return t;
        }
    }
    return -1;
}

void mesh_planar_free(struct mesh_planar *p)
{
    free(p->edge_tri);
    free(p->edge_k);
    free(p->min_dist);
    p->edge_tri = p->edge_k = NULL;
    p->min_dist = NULL;
    p->ntri = 0;
}

int mesh_planar_build(const struct mesh *m, struct mesh_planar *p)
{
    enum { NE = MESH_PLANAR_NEDGE };
    const double init_large = 1e8;
    mesh_planar_free(p);
    size_t n = (size_t)m->ntri;
    p->edge_tri = malloc((n ? n : 1) * NE * sizeof *p->edge_tri);
    p->edge_k = malloc((n ? n : 1) * NE * sizeof *p->edge_k);
    p->min_dist = malloc((n ? n : 1) * sizeof *p->min_dist);
    if (!p->edge_tri || !p->edge_k || !p->min_dist) {
        mesh_planar_free(p);
        return -1;
    }
    p->ntri = m->ntri;
    for (int i = 0; i < m->ntri; i++) {
        struct tri_frame fi;
        frame(m, i, &fi);
        int *et = p->edge_tri + NE * i, *ek = p->edge_k + NE * i, nedge = 0;
        double dist[NE];
        for (int q = 0; q < NE; q++) {
            et[q] = ek[q] = -1;
            dist[q] = init_large;
        }
        for (int j = 0; j < m->ntri; j++) {
            const int *nb = m->nbr + 3 * j;
            if (nb[0] >= 0 && nb[1] >= 0 && nb[2] >= 0)
                continue;   /* no active edge */
            for (int ie = 0; ie < 3; ie++)
                for (int je = 0; je < 3; je++) {
                    if (nb[je] >= 0)
                        continue;
                    double d = frame_edge_dist(&fi, ie, m->vert + 3 * m->tri[3 * j + je]);
                    int slot = nedge;
                    if (nedge < NE)
                        nedge++;
                    else    /* the largest stored distance, the first of equals */
                        for (int q = slot = 0; q < NE; q++)
                            if (dist[q] > dist[slot])
                                slot = q;
                    et[slot] = j;
                    ek[slot] = je;
                    dist[slot] = d;
                }
        }
        double lo = dist[0];
        for (int q = 1; q < NE; q++)
            lo = dist[q] < lo ? dist[q] : lo;
        p->min_dist[i] = lo;
    }
    return 0;
}

int mesh_planar_far(const struct mesh *m, const struct mesh_planar *p, int t,
                    const double x[3], double delta)
{
    if (!(p->min_dist[t] < delta))
        return 1;
    for (int q = 0; q < MESH_PLANAR_NEDGE && p->edge_tri[MESH_PLANAR_NEDGE * t + q] >= 0; q++) {
        double d = mesh_edge_point_dist(m, p->edge_tri[MESH_PLANAR_NEDGE * t + q],
                                        p->edge_k[MESH_PLANAR_NEDGE * t + q], x);
        if (d < delta)
            return 0;
    }
    return 1;
}
