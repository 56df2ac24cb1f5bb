/* variable.h - script variables (equal, string, index, loop, format, getenv,
 * atom)
 * and the expression evaluator behind equal-style variables and $(...).
 *
 * Semantics follow LAMMPS: redefining an index or loop variable that exists is
 * silently ignored (so -var on the command line wins over the script), string,
 * equal, format and getenv variables are replaced, and redefining a variable
 * with a different style is an error. */
#ifndef GR_VARIABLE_H
#define GR_VARIABLE_H

#include "state.h"

struct vars *var_create(void);
void var_destroy(struct vars *v);

/* Define an index variable from the command line (-var NAME V1 V2 ...). */
void var_set_index(struct gravel *g, const char *name, int n, char **values);
/* The `variable` command: argv[0] = name, argv[1] = style or "delete", then
 * the style's arguments. Raises gr_error on any invalid input. */
void var_define(struct gravel *g, int argc, char **argv);
/* Advance an index or loop variable (the `next` command). Returns 1 when it
 * had no more values: it has then been deleted, as in LAMMPS. */
int var_next(struct gravel *g, const char *name);
/* Current value as text (equal-style variables are evaluated), or NULL when
 * no variable has that name. The text stays valid until the next call. */
const char *var_retrieve(struct gravel *g, const char *name);
/* 1 if a variable of that name exists (nothing is evaluated). */
int var_exists(struct gravel *g, const char *name);
/* Numeric value of variable `name`; error if undefined or not numeric. */
double var_compute_equal(struct gravel *g, const char *name);
/* The step an equal-style variable gives as the next one after `step`
 * (thermo, dump_modify every, fix print with v_name): an error "WHO 'NAME'
 * is not defined", or "WHO 'NAME' returned V, which is not a step after
 * STEP" unless step < V < 2^63. */
bigint var_next_step(struct gravel *g, const char *name, bigint step, const char *who);
/* Atom-style variables (`variable NAME atom formula`): 1 if NAME is one;
 * its value for every host atom (g->atoms.n values, host order, the host
 * arrays synced first during a run) into out; var_check_atom raises
 * "who: ..." unless NAME is an atom-style variable. */
int var_is_atom(struct gravel *g, const char *name);
/* 1 if NAME is an equal-style variable (LAMMPS's equalstyle()). */
int var_is_equal(struct gravel *g, const char *name);
void var_compute_atom(struct gravel *g, const char *name, double *out);
void var_check_atom(struct gravel *g, const char *name, const char *who);
/* The same values in a new array (caller frees; freed on error). */
double *var_atom_values(struct gravel *g, const char *name);
/* Print every variable (name, style, value) with gr_print, for `info`. */
void var_print_all(struct gravel *g);
/* Number of defined variables. */
int var_count(const struct gravel *g);

/* Random numbers for random()/normal(): LAMMPS's one RanMars stream,
 * created on first use with that seed and continued on later calls, so a
 * script gives the same sequence every time. seed must be > 0. */
double var_random_uniform(struct gravel *g, long seed);
double var_random_gaussian(struct gravel *g, long seed);

/* Internal: evaluate with a nesting depth (v_name recursion guard). */
double var_compute_equal_depth(struct gravel *g, const char *name, int depth);
void var_compute_atom_depth(struct gravel *g, const char *name, double *out, int depth);

#endif
