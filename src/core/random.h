/* random.h - LAMMPS's two random number generators, reproduced bit for bit
 * so that commands which draw random numbers (velocity create, create_atoms
 * random, set type/fraction|type/ratio|type/subset, the random() and
 * normal() functions of variables) give LAMMPS's atoms and velocities.
 *
 *   rng_park  RanPark: Park and Miller's "minimal standard" multiplicative
 *             congruential generator (a = 16807, m = 2^31 - 1, Schrage's
 *             factorisation), with LAMMPS's per-coordinate reseeding
 *             (Jenkins one-at-a-time hash of the seed and three doubles).
 *   rng_mars  RanMars: Marsaglia and Zaman's RANMAR (F. James, Comp. Phys.
 *             Comm. 60 (1990) 329) with LAMMPS's seeding and one warm-up draw,
 *             and LAMMPS's select_subset (exact-count random selection).
 *
 * Both gaussian() use the polar Box-Muller method and keep the second
 * variate for the next call, as LAMMPS does. */
#ifndef GRAVEL_RANDOM_H
#define GRAVEL_RANDOM_H

#include <stdint.h>

struct rng_park {
    int seed;      /* current state, 1 .. 2^31 - 2 */
    int save;      /* 1 when `second` holds an unused gaussian */
    double second;
};

struct rng_mars {
    double u[98]; /* u[1..97]; u[0] unused, as in RANMAR's Fortran origin */
    int i97, j97;
    double c, cd, cm;
    int save;
    double second;
};

/* Seed must be > 0 (callers check and report). */
void rng_park_init(struct rng_park *r, int seed);
double rng_park_uniform(struct rng_park *r);      /* in (0, 1) */
double rng_park_gaussian(struct rng_park *r);     /* standard normal */
/* LAMMPS RanPark::reset(seed, coord): a new state from the seed and the
 * three coordinates' bytes, then 5 warm-up draws. */
void rng_park_reset_coord(struct rng_park *r, int seed, const double coord[3]);

/* Seed must be in 1 .. 900000000 (callers check and report). */
void rng_mars_init(struct rng_mars *r, int seed);
double rng_mars_uniform(struct rng_mars *r);      /* in [0, 1) */
/* The uniform draws behind a void pointer, for code that takes either stream. */
double rng_park_draw(void *park);
double rng_mars_draw(void *mars);
double rng_mars_gaussian(struct rng_mars *r);
/* Choose exactly ntarget of n items: mark[i] = 1 for chosen ones; next is
 * work space of n ints. LAMMPS RanMars::select_subset on one process. */
void rng_mars_select_subset(struct rng_mars *r, int64_t ntarget, int n, int *mark, int *next);

#endif
