/* region_cylinder.c - region cylinder dim c1 c2 radius lo hi: a right circular
 * cylinder along axis dim (x, y or z) through (c1, c2) in the other two
 * coordinates (in order: y z for x, x z for y, x y for z), from lo to hi along
 * the axis, surface included. lo/hi may be INF or EDGE. With units lattice,
 * c1, c2 and lo/hi are scaled by their dimensions' spacings and the radius by
 * the spacing of c1's dimension (as LAMMPS). */
#include <string.h>

#include "args.h"
#include "error.h"
#include "region.h"
#include "region_cylinder.h"

/* the two transverse dimensions of axis d, in LAMMPS order */
static const int trans[3][2] = {{1, 2}, {0, 2}, {0, 1}};

/* Parse the axis letter; shared with region cone (region.h). */
int region_parse_axis(struct gravel *g, const char *s)
{
    if (!strcmp(s, "x"))
        return 0;
    if (!strcmp(s, "y"))
        return 1;
    if (!strcmp(s, "z"))
        return 2;
    gr_error(g, "axis must be x, y or z, got '%.32s'", s);
}

static int cyl_parse(struct gravel *g, struct region *r, int n, char **a, const double sc[3])
{
    (void)n;
    int d = r->dim = region_parse_axis(g, a[0]);
    int t1 = trans[d][0], t2 = trans[d][1];
    r->p[0] = sc[t1] * arg_double(g, a[1], "c1");
    r->p[1] = sc[t2] * arg_double(g, a[2], "c2");
    double rad = arg_double(g, a[3], "cylinder radius");
    if (!(rad > 0))
        gr_error(g, "cylinder radius must be positive, got %s", a[3]);
    r->p[2] = sc[t1] * rad;
    r->p[3] = region_parse_bound(g, a[4], d, 0, sc[d], "lo");
    r->p[4] = region_parse_bound(g, a[5], d, 1, sc[d], "hi");
    if (!(r->p[3] < r->p[4]))
        gr_error(g, "cylinder needs lo < hi, got %s %s", a[4], a[5]);
    r->bbox = 1;
    r->bbox_lo[t1] = r->p[0] - r->p[2];
    r->bbox_hi[t1] = r->p[0] + r->p[2];
    r->bbox_lo[t2] = r->p[1] - r->p[2];
    r->bbox_hi[t2] = r->p[1] + r->p[2];
    r->bbox_lo[d] = r->p[3];
    r->bbox_hi[d] = r->p[4];
    return 6;
}

static int cyl_inside(const struct region *r, const double x[3])
{
    int d = r->dim;
    double a = x[trans[d][0]] - r->p[0], b = x[trans[d][1]] - r->p[1];
    return a * a + b * b <= r->p[2] * r->p[2] && x[d] >= r->p[3] && x[d] <= r->p[4];
}

const struct region_style region_style_cylinder = {
    "cylinder", "dim c1 c2 radius lo hi", 6, cyl_parse, cyl_inside, NULL};
