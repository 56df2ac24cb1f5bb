/* output.h - thermo output, dumps and the progress line, driven by `run`.
 *
 * Contract with the run loop (core):
 *  - set g->firststep, g->laststep (and g->step = firststep) for the run,
 *    compute the setup forces, then call output_setup(g). It resolves compute
 *    and variable references (errors unwind from here, before any output),
 *    writes the dumps due at the first step, prints the thermo header and
 *    first line, and starts the progress line.
 *  - after each step set g->step and g->time, then call output_step(g). It
 *    writes what is due and calls run_sync_host(g) itself before reading
 *    per-atom data (possibly twice in one step: dumps, then thermo; a second
 *    call in the same step should be cheap). output_due(g, step) says in
 *    advance whether anything will be written at `step` (or the progress
 *    line is due); a loop may call output_step only when it says 1.
 *  - at the end call output_finish(g, &stats): it erases the progress line,
 *    completes appending dump files, and prints LAMMPS' footer. run_stats:
 *    the timing rows from sec[] (rank_spread; Other: t_other, or when 0
 *    the loop time minus their means), Nlocal and Neighs from atoms and
 *    neighs; total_neighbors is the number of entries in gravel's full list (each
 *    pair twice): the footer prints pairs, like LAMMPS' half list;
 *    max_overlap_frac is printed as given.
 *  - a run that stops on an error calls output_abort(g) first.
 *  - styles_free (clear, destroy) must call compute_free_all(g) and
 *    dump_free_all(g) (compute.h, dump.h).
 * g->thermo.lost holds thermo_modify lost (error|warn|ignore) for the core. */
#ifndef GR_OUTPUT_H
#define GR_OUTPUT_H

#include "state.h"

struct run_stats;           /* device.h */

void output_setup(struct gravel *g);
/* 1 if a thermo line or a dump is due at this step of the current run, or
 * the progress line wants a redraw (at most 4 times a second). */
int output_due(struct gravel *g, bigint step);
void output_step(struct gravel *g);
void output_finish(struct gravel *g, const struct run_stats *st);
/* v[0 .. n-1], one value per rank (n = 1: one process), summarised as
 * LAMMPS's Finish does (struct rank_spread, src/engine/device.h). */
struct rank_spread;
void rank_spread(const double *v, int n, struct rank_spread *s);
/* The same of v[0], v[stride], ..., v[(n - 1) stride]. */
void rank_spread_strided(const double *v, int n, int stride, struct rank_spread *s);
/* The footer's per-rank quantities: the section times (RUN_SEC_*), the loop
 * time, owned atoms and neighbor pairs, in that order (run_stats_row); from
 * n ranks' rows (n = 1: one process) run_stats_spread fills st's sec[],
 * atoms and neighs and the loop time's spread into *loop. */
enum { RUN_ROW_N = 7 };
void run_stats_row(const struct run_stats *st, double row[RUN_ROW_N]);
void run_stats_spread(struct run_stats *st, const double *rows, int n, struct rank_spread *loop);
/* `run N post no`: the same housekeeping, and only the "Loop time" line of
 * the footer (LAMMPS prints nothing more with post no). */
void output_finish_brief(struct gravel *g, const struct run_stats *st);
/* A run stopping on an error (before output_finish): erase the progress
 * line so the error message starts on a clean line, and complete appending
 * dump files with the snapshots written so far. Never raises. */
void output_abort(struct gravel *g);

#endif
