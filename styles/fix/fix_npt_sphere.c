/* fix_npt_sphere.c - `fix ID group npt/sphere keyword values...`: fix npt for
 * finite spheres (LAMMPS fix npt/sphere): omega is integrated and
 * thermostatted; temperature temp/sphere. The integrator is styles/fix/fix_nh.c. */
#include "fix.h"
#include "fix_nh.h"

FIX_NH_STYLE(npt_sphere, "npt/sphere", FIX_BOX_CHANGE);
