/* pair_cohesion.h - packed parameter layout of pair_style cohesion
 * (styles/pair/pair_cohesion.c, kernels/pair_cohesion.cl) and the host helpers its
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



#endif
