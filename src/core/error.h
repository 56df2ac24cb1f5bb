/* error.h - errors unwind to the command boundary; warnings print and continue.
 *
 * Contract: gr_error() never returns. It formats
 *     ERROR: <command>: <message> (<file>:<line>)
 * stores it in g->err.msg, and longjmps to g->err.jmp when a command boundary
 * is active (set by the dispatcher); with none it prints and exits 1. The
 * dispatcher prints the message and the offending line, then exits 1 (or, in
 * library/test mode, returns an error code). */
#ifndef GR_ERROR_H
#define GR_ERROR_H

#include "state.h"

_Noreturn void gr_error(struct gravel *g, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
void gr_warn(struct gravel *g, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Report the stored error (message and offending line) to screen and log. */
void gr_report_error(struct gravel *g);

/* Checked allocation: raise an error instead of returning NULL. */
void *gr_malloc(struct gravel *g, size_t n);
void *gr_calloc(struct gravel *g, size_t n, size_t size);
void *gr_realloc(struct gravel *g, void *p, size_t n);
char *gr_strdup(struct gravel *g, const char *s);

#endif
