/* fix_nph.c - `fix ID group nph keyword values...`: Nose-Hoover barostat
 * (LAMMPS fix nph): needs a pressure, no temp; temperature and pressure of
 * group all. The integrator is styles/fix/fix_nh.c. */
#include "fix.h"
#include "fix_nh.h"

FIX_NH_STYLE(nph, "nph", FIX_BOX_CHANGE);
