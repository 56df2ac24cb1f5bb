/* region_intersect.c - region intersect N id1 ... idN: points in every
 * sub-region (each with its own side). Its bounding box is the intersection
 * of the bounded (side in) sub-regions' boxes. */
#include <math.h>

#include "error.h"
#include "region.h"
#include "region_union.h"

static int intersect_parse(struct gravel *g, struct region *r, int n, char **a,
                           const double sc[3])
{
    (void)sc;
    region_link_subs(g, r, n, a);
    r->bbox = 0;
    for (int d = 0; d < 3; d++) {
        r->bbox_lo[d] = -INFINITY;
        r->bbox_hi[d] = INFINITY;
    }
    for (int k = 0; k < r->nsub; k++) {
        const struct region *s = r->sub[k];
        if (!s->bbox || !s->interior)
            continue;
        r->bbox = 1;
        for (int d = 0; d < 3; d++) {
            r->bbox_lo[d] = fmax(r->bbox_lo[d], s->bbox_lo[d]);
            r->bbox_hi[d] = fmin(r->bbox_hi[d], s->bbox_hi[d]);
        }
    }
    return n;
}

static int intersect_inside(const struct region *r, const double x[3])
{
    for (int k = 0; k < r->nsub; k++)
        if (!region_match(r->sub[k], x))
            return 0;
    return 1;
}

const struct region_style region_style_intersect = {
    "intersect", "N id1 id2 ...", -1, intersect_parse, intersect_inside, NULL};
