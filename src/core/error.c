/* error.c - error and warning reporting with a per-command unwind point. */
#include "error.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static void format_where(struct gravel *g, char *buf, size_t n, const char *fmt, va_list ap)
{
    char what[768];
    vsnprintf(what, sizeof what, fmt, ap);
    const struct errctx *e = &g->err;
    if (e->cmd && e->file)
        snprintf(buf, n, "%s: %s (%s:%d)", e->cmd, what, e->file, e->line);
    else if (e->cmd)
        snprintf(buf, n, "%s: %s", e->cmd, what);
    else
        snprintf(buf, n, "%s", what);
}

_Noreturn void gr_error(struct gravel *g, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    format_where(g, g->err.msg, sizeof g->err.msg, fmt, ap);
    va_end(ap);
    if (g->err.jmp)
        longjmp(*g->err.jmp, 1);
    gr_report_error(g);
    exit(1);
}

void gr_report_error(struct gravel *g)
{
    const char *text = g->err.text;
    FILE *outs[2] = {g->screen ? stderr : NULL, g->logfile};
    for (int k = 0; k < 2; k++) {
        if (!outs[k])
            continue;
        fprintf(outs[k], "ERROR: %s\n", g->err.msg);
        if (text && *text) {
            /* echo at most one screen line of the offending command */
            int len = (int)strcspn(text, "\n");
            if (len > 200)
                fprintf(outs[k], "  %.200s...\n", text);
            else
                fprintf(outs[k], "  %.*s\n", len, text);
        }
        fflush(outs[k]);
    }
}

void gr_warn(struct gravel *g, const char *fmt, ...)
{
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    format_where(g, buf, sizeof buf, fmt, ap);
    va_end(ap);
    g->err.nwarn++;
    if (g->screen)
        fprintf(stderr, "WARNING: %s\n", buf);
    if (g->logfile)
        fprintf(g->logfile, "WARNING: %s\n", buf);
}

void *gr_malloc(struct gravel *g, size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p)
        gr_error(g, "out of memory allocating %zu bytes", n);
    return p;
}

void *gr_calloc(struct gravel *g, size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size ? size : 1);
    if (!p)
        gr_error(g, "out of memory allocating %zu x %zu bytes", n, size);
    return p;
}

void *gr_realloc(struct gravel *g, void *p, size_t n)
{
    void *q = realloc(p, n ? n : 1);
    if (!q)
        gr_error(g, "out of memory allocating %zu bytes", n);
    return q;
}

char *gr_strdup(struct gravel *g, const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = gr_malloc(g, n);
    memcpy(d, s, n);
    return d;
}
