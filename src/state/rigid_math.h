/* rigid_math.h - rigid-body rotation arithmetic (LAMMPS MathExtra's
 * quaternion and principal-axes helpers, the same operations in the same
 * order so rigid bodies follow LAMMPS's trajectories to round-off).
 * Quaternions are (w, x, y, z); ex, ey, ez are the columns of the rotation
 * matrix from the body frame to the space frame. Pure functions. */
#ifndef GR_RIGID_MATH_H
#define GR_RIGID_MATH_H

/* Eigenvalues (decreasing) and eigenvectors (columns of evec) of a
 * symmetric 3x3 matrix by cyclic Jacobi rotations; 0, or 1 if it did not
 * converge. */
int rm_jacobi3(const double m[3][3], double eval[3], double evec[3][3]);
/* Principal axes of the inertia tensor t (xx yy zz yz xz xy, LAMMPS's
 * Voigt order): moments (0 below 1e-7 x the largest), right-handed axes,
 * the quaternion; 2d: the axis along z is made the third. 0 or 1 (Jacobi
 * failed). */
int rm_principal(const double t[6], int dim2, double inertia[3], double ex[3], double ey[3],
                 double ez[3], double q[4]);
void rm_exyz_to_q(const double ex[3], const double ey[3], const double ez[3], double q[4]);
void rm_q_to_exyz(const double q[4], double ex[3], double ey[3], double ez[3]);
void rm_quat_to_mat(const double q[4], double m[3][3]);
void rm_axisangle_to_quat(const double v[3], double angle, double q[4]);
void rm_quatquat(const double a[4], const double b[4], double c[4]);
/* space-frame angular momentum -> space-frame angular velocity */
void rm_angmom_to_omega(const double m[3], const double ex[3], const double ey[3],
                        const double ez[3], const double idiag[3], double w[3]);
/* full-step quaternion update by Richardson iteration (LAMMPS
 * MathExtra::richardson; w is updated to the half step's omega) */
void rm_richardson(double q[4], const double m[3], double w[3], const double moments[3],
                   double dtq);
/* ex ey ez times v (body -> space), and the transpose (space -> body) */
void rm_matvec(const double ex[3], const double ey[3], const double ez[3], const double v[3],
               double out[3]);
void rm_transpose_matvec(const double ex[3], const double ey[3], const double ez[3],
                         const double v[3], double out[3]);
/* The unit vector along axis a, for every finite a however large or small
 * (scaled by its largest component first when |a|^2 would overflow or
 * underflow; otherwise a / |a| as computed before, bit for bit): 0, or -1
 * when a is zero or not finite. Used by every command that takes a rotation
 * axis (fix mesh/surface rotate, fix move/mesh rotate, displace_atoms
 * rotate, region rotate). */
int rm_unit_axis(const double a[3], double u[3]);

#endif
