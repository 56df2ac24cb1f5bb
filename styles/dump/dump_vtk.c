/* dump_vtk.c - `dump ID group vtk N file`: legacy VTK POLYDATA snapshots
 * that ParaView and VTK's own readers open.
 *
 * One snapshot per file (legacy VTK holds one dataset): use '*' in the name
 * for a series (ParaView groups file.*.vtk into a time series); without '*'
 * the file is rewritten at each snapshot and holds the latest one.
 *
 * Layout: "# vtk DataFile Version 3.0", a title with dump ID, step and time,
 * ASCII or BINARY (`dump_modify binary yes`; binary data is big-endian as the
 * legacy format requires), DATASET POLYDATA with dataset field data TIME
 * (simulated time) and CYCLE (step), POINTS (double), one VERTICES cell per
 * particle, and POINT_DATA field arrays: id (int, or vtktypeint64 when a tag
 * exceeds 2^31-1), type (int), radius, mass (double), velocity, omega, force
 * (3-component double). Atoms go in host order, or by tag with
 * `dump_modify sort id`. */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "dump.h"
#include "error.h"

struct vtk {
    double *buf;                /* scratch for binary blocks, 3 per atom */
    int cap;
    int32_t *ibuf;              /* scratch for binary int blocks, 2 per atom */
    int icap;
};

static void vtk_create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "dump vtk takes no arguments after the file name, got %d", argc);
    d->data = gr_calloc(g, 1, sizeof(struct vtk));
}

static void vtk_destroy(struct dump *d)
{
    struct vtk *v = d->data;
    if (v) {
        free(v->buf);
        free(v->ibuf);
    }
    free(v);
    d->data = NULL;
}

static double *scratch(struct gravel *g, struct dump *d, int n)
{
    struct vtk *v = d->data;
    if (v->cap < 3 * n || !v->buf) {
        int cap = 3 * n > 48 ? 3 * n : 48;
        v->buf = gr_realloc(g, v->buf, (size_t)cap * sizeof(double));
        v->cap = cap;
    }
    return v->buf;
}

static int32_t *iscratch(struct gravel *g, struct dump *d, int n)
{
    struct vtk *v = d->data;
    if (v->icap < 2 * n || !v->ibuf) {
        int cap = 2 * n > 32 ? 2 * n : 32;
        v->ibuf = gr_realloc(g, v->ibuf, (size_t)cap * sizeof(int32_t));
        v->icap = cap;
    }
    return v->ibuf;
}

static void write_be_int64(FILE *fp, int64_t x)
{
    unsigned char b[8];
    for (int k = 0; k < 8; k++)
        b[k] = (unsigned char)((uint64_t)x >> (8 * (7 - k)));
    fwrite(b, 1, 8, fp);
}

/* One array of `comp` doubles per atom, gathered from src (stride `comp`). */
static void write_doubles(struct gravel *g, struct dump *d, FILE *fp, const double *src,
                          int comp, const int *idx, int n)
{
    if (d->binary) {
        double *b = scratch(g, d, n);
        for (int k = 0; k < n; k++)
            for (int c = 0; c < comp; c++)
                b[(size_t)comp * k + c] = src[(size_t)comp * idx[k] + c];
        dump_write_be_doubles(fp, b, (size_t)comp * n);
        fputc('\n', fp);
        return;
    }
    for (int k = 0; k < n; k++) {
        const double *p = src + (size_t)comp * idx[k];
        if (comp == 3)
            fprintf(fp, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
        else
            fprintf(fp, "%.17g\n", p[0]);
    }
}

static void vtk_write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    const struct atoms *a = &g->atoms;
    int bin = d->binary;
    int64_t maxtag = 0;
    for (int k = 0; k < n; k++)
        if (a->tag[idx[k]] > maxtag)
            maxtag = a->tag[idx[k]];
    int wide = maxtag > INT32_MAX;

    char title[GR_NAMELEN + 96];
    snprintf(title, sizeof title, "gravel dump %s step %lld time %.17g", d->id,
             (long long)g->step, g->time);
    dump_vtk_polydata_head(g, d, fp, title);

    fprintf(fp, "POINTS %d double\n", n);
    write_doubles(g, d, fp, a->x, 3, idx, n);

    fprintf(fp, "VERTICES %d %d\n", n, 2 * n);
    if (bin) {
        int32_t *b = iscratch(g, d, n);
        for (int k = 0; k < n; k++) {
            b[2 * k] = 1;
            b[2 * k + 1] = k;
        }
        dump_write_be_int32(fp, b, 2 * (size_t)n);
        fputc('\n', fp);
    } else {
        for (int k = 0; k < n; k++)
            fprintf(fp, "1 %d\n", k);
    }

    if (n == 0)
        return; /* VTK's reader rejects empty attribute arrays */
    fprintf(fp, "POINT_DATA %d\nFIELD FieldData 7\n", n);

    fprintf(fp, "id 1 %d %s\n", n, wide ? "vtktypeint64" : "int");
    if (bin && wide) {
        for (int k = 0; k < n; k++)
            write_be_int64(fp, a->tag[idx[k]]);
        fputc('\n', fp);
    } else if (bin) {
        int32_t *b = iscratch(g, d, n);
        for (int k = 0; k < n; k++)
            b[k] = (int32_t)a->tag[idx[k]];
        dump_write_be_int32(fp, b, (size_t)n);
        fputc('\n', fp);
    } else {
        for (int k = 0; k < n; k++)
            fprintf(fp, "%lld\n", (long long)a->tag[idx[k]]);
    }

    fprintf(fp, "type 1 %d int\n", n);
    if (bin) {
        int32_t *b = iscratch(g, d, n);
        for (int k = 0; k < n; k++)
            b[k] = a->type[idx[k]];
        dump_write_be_int32(fp, b, (size_t)n);
        fputc('\n', fp);
    } else {
        for (int k = 0; k < n; k++)
            fprintf(fp, "%d\n", a->type[idx[k]]);
    }

    fprintf(fp, "radius 1 %d double\n", n);
    write_doubles(g, d, fp, a->radius, 1, idx, n);
    fprintf(fp, "mass 1 %d double\n", n);
    write_doubles(g, d, fp, a->rmass, 1, idx, n);
    fprintf(fp, "velocity 3 %d double\n", n);
    write_doubles(g, d, fp, a->v, 3, idx, n);
    fprintf(fp, "omega 3 %d double\n", n);
    write_doubles(g, d, fp, a->omega, 3, idx, n);
    fprintf(fp, "force 3 %d double\n", n);
    write_doubles(g, d, fp, a->f, 3, idx, n);
}

const struct dump_style dump_style_vtk = {
    .name = "vtk",
    .append = 0,
    .create = vtk_create,
    .modify = dump_vtk_binary,
    .write = vtk_write,
    .destroy = vtk_destroy,
};
