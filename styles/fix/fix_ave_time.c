/* fix_ave_time.c - `fix ID group ave/time Nevery Nrepeat Nfreq value ...
 * keyword args ...`: time averages of global values, LAMMPS's
 * fix_ave_time.cpp semantics, text file and output.
 *
 * Values: c_ID (a compute's global scalar), c_ID[I] (element I of its
 * vector), f_ID, f_ID[I] (the same of a fix), v_name (an equal-style
 * variable); c_ID[*], c_ID[N*M] ... expand to one value per element
 * (ref.h). `mode vector` reads whole columns instead: c_ID and
 * f_ID a global vector, c_ID[I] and f_ID[I] column I of a global array
 * (all columns of one length; a compute's array, as com/chunk's, may change
 * its row count between Nfreq epochs under ave one). c_thermo_temp without
 * a compute of that ID is the thermo temperature, as in thermo_style.
 * Keywords: mode scalar|vector, ave one|running|window M, start S,
 * off N (column N holds its last value, not averaged), file F, append F,
 * overwrite (ave running), format F (used as given, as LAMMPS 2021),
 * title1/2/3.
 *
 * Samples on steps nvalid, nvalid + Nevery, ... (ave_common.h), at
 * end_of_step and at a run's setup when due; each value is read on the host
 * (arrays synchronized first). Output, read by thermo (f_ID, f_ID[I],
 * f_ID[I][J]), variables and other fixes, current every Nfreq steps
 * (global_freq): scalar mode, one value a global scalar, several a global
 * vector; vector mode, one value a global vector of nrows, several a global
 * array nrows x values. Extensive when what it averages is (variables are
 * intensive), as LAMMPS decides; 0 before the first Nfreq step. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "ave_common.h"
#include "compute.h"
#include "engine.h"
#include "error.h"
#include "expr.h"
#include "fix.h"
#include "ref.h"
#include "thermo.h"
#include "variable.h"

enum { W_COMPUTE, W_FIX, W_VARIABLE, W_THERMO_TEMP };
enum { MODE_SCALAR, MODE_VECTOR };

#define WHO "fix ave/time"

struct value {
    int which;
    char id[GR_NAMELEN];
    int argindex;               /* I of [I], 0 without */
    int varlen;                 /* a compute's array: rows known at evaluation */
    int offcol;                 /* `off`: the last value, not averaged */
    char name[GR_NAMELEN + 16]; /* as the header prints it */
};

struct ave_time {
    struct ave_sched s;
    struct ave_window w;
    struct ave_file af;
    int mode;
    int nvalues;
    struct value *v;
    int nrows;                  /* 1 in scalar mode */
    int any_varlen, all_varlen;
    char *format;
    double *one, *total, *list; /* [nrows][nvalues]; list [nwindow][nrows][nvalues] */
    int *extlist;
};

static void at_destroy(struct fix *f)
{
    struct ave_time *a = f->data;
    if (a) {
        ave_file_close(&a->af);
        free(a->v);
        free(a->format);
        free(a->one);
        free(a->total);
        free(a->list);
        free(a->extlist);
    }
    free(a);
    f->data = NULL;
}

static int is_value(const char *s)
{
    return (s[0] == 'c' || s[0] == 'f' || s[0] == 'v') && s[1] == '_';
}

static void add_value(struct gravel *g, struct ave_time *a, const char *ref, int *cap)
{
    if (a->nvalues == *cap) {
        *cap = *cap ? 2 * *cap : 8;
        a->v = gr_realloc(g, a->v, (size_t)*cap * sizeof *a->v);
    }
    struct value *v = &a->v[a->nvalues++];
    memset(v, 0, sizeof *v);
    if (strlen(ref) >= sizeof v->name)
        gr_error(g, WHO ": value '%.64s' is too long", ref);
    snprintf(v->name, sizeof v->name, "%s", ref);
    int col;
    if (!ref_parse(ref, ref[0], v->id, &v->argindex, &col) || col)
        gr_error(g, WHO ": invalid value '%.64s' (c_ID, c_ID[I], f_ID, f_ID[I], v_name, or a "
                    "wildcard c_ID[*], c_ID[N*M])", ref);
    v->which = ref[0] == 'c' ? W_COMPUTE : ref[0] == 'f' ? W_FIX : W_VARIABLE;
}

/* LAMMPS's checks of each value against what it names; sets varlen. */
static void check_value(struct gravel *g, struct ave_time *a, struct value *v)
{
    const int vec = a->mode == MODE_VECTOR, i = v->argindex;
    if (v->which == W_COMPUTE || v->which == W_THERMO_TEMP) {
        if (!vec && !i && !strcmp(v->id, "thermo_temp") && !compute_find(g, "thermo_temp")) {
            v->which = W_THERMO_TEMP; /* thermo's implicit temperature, as thermo_style */
            return;
        }
        ave_global_check(g, 'c', v->id, i, vec, a->s.nevery, WHO);
        v->varlen = vec && (i || compute_get(g, v->id, WHO)->size_vector_variable);
    } else if (v->which == W_FIX) {
        ave_global_check(g, 'f', v->id, i, vec, a->s.nevery, WHO);
    } else {
        if (!var_exists(g, v->id))
            gr_error(g, WHO ": variable name '%s' for %s does not exist", v->id, v->name);
        if (i)
            gr_error(g, WHO ": %s: variable %s is not vector-style (gravel has no vector-style "
                        "variables)", v->name, v->id);
        if (vec)
            gr_error(g, WHO ": mode vector needs vector-style variables; %s is not one (gravel "
                        "has none)", v->name);
        if (!var_is_equal(g, v->id))
            gr_error(g, WHO ": variable %s is not an equal-style variable", v->id);
    }
}

/* Rows of value v's column now (vector mode); evaluates a compute's array. */
static int column_length(struct gravel *g, const struct value *v)
{
    if (v->which == W_COMPUTE) {
        struct compute *c = compute_get(g, v->id, WHO);
        if (v->argindex == 0) {
            if (c->size_vector_variable)
                compute_vector(g, c);
            return c->size_vector;
        }
        compute_array(g, c);
        return c->size_array_rows;
    }
    struct fix *f = fix_find(g, v->id);
    return v->argindex == 0 ? f->size_vector : f->size_array_rows;
}

static void allocate(struct gravel *g, struct fix *f, struct ave_time *a)
{
    size_t n = (size_t)a->nrows * a->nvalues;
    free(a->one);
    free(a->total);
    free(a->list);
    a->one = gr_calloc(g, n ? n : 1, sizeof(double));
    a->total = gr_calloc(g, n ? n : 1, sizeof(double));
    a->list = a->w.kind == AVE_WINDOW ? gr_calloc(g, (size_t)a->w.nwindow * (n ? n : 1),
                                                  sizeof(double))
                                      : NULL;
    a->w.iwindow = a->w.full = a->w.norm = 0;
    if (a->mode == MODE_VECTOR) {
        if (a->nvalues == 1)
            f->size_vector = a->nrows;
        else
            f->size_array_rows = a->nrows;
    }
}

/* The rows every column has this epoch (vector mode): all static columns
 * agree at create; the variable ones must agree with them, or among
 * themselves when all are variable (then the arrays are resized). */
static void epoch_rows(struct gravel *g, struct fix *f, struct ave_time *a)
{
    int len = 0;
    for (int j = 0; j < a->nvalues; j++) {
        const struct value *v = &a->v[j];
        if (!v->varlen)
            continue;
        int l = column_length(g, v);
        if (a->all_varlen && len == 0)
            len = l;
        else if (l != (a->all_varlen ? len : a->nrows))
            gr_error(g, WHO " %s: columns are inconsistent lengths (%s has %d rows, %d "
                        "expected)", f->id, v->name, l, a->all_varlen ? len : a->nrows);
    }
    if (!a->all_varlen || len == a->nrows)
        return;
    if (a->w.kind != AVE_ONE && a->w.norm > 0)
        gr_error(g, WHO " %s: the row count of %s changed from %d to %d under ave %s", f->id,
                 a->v[0].name, a->nrows, len, a->w.kind == AVE_RUNNING ? "running" : "window");
    a->nrows = len;
    allocate(g, f, a);
}

static int extensive_of(struct gravel *g, const struct ave_time *a, const struct value *v,
                        int row)
{
    if (v->which == W_VARIABLE || v->which == W_THERMO_TEMP)
        return 0;
    if (v->which == W_COMPUTE) {
        struct compute *c = compute_find(g, v->id);
        if (a->mode == MODE_SCALAR)
            return v->argindex ? c->extvector : c->extscalar;
        return v->argindex ? c->extarray : c->extvector;
    }
    struct fix *f = fix_find(g, v->id);
    if (a->mode == MODE_SCALAR)
        return fix_output_extensive(f, v->argindex, 0);
    if (v->argindex)
        return f->extarray;
    return row >= 0 ? fix_output_extensive(f, row + 1, 0) : f->extvector;
}

/* LAMMPS: the output's kind and intensive/extensive flags from its inputs. */
static void set_output(struct gravel *g, struct fix *f, struct ave_time *a)
{
    f->scalar_flag = f->vector_flag = f->array_flag = 0;
    f->global_freq = a->s.nfreq;
    f->rows_variable = a->mode == MODE_VECTOR && a->all_varlen;
    const struct value *v0 = &a->v[0];
    if (a->mode == MODE_SCALAR && a->nvalues == 1) {
        f->scalar_flag = 1;
        f->extscalar = extensive_of(g, a, v0, -1);
    } else if (a->mode == MODE_SCALAR) {
        f->vector_flag = 1;
        f->size_vector = a->nvalues;
        f->extvector = -1;
        a->extlist = gr_calloc(g, (size_t)a->nvalues, sizeof(int));
        for (int j = 0; j < a->nvalues; j++)
            a->extlist[j] = extensive_of(g, a, &a->v[j], -1);
        f->extlist = a->extlist;
    } else if (a->nvalues == 1) {
        f->vector_flag = 1;
        f->size_vector = a->nrows;
        f->extvector = extensive_of(g, a, v0, -1);
        if (f->extvector < 0) {
            a->extlist = gr_calloc(g, (size_t)a->nrows, sizeof(int));
            for (int i = 0; i < a->nrows; i++)
                a->extlist[i] = extensive_of(g, a, v0, i);
            f->extlist = a->extlist;
        }
    } else {
        f->array_flag = 1;
        f->size_array_rows = a->nrows;
        f->size_array_cols = a->nvalues;
        for (int j = 0; j < a->nvalues; j++) {
            int e = extensive_of(g, a, &a->v[j], -1);
            if (e < 0 || (j > 0 && e != f->extarray))
                gr_error(g, WHO ": cannot set the output array intensive/extensive from "
                            "these inputs (%s is %s)", a->v[j].name,
                         e < 0 ? "mixed" : e ? "extensive" : "intensive");
            f->extarray = e;
        }
    }
}

static void write_header(struct gravel *g, struct fix *f, struct ave_time *a,
                         const char *const title[3])
{
    FILE *fp = a->af.fp;
    if (title[0])
        fprintf(fp, "%s\n", title[0]);
    else
        fprintf(fp, "# Time-averaged data for fix %s\n", f->id);
    if (title[1])
        fprintf(fp, "%s\n", title[1]);
    else if (a->mode == MODE_SCALAR) {
        fputs("# TimeStep", fp);
        for (int j = 0; j < a->nvalues; j++)
            fprintf(fp, " %s", a->v[j].name);
        fputc('\n', fp);
    } else {
        fputs("# TimeStep Number-of-rows\n", fp);
    }
    if (a->mode == MODE_VECTOR) {
        if (title[2])
            fprintf(fp, "%s\n", title[2]);
        else {
            fputs("# Row", fp);
            for (int j = 0; j < a->nvalues; j++)
                fprintf(fp, " %s", a->v[j].name);
            fputc('\n', fp);
        }
    }
    ave_file_header_done(g, &a->af, WHO);
}

static void at_create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, WHO " expects Nevery Nrepeat Nfreq and at least one value");
    struct ave_time *a = gr_calloc(g, 1, sizeof *a);
    f->data = a;
    ave_sched_parse(g, &a->s, argv, WHO);
    int nargs = 0;
    while (3 + nargs < argc && is_value(argv[3 + nargs]))
        nargs++;
    if (nargs == 0)
        gr_error(g, WHO ": no values from computes, fixes or variables (c_ID, f_ID, v_name), "
                    "got '%.64s'", argv[3]);
    /* keywords first: the mode decides how wildcards expand */
    a->w.kind = AVE_ONE;
    struct ave_opts o = {0};
    int noff = 0, off[64];
    for (int i = 3 + nargs; i < argc; i++) {
        const char *kw = argv[i];
        if (ave_keyword(g, &o, &a->s, &a->w, &a->af, argc, argv, &i, WHO)) {
            continue;
        } else if (!strcmp(kw, "off")) {
            arg_need(g, argc, i, 1, kw);
            if (noff == (int)(sizeof off / sizeof off[0]))
                gr_error(g, WHO ": at most %d off keywords", noff);
            off[noff++] = arg_int(g, argv[++i], "off column");
        } else if (!strcmp(kw, "format")) {
            arg_need(g, argc, i, 1, kw);
            free(a->format);
            a->format = gr_strdup(g, argv[++i]); /* used as given (LAMMPS 2021) */
            if (!expr_format_ok(a->format))
                gr_error(g, WHO ": format '%.64s' must have exactly one floating point "
                            "conversion", argv[i]);
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s' (file, append, ave, start, mode, off, "
                        "overwrite, format, title1, title2, title3)", kw);
        }
    }
    a->mode = o.vector_mode ? MODE_VECTOR : MODE_SCALAR;
    if (a->w.kind != AVE_RUNNING && a->af.overwrite)
        gr_error(g, WHO ": overwrite needs ave running");
    /* the values, wildcards expanded */
    int cap = 0;
    for (int k = 0; k < nargs; k++) {
        const char *ref = argv[3 + k];
        char prefix[GR_NAMELEN + 2], one[GR_NAMELEN + 16];
        int lo, hi;
        if (!ref_wildcard(g, ref, a->mode == MODE_VECTOR, prefix, &lo, &hi, WHO)) {
            add_value(g, a, ref, &cap);
            continue;
        }
        for (int i = lo; i <= hi; i++) {
            snprintf(one, sizeof one, "%s[%d]", prefix, i);
            add_value(g, a, one, &cap);
        }
    }
    for (int k = 0; k < noff; k++) {
        if (off[k] < 1 || off[k] > a->nvalues)
            gr_error(g, WHO ": off column %d is not among the %d values", off[k], a->nvalues);
        a->v[off[k] - 1].offcol = 1;
    }
    a->all_varlen = 1;
    for (int j = 0; j < a->nvalues; j++) {
        check_value(g, a, &a->v[j]);
        a->any_varlen |= a->v[j].varlen;
        a->all_varlen &= a->v[j].varlen;
    }
    /* vector mode: the static columns' common length (variable ones: 1 until the first
     * sample) */
    a->nrows = 1;
    if (a->mode == MODE_VECTOR && !a->all_varlen) {
        int len = 0;
        for (int j = 0; j < a->nvalues; j++) {
            if (a->v[j].varlen)
                continue;
            int l = column_length(g, &a->v[j]);
            if (len && l != len)
                gr_error(g, WHO ": columns are inconsistent lengths (%s has %d rows, %s %d)",
                         a->v[j].name, l, a->v[0].name, len);
            len = l;
        }
        a->nrows = len;
    }
    if (a->mode == MODE_VECTOR && a->nrows < 1)
        gr_error(g, WHO ": %s has no rows", a->v[0].name);
    if (o.file) {
        ave_file_open(g, &a->af, o.file, o.append, WHO);
        write_header(g, f, a, o.title);
    }
    allocate(g, f, a);
    set_output(g, f, a);
    ave_sched_reset(g, &a->s);
    f->time_depend = 1;
    f->hooks = HOOK_END_OF_STEP;
}

/* Add value j's sample (scalar mode) or column (vector mode) into a->one. */
static void accumulate(struct gravel *g, struct ave_time *a, int j)
{
    const struct value *v = &a->v[j];
    const int nv = a->nvalues, nr = a->nrows;
    double *dst = a->one + j;
    if (a->mode == MODE_SCALAR) {
        double x;
        if (v->which == W_THERMO_TEMP)
            thermo_keyword_value(g, "c_thermo_temp", &x);
        else
            x = ave_scalar_input(g, v->name[0], v->id, v->argindex, v->name, WHO);
        *dst = v->offcol ? x : *dst + x;
        return;
    }
    const double *src = NULL;
    int stride = 1;
    struct fix *f = NULL;
    if (v->which == W_COMPUTE) {
        struct compute *c = compute_get(g, v->id, WHO);
        if (v->argindex) {
            src = compute_array(g, c) + (v->argindex - 1);
            stride = c->size_array_cols;
            if (c->size_array_rows != nr)
                gr_error(g, WHO ": %s changed its row count within an Nfreq epoch (%d, was "
                            "%d)", v->name, c->size_array_rows, nr);
        } else {
            src = compute_vector(g, c);
        }
    } else {
        f = fix_find(g, v->id);
        if (!f)
            gr_error(g, WHO ": fix ID '%s' for %s does not exist", v->id, v->name);
    }
    for (int i = 0; i < nr; i++) {
        double x = src ? src[(size_t)i * stride]
                       : fix_output(g, f, i + 1, v->argindex, 0, WHO);
        double *d = dst + (size_t)i * nv;
        *d = v->offcol ? x : *d + x;
    }
}

/* One sample (and the epoch's output when it closes it), on the host atoms. */
static void at_take(struct gravel *g, struct fix *f)
{
    struct ave_time *a = f->data;
    run_sync_host(g);
    const int nv = a->nvalues;
    if (a->s.irepeat == 0) {
        if (a->mode == MODE_VECTOR && a->any_varlen)
            epoch_rows(g, f, a);
        memset(a->one, 0, (size_t)a->nrows * nv * sizeof(double));
    }
    for (int j = 0; j < nv; j++)
        accumulate(g, a, j);
    if (!ave_sched_next(g, &a->s))
        return;
    const size_t n = (size_t)a->nrows * nv;
    for (size_t k = 0; k < n; k++)
        if (!a->v[k % nv].offcol)
            a->one[k] /= a->s.nrepeat;
    ave_window_add(&a->w, a->total, a->list, a->one, n);
    ave_window_advance(&a->w);
    /* off columns read as their last value */
    for (size_t k = 0; k < n; k++)
        if (a->v[k % nv].offcol)
            a->total[k] = a->w.norm * a->one[k];
    FILE *fp = a->af.fp;
    if (!fp)
        return;
    ave_file_begin(&a->af);
    const char *fmt = a->format ? a->format : " %g";
    const double norm = a->w.norm;
    if (a->mode == MODE_SCALAR) {
        fprintf(fp, "%lld", (long long)g->step);
        for (int j = 0; j < nv; j++)
            fprintf(fp, fmt, a->total[j] / norm);
        fputc('\n', fp);
    } else {
        fprintf(fp, "%lld %d\n", (long long)g->step, a->nrows);
        for (int i = 0; i < a->nrows; i++) {
            fprintf(fp, "%d", i + 1);
            for (int j = 0; j < nv; j++)
                fprintf(fp, fmt, a->total[(size_t)i * nv + j] / norm);
            fputc('\n', fp);
        }
    }
    ave_file_end(g, &a->af, WHO, f->id);
}

static void at_init(struct gravel *g, struct fix *f)
{
    struct ave_time *a = f->data;
    for (int j = 0; j < a->nvalues; j++)
        if (a->v[j].which != W_THERMO_TEMP)
            ave_source_check(g, &a->s, a->v[j].name[0], a->v[j].id, WHO, f->id);
    if (a->s.nvalid < g->step)
        ave_sched_reset(g, &a->s);
}

static double at_scalar(struct gravel *g, struct fix *f)
{
    (void)g;
    const struct ave_time *a = f->data;
    return a->w.norm ? a->total[0] / a->w.norm : 0.0;
}

/* Element i (1-based): scalar mode the i-th value, vector mode row i. */
static double at_vector(struct gravel *g, struct fix *f, int i)
{
    (void)g;
    const struct ave_time *a = f->data;
    int k = a->mode == MODE_SCALAR ? i - 1 : (i - 1) * a->nvalues;
    if (!a->w.norm || i < 1 || (a->mode == MODE_VECTOR && i > a->nrows))
        return 0.0;
    return a->total[k] / a->w.norm;
}

static double at_array(struct gravel *g, struct fix *f, int i, int j)
{
    (void)g;
    const struct ave_time *a = f->data;
    if (!a->w.norm || i < 1 || i > a->nrows)
        return 0.0;
    return a->total[(size_t)(i - 1) * a->nvalues + (j - 1)] / a->w.norm;
}

static void at_sample(struct gravel *g, struct fix *f)
{
    struct ave_time *a = f->data;
    ave_sample(g, f, &a->s, WHO, at_take);
}

const struct fix_style fix_style_ave_time = {
    .name = "ave/time",
    .flags = FIX_OUTPUT,
    .create = at_create,
    .init = at_init,
    .setup = at_sample, /* LAMMPS's setup(): a sample when the run's first step is due */
    .end_of_step = at_sample,
    .scalar = at_scalar,
    .vector = at_vector,
    .array = at_array,
    .destroy = at_destroy,
};
