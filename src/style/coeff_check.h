/* coeff_check.h - the one validation layer for physical coefficients.
 *
 * Every style that reads a physical coefficient (the pair styles, fix
 * wall/gran and its region and mesh walls, fix wall/pair, and material
 * properties when they land) checks it here, so a coefficient means the same
 * range everywhere and the error reads the same:
 *
 *     ERROR: <command>: <who>: <name> must be <range>, got <value> (<file>:<line>)
 *
 * named at the script line that holds the value (the pair_style, pair_coeff
 * or fix line: the check runs while that command is parsed). Ranges follow
 * what LAMMPS accepts where LAMMPS checks (zero friction, zero stiffness and
 * a Poisson's ratio of 0.5 are accepted) and physics where it does not
 * (doc/coefficients.md lists them). */
#ifndef GR_COEFF_CHECK_H
#define GR_COEFF_CHECK_H

#include "state.h"

enum coeff_range {
    CR_FINITE,          /* any finite number */
    CR_POSITIVE,        /* > 0: Young's modulus, a stiffness that must act */
    CR_NONNEG,          /* >= 0: stiffness, damping, friction, cohesion, energies */
    CR_POISSON,         /* (-1, 0.5]: Poisson's ratio */
    CR_RESTITUTION,     /* (0, 1]: a restitution coefficient turned into damping by ln e */
    CR_UNIT,            /* [0, 1]: a fraction (tsuji's e, whose fit is finite at 0) */
};

/* v when it is finite and in `range`; otherwise the error above. who (the
 * style, e.g. "pair_coeff granular") may be NULL. */
double coeff_check(struct gravel *g, const char *who, const char *name, double v,
                   enum coeff_range range);
/* v when finite and 0 <= v <= hi (xmu's [0, 10000] of LAMMPS's gran styles). */
double coeff_upto(struct gravel *g, const char *who, const char *name, double v, double hi);
/* Parse the argument s as a number (arg_double's error when it is not one),
 * then coeff_check it. */
double coeff_arg(struct gravel *g, const char *who, const char *s, const char *name,
                 enum coeff_range range);

#endif
