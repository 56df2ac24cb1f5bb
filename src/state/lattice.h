/* lattice.h - lattice styles and lattice-point generation (LAMMPS lattice).
 *
 * g->dom.lat holds the current lattice: its style, spacings a[3] in box units
 * (LAMMPS xlattice, ylattice, zlattice), primitive cell lengths prim[3],
 * fractional origin and basis. As LAMMPS' Lattice::lattice2box, point
 * (i, j, k) + basis[m] is at box position
 *     x_d = (index_d + basis[m][d]) * prim[d] + origin[d] * a[d]. */
#ifndef GR_LATTICE_H
#define GR_LATTICE_H

#include "state.h"

enum lattice_style { LAT_NONE = 0, LAT_SC, LAT_BCC, LAT_FCC, LAT_HCP, LAT_DIAMOND, LAT_SQ, LAT_SQ2,
                     LAT_HEX };

/* Called for every lattice point inside [lo, hi) (box units) with the index
 * of its basis atom; it may raise errors. */
typedef void (*lattice_point_fn)(struct gravel *g, const double x[3], int basis, void *ctx);

/* Visit every lattice point p with lo[d] <= p[d] < hi[d], in k, j, i, basis
 * order (as LAMMPS create_atoms). If rlo/rhi are given, points outside the
 * closed range [rlo, rhi] are skipped without being visited (a bounding box
 * to shorten the loops; NULL = none). Errors if no lattice is defined or the
 * loops would visit more than 2^31 points. */
void lattice_foreach(struct gravel *g, const double lo[3], const double hi[3],
                     const double *rlo, const double *rhi, lattice_point_fn fn, void *ctx);

#endif
