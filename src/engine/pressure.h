/* pressure.h - the pressure of thermo `press`, `pxx` .. `pyz` and compute
 * pressure (scalar and tensor),
 * as LAMMPS' compute pressure (thermo_press):
 *   p = (dof kB T + W_xx + W_yy + W_zz) / (3 V) nktv2p        (3d)
 *   p = (dof kB T + W_xx + W_yy) / (2 A) nktv2p               (2d, A = Lx Ly)
 * with T and dof from the temperature (thermo_modify temp, else thermo_temp)
 * and W the pair virial of the current step: sum over contacts of
 * del_a F_a (del = x_i - x_j, F the force on i), LAMMPS' granular pair
 * virial. Walls and the other fixes add none (LAMMPS 2021's granular fixes
 * have no virial). nktv2p = 1 in lj, si and cgs. The virial is computed on
 * demand, only when a pressure is asked for (pair_virial kernel), summed
 * per particle in row order and over particles in tag order: deterministic. */
#ifndef GR_PRESSURE_H
#define GR_PRESSURE_H

#include "state.h"
#include "ocl.h"

/* The virial tensor W_xx, W_yy, W_zz, W_xy, W_xz, W_yz of the current step
 * (0 without a pair style or outside a run). */
void pressure_virial(struct gravel *g, double w[6]);
/* The pair virial of each host atom, w[6 i ..] = W_xx .. W_yz of atom i
 * (1/2 of its contacts' del_a F_b, LAMMPS's per-atom virial; the host atoms
 * are in device order during a run), zeros without a pair style or
 * outside a run. One process. */
void pressure_virial_atoms(struct gravel *g, double *w);
/* Take the virial of this step now and return it for the rest of the step:
 * a box change (src/engine/box_change.c) calls it before it moves the atoms, since
 * pair_virial recomputes the separations from the positions (LAMMPS tallies
 * the virial with the forces, before fix deform's end_of_step). */
void pressure_virial_snapshot(struct gravel *g);
/* The volume the pressure divides by: Lx Ly Lz (3d), Lx Ly (2d); tilts
 * do not change it. */
double pressure_volume(const struct gravel *g);
/* The pressure tensor xx yy zz xy xz yz, LAMMPS's compute pressure vector:
 * (K_ab + W_ab) / V nktv2p with K the kinetic-energy tensor of t
 * (temp_vector, mvv2e sum m v_a v_b), xz yz zz = 0 in 2d. */
void pressure_tensor(struct gravel *g, struct temp_state *t, int keflag, int virialflag,
                     double out[6]);
/* The per-particle scratch of the on-demand pair tallies (virial, energy):
 * REAL[6 cap] on the device, kept with the engine. */
cl_mem pressure_scratch(struct gravel *g);
/* The pressure with temperature t (host arrays current). */
double pressure_scalar(struct gravel *g, struct temp_state *t);
/* The same with the kinetic part (dof kB T, needs t) and the virial part
 * chosen (compute pressure's ke, virial/pair keywords). */
double pressure_parts(struct gravel *g, struct temp_state *t, int keflag, int virialflag);

#endif
