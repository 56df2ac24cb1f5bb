/* style.c - release of every style instance on `clear` and destroy. */
#include "gravel.h"
#include "fix.h"
#include "pair.h"
#include "styles.h"

void styles_free(struct gravel *g)
{
    pair_free(g);
    fix_free_all(g);
}
