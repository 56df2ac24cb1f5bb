/* progress.c - one updating progress line on stderr during a run: percent,
 * steps/s and ETA, redrawn in place with '\r' at most 4 times a second and
 * erased at the end of the run. Shown with -progress or when stderr is a
 * terminal; it never goes to the log or the screen stream. */
#include "progress.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "thermo.h"
#include "wall_clock.h"

#define PROGRESS_PERIOD 0.25 /* seconds between redraws */

void progress_begin(struct gravel *g)
{
    struct output_state *st = output_state(g);
    st->progress_on = g->laststep > g->firststep && (g->opt.progress || isatty(STDERR_FILENO));
    st->prog_last_wall = wall_clock();
    st->prog_len = 0;
}

static void format_eta(char *buf, size_t n, double s)
{
    if (!(s >= 0) || s > 99.0 * 86400)
        snprintf(buf, n, "--:--:--");
    else
        snprintf(buf, n, "%d:%02d:%02d", (int)(s / 3600), (int)(s / 60) % 60, (int)s % 60);
}

int progress_due(struct gravel *g)
{
    struct output_state *st = output_state(g);
    return st->progress_on && wall_clock() - st->prog_last_wall >= PROGRESS_PERIOD;
}

void progress_update(struct gravel *g)
{
    struct output_state *st = output_state(g);
    if (!st->progress_on)
        return;
    double now = wall_clock();
    if (now - st->prog_last_wall < PROGRESS_PERIOD)
        return;
    st->prog_last_wall = now;
    double done = (double)(g->step - g->firststep);
    double total = (double)(g->laststep - g->firststep);
    double elapsed = now - st->wall0;
    double rate = elapsed > 0 ? done / elapsed : 0.0;
    char eta[32], line[160];
    format_eta(eta, sizeof eta, rate > 0 ? (total - done) / rate : -1.0);
    int len = snprintf(line, sizeof line, "step %lld / %lld  %5.1f%%  %.4g steps/s  ETA %s",
                       (long long)g->step, (long long)g->laststep, 100.0 * done / total, rate,
                       eta);
    /* pad with blanks over a longer previous line */
    fprintf(stderr, "\r%s%*s", line, st->prog_len > len ? st->prog_len - len : 0, "");
    fflush(stderr);
    st->prog_len = len;
}

void progress_clear(struct gravel *g)
{
    struct output_state *st = output_state(g);
    if (st->progress_on && st->prog_len > 0) {
        fprintf(stderr, "\r%*s\r", st->prog_len, "");
        fflush(stderr);
    }
    st->prog_len = 0;
}

void progress_end(struct gravel *g)
{
    progress_clear(g);
    output_state(g)->progress_on = 0;
}
