/* dump_local.c - `dump ID group local N file value1 value2 ...`: LAMMPS's
 * dump local, the rows of local computes (compute pair/local,
 * property/local), one line per row:
 *   ITEM: TIMESTEP / step / ITEM: NUMBER OF ENTRIES / rows /
 *   ITEM: BOX BOUNDS (as dump custom) / three "lo hi" lines /
 *   ITEM: ENTRIES value1 value2 ... / rows, each value followed by a space
 * (LAMMPS's layout, trailing space included). Values: c_ID (a local
 * compute's vector), c_ID[N] (column N of its local array), index (the row
 * number, 1-based). Every compute named must give the same number of rows
 * (LAMMPS: "Dump local count is not consistent across input fields"). The
 * group is not used, as in LAMMPS. Formats: "%g" for values, "%d" for
 * index; dump_modify format line|int|float|N "fmt" and format none as dump
 * custom, dump_modify label WORD replaces ENTRIES in both header lines. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "compute.h"
#include "dump.h"
#include "dump_custom.h"
#include "error.h"
#include "thermo.h"

struct lcol {
    char name[GR_NAMELEN];
    int is_index;
    char cid[GR_NAMELEN];
    int index;                  /* c_ID[N]: N; 0: the local vector */
    char fmt[80];
};

struct local {
    int n;
    struct lcol *col;
    struct dump_formats fmt;
    char label[GR_NAMELEN];
    const double **data;        /* [n] scratch of one snapshot: column i's first value */
    int *stride;                /* [n] its row stride */
};

static void local_destroy(struct dump *d)
{
    struct local *l = d->data;
    if (!l)
        return;
    free(l->col);
    free(l->data);
    free(l->stride);
    dump_formats_free(&l->fmt);
    free(l);
    d->data = NULL;
}

static void local_create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "dump local needs at least one value after the file name (c_ID, c_ID[N], "
                    "index)");
    struct local *l = gr_calloc(g, 1, sizeof *l);
    d->data = l;
    snprintf(l->label, sizeof l->label, "ENTRIES");
    l->col = gr_calloc(g, (size_t)argc, sizeof *l->col);
    l->data = gr_calloc(g, (size_t)argc, sizeof *l->data);
    l->stride = gr_calloc(g, (size_t)argc, sizeof *l->stride);
    l->n = argc;
    l->fmt.col = gr_calloc(g, (size_t)argc, sizeof *l->fmt.col);
    l->fmt.n = argc;
    int ncompute = 0;
    for (int i = 0; i < argc; i++) {
        struct lcol *c = &l->col[i];
        const char *s = argv[i];
        if (strlen(s) >= GR_NAMELEN)
            gr_error(g, "dump local value '%.64s...' is too long", s);
        snprintf(c->name, sizeof c->name, "%s", s);
        if (!strcmp(s, "index")) {
            c->is_index = 1;
            continue;
        }
        if (!strncmp(s, "f_", 2))
            gr_error(g, "dump local: fix values ('%.64s') are not supported; use local computes",
                     s);
        if (strncmp(s, "c_", 2) || !compute_parse_ref(s, c->cid, &c->index))
            gr_error(g, "dump local: invalid value '%.64s' (c_ID, c_ID[N] or index)", s);
        compute_local_check(g, c->cid, c->index, "dump local");
        ncompute++;
    }
    if (ncompute == 0)
        gr_error(g, "dump local needs at least one compute value (c_ID or c_ID[N])");
}

static int local_is_int(const void *ctx, int k)
{
    return ((const struct local *)ctx)->col[k].is_index;
}

static const char *local_name(const void *ctx, int k)
{
    return ((const struct local *)ctx)->col[k].name;
}

/* dump_modify label WORD, and format as dump custom */
static int local_modify(struct gravel *g, struct dump *d, int argc, char **argv, int i,
                        int apply)
{
    struct local *l = d->data;
    if (!strcmp(argv[i], "label")) {
        arg_need(g, argc, i, 1, "label");
        const char *w = argv[i + 1];
        if (!w[0] || strlen(w) >= GR_NAMELEN || strpbrk(w, " \t\n"))
            gr_error(g, "dump_modify label must be one word of at most %d characters",
                     GR_NAMELEN - 1);
        if (apply)
            snprintf(l->label, sizeof l->label, "%s", w);
        return 2;
    }
    const struct dump_columns dc = {l, local_is_int, local_name, "values"};
    return dump_formats_modify(g, &l->fmt, &dc, argc, argv, i, apply);
}

static void local_init(struct gravel *g, struct dump *d)
{
    struct local *l = d->data;
    char line[4100] = "";
    char *save = NULL, *word = NULL;
    if (l->fmt.line) {
        snprintf(line, sizeof line, "%s", l->fmt.line);
        word = strtok_r(line, " \t", &save);
    }
    for (int i = 0; i < l->n; i++) {
        struct lcol *c = &l->col[i];
        if (!c->is_index)
            compute_local_check(g, c->cid, c->index, "dump local");
        const char *f = l->fmt.col[i];
        if (!f)
            f = c->is_index ? l->fmt.fint : l->fmt.ffloat;
        if (!f && l->fmt.line) {
            if (!word)
                gr_error(g, "dump %s: dump_modify format line has fewer words than the %d "
                            "values", d->id, l->n);
            f = word;
        }
        if (f) {
            const char *bad = output_format_fix(f, c->is_index, c->fmt);
            if (bad)
                gr_error(g, "dump %s: format '%.64s' for %s %s", d->id, f, c->name, bad);
        } else {
            snprintf(c->fmt, sizeof c->fmt, "%s", c->is_index ? "%lld" : "%g");
        }
        if (word)
            word = strtok_r(NULL, " \t", &save);
    }
}

static void local_write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    (void)idx;
    (void)n;
    struct local *l = d->data;
    local_init(g, d);
    /* each compute once per snapshot: rows of compute k in data[k] */
    const double **data = l->data;
    int *stride = l->stride;
    int rows = -1;
    for (int i = 0; i < l->n; i++) {
        struct lcol *c = &l->col[i];
        if (c->is_index)
            continue;
        int same = -1;
        for (int k = 0; k < i; k++)
            if (!l->col[k].is_index && !strcmp(l->col[k].cid, c->cid))
                same = k;
        struct compute *cp = compute_find(g, c->cid);
        int cols = cp->size_local_cols > 0 ? cp->size_local_cols : 1;
        const double *base;
        int r;
        if (same >= 0) {
            base = data[same] - (l->col[same].index > 0 ? l->col[same].index - 1 : 0);
            r = cp->size_local_rows;
        } else {
            r = compute_local(g, cp, &base);
        }
        if (rows >= 0 && r != rows)
            gr_error(g, "dump %s: local computes give different numbers of rows (%d and %d "
                        "for %s)", d->id, rows, r, c->name);
        rows = r;
        data[i] = base + (c->index > 0 ? c->index - 1 : 0);
        stride[i] = cols;
    }
    dump_box_header(g, fp, l->label, rows);
    fprintf(fp, "ITEM: %s ", l->label);
    for (int i = 0; i < l->n; i++)
        fprintf(fp, "%s ", l->col[i].name);
    fprintf(fp, "\n");
    for (int r = 0; r < rows; r++) {
        for (int i = 0; i < l->n; i++) {
            const struct lcol *c = &l->col[i];
            if (c->is_index)
                fprintf(fp, c->fmt, (long long)r + 1);
            else
                fprintf(fp, c->fmt, data[i][(size_t)r * stride[i]]);
            fputc(' ', fp);
        }
        fputc('\n', fp);
    }
}

const struct dump_style dump_style_local = {
    .name = "local",
    .append = 1,
    .create = local_create,
    .modify = local_modify,
    .init = local_init,
    .write = local_write,
    .destroy = local_destroy,
};
