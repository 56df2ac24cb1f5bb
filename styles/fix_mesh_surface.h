/* fix_mesh_surface.h - what the mesh styles share: the mesh of a
 * `fix ID group mesh/surface` (styles/fix_mesh_surface.c), its pose at the
 * current step from the `fix move/mesh` motions stacked on it
 * (styles/fix_move_mesh.c), and the force/torque buffer that fix wall/gran
 * ... mesh fills for the mesh's f_ID[i] output. */
#ifndef GR_FIX_MESH_SURFACE_H
#define GR_FIX_MESH_SURFACE_H

#include "fix.h"
#include "mesh.h"

struct mesh_surface {
    struct mesh m;              /* vertices after scale/move/rotate, in the mesh's own frame */
    double *normal;             /* unit normal per triangle (right hand over vertices 0 1 2) */
    int type;                   /* wall material type */
    double curvature, temperature;
    double ref[3];              /* torque reference point (moves with the mesh) */
    int ref_set;
    /* filled by fix wall/gran ... mesh: per atom force on the mesh and torque about ref */
    cl_mem fmesh;
    size_t fmesh_cap;           /* atoms it holds */
    int fmesh_valid;            /* the wall fix wrote it at fmesh_step */
    bigint fmesh_step;
    char wall_id[GR_NAMELEN];   /* the wall fix that owns fmesh this run */
    bigint cache_step;          /* step of cache[] */
    double cache[7];
};

/* Rigid pose of a mesh: x = R x0 + d for a point x0 of the mesh's own
 * frame; surface velocity at a point p (lab frame) V0 + omega x p. */
struct mesh_pose {
    double R[9], d[3], V0[3], omega[3];
    int moving;                 /* some motion acts (else R = I, d = V0 = omega = 0) */
};

/* One rigid motion of fix move/mesh (kind = MOVE_*), defined for fix_move_mesh.c. */
enum { MOVE_LINEAR, MOVE_WIGGLE, MOVE_ROTATE };
struct mesh_motion {
    char mesh[GR_NAMELEN];
    int kind;
    double v[3];                /* linear velocity / wiggle amplitude */
    double origin[3], axis[3];  /* rotate (axis unit) */
    double period;
    bigint time_origin;         /* step the motion started */
};

extern const struct fix_style fix_style_mesh_surface;
extern const struct fix_style fix_style_move_mesh;

/* The mesh of fix `id`, or an error naming `who` when there is none. */
struct mesh_surface *mesh_surface_get(struct gravel *g, const char *id, const char *who);
/* The pose of the mesh of fix `id` at the current step: the move/mesh
 * motions on it composed in the order of their fixes. */
void mesh_surface_pose(struct gravel *g, const char *id, struct mesh_pose *p);

#endif
