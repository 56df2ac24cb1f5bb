/* wall_layout.h - the host/device contracts of the wall stage, declared once:
 * read by the host (src/contact/wall.c, src/contact/wall_region.c, src/contact/accuracy.c) and by
 * the kernels (the engine prepends it to every program, after
 * param_layout.h). Plain enums: valid C and OpenCL C. */
#ifndef GR_WALL_LAYOUT_H
#define GR_WALL_LAYOUT_H

/* Geometry kinds of a plane/cylinder wall (kernels/wall.cl wall_point) */
enum wall_kind { WALL_PLANE = 0, WALL_CYLINDER = 1 };
/* A cylinder's surface motion when sheared across its axis: LAMMPS's
 * azimuthal speed vshear (zcylinder), or LIGGGHTS's angular velocity vshear
 * about the axis (v = vshear e_axis x r) */
enum wall_cyl_shear { CYL_SHEAR_NONE = 0, CYL_SHEAR_SPEED = 1, CYL_SHEAR_OMEGA = 2 };

/* REAL of history per wall contact in the row form (a law's whole history
 * row: pair granular's sub-models) */
enum { WALL_HMAX = 10 };

/* The pose of a mesh (REAL each, uploaded at every launch; kernels/wall.cl
 * MESH_KERNEL): R row-major, d, surface velocity V0 and angular velocity
 * omega (v(p) = V0 + omega x p), bin origin, 1 / bin size, torque reference
 * point. Vector entries start at multiples of 3 (vload3(POSE_x / 3)). */
enum mesh_pose_layout { POSE_R = 0, POSE_D = 9, POSE_V0 = 12, POSE_OMEGA = 15, POSE_GLO = 18,
                        POSE_GINV = 21, POSE_REF = 22, POSE_N = 25 };
/* History slots per atom per mesh: key (triangle + 1, 0 = free), then the
 * law's history */
enum { MESH_SLOTS = 4 };
/* fix mesh/surface/stress: per atom and mesh MESH_SLOTS contact records of
 * MESH_SREC_W REAL: the triangle + 1 (0: no more records), the force on the
 * mesh (3), the atom's velocity relative to the surface at the contact
 * point (3), and (contact point - centre) . that velocity */
enum { MESH_SREC_KEY = 0, MESH_SREC_F = 1, MESH_SREC_V = 4, MESH_SREC_CV = 7,
       MESH_SREC_W = 8 };
/* The per-atom triangle list of a mesh (kernels/wall.cl mesh_candidates):
 * MESH_LIST_W int (the atom's tag in two halves, the count n (-1: stale),
 * then up to MESH_LIST_K triangle ids) and MESH_LPOS_W REAL (the point it
 * was built at, mesh frame, then its radius) */
enum mesh_list_layout { MESH_LIST_TAGLO = 0, MESH_LIST_TAGHI = 1, MESH_LIST_N = 2,
                        MESH_LIST_T = 3, MESH_LIST_K = 13, MESH_LIST_W = 16,
                        MESH_LPOS_RL = 3, MESH_LPOS_W = 4 };

/* A region as device nodes (kernels/wall_region.cl; filled by
 * src/contact/wall_region.c every step): up to RG_MAXNODE primitive nodes of
 * RG_NODE REAL, at most RG_MAXC contacts per atom. Node layout: */
enum region_node_layout {
    RG_KIND = 0,        /* enum region_primitive */
    RG_INTERIOR = 1,
    RG_OPENFLAG = 2,
    RG_OPEN = 3,        /* open faces 0..5 as bits; bit RG_OPEN_RIM2021: -compat lammps2021 */
    RG_AXIS = 4,
    RG_WALLOFF = 5,     /* wall id offset inside a union / intersect */
    RG_MOVE = 6,
    RG_ROT = 7,
    RG_P = 8,           /* 8 shape parameters */
    RG_D = 16,          /* displacement */
    RG_SIN = 19,
    RG_COS = 20,
    RG_POINT = 21,
    RG_RUNIT = 24,
    RG_V = 27,
    RG_OMEGA = 30,
    RG_RPOINT = 33,
    RG_NODE = 40
};
/* RG_OPEN's bit set under -compat lammps2021: an open cylinder's cap contact
 * outside its radius is LAMMPS 2021's (the point above the atom on the cap's
 * plane, not on the rim) */
enum { RG_OPEN_RIM2021 = 6 };
enum region_primitive { RG_BLOCK = 1, RG_SPHERE, RG_CYLINDER, RG_CONE, RG_PLANE };
enum { RG_MAXNODE = 4, RG_MAXC = 8 };
/* A set of region walls run by one launch (kernels/wall_region.cl
 * REGION_KERNEL, filled by src/contact/wall_region.c every step): up to
 * RS_MAXWALL walls of one law, in the order of their post_force calls; per
 * wall a header of RS_HEAD REAL (its group bit, history width, accuracy
 * code, node count, combinator, side, slots, motion, parameter form, heat
 * and `contacts` switches), and its nodes from RS_NODES(w). */
enum region_set_layout { RS_GROUPBIT = 0, RS_HW, RS_ACODE, RS_NNODE, RS_COMB, RS_INTERIOR,
                         RS_SLOTS, RS_DYNAMIC, RS_BYTYPE, RS_NPARAM, RS_WHEAT, RS_TWALL,
                         RS_CONTACTS, RS_HEAD = 16, RS_MAXWALL = 4 };
#define RS_NODES(w) (RS_MAXWALL * RS_HEAD + (w) * RG_MAXNODE * RG_NODE)
#define RS_SIZE RS_NODES(RS_MAXWALL)
/* fix wall/gran's `contacts` record per atom (LAMMPS's per-atom array, its
 * 8 columns): touching (1 or 0), the wall's force on the atom (3), the
 * contact point on the wall (3, device coordinates: the host adds the run's
 * origin) and the atom's radius; all zero without contact. An atom with
 * several contacts keeps its last one (LAMMPS). */
enum { WALL_CONTACT_W = 8 };
/* region_probe's per-atom record: the contact count, then per contact its
 * distance r, del (3) and wall id */
enum { RG_PROBE_C = 5, RG_PROBE_W = 1 + RG_PROBE_C * RG_MAXC };

/* Accuracy records (kernels/accuracy.cl, src/contact/accuracy.c), float in
 * both precisions: ACC_PAIR_W per pair contact (largest dt / t_col, the
 * squared normal speed then) and ACC_WALL_W per particle for its wall
 * contacts (largest dt / t_col, largest overlap / radius, then two keys of
 * ACC_KEY_W: the wall's code, normal speed, R* and m* of the contact that
 * gave the largest dt / t_col and of the last one evaluated that did not). */
enum acc_layout { ACC_PAIR_Q = 0, ACC_PAIR_VN2 = 1, ACC_PAIR_W = 2,
                  ACC_KEY_CODE = 0, ACC_KEY_VN = 1, ACC_KEY_REFF = 2, ACC_KEY_MEFF = 3,
                  ACC_KEY_W = 4,
                  ACC_WALL_Q = 0, ACC_WALL_OV = 1, ACC_WALL_KEY = 2,
                  ACC_WALL_LAST = ACC_WALL_KEY + ACC_KEY_W, ACC_WALL_W = ACC_WALL_LAST + ACC_KEY_W,
                  ACC_WALL_VN = ACC_WALL_KEY + ACC_KEY_VN,
                  ACC_WALL_CODE = ACC_WALL_KEY + ACC_KEY_CODE };

#endif
