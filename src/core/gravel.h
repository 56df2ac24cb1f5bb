/* gravel.h - a simulation's lifecycle: create, `clear`, destroy; the top of
 * the include order (gravel.c releases what every module owns).
 *
 * The types live in state.h, printing and the log file in log.h; both are
 * included here, so a library caller or a test that includes gravel.h has
 * the whole public surface of a simulation handle. Modules inside gravel
 * include state.h (and log.h), never this header. */
#ifndef GRAVEL_H
#define GRAVEL_H

#include "log.h"
#include "state.h"

/* Lifecycle (gravel.c). */
struct gravel *gr_create(void);
void gr_destroy(struct gravel *g);
/* `clear`: back to the state of a fresh engine, keeping options and outputs. */
void gr_clear(struct gravel *g);
/* Unit-dependent defaults (timestep, skin, thermo norm) for g->dom.units. */
void gr_unit_defaults(struct gravel *g);

#endif
