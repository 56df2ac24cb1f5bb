/* region_sphere.c - region sphere x y z radius: a ball, surface included.
 * With units lattice the center is scaled per dimension and the radius by
 * the x lattice spacing (as LAMMPS). */
#include "args.h"
#include "error.h"
#include "region.h"

static int sphere_parse(struct gravel *g, struct region *r, int n, char **a, const double sc[3])
{
    (void)n;
    for (int d = 0; d < 3; d++)
        r->p[d] = sc[d] * arg_double(g, a[d], "sphere center");
    double rad = arg_double(g, a[3], "sphere radius");
    if (rad < 0)
        gr_error(g, "sphere radius must not be negative, got %s", a[3]);
    r->p[3] = sc[0] * rad;
    r->bbox = 1;
    for (int d = 0; d < 3; d++) {
        r->bbox_lo[d] = r->p[d] - r->p[3];
        r->bbox_hi[d] = r->p[d] + r->p[3];
    }
    return 4;
}

static int sphere_inside(const struct region *r, const double x[3])
{
    double dx = x[0] - r->p[0], dy = x[1] - r->p[1], dz = x[2] - r->p[2];
    return dx * dx + dy * dy + dz * dz <= r->p[3] * r->p[3];
}

const struct region_style region_style_sphere = {
    "sphere", "x y z radius", 4, sphere_parse, sphere_inside, NULL};
