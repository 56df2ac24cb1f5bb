/* fix_property_global.h - the named global properties of LIGGGHTS's `fix ID
 * group property/global name form values...` (styles/fix/fix_property_global.c),
 * read by the styles that take their coefficients from them (pair gran,
 * fix wall/gran model ..., fix check/timestep/gran). */
#ifndef GR_FIX_PROPERTY_GLOBAL_H
#define GR_FIX_PROPERTY_GLOBAL_H

#include "state.h"

/* LIGGGHTS's forms; atomtype and atomtypepair are its other names of
 * peratomtype and peratomtypepair. */
enum fpg_form { FPG_SCALAR, FPG_VECTOR, FPG_PERATOMTYPE, FPG_MATRIX, FPG_PERATOMTYPEPAIR };

struct fpg {
    char name[64];
    enum fpg_form form;
    int n;                      /* values */
    int ncol;                   /* matrix and peratomtypepair: columns (n / ncol rows) */
    double *v;                  /* row-major */
};

/* The property registered under this name (the first fix that defines it),
 * or NULL. */
const struct fpg *fpg_find(struct gravel *g, const char *name);
/* The scalar `name`, errors (naming `who`) when missing or not a scalar. */
double fpg_scalar(struct gravel *g, const char *name, const char *who);
/* The per-type vector `name` with at least nt values (type t at [t - 1]). */
const double *fpg_pertype(struct gravel *g, const char *name, int nt, const char *who);
/* Value (I, J) (1-based) of the per-type-pair matrix `name` of at least
 * nt x nt values. */
double fpg_pair(struct gravel *g, const char *name, int nt, int I, int J, const char *who);

#endif
