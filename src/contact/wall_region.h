/* wall_region.h - region walls (wall_region.c): the surface of a LAMMPS
 * region as a contact source of fix wall/gran region. The device record,
 * struct wall_region, and its limits are in wall.h with the other walls. */
#ifndef GR_WALL_REGION_H
#define GR_WALL_REGION_H

#include "wall.h"

/* Check that region r can be a wall (error naming `who` otherwise) and set
 * up wr; returns the per-atom history bytes (0 without history). */
size_t wall_region_init(struct gravel *g, struct wall_region *wr, struct region *r,
                        const struct wall_law *law, const char *who);
/* One wall of a set run by one launch: its fix, region record, region and
 * law. */
struct region_wall {
    struct fix *f;
    struct wall_region *wr;
    struct region *r;
    const struct wall_law *law;
};
/* Evaluate the motion of each wall's region at this step, upload the set
 * (through set[0].wr) and add the contact forces and torques of each
 * wall's atoms, in set order: nwall (1..RS_MAXWALL) walls of one law. */
void wall_region_apply(struct gravel *g, const struct region_wall *set, int nwall);
/* The surface contacts of f's atoms with r at its present position (the
 * contacts wall_region_apply would find, reach the radius) into out:
 * RG_PROBE_W REAL per atom in device order (kernels/wall_region.cl
 * region_probe). Nothing moves. */
void wall_region_probe(struct gravel *g, struct fix *f, struct wall_region *wr,
                       struct region *r, cl_mem out);
void wall_region_release(struct wall_region *wr);

#endif
