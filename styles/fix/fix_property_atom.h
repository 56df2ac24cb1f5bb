/* fix_property_atom.h - what the core asks of fix property/atom. */
#ifndef GR_FIX_PROPERTY_ATOM_H
#define GR_FIX_PROPERTY_ATOM_H

#include "fix.h"

/* unfix of a fix property/atom: the per-atom properties it defined go
 * (nothing for another style). */
void property_atom_release(struct gravel *g, struct fix *f);

/* 1 when f is a fix property/atom. */
int property_atom_is(const struct fix *f);

/* One value column of a fix property/atom's data-file section (read_data
 * ... fix ID NULL Section, write_data): the fix's properties in command
 * order, an array's N columns in turn. */
enum prop_column_kind { PC_MOL, PC_TEMPERATURE, PC_HEATFLOW, PC_CUSTOM };
struct prop_column {
    enum prop_column_kind kind;
    struct {
        int idx, col;           /* PC_CUSTOM: atoms.cus property and column */
    } ref;
};
/* The columns of fix f (a fix property/atom) into col[0..max-1]; their
 * count, or -1 when more than max. */
int property_atom_columns(struct gravel *g, const struct fix *f, struct prop_column *col,
                          int max);

#endif
