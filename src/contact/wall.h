/* wall.h - walls as contact sources of the contact pipeline (kernels/wall.cl).
 *
 * A wall front-end (fix wall/gran, fix wall/pair) describes its geometry as
 * a struct wall_geom, creates the kernel of its contact law (a WALL_KERNEL
 * instantiation) and calls wall_apply() in post_force: one launch per wall,
 * every kernel argument bound here. Contact history is engine-managed
 * per-atom state of the fix, wall_elements() slots of 3 REAL per atom. */
#ifndef GR_WALL_H
#define GR_WALL_H

#include "state.h"
#include "kargs.h"
#include "ocl.h"
#include "wall_layout.h"

struct fix;

struct wall_geom {
    enum wall_kind kind;
    int axis;                   /* plane: normal axis 0..2; cylinder: its axis a */
    double lo, hi;              /* plane: face positions (+-WALL_FAR = no face) */
    double radius;              /* cylinder */
    double v[3];                /* velocity of the surface */
    int cyl_shear;              /* cylinder: CYL_SHEAR_* (kernels/wall_layout.h) */
    double cx, cy;              /* cylinder: the axis's coordinates in dimensions a + 1
                                 * and a + 2 (mod 3) (0, 0 for LAMMPS's zcylinder) */
    double vshear;
};

#define WALL_FAR 1.0e20

/* The contact law of a wall: one packed parameter set, or (by_type) the
 * pair style's parameters of type pair (t_i, t_i). */
struct wall_law {
    cl_kernel kernel;
    cl_mem param;
    int by_type;                /* < 0: a table by type pair, column -by_type - 1 */
    int nparam;                 /* REALs per set of a by-type table (0: the pair style's) */
    int history;                /* REAL of history per element per atom (0: none;
                                 * 3: shear; granular: its sub-models' width) */
    int inclusive;              /* |del| = radius is a contact (LAMMPS wall/gran) */
    int heat;                   /* conducts heat (a wall/gran heat sub-model) ... */
    double twall;               /* ... at this temperature (`temperature T`) */
    /* LAMMPS's `contacts`: per atom WALL_CONTACT_W REAL (kernels/wall_layout.h),
     * cleared and written by every launch (plane, cylinder and region walls) */
    int contacts_on;
    cl_mem contacts;
};

/* History slots per atom of a wall of this geometry. */
int wall_elements(const struct wall_geom *w);
/* Bytes of per-atom state the fix must declare (f->peratom_bytes). */
size_t wall_peratom_bytes(struct gravel *g, const struct wall_geom *w, const struct wall_law *law);
/* Add the wall's contact forces and torques for the atoms of f's group. */
void wall_apply(struct gravel *g, struct fix *f, const struct wall_geom *w,
                const struct wall_law *law);

/* The kernel arguments shared by every wall kind (kernels/kernel_args.h):
 * the atoms and their wall records (KARGS_wall_atoms), fix f's group,
 * history and switches (KARGS_wall_own), and the law's parameters
 * (KARGS_wall_law). */
struct wall_atoms_args wall_atoms_args(struct gravel *g);
struct wall_own_args wall_own_args(struct gravel *g, struct fix *f, const struct wall_law *law);
struct wall_law_args wall_law_args(struct gravel *g, const struct wall_law *law);

/* ---- region walls (kernels/wall_region.cl REGION_KERNEL; src/contact/wall_region.c) ----
 * The surface of a LAMMPS region: a primitive (block, sphere, cylinder,
 * cone, plane) or a union / intersect of primitives, each with its side,
 * open faces and motion, packed for the device at every launch. History per
 * atom: the contact count, WALL_REGION_MAXC wall ids and 3 REAL of shear
 * per contact (1 + 4 slots REAL). */
#define WALL_REGION_MAXC RG_MAXC         /* kernels/wall_layout.h */
#define WALL_REGION_MAXNODE RG_MAXNODE

struct region;

struct wall_region {
    cl_mem nodes;               /* the nodes for region_probe */
    cl_mem set;                 /* RS_SIZE REAL: the set this wall leads (RS_* layout) */
    int nnode, comb, interior, slots;
};

/* Set up, apply and release: wall_region.h. */

/* ---- mesh walls (kernels/wall.cl MESH_KERNEL) ----
 * A triangle mesh on the device in its own frame: per triangle its three
 * vertices and unit normal (12 REAL), its welded vertex ids (3 int), and its
 * bins (src/state/mesh.h). The pose (R, d, V0, omega, see fix_mesh_surface.h) is
 * uploaded at every launch. History: WALL_MESH_SLOTS slots of 1 + width REAL
 * (key, shear) per atom per mesh. */
#define WALL_MESH_SLOTS MESH_SLOTS   /* kernels/wall_layout.h */

struct mesh;

struct wall_mesh {
    int ntri;
    cl_mem tri, triv, cstart, ctri, pose;
    int gn[3];
    double glo[3], h;
    double reach, lskin, mscale;    /* bin reach, list skin, largest |vertex|_1 */
    cl_mem mlist, mlpos;            /* per-atom triangle lists (MESH_LIST_*) */
    size_t lcap;                    /* atoms they hold */
    double pose_up[POSE_N];         /* the pose last uploaded (pose_ok: valid) */
    int pose_ok;
    /* a moving mesh's pose goes up without a wait: two host copies, each
     * kept until the write from it (its event) has completed */
    void *pose_host[2];
    cl_event pose_ev[2];
    int pose_k;
};

/* Upload mesh m (normals: 3 per triangle) with bins for particles of radius
 * up to reach + lskin, and per-atom triangle lists built lskin beyond an
 * atom's radius (0: none; kernels/wall.cl mesh_candidates); `who` names the
 * caller in errors. */
void wall_mesh_upload(struct gravel *g, struct wall_mesh *wm, const struct mesh *m,
                      const double *normal, double reach, double lskin, const char *who);
void wall_mesh_release(struct wall_mesh *wm);
/* Add the mesh contacts of f's atoms. R, d, V0, omega: the pose; ref: the
 * torque reference point (lab frame). History at REAL offset hoff of a
 * per-atom record of hstride REAL; fmesh (or NULL): per atom force on the
 * mesh and torque about ref; mstress (or NULL): per atom the records of its
 * contacts (MESH_SREC_*, kernels/wall_layout.h) for fix mesh/surface/stress. */
void wall_mesh_apply(struct gravel *g, struct fix *f, struct wall_mesh *wm,
                     const struct wall_law *law, const double R[9], const double d[3],
                     const double V0[3], const double omega[3], const double ref[3], int moving,
                     int hstride, int hoff, cl_mem fmesh, cl_mem mstress);

#endif
