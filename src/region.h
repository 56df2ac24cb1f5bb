/* region.h - geometric regions (LAMMPS region command) and their registry.
 *
 * A region style is a descriptor `const struct region_style region_style_<ident>`
 * in styles/region_<ident>.c, listed once in styles/styles.def as
 * REGION("keyword", ident). The style parses its own arguments (already in box
 * units via the scale factors it is given), fills r->p / r->dim / r->sub and
 * the bounding box, and answers `inside` for the geometric interior; side
 * in|out is applied by region_match(). Boundaries are inclusive as in LAMMPS
 * (a point on a block face or sphere surface is inside). */
#ifndef GR_REGION_H
#define GR_REGION_H

#include "gravel.h"

#define REGION_NPARAM 12

struct region {
    char id[GR_NAMELEN];
    const struct region_style *style;
    int interior;               /* 1: side in (default), 0: side out */
    int lattice_units;          /* 1: units lattice (default), 0: units box */
    double p[REGION_NPARAM];    /* style parameters, box units */
    int dim;                    /* axis (0, 1, 2) for cylinder and cone */
    int nsub;                   /* union / intersect: sub-regions */
    struct region **sub;
    int nref;                   /* how many union/intersect regions use this one */
    int bbox;                   /* 1: lo/hi below bound every point that matches */
    double bbox_lo[3], bbox_hi[3];
};

struct region_style {
    const char *name;
    const char *usage;          /* style arguments, for error messages */
    int nargs;                  /* number of style arguments; -1 = variable (union) */
    /* Parse the style arguments args[0..nargs-1] (nargs counted by the
     * style for variable styles; return how many were consumed). scale
     * converts lattice to box units. Must set r->bbox and the bounds when the
     * interior is bounded. */
    int (*parse)(struct gravel *g, struct region *r, int nargs, char **args,
                 const double scale[3]);
    /* 1 if x is in the geometric interior (before side in|out). */
    int (*inside)(const struct region *r, const double x[3]);
};

/* 1 if x is in region r, with side in|out applied. */
int region_match(const struct region *r, const double x[3]);

/* The region with this ID, or NULL. */
struct region *region_find(struct gravel *g, const char *id);
/* The region with this ID, or an error "unknown region". */
struct region *region_get(struct gravel *g, const char *id);

/* Bounding box of the points that can match r, intersected with the
 * simulation box (which must exist). Returns 0 if the intersection is empty. */
int region_box_bounds(struct gravel *g, const struct region *r, double lo[3], double hi[3]);

/* Parse one region bound: a number (scaled), or INF / -INF / +INF (+-1e20,
 * `is_hi` picks the sign of plain INF), or EDGE (the box face, needs the box).
 * Used by the styles. */
double region_parse_bound(struct gravel *g, const char *s, int dim, int is_hi, double scale,
                          const char *what);

#endif
