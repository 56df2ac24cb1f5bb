/* atom_attr.h - the per-atom attributes by name that LAMMPS's compute
 * property/atom and fix store/state read: id type mass x y z xu yu zu ix
 * iy iz vx vy vz fx fy fz radius diameter omegax omegay omegaz tqx tqy tqz,
 * temperature heatflow (fix property/atom temperature heatflow), quatw
 * quati quatj quatk shapex shapey shapez (diameters) angmomx angmomy
 * angmomz (atom_style ellipsoid superellipsoid). The custom properties
 * (i_name, d_name, ...) are atom_custom.h's. */
#ifndef GR_ATOM_ATTR_H
#define GR_ATOM_ATTR_H

#include "state.h"

/* The attribute named `word`, or -1. */
int atom_attr_find(const char *word);
/* The names, space-separated, for error messages. */
extern const char atom_attr_names[];
/* An error naming `who` when the atoms do not carry attribute a (`word`):
 * the ellipsoid and heat attributes. */
void atom_attr_check(struct gravel *g, int a, const char *word, const char *who);
/* Attribute a of host atom i (positions as stored; xu yu zu unwrapped). */
double atom_attr_value(const struct gravel *g, int a, int i);

#endif
