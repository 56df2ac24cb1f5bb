/* region_plane.c - region plane px py pz nx ny nz: the half-space on the side
 * the normal points to, the plane itself included: (x - p) . n >= 0. The
 * point is scaled with units lattice, the normal is not (as LAMMPS). */
#include <math.h>

#include "args.h"
#include "error.h"
#include "region.h"

static int plane_parse(struct gravel *g, struct region *r, int n, char **a, const double sc[3])
{
    (void)n;
    for (int d = 0; d < 3; d++) {
        r->p[d] = sc[d] * arg_double(g, a[d], "plane point");
        r->p[3 + d] = arg_double(g, a[3 + d], "plane normal");
    }
    double len = sqrt(r->p[3] * r->p[3] + r->p[4] * r->p[4] + r->p[5] * r->p[5]);
    if (!(len > 0))
        gr_error(g, "plane normal cannot be zero");
    for (int d = 0; d < 3; d++)
        r->p[3 + d] /= len;
    r->bbox = 0;
    return 6;
}

static int plane_inside(const struct region *r, const double x[3])
{
    double dot = (x[0] - r->p[0]) * r->p[3] + (x[1] - r->p[1]) * r->p[4] +
                 (x[2] - r->p[2]) * r->p[5];
    return dot >= 0.0;
}

const struct region_style region_style_plane = {
    "plane", "px py pz nx ny nz", 6, plane_parse, plane_inside, NULL};
