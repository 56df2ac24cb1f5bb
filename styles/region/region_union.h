/* region_union.h - what region union (styles/region/region_union.c) shares with
 * region intersect. */
#ifndef GR_REGION_UNION_H
#define GR_REGION_UNION_H

struct gravel;
struct region;

/* Resolve the sub-region IDs a[1..n-1] of union/intersect into r->sub and
 * count the references. */
void region_link_subs(struct gravel *g, struct region *r, int n, char **a);

#endif
