/* fused_layout.h - the contract of the fused per-particle fix work, declared
 * once: read by the host (src/engine/fused.c builds the op list) and by the kernels
 * (kernels/fused.cl runs it; the engine prepends this file to every
 * program). Plain enums: valid C and OpenCL C. */
#ifndef GR_FUSED_LAYOUT_H
#define GR_FUSED_LAYOUT_H

/* The ops, each exactly the arithmetic of its fix's own kernel */
enum fused_kind {
    FOP_GRAVITY = 1,            /* f += m g          prm: gx gy gz */
    FOP_FREEZE = 2,             /* f = torque = 0 */
    FOP_VISCOUS = 3,            /* f -= gamma_t v    prm: gamma per type */
    FOP_NVE_INITIAL = 4,        /* v += dtf/m f; x += dtv v          prm: dtv dtf */
    FOP_NVE_SPHERE_INITIAL = 5, /* and omega += dtf/(I m r^2) torque prm: dtv dtf dtf/I */
    FOP_NVE_FINAL = 6,          /* v += dtf/m f                      prm: dtf */
    FOP_NVE_SPHERE_FINAL = 7,   /* and omega += dtf/(I m r^2) torque prm: dtf dtf/I */
    /* fix drag (kernels/drag_law.cl); prm: mu flow p0 p1 p2 [exact h] */
    FOP_DRAG_EXPLICIT = 8,      /* f += 3 pi mu d (u_f(x) - v) */
    FOP_DRAG_KICK = 9,          /* post_force: u_f(x) kept, f += D of the closing kick */
    FOP_DRAG_KICK_AGAIN = 10    /* end_of_step: f = f - D + D' of the next opening kick */
};

/* An op that keeps per-atom state (FOP_DRAG_KICK*: D then u_f, 6 REAL per
 * atom) reads and writes its fix's store, the kernel's `store` argument: one
 * such fix per run is fused (src/engine/fused.c). */

/* One op in the int list: its kind, its group bit, the offset of its
 * parameters in the REAL list */
enum fused_op_layout { FOP_KIND = 0, FOP_GROUP = 1, FOP_PRM = 2, FOP_W = 3 };

#endif
