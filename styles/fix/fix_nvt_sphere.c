/* fix_nvt_sphere.c - `fix ID group nvt/sphere keyword values...`: fix nvt for
 * finite spheres (LAMMPS fix nvt/sphere): omega is integrated and
 * thermostatted too; its temperature is a compute temp/sphere. The integrator
 * is styles/fix/fix_nh.c. */
#include "fix.h"
#include "fix_nh.h"

FIX_NH_STYLE(nvt_sphere, "nvt/sphere", 0);
