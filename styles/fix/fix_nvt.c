/* fix_nvt.c - `fix ID group nvt keyword values...`: Nose-Hoover thermostat
 * (LAMMPS fix nvt): needs temp, no pressure; its temperature is a compute temp
 * of the fix group. The integrator is styles/fix/fix_nh.c. */
#include "fix.h"
#include "fix_nh.h"

FIX_NH_STYLE(nvt, "nvt", 0);
