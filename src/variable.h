/* variable.h - script variables (equal, string, index, loop, format, getenv)
 * and the expression evaluator behind equal-style variables and $(...). */
#ifndef GR_VARIABLE_H
#define GR_VARIABLE_H

#include "gravel.h"

struct vars *var_create(void);
void var_destroy(struct vars *v);

/* Define an index variable from the command line (-var NAME V1 V2 ...). */
void var_set_index(struct gravel *g, const char *name, int n, char **values);
/* Current value as text (equal-style variables are evaluated), or NULL when
 * no variable has that name. The text stays valid until the next call. */
const char *var_retrieve(struct gravel *g, const char *name);
/* Numeric value of variable `name`; error if undefined or not numeric. */
double var_compute_equal(struct gravel *g, const char *name);
/* Evaluate an expression as in equal-style variables. */
double expr_eval(struct gravel *g, const char *text);

#endif
