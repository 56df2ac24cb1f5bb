/* compute_slice.c - `compute ID group slice Nstart Nstop Nskip input ...`:
 * LAMMPS's slices of global vectors, inputs c_ID (a compute's global
 * vector), c_ID[I] (column I of its global array), f_ID, f_ID[I] (a fix's).
 * Elements Nstart, Nstart + Nskip, ... below Nstop, (Nstop - Nstart) / Nskip
 * of them (LAMMPS's count: the rounded-down quotient; Nstop itself never
 * taken). One input gives a global vector, several a global array of one
 * column per input (LAMMPS's array path fills every column from the first
 * input: gravel takes each input's own, as LAMMPS documents). Extensive
 * when the input is (a vector of extensive and intensive elements is
 * refused); an array when any input is. The group is ignored. Vector-style
 * variables do not exist in gravel: v_name is refused. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "compute.h"
#include "error.h"
#include "fix.h"
#include "ref.h"

#define WHO "compute slice"

struct slice_in {
    char kind;                  /* 'c' or 'f' */
    char id[GR_NAMELEN];
    int col;                    /* 0: the vector, else the array's column */
};

struct slice {
    int start, stop, skip, n;   /* n elements */
    int nin;
    struct slice_in *in;
};

static void sl_destroy(struct compute *c)
{
    struct slice *s = c->data;
    if (s)
        free(s->in);
    free(s);
    c->data = NULL;
}

/* the rows input m has now (its vector's length, or its array's rows) and
 * whether its elements in the slice are extensive: 1, 0, or -1 when mixed */
static int input_rows(struct gravel *g, const struct slice *s, int m, int *ext)
{
    const struct slice_in *in = &s->in[m];
    if (in->kind == 'c') {
        struct compute *cc = compute_find(g, in->id);
        if (!cc)
            gr_error(g, WHO ": compute ID %s does not exist", in->id);
        if (in->col == 0 && !cc->vector_flag)
            gr_error(g, WHO ": compute %s does not calculate a global vector", in->id);
        if (in->col > 0 && !cc->array_flag)
            gr_error(g, WHO ": compute %s does not calculate a global array", in->id);
        if (in->col > cc->size_array_cols)
            gr_error(g, WHO ": compute %s array is accessed out-of-range (column %d of %d)",
                     in->id, in->col, cc->size_array_cols);
        *ext = in->col ? cc->extarray : cc->extvector;
        return in->col ? cc->size_array_rows : cc->size_vector;
    }
    struct fix *f = fix_find(g, in->id);
    if (!f)
        gr_error(g, WHO ": fix ID %s does not exist", in->id);
    if (in->col == 0 && !f->vector_flag)
        gr_error(g, WHO ": fix %s does not calculate a global vector", in->id);
    if (in->col > 0 && !f->array_flag)
        gr_error(g, WHO ": fix %s does not calculate a global array", in->id);
    if (in->col > f->size_array_cols)
        gr_error(g, WHO ": fix %s array is accessed out-of-range (column %d of %d)", in->id,
                 in->col, f->size_array_cols);
    const int rows = in->col ? f->size_array_rows : f->size_vector;
    *ext = -2;
    for (int k = 0; k < s->n && s->start + k * s->skip <= rows; k++) {
        const int e = in->col ? fix_output_extensive(f, s->start + k * s->skip, in->col)
                              : fix_output_extensive(f, s->start + k * s->skip, 0);
        *ext = *ext == -2 ? e : *ext == e ? e : -1;
    }
    if (*ext == -2)
        *ext = 0;
    return rows;
}

static void sl_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, WHO " expects Nstart Nstop Nskip and at least one input, got %d arguments",
                 argc);
    struct slice *s = gr_calloc(g, 1, sizeof *s);
    c->data = s;
    s->start = arg_int(g, argv[0], "Nstart");
    s->stop = arg_int(g, argv[1], "Nstop");
    s->skip = arg_int(g, argv[2], "Nskip");
    if (s->start < 1)
        gr_error(g, WHO ": invalid nstart value %d < 1", s->start);
    if (s->stop < s->start)
        gr_error(g, WHO ": invalid nstop value %d < %d", s->stop, s->start);
    if (s->skip < 1)
        gr_error(g, WHO ": invalid nskip value < 1: %d", s->skip);
    s->n = (s->stop - s->start) / s->skip;
    s->nin = argc - 3;
    s->in = gr_calloc(g, (size_t)s->nin, sizeof *s->in);
    int ext_any = 0;
    for (int m = 0; m < s->nin; m++) {
        const char *a = argv[3 + m];
        struct slice_in *in = &s->in[m];
        int index = 0, col = 0;
        if (!strncmp(a, "v_", 2))
            gr_error(g, WHO ": variable %s is not a vector-style variable (gravel has none)",
                     a + 2);
        if ((a[0] != 'c' && a[0] != 'f') || a[1] != '_' ||
            !ref_parse(a, a[0], in->id, &index, &col) || col)
            gr_error(g, WHO ": illegal input '%.64s' (c_ID, c_ID[I], f_ID, f_ID[I])", a);
        in->kind = a[0];
        in->col = index;
        int ext;
        const int rows = input_rows(g, s, m, &ext);
        if (rows > 0 && s->stop > rows) /* 0: known at its first evaluation (rdf, chunks) */
            gr_error(g, WHO ": %s %s %s is accessed out-of-range (Nstop %d, %d rows)",
                     in->kind == 'c' ? "compute" : "fix", in->id, in->col ? "array" : "vector",
                     s->stop, rows);
        if (s->nin == 1 && ext < 0)
            gr_error(g, WHO ": the elements of %s mix extensive and intensive values (not "
                        "supported)", a);
        ext_any |= ext != 0;
    }
    if (s->nin == 1) {
        c->vector_flag = 1;
        c->size_vector = s->n;
        c->extvector = ext_any;
    } else {
        c->array_flag = 1;
        c->size_array_cols = s->nin;
        c->extarray = ext_any;
    }
}

/* input m's elements into out[k stride] */
static void take(struct gravel *g, const struct slice *s, int m, double *out, int stride)
{
    const struct slice_in *in = &s->in[m];
    int ext;
    input_rows(g, s, m, &ext); /* still there */
    if (in->kind == 'c') {
        struct compute *cc = compute_find(g, in->id);
        const double *v = in->col ? compute_array(g, cc) : compute_vector(g, cc);
        const int rows = in->col ? cc->size_array_rows : cc->size_vector;
        if (s->stop > rows)
            gr_error(g, WHO ": compute %s %s is accessed out-of-range (Nstop %d, %d rows)",
                     in->id, in->col ? "array" : "vector", s->stop, rows);
        const int w = in->col ? cc->size_array_cols : 1;
        for (int k = 0; k < s->n; k++)
            out[(size_t)k * stride] =
                v[(size_t)(s->start + k * s->skip - 1) * w + (in->col ? in->col - 1 : 0)];
        return;
    }
    struct fix *f = fix_find(g, in->id);
    if (f->global_freq > 1 && g->step % f->global_freq)
        gr_error(g, WHO ": fix %s used in compute slice not computed at compatible time "
                    "(step %lld, every %d)", in->id, (long long)g->step, f->global_freq);
    for (int k = 0; k < s->n; k++)
        out[(size_t)k * stride] =
            fix_output(g, f, s->start + k * s->skip, in->col, 0, WHO);
}

static void sl_vector(struct gravel *g, struct compute *c)
{
    take(g, c->data, 0, c->vector, 1);
}

static void sl_array(struct gravel *g, struct compute *c)
{
    const struct slice *s = c->data;
    double *out = compute_array_rows(g, c, s->n);
    for (int m = 0; m < s->nin; m++)
        take(g, s, m, out + m, s->nin);
}

/* several ranks: its inputs evaluated on every rank's atoms gathered, as
 * fix ave/time's */
const struct compute_style compute_style_slice = {
    .name = "slice",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = sl_create,
    .vector = sl_vector,
    .array = sl_array,
    .destroy = sl_destroy,
};
