/* mesh.h - triangle meshes: reading (ASCII and binary STL, legacy VTK
 * polydata or unstructured grid of triangles, ASCII or BINARY, file
 * versions 2-5), validation, vertex welding,
 * edge and vertex adjacency, rigid transforms. Pure host C (no engine, no
 * OpenCL): the fix mesh/surface front-end and the unit tests call it.
 *
 * Contract of every reader: on success returns 0 and fills a mesh whose
 * triangles are in file order (triangle i of the mesh is triangle i of the
 * file, counted from 0). On failure returns -1, leaves the mesh empty and
 * writes a message that names the file and, where one is to blame, the
 * triangle: "box.stl: triangle 3: zero area (vertices coincide or are
 * collinear)". */
#ifndef GR_MESH_H
#define GR_MESH_H

#include <stddef.h>

struct mesh {
    int nvert, ntri;
    double *vert;       /* 3 per welded vertex */
    int *tri;           /* 3 vertex indices per triangle (welded) */
    int *nbr;           /* 3 per triangle: the triangle across edge k (vertices k, k+1 mod 3),
                           -1 = boundary edge or an edge shared by more than two triangles */
    int nedge;          /* distinct edges */
    int *vtri_start;    /* nvert + 1: triangles around vertex v are */
    int *vtri;          /*   vtri[vtri_start[v] .. vtri_start[v + 1]) */
};

/* Read F (format from the contents: binary STL when the file size matches
 * its header count, ASCII STL when it starts with "solid", legacy VTK when
 * it starts with "# vtk"), weld, validate and build adjacency. weld_tol:
 * vertices closer than this are one (<= 0: 1e-10 of the bounding box
 * diagonal). */
int mesh_read(const char *path, double weld_tol, struct mesh *m, char *err, size_t errlen);

/* The same from raw triangle soup (9 doubles per triangle), for tests and
 * generators; `name` stands for the file in messages. */
int mesh_from_soup(const char *name, const double *soup, int ntri, double weld_tol,
                   struct mesh *m, char *err, size_t errlen);

/* Rigid and scaling transforms of the vertices (fix mesh/surface keywords):
 * scale about the origin, translate, rotate by deg degrees about an axis
 * through the origin (right-hand rule). */
void mesh_scale(struct mesh *m, double s);
void mesh_move(struct mesh *m, const double d[3]);
void mesh_rotate(struct mesh *m, const double axis[3], double deg);

/* Coordinates beyond this make squared areas overflow: the readers refuse
 * them, and so does mesh_check_range after the transforms. */
#define MESH_COORD_MAX 1e75
/* 0 if every vertex is finite and within MESH_COORD_MAX and every triangle
 * still has a non-zero, finite area (a normal); else -1 and a message naming
 * the file (name) and the first vertex or triangle at fault. */
int mesh_check_range(const struct mesh *m, const char *name, char *err, size_t errlen);

/* Rotation matrix (row-major 3x3) of angle rad about the unit axis a. */
void mesh_rotation_matrix(const double a[3], double rad, double R[9]);

void mesh_free(struct mesh *m);

/* Bins of a mesh for contact search: a uniform grid over the bounding box
 * grown by `reach` (the largest particle radius); cell c lists, in
 * ascending order, every triangle within reach of some point of the cell,
 * so a sphere of radius <= reach centred in cell c can only touch the
 * triangles of c. Cell size >= 2 reach, grown until the grid has at most
 * 2^22 cells. */
struct mesh_bins {
    double lo[3], h;
    int n[3];
    int *start;         /* ncell + 1 */
    int *list;
};
int mesh_bin(const struct mesh *m, double reach, struct mesh_bins *b, char *err, size_t errlen);
void mesh_bins_free(struct mesh_bins *b);
/* 1 if some triangle of m is closer than dist to point p (mesh frame);
 * b must be m's bins built with reach >= dist. */
int mesh_near(const struct mesh *m, const struct mesh_bins *b, const double p[3], double dist);

#endif
