/* ave_common.c - schedule, running/window combination and output file of
 * the time-averaging fixes (ave_common.h). */
#include "ave_common.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

#include "args.h"
#include "error.h"
#include "outfile.h"

void ave_sched_parse(struct gravel *g, struct ave_sched *s, char **argv, const char *who)
{
    s->nevery = arg_int(g, argv[0], "Nevery");
    s->nrepeat = arg_int(g, argv[1], "Nrepeat");
    s->nfreq = arg_int(g, argv[2], "Nfreq");
    if (s->nevery <= 0 || s->nrepeat <= 0 || s->nfreq <= 0)
        gr_error(g, "%s: Nevery, Nrepeat and Nfreq must be positive (got %d %d %d)", who,
                 s->nevery, s->nrepeat, s->nfreq);
    if (s->nfreq % s->nevery || (bigint)s->nrepeat * s->nevery > s->nfreq)
        gr_error(g, "%s: Nfreq must be a multiple of Nevery and Nrepeat*Nevery <= Nfreq (got "
                    "%d %d %d)", who, s->nevery, s->nrepeat, s->nfreq);
    s->nvalid_last = -1;
}

void ave_sched_reset(const struct gravel *g, struct ave_sched *s)
{
    bigint step = g->step, nv = (step / s->nfreq) * s->nfreq + s->nfreq;
    while (nv < s->start)
        nv += s->nfreq;
    if (nv - s->nfreq == step && s->nrepeat == 1)
        nv = step;
    else
        nv -= (bigint)(s->nrepeat - 1) * s->nevery;
    if (nv < step)
        nv += s->nfreq;
    s->nvalid = nv;
    s->irepeat = 0;
}

int ave_sched_due(struct gravel *g, struct ave_sched *s, const char *who, const char *id)
{
    if (g->step < s->nvalid_last || g->step > s->nvalid)
        gr_error(g, "%s %s: invalid timestep reset (step %lld, next sample %lld)", who, id,
                 (long long)g->step, (long long)s->nvalid);
    if (g->step != s->nvalid)
        return 0;
    s->nvalid_last = s->nvalid;
    return 1;
}

int ave_sched_next(const struct gravel *g, struct ave_sched *s)
{
    if (++s->irepeat < s->nrepeat) {
        s->nvalid += s->nevery;
        return 0;
    }
    s->irepeat = 0;
    s->nvalid = g->step + s->nfreq - (bigint)(s->nrepeat - 1) * s->nevery;
    return 1;
}

void ave_window_parse(struct gravel *g, struct ave_window *w, int argc, char **argv, int *i,
                      const char *who)
{
    arg_need(g, argc, *i, 1, "ave");
    const char *v = argv[++*i];
    if (!strcmp(v, "one")) {
        w->kind = AVE_ONE;
    } else if (!strcmp(v, "running")) {
        w->kind = AVE_RUNNING;
    } else if (!strcmp(v, "window")) {
        w->kind = AVE_WINDOW;
        arg_need(g, argc, *i, 1, "ave window");
        w->nwindow = arg_int(g, argv[++*i], "window length M");
        if (w->nwindow < 1 || w->nwindow > 1 << 20)
            gr_error(g, "%s: ave window length M must be between 1 and %d, got %d", who, 1 << 20,
                     w->nwindow);
    } else {
        gr_error(g, "%s: ave must be one, running or window M, got '%.32s'", who, v);
    }
}

void ave_window_add(const struct ave_window *w, double *total, double *list, const double *one,
                    size_t n)
{
    if (w->kind == AVE_ONE) {
        memcpy(total, one, n * sizeof *total);
    } else if (w->kind == AVE_RUNNING) {
        for (size_t k = 0; k < n; k++)
            total[k] += one[k];
    } else {
        double *slot = list + (size_t)w->iwindow * n;
        for (size_t k = 0; k < n; k++) {
            total[k] += one[k];
            if (w->full)
                total[k] -= slot[k];
            slot[k] = one[k];
        }
    }
}

void ave_window_advance(struct ave_window *w)
{
    if (w->kind == AVE_ONE) {
        w->norm = 1;
    } else if (w->kind == AVE_RUNNING) {
        w->norm++;
    } else {
        if (++w->iwindow == w->nwindow) {
            w->iwindow = 0;
            w->full = 1;
        }
        w->norm = w->full ? w->nwindow : w->iwindow;
    }
}

void ave_file_open(struct gravel *g, struct ave_file *af, const char *path, int append,
                   const char *who)
{
    af->fd = of_open_fd(path, append);
    af->fp = af->fd < 0 ? NULL : of_stream(af->fd, &af->err);
    if (!af->fp)
        gr_error(g, "%s: cannot open file %.200s: %s", who, path, strerror(errno));
}

void ave_file_header_done(struct gravel *g, struct ave_file *af, const char *who)
{
    if (fflush(af->fp) != 0 || ferror(af->fp))
        gr_error(g, "%s: writing the file header failed: %s", who,
                 strerror(af->err ? af->err : EIO));
    af->filepos = ftell(af->fp);
}

void ave_file_begin(struct ave_file *af)
{
    if (af->overwrite)
        fseek(af->fp, af->filepos, SEEK_SET);
}

void ave_file_end(struct gravel *g, struct ave_file *af, const char *who, const char *id)
{
    fflush(af->fp);
    if (af->overwrite) {
        long end = ftell(af->fp);
        if (end >= 0 && ftruncate(af->fd, end) != 0)
            gr_warn(g, "%s %s: could not truncate its file", who, id);
    }
    if (ferror(af->fp))
        gr_error(g, "%s %s: writing its file failed: %s", who, id,
                 strerror(af->err ? af->err : EIO));
}

void ave_file_close(struct ave_file *af)
{
    if (af->fp)
        fclose(af->fp);
    af->fp = NULL;
}
