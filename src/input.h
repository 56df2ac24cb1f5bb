/* input.h - the script interpreter: lines, continuation, comments, quotes,
 * variable substitution, and dispatch through the command table.
 *
 * Contract: each command runs inside a setjmp boundary. On error the message
 * (g->err.msg) and offending line are reported to screen and log and the
 * reader stops: the functions return GR_ERR. `quit` returns GR_QUIT. */
#ifndef GR_INPUT_H
#define GR_INPUT_H

#include <stdio.h>

#include "gravel.h"

enum { GR_OK = 0, GR_ERR = 1, GR_QUIT = 2 };

struct inp *inp_create(void);
void inp_destroy(struct inp *in);

/* Read and execute a whole script. */
int inp_file(struct gravel *g, const char *path);
int inp_stream(struct gravel *g, FILE *fp, const char *name);
/* Execute script text held in memory (tests); `name` is used in messages. */
int inp_string(struct gravel *g, const char *text, const char *name);

#endif
