/* fix_gravity.h - what other styles read of a fix gravity (fix pour needs
 * the field LAMMPS's FixGravity exposes as magnitude and xgrav/ygrav/zgrav). */
#ifndef GR_FIX_GRAVITY_H
#define GR_FIX_GRAVITY_H

#include "fix.h"

/* For a fix of style gravity: its magnitude and unit direction (3d: the
 * spherical/chute/vector direction; 2d: z = 0); returns 1. Other fixes: 0. */
int fix_gravity_field(const struct fix *f, double *magnitude, double dir[3]);

/* Its acceleration vector (magnitude x direction, LAMMPS's gvec); 1, or 0
 * for other fixes. */
int fix_gravity_vector(const struct fix *f, double acc[3]);

#endif
