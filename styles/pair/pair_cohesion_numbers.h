/* pair_cohesion_numbers.h - the run-setup report of pair_style cohesion
 * (styles/pair/pair_cohesion_numbers.c): dimensionless numbers and the static
 * overlap check. */
#ifndef GR_PAIR_COHESION_NUMBERS_H
#define GR_PAIR_COHESION_NUMBERS_H

struct gravel;
struct pair;

/* Run setup: with fix drag active, log the Stokes number (000 eq. 6.4) and
 * the Stickiness number (eq. 6.5) of the scene. */
void pair_cohesion_dimensionless(struct gravel *g, const struct pair *coh);

/* Run setup: with a linear contact term (linear/restitution, gran/hooke),
 * log the static overlap kc (d_e - d_b)/(k - kc) of a resting pair and warn
 * when it exceeds 10 % or kc >= k (cohesion overpowers the contact). */
void pair_cohesion_overlap_check(struct gravel *g, const struct pair *coh);

#endif
