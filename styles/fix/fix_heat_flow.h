/* fix_heat_flow.h - the temperature update fix heat/flow and fix heat/gran
 * share (styles/fix/fix_heat_flow.c). */
#ifndef GR_FIX_HEAT_FLOW_H
#define GR_FIX_HEAT_FLOW_H

#include "device.h"

/* Launch k (kernel heat_flow_final of fix_heat_flow.cl) on the atoms of
 * groupbit: T += dt Q / (cp m), cp per type on the device (cp[t - 1]). */
void heat_flow_integrate(struct gravel *g, unsigned groupbit, cl_kernel k, cl_mem cp);

#endif
