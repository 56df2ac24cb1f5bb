/* region_cone.c - region cone dim c1 c2 radlo radhi lo hi: a truncated cone
 * along axis dim whose radius varies linearly from radlo at lo to radhi at
 * hi, surface included. Scaling as region cylinder; lo/hi may be INF or EDGE
 * only when the radii are equal (otherwise the cone would be infinite). */
#include <math.h>

#include "args.h"
#include "error.h"
#include "region.h"
#include "region_cylinder.h"

static const int trans[3][2] = {{1, 2}, {0, 2}, {0, 1}};

static int cone_parse(struct gravel *g, struct region *r, int n, char **a, const double sc[3])
{
    (void)n;
    int d = r->dim = region_parse_axis(g, a[0]);
    int t1 = trans[d][0], t2 = trans[d][1];
    r->p[0] = sc[t1] * arg_double(g, a[1], "c1");
    r->p[1] = sc[t2] * arg_double(g, a[2], "c2");
    double rlo = arg_double(g, a[3], "radlo"), rhi = arg_double(g, a[4], "radhi");
    if (rlo < 0 || rhi < 0)
        gr_error(g, "cone radii must not be negative, got %s %s", a[3], a[4]);
    if (rlo == 0 && rhi == 0)
        gr_error(g, "cone radii cannot both be zero");
    r->p[2] = sc[t1] * rlo;
    r->p[3] = sc[t1] * rhi;
    r->p[4] = region_parse_bound(g, a[5], d, 0, sc[d], "lo");
    r->p[5] = region_parse_bound(g, a[6], d, 1, sc[d], "hi");
    if (!(r->p[4] < r->p[5]))
        gr_error(g, "cone needs lo < hi, got %s %s", a[5], a[6]);
    if (fabs(r->p[4]) >= 1e19 || fabs(r->p[5]) >= 1e19)
        gr_error(g, "cone lo and hi must be finite");
    double rmax = fmax(r->p[2], r->p[3]);
    r->bbox = 1;
    r->bbox_lo[t1] = r->p[0] - rmax;
    r->bbox_hi[t1] = r->p[0] + rmax;
    r->bbox_lo[t2] = r->p[1] - rmax;
    r->bbox_hi[t2] = r->p[1] + rmax;
    r->bbox_lo[d] = r->p[4];
    r->bbox_hi[d] = r->p[5];
    return 7;
}

static int cone_inside(const struct region *r, const double x[3])
{
    int d = r->dim;
    if (!(x[d] >= r->p[4] && x[d] <= r->p[5]))
        return 0;
    double a = x[trans[d][0]] - r->p[0], b = x[trans[d][1]] - r->p[1];
    double rad = r->p[2] + (x[d] - r->p[4]) * (r->p[3] - r->p[2]) / (r->p[5] - r->p[4]);
    return sqrt(a * a + b * b) <= rad;
}

const struct region_style region_style_cone = {
    "cone", "dim c1 c2 radlo radhi lo hi", 7, cone_parse, cone_inside, NULL};
