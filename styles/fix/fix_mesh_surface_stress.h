/* fix_mesh_surface_stress.h - the per-triangle state of fix
 * mesh/surface/stress (fix_mesh_surface_stress.c), read by dump
 * mesh/gran/VTK. */
#ifndef GR_FIX_MESH_SURFACE_STRESS_H
#define GR_FIX_MESH_SURFACE_STRESS_H

#include "ocl.h"
#include "state.h"

struct mesh_stress {
    int do_stress, do_wear;     /* stress on, wear finnie */
    cl_mem rec;                 /* the wall kernel's contact records (MESH_SREC_*) */
    size_t cap;                 /* atoms rec holds */
    double *f;                  /* 3 per triangle: force of this step's contacts on it */
    double *sigma_n, *sigma_t;  /* per triangle: normal and shear stress of that force */
    double *wear;               /* per triangle: accumulated Finnie wear */
    double *area;               /* per triangle */
    double *kf;                 /* k_finnie (mesh type, atom type t) at [t - 1] */
    int nt;
    bigint step;                /* step of the last sums (-1: none) */
};

/* The device buffer of the wall kernel's contact records for n atoms (NULL
 * when st is NULL: the mesh measures nothing). */
cl_mem mesh_stress_records(struct gravel *g, struct mesh_stress *st, int n);
/* Free st and what it holds (NULL: nothing). */
void mesh_stress_free(struct mesh_stress *st);

#endif
