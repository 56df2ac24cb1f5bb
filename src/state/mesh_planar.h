/* mesh_planar.h - LIGGGHTS's planar triangle meshes (`fix
 * mesh/surface/planar`, TriMeshPlanar): the planarity test and the lists of
 * nearest active edges that `all_in yes` of fix insert/stream uses to keep
 * a random point of the face at least a radius from the face's border.
 * Pure host C on a struct mesh (src/state/mesh.h).
 *
 * An edge is active when no other triangle shares it (nbr == -1): on a
 * planar mesh every shared edge joins coplanar triangles, which LIGGGHTS
 * deactivates on both sides. Edge k of a triangle runs from its vertex k to
 * vertex k + 1 mod 3, as in LIGGGHTS. */
#ifndef GR_MESH_PLANAR_H
#define GR_MESH_PLANAR_H

#include "mesh.h"

#define MESH_PLANAR_NEDGE 6     /* LIGGGHTS's 2 * NUM_NODES stored edges per triangle */
#define MESH_PLANAR_MAXTRY 500  /* LIGGGHTS's MAXTRY_WITHIN */

struct mesh_planar {
    int ntri;
    int *edge_tri;      /* MESH_PLANAR_NEDGE per triangle: triangle of a stored edge, -1 none */
    int *edge_k;        /* its edge index 0..2 */
    double *min_dist;   /* per triangle: the smallest stored distance */
};

/* LIGGGHTS's isPlanar: every two triangles that share an edge have unit
 * normals with |n_a . n_b| > cos_tol (LIGGGHTS's curvature_: 1 - 1e-5, or
 * cos of the `curvature` angle). Returns -1 if so, else the first triangle
 * with a neighbour out of its plane. */
int mesh_planar_check(const struct mesh *m, double cos_tol);

/* TriMeshPlanar::buildEdgeLists, as LIGGGHTS computes it: for triangle i,
 * every (edge iE of i, triangle j with active edges, active edge jE of j)
 * in that loop order gives the distance from edge iE of i to vertex jE of
 * j; the first six fill the list, each later one replaces the entry of the
 * largest stored distance (whatever its own distance: LIGGGHTS's rule).
 * Returns 0, or -1 when out of memory. */
int mesh_planar_build(const struct mesh *m, struct mesh_planar *p);
void mesh_planar_free(struct mesh_planar *p);

/* LIGGGHTS's edgePointDist: the distance from point x to edge k of
 * triangle t (to the nearer end beyond the segment; in the triangle's
 * plane, across the edge, within it). */
double mesh_edge_point_dist(const struct mesh *m, int t, int k, const double x[3]);

/* The test of TriMeshPlanar::generateRandomOwnedGhostWithin for point x
 * drawn on triangle t: 1 if no stored edge of t is closer than delta. */
int mesh_planar_far(const struct mesh *m, const struct mesh_planar *p, int t,
                    const double x[3], double delta);

#endif
