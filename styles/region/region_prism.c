/* region_prism.c - region prism xlo xhi ylo yhi zlo zhi xy xz yz: the
 * parallelepiped with corner (xlo, ylo, zlo) and edge vectors a = (xhi -
 * xlo, 0, 0), b = (xy, yhi - ylo, 0), c = (xz, yz, zhi - zlo), faces
 * included (LAMMPS's RegPrism: a point is inside when its coordinates in
 * that basis are in [0, 1]). Lattice units scale xy and xz by the x
 * spacing, yz by the y spacing. Bounds may be INF (with zero tilts across
 * them) or EDGE. create_box with a prism makes a triclinic box. */
#include <math.h>

#include "args.h"
#include "domain.h"
#include "error.h"
#include "region.h"

static int prism_parse(struct gravel *g, struct region *r, int n, char **a, const double sc[3])
{
    static const char *what[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
    (void)n;
    for (int d = 0; d < 3; d++) {
        double lo = region_parse_bound(g, a[2 * d], d, 0, sc[d], what[2 * d]);
        double hi = region_parse_bound(g, a[2 * d + 1], d, 1, sc[d], what[2 * d + 1]);
        if (!(lo < hi))
            gr_error(g, "region prism needs %s < %s, got %s %s", what[2 * d], what[2 * d + 1],
                     a[2 * d], a[2 * d + 1]);
        r->p[2 * d] = lo;
        r->p[2 * d + 1] = hi;
    }
    double xy = sc[0] * arg_double(g, a[6], "xy");
    double xz = sc[0] * arg_double(g, a[7], "xz");
    double yz = sc[1] * arg_double(g, a[8], "yz");
    r->p[6] = xy;
    r->p[7] = xz;
    r->p[8] = yz;
    int inf[3];
    for (int d = 0; d < 3; d++)
        inf[d] = fabs(r->p[2 * d]) >= DOMAIN_BIG || fabs(r->p[2 * d + 1]) >= DOMAIN_BIG;
    if ((xy != 0.0 && inf[1]) || ((xz != 0.0 || yz != 0.0) && inf[2]))
        gr_error(g, "region prism: a non-zero tilt across an infinite dimension (xy needs y "
                    "bounded, xz and yz need z bounded)");
    /* the bounding box, as LAMMPS's extent */
    r->bbox = 1;
    double xlo = r->p[0], xhi = r->p[1], ylo = r->p[2], yhi = r->p[3];
    r->bbox_lo[0] = fmin(fmin(xlo, xlo + xy), fmin(xlo + xz, xlo + xy + xz));
    r->bbox_hi[0] = fmax(fmax(xhi, xhi + xy), fmax(xhi + xz, xhi + xy + xz));
    r->bbox_lo[1] = fmin(ylo, ylo + yz);
    r->bbox_hi[1] = fmax(yhi, yhi + yz);
    r->bbox_lo[2] = r->p[4];
    r->bbox_hi[2] = r->p[5];
    return 9;
}

static int prism_inside(const struct region *r, const double x[3])
{
    const double *p = r->p;
    double h00 = p[1] - p[0], h11 = p[3] - p[2], h22 = p[5] - p[4];
    double h01 = p[6], h02 = p[7], h12 = p[8];
    double i00 = 1.0 / h00, i01 = -h01 / (h00 * h11), i02 = (h01 * h12 - h02 * h11) / (h00 * h11 * h22);
    double i11 = 1.0 / h11, i12 = -h12 / (h11 * h22), i22 = 1.0 / h22;
    double dx = x[0] - p[0], dy = x[1] - p[2], dz = x[2] - p[4];
    double a = i00 * dx + i01 * dy + i02 * dz, b = i11 * dy + i12 * dz, c = i22 * dz;
    return a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0 && c >= 0.0 && c <= 1.0;
}

const struct region_style region_style_prism = {
    "prism", "xlo xhi ylo yhi zlo zhi xy xz yz", 9, prism_parse, prism_inside, NULL};
