/* fix_property_atom.h - what the core asks of fix property/atom. */
#ifndef GR_FIX_PROPERTY_ATOM_H
#define GR_FIX_PROPERTY_ATOM_H

#include "fix.h"

/* unfix of a fix property/atom: the per-atom properties it defined go
 * (nothing for another style). */
void property_atom_release(struct gravel *g, struct fix *f);

#endif
