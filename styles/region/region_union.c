/* region_union.c - region union N id1 ... idN: points in any sub-region
 * (each with its own side). Bounded when every sub-region is bounded.
 * Sub-regions must exist already; a deleted one is replaced by the region of
 * its ID when the union is next used (region_relink, src/state/region.c). */
#include <math.h>
#include <string.h>

#include "error.h"
#include "region.h"
#include "region_union.h"

/* Resolve the N sub-region IDs of union/intersect (region.h). */
void region_link_subs(struct gravel *g, struct region *r, int n, char **a)
{
    int nsub = n - 1;
    r->sub = gr_calloc(g, (size_t)nsub, sizeof *r->sub);
    for (int k = 0; k < nsub; k++) {
        if (!strcmp(a[1 + k], r->id))
            gr_error(g, "region '%s' cannot contain itself", r->id);
        r->sub[k] = region_get(g, a[1 + k]);
    }
    r->nsub = nsub;
    for (int k = 0; k < nsub; k++)
        r->sub[k]->nref++;
}

static int union_parse(struct gravel *g, struct region *r, int n, char **a, const double sc[3])
{
    (void)sc;
    region_link_subs(g, r, n, a);
    r->bbox = 1;
    for (int d = 0; d < 3; d++) {
        r->bbox_lo[d] = INFINITY;
        r->bbox_hi[d] = -INFINITY;
    }
    for (int k = 0; k < r->nsub; k++) {
        const struct region *s = r->sub[k];
        if (!s->bbox || !s->interior) {
            r->bbox = 0;
            break;
        }
        for (int d = 0; d < 3; d++) {
            r->bbox_lo[d] = fmin(r->bbox_lo[d], s->bbox_lo[d]);
            r->bbox_hi[d] = fmax(r->bbox_hi[d], s->bbox_hi[d]);
        }
    }
    return n;
}

static int union_inside(const struct region *r, const double x[3])
{
    for (int k = 0; k < r->nsub; k++)
        if (region_match(r->sub[k], x))
            return 1;
    return 0;
}

const struct region_style region_style_union = {
    "union", "N id1 id2 ...", -1, union_parse, union_inside, NULL};
