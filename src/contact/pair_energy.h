/* pair_energy.h - the pair potential energy of thermo epair, pe and etotal
 * (LAMMPS eng_vdwl): the sum over pairs within their cut-off of the pair
 * style's energy function (pair_style energy; pair colloid). Granular
 * contact styles have none (0, as LAMMPS). Computed on demand, only on the
 * steps that print it (pair_energy kernel, kernels/pair_loop.cl): summed per
 * particle in row order and over particles in tag order, deterministic.
 * Extensive; thermo normalizes it like ke. */
#ifndef GR_PAIR_ENERGY_H
#define GR_PAIR_ENERGY_H

#include "state.h"

/* The pair energy of the current positions (0 outside a run, without a
 * pair style or for a style without an energy). */
double pair_energy(struct gravel *g);
/* Each atom's half of its pairs' energies (LAMMPS's eatom of the pair
 * style: compute pe/atom) into out[0 .. atoms.n), in device order = host
 * order after a run's host sync. Returns 0 (out untouched) when there is no
 * pair energy to take (outside a run, no pair style, a style without one). */
int pair_energy_atoms(struct gravel *g, double *out);
/* Take this step's pair energy now, for the rest of the step: a box change
 * after the forces (src/engine/box_change.c) calls it before it moves the atoms
 * (compute_forces discards it). */
void pair_energy_snapshot(struct gravel *g);

#endif
