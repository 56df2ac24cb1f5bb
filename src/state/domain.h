/* domain.h - the simulation box: boundaries, shrink-wrapping, periodic
 * wrapping, volume and lattice <-> box unit conversion.
 *
 * The box lives in g->dom (state.h). It is created by create_box or
 * read_data through domain_set_initial_box(); afterwards the run core keeps
 * shrink-wrapped faces fitted to the atoms with domain_shrink_wrap(). */
#ifndef GR_DOMAIN_H
#define GR_DOMAIN_H

#include "state.h"

/* LAMMPS' SMALL (domain.cpp): shrink-wrap margin as a fraction of the box length. */
#define DOMAIN_SMALL 1.0e-4
/* LAMMPS' BIG: what INF stands for in region bounds. */
#define DOMAIN_BIG 1.0e20

/* Set the boundary flags from three words of p f s m (the `boundary` and
 * `change_box ... boundary` arguments); errors leave the flags unchanged. */
void domain_set_boundary(struct gravel *g, char **argv);

/* Finish a box whose g->dom.lo/hi were just set (create_box, read_data), as
 * LAMMPS' Domain::set_initial_box(1): small[d] = 1e-4 * (hi - lo); faces with
 * 's' move outward by small; faces with 'm' record their position as the
 * minimum extent. Errors if lo >= hi in some dimension. Sets box_exists. */
void domain_set_initial_box(struct gravel *g);

/* Fit the non-periodic faces to the atom extent lo[d]..hi[d], as LAMMPS'
 * Domain::reset_box(): 's' face: lo = extent_lo - small, hi = extent_hi + small;
 * 'm' face: the same but never inside the face recorded at box creation;
 * 'f' faces and periodic dimensions are untouched. An empty extent (some
 * lo[d] > hi[d], no atoms) changes nothing. Errors if the box turns inside out. */
void domain_shrink_wrap(struct gravel *g, const double lo[3], const double hi[3]);

/* 1 if dimension d is periodic for wrapping, binning and minimum images.
 * In 2d (g->dom.dimension == 2, set by the `dimension` command) z is
 * periodic by LAMMPS's rule but thin: every atom stays in one z plane
 * (fix enforce2d), so z is neither wrapped nor imaged and has one cell. */
int domain_contact_periodic(const struct gravel *g, int d);

/* Box volume (product of the three lengths). 0 before the box exists. */
double domain_volume(const struct gravel *g);

/* Triclinic geometry, LAMMPS's conventions (Domain::set_global_box):
 * h = (Lx, Ly, Lz, yz, xz, xy) and its inverse (upper triangular); lamda
 * (fractional) coordinates lamda = h_inv (x - lo), x = h lamda + lo, with
 * LAMMPS's operation order (the bits matter). Valid for orthogonal boxes too
 * (tilts 0). */
void domain_h(const struct gravel *g, double h[6]);
void domain_h_inv(const struct gravel *g, double hinv[6]);
void domain_x2lamda(const struct gravel *g, const double x[3], double lam[3]);
void domain_lamda2x(const struct gravel *g, const double lam[3], double x[3]);
/* Errors for tilts that LAMMPS refuses: a non-zero tilt along a non-periodic
 * dimension (xy needs y periodic, xz and yz z periodic), z tilts in 2d. */
void domain_check_tilt(struct gravel *g);
/* Errors for a triclinic box skewed beyond half a box length, LAMMPS's
 * "Triclinic box skew is too large" of Domain::set_initial_box (|xy| and
 * |xz| at most Lx / 2, |yz| at most Ly / 2): create_box, read_data and
 * change_box. fix deform is exempt (it flips the box, as LAMMPS). */
void domain_check_skew(struct gravel *g);
/* Per dimension, how much wider than a separation's length its component of
 * u = L lamda can be: f_q = |row q of L h^-1| (1 when orthogonal). Cells of
 * u hold every partner within cut in the neighboring cells when they are
 * at least cut f_q wide (kernels/common.cl box_ufac, the same numbers). */
void domain_ufac(const struct domain *d, double f[3]);
/* The bounding box of a (tilted) box, LAMMPS's boxlo_bound / boxhi_bound:
 * lo + min(0, xy, xz, xy + xz) in x, lo + min(0, yz) in y (hi with max). */
void domain_bbox(const struct gravel *g, double lo[3], double hi[3]);
/* "  orthogonal box = (...) to (...)" or "  triclinic box = ... with tilt
 * (xy xz yz)" as LAMMPS prints it, after indent. */
void domain_print_box(struct gravel *g, const char *indent);

/* Wrap x into [lo, hi) in every periodic dimension, updating the image
 * counts (LAMMPS' Domain::remap; triclinic: the lamda coordinates wrap into
 * [0, 1) and x is mapped back). Non-periodic dimensions and non-finite
 * coordinates are left alone. image may be NULL. */
void domain_remap(const struct gravel *g, double x[3], int image[3]);

/* Unwrapped position x + image . (a, b, c) (periodic dimensions only). */
void domain_unmap(const struct gravel *g, const double x[3], const int image[3], double out[3]);

/* Shortest periodic image of a separation vector (minimum image convention;
 * triclinic: z, then y, then x, each image shifting the tilted components). */
void domain_minimum_image(const struct gravel *g, double del[3]);

/* 1 if x is inside the box as LAMMPS assigns atoms to it: lo <= x < hi
 * (triclinic: 0 <= lamda < 1). */
int domain_inside(const struct gravel *g, const double x[3]);

/* Lattice <-> box units: with units lattice, a length along dimension d is
 * multiplied by the lattice spacing g->dom.lat.a[d] (xlattice, ylattice,
 * zlattice in LAMMPS). lattice_flag 0 (units box) gives factor 1. */
void domain_unit_scale(const struct gravel *g, int lattice_flag, double scale[3]);

/* Convert a vector in place: lattice units -> box units (times a[d]) and back. */
void domain_lattice_to_box(const struct gravel *g, double v[3]);
void domain_box_to_lattice(const struct gravel *g, double v[3]);

/* Parse the value of a `units` keyword: "box" -> 0, "lattice" -> 1. */
int domain_parse_units_kw(struct gravel *g, const char *value);

/* Error unless the box exists (for commands that need it). */
void domain_require_box(struct gravel *g);

#endif
