/* run.h - the run loop (run.c) as other commands call it: `rerun`.
 *
 * The `run` command itself is a row of the command table (commands.def).
 * The device engine the loop drives is device.h (state, helpers) and
 * engine.h (program, upload, run_sync_host, teardown); what a finished run
 * reports is struct run_stats (device.h). */
#ifndef GR_RUN_H
#define GR_RUN_H

#include "state.h"

/* rerun (src/io/rerun.c): the first snapshot is already in the host atoms;
 * each is set up and output without integrating, load() then puts the next
 * one into the host atoms and returns its step (-1: no more). firststep and
 * laststep are the run's bounds as time-dependent styles and thermo see
 * them. */
void run_rerun(struct gravel *g, bigint (*load)(struct gravel *, void *), void *ctx,
               bigint firststep, bigint laststep);

/* This run's post_force calls, in order (the fixes fused into the scene's
 * kernels are not among them); *n their count. */
struct hook_call; /* device.h */
const struct hook_call *run_post_force_calls(struct gravel *g, int *n);

#endif
