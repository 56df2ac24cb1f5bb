/* input.h - the script interpreter: lines, continuation, comments, quotes,
 * variable substitution, and dispatch through the command table.
 *
 * Contract: each command runs inside a setjmp boundary. On error the message
 * (g->err.msg) and offending line are reported to screen and log and the
 * reader stops: the functions return GR_ERR. `quit` returns GR_QUIT.
 *
 * Sources form a stack (include pushes a file, jump replaces or rewinds the
 * current one); inp_file/inp_stream/inp_string run until the source they
 * pushed is exhausted, so they may be called again from inside a command. */
#ifndef GR_INPUT_H
#define GR_INPUT_H

#include <stdio.h>

#include "state.h"

enum { GR_OK = 0, GR_ERR = 1, GR_QUIT = 2 };

struct inp *inp_create(void);
void inp_destroy(struct inp *in);

/* Read and execute a whole script. */
int inp_file(struct gravel *g, const char *path);
int inp_stream(struct gravel *g, FILE *fp, const char *name);
/* Execute script text held in memory (tests); `name` is used in messages. */
int inp_string(struct gravel *g, const char *text, const char *name);

/* ---- used by the flow commands (cmd_flow.c) ---- */

/* Push script file `path` on the source stack (include). */
void inp_include(struct gravel *g, const char *path);
/* Execute one command line now (LAMMPS Input::one), within the script being
 * read: substitution, echo and dispatch as for a script line; jump, label
 * searches, next and quit act on the enclosing script. Errors unwind to the
 * caller's boundary. Used by `if` and `run ... every`. Returns GR_OK or
 * GR_QUIT. */
int inp_one(struct gravel *g, const char *text);
/* inp_one for each of n command lines, copied first (they may point into
 * the reader's buffers, which running a command reuses); stops after quit. */
int inp_run_commands(struct gravel *g, int n, char **cmds);
/* jump: `file` = "SELF" rewinds the current source, else it replaces the
 * current source; with `label` non-NULL, commands are skipped until
 * `label <label>`. Honours the skip flag set by an exhausted `next`. */
void inp_jump(struct gravel *g, const char *file, const char *label);
/* `next` found an exhausted variable: the next jump is skipped. */
void inp_skip_next_jump(struct gravel *g);
/* `quit`: stop reading after this command with exit status `status`. */
void inp_quit(struct gravel *g, int status);
/* Exit status given to `quit` (0 when none). */
int inp_quit_status(const struct gravel *g);
/* Substitute $x ${name} $(expr[:fmt]) everywhere in `text` (quotes are not
 * special here; `print` uses this). The result stays valid until the next
 * call. */
const char *inp_substitute(struct gravel *g, const char *text);
/* The same with quoted text copied unchanged (rule 6, LAMMPS's
 * Input::substitute): a string variable's definition. */
const char *inp_substitute_quoted(struct gravel *g, const char *text);

/* ---- limits for the fuzz harness (0 = unlimited, the default) ---- */

/* Refuse commands for which allow(argc, argv) returns 0 (argv[0] is the
 * command name; error "not allowed here"), stop after max_commands commands,
 * and refuse command lines longer than max_line bytes. */
void inp_set_limits(struct gravel *g, int (*allow)(int argc, char **argv), long max_commands,
                    size_t max_line);

#endif
