/* fix_npt.c - `fix ID group npt keyword values...`: Nose-Hoover thermostat and
 * barostat (LAMMPS fix npt): needs temp and a pressure; temperature and
 * pressure of group all. The integrator is styles/fix/fix_nh.c. */
#include "fix.h"
#include "fix_nh.h"

FIX_NH_STYLE(npt, "npt", FIX_BOX_CHANGE);
