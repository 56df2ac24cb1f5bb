/* region_cylinder.h - what region cylinder (styles/region/region_cylinder.c)
 * shares with the other axial region (cone). */
#ifndef GR_REGION_CYLINDER_H
#define GR_REGION_CYLINDER_H

struct gravel;

/* Axis letter x|y|z -> 0|1|2 (cylinder, cone). */
int region_parse_axis(struct gravel *g, const char *s);

#endif
