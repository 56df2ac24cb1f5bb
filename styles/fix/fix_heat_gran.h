/* fix_heat_gran.h - what pair_style gran takes from fix heat/gran
 * (styles/fix/fix_heat_gran.c) into its per-type-pair parameters. */
#ifndef GR_FIX_HEAT_GRAN_H
#define GR_FIX_HEAT_GRAN_H

#include "fix.h"

extern const struct fix_style fix_style_heat_gran;
extern const struct fix_style fix_style_heat_gran_conduction;

/* The conduction of type pair (I, J) (1-based, nt types): the contact area
 * mode LG_H_* (LG_H_NONE without a fix heat/gran), *hc = 4 k_I k_J / (k_I +
 * k_J) from thermalConductivity (0 if one is below 1e-6, LIGGGHTS), *area
 * the contact_area constant value. */
int heat_gran_conduction(struct gravel *g, int nt, int I, int J, double *hc, double *area);

#endif
