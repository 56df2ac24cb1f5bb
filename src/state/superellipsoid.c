/* superellipsoid.c - superellipsoid volume, inertia and bounding radius
 * (superellipsoid.h). */
#include "superellipsoid.h"

#include <math.h>

double sqe_beta(double x, double y)
{
    /* the Gamma values stay finite for the exponents of any sane shape
     * (e = 2/n >= 0.01); log form beyond, where tgamma overflows */
    double gx = tgamma(x), gy = tgamma(y), gxy = tgamma(x + y);
    if (isfinite(gx) && isfinite(gy) && isfinite(gxy))
        return gx * gy / gxy;
    return exp(lgamma(x) + lgamma(y) - lgamma(x + y));
}

double sqe_volume(const double shape[3], const double block[2])
{
    double abc = shape[0] * shape[1] * shape[2];
    if (sqe_kind(block) == SQE_ELLIPSOID)
        return 4.0 * M_PI / 3.0 * abc;
    double e1 = 2.0 / block[0], e2 = 2.0 / block[1];
    return abc * e1 * e2 * sqe_beta(0.5 * e1, 1.0 + e1) * sqe_beta(0.5 * e2, 0.5 * e2);
}

void sqe_inertia(const double shape[3], double mass, const double block[2], double idiag[3])
{
    double a2 = shape[0] * shape[0], b2 = shape[1] * shape[1], c2 = shape[2] * shape[2];
    if (sqe_kind(block) == SQE_ELLIPSOID) {
        double d = 0.2 * mass;
        idiag[0] = d * (b2 + c2);
        idiag[1] = d * (a2 + c2);
        idiag[2] = d * (a2 + b2);
        return;
    }
    /* the second moments of the unit-density body over its volume factor:
     * x^2 and y^2 share B(e1/2, 1 + 2 e1) B(e2/2, 3 e2/2) / 2, z^2 has
     * B(3 e1/2, 1 + e1) B(e2/2, e2/2) */
    double e1 = 2.0 / block[0], e2 = 2.0 / block[1];
    double bxy = sqe_beta(0.5 * e1, 1.0 + 2.0 * e1) * sqe_beta(0.5 * e2, 1.5 * e2);
    double b22 = sqe_beta(0.5 * e2, 0.5 * e2);
    double dens = mass / (sqe_beta(0.5 * e1, 1.0 + e1) * b22);
    double mx = 0.5 * a2 * bxy, my = 0.5 * b2 * bxy;
    double mz = c2 * sqe_beta(1.5 * e1, 1.0 + e1) * b22;
    idiag[0] = dens * (my + mz);
    idiag[1] = dens * (mx + mz);
    idiag[2] = dens * (mx + my);
}

double sqe_bounding_radius(const double shape[3], const double block[2])
{
    if (sqe_kind(block) == SQE_ELLIPSOID)
        return fmax(shape[0], fmax(shape[1], shape[2]));
    double a = fmax(shape[0], shape[1]), b = fmin(shape[0], shape[1]), c = shape[2];
    if (block[1] < 2.0 + SQE_EPSILON_BLOCK) /* n2 = 2: round in x-y, a cylinder bounds it */
        return sqrt(a * a + c * c);
    if (block[0] < 2.0 + SQE_EPSILON_BLOCK) /* n1 = 2 */
        return fmax(c, sqrt(a * a + b * b));
    return sqrt(a * a + b * b + c * c);
}
