/* progress.h - the progress line on stderr (progress.c): begun at
 * output_setup, updated after each step, ended at output_finish. Its state
 * lives in the output module's struct output_state (thermo.h). */
#ifndef GR_PROGRESS_H
#define GR_PROGRESS_H

struct gravel;

/* Progress line: begin at output_setup, update after each step, end at
 * output_finish (clears it). Active with -progress or when stderr is a
 * terminal; writes only to stderr. */
void progress_begin(struct gravel *g);
void progress_update(struct gravel *g);
void progress_end(struct gravel *g);
/* 1 when the progress line should be redrawn now (callers that only call
 * output_step when output_due says so still get a live line). */
int progress_due(struct gravel *g);
/* Erase the line if shown (before other text goes to the terminal); the
 * next update redraws it. */
void progress_clear(struct gravel *g);

#endif
