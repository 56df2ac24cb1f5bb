/* fix_ave_histo.c - `fix ID group ave/histo Nevery Nrepeat Nfreq lo hi Nbin
 * value ... keyword args ...`: histograms of values over time, LAMMPS's
 * fix_ave_histo.cpp semantics, text file and output (29 Sep 2021).
 *
 * Values, all of one kind:
 *  - per-atom (the atoms of the group; mode vector): x y z vx vy vz fx fy fz,
 *    c_ID / c_ID[I] of a per-atom compute (vector / column I), f_ID /
 *    f_ID[I] of a fix's per-atom output, v_name of an atom-style variable;
 *  - local (every row; mode vector): c_ID / c_ID[I] of a local compute;
 *  - global: mode scalar, c_ID (scalar), c_ID[I] (vector element), f_ID,
 *    f_ID[I], v_name (equal-style); mode vector, c_ID / f_ID (the global
 *    vector) and c_ID[I] / f_ID[I] (array column I).
 * c_ID[*] wildcards expand (ref.h). Each sample bins every value into Nbin
 * bins of [lo, hi]; values beyond go, by `beyond`, to the missing count
 * (ignore), the end bins (end) or two extra bins (extra). Counts add up
 * over the Nrepeat samples (not averaged, as LAMMPS) and over earlier Nfreq
 * results under ave running / window M.
 * Keywords: mode, file, append, ave, start, beyond, overwrite, title1/2/3.
 * Output: a global vector (total count, missing count, min, max) and a
 * global array of Nbin rows (bin centre, count, count / total), intensive,
 * current every Nfreq steps. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "ave_common.h"
#include "compute.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "ref.h"
#include "variable.h"

#define WHO "fix ave/histo"
#define BIG 1.0e20

enum { W_X, W_V, W_F, W_COMPUTE, W_FIX, W_VARIABLE };
enum { K_GLOBAL, K_PERATOM, K_LOCAL };
enum { B_IGNORE, B_END, B_EXTRA };
enum { S_COUNT, S_MISSING, S_MIN, S_MAX }; /* stats, LAMMPS's order */

struct hvalue {
    int which, kind;
    int argindex;               /* I of [I]; x y z ...: the component */
    char id[GR_NAMELEN];
};

struct ave_histo {
    struct ave_sched s;
    struct ave_window w;
    struct ave_file af;
    int vector_mode, kind, beyond;
    double lo, hi, binsize;
    int nbins;                  /* with the two extra bins of `beyond extra` */
    int nvalues;
    struct hvalue *v;
    double *coord;              /* [nbins] bin centres (extra: lo and hi) */
    /* [S_COUNT, S_MISSING, bins...]: this epoch's, the totals, the window */
    double *one, *total, *list;
    double min, max, min_total, max_total;
    double *minmax_list;        /* [nwindow][2] */
};

static void ah_destroy(struct fix *f)
{
    struct ave_histo *a = f->data;
    if (a) {
        ave_file_close(&a->af);
        free(a->v);
        free(a->coord);
        free(a->one);
        free(a->total);
        free(a->list);
        free(a->minmax_list);
    }
    free(a);
    f->data = NULL;
}

static const char *const atom_words[] = {"x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz"};
#define NATOMWORDS ((int)(sizeof atom_words / sizeof atom_words[0]))

static int atom_word(const char *s)
{
    for (int k = 0; k < NATOMWORDS; k++)
        if (!strcmp(s, atom_words[k]))
            return k;
    return -1;
}

static int is_value(const char *s)
{
    return atom_word(s) >= 0 || ((s[0] == 'c' || s[0] == 'f' || s[0] == 'v') && s[1] == '_');
}

static struct hvalue *add_value(struct gravel *g, struct ave_histo *a, int *cap)
{
    if (a->nvalues == *cap) {
        *cap = *cap ? 2 * *cap : 8;
        a->v = gr_realloc(g, a->v, (size_t)*cap * sizeof *a->v);
    }
    struct hvalue *v = &a->v[a->nvalues++];
    memset(v, 0, sizeof *v);
    return v;
}

/* One value word (wildcards already expanded). */
static void parse_value(struct gravel *g, struct ave_histo *a, const char *ref, int *cap)
{
    int k = atom_word(ref);
    if (k >= 0) {
        struct hvalue *v = add_value(g, a, cap);
        v->which = k / 3; /* W_X, W_V, W_F */
        v->argindex = k % 3;
        v->kind = K_PERATOM;
        return;
    }
    char id[GR_NAMELEN];
    int index, col;
    if (!ref_parse(ref, ref[0], id, &index, &col) || col)
        gr_error(g, WHO ": invalid value '%.64s' (x y z vx vy vz fx fy fz, c_ID, c_ID[I], f_ID, "
                    "f_ID[I], v_name)", ref);
    int which = ref[0] == 'c' ? W_COMPUTE : ref[0] == 'f' ? W_FIX : W_VARIABLE, kind;
    if (which == W_COMPUTE) {
        struct compute *c = compute_find(g, id);
        if (!c)
            gr_error(g, WHO ": compute ID '%s' for %s does not exist", id, ref);
        kind = c->scalar_flag || c->vector_flag || c->array_flag ? K_GLOBAL
               : c->peratom_flag ? K_PERATOM : K_LOCAL;
    } else if (which == W_FIX) {
        struct fix *f = fix_find(g, id);
        if (!f)
            gr_error(g, WHO ": fix ID '%s' for %s does not exist", id, ref);
        if (!f->scalar_flag && !f->vector_flag && !f->array_flag && !f->peratom_flag)
            gr_error(g, WHO ": fix %s (%s) has no global or per-atom output (gravel's fixes have "
                        "no local output)", id, f->style->name);
        kind = f->scalar_flag || f->vector_flag || f->array_flag ? K_GLOBAL : K_PERATOM;
    } else {
        if (!var_exists(g, id))
            gr_error(g, WHO ": variable name '%s' for %s does not exist", id, ref);
        if (var_is_atom(g, id))
            kind = K_PERATOM;
        else if (var_is_equal(g, id))
            kind = K_GLOBAL;
        else
            gr_error(g, WHO ": variable %s is neither equal-style nor atom-style", id);
        if (index)
            gr_error(g, WHO ": %s: variable %s is not vector-style (gravel has no vector-style "
                        "variables)", ref, id);
    }
    struct hvalue *v = add_value(g, a, cap);
    v->which = which;
    v->kind = kind;
    v->argindex = index;
    snprintf(v->id, sizeof v->id, "%s", id);
}

/* "f_ID" or "f_ID[I]" of a fix value (static: one at a time) */
static const char *fix_ref_text(const struct hvalue *v)
{
    static char ref[GR_NAMELEN + 24];
    if (v->argindex)
        snprintf(ref, sizeof ref, "f_%s[%d]", v->id, v->argindex);
    else
        snprintf(ref, sizeof ref, "f_%s", v->id);
    return ref;
}

/* LAMMPS's checks of a value of the fix's kind and mode. */
static void check_value(struct gravel *g, struct ave_histo *a, const struct hvalue *v)
{
    if (v->which == W_COMPUTE && a->kind == K_PERATOM)
        compute_peratom_check(g, v->id, v->argindex, WHO);
    else if (v->which == W_COMPUTE && a->kind == K_LOCAL)
        compute_local_check(g, v->id, v->argindex, WHO);
    else if (v->which == W_FIX && a->kind == K_PERATOM) {
        struct fix *src = fix_peratom_check(g, fix_ref_text(v), WHO);
        if (a->s.nevery % src->peratom_freq) /* LAMMPS: "not computed at compatible time" */
            gr_error(g, WHO ": fix %s's per-atom output is current every %d steps, Nevery is %d",
                     src->id, src->peratom_freq, a->s.nevery);
    }
    else if (v->which == W_COMPUTE || v->which == W_FIX)
        ave_global_check(g, v->which == W_COMPUTE ? 'c' : 'f', v->id, v->argindex,
                         a->vector_mode, a->s.nevery, WHO);
}

static void bin_one(struct ave_histo *a, double x)
{
    double *bin = a->one + 2;
    if (x < a->min)
        a->min = x;
    if (x > a->max)
        a->max = x;
    if (x < a->lo || x > a->hi) {
        if (a->beyond == B_IGNORE) {
            a->one[S_MISSING] += 1.0;
            return;
        }
        bin[x < a->lo ? 0 : a->nbins - 1] += 1.0;
    } else {
        /* as LAMMPS: x == hi goes to the last bin, the upper extra bin under extra */
        const int extra = a->beyond == B_EXTRA;
        int ib = (int)((x - a->lo) / a->binsize);
        if (ib > a->nbins - 1 - extra)
            ib = a->nbins - 1 - extra;
        bin[ib + extra] += 1.0;
    }
    a->one[S_COUNT] += 1.0;
}

/* n values at p with a stride; per-atom ones only for the group's atoms. */
static void bin_many(struct gravel *g, struct fix *f, struct ave_histo *a, const double *p,
                     int n, int stride, int peratom)
{
    for (int k = 0; k < n; k++)
        if (!peratom || (g->atoms.mask[k] & f->groupbit))
            bin_one(a, p[(size_t)k * stride]);
}

static void bin_value(struct gravel *g, struct fix *f, struct ave_histo *a,
                      const struct hvalue *v)
{
    const int i = v->argindex, natoms = g->atoms.n;
    switch (v->which) {
    case W_X: bin_many(g, f, a, g->atoms.x + i, natoms, 3, 1); return;
    case W_V: bin_many(g, f, a, g->atoms.v + i, natoms, 3, 1); return;
    case W_F: bin_many(g, f, a, g->atoms.f + i, natoms, 3, 1); return;
    case W_VARIABLE:
        if (a->kind == K_GLOBAL) {
            bin_one(a, var_compute_equal(g, v->id));
        } else {
            double *val = var_atom_values(g, v->id);
            bin_many(g, f, a, val, natoms, 1, 1);
            free(val);
        }
        return;
    case W_FIX: {
        struct fix *src = fix_find(g, v->id);
        if (!src)
            gr_error(g, WHO " %s: fix ID '%s' does not exist", f->id, v->id);
        if (a->kind == K_PERATOM) {
            int stride;
            const double *p = fix_peratom_ref(g, fix_ref_text(v), &stride, WHO);
            bin_many(g, f, a, p, natoms, stride, 1);
        } else if (!a->vector_mode)
            bin_one(a, fix_output(g, src, i, 0, 0, WHO));
        else if (!i)
            for (int r = 1; r <= src->size_vector; r++)
                bin_one(a, fix_output(g, src, r, 0, 0, WHO));
        else
            for (int r = 1; r <= src->size_array_rows; r++)
                bin_one(a, fix_output(g, src, r, i, 0, WHO));
        return;
    }
    default: break;
    }
    struct compute *c = compute_get(g, v->id, WHO);
    if (a->kind == K_PERATOM) {
        int stride;
        const double *p = compute_peratom_ref(g, c, i, &stride, WHO);
        bin_many(g, f, a, p, natoms, stride, 1);
    } else if (a->kind == K_LOCAL) {
        const double *p;
        int rows = compute_local(g, c, &p), cols = c->size_local_cols > 0 ? c->size_local_cols : 1;
        bin_many(g, f, a, p + (i ? i - 1 : 0), rows, cols, 0);
    } else if (!a->vector_mode) {
        bin_one(a, i ? compute_vector(g, c)[i - 1] : compute_scalar(g, c));
    } else if (!i) {
        bin_many(g, f, a, compute_vector(g, c), c->size_vector, 1, 0);
    } else {
        const double *p = compute_array(g, c);
        bin_many(g, f, a, p + (i - 1), c->size_array_rows, c->size_array_cols, 0);
    }
}

/* One sample (and the epoch's output when it closes it), on the host atoms. */
static void ah_take(struct gravel *g, struct fix *f)
{
    struct ave_histo *a = f->data;
    run_sync_host(g);
    const size_t n = (size_t)a->nbins + 2;
    if (a->s.irepeat == 0) {
        memset(a->one, 0, n * sizeof(double));
        a->min = BIG;
        a->max = -BIG;
    }
    for (int j = 0; j < a->nvalues; j++)
        bin_value(g, f, a, &a->v[j]);
    if (!ave_sched_next(g, &a->s))
        return;
    /* counts add up; min and max of the results combined */
    int first = a->w.norm == 0;
    ave_window_add(&a->w, a->total, a->list, a->one, n);
    if (a->w.kind == AVE_ONE || (a->w.kind == AVE_RUNNING && first)) {
        a->min_total = a->min;
        a->max_total = a->max;
    } else if (a->w.kind == AVE_RUNNING) {
        a->min_total = a->min < a->min_total ? a->min : a->min_total;
        a->max_total = a->max > a->max_total ? a->max : a->max_total;
    } else {
        double *mm = a->minmax_list;
        mm[2 * a->w.iwindow] = a->min;
        mm[2 * a->w.iwindow + 1] = a->max;
        int m = a->w.full ? a->w.nwindow : a->w.iwindow + 1;
        a->min_total = mm[0];
        a->max_total = mm[1];
        for (int k = 1; k < m; k++) {
            a->min_total = mm[2 * k] < a->min_total ? mm[2 * k] : a->min_total;
            a->max_total = mm[2 * k + 1] > a->max_total ? mm[2 * k + 1] : a->max_total;
        }
    }
    ave_window_advance(&a->w);
    FILE *fp = a->af.fp;
    if (!fp)
        return;
    ave_file_begin(&a->af);
    const double total = a->total[S_COUNT];
    fprintf(fp, "%lld %d %g %g %g %g\n", (long long)g->step, a->nbins, total,
            a->total[S_MISSING], a->min_total, a->max_total);
    for (int b = 0; b < a->nbins; b++) {
        double cnt = total != 0.0 ? a->total[2 + b] : 0.0;
        fprintf(fp, "%d %g %g %g\n", b + 1, a->coord[b], cnt, total != 0.0 ? cnt / total : 0.0);
    }
    ave_file_end(g, &a->af, WHO, f->id);
}

static void ah_create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 7)
        gr_error(g, WHO " expects Nevery Nrepeat Nfreq lo hi Nbin and at least one value");
    struct ave_histo *a = gr_calloc(g, 1, sizeof *a);
    f->data = a;
    ave_sched_parse(g, &a->s, argv, WHO);
    a->lo = arg_double(g, argv[3], "lo");
    a->hi = arg_double(g, argv[4], "hi");
    a->nbins = arg_int(g, argv[5], "Nbin");
    if (a->lo >= a->hi)
        gr_error(g, WHO ": lo must be below hi (got %g %g)", a->lo, a->hi);
    if (a->nbins <= 0)
        gr_error(g, WHO ": Nbin must be positive, got %d", a->nbins);
    int nargs = 0;
    while (6 + nargs < argc && is_value(argv[6 + nargs]))
        nargs++;
    if (nargs == 0)
        gr_error(g, WHO ": no values (x y z vx vy vz fx fy fz, c_ID, f_ID, v_name), got '%.64s'",
                 argv[6]);
    a->w.kind = AVE_ONE;
    struct ave_opts o = {0};
    for (int i = 6 + nargs; i < argc; i++) {
        const char *kw = argv[i];
        if (ave_keyword(g, &o, &a->s, &a->w, &a->af, argc, argv, &i, WHO)) {
            continue;
        } else if (!strcmp(kw, "beyond")) {
            arg_need(g, argc, i, 1, kw);
            const char *b = argv[++i];
            if (!strcmp(b, "ignore"))
                a->beyond = B_IGNORE;
            else if (!strcmp(b, "end"))
                a->beyond = B_END;
            else if (!strcmp(b, "extra"))
                a->beyond = B_EXTRA;
            else
                gr_error(g, WHO ": beyond must be ignore, end or extra, got '%.32s'", b);
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s' (file, append, ave, start, mode, beyond, "
                        "overwrite, title1, title2, title3)", kw);
        }
    }
    a->vector_mode = o.vector_mode;
    if (a->w.kind != AVE_RUNNING && a->af.overwrite)
        gr_error(g, WHO ": overwrite needs ave running");
    int cap = 0;
    for (int k = 0; k < nargs; k++) {
        const char *ref = argv[6 + k];
        char prefix[GR_NAMELEN + 2], one[GR_NAMELEN + 16];
        int lo, hi;
        if (atom_word(ref) >= 0 || !ref_wildcard(g, ref, a->vector_mode, prefix, &lo, &hi, WHO)) {
            parse_value(g, a, ref, &cap);
            continue;
        }
        for (int i = lo; i <= hi; i++) {
            snprintf(one, sizeof one, "%s[%d]", prefix, i);
            parse_value(g, a, one, &cap);
        }
    }
    static const char *const kinds[] = {"global", "per-atom", "local"};
    a->kind = a->v[0].kind;
    for (int j = 1; j < a->nvalues; j++)
        if (a->v[j].kind != a->kind)
            gr_error(g, WHO ": values are not all global, per-atom or local (value %d is %s, "
                        "value 1 %s)", j + 1, kinds[a->v[j].kind], kinds[a->kind]);
    if (a->kind != K_GLOBAL && !a->vector_mode)
        gr_error(g, WHO ": cannot take %s values in scalar mode (add mode vector)",
                 kinds[a->kind]);
    for (int j = 0; j < a->nvalues; j++)
        check_value(g, a, &a->v[j]);
    const char *const *title = o.title;
    if (o.file) {
        ave_file_open(g, &a->af, o.file, o.append, WHO);
        if (title[0])
            fprintf(a->af.fp, "%s\n", title[0]);
        else
            fprintf(a->af.fp, "# Histogrammed data for fix %s\n", f->id);
        fprintf(a->af.fp, "%s\n", title[1] ? title[1] : "# TimeStep Number-of-bins "
                "Total-counts Missing-counts Min-value Max-value");
        fprintf(a->af.fp, "%s\n", title[2] ? title[2] : "# Bin Coord Count Count/Total");
        ave_file_header_done(g, &a->af, WHO);
    }
    /* bins and their centres (extra: lo and hi for the two outer ones) */
    int inner = a->nbins;
    if (a->beyond == B_EXTRA)
        a->nbins += 2;
    a->binsize = (a->hi - a->lo) / inner;
    a->coord = gr_calloc(g, (size_t)a->nbins, sizeof(double));
    for (int b = 0; b < inner; b++)
        a->coord[b + (a->beyond == B_EXTRA)] = a->lo + (b + 0.5) * a->binsize;
    if (a->beyond == B_EXTRA) {
        a->coord[0] = a->lo;
        a->coord[a->nbins - 1] = a->hi;
    }
    size_t n = (size_t)a->nbins + 2;
    a->one = gr_calloc(g, n, sizeof(double));
    a->total = gr_calloc(g, n, sizeof(double));
    if (a->w.kind == AVE_WINDOW) {
        a->list = gr_calloc(g, (size_t)a->w.nwindow * n, sizeof(double));
        a->minmax_list = gr_calloc(g, (size_t)a->w.nwindow * 2, sizeof(double));
    }
    f->scalar_flag = 0;
    f->vector_flag = f->array_flag = 1;
    f->size_vector = 4;
    f->size_array_rows = a->nbins;
    f->size_array_cols = 3;
    f->extvector = f->extarray = 0;
    f->global_freq = a->s.nfreq;
    ave_sched_reset(g, &a->s);
    f->hooks = HOOK_END_OF_STEP;
}

static const char kind_letter[] = {[W_COMPUTE] = 'c', [W_FIX] = 'f', [W_VARIABLE] = 'v'};

static void ah_init(struct gravel *g, struct fix *f)
{
    struct ave_histo *a = f->data;
    for (int j = 0; j < a->nvalues; j++)
        if (a->v[j].which >= W_COMPUTE)
            ave_source_check(g, &a->s, kind_letter[a->v[j].which], a->v[j].id, WHO, f->id);
    if (a->s.nvalid < g->step)
        ave_sched_reset(g, &a->s);
}

/* (total count, missing count, min, max) of the combined results */
static double ah_vector(struct gravel *g, struct fix *f, int i)
{
    (void)g;
    const struct ave_histo *a = f->data;
    switch (i) {
    case 1: return a->total[S_COUNT];
    case 2: return a->total[S_MISSING];
    case 3: return a->w.norm ? a->min_total : 0.0;
    default: return a->w.norm ? a->max_total : 0.0;
    }
}

/* row b: bin centre, count, count / total */
static double ah_array(struct gravel *g, struct fix *f, int b, int j)
{
    (void)g;
    const struct ave_histo *a = f->data;
    if (j == 1)
        return a->coord[b - 1];
    if (j == 2)
        return a->total[1 + b];
    return a->total[S_COUNT] != 0.0 ? a->total[1 + b] / a->total[S_COUNT] : 0.0;
}

static void ah_sample(struct gravel *g, struct fix *f)
{
    struct ave_histo *a = f->data;
    ave_sample(g, f, &a->s, WHO, ah_take);
}

const struct fix_style fix_style_ave_histo = {
    .name = "ave/histo",
    .flags = FIX_OUTPUT,
    .create = ah_create,
    .init = ah_init,
    .setup = ah_sample, /* LAMMPS's setup(): a sample when the run's first step is due */
    .end_of_step = ah_sample,
    .vector = ah_vector,
    .array = ah_array,
    .destroy = ah_destroy,
};
