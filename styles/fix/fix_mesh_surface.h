/* fix_mesh_surface.h - what the mesh styles share: the mesh of a
 * `fix ID group mesh/surface` (styles/fix/fix_mesh_surface.c), its pose at the
 * current step from the `fix move/mesh` motions stacked on it
 * (styles/fix/fix_move_mesh.c), and the force/torque buffer that fix wall/gran
 * ... mesh fills for the mesh's f_ID[i] output. */
#ifndef GR_FIX_MESH_SURFACE_H
#define GR_FIX_MESH_SURFACE_H

#include "fix.h"
#include "mesh.h"
#include "mesh_planar.h"
#include "wall.h"

/* One rigid motion of fix move/mesh or of fix_modify ID move (fix
 * surface/global) (kind = MOVE_*). */
enum { MOVE_LINEAR, MOVE_WIGGLE, MOVE_ROTATE };
struct mesh_motion {
    char mesh[GR_NAMELEN];
    int kind;
    double v[3];                /* linear velocity / wiggle amplitude */
    double origin[3], axis[3];  /* rotate (axis unit) */
    double period;
    bigint time_origin;         /* step the motion started */
};

#define MESH_OWN_MOTIONS 2      /* fix surface/global: transrot = linear then rotate */

struct mesh_stress; /* fix_mesh_surface_stress.h */

struct mesh_surface {
    struct mesh m;              /* vertices after scale/move/rotate, in the mesh's own frame */
    double *normal;             /* unit normal per triangle (right hand over vertices 0 1 2) */
    int type;                   /* wall material type */
    double curvature, temperature;
    double surface_vel[3];      /* LIGGGHTS's surface_vel: the surface moves in place */
    int has_surface_vel;
    double ref[3];              /* torque reference point (moves with the mesh) */
    int planar;                 /* fix mesh/surface/planar: checked planar, edges built */
    struct mesh_planar edges;   /*   its nearest active edges (insert/stream all_in) */
    int ref_set;
    /* filled by fix wall/gran ... mesh: per atom force on the mesh and torque about ref */
    cl_mem fmesh;
    size_t fmesh_cap;           /* atoms it holds */
    int fmesh_valid;            /* the wall fix wrote it at fmesh_step */
    bigint fmesh_step;
    const struct fix *owner;    /* the wall fix that fills fmesh (mesh_surface_claim) */
    bigint cache_step;          /* step of cache[] */
    double cache[7];
    /* fix surface/global: the mesh's molecule ID, the fix's largest surface
     * type and molecule ID (smaxtype, smaxmol), its own motions (from
     * fix_modify ID move), composed before any fix move/mesh */
    int mol, smaxtype, smaxmol;
    char *model;                /* fix surface/local: the model words its wall was made of */
    int nmotion;
    struct mesh_motion motion[MESH_OWN_MOTIONS];
    struct mesh_stress *stress; /* fix mesh/surface/stress (fix_mesh_surface_stress.c), else NULL */
};

/* Rigid pose of a mesh: x = R x0 + d for a point x0 of the mesh's own
 * frame; surface velocity at a point p (lab frame) V0 + omega x p. */
struct mesh_pose {
    double R[9], d[3], V0[3], omega[3];
    int moving;                 /* some motion acts (else R = I, d = V0 = omega = 0) */
};

extern const struct fix_style fix_style_mesh_surface;
extern const struct fix_style fix_style_mesh_surface_planar;
extern const struct fix_style fix_style_mesh_surface_stress;

/* The mesh/surface style's hooks, shared by mesh/surface/stress. */
void mesh_surface_create(struct gravel *g, struct fix *f, int argc, char **argv);
void mesh_surface_destroy(struct fix *f);
double mesh_surface_vector(struct gravel *g, struct fix *f, int i);
void mesh_surface_reset_step(struct gravel *g, struct fix *f, bigint shift);

/* 1 if f is a fix mesh/surface or mesh/surface/planar. */
int fix_is_mesh_surface(const struct fix *f);
extern const struct fix_style fix_style_move_mesh;

/* The mesh of fix `id`, or an error naming `who` when there is none. */
struct mesh_surface *mesh_surface_get(struct gravel *g, const char *id, const char *who);
/* The pose of the mesh of fix `id` at the current step: the move/mesh
 * motions on it composed in the order of their fixes. */
void mesh_surface_pose(struct gravel *g, const char *id, struct mesh_pose *p);
/* The pose of mesh ms at the current step: its own motions (ms->motion),
 * then the move/mesh motions on fix id (id NULL: none). */
void mesh_surface_pose_of(struct gravel *g, const struct mesh_surface *ms, const char *id,
                          struct mesh_pose *p);
/* Unit normal n of triangle t of m (right hand over vertices 0 1 2); returns
 * its area. */
double mesh_surface_tri_normal(const struct mesh *m, int t, double n[3]);
/* Unit normals of ms's triangles (ms->normal, right hand over vertices 0 1 2). */
void mesh_surface_normals(struct gravel *g, struct mesh_surface *ms);
/* The cosine two neighbouring triangles' normals must exceed for LIGGGHTS's
 * planarity test (its curvature_: cos of the `curvature` angle, else
 * 1 - 1e-5), for mesh_planar_check. */
double mesh_surface_cos_tol(const struct mesh_surface *ms);
/* Free what ms holds (not ms itself). */
void mesh_surface_free(struct mesh_surface *ms);

/* The mesh of fix `id` takes its pose of the current step as its own frame
 * (vertices, normals, torque reference): what `unfix` of its one fix
 * move/mesh leaves, the mesh where the motion put it (LIGGGHTS). */
void mesh_surface_bake(struct gravel *g, const char *id);

/* x = R x0 + d: a point of the mesh's own frame at the pose (x may be x0). */
void mesh_pose_point(const struct mesh_pose *p, const double x0[3], double x[3]);
/* v = R v0: a direction (a normal) at the pose (v may be v0). */
void mesh_pose_vector(const struct mesh_pose *p, const double v0[3], double v[3]);

/* u = V0 + omega x x: the surface velocity at the lab point x. */
void mesh_pose_velocity(const struct mesh_pose *p, const double x[3], double u[3]);

/* At a wall fix's init: make f the one wall of the mesh (its force output);
 * an error when another wall fix still holds it. */
void mesh_surface_claim(struct gravel *g, struct mesh_surface *ms, const char *mesh_id,
                        const struct fix *f);
/* After a wall fix's launch for this mesh: fmesh holds the current step. */
void mesh_surface_filled(struct gravel *g, struct mesh_surface *ms);
/* Make ms->fmesh hold n atoms (6 REAL each). */
void mesh_surface_fmesh_reserve(struct gravel *g, struct mesh_surface *ms, int n);

/* The meshes of one wall fix (wall/gran or wall/pair ... mesh): fixes
 * mesh/surface by ID, or meshes the wall owns (own[m], fix surface/global;
 * freed by mesh_walls_release). */
#define MESH_WALLS_MAX 8   /* 8 x 128 bytes of history per atom: the restart limit of 1024 */
struct mesh_walls {
    int n;
    char id[MESH_WALLS_MAX][GR_NAMELEN];
    struct mesh_surface *own[MESH_WALLS_MAX];
    struct wall_mesh wm[MESH_WALLS_MAX];
};
/* Run start: claim and upload every mesh (bins for the largest radius);
 * returns the per-atom history bytes the fix must declare. */
size_t mesh_walls_init(struct gravel *g, struct fix *f, struct mesh_walls *mw, int history);
/* post_force: one launch per mesh. pair_types: the law's parameters are the
 * pair style's of type pair (t_i, mesh type) (wall/pair), else one set. */
void mesh_walls_apply(struct gravel *g, struct fix *f, struct mesh_walls *mw,
                      struct wall_law *law, int pair_types);
void mesh_walls_release(struct mesh_walls *mw);

/* Parse LIGGGHTS' `mesh n_meshes N meshes ID1 ... IDN` starting at argv[i]
 * (the word `mesh`) into ids (at most max, each a mesh/surface fix); returns
 * the index after the last ID. */
int mesh_surface_parse_list(struct gravel *g, int argc, char **argv, int i,
                            char (*ids)[GR_NAMELEN], int max, int *n, const char *who);

#endif
