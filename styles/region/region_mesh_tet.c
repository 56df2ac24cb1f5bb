/* region_mesh_tet.c - LIGGGHTS's region mesh/tet: the union of the
 * tetrahedra of an ASCII legacy VTK unstructured grid.
 *
 *   region ID mesh/tet file F scale s move dx dy dz rotate ax ay az [side] units box
 *
 * Each vertex is read, shifted by (dx, dy, dz), scaled by s, then rotated by
 * Rz(az) Ry(ay) Rx(ax) (degrees), as LIGGGHTS's input_mesh_tet.cpp. Only
 * cells of VTK type 10 (tetrahedra) are kept; a file with other cells is
 * accepted with LIGGGHTS's warning. A tetrahedron of negative orientation
 * gets its nodes 0 and 3 swapped. A point is inside when it lies inside the
 * vertices' bounding box and strictly inside one tetrahedron: the four
 * volumes of the point with three of the nodes are all > 0 (LIGGGHTS's
 * is_inside_tet, in its operation order), so a point on a face of a
 * tetrahedron, inner faces included, is outside, unlike the other region
 * styles whose surfaces are inside. LIGGGHTS's errors: `units lattice`
 * (its default) is refused, every vertex must lie in the box. */
#include <math.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fileio.h"
#include "region.h"

#define TET_MAXLINE (1 << 20)
#define TET_MAXWORDS 192 /* values on one line (64 points) */

struct tet_mesh {
    int n;
    double (*node)[4][3];
};

/* (v3 - v1) x (v2 - v1) . (v0 - v1) / 6: LIGGGHTS's volume_of_tet */
static double tet_volume(const double *v0, const double *v1, const double *v2,
                         const double *v3)
{
    double a[3], b[3], c[3];
    for (int k = 0; k < 3; k++) {
        a[k] = v3[k] - v1[k];
        b[k] = v2[k] - v1[k];
        c[k] = v0[k] - v1[k];
    }
    double cp0 = a[1] * b[2] - a[2] * b[1];
    double cp1 = -a[0] * b[2] + a[2] * b[0];
    double cp2 = a[0] * b[1] - a[1] * b[0];
    return (cp0 * c[0] + cp1 * c[1] + cp2 * c[2]) / 6.;
}

/* Split line at blanks into at most max words; '#' starts a comment. */
static int split(char *line, char **w, int max)
{
    char *h = strchr(line, '#');
    if (h)
        *h = '\0';
    int n = 0;
    for (char *t = strtok(line, " \t\r\n"); t; t = strtok(NULL, " \t\r\n"))
        if (n < max)
            w[n++] = t;
        else
            return max + 1;
    return n;
}

static long file_int(struct gravel *g, const char *file, int lno, const char *s, long lo,
                     long hi, const char *what)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (end == s || *end || v < lo || v > hi)
        gr_error(g, "region mesh/tet: %s line %d: %s must be an integer in %ld..%ld, got '%.32s'",
                 file, lno, what, lo, hi, s);
    return v;
}

static double file_double(struct gravel *g, const char *file, int lno, const char *s)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v))
        gr_error(g, "region mesh/tet: %s line %d: expected a coordinate, got '%.32s'", file,
                 lno, s);
    return v;
}

/* v rotated by Rz(az) Ry(ay) Rx(ax) of the angles' cosines c and sines s,
 * each component summed in LIGGGHTS's order (the same bits as its mesh). */
static void rotate(const double c[3], const double s[3], const double v[3], double out[3])
{
    out[0] = v[0] * c[1] * c[2] + v[1] * (c[2] * s[0] * s[1] - c[0] * s[2]) +
             v[2] * (c[0] * c[2] * s[1] + s[0] * s[2]);
    out[1] = v[0] * c[1] * s[2] + v[2] * (-c[2] * s[0] + c[0] * s[1] * s[2]) +
             v[1] * (c[0] * c[2] + s[0] * s[1] * s[2]);
    out[2] = v[2] * c[0] * c[1] + v[1] * c[1] * s[0] - v[0] * s[1];
}

struct vtk_read {
    double (*pt)[3];
    long npt, ncell, ntet;
    int (*cell)[4]; /* -1 in [0]: not a tetrahedron */
    int other;      /* cells of other types were dropped */
    FILE *fp;       /* open file and line buffer: freed by the caller on error */
    char *buf;
};

/* Parse the VTK file into rd (points transformed by the region's keywords). */
static void read_vtk(struct gravel *g, const char *file, const double off[3], double scale,
                     const double c[3], const double s[3], struct vtk_read *rd)
{
    const char *why = NULL;
    FILE *fp = rd->fp = fio_open_read(file, 0, &why);
    if (!fp)
        gr_error(g, "region mesh/tet: cannot open mesh file %s: %s", file, why);
    char *w[TET_MAXWORDS];
    size_t cap = 0;
    ssize_t len;
    int lno = 0, item = 0; /* item: non-empty lines so far (LIGGGHTS's iLine) */
    enum { HEAD, POINTS, CELLS_HEAD, CELLS, TYPES_HEAD, TYPES, DONE } sec = HEAD;
    long ip = 0, ic = 0;
    while ((len = fio_getline(fp, &rd->buf, &cap, TET_MAXLINE)) >= 0) {
        lno++;
        int nw = split(rd->buf, w, TET_MAXWORDS);
        if (nw > TET_MAXWORDS)
            gr_error(g, "region mesh/tet: %s line %d: more than %d values on a line", file, lno,
                     TET_MAXWORDS);
        if (nw == 0)
            continue;
        item++;
        if (sec == HEAD) {
            if (item == 2 && strcmp(w[0], "ASCII"))
                gr_error(g, "region mesh/tet: %s line %d: expecting an ASCII VTK mesh file",
                         file, lno);
            if (item == 3 && (nw < 2 || strcmp(w[0], "DATASET") ||
                              strcmp(w[1], "UNSTRUCTURED_GRID")))
                gr_error(g, "region mesh/tet: %s line %d: expecting 'DATASET "
                            "UNSTRUCTURED_GRID'", file, lno);
            if (item == 4) {
                if (strcmp(w[0], "POINTS") || nw < 2)
                    gr_error(g, "region mesh/tet: %s line %d: expecting the 'POINTS' section",
                             file, lno);
                rd->npt = file_int(g, file, lno, w[1], 1, 100000000, "the number of points");
                rd->pt = gr_malloc(g, (size_t)rd->npt * sizeof *rd->pt);
                sec = POINTS;
            }
        } else if (sec == POINTS) {
            if (nw % 3)
                gr_error(g, "region mesh/tet: %s line %d: expecting 3 values for each point",
                         file, lno);
            for (int p = 0; p < nw; p += 3) {
                if (ip == rd->npt)
                    gr_error(g, "region mesh/tet: %s line %d: more points than the %ld "
                                "announced", file, lno, rd->npt);
                double v[3];
                for (int k = 0; k < 3; k++)
                    v[k] = (file_double(g, file, lno, w[p + k]) + off[k]) * scale;
                rotate(c, s, v, rd->pt[ip]);
                ip++;
            }
            if (ip == rd->npt)
                sec = CELLS_HEAD;
        } else if (sec == CELLS_HEAD) {
            if (strcmp(w[0], "CELLS") || nw < 2)
                gr_error(g, "region mesh/tet: %s line %d: expecting the 'CELLS' section", file,
                         lno);
            rd->ncell = file_int(g, file, lno, w[1], 1, 100000000, "the number of cells");
            rd->cell = gr_malloc(g, (size_t)rd->ncell * sizeof *rd->cell);
            sec = CELLS;
        } else if (sec == CELLS) {
            rd->cell[ic][0] = -1;
            if (nw == 5)
                for (int j = 0; j < 4; j++)
                    rd->cell[ic][j] = (int)file_int(g, file, lno, w[1 + j], 0, rd->npt - 1,
                                                    "a point index");
            if (++ic == rd->ncell)
                sec = TYPES_HEAD;
        } else if (sec == TYPES_HEAD) {
            if (strcmp(w[0], "CELL_TYPES") || nw < 2)
                gr_error(g, "region mesh/tet: %s line %d: expecting the 'CELL_TYPES' section",
                         file, lno);
            if (file_int(g, file, lno, w[1], 0, 100000000, "the number of cell types") !=
                rd->ncell)
                gr_error(g, "region mesh/tet: %s line %d: CELL_TYPES %s does not match CELLS "
                            "%ld", file, lno, w[1], rd->ncell);
            ic = 0;
            sec = TYPES;
        } else if (sec == TYPES) {
            if (strcmp(w[0], "10")) {
                rd->cell[ic][0] = -1;
                rd->other = 1;
            } else if (rd->cell[ic][0] < 0) {
                gr_error(g, "region mesh/tet: %s line %d: cell %ld is a tetrahedron (type 10) "
                            "without 4 point indices", file, lno, ic);
            } else {
                rd->ntet++;
            }
            if (++ic == rd->ncell)
                sec = DONE;
        }
    }
    int err = len == FIO_ERR;
    free(rd->buf);
    rd->buf = NULL;
    fclose(fp);
    rd->fp = NULL;
    if (err)
        gr_error(g, "region mesh/tet: cannot read mesh file %s", file);
    if (sec != DONE)
        gr_error(g, "region mesh/tet: mesh file %s ends before its %s section is complete", file,
                 sec <= POINTS ? "POINTS" : sec <= CELLS ? "CELLS" : "CELL_TYPES");
}

static int tet_parse(struct gravel *g, struct region *r, int n, char **a, const double sc[3])
{
    (void)n;
    (void)sc;
    if (r->lattice_units)
        gr_error(g, "region mesh/tet: lattice scaling is not implemented for region mesh/tet "
                    "(LIGGGHTS's rule), use 'units box'");
    static const char *kw[3] = {"file", "scale", "move"};
    static const int at[3] = {0, 2, 4};
    for (int k = 0; k < 3; k++)
        if (strcmp(a[at[k]], kw[k]))
            gr_error(g, "region mesh/tet: expected keyword '%s', got '%.32s'", kw[k], a[at[k]]);
    if (strcmp(a[8], "rotate"))
        gr_error(g, "region mesh/tet: expected keyword 'rotate', got '%.32s'", a[8]);
    if (!g->dom.box_exists)
        gr_error(g, "region mesh/tet: cannot load a mesh before the simulation box is defined");
    double scale = arg_double(g, a[3], "scale");
    if (!(scale > 0))
        gr_error(g, "region mesh/tet: scale must be positive, got %s", a[3]);
    double off[3], c[3], s[3];
    for (int k = 0; k < 3; k++) {
        off[k] = arg_double(g, a[5 + k], "move offset");
        double phi = arg_double(g, a[9 + k], "rotate angle") * M_PI / 180.;
        c[k] = cos(phi);
        s[k] = sin(phi);
    }
    struct vtk_read rd = {0};
    /* free the read buffers if the file is bad */
    jmp_buf *outer = g->err.jmp, here;
    g->err.jmp = &here;
    if (setjmp(here)) {
        g->err.jmp = outer;
        if (rd.fp)
            fclose(rd.fp);
        free(rd.buf);
        free(rd.pt);
        free(rd.cell);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    read_vtk(g, a[1], off, scale, c, s, &rd);
    const struct domain *d = &g->dom;
    for (long i = 0; i < rd.npt; i++)
        for (int k = 0; k < 3; k++)
            if (rd.pt[i][k] < d->lo[k] || rd.pt[i][k] > d->hi[k])
                gr_error(g, "region mesh/tet: mesh file %s is incompatible with the simulation "
                            "box: vertex %ld (%g %g %g) lies outside it", a[1], i, rd.pt[i][0],
                         rd.pt[i][1], rd.pt[i][2]);
    if (rd.ntet == 0)
        gr_error(g, "region mesh/tet: mesh file %s contains no tetrahedron (VTK cell type 10)",
                 a[1]);
    struct tet_mesh *m = gr_malloc(g, sizeof *m);
    m->n = 0;
    m->node = malloc((size_t)rd.ntet * sizeof *m->node);
    if (!m->node) {
        free(m);
        gr_error(g, "region mesh/tet: out of memory for %ld tetrahedra", rd.ntet);
    }
    g->err.jmp = outer;
    for (long c = 0; c < rd.ncell; c++) {
        if (rd.cell[c][0] < 0)
            continue;
        double (*t)[3] = m->node[m->n++];
        for (int j = 0; j < 4; j++)
            memcpy(t[j], rd.pt[rd.cell[c][j]], sizeof t[j]);
        if (tet_volume(t[0], t[1], t[2], t[3]) < 0.) { /* LIGGGHTS flips nodes 0 and 3 */
            double s[3];
            memcpy(s, t[0], sizeof s);
            memcpy(t[0], t[3], sizeof s);
            memcpy(t[3], s, sizeof s);
        }
    }
    free(rd.pt);
    free(rd.cell);
    r->data = m;
    r->bbox = 1;
    for (int k = 0; k < 3; k++) {
        r->bbox_lo[k] = INFINITY;
        r->bbox_hi[k] = -INFINITY;
    }
    for (int i = 0; i < m->n; i++)
        for (int j = 0; j < 4; j++)
            for (int k = 0; k < 3; k++) {
                r->bbox_lo[k] = fmin(r->bbox_lo[k], m->node[i][j][k]);
                r->bbox_hi[k] = fmax(r->bbox_hi[k], m->node[i][j][k]);
            }
    if (rd.other)
        gr_warn(g, "region mesh/tet: %s contains cells other than tetrahedra; only its %d "
                   "tetrahedra are used (as LIGGGHTS)", a[1], m->n);
    return 12;
}

static int tet_inside(const struct region *r, const double x[3])
{
    for (int k = 0; k < 3; k++)
        if (x[k] < r->bbox_lo[k] || x[k] > r->bbox_hi[k])
            return 0;
    const struct tet_mesh *m = r->data;
    for (int i = 0; i < m->n; i++) {
        const double (*t)[3] = (const double (*)[3])m->node[i];
        if (tet_volume(t[0], t[1], t[2], x) > 0. && tet_volume(t[0], t[1], x, t[3]) > 0. &&
            tet_volume(t[0], x, t[2], t[3]) > 0. && tet_volume(x, t[1], t[2], t[3]) > 0.)
            return 1;
    }
    return 0;
}

static void tet_free(void *data)
{
    struct tet_mesh *m = data;
    if (m)
        free(m->node);
    free(m);
}

const struct region_style region_style_mesh_tet = {
    "mesh/tet", "file F scale s move dx dy dz rotate ax ay az", 12, tet_parse, tet_inside,
    tet_free};
