/* superellipsoid.h - the geometry and mass properties of a superellipsoid
 * ((x/a)^n2 + (y/b)^n2)^(n1/n2) + (z/c)^n1 = 1 in its body frame, as LAMMPS
 * 30 Mar 2026 computes them (atom_vec_ellipsoid.cpp, MathExtra): semi-axes
 * a b c (`shape`), blockiness n1 n2 (`block`; 2 2 is an ellipsoid, large
 * values a box). Pure functions. */
#ifndef GR_SUPERELLIPSOID_H
#define GR_SUPERELLIPSOID_H

/* enum sqe_kind (LAMMPS's BlockType) and sqe_kind(block): in the geometry
 * the host and the device share (kernels/superellipsoid_geom.h). */
#include "superellipsoid_geom.h"

/* Euler's Beta function B(x, y) = G(x) G(y) / G(x + y), x, y > 0. */
double sqe_beta(double x, double y);
/* Volume a b c e1 e2 B(e1/2, 1 + e1) B(e2/2, e2/2), e = 2/n (4/3 pi a b c
 * for an ellipsoid). */
double sqe_volume(const double shape[3], const double block[2]);
/* Principal moments of inertia of mass m about the body axes (Jaklic &
 * Solina 2003 eq. 12; m (b^2 + c^2)/5 ... for an ellipsoid). */
void sqe_inertia(const double shape[3], double mass, const double block[2], double idiag[3]);
/* The bounding (circumscribed) radius LAMMPS uses for neighbor lists: the
 * largest semi-axis for an ellipsoid; sqrt(a^2 + c^2) for n2 = 2
 * (cylinder), max(c, sqrt(a^2 + b^2)) for n1 = 2, else the box diagonal
 * sqrt(a^2 + b^2 + c^2) (a >= b the larger in-plane semi-axis). */
double sqe_bounding_radius(const double shape[3], const double block[2]);

#endif
