/* thermo.h - the thermo table (LAMMPS 2021 layout), the run-time output state
 * shared by output.c, thermo.c and progress.c, and the progress line.
 *
 * The run loop drives output through output.h; this header is the thermo
 * table's own: the thermo commands, thermo keyword values for expressions
 * (expr.c), and what output.c and progress.c share. Tests call the text
 * functions directly. */
#ifndef GR_THERMO_H
#define GR_THERMO_H

#include "state.h"

/* Run-time state of the output module, one per engine (g->thermo.state). */
enum { PRE_KW = 10 };           /* pe etotal epair press pxx pyy pzz pxy pxz pyz */

struct output_state {
    int active;                 /* between output_setup and output_finish */
    double wall0;               /* monotonic seconds at output_setup */
    int firstflag;              /* the thermo line being built is the run's first */
    double last_tp_time, last_tp_cpu;   /* tpcpu: previous sample */
    double last_sp_cpu;                 /* spcpu: previous sample */
    bigint last_sp_step;
    bigint next_thermo;         /* next step with a thermo line */
    bigint last_thermo;         /* last step that printed one (-1: none this run) */
    /* per-column formats resolved by thermo_init (printf, ints as long long) */
    int ncol;
    char fmt[GR_MAXTHERMO][80];
    int kind[GR_MAXTHERMO];     /* thermo.c: keyword index, or a reference kind */
    /* progress line on stderr */
    int progress_on;
    double prog_last_wall;
    int prog_len;               /* length of the line currently shown */
    char *text;                 /* buffer behind thermo_*_text */
    /* energy drift of a conserving run (output.c): kinetic energy and time
     * at output_setup, collision time of the setup's lightest particle */
    int drift_on;
    double drift_e0, drift_t0, drift_tcol;
    size_t text_len, text_cap;
    /* several ranks: the step's pressure and energy keywords (thermo.c,
     * PRE_KW), taken before a gathered evaluation of variables, which cannot
     * compute them on the gathered atoms */
    bigint pre_step;            /* the step they are of (-1: none) */
    double pre[PRE_KW];
};

/* The state, allocated on first use; freed by thermo_settings_free. */
struct output_state *output_state(struct gravel *g);

/* Check that printf format `f` holds exactly one conversion of the wanted
 * kind (integer d/i, or float e/E/f/F/g/G), with widths and precisions of
 * at most 3 digits and no '*'; "%%" is literal. Writes the usable format to
 * `out` (>= 80 bytes; integer conversions become long long). Returns NULL
 * when valid, else what is wrong, for an error message. */
const char *output_format_fix(const char *f, int want_int, char *out);

/* Resolve the column list (default `one`), check c_ID and v_name references
 * and the formats; errors name thermo_style or thermo_modify. */
void thermo_init(struct gravel *g);
/* 1 if a thermo_style column is f_ID[N] of this fix (fixes that compute
 * their vector only when it is shown ask at run setup). */
int thermo_shows_fix_vector(const struct gravel *g, const char *id);
/* Header line ("Step Atoms KinEng ... \n"; empty in multi mode) and one
 * line of values at the current step (state->firstflag marks the run's
 * first line). The text lives in the state and stays valid until the next
 * call. Values that need per-atom data call run_sync_host() first. */
const char *thermo_header_text(struct gravel *g);
const char *thermo_line_text(struct gravel *g);

/* Value of a thermo keyword for expressions: step elapsed dt time cpu tpcpu
 * spcpu cpuremain atoms ke pe etotal vol lx ly lz xlo xhi ylo yhi zlo zhi temp epair
 * emol, c_ID, c_ID[N] (normalized like thermo output with norm yes) and
 * v_name. Returns 0 when `name` is none of these (or names no existing
 * compute/variable); raises an error when c_ID exists but has no such value. */
int thermo_keyword_value(struct gravel *g, const char *name, double *out);
/* Several ranks, before equal-style variables are evaluated on the gathered
 * atoms outside a thermo line (fix ave/time's variable inputs): the step's
 * pe, epair, etotal and pressure keywords taken on the ranks, as a thermo
 * line takes them (collective; nothing on one rank); thermo_pre_clear
 * after the evaluation. */
void thermo_pre_take(struct gravel *g);
void thermo_pre_clear(struct gravel *g);

/* Commands (commands.def): thermo, thermo_style, thermo_modify. */
void cmd_thermo(struct gravel *g, int argc, char **argv);
void cmd_thermo_style(struct gravel *g, int argc, char **argv);
void cmd_thermo_modify(struct gravel *g, int argc, char **argv);

/* Release the thermo settings' strings and the output state (`clear`,
 * destroy: gravel.c). */
void thermo_settings_free(struct thermo_settings *t);

#endif
