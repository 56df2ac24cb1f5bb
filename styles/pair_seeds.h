/* pair_seeds.h - parameter layouts and host helpers shared by the pair
 * styles of the source documents (linear/restitution, hertz/mindlin) and
 * their tests. Index enums give the packed per-type-pair REAL layout the
 * kernels read (kernels/pair_linear_restitution.cl, pair_hertz_mindlin.cl). */
#ifndef GR_PAIR_SEEDS_H
#define GR_PAIR_SEEDS_H

/* linear/restitution: ke kf mu ceta ctcol torque;
 * eta = ceta sqrt(m*), t_col = ctcol sqrt(m*). */
enum { LR_KE, LR_KF, LR_MU, LR_CETA, LR_CTCOL, LR_TORQUE, LR_NPARAM };

/* hertz/mindlin: see styles/pair_hertz_mindlin.c. */
enum { HM_KN, HM_KT, HM_CDAMP, HM_MU, HM_MUR, HM_NPARAM };

/* -2 ln(e) / sqrt(pi^2 + ln(e)^2): eta = this x sqrt(m* ke) (000 eq. 2.17). */
double seeds_restitution_damping_factor(double e);
/* sqrt(m_eff / ke) sqrt(pi^2 + ln(e)^2) (000 eq. 2.15). */
double seeds_linear_collision_time(double ke, double e, double meff);

#endif
