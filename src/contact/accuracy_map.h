/* accuracy_map.h - the accuracy map of a scene (`gravel -check`, `run N
 * accuracy`): its contact law replayed on isolated two-body collisions at
 * its time step and at half and twice it (src/contact/accuracy_map.c,
 * doc/accuracy_map.md). */
#ifndef GR_ACCURACY_MAP_H
#define GR_ACCURACY_MAP_H

#include "state.h"

/* Print the table (and accuracy_map.png where gnuplot exists). */
void accuracy_map(struct gravel *g);

#endif
