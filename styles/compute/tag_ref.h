/* tag_ref.h - a per-atom reference vector kept by atom ID (compute msd's
 * positions, compute vacf's velocities at the compute's start): three
 * doubles per tag and a flag for the tags that have one, grown on demand. */
#ifndef GR_TAG_REF_H
#define GR_TAG_REF_H

#include "state.h"

struct tag_ref {
    double *v;              /* [3 * cap] by tag */
    unsigned char *have;    /* [cap] by tag: 1 where v holds the reference */
    int64_t cap;
};

/* Room for tag (new entries zeroed, have 0). */
void tag_ref_reserve(struct gravel *g, struct tag_ref *r, int64_t tag);
void tag_ref_free(struct tag_ref *r);

#endif
