/* style.c - PLACEHOLDER: pair/fix/compute/dump instances land with the core. */
#include "gravel.h"
#include "styles.h"

void styles_free(struct gravel *g)
{
    (void)g;
}
