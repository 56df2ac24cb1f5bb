/* region.h - geometric regions (LAMMPS region command) and their registry.
 *
 * A region style is a descriptor `const struct region_style region_style_<ident>`
 * in styles/region_<ident>.c, listed once in styles/styles.def as
 * REGION("keyword", ident). The style parses its own arguments (already in box
 * units via the scale factors it is given), fills r->p / r->dim / r->sub and
 * the bounding box, and answers `inside` for the geometric interior; side
 * in|out is applied by region_match(). Boundaries are inclusive as in LAMMPS
 * (a point on a block face or sphere surface is inside).
 *
 * Motion (LAMMPS region keywords `move v_x v_y v_z`, `rotate v_theta Px Py
 * Pz Rx Ry Rz`): the region is its static shape carried by a displacement d
 * and a rotation by theta about the axis through P; region_prematch()
 * evaluates the equal-style variables (call it once before a loop over
 * points), region_match() takes the point back into the static frame
 * (subtract d, then rotate by -theta about P). `open N` removes face N of a
 * block (1..6), cylinder or cone (1..3) for wall contacts; a region with an
 * open face matches every point (LAMMPS). */
#ifndef GR_REGION_H
#define GR_REGION_H

#include "state.h"

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
    int deleted;                /* `region ID delete`d, alive for the compounds using it */
    int bbox;                   /* 1: lo/hi below bound every point that matches */
    double bbox_lo[3], bbox_hi[3];
    /* motion and open faces (see above) */
    int moveflag, rotateflag, openflag, open_faces[6];
    char mvar[3][GR_NAMELEN];   /* move: variable names ("" = NULL) */
    char tvar[GR_NAMELEN];      /* rotate: variable name */
    double point[3], axis[3], runit[3];
    double d[3], theta;         /* current displacement and angle */
    /* wall velocity by differences (LAMMPS Region::set_velocity) */
    double prev[4], v[3], omega[3], rpoint[3];
    bigint vel_step;            /* step of the last set_velocity, -1: none */
    int prev_set;               /* prev holds an earlier evaluation */
    int cmax;                   /* most contacts its surface can report (wall ids) */
    void *data;                 /* style data beyond p[] (mesh/tet: its tetrahedra) */
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
    void (*destroy)(void *data); /* optional: frees r->data */
};

/* 1 if x is in region r, with side in|out and the current motion applied
 * (an open region matches every point). */
int region_match(const struct region *r, const double x[3]);
/* Evaluate the motion variables of r and of its sub-regions at the current
 * step (LAMMPS Region::prematch). No-op for a static region. */
void region_prematch(struct gravel *g, struct region *r);
/* A union / intersect whose sub-region was deleted takes the region now
 * defined with that ID (error if none); region_prematch does this first. */
void region_relink(struct gravel *g, struct region *r);
/* 1 if r or a sub-region moves or rotates. */
int region_dynamic(const struct region *r);
/* Update r's surface velocity from the change of d and theta since the
 * previous step, once per step (LAMMPS Region::set_velocity: zero at step
 * 0 unless an earlier evaluation exists, i.e. after reset_timestep 0;
 * omega = dtheta/dt times the axis as given). */
void region_set_velocity(struct gravel *g, struct region *r);
/* Rotate x about the axis through r->point by the angle with sine s and
 * cosine c (LAMMPS Region::rotate, same operation order). */
void region_rotate(const struct region *r, double x[3], double s, double c);

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

/* Release every region (`clear`, destroy: gravel.c). */
void regions_free(struct gravel *g);

#endif
