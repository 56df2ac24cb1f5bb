/* output.h - thermo output, dumps and the progress line, driven by `run`.
 *
 * The run loop calls output_setup() before step 0, output_step() after each
 * step (it decides what is due and syncs the host copy when it writes), and
 * output_finish() with the run's statistics. */
#ifndef GR_OUTPUT_H
#define GR_OUTPUT_H

#include "gravel.h"
#include "run.h"

void output_setup(struct gravel *g);
/* 1 if any thermo line, dump or restart is due at this step. */
int output_due(struct gravel *g, bigint step);
void output_step(struct gravel *g);
void output_finish(struct gravel *g, const struct run_stats *st);

/* Value of a thermo keyword (step, atoms, ke, c_ID, v_name, ...) for
 * expressions; returns 0 when `name` is not a thermo keyword. */
int thermo_keyword_value(struct gravel *g, const char *name, double *out);

#endif
