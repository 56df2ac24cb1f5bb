/* fix_wall_gran.h - what other styles use of fix wall/gran
 * (styles/fix/fix_wall_gran.c): its descriptor, and the wall of fix
 * surface/global, a wall/gran mesh wall on meshes it owns. */
#ifndef GR_STYLE_FIX_WALL_GRAN_H
#define GR_STYLE_FIX_WALL_GRAN_H

#include "fix_mesh_surface.h"

/* fix surface/global's wall: f becomes a fix
 * wall/gran whose wall is the n meshes own (taken over: freed with f),
 * its model the words argv (as wall/gran's before its wall style: hooke
 * ... | granular ...), then wall/gran's options (temperature T). On an
 * error f->data is untouched and the meshes stay the caller's. */
extern const struct fix_style fix_style_wall_gran;
void wall_gran_create_own(struct gravel *g, struct fix *f, int argc, char **argv,
                          struct mesh_surface **own, int n);
/* The meshes of such a wall. */
struct mesh_walls *wall_gran_meshes(struct fix *f);

#endif
