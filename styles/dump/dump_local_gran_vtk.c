/* dump_local_gran_vtk.c - LIGGGHTS's `dump ID group local/gran/vtk N
 * file.vtk CID`: the contacts of compute pair/gran/local CID as lines, for
 * ParaView (its Tube filter draws force chains), written by gravel's own
 * code as legacy VTK 3.0 POLYDATA (LIGGGHTS 3.8 writes the same dataset
 * through the VTK library). Per contact: the points x_i and x_j and the line
 * between them; with the compute's contactPoint also that point and the lines
 * from x_i and from x_j to it (three cells, each carrying the contact's
 * values). Cell arrays, in LIGGGHTS's order, of the compute's keywords: vel1
 * vel2 (vel), id1 id2 (id, as doubles), force, force_normal,
 * force_tangential, torque, torque_normal, torque_tangential, contact_area,
 * delta; the history is not written (as LIGGGHTS). The compute must write pos.
 * Dataset field data TIME and CYCLE. `dump_modify binary yes`: big-endian
 * binary blocks. The group is not used; XML extensions are refused. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "compute.h"
#include "compute_pair_gran_local.h"
#include "dump.h"
#include "error.h"

struct lgv {
    char cid[GR_NAMELEN];
    double *buf;
    size_t cap;
};

/* The cell arrays: name, the compute's keyword, its column within it, width */
static const struct {
    const char *name;
    int kw, off, comp;
} arrays[] = {
    {"vel1", PG_VEL, 0, 3}, {"vel2", PG_VEL, 3, 3}, {"id1", PG_ID, 0, 1}, {"id2", PG_ID, 1, 1},
    {"force", PG_F, 0, 3}, {"force_normal", PG_FN, 0, 3}, {"force_tangential", PG_FT, 0, 3},
    {"torque", PG_T, 0, 3}, {"torque_normal", PG_TN, 0, 3},
    {"torque_tangential", PG_TT, 0, 3}, {"contact_area", PG_AREA, 0, 1},
    {"delta", PG_DELTA, 0, 1},
};
#define NARRAYS (int)(sizeof arrays / sizeof arrays[0])

static void lgv_create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    dump_vtk_check_name(g, d);
    if (argc != 1)
        gr_error(g, "dump local/gran/vtk: expected the ID of a compute pair/gran/local after the "
                    "file name, got %d words", argc);
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, "dump local/gran/vtk: compute ID '%.64s...' is too long", argv[0]);
    struct lgv *l = gr_calloc(g, 1, sizeof *l);
    d->data = l;
    snprintf(l->cid, sizeof l->cid, "%s", argv[0]);
}

static void lgv_destroy(struct dump *d)
{
    struct lgv *l = d->data;
    if (l)
        free(l->buf);
    free(l);
    d->data = NULL;
}

/* The compute and its columns (errors name the dump). */
static struct compute *lgv_compute(struct gravel *g, struct dump *d, int at[PG_N])
{
    struct lgv *l = d->data;
    struct compute *c = compute_find(g, l->cid);
    if (!c || !pgl_columns(c, at))
        gr_error(g, "dump %s: local/gran/vtk requires a valid ID of a compute pair/gran/local "
                    "('%s' is %s)", d->id, l->cid, c ? "another style" : "not defined");
    if (at[PG_POS] < 0)
        gr_error(g, "dump %s: local/gran/vtk requires a compute pair/gran/local that writes the "
                    "positions (pos)", d->id);
    return c;
}

static void lgv_init(struct gravel *g, struct dump *d)
{
    int at[PG_N];
    lgv_compute(g, d, at);
}

/* n values v, as doubles (ASCII or big-endian binary), then a newline */
static void put_doubles(struct gravel *g, struct dump *d, FILE *fp, const double *v, size_t n,
                        int per_line)
{
    if (d->binary) {
        dump_write_be_doubles(fp, v, n);
        fputc('\n', fp);
        return;
    }
    (void)g;
    for (size_t k = 0; k < n; k++)
        fprintf(fp, "%.17g%c", v[k], (k + 1) % (size_t)per_line == 0 || k + 1 == n ? '\n' : ' ');
}

static double *room(struct gravel *g, struct lgv *l, size_t n)
{
    if (l->cap < n) {
        l->cap = n;
        l->buf = gr_realloc(g, l->buf, n * sizeof *l->buf);
    }
    return l->buf;
}

static void lgv_write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    (void)idx;
    (void)n;
    struct lgv *l = d->data;
    int at[PG_N];
    struct compute *c = lgv_compute(g, d, at);
    const double *rows;
    const int nr = compute_local(g, c, &rows);
    const int ncol = c->size_local_cols;
    const int cp = at[PG_CP] >= 0, per = cp ? 3 : 2; /* points per contact */
    const int cells = cp ? 3 : 1;                  /* lines per contact */
    const int bin = d->binary;
    char title[2 * GR_NAMELEN + 96];
    snprintf(title, sizeof title, "gravel dump %s contacts of compute %s step %lld time %.17g",
             d->id, l->cid, (long long)g->step, g->time);
    dump_vtk_polydata_head(g, d, fp, title);
    const size_t np = (size_t)nr * per, nc = (size_t)nr * cells;
    fprintf(fp, "POINTS %zu double\n", np);
    double *b = room(g, l, 3 * np + 1);
    for (int r = 0; r < nr; r++) {
        const double *row = rows + (size_t)r * ncol;
        memcpy(b + 3 * per * (size_t)r, row + at[PG_POS], 6 * sizeof *b);
        if (cp)
            memcpy(b + 3 * per * (size_t)r + 6, row + at[PG_CP], 3 * sizeof *b);
    }
    if (np > 0)
        put_doubles(g, d, fp, b, 3 * np, 3);
    fprintf(fp, "LINES %zu %zu\n", nc, 3 * nc);
    for (size_t r = 0; r < (size_t)nr; r++) {
        const int32_t p = (int32_t)(per * r);
        const int32_t line[9] = {2, p, p + 1, 2, p, p + 2, 2, p + 1, p + 2};
        if (bin)
            dump_write_be_int32(fp, line, 3 * (size_t)cells);
        else
            for (int k = 0; k < cells; k++)
                fprintf(fp, "2 %d %d\n", line[3 * k + 1], line[3 * k + 2]);
    }
    if (bin && nc > 0)
        fputc('\n', fp);
    if (nr == 0)
        return; /* VTK's reader rejects empty attribute arrays */
    int narr = 0;
    for (int a = 0; a < NARRAYS; a++)
        narr += at[arrays[a].kw] >= 0;
    fprintf(fp, "CELL_DATA %zu\nFIELD FieldData %d\n", nc, narr);
    for (int a = 0; a < NARRAYS; a++) {
        if (at[arrays[a].kw] < 0)
            continue;
        const int comp = arrays[a].comp, col = at[arrays[a].kw] + arrays[a].off;
        fprintf(fp, "%s %d %zu double\n", arrays[a].name, comp, nc);
        b = room(g, l, (size_t)comp * nc + 1);
        for (size_t r = 0; r < (size_t)nr; r++)
            for (int k = 0; k < cells; k++) /* each of the contact's cells */
                memcpy(b + ((size_t)cells * r + k) * comp, rows + r * ncol + col,
                       (size_t)comp * sizeof *b);
        put_doubles(g, d, fp, b, (size_t)comp * nc, comp);
    }
}

const struct dump_style dump_style_local_gran_vtk = {
    .name = "local/gran/vtk",
    .append = 0,
    .create = lgv_create,
    .modify = dump_vtk_binary,
    .init = lgv_init,
    .write = lgv_write,
    .destroy = lgv_destroy,
};
