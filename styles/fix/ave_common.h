/* ave_common.h - what the time-averaging fixes (ave/time, ave/chunk,
 * ave/histo) share,
 * as LAMMPS's FixAve* classes do:
 *  - the schedule: samples on steps nvalid, nvalid + Nevery, ... (Nrepeat of
 *    them) ending on a multiple of Nfreq (LAMMPS nextvalid());
 *  - the combination of each Nfreq result with earlier ones (ave one,
 *    running, window M);
 *  - the output file: opened in place through of_open_fd (symlinks
 *    followed, FIFOs and devices written through), `overwrite` rewinding
 *    to the end of the header for each record, every write checked. */
#ifndef GR_AVE_COMMON_H
#define GR_AVE_COMMON_H

#include <stdio.h>

#include "state.h"

struct ave_sched {
    int nevery, nrepeat, nfreq;
    bigint start;               /* ave/time's `start`: no epoch ends before it */
    bigint nvalid;              /* next sampling step */
    bigint nvalid_last;         /* last sampling step (-1: none yet) */
    int irepeat;                /* samples taken in this epoch */
    int reads_vars;             /* a variable input (several ranks: pre-gather keywords) */
};

/* Parse "Nevery Nrepeat Nfreq" (argv[0..2]) with LAMMPS's rules: all
 * positive, Nfreq a multiple of Nevery, Nrepeat * Nevery <= Nfreq. */
void ave_sched_parse(struct gravel *g, struct ave_sched *s, char **argv, const char *who);
/* The first sampling step at or after the current one (LAMMPS nextvalid()):
 * sets s->nvalid, s->irepeat = 0. */
void ave_sched_reset(const struct gravel *g, struct ave_sched *s);
/* At end_of_step (and setup): 1 when this step samples. A step before the
 * last sample or past the next one (the step counter moved) is an error
 * naming the fix. */
int ave_sched_due(struct gravel *g, struct ave_sched *s, const char *who, const char *id);
/* At end_of_step (and setup): when this step samples (ave_sched_due), take
 * it: take(g, f) on the host atoms, every rank's gathered in tag order on
 * several MPI ranks (par.h). */
void ave_sample(struct gravel *g, struct fix *f, struct ave_sched *s, const char *who,
                void (*take)(struct gravel *g, struct fix *f));
/* After a sample: 1 when it closed the epoch (the Nfreq step). */
int ave_sched_next(const struct gravel *g, struct ave_sched *s);

enum ave_kind { AVE_ONE, AVE_RUNNING, AVE_WINDOW };
struct ave_window {
    enum ave_kind kind;
    int nwindow;                /* M of ave window M */
    int iwindow, full;
    int norm;                   /* results the totals hold */
};

/* Parse "ave one|running|window M" at argv[*i] (the keyword), advancing *i. */
void ave_window_parse(struct gravel *g, struct ave_window *w, int argc, char **argv, int *i,
                      const char *who);
/* Fold this epoch's n results `one` into `total`; `list` holds the window's
 * last nwindow results ([nwindow][n], kind window only). Call for every
 * array of the epoch, then ave_window_advance once. */
void ave_window_add(const struct ave_window *w, double *total, double *list, const double *one,
                    size_t n);
void ave_window_advance(struct ave_window *w);

/* The keywords fix ave/time and ave/histo share, as parsed. */
struct ave_opts {
    const char *file;           /* file or append F */
    int append;
    const char *title[3];       /* title1/2/3 */
    int vector_mode;            /* mode vector */
};

/* If argv[*i] is one of the shared keywords (file, append, ave, start, mode,
 * overwrite, title1, title2, title3), parse it and its values into o, w,
 * s->start and af->overwrite, advance *i to its last word and return 1;
 * else return 0. */
struct ave_file;
int ave_keyword(struct gravel *g, struct ave_opts *o, struct ave_sched *s, struct ave_window *w,
                struct ave_file *af, int argc, char **argv, int *i, const char *who);
/* LAMMPS's checks of a global input c_ID / c_ID[I] (kind 'c') or f_ID /
 * f_ID[I] ('f'): scalar mode reads the scalar (index 0) or vector element I,
 * vector mode the vector (index 0) or column I of the array; a fix's output
 * must be current on every Nevery-th step. */
void ave_global_check(struct gravel *g, char kind, const char *id, int index, int vector_mode,
                      int nevery, const char *who);
/* At run setup: the compute ('c'), fix ('f') or variable ('v') `id` that
 * fix `fid` reads still exists, else an error. Several ranks: a variable
 * is evaluated on every rank's atoms gathered (s->reads_vars), a fix's
 * value must be the same on every rank (par_fix_value_global), else the
 * run is refused. */
void ave_source_check(struct gravel *g, struct ave_sched *s, char kind, const char *id,
                      const char *who,
                      const char *fid);

/* The current value of a global input: compute `id`'s scalar (index 0) or
 * vector element `index` (kind 'c'), fix `ref`'s likewise ('f'; ref the
 * input as written, f_ID or f_ID[I]), equal-style variable `id` ('v'). */
double ave_scalar_input(struct gravel *g, char kind, const char *id, int index, const char *ref,
                        const char *who);

struct ave_file {
    FILE *fp;
    int fd, err;
    long filepos;               /* end of the header (overwrite rewinds here) */
    int overwrite;
};

/* Open `path` (truncated, or appended to) or raise "who: cannot open". */
void ave_file_open(struct gravel *g, struct ave_file *af, const char *path, int append,
                   const char *who);
/* After the header lines: check them, remember where records start. */
void ave_file_header_done(struct gravel *g, struct ave_file *af, const char *who);
/* Before a record: rewind when overwrite. */
void ave_file_begin(struct ave_file *af);
/* After a record: flush, cut what an earlier longer record left
 * (overwrite), and raise the first write error naming the fix. */
void ave_file_end(struct gravel *g, struct ave_file *af, const char *who, const char *id);
void ave_file_close(struct ave_file *af);

#endif
