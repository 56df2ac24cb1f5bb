/* expr.h - the expression evaluator (expr.c) behind equal-style and
 * atom-style variables, $(...) and the formulas of styles that take one.
 *
 * Grammar and operands as LAMMPS: numbers, thermo keywords, c_ID, f_ID,
 * v_name, math and group functions. With variable.c it is the variable
 * language: variables hold formulas this evaluates, and formulas read
 * variables, so the two call each other. */
#ifndef GR_EXPR_H
#define GR_EXPR_H

struct gravel;

/* Evaluate an expression as in equal-style variables. */
double expr_eval(struct gravel *g, const char *text);
/* Evaluate a formula once per host atom (atom-style variables): bare x y z
 * vx vy vz fx fy fz mass radius type id are that atom's, c_ID / c_ID[N] of a
 * per-atom compute and v_name of an atom-style variable its value; every
 * other operand is global and evaluated once. out: g->atoms.n values. */
void expr_eval_atoms(struct gravel *g, const char *text, double *out, int depth);
/* Check that `fmt` is a printf format with exactly one double conversion
 * (%f %e %g %E %G with flags, width <= 999, precision <= 999) and no other
 * conversions except %%; returns 1 if valid. Used by format variables and
 * $(expr:fmt). */
int expr_format_ok(const char *fmt);

/* Internal: evaluate with a nesting depth (v_name recursion guard). */
double expr_eval_depth(struct gravel *g, const char *text, int depth);

#endif
