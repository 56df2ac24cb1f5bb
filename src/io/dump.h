/* dump.h - per-atom snapshots written every N steps (`dump ID group style N
 * file args`), modified by `dump_modify` and removed by `undump`.
 *
 * Scheduling follows LAMMPS: a dump writes at every step that is a multiple
 * of N, including the first step of a run (unless that step was already
 * written), never at other steps.
 *
 * Files are never left half-written over good output:
 *  - a '*' in the file name is replaced by the step: one file per snapshot,
 *    written to "<name>.tmp" and renamed over <name> when complete;
 *  - styles that hold one snapshot per file (vtk) without '*' rewrite the
 *    file the same way at every snapshot: it always holds the latest one;
 *  - styles that append snapshots (custom) without '*' write into
 *    "<file>.tmp" during a run and rename it over <file> at the end of each
 *    run (output_finish), at undump and at exit; the next run copies <file>
 *    back to "<file>.tmp" and appends. Until a run ends the previous <file>
 *    stays intact.
 *
 * Styles register in styles/styles.def with DUMP(keyword, ident); the
 * descriptor is `const struct dump_style dump_style_<ident>` in
 * styles/dump_<ident>.c. */
#ifndef GR_DUMP_H
#define GR_DUMP_H

#include <stdio.h>

#include "outfile.h"
#include "state.h"

struct dump;

struct dump_style {
    const char *name;
    int append;                 /* 1: snapshots accumulate in one file (LAMMPS text) */
    /* Parse the style arguments after the file name; allocate d->data. */
    void (*create)(struct gravel *g, struct dump *d, int argc, char **argv);
    /* A style-specific dump_modify keyword at argv[i]: returns the number of
     * words used (keyword included), or 0 if the keyword is not the style's.
     * With apply 0 it only checks (errors as usual) and changes nothing:
     * dump_modify checks every keyword before it applies any. */
    int (*modify)(struct gravel *g, struct dump *d, int argc, char **argv, int i, int apply);
    /* Run setup: check references (may be NULL). */
    void (*init)(struct gravel *g, struct dump *d);
    /* Write one snapshot of atoms idx[0..n) (host indices) to fp. Errors go
     * through gr_error; write failures are detected by the caller. */
    void (*write)(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n);
    void (*destroy)(struct dump *d);
};

struct dump {
    char id[GR_NAMELEN];
    const struct dump_style *style;
    int igroup;
    unsigned groupbit;
    int every;                  /* N (unused while every_var is set) */
    char *every_var;            /* dump_modify every v_name: the variable giving the next
                                 * snapshot's step (LAMMPS), else NULL; next_dump is -1
                                 * until output.c evaluates it (src/io/output.c) */
    char *file;                 /* as given */
    int multifile;              /* file name holds '*' */
    int pad;                    /* dump_modify pad: zero-pad the step to this width */
    int sort;                   /* dump_modify sort id */
    int binary;                 /* dump_modify binary yes (vtk) */
    int first;                  /* dump_modify first yes: write at the first step of a run */
    bigint last_dump;           /* step of the last snapshot, -1 = none */
    bigint next_dump;
    /* append mode (one file, several snapshots) */
    struct ofile out;           /* open "<file>.tmp" (or the file written through) */
    int published;              /* <file> holds snapshots to keep (ours, or append yes) */
    int nsnap;                  /* snapshots written */
    /* scratch */
    int *idx;
    int idx_cap;
    void *data;                 /* style state */
};

/* Commands (commands.def). */
void cmd_dump(struct gravel *g, int argc, char **argv);
void cmd_dump_modify(struct gravel *g, int argc, char **argv);
void cmd_undump(struct gravel *g, int argc, char **argv);
void cmd_write_dump(struct gravel *g, int argc, char **argv);

struct dump *dump_find(struct gravel *g, const char *id);

/* Write one snapshot of dump d at the current step now (host arrays must be
 * current: output calls run_sync_host first). Used by the scheduler and by
 * tests. */
void dump_write(struct gravel *g, struct dump *d);

/* Run setup: check every dump, write those due at the first step, set the
 * schedule. */
void dump_setup_all(struct gravel *g);
/* After a step: write the dumps due at g->step. Returns 1 if any was. */
int dump_step_all(struct gravel *g);
/* 1 if some dump writes at `step`. */
int dump_due(struct gravel *g, bigint step);
/* End of a run: publish append-mode files (rename .tmp over the target). */
void dump_run_end(struct gravel *g);
/* The same without raising errors (warnings instead), for error paths. */
void dump_free_pending(struct gravel *g);
/* Free every dump, publishing append-mode files (styles_free). */
void dump_free_all(struct gravel *g);


/* Helpers for styles (format checks: output_format_fix in thermo.h).
 * Write n doubles / int32 in big-endian order (legacy VTK binary). */
void dump_write_be_doubles(FILE *fp, const double *v, size_t n);
void dump_write_be_int32(FILE *fp, const int32_t *v, size_t n);
/* A legacy VTK dump's checks, errors naming the dump style: its file name
 * ends in .vtk (the XML extensions need the VTK library: refused by name);
 * dump_modify binary yes|no at argv[i]: the words used (0: not `binary`),
 * d->binary set with apply. */
void dump_vtk_check_name(struct gravel *g, const struct dump *d);
/* A legacy VTK POLYDATA snapshot's head: version, the title line, ASCII or
 * BINARY (d->binary), the dataset and its field data TIME and CYCLE (the
 * step, capped at INT32_MAX), which ParaView shows as time. */
void dump_vtk_polydata_head(struct gravel *g, const struct dump *d, FILE *fp, const char *title);
int dump_vtk_binary(struct gravel *g, struct dump *d, int argc, char **argv, int i, int apply);

#endif
