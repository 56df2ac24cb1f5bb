/* atom_custom.h - custom per-atom properties (LAMMPS's Atom::add_custom,
 * find_custom): integer and floating vectors and arrays that fix
 * property/atom defines by name (i_name, d_name, i2_name N, d2_name N) and
 * that set, read_data's fix sections, dump custom, compute property/atom,
 * atom-style variables and balance's weight store read or write. The values
 * live in atoms.custom (atom_fields.h), one record per atom. */
#ifndef GR_ATOM_CUSTOM_H
#define GR_ATOM_CUSTOM_H

#include "state.h"

/* Index of the property `name` (without prefix), or -1. */
int custom_find(const struct atoms *a, const char *name);

/* ... in a layout that is not (yet) the atoms'. */
int custom_find_in(const struct atom_custom *c, const char *name);

/* A word naming a custom property or one column of it: i_name d_name
 * (vectors), i2_name[k] d2_name[k] (column k of an array, 1-based). */
struct custom_ref {
    int idx;                    /* property index in atoms.cus */
    int col;                    /* 0-based column; 0 for a vector */
};
/* 1 when `word` has a custom prefix (i_ d_ i2_ d2_), 0 otherwise. With
 * one, the property must exist with that type and shape (else an error
 * naming `who`); an array needs its [k] unless whole_array is non-NULL
 * (then *whole_array = 1 and ref->col = 0 for a bare array name). */
int custom_ref_parse(struct gravel *g, const char *word, const char *who, struct custom_ref *ref,
                     int *whole_array);
/* The prefixed name of property k, e.g. "d2_name" (buf of GR_CUSTOMLEN+4). */
const char *custom_prefixed(const struct atoms *a, int k, char *buf);

/* Atom i's value of the reference. */
static inline double custom_get(const struct atoms *a, struct custom_ref r, int i)
{
    return a->custom[(size_t)i * a->cus.slots + a->cus.p[r.idx].slot + r.col];
}
static inline double *custom_at(struct atoms *a, struct custom_ref r, int i)
{
    return a->custom + (size_t)i * a->cus.slots + a->cus.p[r.idx].slot + r.col;
}
/* A value checked for property k: an integer property takes integers that
 * fit LAMMPS's int (a clear error otherwise, naming `what`). */
double custom_check_value(struct gravel *g, const struct atoms *a, int k, double v,
                          const char *what);

/* One property of a fix property/atom command. */
struct custom_def {
    const char *name;           /* without prefix */
    int isint, cols;
    const double *def;          /* a new atom's values (custom_width of them), or NULL: 0 */
};
/* Make fix `fix`'s properties exactly defs[0..n-1]: a property it already
 * had with the same type and shape keeps its values (a fix given again with
 * its ID; one restored from a restart file for this fix ID), the others
 * start at zero; its properties not listed are removed. A name that another
 * fix defines is an error (LAMMPS: "Fix property/atom vector name already
 * exists"). */
void custom_define(struct gravel *g, const char *fix, int n, const struct custom_def *defs);
/* Atom i's custom values: every property's new-atom values (atoms_add). */
void custom_new_atom(struct atoms *a, int i);
/* Remove every property of fix `fix` (unfix). */
void custom_remove_fix(struct gravel *g, const char *fix);
/* 1 when `name` is a valid property name (letters, digits, underscores). */
int custom_name_ok(const char *name);

/* Slots (doubles) property k takes per atom. */
static inline int custom_width(const struct custom_prop *p) { return p->cols ? p->cols : 1; }

#endif
