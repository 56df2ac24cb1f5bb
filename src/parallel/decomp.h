/* decomp.h - the spatial decomposition: LAMMPS's `processors Px Py Pz`
 * grid of bricks over the box, each rank owning the atoms in its brick.
 * The grid is chosen at each run start from the rank count and the box
 * (LAMMPS's ProcMap::onelevel_grid: the factorization of smallest
 * sub-domain surface, `*` free, a given count fixed); bricks split each
 * box length (a triclinic box: each lamda coordinate) evenly until `balance` or `fix balance` moves the cuts
 * (balance.c), or, under comm_style tiled, `balance rcb` tiles the box
 * (rcb.h): the sub-domains are then boxes that do not form a grid. */
#ifndef GR_DECOMP_H
#define GR_DECOMP_H

#include "rcb.h"
#include "state.h"

struct decomp {
    int user[3];            /* `processors`: the count per dimension, 0 = * */
    int p[3];               /* the grid of the run */
    int me[3];              /* this rank's place in it (rank = x + px (y + py z)) */
    double *cut[3];         /* balance: p[q] + 1 cuts per dimension as fractions of the
                             * box length (0 ... 1); NULL = even slabs */
    int tiled;              /* comm_style tiled: balance rcb may tile the box */
    struct rcb rcb;         /* balance rcb: the ranks' tiles (rcb.n = 0: the grid) */
};

/* The grid of the current box for comm_size() ranks (cuts kept while the
 * grid stays the same; an rcb tiling while the rank count and comm_style
 * tiled stay). */
void decomp_setup(struct gravel *g, struct decomp *d);
void decomp_free(struct decomp *d);
/* Whether the ranks hold rcb tiles rather than the grid's bricks. */
int decomp_tiled(const struct decomp *d);
/* Tile the box by rcb from the n records of every atom (decomp_fractions
 * with q < 0: s[3 i + q], or weighted: s[4 i + q] and the weight s[4 i + 3];
 * reordered here). */
void decomp_rcb(const struct gravel *g, struct decomp *d, double *s, long n, int weighted);
/* The records of atoms x[0 .. n-1] (malloc'd): their fractions of the box
 * (decomp_fraction) in dimension q, or in all three when q < 0, each
 * followed by its weight wt[k] when wt is not NULL. */
double *decomp_fractions(struct gravel *g, const double *x, int n, const double *wt, int q);
/* Sub-domain of rank r as fractions of the box (lamda when triclinic):
 * [lo, hi) per dimension, a brick of the grid or an rcb tile. */
void decomp_box(const struct decomp *d, int r, double lo[3], double hi[3]);
/* Fraction of the box of position x in dimension q: (x - lo) / L, in a
 * triclinic box the lamda coordinate (LAMMPS's bricks of a triclinic box
 * are slabs of lamda); periodic: wrapped; clamped to 0 ... 1 (the raw form
 * unclamped). */
double decomp_fraction(const struct gravel *g, int q, const double x[3]);
double decomp_fraction_raw(const struct gravel *g, int q, const double x[3]);
/* Slab cuts of dimension q at the quantiles of the n fractions s (sorted
 * in place; balance's shift); even slabs where the atoms cannot separate
 * them. weighted: s[2 i] an atom's fraction, s[2 i + 1] its weight (> 0),
 * each slab holding its share of the weight (balance weight). */
void decomp_quantile_cuts(struct decomp *dc, int q, double *s, long n, int weighted);
/* Fraction of the box length below slab k's lower face in dimension q. */
double decomp_cut(const struct decomp *d, int q, int k);
/* The rank owning position x (periodic dimensions wrapped into the box;
 * outside a fixed face: the nearest brick). */
int decomp_owner(const struct gravel *g, const struct decomp *d, const double x[3]);
/* Sub-domain of rank r in box coordinates: [lo, hi) per dimension
 * (orthogonal boxes; a triclinic box's are decomp_box's lamda). */
void decomp_brick(const struct gravel *g, const struct decomp *d, int r, double lo[3],
                  double hi[3]);

#endif
