/* lanes_tune.h - the lane width of the contact and particle kernels,
 * measured in the run.
 *
 * A program with a lane form of the pair stage (PAIR_LW > 1,
 * kernels/pair_gran_lanes.cl) or of the gather (ATOM_LW > 1,
 * kernels/atom_lanes.cl) holds the one-per-work-item kernels beside them
 * (pair_contacts_1, pair_gather_1, fused_tail_1; kernels/pair_loop.cl).
 * Both forms give the same bits, so a run may take either at any step.
 * Which is faster depends on the processor (a load gathered for four lanes
 * costs more on some than four loads do) and on the scene (how many listed
 * pairs touch), so a run of at least LANES_MIN_STEPS steps times both,
 * alternating step by step over its first 2 LANES_TRIALS steps (the queue
 * drained around each kernel), and keeps for the rest of the run, for each
 * stage, the form with the lower median time, the lane form unless the other
 * is faster by more than LANES_MARGIN. The choice is printed with the
 * run's statistics (lanes_report).
 *
 * Env GRAVEL_LANES (a width, src/engine/ocl.c) fixes the widths: no trial.
 * GRAVEL_LANES_TUNE=0: no trial (the lane forms); =always: the forms
 * alternate at every step of every run, GRAVEL_LANES or not
 * (tests/scripts/determinism.py). */
#ifndef GR_LANES_TUNE_H
#define GR_LANES_TUNE_H

#include "ocl.h"
#include "state.h"

enum { LANES_TRIALS = 16, LANES_MIN_STEPS = 400 };
#define LANES_MARGIN 0.03

enum lanes_stage { LANES_PAIR, LANES_ATOM, LANES_STAGES };

struct lanes_tune {
    int trial;                          /* this run's trial steps done; -1: none to do */
    int always;                         /* GRAVEL_LANES_TUNE=always */
    int measured;                       /* this step is a trial (lanes_step) */
    int wide[LANES_STAGES];             /* the form in use: 1 lanes, 0 one per work-item */
    double t0;                          /* the last mark of a trial step */
    float sec[LANES_STAGES][2][LANES_TRIALS]; /* trial times: [stage][wide][trial / 2] */
    char report[320];                   /* the choice and its times ("": none made) */
};

/* Run start (after the pair kernels are made): the lane forms, and the
 * trials of a run of nsteps steps that has both forms of a stage. */
void lanes_begin(struct gravel *g, bigint nsteps);
/* Before a step's pair stage (not at setup): which form each stage takes
 * at this step; on a trial step the queue is drained and the clock read. */
void lanes_step(struct gravel *g);
/* After stage s's kernel of a step: on a trial step, drain the queue and
 * keep the kernel's time; after the last trial, choose and print. */
void lanes_done(struct gravel *g, enum lanes_stage s);
/* The kernel of a stage at this step, and its items per work-item. */
cl_kernel lanes_pair_kernel(struct gravel *g, size_t *per_item);
cl_kernel lanes_gather_kernel(struct gravel *g, int tail, size_t *per_item);
/* The run's choice as a line of its statistics, or NULL when it made none. */
const char *lanes_report(const struct gravel *g);

#endif
