/* balance.h - LAMMPS's `balance` command and the shift of `fix balance`:
 * the processor grid's slab cuts moved so that each slab of a dimension
 * holds as many atoms as the others (style shift: the cuts at the atoms'
 * quantiles, exact in one pass) or set by hand (x/y/z uniform or cuts);
 * under comm_style tiled, style rcb tiles the box by recursive coordinate
 * bisection of the atoms (rcb.h), each tile holding a rank's share. */
#ifndef GR_BALANCE_H
#define GR_BALANCE_H

#include "state.h"

/* `balance thresh style args ...` (between runs) */
void cmd_balance(struct gravel *g, int argc, char **argv);
/* Parse `dimstr` of style shift: bit q set for each of x, y, z named. */
unsigned balance_dims(struct gravel *g, const char *dimstr);
#endif
