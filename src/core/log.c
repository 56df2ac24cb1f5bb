/* log.c - output to screen and log file; opening, checking and closing the
 * log and the thermo log (LIGGGHTS's thermo_log), both "sinks": a stream,
 * its name and the errno of its first failed write. */
#include "log.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "fileio.h"
#include "state.h"

/* A sink's parts inside struct gravel, and what it is called in messages. */
struct sink {
    FILE **fp;
    char **name;
    int **err;
    const char *what;
};

static struct sink log_sink(struct gravel *g)
{
    return (struct sink){&g->logfile, &g->logname, &g->logerr, "log file"};
}

static struct sink thermo_sink(struct gravel *g)
{
    return (struct sink){&g->thermolog, &g->thermologname, &g->thermologerr, "thermo log file"};
}

static void sink_forget(struct sink s)
{
    free(*s.name);
    free(*s.err);
    *s.name = NULL;
    *s.err = NULL;
}

static void sink_release(struct sink s)
{
    if (*s.fp)
        fclose(*s.fp);
    *s.fp = NULL;
    sink_forget(s);
}

/* Close; 0 if it and every write to it succeeded, else the errno. */
static int sink_close_stream(struct sink s)
{
    int err = 0;
    if (*s.fp) {
        int bad = ferror(*s.fp) || (*s.err && **s.err);
        if (fclose(*s.fp) != 0)
            bad = 1;
        if (bad)
            err = *s.err && **s.err ? **s.err : EIO;
    }
    *s.fp = NULL;
    return err;
}

static void sink_message(struct gravel *g, struct sink s, int err)
{
    snprintf(g->err.msg, sizeof g->err.msg, "cannot write %s '%.200s': %s", s.what,
             *s.name ? *s.name : "(log)", strerror(err));
}

static int sink_close(struct gravel *g, struct sink s)
{
    int err = sink_close_stream(s);
    if (err)
        sink_message(g, s, err);
    sink_forget(s);
    return err ? -1 : 0;
}

static int sink_open(struct gravel *g, struct sink s, const char *path, int append)
{
    const char *why;
    char *name = strdup(path);
    int *slot = malloc(sizeof *slot);
    if (!name || !slot) {
        free(name);
        free(slot);
        return ENOMEM;
    }
    FILE *fp = fio_open_write_checked(path, append, slot, &why);
    if (!fp) {
        int err = errno ? errno : EIO;
        free(name);
        free(slot);
        return err;
    }
    int bad = sink_close(g, s); /* the previous one, checked */
    *s.fp = fp;
    *s.name = name;
    *s.err = slot;
    return bad;
}

static void sink_check(struct gravel *g, struct sink s)
{
    if (!*s.fp)
        return;
    int err = *s.err ? **s.err : 0;
    if (!err && !ferror(*s.fp))
        return;
    char *name = *s.name ? strdup(*s.name) : NULL;
    if (sink_close(g, s) == 0) /* cannot happen: an error was seen */
        snprintf(g->err.msg, sizeof g->err.msg, "cannot write %s '%.200s': %s", s.what,
                 name ? name : "(log)", strerror(err ? err : EIO));
    free(name);
    /* g->err.msg holds the message; raise it with the command's context */
    char msg[sizeof g->err.msg];
    snprintf(msg, sizeof msg, "%s", g->err.msg);
    gr_error(g, "%s", msg);
}

void gr_log_release(struct gravel *g)
{
    sink_release(log_sink(g));
    sink_release(thermo_sink(g));
}

int gr_log_close(struct gravel *g)
{
    return sink_close(g, log_sink(g));
}

int gr_log_open(struct gravel *g, const char *path, int append)
{
    return sink_open(g, log_sink(g), path, append);
}

void gr_log_check(struct gravel *g)
{
    sink_check(g, log_sink(g));
    sink_check(g, thermo_sink(g));
}

int gr_thermolog_open(struct gravel *g, const char *path, int append)
{
    return sink_open(g, thermo_sink(g), path, append);
}

int gr_thermolog_close(struct gravel *g)
{
    return sink_close(g, thermo_sink(g));
}

void gr_thermolog_write(struct gravel *g, const char *text)
{
    if (!g->thermolog)
        return;
    fputs(text, g->thermolog);
    if (g->thermo.flush)
        fflush(g->thermolog);
}

void gr_print(struct gravel *g, const char *fmt, ...)
{
    va_list ap;
    if (g->screen) {
        va_start(ap, fmt);
        vfprintf(g->screen, fmt, ap);
        va_end(ap);
    }
    if (g->logfile) {
        va_start(ap, fmt);
        vfprintf(g->logfile, fmt, ap);
        va_end(ap);
    }
}
