/* run.c - PLACEHOLDER: the run loop lands with the OpenCL core. */
#include "run.h"

void run_sync_host(struct gravel *g)
{
    (void)g;
}

void engine_destroy(struct gravel *g)
{
    (void)g;
}
