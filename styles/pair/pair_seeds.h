/* pair_seeds.h - parameter layouts and host helpers shared by the pair
 * styles of the source documents (linear/restitution, hertz/mindlin) and
 * their tests. */
#ifndef GR_PAIR_SEEDS_H
#define GR_PAIR_SEEDS_H

/* LR_* and HM_*: kernels/param_layout.h, shared with the kernels */
#include "param_layout.h"

/* -2 ln(e) / sqrt(pi^2 + ln(e)^2): eta = this x sqrt(m* ke) (000 eq. 2.17). */
double seeds_restitution_damping_factor(double e);
/* sqrt(m_eff / ke) sqrt(pi^2 + ln(e)^2) (000 eq. 2.15). */
double seeds_linear_collision_time(double ke, double e, double meff);

#endif
