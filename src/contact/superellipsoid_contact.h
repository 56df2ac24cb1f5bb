/* superellipsoid_contact.h - the contact geometry of two superellipsoids as
 * LAMMPS 30 Mar 2026 finds it (MathExtraSuperellipsoids, pair
 * granular/superellipsoid): pure functions of the particles' centres xc,
 * rotation matrices R (body to space, columns the body axes), semi-axes and
 * blockiness (superellipsoid.h).
 *
 * Shape function (body frame, x = R^T (X - xc)):
 *   F(x) = ((|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1) - 1,
 * negative inside; the "algebraic" formulation solves with F itself, the
 * "geometric" one with G = r (F + 1)^(1/n1) - r (r the mean semi-axis), a
 * distance-like function.
 * Contact point ("midway" point, Houlsby 2009): X0 minimises F_i + F_j on
 * F_i = F_j, i.e. grad F_i + mu^2 grad F_j = 0 and F_i - F_j = 0, solved by
 * Newton's method on (X, mu^2) with a step limit (0.2 |xc_i - xc_j|), a
 * backtracking Armijo line search and a Tikhonov-regularised fallback for a
 * singular Jacobian; converged when the scaled residual is below 1e-10 and
 * the last step below 1e-6 |xc_i - xc_j|. The particles touch when both
 * shape functions are <= 0 there. The normal n_ij is grad F_i / |grad F_i|
 * (from i towards j); each particle's overlap is the distance along the
 * normal from X0 to its own surface (the other's direction for j). */
#ifndef GR_SUPERELLIPSOID_CONTACT_H
#define GR_SUPERELLIPSOID_CONTACT_H

#include "superellipsoid.h"

enum sqe_formulation { SQE_ALGEBRAIC, SQE_GEOMETRIC };

/* One particle's geometry. */
struct sqe_body {
    double xc[3];
    double R[3][3];
    double shape[3];
    double block[2];
    enum sqe_kind kind;
};

/* F - 1 at body-frame point xl, its gradient and Hessian (body frame). */
double sqe_shape_local(const double xl[3], const double shape[3], const double block[2],
                       enum sqe_kind kind, double grad[3], double hess[3][3]);
/* The contact point: X0[0..2] the point, X0[3] = mu^2, starting from the
 * values in X0. Returns 0 converged and touching, 1 separated (converged,
 * or not converged with a positive shape function), 2 not converged while
 * seemingly overlapping; nij is set when converged. */
int sqe_contact_point(const struct sqe_body *bi, const struct sqe_body *bj, double X0[4],
                      double nij[3], enum sqe_formulation form);
/* Distance from global point X along unit normal n to the surface of body b
 * (closed form for an ellipsoid, Newton's method on the radial distance
 * function otherwise, 20 iterations at most, |residual| < 1e-8). */
double sqe_overlap_distance(const struct sqe_body *b, const double X[3], const double n[3]);
/* Mean curvature |n.H n - tr H| / (2 |grad F|) (gaussian = 0) or the square
 * root of the Gaussian curvature |K| (gaussian = 1) of body b at its surface
 * point X. */
double sqe_curvature(const struct sqe_body *b, const double X[3], int gaussian);
/* Oriented bounding boxes (semi-axes as half-widths) of the two bodies:
 * the index 0..14 of a separating axis (the 3 + 3 face normals and 9 edge
 * cross products, `first` tried first), or -1 when the boxes intersect. */
int sqe_obb_separating_axis(const struct sqe_body *bi, const struct sqe_body *bj, int first);

#endif
