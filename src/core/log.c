/* log.c - output to screen and log file; opening, checking and closing the log. */
#include "log.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "fileio.h"
#include "state.h"

static void log_forget(struct gravel *g)
{
    free(g->logname);
    free(g->logerr);
    g->logname = NULL;
    g->logerr = NULL;
}

void gr_log_release(struct gravel *g)
{
    if (g->logfile)
        fclose(g->logfile);
    g->logfile = NULL;
    log_forget(g);
}

/* Close the log; 0 if it and every write to it succeeded, else the errno. */
static int log_close(struct gravel *g)
{
    int err = 0;
    if (g->logfile) {
        int bad = ferror(g->logfile) || (g->logerr && *g->logerr);
        if (fclose(g->logfile) != 0)
            bad = 1;
        if (bad)
            err = g->logerr && *g->logerr ? *g->logerr : EIO;
    }
    g->logfile = NULL;
    return err;
}

static void log_message(struct gravel *g, int err)
{
    snprintf(g->err.msg, sizeof g->err.msg, "cannot write log file '%.200s': %s",
             g->logname ? g->logname : "(log)", strerror(err));
}

int gr_log_close(struct gravel *g)
{
    int err = log_close(g);
    if (err)
        log_message(g, err);
    log_forget(g);
    return err ? -1 : 0;
}

int gr_log_open(struct gravel *g, const char *path, int append)
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
    int bad = gr_log_close(g); /* the previous log, checked */
    g->logfile = fp;
    g->logname = name;
    g->logerr = slot;
    return bad;
}

void gr_log_check(struct gravel *g)
{
    if (!g->logfile)
        return;
    int err = g->logerr ? *g->logerr : 0;
    if (!err && !ferror(g->logfile))
        return;
    char *name = g->logname ? strdup(g->logname) : NULL;
    if (gr_log_close(g) == 0) { /* cannot happen: an error was seen */
        snprintf(g->err.msg, sizeof g->err.msg, "cannot write log file '%.200s': %s",
                 name ? name : "(log)", strerror(err ? err : EIO));
    }
    free(name);
    /* g->err.msg holds the message; raise it with the command's context */
    char msg[sizeof g->err.msg];
    snprintf(msg, sizeof msg, "%s", g->err.msg);
    gr_error(g, "%s", msg);
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
