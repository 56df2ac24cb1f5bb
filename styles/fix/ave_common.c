/* ave_common.c - schedule, running/window combination and output file of
 * the time-averaging fixes (ave_common.h). */
#include "ave_common.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "args.h"
#include "comm.h"
#include "compute.h"
#include "error.h"
#include "fix.h"
#include "outfile.h"
#include "par.h"
#include "thermo.h"
#include "variable.h"

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

int ave_keyword(struct gravel *g, struct ave_opts *o, struct ave_sched *s, struct ave_window *w,
                struct ave_file *af, int argc, char **argv, int *i, const char *who)
{
    const char *kw = argv[*i];
    if (!strcmp(kw, "file") || !strcmp(kw, "append")) {
        arg_need(g, argc, *i, 1, kw);
        o->file = argv[++*i];
        o->append = !strcmp(kw, "append");
    } else if (!strcmp(kw, "ave")) {
        ave_window_parse(g, w, argc, argv, i, who);
    } else if (!strcmp(kw, "start")) {
        arg_need(g, argc, *i, 1, kw);
        s->start = arg_bigint(g, argv[++*i], "start step");
    } else if (!strcmp(kw, "mode")) {
        arg_need(g, argc, *i, 1, kw);
        const char *m = argv[++*i];
        if (strcmp(m, "scalar") && strcmp(m, "vector"))
            gr_error(g, "%s: mode must be scalar or vector, got '%.32s'", who, m);
        o->vector_mode = !strcmp(m, "vector");
    } else if (!strcmp(kw, "overwrite")) {
        af->overwrite = 1;
    } else if (!strcmp(kw, "title1") || !strcmp(kw, "title2") || !strcmp(kw, "title3")) {
        arg_need(g, argc, *i, 1, kw);
        o->title[kw[5] - '1'] = argv[++*i];
    } else {
        return 0;
    }
    return 1;
}

void ave_global_check(struct gravel *g, char kind, const char *id, int index, int vector_mode,
                      int nevery, const char *who)
{
    static const char *const what[2][2] = {{"scalar", "vector"}, {"vector", "array"}};
    const char *need = what[vector_mode != 0][index > 0];
    int has, n;
    const char *style;
    if (kind == 'c') {
        struct compute *c = compute_find(g, id);
        if (!c)
            gr_error(g, "%s: compute ID '%s' does not exist", who, id);
        has = !vector_mode ? (index ? c->vector_flag : c->scalar_flag)
                           : (index ? c->array_flag : c->vector_flag);
        n = !vector_mode ? c->size_vector : c->size_array_cols;
        style = c->style->name;
    } else {
        struct fix *f = fix_find(g, id);
        if (!f)
            gr_error(g, "%s: fix ID '%s' does not exist", who, id);
        has = !vector_mode ? (index ? f->vector_flag : f->scalar_flag)
                           : (index ? f->array_flag : f->vector_flag);
        n = !vector_mode ? f->size_vector : f->size_array_cols;
        style = f->style->name;
        if (nevery % f->global_freq)
            gr_error(g, "%s: fix %s is not computed at compatible times (its output is "
                        "current every %d steps, Nevery is %d)", who, id, f->global_freq,
                     nevery);
    }
    const char *kname = kind == 'c' ? "compute" : "fix";
    if (!has)
        gr_error(g, "%s: %s %s (%s) does not calculate a global %s%s", who, kname, id, style,
                 need, vector_mode ? " (mode vector reads c_ID as a vector, c_ID[I] as an "
                                     "array column)" : "");
    if (index > n)
        gr_error(g, "%s: %c_%s[%d] is out of range: %s %s has %d %s", who, kind, id, index,
                 kname, id, n, vector_mode ? "columns" : "values");
}

void ave_sample(struct gravel *g, struct fix *f, struct ave_sched *s, const char *who,
                void (*take)(struct gravel *g, struct fix *f))
{
    if (!ave_sched_due(g, s, who, f->id))
        return;
    if (s->reads_vars)
        thermo_pre_take(g); /* several ranks: the keywords a gathered pass cannot take */
    par_gather_begin(g); /* several ranks: every rank's atoms, as one process */
    take(g, f);
    par_gather_end(g);
    if (s->reads_vars)
        thermo_pre_clear(g);
}

void ave_source_check(struct gravel *g, struct ave_sched *s, char kind, const char *id,
                      const char *who, const char *fid)
{
    s->reads_vars |= kind == 'v';
    const struct fix *src = kind == 'f' ? fix_find(g, id) : NULL;
    if (src && comm_size() > 1 && !par_fix_value_global(src)) { /* may be one rank's part */
        char why[160];
        snprintf(why, sizeof why, "%s %s reading f_%s (%s)", who, fid, id, src->style->name);
        par_refuse(g, why);
    }
    if (kind == 'c' && !compute_find(g, id))
        gr_error(g, "%s %s: compute ID '%s' does not exist", who, fid, id);
    if (kind == 'f' && !fix_find(g, id))
        gr_error(g, "%s %s: fix ID '%s' does not exist", who, fid, id);
    if (kind == 'v' && !var_exists(g, id))
        gr_error(g, "%s %s: variable name '%s' does not exist", who, fid, id);
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

double ave_scalar_input(struct gravel *g, char kind, const char *id, int index, const char *ref,
                        const char *who)
{
    if (kind == 'c') {
        struct compute *c = compute_get(g, id, who);
        return index ? compute_vector(g, c)[index - 1] : compute_scalar(g, c);
    }
    if (kind == 'f')
        return fix_output(g, fix_ref_check(g, ref, who), index, 0, 0, who);
    return var_compute_equal(g, id);
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
