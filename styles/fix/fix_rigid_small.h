/* fix_rigid_small.h - what fix pour needs of a fix rigid/small: its
 * molecule template, and LAMMPS's FixRigidSmall::set_molecule for a body it
 * has just inserted. */
#ifndef GR_FIX_RIGID_SMALL_H
#define GR_FIX_RIGID_SMALL_H

#include "fix.h"

struct molecule;

/* The `mol` template of a fix rigid/small (NULL without one, or for other
 * fixes). */
struct molecule *rigid_small_template(const struct fix *f);
/* A new body of template `mol` for fix f (rigid/small or multisphere): its
 * members are the template's atoms, tags tagprev + 1 ..., at the positions
 * xs (member k at xs + k xstride), of group bits mask; the host atoms of
 * them this rank holds are first .. g->atoms.n - 1 (all of them on one
 * rank; on several, the owned ones). Inserted with the template's
 * geometric centre at xgeom, rotated by quat about it, moving with vcm
 * (LAMMPS set_molecule); its mass, centre of mass and principal moments are
 * the template's. fix multisphere also gives the atoms the body's ID as
 * molecule ID and its clump group. Returns the body's index. */
int rigid_small_add_body(struct gravel *g, struct fix *f, const struct molecule *mol,
                         int first, int64_t tagprev, const double *xs, int xstride,
                         unsigned mask, const double xgeom[3], const double vcm[3],
                         const double quat[4]);
/* LIGGGHTS's fflag/tflag of body `body` (every body when < 0): 0 where a
 * component of its velocity (fflag) or angular momentum (tflag) is never
 * kicked; NULL leaves that set as it is. */
void rigid_small_hold(struct fix *f, int body, const int fflag[3], const int tflag[3]);
/* fix insert/stream's approach of body `body` of fix multisphere f
 * (LIGGGHTS Multisphere::calc_n_steps): unless set already, its release
 * step = now + int(distance of its centre of mass to the face plane through
 * p_ref (unit normal) / (|v_normal| dt)); until then it moves at v_normal,
 * untouched by forces, then takes v_rel. Returns the release step. */
int64_t rigid_small_stream(struct gravel *g, struct fix *f, int body, const double p_ref[3],
                           const double normal[3], const double v_normal[3],
                           const double v_rel[3]);
/* The mask bits of fix multisphere f's clump atoms (its group ID_clumps). */
unsigned rigid_small_member_bits(const struct fix *f);
/* The three on/off words after argv[i] (fflag or tflag) as 1/0 in v. */
void rigid_small_flags_arg(struct gravel *g, int argc, char **argv, int i, int v[3]);

/* The bodies' kinetic energies (mass x velocity^2 units, before mvv2e):
 * translational sum 1/2 M vcm^2 and rotational sum 1/2 sum_k I_k w_k^2, w_k
 * the angular velocity on principal axis k, over fix f's bodies, in body
 * order. */
void rigid_small_body_energy(const struct fix *f, double *ke, double *erot);

#endif
