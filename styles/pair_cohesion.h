/* pair_cohesion.h - packed parameter layout of pair_style cohesion
 * (styles/pair_cohesion.c, kernels/pair_cohesion.cl) and the host helpers its
 * tests and the run-setup report use. */
#ifndef GR_PAIR_COHESION_H
#define GR_PAIR_COHESION_H

#include "pair.h"

struct fix;

/* COH_*: kernels/param_layout.h, shared with the kernels */
#include "param_layout.h"

/* Centre distance at which the effect surfaces of an I-J pair with body radii
 * radi, radj touch; *kc (if not NULL) receives the pair's stiffness. The
 * coefficients must have been prepared (pair_setup). */
double pair_cohesion_effect_distance(const struct pair *p, int itype, int jtype, double radi,
                                     double radj, double *kc);

/* Run setup: with fix drag active, log the Stokes number (000 eq. 6.4) and
 * the Stickiness number (eq. 6.5) of the scene (pair_cohesion_numbers.c). */
void pair_cohesion_dimensionless(struct gravel *g, const struct pair *coh);

/* Run setup: with a linear contact term (linear/restitution, gran/hooke),
 * log the static overlap kc (d_e - d_b)/(k - kc) of a resting pair and warn
 * when it exceeds 10 % or kc >= k (cohesion overpowers the contact). */
void pair_cohesion_overlap_check(struct gravel *g, const struct pair *coh);

/* styles/fix_drag.c: fluid viscosity mu and the flow's velocity and length
 * scales (uniform: |u_f| and 0; taylor_green: mean speed 0.7839 A and the
 * vortex diameter pi / a). Returns 0 if f is not a fix drag. */
int fix_drag_scales(const struct fix *f, double *mu, double *u0, double *l0);

#endif
