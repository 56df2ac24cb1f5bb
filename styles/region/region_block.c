/* region_block.c - region block xlo xhi ylo yhi zlo zhi: an axis-aligned box,
 * faces included. Bounds may be INF (unbounded) or EDGE (the box face). */
#include <math.h>

#include "domain.h"
#include "error.h"
#include "region.h"

static int block_parse(struct gravel *g, struct region *r, int n, char **a, const double sc[3])
{
    static const char *what[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
    (void)n;
    r->bbox = 1;
    for (int d = 0; d < 3; d++) {
        double lo = region_parse_bound(g, a[2 * d], d, 0, sc[d], what[2 * d]);
        double hi = region_parse_bound(g, a[2 * d + 1], d, 1, sc[d], what[2 * d + 1]);
        if (!(lo < hi))
            gr_error(g, "region block needs %s < %s, got %s %s", what[2 * d], what[2 * d + 1],
                     a[2 * d], a[2 * d + 1]);
        r->p[2 * d] = lo;
        r->p[2 * d + 1] = hi;
        r->bbox_lo[d] = lo;
        r->bbox_hi[d] = hi;
    }
    return 6;
}

static int block_inside(const struct region *r, const double x[3])
{
    return x[0] >= r->p[0] && x[0] <= r->p[1] && x[1] >= r->p[2] && x[1] <= r->p[3] &&
           x[2] >= r->p[4] && x[2] <= r->p[5];
}

const struct region_style region_style_block = {
    "block", "xlo xhi ylo yhi zlo zhi", 6, block_parse, block_inside, NULL};
