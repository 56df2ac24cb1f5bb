/* pair_single_eval.h - the pair style's single-pair evaluation (LAMMPS's
 * Pair::single) of host pairs, for the computes that report per-contact
 * forces at output time (pair/local, fabric). */
#ifndef GR_PAIR_SINGLE_EVAL_H
#define GR_PAIR_SINGLE_EVAL_H

#include "host_pairs.h"
#include "pair.h"

#define PAIR_SINGLE_SV 64 /* room per pair for the style's extra values */

/* For each of the np pairs p (host_pairs_local's, i the lower tag): eng[k]
 * (the pair energy, may be NULL), fpair[k] (force / r: the force on i is
 * del fpair) and, when sv is not NULL, the style's extra values (LAMMPS's
 * svector) at sv[k PAIR_SINGLE_SV ...] (zeros beyond the style's), with the
 * current positions, velocities and the contacts' stored history (every
 * rank's, by tag pair, on several ranks). The style must have single
 * (pair_caps.single; callers check and name themselves in the error). */
void pair_single_eval(struct gravel *g, const struct pair_caps *caps, const struct host_pair *p,
                      int np, double *eng, double *fpair, double *sv);

#endif
