/* group.h - static groups of atoms (LAMMPS group command) and group
 * reductions used by commands and expressions.
 *
 * A group is a bit of the per-atom mask (bit 0 = "all"); g->groups holds the
 * names. Membership is assigned when a group command runs (static groups). */
#ifndef GR_GROUP_H
#define GR_GROUP_H

#include "state.h"

/* Index of group `name`, or -1. */
int group_find(const struct gravel *g, const char *name);
/* Index of group `name`, creating it (no atoms) if new; errors when all 32
 * slots are used or the name is not letters, digits and underscores. */
int group_create(struct gravel *g, const char *name);
/* The mask bit of group index i. */
static inline unsigned group_bit(int i) { return 1u << i; }

/* Dynamic groups: re-evaluate every dynamic group's membership (parent
 * AND region AND atom-style variable != 0) on the host arrays and, during a
 * run, write the masks to the device. `step` < 0: all of them (run setup);
 * else those whose `every` divides step. */
void group_dynamic_update(struct gravel *g, bigint step);

/* Reductions over the atoms of group i (host arrays); sums in tag order, so
 * they depend on the atoms only; during a decomposed run (the host holds
 * this rank's atoms) the sums run over every rank's atoms (par_sum.h):
 * the same bits on any number of MPI ranks. group_count is this host's. */
bigint group_count(const struct gravel *g, int igroup);
double group_mass(struct gravel *g, int igroup);
/* Center of mass of unwrapped positions; masstotal from group_mass (0: xcm = 0). */
void group_xcm(struct gravel *g, int igroup, double masstotal, double xcm[3]);
/* Center-of-mass velocity. */
void group_vcm(struct gravel *g, int igroup, double masstotal, double vcm[3]);
/* Extent of the (wrapped) positions; lo > hi when the group is empty. */
void group_bounds(const struct gravel *g, int igroup, double lo[3], double hi[3]);
/* Translational kinetic energy sum 1/2 m v^2. */
double group_ke(struct gravel *g, int igroup);
/* Total force on the group (LAMMPS's fcm). */
void group_fcm(struct gravel *g, int igroup, double fcm[3]);
/* Torque of the atoms' forces about xcm (unwrapped positions). */
void group_torque(struct gravel *g, int igroup, const double xcm[3], double tq[3]);
/* Radius of gyration about xcm: sqrt(sum m |x - xcm|^2 / masstotal), 0 for no mass. */
double group_gyration(struct gravel *g, int igroup, double masstotal, const double xcm[3]);
/* Angular momentum about xcm (unwrapped positions). */
void group_angmom(struct gravel *g, int igroup, const double xcm[3], double L[3]);
/* Inertia tensor about xcm (point masses, unwrapped positions). */
void group_inertia(struct gravel *g, int igroup, const double xcm[3], double I[3][3]);
/* Angular velocity w with I w = L, solved in the principal frame; principal
 * moments below 1e-10 of the largest (two atoms, a line of atoms) get no
 * rotation about that axis, as LAMMPS' nearly-singular branch. */
void group_omega(const double L[3], double I[3][3], double w[3]);

#endif
