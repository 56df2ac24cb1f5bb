/* par_sum.h - sums over every rank's atoms in one process's order, and the
 * collectives of insertion on several ranks (src/parallel/par.h). */
#ifndef GR_PAR_SUM_H
#define GR_PAR_SUM_H

#include <stdint.h>

#include "state.h"

/* Insertion on several ranks (fix pour): every rank draws the same
 * particles from the same neighbors and keeps those of its brick.
 * par_owns: x lies in this rank's brick (1 on one rank). par_gather_rows:
 * the n rows of `width` doubles at *rows (malloc'd) become every rank's
 * rows, rank by rank (returns their count). par_max_tag: the largest of
 * every rank's `mine`. Collective but par_owns. */
int par_owns(struct gravel *g, const double x[3]);
int par_gather_rows(struct gravel *g, double **rows, int n, int width);
int64_t par_max_tag(struct gravel *g, int64_t mine);
/* The largest atom ID of every rank's host atoms (0: none). Collective. */
int64_t par_max_atom_tag(struct gravel *g);

/* A sum over the atoms of every rank in one process's order: terms added
 * with ascending keys (a tag, or 2 tag + k for several terms per atom) give
 * the bits of one process adding them in that order. On one rank the terms
 * are added as they come (the caller adds them in key order). */
struct par_sum {
    double acc;
    int n, cap;
    int64_t *key;
    double *v;
};
void par_sum_add(struct gravel *g, struct par_sum *s, int64_t key, double v);
/* The total on every rank (collective); releases s. */
double par_sum_total(struct gravel *g, struct par_sum *s);

#endif
