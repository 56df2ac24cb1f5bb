/* tag_ref.c - per-atom reference vectors by atom ID (tag_ref.h). */
#include "tag_ref.h"

#include <stdlib.h>
#include <string.h>

#include "error.h"

void tag_ref_reserve(struct gravel *g, struct tag_ref *r, int64_t tag)
{
    if (tag < r->cap)
        return;
    int64_t cap = r->cap ? r->cap : 64;
    while (cap <= tag)
        cap *= 2;
    r->v = gr_realloc(g, r->v, (size_t)cap * 3 * sizeof *r->v);
    r->have = gr_realloc(g, r->have, (size_t)cap);
    memset(r->have + r->cap, 0, (size_t)(cap - r->cap));
    memset(r->v + 3 * r->cap, 0, (size_t)(cap - r->cap) * 3 * sizeof *r->v);
    r->cap = cap;
}

void tag_ref_free(struct tag_ref *r)
{
    free(r->v);
    free(r->have);
    r->v = NULL;
    r->have = NULL;
    r->cap = 0;
}
