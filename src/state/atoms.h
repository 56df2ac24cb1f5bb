/* atoms.h - host-side per-atom arrays (atom_style sphere).
 *
 * The host copy is the source of truth between runs; `run` uploads it and
 * downloads it back at the end and whenever output needs it. Arrays grow
 * geometrically; indices are local positions, `tag` is the identity. The
 * arrays themselves are the rows of the field table (atom_fields.h). */
#ifndef GR_ATOMS_H
#define GR_ATOMS_H

#include "state.h"

/* Whether the host holds a field of this `when` (atom_fields.h): every field
 * but the superellipsoid rows, which only atom_style ellipsoid superellipsoid
 * writes (fixed before the first atom exists); elsewhere their arrays stay
 * untouched zero pages, which cost no memory. Loops over the table that
 * write or move per-atom values skip the fields not held. */
static inline int atoms_holds(const struct atoms *a, int when)
{
    return when != FW_ELLIPSOID || a->ellipsoid_flag;
}

/* Make room for at least n atoms (values of new slots are zero). */
void atoms_reserve(struct gravel *g, int n);
/* Append one atom; returns its index. Tag 0 = next free tag. Radius and
 * mass as given; velocity, omega, image zero; mask = "all". */
int atoms_add(struct gravel *g, int64_t tag, int type, const double x[3], double radius,
              double rmass);
/* Copy every per-atom field of atom `from` into slot `to` (LAMMPS's
 * AtomVec::copy). */
void atoms_copy(struct atoms *a, int from, int to);
/* Give the custom properties the layout `to` (atom_fields.h): property k
 * of `to` keeps the values at old slot from_slot[k] (< 0: a new one, zero).
 * Replaces atoms.cus. */
void atoms_custom_relayout(struct gravel *g, const struct atom_custom *to, const int *from_slot);
/* Remove atom i by moving the last atom into its slot. */
void atoms_remove(struct gravel *g, int i);
/* Set ntypes and size the per-type tables. */
void atoms_set_ntypes(struct gravel *g, int ntypes);
void atoms_free(struct atoms *a);
/* Release the per-atom arrays and the order scratch only (the per-type
 * tables stay: a temporary set that shares them, src/parallel/par.c). */
void atoms_free_fields(struct atoms *a);
/* Atom indices in ascending tag order (valid until the atoms change):
 * host reductions (thermo, computes) sum in this order, so their results
 * do not depend on the device's memory order (atom_modify sort). */
const int *atoms_tag_order(struct gravel *g);
/* ord[k] = the index of the k-th smallest of the n tags (ties: any order). */
void atoms_order_by_tag(const int64_t *tag, int n, int *ord);
/* Index of the atom with this tag, or -1 (linear scan; callers cache). */
int atoms_find_tag(const struct atoms *a, int64_t tag);

/* Hash of every per-atom host array of the restart file's atoms section
 * (a file's exact continuation data is valid while it is unchanged). */
uint64_t atoms_fingerprint(const struct atoms *a);

#endif
