/* pair_surf_granular.h - the particle/surface models of `pair_style hybrid
 * ... surf/granular` (LAMMPS 4 Jul 2026, GRANSURF), which fix surface/local
 * reads (styles/pair/pair_surf_granular.c). */
#ifndef GR_STYLE_PAIR_SURF_GRANULAR_H
#define GR_STYLE_PAIR_SURF_GRANULAR_H

#include "state.h"

/* The words of `pair_coeff I J surf/granular words...` for the type pair
 * (ptype, stype) in either order (*words, returns their count), or -1 when
 * no such pair_coeff was given (or there is no surf/granular sub-style). */
int surf_granular_model(const struct gravel *g, int ptype, int stype, char ***words);

#endif
