/* region.c - PLACEHOLDER: regions land with the state commands. */
#include "gravel.h"
#include "styles.h"

void regions_free(struct gravel *g)
{
    (void)g;
}
