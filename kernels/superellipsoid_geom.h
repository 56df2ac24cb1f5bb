/* superellipsoid_geom.h - the contact geometry of two superellipsoids as
 * LAMMPS 30 Mar 2026 finds it (MathExtraSuperellipsoids, pair
 * granular/superellipsoid), in its operation order: ONE source for the host
 * and the device. The host's src/contact/superellipsoid_contact.c compiles
 * the bodies (SQE_DEFINE); any other host file gets the types and the
 * prototypes; an OpenCL program that includes this file (after common.cl's
 * fp64 and FP_CONTRACT OFF pragmas) gets every function static inline. Pure
 * functions of the particles' centres xc, rotation matrices R (body to
 * space, columns the body axes), semi-axes and blockiness; plain C arrays in
 * the private address space, no library calls beyond math.
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
#ifndef GR_SUPERELLIPSOID_GEOM_H
#define GR_SUPERELLIPSOID_GEOM_H

#ifdef __OPENCL_VERSION__
#define SQE_API static inline
#define SQE_LOCAL static inline
#define SQE_BODIES 1
#else
#include <math.h>
#define SQE_API
#define SQE_LOCAL static
#ifdef SQE_DEFINE
#define SQE_BODIES 1
#else
#define SQE_BODIES 0
#endif
#endif

/* LAMMPS's BlockType: within 1e-3 of n1 = n2 = 2 an ellipsoid (exact
 * ellipsoid formulas), n1 = n2 within 1e-3, or general. */
enum sqe_kind { SQE_ELLIPSOID, SQE_N1_EQUAL_N2, SQE_GENERAL };
#define SQE_EPSILON_BLOCK 1.0e-3

enum sqe_formulation { SQE_ALGEBRAIC, SQE_GEOMETRIC };

/* One particle's geometry. */
struct sqe_body {
    double xc[3];
    double R[3][3];
    double shape[3];
    double block[2];
    enum sqe_kind kind;
};

#if !SQE_BODIES
/* The kind of blockiness n1 n2. */
enum sqe_kind sqe_kind(const double block[2]);
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
#else

enum {
    SQE_NEWTON_MAX = 100,   /* Newton iterations */
    SQE_LINE_MAX = 10,      /* backtracking steps */
    SQE_OVERLAP_MAX = 20,   /* overlap-distance Newton iterations */
};
#define SQE_TOL_RES 1e-20       /* scaled squared residual (1e-10^2) */
#define SQE_TOL_POS 1e-12       /* squared step / squared centre distance */
#define SQE_ARMIJO 1e-4
#define SQE_CUTBACK 0.5
#define SQE_TIKHONOV 1e-14
#define SQE_MAX_SOLUTION 1e30
#define SQE_TOL_OVERLAP 1e-8
#define SQE_MIN_SLOPE 1e-12
#define SQE_REG_EPSILON 1e-12

/* LAMMPS's BlockType of blockiness n1 n2 */
SQE_API enum sqe_kind sqe_kind(const double block[2])
{
    if (fabs(block[0] - 2.0) <= SQE_EPSILON_BLOCK && fabs(block[1] - 2.0) <= SQE_EPSILON_BLOCK)
        return SQE_ELLIPSOID;
    if (fabs(block[0] - block[1]) <= SQE_EPSILON_BLOCK)
        return SQE_N1_EQUAL_N2;
    return SQE_GENERAL;
}

/* ---- small linear algebra ------------------------------------------------ */

SQE_LOCAL void sqe_matT_vec(const double R[3][3], const double v[3], double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = R[0][i] * v[0] + R[1][i] * v[1] + R[2][i] * v[2];
}

SQE_LOCAL void sqe_mat_vec(const double R[3][3], const double v[3], double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = R[i][0] * v[0] + R[i][1] * v[1] + R[i][2] * v[2];
}

SQE_LOCAL double sqe_dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

SQE_LOCAL void sqe_unit3(const double v[3], double out[3])
{
    double s = 1.0 / sqrt(sqe_dot3(v, v));
    for (int k = 0; k < 3; k++)
        out[k] = v[k] * s;
}

/* H <- R H R^T */
SQE_LOCAL void sqe_to_space(const double R[3][3], double H[3][3])
{
    double t[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            t[i][j] = H[i][0] * R[j][0] + H[i][1] * R[j][1] + H[i][2] * R[j][2];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            H[i][j] = R[i][0] * t[0][j] + R[i][1] * t[1][j] + R[i][2] * t[2][j];
}

SQE_LOCAL double sqe_det3(const double m[3][3])
{
    return m[0][0] * m[1][1] * m[2][2] - m[0][0] * m[1][2] * m[2][1] -
           m[1][0] * m[0][1] * m[2][2] + m[1][0] * m[0][2] * m[2][1] +
           m[2][0] * m[0][1] * m[1][2] - m[2][0] * m[0][2] * m[1][1];
}

/* Solve A x = b (A row-major 4x4) by Gaussian elimination with partial
 * pivoting, x into b; 0 when a pivot is exactly zero. A is destroyed. */
SQE_LOCAL int sqe_solve4(double A[16], double b[4])
{
    for (int c = 0; c < 4; c++) {
        int p = c;
        double best = fabs(A[4 * c + c]);
        for (int r = c + 1; r < 4; r++)
            if (fabs(A[4 * r + c]) > best)
                best = fabs(A[4 * r + c]), p = r;
        if (!(best > 0.0))
            return 0;
        if (p != c) {
            for (int k = c; k < 4; k++) {
                double t = A[4 * c + k];
                A[4 * c + k] = A[4 * p + k];
                A[4 * p + k] = t;
            }
            double t = b[c];
            b[c] = b[p];
            b[p] = t;
        }
        double inv = 1.0 / A[4 * c + c];
        for (int r = c + 1; r < 4; r++) {
            double f = A[4 * r + c] * inv;
            for (int k = c + 1; k < 4; k++)
                A[4 * r + k] -= f * A[4 * c + k];
            b[r] -= f * b[c];
        }
    }
    for (int r = 3; r >= 0; r--) {
        double s = b[r];
        for (int k = r + 1; k < 4; k++)
            s -= A[4 * r + k] * b[k];
        b[r] = s * (1.0 / A[4 * r + r]);
    }
    return 1;
}

/* ---- shape functions ---------------------------------------------------- */

SQE_LOCAL double sqe_sgn(double v) { return v > 0.0 ? 1.0 : -1.0; }

SQE_API double sqe_shape_local(const double xl[3], const double shape[3], const double block[2],
                               enum sqe_kind kind, double grad[3], double hess[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            hess[i][j] = 0.0;
    if (kind == SQE_ELLIPSOID) {
        double s = 0.0;
        for (int k = 0; k < 3; k++) {
            double w = 2.0 / (shape[k] * shape[k]);
            grad[k] = w * xl[k];
            hess[k][k] = w;
            s += grad[k] * xl[k];
        }
        return 0.5 * s - 1.0;
    }
    if (kind == SQE_N1_EQUAL_N2) {
        double n = block[0], F = 0.0;
        for (int k = 0; k < 3; k++) {
            double inv = 1.0 / shape[k], t = fabs(xl[k] * inv);
            double pm2 = pow(t, n - 2.0), pm1 = pm2 * t;
            grad[k] = n * inv * pm1 * sqe_sgn(xl[k]);
            hess[k][k] = inv * inv * n * (n - 1.0) * pm2;
            F += pm1 * t;
        }
        return F - 1.0;
    }
    double n1 = block[0], n2 = block[1];
    double ai = 1.0 / shape[0], bi = 1.0 / shape[1], ci = 1.0 / shape[2];
    double tx = fabs(xl[0] * ai), ty = fabs(xl[1] * bi), tz = fabs(xl[2] * ci);
    double xm2 = pow(tx, n2 - 2.0), xm1 = xm2 * tx;
    double ym2 = pow(ty, n2 - 2.0), ym1 = ym2 * ty;
    double nu = xm1 * tx + ym1 * ty;
    double num2 = pow(nu, n1 / n2 - 2.0), num1 = num2 * nu;
    double zm2 = pow(tz, n1 - 2.0), zm1 = zm2 * tz;
    double sx = sqe_sgn(xl[0]), sy = sqe_sgn(xl[1]);
    grad[0] = n1 * ai * xm1 * num1 * sx;
    grad[1] = n1 * bi * ym1 * num1 * sy;
    grad[2] = n1 * ci * zm1 * sqe_sgn(xl[2]);
    hess[0][0] = ai * ai * (n1 * (n2 - 1.0) * xm2 * num1 + (n1 - n2) * n1 * (xm1 * xm1) * num2);
    hess[1][1] = bi * bi * (n1 * (n2 - 1.0) * ym2 * num1 + (n1 - n2) * n1 * (ym1 * ym1) * num2);
    hess[0][1] = hess[1][0] = ai * bi * (n1 - n2) * n1 * xm1 * ym1 * num2 * (sx * sy);
    hess[2][2] = ci * ci * n1 * (n1 - 1.0) * zm2;
    return num1 * nu + zm1 * tz - 1.0;
}

/* The radial distance function F^(1/n1) - 1 and its gradient (body frame),
 * used for the normal of an already converged point and the overlap
 * search: an ellipsoid or n1 = n2 body takes the n1 = n2 form with
 * n = n1. */
SQE_LOCAL double sqe_surface_local(const double xl[3], const double shape[3], const double block[2],
                                   enum sqe_kind kind, double grad[3])
{
    double F, n;
    if (kind != SQE_GENERAL) {
        n = block[0];
        F = 0.0;
        for (int k = 0; k < 3; k++) {
            double inv = 1.0 / shape[k], t = fabs(xl[k] * inv);
            double pm1 = pow(t, n - 2.0) * t;
            grad[k] = n * inv * pm1 * sqe_sgn(xl[k]);
            F += pm1 * t;
        }
    } else {
        double n1 = block[0], n2 = block[1];
        double ai = 1.0 / shape[0], bi = 1.0 / shape[1], ci = 1.0 / shape[2];
        double tx = fabs(xl[0] * ai), ty = fabs(xl[1] * bi), tz = fabs(xl[2] * ci);
        double xm1 = pow(tx, n2 - 2.0) * tx, ym1 = pow(ty, n2 - 2.0) * ty;
        double nu = xm1 * tx + ym1 * ty;
        double num1 = pow(nu, n1 / n2 - 2.0) * nu;
        double zm1 = pow(tz, n1 - 2.0) * tz;
        grad[0] = n1 * ai * xm1 * num1 * sqe_sgn(xl[0]);
        grad[1] = n1 * bi * ym1 * num1 * sqe_sgn(xl[1]);
        grad[2] = n1 * ci * zm1 * sqe_sgn(xl[2]);
        F = num1 * nu + zm1 * tz;
        n = n1;
    }
    double s = pow(F, 1.0 / n - 1.0) / n;
    for (int k = 0; k < 3; k++)
        grad[k] *= s;
    return pow(F, 1.0 / n) - 1.0;
}

/* Geometric formulation: G = r ((F + 1)^(1/n1) - 1) from value = F - 1
 * (F + 1 floored at 1e-12), with its gradient and Hessian. */
SQE_LOCAL void sqe_regularize(double n1, double r, double *value, double grad[3], double hess[3][3])
{
    double base = fmax(*value + 1.0, SQE_REG_EPSILON), inv = 1.0 / base, in1 = 1.0 / n1;
    double p = pow(base, in1);
    double s1 = r * in1 * p * inv, s2 = s1 * (in1 - 1.0) * inv;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            hess[i][j] = hess[i][j] * s1 + s2 * (grad[i] * grad[j]);
    for (int i = 0; i < 3; i++)
        grad[i] *= s1;
    *value = r * (p - 1.0);
}

/* The solver's function of body b at global X: value, space-frame gradient
 * and (with hess) Hessian. */
SQE_LOCAL double sqe_shape_global(const struct sqe_body *b, const double X[3],
                                  enum sqe_formulation form, double r, double grad[3],
                                  double hess[3][3], int want_hess)
{
    double d[3] = {X[0] - b->xc[0], X[1] - b->xc[1], X[2] - b->xc[2]}, xl[3], gl[3];
    sqe_matT_vec(b->R, d, xl);
    double v = sqe_shape_local(xl, b->shape, b->block, b->kind, gl, hess);
    if (form == SQE_GEOMETRIC)
        sqe_regularize(b->block[0], r, &v, gl, hess);
    sqe_mat_vec(b->R, gl, grad);
    if (want_hess)
        sqe_to_space(b->R, hess);
    return v;
}

/* Scaled squared residual of the midway conditions. */
SQE_LOCAL double sqe_residual(double fi, const double gi[3], double fj, const double gj[3],
                              double mu2, double res[4], enum sqe_formulation form,
                              double rscale)
{
    for (int k = 0; k < 3; k++)
        res[k] = mu2 * gj[k] + gi[k];
    res[3] = fi - fj;
    double gmag = 0.5 * (sqe_dot3(gi, gi) + sqe_dot3(gj, gj));
    double spatial = (res[0] * res[0] + res[1] * res[1] + res[2] * res[2]) / gmag;
    double den = form == SQE_GEOMETRIC ? rscale : fi + 1.0;
    if (fabs(den) < 1e-12)
        den = 1.0;
    return spatial + res[3] * res[3] / (den * den);
}

SQE_LOCAL void sqe_jacobian(const double gi[3], double Hi[3][3], const double gj[3],
                            double Hj[3][3], double mu2, double J[16])
{
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++)
            J[4 * r + c] = Hi[r][c] + mu2 * Hj[r][c];
        J[4 * r + 3] = gj[r];
    }
    for (int c = 0; c < 3; c++)
        J[12 + c] = gi[c] - gj[c];
    J[15] = 0.0;
}

struct sqe_solver {
    const struct sqe_body *bi, *bj;
    enum sqe_formulation form;
    double ri, rj;          /* mean semi-axes (geometric formulation), else 1 */
    double f[2], gi[3], res[4], J[16];
};

/* Residual (and Jacobian with want_jac) of the solver at X (X[3] = mu^2). */
SQE_LOCAL double sqe_evaluate(struct sqe_solver *s, const double X[4], int want_jac)
{
    double gj[3], Hi[3][3], Hj[3][3];
    s->f[0] = sqe_shape_global(s->bi, X, s->form, s->ri, s->gi, Hi, want_jac);
    s->f[1] = sqe_shape_global(s->bj, X, s->form, s->rj, gj, Hj, want_jac);
    if (want_jac)
        sqe_jacobian(s->gi, Hi, gj, Hj, X[3], s->J);
    return sqe_residual(s->f[0], s->gi, s->f[1], gj, X[3], s->res, s->form, 0.5 * (s->ri + s->rj));
}

/* The normal at X from body i's radial distance function. */
SQE_LOCAL void sqe_surface_normal(const struct sqe_body *b, const double X[3], double n[3])
{
    double d[3] = {X[0] - b->xc[0], X[1] - b->xc[1], X[2] - b->xc[2]}, xl[3], gl[3], g[3];
    sqe_matT_vec(b->R, d, xl);
    sqe_surface_local(xl, b->shape, b->block, b->kind, gl);
    sqe_mat_vec(b->R, gl, g);
    sqe_unit3(g, n);
}

SQE_LOCAL int sqe_touching(const struct sqe_solver *s) { return !(s->f[0] > 0.0 || s->f[1] > 0.0); }

SQE_API int sqe_contact_point(const struct sqe_body *bi, const struct sqe_body *bj, double X0[4],
                              double nij[3], enum sqe_formulation form)
{
    struct sqe_solver s = {.bi = bi, .bj = bj, .form = form, .ri = 1.0, .rj = 1.0};
    double dc[3] = {bi->xc[0] - bj->xc[0], bi->xc[1] - bj->xc[1], bi->xc[2] - bj->xc[2]};
    double lsq = sqe_dot3(dc, dc), max_step = 0.2 * sqrt(lsq);
    if (form == SQE_GEOMETRIC) {
        s.ri = (bi->shape[0] + bi->shape[1] + bi->shape[2]) * (1.0 / 3.0);
        s.rj = (bj->shape[0] + bj->shape[1] + bj->shape[2]) * (1.0 / 3.0);
    }
    double norm = sqe_evaluate(&s, X0, 1);
    if (norm < SQE_TOL_RES) { /* the guess (the last step's point) still holds */
        sqe_surface_normal(bi, X0, nij);
        return sqe_touching(&s) ? 0 : 1;
    }
    int converged = 0;
    for (int it = 0; it < SQE_NEWTON_MAX && !converged; it++) {
        double norm_old = norm, A[16], step[4];
        for (int k = 0; k < 16; k++)
            A[k] = s.J[k];
        for (int k = 0; k < 4; k++)
            step[k] = -s.res[k];
        int ok = sqe_solve4(A, step);
        for (int k = 0; k < 4; k++)
            if (!isfinite(step[k]) || fabs(step[k]) > SQE_MAX_SOLUTION)
                ok = 0;
        if (!ok) { /* flat on flat: a Tikhonov-regularised spatial block */
            double b[4];
            for (int k = 0; k < 16; k++)
                A[k] = s.J[k];
            for (int k = 0; k < 4; k++)
                b[k] = -s.res[k];
            double w = fmax(SQE_TIKHONOV * (s.J[0] + s.J[5] + s.J[10]), SQE_TIKHONOV);
            A[0] += w, A[5] += w, A[10] += w;
            if (sqe_solve4(A, b))
                for (int k = 0; k < 4; k++)
                    step[k] = b[k];
        }
        double len = sqrt(step[0] * step[0] + step[1] * step[1] + step[2] * step[2]);
        if (len > max_step)
            for (int k = 0; k < 3; k++)
                step[k] *= max_step / len;
        double a = 1.0, Xl[4];
        int ls;
        for (ls = 0; ls < SQE_LINE_MAX; ls++) {
            for (int k = 0; k < 4; k++)
                Xl[k] = X0[k] + a * step[k];
            norm = sqe_evaluate(&s, Xl, 0);
            double sq = step[0] * step[0] + step[1] * step[1] + step[2] * step[2];
            if (norm <= SQE_TOL_RES && sq * a * a <= SQE_TOL_POS * lsq) {
                converged = 1;
                sqe_unit3(s.gi, nij);
                break;
            }
            if (norm > norm_old - SQE_ARMIJO * a * norm_old) {
                a *= SQE_CUTBACK;
            } else {
                sqe_evaluate(&s, Xl, 1); /* the next Newton step's Jacobian */
                break;
            }
        }
        if (ls == SQE_LINE_MAX) { /* no descent: take the full step to leave the region */
            for (int k = 0; k < 4; k++)
                X0[k] += step[k];
            norm = sqe_evaluate(&s, X0, 1);
            if (norm < SQE_TOL_RES) {
                converged = 1;
                sqe_unit3(s.gi, nij);
            }
        } else {
            for (int k = 0; k < 4; k++)
                X0[k] = Xl[k];
        }
    }
    if (!converged)
        return sqe_touching(&s) ? 2 : 1;
    return sqe_touching(&s) ? 0 : 1;
}

SQE_API double sqe_overlap_distance(const struct sqe_body *b, const double X[3], const double n[3])
{
    double d[3] = {X[0] - b->xc[0], X[1] - b->xc[1], X[2] - b->xc[2]}, p[3], m[3];
    sqe_matT_vec(b->R, d, p);
    sqe_matT_vec(b->R, n, m);
    if (b->kind == SQE_ELLIPSOID) { /* |p + t m| on the ellipsoid: a quadratic in t */
        double A = 0.0, B = 0.0, C = -1.0;
        for (int k = 0; k < 3; k++) {
            double w = 1.0 / (b->shape[k] * b->shape[k]);
            A += m[k] * m[k] * w;
            B += p[k] * m[k] * w;
            C += p[k] * p[k] * w;
        }
        B *= 2.0;
        double disc = fmax(B * B - 4.0 * A * C, 0.0);
        return (-B + sqrt(disc)) / (2.0 * A);
    }
    double t = 0.0;
    for (int it = 0; it < SQE_OVERLAP_MAX; it++) {
        double q[3] = {p[0] + t * m[0], p[1] + t * m[1], p[2] + t * m[2]}, g[3];
        double v = sqe_surface_local(q, b->shape, b->block, b->kind, g);
        if (fabs(v) < SQE_TOL_OVERLAP)
            break;
        double slope = sqe_dot3(g, m);
        if (fabs(slope) < SQE_MIN_SLOPE)
            break;
        t -= v / slope;
    }
    return t;
}

SQE_API double sqe_curvature(const struct sqe_body *b, const double X[3], int gaussian)
{
    double d[3] = {X[0] - b->xc[0], X[1] - b->xc[1], X[2] - b->xc[2]}, xl[3], g[3], H[3][3];
    sqe_matT_vec(b->R, d, xl);
    sqe_shape_local(xl, b->shape, b->block, b->kind, g, H);
    double gmag = sqrt(sqe_dot3(g, g));
    if (!gaussian) {
        double n[3], Hn[3];
        sqe_unit3(g, n);
        sqe_mat_vec(H, n, Hn);
        return fabs(sqe_dot3(n, Hn) - (H[0][0] + H[1][1] + H[2][2])) / (2.0 * gmag);
    }
    /* K = -det [[H, g], [g^T, 0]] / |g|^4, by cofactors of the last row */
    double m[3][3][3];
    for (int drop = 0; drop < 3; drop++)
        for (int r = 0; r < 3; r++)
            for (int c = 0, cc = 0; c < 3; c++) {
                if (c == drop)
                    continue;
                m[drop][r][cc++] = H[r][c];
                if (cc == 2)
                    m[drop][r][2] = g[r];
            }
    double det = -g[0] * sqe_det3(m[0]) + g[1] * sqe_det3(m[1]) - g[2] * sqe_det3(m[2]);
    double K = -det / (gmag * gmag * gmag * gmag);
    return sqrt(fabs(K));
}

/* Separation of the boxes along axis k (Eberly's 15-axis test): C = R1^T R2,
 * d1, d2 the centre distance in each body frame, a, b the half-widths. */
SQE_LOCAL int sqe_separated(int k, const double C[3][3], const double Ab[3][3], const double d1[3],
                            const double d2[3], const double a[3], const double b[3])
{
    double r1, r2, r;
    if (k < 3) {
        r1 = a[k];
        r2 = b[0] * Ab[k][0] + b[1] * Ab[k][1] + b[2] * Ab[k][2];
        r = fabs(d1[k]);
    } else if (k < 6) {
        int j = k - 3;
        r1 = a[0] * Ab[0][j] + a[1] * Ab[1][j] + a[2] * Ab[2][j];
        r2 = b[j];
        r = fabs(d2[j]);
    } else { /* A_i x B_j */
        int i = (k - 6) / 3, j = (k - 6) % 3;
        int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        r1 = a[i1] * Ab[i2][j] + a[i2] * Ab[i1][j];
        r2 = b[j1] * Ab[i][j2] + b[j2] * Ab[i][j1];
        r = fabs(d1[i2] * C[i1][j] - d1[i1] * C[i2][j]);
    }
    return r > r1 + r2;
}

SQE_API int sqe_obb_separating_axis(const struct sqe_body *bi, const struct sqe_body *bj, int first)
{
    double C[3][3], Ab[3][3], d[3], d1[3], d2[3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            C[i][j] = bi->R[0][i] * bj->R[0][j] + bi->R[1][i] * bj->R[1][j] +
                      bi->R[2][i] * bj->R[2][j];
            Ab[i][j] = fabs(C[i][j]);
        }
    for (int q = 0; q < 3; q++)
        d[q] = bj->xc[q] - bi->xc[q];
    sqe_matT_vec(bi->R, d, d1);
    sqe_matT_vec(bj->R, d, d2);
    if (first >= 0 && first < 15 && sqe_separated(first, C, Ab, d1, d2, bi->shape, bj->shape))
        return first;
    for (int k = 0; k < 15; k++)
        if (k != first && sqe_separated(k, C, Ab, d1, d2, bi->shape, bj->shape))
            return k;
    return -1;
}

#endif /* SQE_BODIES */
#endif
