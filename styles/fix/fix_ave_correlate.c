/* fix_ave_correlate.c - `fix ID group ave/correlate Nevery Nrepeat Nfreq
 * value ... [type auto|upper|lower|auto/upper|auto/lower|full] [ave
 * one|running] [start S] [prefactor p] [file F] [overwrite] [title1 ..
 * title3 T]`: LAMMPS's fix ave/correlate (2021). Every Nevery steps (from
 * max(the step it is defined or a run starts, S) rounded up to a multiple
 * of Nevery) the global values (c_ID, c_ID[I], f_ID, f_ID[I], v_name;
 * c_ID[*] expands) join a ring of the last Nrepeat samples, and each
 * pair's product of the newest sample with the one k samples earlier is
 * added to C_k (k = 0 .. Nrepeat-1) and its count. On multiples of Nfreq
 * the averages p C_k / count_k are kept (and written: "step Nrepeat", then
 * per k "k+1 k*Nevery count" and each pair's value with %g, 0.0 without
 * samples); `ave one` then starts the sums again from the newest sample.
 * The pairs: auto (i,i); upper i < j; lower j < i; auto/upper j >= i;
 * auto/lower j <= i; full all (i the older sample's value). As LAMMPS 2021,
 * the file header of `lower` lists the pairs j < i - 1 and that of
 * `auto/lower` j < i. Global array Nrepeat x (npair + 2): k Nevery, the
 * count, the averages. The group is not used. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "ave_common.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "par.h"
#include "ref.h"
#include "thermo.h"
#include "variable.h"

#define WHO "fix ave/correlate"

enum corr_type { T_AUTO, T_UPPER, T_LOWER, T_AUTOUPPER, T_AUTOLOWER, T_FULL };

struct corr_value {
    char kind;                  /* c f v */
    char id[GR_NAMELEN];
    int index;                  /* I of [I], 0 without */
    char name[GR_NAMELEN + 16]; /* as written (the header's) */
};

struct ave_correlate {
    int nevery, nrepeat, nfreq, running;
    bigint start, nvalid;
    enum corr_type type;
    double prefactor;
    int nvalues, npair;
    struct corr_value *v;
    double *values;             /* ring [nrepeat][nvalues] */
    int lastindex, firstindex, nsample;
    int *count, *save_count;    /* [nrepeat] */
    double *corr, *save_corr;   /* [nrepeat][npair] */
    struct ave_file af;         /* af.fp NULL: no file */
    int reads_vars;
};

static void destroy(struct fix *f)
{
    struct ave_correlate *a = f->data;
    if (!a)
        return;
    ave_file_close(&a->af);
    free(a->v);
    free(a->values);
    free(a->count);
    free(a->save_count);
    free(a->corr);
    free(a->save_corr);
    free(a);
}

/* pair (i, j) is counted by type t (the data's rule) */
static int pair_in(enum corr_type t, int i, int j)
{
    switch (t) {
    case T_AUTO: return i == j;
    case T_UPPER: return j > i;
    case T_LOWER: return j < i;
    case T_AUTOUPPER: return j >= i;
    case T_AUTOLOWER: return j <= i;
    case T_FULL: return 1;
    }
    return 0;
}

/* the header's rule: LAMMPS 2021 lists lower's pairs j < i - 1, auto/lower's j < i */
static int pair_named(enum corr_type t, int i, int j)
{
    if (t == T_LOWER)
        return j < i - 1;
    if (t == T_AUTOLOWER)
        return j < i;
    return pair_in(t, i, j);
}

static enum corr_type parse_type(struct gravel *g, const char *s)
{
    static const char *const names[] = {"auto", "upper", "lower", "auto/upper", "auto/lower",
                                        "full"};
    for (int k = 0; k < 6; k++)
        if (!strcmp(s, names[k]))
            return (enum corr_type)k;
    gr_error(g, WHO ": type must be auto, upper, lower, auto/upper, auto/lower or full, got "
                "'%.32s'", s);
    return T_AUTO;
}

static void add_value(struct gravel *g, struct ave_correlate *a, const char *ref)
{
    a->v = gr_realloc(g, a->v, (size_t)(a->nvalues + 1) * sizeof *a->v);
    struct corr_value *v = &a->v[a->nvalues++];
    memset(v, 0, sizeof *v);
    if (strlen(ref) >= sizeof v->name)
        gr_error(g, WHO ": value '%.64s' is too long", ref);
    snprintf(v->name, sizeof v->name, "%s", ref);
    int col;
    if (!ref_parse(ref, ref[0], v->id, &v->index, &col) || col)
        gr_error(g, WHO ": invalid value '%.64s' (c_ID, c_ID[I], f_ID, f_ID[I], v_name)", ref);
    v->kind = ref[0];
}

/* LAMMPS's nextvalid(): this step, or start, rounded up to a multiple of Nevery */
static bigint next_valid(const struct gravel *g, const struct ave_correlate *a)
{
    bigint n = g->step > a->start ? g->step : a->start;
    if (n % a->nevery)
        n = (n / a->nevery) * a->nevery + a->nevery;
    return n;
}

static void restart_sums(struct ave_correlate *a)
{
    a->lastindex = -1;
    a->firstindex = 0;
    a->nsample = 0;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, WHO " expects Nevery Nrepeat Nfreq and at least one value");
    struct ave_correlate *a = gr_calloc(g, 1, sizeof *a);
    f->data = a;
    a->nevery = arg_int(g, argv[0], "Nevery");
    a->nrepeat = arg_int(g, argv[1], "Nrepeat");
    a->nfreq = arg_int(g, argv[2], "Nfreq");
    a->prefactor = 1.0;
    int i = 3;
    for (; i < argc && (argv[i][0] == 'c' || argv[i][0] == 'f' || argv[i][0] == 'v') &&
           argv[i][1] == '_';
         i++) {
        char prefix[GR_NAMELEN + 2], one[GR_NAMELEN + 16];
        int lo, hi;
        if (!ref_wildcard(g, argv[i], 0, prefix, &lo, &hi, WHO)) {
            add_value(g, a, argv[i]);
            continue;
        }
        for (int k = lo; k <= hi; k++) {
            snprintf(one, sizeof one, "%s[%d]", prefix, k);
            add_value(g, a, one);
        }
    }
    if (!a->nvalues)
        gr_error(g, WHO ": no values from computes, fixes or variables (c_ID, f_ID, v_name)");
    const char *file = NULL, *title[3] = {NULL, NULL, NULL};
    for (; i < argc; i++) {
        const char *kw = argv[i];
        if (!strcmp(kw, "overwrite")) {
            a->af.overwrite = 1;
            continue;
        }
        arg_need(g, argc, i, 1, kw);
        const char *val = argv[++i];
        if (!strcmp(kw, "type"))
            a->type = parse_type(g, val);
        else if (!strcmp(kw, "ave") && (!strcmp(val, "one") || !strcmp(val, "running")))
            a->running = val[0] == 'r';
        else if (!strcmp(kw, "ave"))
            gr_error(g, WHO ": ave must be one or running, got '%.32s'", val);
        else if (!strcmp(kw, "start"))
            a->start = arg_bigint(g, val, "start");
        else if (!strcmp(kw, "prefactor"))
            a->prefactor = arg_double(g, val, "prefactor");
        else if (!strcmp(kw, "file"))
            file = val;
        else if (!strncmp(kw, "title", 5) && kw[5] >= '1' && kw[5] <= '3' && !kw[6])
            title[kw[5] - '1'] = val;
        else
            gr_error(g, WHO ": unknown keyword '%.64s' (type, ave, start, prefactor, file, "
                        "overwrite, title1, title2, title3)", kw);
    }
    if (a->nevery <= 0 || a->nrepeat <= 0 || a->nfreq <= 0)
        gr_error(g, WHO ": Nevery, Nrepeat and Nfreq must be positive");
    if (a->nfreq % a->nevery)
        gr_error(g, WHO ": Nfreq %d is not a multiple of Nevery %d", a->nfreq, a->nevery);
    if (!a->running && a->nfreq < (a->nrepeat - 1) * a->nevery)
        gr_error(g, WHO ": with ave one, Nfreq must be at least (Nrepeat - 1) Nevery");
    if (!a->running && a->af.overwrite)
        gr_error(g, WHO ": overwrite needs ave running");
    for (int k = 0; k < a->nvalues; k++) {
        const struct corr_value *v = &a->v[k];
        if (v->kind == 'v') {
            if (!var_exists(g, v->id))
                gr_error(g, WHO ": variable name '%s' does not exist", v->id);
            if (v->index || !var_is_equal(g, v->id))
                gr_error(g, WHO ": variable %s is not an equal-style variable", v->id);
        } else {
            ave_global_check(g, v->kind, v->id, v->index, 0, a->nevery, WHO);
        }
    }
    const int n = a->nvalues;
    for (int p = 0; p < n; p++)
        for (int q = 0; q < n; q++)
            a->npair += pair_in(a->type, p, q);
    if (file) {
        ave_file_open(g, &a->af, file, 0, WHO);
        FILE *fp = a->af.fp;
        if (title[0])
            fprintf(fp, "%s\n", title[0]);
        else
            fprintf(fp, "# Time-correlated data for fix %s\n", f->id);
        fprintf(fp, "%s\n", title[1] ? title[1] : "# Timestep Number-of-time-windows");
        if (title[2]) {
            fprintf(fp, "%s\n", title[2]);
        } else {
            fprintf(fp, "# Index TimeDelta Ncount");
            for (int p = 0; p < n; p++)
                for (int q = 0; q < n; q++)
                    if (pair_named(a->type, p, q))
                        fprintf(fp, " %s*%s", a->v[p].name, a->v[q].name);
            fprintf(fp, "\n");
        }
        ave_file_header_done(g, &a->af, WHO);
    }
    const size_t r = (size_t)a->nrepeat;
    a->values = gr_calloc(g, r * (size_t)n, sizeof *a->values);
    a->count = gr_calloc(g, r, sizeof *a->count);
    a->save_count = gr_calloc(g, r, sizeof *a->save_count);
    a->corr = gr_calloc(g, r * (size_t)a->npair + 1, sizeof *a->corr);
    a->save_corr = gr_calloc(g, r * (size_t)a->npair + 1, sizeof *a->save_corr);
    f->array_flag = 1;
    f->size_array_rows = a->nrepeat;
    f->size_array_cols = a->npair + 2;
    f->extarray = 0; /* intensive, as LAMMPS */
    f->global_freq = a->nfreq;
    f->time_depend = 1;
    f->hooks = HOOK_END_OF_STEP;
    restart_sums(a);
    a->nvalid = next_valid(g, a);
}

static void init(struct gravel *g, struct fix *f)
{
    struct ave_correlate *a = f->data;
    struct ave_sched s = {0};
    for (int k = 0; k < a->nvalues; k++)
        ave_source_check(g, &s, a->v[k].kind, a->v[k].id, WHO, f->id);
    a->reads_vars = s.reads_vars;
    if (a->nvalid < g->step) { /* LAMMPS: after a minimization; here a reset step */
        restart_sums(a);
        a->nvalid = next_valid(g, a);
    }
}

/* Each pair's product of the newest sample with the k-th before it, k <
 * nsample, into C_k; every count k < nsample up by one (LAMMPS's
 * accumulate). */
static void accumulate(struct ave_correlate *a)
{
    const int n = a->nvalues, r = a->nrepeat;
    for (int k = 0; k < a->nsample; k++)
        a->count[k]++;
    const double *newest = a->values + (size_t)a->lastindex * n;
    int m = a->lastindex;
    for (int k = 0; k < a->nsample; k++) {
        const double *old = a->values + (size_t)m * n;
        double *c = a->corr + (size_t)k * a->npair;
        int ip = 0;
        for (int p = 0; p < n; p++)
            for (int q = 0; q < n; q++)
                if (pair_in(a->type, p, q))
                    c[ip++] += old[p] * newest[q];
        if (--m < 0)
            m = r - 1;
    }
}

static void write_record(struct gravel *g, struct fix *f, struct ave_correlate *a)
{
    FILE *fp = a->af.fp;
    ave_file_begin(&a->af);
    fprintf(fp, "%lld %d\n", (long long)g->step, a->nrepeat);
    for (int k = 0; k < a->nrepeat; k++) {
        fprintf(fp, "%d %d %d", k + 1, k * a->nevery, a->count[k]);
        for (int j = 0; j < a->npair; j++) {
            if (a->count[k])
                fprintf(fp, " %g",
                        a->prefactor * a->corr[(size_t)k * a->npair + j] / a->count[k]);
            else
                fprintf(fp, " 0.0");
        }
        fprintf(fp, "\n");
    }
    ave_file_end(g, &a->af, WHO, f->id);
}

static void end_of_step(struct gravel *g, struct fix *f)
{
    struct ave_correlate *a = f->data;
    if (g->step != a->nvalid)
        return;
    run_sync_host(g);
    if (a->reads_vars)
        thermo_pre_take(g); /* several ranks: the keywords a gathered pass cannot take */
    par_gather_begin(g);
    if (++a->lastindex == a->nrepeat)
        a->lastindex = 0;
    for (int k = 0; k < a->nvalues; k++) {
        const struct corr_value *v = &a->v[k];
        a->values[(size_t)a->lastindex * a->nvalues + k] =
            ave_scalar_input(g, v->kind, v->id, v->index, v->name, WHO);
    }
    par_gather_end(g);
    if (a->reads_vars)
        thermo_pre_clear(g);
    if (a->nsample < a->nrepeat)
        a->nsample++;
    else if (++a->firstindex == a->nrepeat)
        a->firstindex = 0;
    a->nvalid += a->nevery;
    accumulate(a);
    if (g->step % a->nfreq)
        return;
    for (int k = 0; k < a->nrepeat; k++) {
        a->save_count[k] = a->count[k];
        for (int j = 0; j < a->npair; j++) {
            const size_t at = (size_t)k * a->npair + j;
            a->save_corr[at] = a->count[k] ? a->prefactor * a->corr[at] / a->count[k] : 0.0;
        }
    }
    if (a->af.fp)
        write_record(g, f, a);
    if (!a->running) { /* ave one: the sums again from the newest sample */
        memset(a->count, 0, (size_t)a->nrepeat * sizeof *a->count);
        memset(a->corr, 0, (size_t)a->nrepeat * a->npair * sizeof *a->corr);
        a->nsample = 1;
        accumulate(a);
    }
}

/* row i (1-based), column j: 1 the time delta, 2 the count, then the averages */
static double array(struct gravel *g, struct fix *f, int i, int j)
{
    (void)g;
    const struct ave_correlate *a = f->data;
    if (i < 1 || i > a->nrepeat || j < 1 || j > a->npair + 2)
        return 0.0;
    if (j == 1)
        return (double)(i - 1) * a->nevery;
    if (j == 2)
        return (double)a->save_count[i - 1];
    return a->save_count[i - 1] ? a->save_corr[(size_t)(i - 1) * a->npair + (j - 3)] : 0.0;
}

const struct fix_style fix_style_ave_correlate = {
    .name = "ave/correlate",
    .flags = FIX_OUTPUT,
    .create = create,
    .init = init,
    .setup = end_of_step, /* LAMMPS's setup(): a sample when the run's first step is due */
    .end_of_step = end_of_step,
    .array = array,
    .destroy = destroy,
};
