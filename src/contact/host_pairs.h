/* host_pairs.h - pairs of atoms closer than a distance, found on the host
 * from the host arrays (a cell grid, minimum image in periodic dimensions),
 * for the computes that look at neighbours at output time (contact/atom,
 * coord/atom, cluster/atom, pair/local, property/local), as LAMMPS's
 * occasional neighbor lists serve its computes. Orthogonal boxes only.
 * Each pair appears once, ordered by (lower tag, higher tag): i is the
 * partner with the lower tag; del = x_i - x_j (minimum image). */
#ifndef GR_HOST_PAIRS_H
#define GR_HOST_PAIRS_H

#include "state.h"

struct host_pair {
    int i, j;           /* host indices, tag[i] < tag[j] */
    double del[3];      /* x_i - x_j, minimum image */
    double rsq;
};

/* The cell-grid scan behind host_pairs_find: every unordered pair of the
 * listed atoms idx[0..m) that may be closer than cut (cells of width >= cut
 * over the box in periodic dimensions, the atoms' extent otherwise) is given
 * to visit(g, k, kk, ctx), k < kk positions in idx, in a fixed order (k
 * ascending, then the 27-cell stencil, then cell order). visit tests the
 * distance itself (minimum image in periodic dimensions). */
void host_pairs_scan(struct gravel *g, const int *idx, int m, double cut,
                     void (*visit)(struct gravel *g, int k, int kk, void *ctx), void *ctx);

/* The same scan over positions x (3 per atom, indexed by idx) other than
 * the host arrays': a run's device state read back (pair
 * granular/superellipsoid). */
void host_pairs_scan_x(struct gravel *g, const double *x, const int *idx, int m, double cut,
                       void (*visit)(struct gravel *g, int k, int kk, void *ctx), void *ctx);

/* Every pair of atoms, one in mask bits `bits_a` and the other in `bits_b`
 * (either way round), with |del| < cut (cut > 0). Returns the count and sets
 * *out (malloc'd, caller frees; NULL when none). Errors name `who`. */
int host_pairs_find(struct gravel *g, double cut, unsigned bits_a, unsigned bits_b,
                    struct host_pair **out, const char *who);

/* The pairs LAMMPS's local pair computes list (compute pair/local and the
 * p* values of compute property/local): both atoms in `groupbit`, closer
 * than the cut-off: with `radius`, r_i + r_j (LAMMPS's cutoff radius);
 * else the pair style's type-pair cut-off of LAMMPS 2021's init_one
 * (cutoff type): the largest of R_i + R_j over the largest radii of the
 * two types' dynamic and frozen (fix freeze) atoms, frozen-frozen
 * excluded, through the style's caps.lammps2021_cut when it has one (pair
 * granular: JKR pull-off, its cutoff keyword), the radii of the atoms
 * present now; pairs neigh_modify exclude removes are left out (as from
 * LAMMPS's lists). Same order and layout as host_pairs_find. */
int host_pairs_local(struct gravel *g, unsigned groupbit, int radius, struct host_pair **out,
                     const char *who);

/* LAMMPS 2021's pair cut-off `cutforce`: the largest type-pair cut-off of
 * host_pairs_local's `cutoff type`. Errors name `who` (no pair style). */
double host_pairs_cutforce(struct gravel *g, const char *who);

/* 1 when neigh_modify exclude keeps atoms i and j (host indices) out of the
 * neighbor lists (a type pair, a group pair, molecule/intra or inter), the
 * test the device's list build applies; LAMMPS's lists for its computes
 * apply it too. */
int host_pairs_excluded(const struct gravel *g, int i, int j);

/* The engine's contact history of each pair (LAMMPS's fix neigh/history
 * values that Pair::single reads): hist[k * width + d] for pair k, seen from
 * its atom i, from the engine's current neighbor list (host order = device
 * order after a run's host sync). Returns the width (REALs per contact), 0
 * when there is none (no history style, no list built yet, atoms changed
 * since): hist is then untouched. Pairs not in the list get zeros. hist
 * needs np * HOST_PAIRS_HIST_MAX doubles. */
#define HOST_PAIRS_HIST_MAX 40 /* = the engine's GR_HIST_MAX (checked in host_pairs.c) */
int host_pairs_history(struct gravel *g, const struct host_pair *p, int np, double *hist);

#endif
