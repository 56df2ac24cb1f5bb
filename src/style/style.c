/* style.c - release of every style instance on `clear` and destroy: dumps
 * first (they publish their files), then computes, fixes and the pair. */
#include "style.h"

#include "compute.h"
#include "dump.h"
#include "fix.h"
#include "pair.h"
#include "state.h"

void styles_free(struct gravel *g)
{
    dump_free_all(g);
    compute_free_all(g);
    fix_free_all(g);
    pair_free(g);
}
