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

/* An mdr wall (fix wall/gran/region granular mdr ...) as fix granular/mdr
 * sees it: its material (E nu Y gamma psi_b eta_n0 and damping mdr's
 * type), its region (set by the wall's init; NULL before), the offset of
 * the mdr block in a contact's history (hoff, kernels/param_layout.h enum
 * mdr_hist), the history REAL per contact (hw) and the contact slots per
 * atom: the wall's per-atom state is, per atom, the contact count, `slots`
 * wall ids, then hw REAL per slot (kernels/wall_region.cl region_slots). */
struct region;
struct wall_mdr {
    double par[7];
    struct region *region;
    int hoff, hw, slots;
};
/* 1 and *out when f is such a wall, else 0. */
int wall_gran_mdr(const struct fix *f, struct wall_mdr *out);
/* Such a wall's region surface contacts of its atoms at this step into
 * out (RG_PROBE_W REAL per atom, device order; src/contact/wall_region.h
 * wall_region_probe). */
void wall_gran_mdr_probe(struct gravel *g, struct fix *f, cl_mem out);

#endif
