/* wall_clock.h - seconds on the monotonic clock: the wall time between two
 * readings (run timers, thermo's cpu keyword, progress lines, the lane
 * measurement). A leaf header: anything may include it. */
#ifndef GRAVEL_WALL_CLOCK_H
#define GRAVEL_WALL_CLOCK_H

#include <time.h>

static inline double wall_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#endif
