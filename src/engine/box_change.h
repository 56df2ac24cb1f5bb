/* box_change.h - the box changes during a run: one generic piece for every
 * fix that moves the box (fix deform, the barostats fix nph / npt).
 *
 * Contract of box_change_apply(g, b, remap, groupbit):
 *   - call it from a fix hook during a run (the atoms are on the device;
 *     any hook: initial_integrate, post_force, final_integrate, end_of_step,
 *     pre_exchange), never between runs (change_box does that on the host);
 *   - b is the complete new box: lo[3], hi[3] and the tilts xy xz yz
 *     (LAMMPS's boxlo, boxhi and xy xz yz after set_global_box); tilts must
 *     be 0 unless the box is triclinic, and a tilt needs its periodic
 *     dimension (errors otherwise, naming the fix's script line);
 *   - remap BOX_REMAP_X: the atoms of groupbit keep their lamda (fractional)
 *     coordinates, LAMMPS's x2lamda with the old box then lamda2x with the
 *     new one (bit for bit in double precision; kernels/box_change.cl);
 *     BOX_REMAP_NONE: no atom moves (LAMMPS's remap none);
 *   - remap v (LAMMPS's deform_vremap): a fix sets g->dom.h_rate (the rates
 *     of Lx Ly Lz yz xz xy) and g->dom.vremap_group in its init (both are
 *     reset at every run start and uploaded before the setup forces); when
 *     the rates change during the run it calls box_change_rates(g). With
 *     the build option VREMAP (the fix puts "VREMAP" in f->defines) an atom
 *     of the group that crosses a periodic face gets v -/+ n . h_rate, and a
 *     contact with a partner's periodic image sees the image's velocity
 *     v + n . h_rate (LAMMPS's Domain::pbc and ghost velocities);
 *   - afterwards g->dom holds the new box, and every kernel launched after
 *     it sees the new box: the wrap, rebuild check and binning read g->dom at
 *     launch, the pair, virial and history kernels read the list's lengths and
 *     tilts, refreshed here (nbr_box_changed); the next rebuild check
 *     subtracts the box corners' motion since the last build from the
 *     trigger distance, as LAMMPS's Neighbor::check_distance, so a box that
 *     moves faster than half the skin forces rebuilds. Atoms that leave the
 *     new box are wrapped back at the next step (nbr_check), as LAMMPS's pbc.
 *   - a change of a non-periodic (shrink-wrapped or fixed) face is allowed;
 *     atoms outside a fixed face are lost at the next rebuild.
 *   - on a step with output due, the pair virial of the step's forces is
 *     taken before the atoms move (pressure_virial_snapshot), so the
 *     pressure printed is that of the forces, as LAMMPS's tally;
 *   - nothing else is refreshed: a fix that caches box-derived values on the
 *     device (none today) must recompute them. */
#ifndef GR_BOX_CHANGE_H
#define GR_BOX_CHANGE_H

#include "state.h"

enum box_remap { BOX_REMAP_NONE, BOX_REMAP_X };

struct box_target {
    double lo[3], hi[3];
    double xy, xz, yz;
};

/* The current box as a target (a starting point for a change). */
void box_current(const struct gravel *g, struct box_target *b);
/* A box flip (LAMMPS's FixDeform::pre_exchange): the tilts become xy xz yz
 * of b, whose edge vectors are b' = b + fxy a and c' = c + fyz b + fxz a
 * (fxy, fxz, fyz in -1, 0, 1); no atom moves, image flags change so that
 * unwrapped positions are kept (Domain::image_flip). The caller forces a
 * neighbor rebuild on this step (call it from pre_exchange), which wraps the
 * atoms into the flipped box. */
void box_change_flip(struct gravel *g, const struct box_target *b, int fxy, int fxz, int fyz);
/* Upload g->dom.h_rate again (rates that change during a run). */
void box_change_rates(struct gravel *g);
/* Apply the new box b (contract above). */
void box_change_apply(struct gravel *g, const struct box_target *b, enum box_remap remap,
                      unsigned groupbit);

#endif
