/* ref.h - references to the global outputs of computes and fixes, the
 * c_ID / c_ID[I] / c_ID[I][J] (f_ID ...) words of thermo, variables and the
 * averaging fixes: their one parser, and LAMMPS's wildcard references
 * (utils::expand_args): c_ID[*], c_ID[N*], c_ID[*M], c_ID[N*M] and the same for f_ID stand for one
 * reference per index, c_ID[N] ... c_ID[M]. An open end is the width of the
 * compute's or fix's output the reader takes: its global vector
 * (size_vector) in vector mode, the columns of its global array
 * (size_array_cols) in array mode; for a compute without that output, the
 * columns of its per-atom array, else of its local array (LAMMPS's order). */
#ifndef GR_REF_H
#define GR_REF_H

#include "state.h"

/* Parse "K_ID", "K_ID[I]" or "K_ID[I][J]" (K the kind letter: 'c', 'f', 'v';
 * I, J >= 1): copies ID into id (GR_NAMELEN), sets *index to I and *col to
 * J (0 when absent). Returns 0 when `ref` does not have that form. */
int ref_parse(const char *ref, char kind, char *id, int *index, int *col);

/* 0 when `ref` has no wildcard index. Else 1, with the ID prefix ("c_ID")
 * in prefix (GR_NAMELEN + 2) and the indices in [*lo, *hi]; `array`: expand
 * array columns, else vector elements. Errors (unknown ID, nothing to
 * expand, empty or malformed range) name `who`. */
int ref_wildcard(struct gravel *g, const char *ref, int array, char *prefix, int *lo, int *hi,
                 const char *who);

#endif
