/* args.h - argument parsing shared by every command and style.
 *
 * Each parser raises a gr_error naming what was expected and what was given,
 * e.g. "expected a positive number for skin, got 'abc'". `what` names the
 * argument in the user's terms. */
#ifndef GR_ARGS_H
#define GR_ARGS_H

#include "state.h"

double arg_double(struct gravel *g, const char *s, const char *what);
double arg_positive(struct gravel *g, const char *s, const char *what);     /* > 0 */
double arg_nonneg(struct gravel *g, const char *s, const char *what);       /* >= 0 */
int arg_int(struct gravel *g, const char *s, const char *what);
int arg_int_range(struct gravel *g, const char *s, int lo, int hi, const char *what);
bigint arg_bigint(struct gravel *g, const char *s, const char *what);
int arg_yesno(struct gravel *g, const char *s, const char *what);           /* yes/no */
/* 1 if s parses fully as a number (no error). */
int arg_is_number(const char *s);
/* Parse a LAMMPS type range: "*", "n", "n*", "*n", "m*n" into [lo, hi] within 1..ntypes. */
void arg_type_range(struct gravel *g, const char *s, int ntypes, int *lo, int *hi);
/* The same for other numbered things (what: "molecule ID", "surface type" ...) in 1..n. */
void arg_range(struct gravel *g, const char *s, int n, int *lo, int *hi, const char *what);
/* "x", "y", "z" -> 0, 1, 2; else "what must be x, y or z". */
int arg_axis(struct gravel *g, const char *s, const char *what);
/* Index of group `name` or an error "unknown group". */
int arg_group(struct gravel *g, const char *name);
/* Check that a keyword has `need` values after it at argv[i]. */
void arg_need(struct gravel *g, int argc, int i, int need, const char *keyword);

#endif
