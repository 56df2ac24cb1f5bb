/* balance_weight.h - the `weight` and `out` keywords of LAMMPS's balance and
 * fix balance: a weight per atom whose sums the slab cuts and rcb tiles
 * equalize instead of the atom counts, and the sub-domains' boxes written
 * to a file in LAMMPS's format.
 *
 * Styles (each multiplies every atom's weight, starting from 1, LAMMPS's
 * Imbalance classes):
 *   group N g1 f1 ... gN fN   the factor of each group the atom is in
 *   var name                   an atom-style variable (each value > 0)
 *   time factor                the rank's Pair + Neigh wall time since the
 *                              last balance (the last run's, for balance)
 *                              over its atoms: not deterministic; the
 *                              partition, never the physics, depends on it
 *   neigh factor               the rank's neighbor pairs over its atoms
 * time and neigh give every atom of a rank the same weight; factor != 1
 * stretches the ranks' weights from the lowest to factor times the highest
 * (LAMMPS 2021).
 *   store name                 each atom's weight so far (the product of the
 *                              styles given before it; 1 without) into the
 *                              custom vector d_name of fix property/atom
 *                              (LAMMPS's ImbalanceStore), on every atom the
 *                              weights are computed for. */
#ifndef GR_BALANCE_WEIGHT_H
#define GR_BALANCE_WEIGHT_H

#include <stdio.h>

#include "state.h"

#define BW_MAXGROUP 32
enum { BW_GROUP = 1, BW_VAR = 2, BW_TIME = 4, BW_NEIGH = 8 };

struct bal_weight {
    int on;                        /* a weight style was given */
    int ngroup, gid[BW_MAXGROUP];  /* weight group: group indices and factors */
    double gfac[BW_MAXGROUP];
    char *var;                     /* weight var */
    double time_factor;            /* weight time (0: not given) */
    double neigh_factor;           /* weight neigh (0: not given) */
    char *store;                   /* weight store: the d_ vector's name (NULL: none) */
    unsigned store_before;         /* BW_* styles given before store */
    char *out;                     /* out file name */
    FILE *fp;                      /* out file, open (rank 0) */
};

/* Parse `weight style args` (argv[i] = "weight") or `out file` (argv[i] =
 * "out"); returns the index after them. who names the command in errors. */
int bal_weight_parse(struct gravel *g, struct bal_weight *w, int argc, char **argv, int i,
                     const char *who);
void bal_weight_free(struct bal_weight *w);
/* The weights of atoms 0 .. n-1 of g->atoms (a new array; NULL when no style
 * is given), stored in d_name too with `store name`. owner[i]: the rank whose cost atom i shares (NULL: this rank);
 * cost_time / cost_neigh: each rank's cost (P values, the same on every
 * rank) and nown each rank's atom count, for the time and neigh styles. */
double *bal_weight_compute(struct gravel *g, const struct bal_weight *w, int n,
                           const int *owner, const double *cost_time,
                           const double *cost_neigh, const long *nown);
/* The boxes of every rank at step `step` to w->out (opened on first use;
 * rank 0 writes: LAMMPS's `out` format of nodes and cubes / squares). */
struct decomp;
void bal_weight_out(struct gravel *g, struct bal_weight *w, const struct decomp *dc, bigint step);

#endif
