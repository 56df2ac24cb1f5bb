/* fix_nph_sphere.c - `fix ID group nph/sphere keyword values...`: fix nph for
 * finite spheres (LAMMPS fix nph/sphere): omega is integrated; temperature
 * temp/sphere. The integrator is styles/fix/fix_nh.c. */
#include "fix.h"
#include "fix_nh.h"

FIX_NH_STYLE(nph_sphere, "nph/sphere", FIX_BOX_CHANGE);
