/* fix_property_atom_tracer.h - LIGGGHTS's tracer markers, as compute
 * nparticles/tracer/region reads them. */
#ifndef GR_FIX_PROPERTY_ATOM_TRACER_H
#define GR_FIX_PROPERTY_ATOM_TRACER_H

/* 1 when a marker value counts as set: within 1e-5 of 1 (LIGGGHTS's
 * compDouble). The markers are the custom property named after the fix. */
int tracer_marked(double marker);

#endif
