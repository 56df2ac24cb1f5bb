/* fix_drag.h - what fix drag (styles/fix/fix_drag.c) tells the cohesion
 * report (pair_cohesion_numbers.c) about the fluid. */
#ifndef GR_FIX_DRAG_H
#define GR_FIX_DRAG_H

struct fix;

/* The fluid viscosity mu and the flow's velocity and length
 * scales (uniform: |u_f| and 0; taylor_green: mean speed 0.7839 A and the
 * vortex diameter pi / a). Returns 0 if f is not a fix drag. */
int fix_drag_scales(const struct fix *f, double *mu, double *u0, double *l0);

#endif
