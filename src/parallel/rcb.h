/* rcb.h - recursive coordinate bisection, LAMMPS's `balance rcb` (src/rcb.cpp):
 * the box is cut in two where the lower part holds its share of the
 * particles (the share of the ranks it gets: the lower half of a range of
 * ranks takes ceil(n/2) of them), across the dimension whose cut leaves the
 * larger of the two smaller sides (tiles as cube-ish as possible), as
 * LAMMPS, and each part again, until every rank has a tile. Tiles are boxes of fractions of
 * the box (its lamda coordinates when triclinic), no longer a grid. The
 * cuts depend only on the set of positions, not on their order, so every
 * rank computes the same tiling from the gathered positions. */
#ifndef GR_RCB_H
#define GR_RCB_H

struct rcb {
    int n;       /* ranks tiled; 0: no tiling */
    int *dim;    /* dim[k], cut[k] (k = 1 .. n-1): the cut between ranks < k and >= k */
    double *cut; /* as a fraction of the box */
};

/* Tile the unit box for nranks from the n fractions s[3 i + q] (reordered
 * here); len[q] weighs the sides when choosing the longest (box lengths;
 * 1 each for lamda); nd = 2 never cuts z. */
void rcb_compute(struct rcb *t, int nranks, double *s, long n, const double len[3], int nd);
/* The same with a weight per particle: s[4 i + q] the fractions, s[4 i + 3]
 * its weight (> 0); each lower part holds its share of the weight (balance
 * weight, LAMMPS's weighted rcb); ties ordered by every field. */
void rcb_compute_w(struct rcb *t, int nranks, double *s, long n, const double len[3], int nd);
/* The rank whose tile holds the fractions s (a fraction on a cut goes up). */
int rcb_owner(const struct rcb *t, const double s[3]);
/* Tile of rank r: [lo, hi) per dimension, fractions of the box. */
void rcb_box(const struct rcb *t, int r, double lo[3], double hi[3]);
void rcb_free(struct rcb *t);

#endif
