/* mesh.c - triangle mesh input, validation, welding and adjacency (see
 * mesh.h for the contract). Everything here is plain C on the host: the
 * device sees the result through fix mesh/surface and src/contact/wall.c.
 *
 * Validation, per triangle in file order (index from 0):
 *   - every coordinate finite (no NaN or inf);
 *   - after welding, three distinct vertices and a non-zero area:
 *     area > 1e-14 L^2 (L = longest edge), else "zero area";
 *   - not a needle: shortest altitude 2A/L >= 1e-5 L, else "needle".
 * Welding: raw vertices closer than the tolerance are one vertex (union-find
 * over a sweep sorted by x); welded vertices are numbered in order of first
 * appearance in the file, so ids are stable for a given file. */
#include "mesh.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fileio.h"

#define ZERO_AREA_REL 1e-14
#define NEEDLE_REL 1e-5

static int fail(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fail(char *err, size_t errlen, const char *fmt, ...)
{
    if (err && errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return -1;
}

void mesh_free(struct mesh *m)
{
    free(m->vert);
    free(m->tri);
    free(m->nbr);
    free(m->vtri_start);
    free(m->vtri);
    memset(m, 0, sizeof *m);
}

/* ---- welding and adjacency ------------------------------------------------------ */

static int uf_find(int *p, int i)
{
    while (p[i] != i) {
        p[i] = p[p[i]];
        i = p[i];
    }
    return i;
}

static void uf_union(int *p, int a, int b)
{
    a = uf_find(p, a);
    b = uf_find(p, b);
    if (a < b)
        p[b] = a;
    else if (b < a)
        p[a] = b;
}

static const double *sort_x;
static int cmp_x(const void *a, const void *b)
{
    int i = *(const int *)a, j = *(const int *)b;
    double xi = sort_x[3 * i], xj = sort_x[3 * j];
    if (xi != xj)
        return xi < xj ? -1 : 1;
    return i - j;
}

struct edge_rec {
    int a, b, t, k;
};

static int cmp_edge(const void *pa, const void *pb)
{
    const struct edge_rec *x = pa, *y = pb;
    if (x->a != y->a)
        return x->a - y->a;
    if (x->b != y->b)
        return x->b - y->b;
    if (x->t != y->t)
        return x->t - y->t;
    return x->k - y->k;
}

int mesh_from_soup(const char *name, const double *soup, int ntri, double weld_tol,
                   struct mesh *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    if (ntri <= 0)
        return fail(err, errlen, "%s: no triangles", name);
    int nraw = 3 * ntri;
    for (int t = 0; t < ntri; t++)
        for (int c = 0; c < 9; c++)
            if (!isfinite(soup[9 * t + c]))
                return fail(err, errlen, "%s: triangle %d: vertex %d is not finite (NaN or inf)",
                            name, t, c / 3);
    double lo[3], hi[3];
    for (int d = 0; d < 3; d++)
        lo[d] = hi[d] = soup[d];
    for (int i = 0; i < nraw; i++)
        for (int d = 0; d < 3; d++) {
            double v = soup[3 * i + d];
            lo[d] = v < lo[d] ? v : lo[d];
            hi[d] = v > hi[d] ? v : hi[d];
        }
    double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
    double tol = weld_tol > 0 ? weld_tol : 1e-10 * diag;

    int *order = malloc((size_t)nraw * sizeof *order);
    int *parent = malloc((size_t)nraw * sizeof *parent);
    int *id = malloc((size_t)nraw * sizeof *id);
    if (!order || !parent || !id) {
        free(order);
        free(parent);
        free(id);
        return fail(err, errlen, "%s: out of memory for %d triangles", name, ntri);
    }
    for (int i = 0; i < nraw; i++)
        order[i] = parent[i] = i;
    sort_x = soup;
    qsort(order, (size_t)nraw, sizeof *order, cmp_x);
    for (int s = 0; s < nraw; s++) {
        const double *p = soup + 3 * order[s];
        for (int r = s - 1; r >= 0; r--) {
            const double *q = soup + 3 * order[r];
            if (p[0] - q[0] > tol)
                break;
            double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
            if (dx * dx + dy * dy + dz * dz <= tol * tol)
                uf_union(parent, order[s], order[r]);
        }
    }
    int nvert = 0;
    for (int i = 0; i < nraw; i++) {
        int r = uf_find(parent, i);
        id[i] = r == i ? nvert++ : id[r];
    }
    m->nvert = nvert;
    m->ntri = ntri;
    m->vert = malloc((size_t)nvert * 3 * sizeof(double));
    m->tri = malloc((size_t)nraw * sizeof(int));
    m->nbr = malloc((size_t)nraw * sizeof(int));
    m->vtri_start = calloc((size_t)nvert + 1, sizeof(int));
    m->vtri = malloc((size_t)nraw * sizeof(int));
    struct edge_rec *edges = malloc((size_t)nraw * sizeof *edges);
    if (!m->vert || !m->tri || !m->nbr || !m->vtri_start || !m->vtri || !edges) {
        free(order);
        free(parent);
        free(id);
        free(edges);
        mesh_free(m);
        return fail(err, errlen, "%s: out of memory for %d triangles", name, ntri);
    }
    for (int i = 0; i < nraw; i++) {
        if (uf_find(parent, i) == i)
            memcpy(m->vert + 3 * id[i], soup + 3 * i, 3 * sizeof(double));
        m->tri[i] = id[i];
    }
    free(order);
    free(parent);
    free(id);

    /* geometry checks on the welded triangles */
    for (int t = 0; t < ntri; t++) {
        const int *v = m->tri + 3 * t;
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
            free(edges);
            mesh_free(m);
            return fail(err, errlen, "%s: triangle %d: zero area (two vertices coincide)", name,
                        t);
        }
        const double *a = m->vert + 3 * v[0], *b = m->vert + 3 * v[1], *c = m->vert + 3 * v[2];
        double e1[3], e2[3], e3[3], n[3];
        for (int d = 0; d < 3; d++) {
            e1[d] = b[d] - a[d];
            e2[d] = c[d] - a[d];
            e3[d] = c[d] - b[d];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double area = 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double l1 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
        double l2 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
        double l3 = e3[0] * e3[0] + e3[1] * e3[1] + e3[2] * e3[2];
        double L2 = l1 > l2 ? l1 : l2;
        L2 = l3 > L2 ? l3 : L2;
        if (!(area > ZERO_AREA_REL * L2)) {
            free(edges);
            mesh_free(m);
            return fail(err, errlen, "%s: triangle %d: zero area (collinear vertices)", name, t);
        }
        double ratio = 2.0 * area / L2;   /* shortest altitude / longest edge */
        if (ratio < NEEDLE_REL) {
            free(edges);
            mesh_free(m);
            return fail(err, errlen,
                        "%s: triangle %d: needle triangle (shortest altitude / longest edge = "
                        "%.3g < %g)", name, t, ratio, NEEDLE_REL);
        }
    }

    /* edge adjacency */
    for (int t = 0; t < ntri; t++)
        for (int k = 0; k < 3; k++) {
            int a = m->tri[3 * t + k], b = m->tri[3 * t + (k + 1) % 3];
            edges[3 * t + k] = (struct edge_rec){a < b ? a : b, a < b ? b : a, t, k};
            m->nbr[3 * t + k] = -1;
        }
    qsort(edges, (size_t)nraw, sizeof *edges, cmp_edge);
    m->nedge = 0;
    for (int s = 0; s < nraw;) {
        int e = s;
        while (e < nraw && edges[e].a == edges[s].a && edges[e].b == edges[s].b)
            e++;
        m->nedge++;
        if (e - s == 2) {
            m->nbr[3 * edges[s].t + edges[s].k] = edges[s + 1].t;
            m->nbr[3 * edges[s + 1].t + edges[s + 1].k] = edges[s].t;
        }
        s = e;
    }
    free(edges);

    /* vertex adjacency (CSR, triangles in ascending order) */
    for (int i = 0; i < nraw; i++)
        m->vtri_start[m->tri[i] + 1]++;
    for (int v = 0; v < nvert; v++)
        m->vtri_start[v + 1] += m->vtri_start[v];
    int *fill = calloc((size_t)nvert, sizeof *fill);
    if (!fill) {
        mesh_free(m);
        return fail(err, errlen, "%s: out of memory", name);
    }
    for (int t = 0; t < ntri; t++)
        for (int k = 0; k < 3; k++) {
            int v = m->tri[3 * t + k];
            m->vtri[m->vtri_start[v] + fill[v]++] = t;
        }
    free(fill);
    return 0;
}

/* ---- file readers --------------------------------------------------------------- */

/* Largest mesh file read: a binary STL of 21 million triangles. A FIFO, a
 * device (/dev/zero) or a directory is refused before anything is read, and
 * a larger file before anything is allocated (fio_read_all). */
#define MESH_MAX_BYTES ((size_t)1 << 30)

static unsigned char *slurp(const char *path, size_t *len, char *err, size_t errlen)
{
    char why[160];
    unsigned char *buf = fio_read_all(path, MESH_MAX_BYTES, len, why, sizeof why);
    if (!buf)
        fail(err, errlen, "%s: cannot open mesh file: %s", path, why);
    return buf;
}

/* Token scanner over text with line numbers. */
struct scan {
    const char *p, *end;
    int line;
    char tok[128];
};

static int next_tok(struct scan *s)
{
    while (s->p < s->end && isspace((unsigned char)*s->p)) {
        if (*s->p == '\n')
            s->line++;
        s->p++;
    }
    if (s->p >= s->end)
        return 0;
    size_t n = 0;
    while (s->p < s->end && !isspace((unsigned char)*s->p)) {
        if (n + 1 < sizeof s->tok)
            s->tok[n++] = *s->p;
        s->p++;
    }
    s->tok[n] = 0;
    return 1;
}

static int tok_is(const struct scan *s, const char *w)
{
    const char *a = s->tok;
    while (*a && *w && tolower((unsigned char)*a) == *w)
        a++, w++;
    return !*a && !*w;
}

static int tok_double(const struct scan *s, double *v)
{
    char *e;
    *v = strtod(s->tok, &e);
    return e != s->tok && *e == 0;
}

/* Growable triangle soup. */
struct soup {
    double *v;
    int n, cap;
};

static double *soup_add(struct soup *s)
{
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 64;
        double *nv = realloc(s->v, (size_t)cap * 9 * sizeof(double));
        if (!nv)
            return NULL;
        s->v = nv;
        s->cap = cap;
    }
    return s->v + 9 * (size_t)s->n++;
}

static int stl_expect(struct scan *s, const char *path, const char *w, int t, char *err,
                      size_t errlen)
{
    if (!next_tok(s))
        return fail(err, errlen, "%s:%d: unexpected end of file, expected '%s' (triangle %d)",
                    path, s->line, w, t);
    if (!tok_is(s, w))
        return fail(err, errlen, "%s:%d: expected '%s', got '%.40s' (triangle %d)", path,
                    s->line, w, s->tok, t);
    return 0;
}

static int read_stl_ascii(const char *path, const char *text, size_t len, struct soup *out,
                          char *err, size_t errlen)
{
    struct scan s = {text, text + len, 1, {0}};
    int in_solid = 0;
    while (next_tok(&s)) {
        if (tok_is(&s, "solid")) {
            in_solid = 1;
            /* the name runs to the end of the line */
            while (s.p < s.end && *s.p != '\n')
                s.p++;
            continue;
        }
        if (tok_is(&s, "endsolid")) {
            in_solid = 0;
            while (s.p < s.end && *s.p != '\n')
                s.p++;
            continue;
        }
        int t = out->n;
        if (!tok_is(&s, "facet"))
            return fail(err, errlen, "%s:%d: expected 'facet' or 'endsolid', got '%.40s' "
                        "(triangle %d)", path, s.line, s.tok, t);
        if (!in_solid)
            return fail(err, errlen, "%s:%d: 'facet' outside 'solid' (triangle %d)", path,
                        s.line, t);
        if (stl_expect(&s, path, "normal", t, err, errlen))
            return -1;
        for (int c = 0; c < 3; c++) {
            double dummy;
            if (!next_tok(&s) || !tok_double(&s, &dummy))
                return fail(err, errlen, "%s:%d: bad facet normal component '%.40s' "
                            "(triangle %d)", path, s.line, s.tok, t);
        }
        if (stl_expect(&s, path, "outer", t, err, errlen) ||
            stl_expect(&s, path, "loop", t, err, errlen))
            return -1;
        double *tri = soup_add(out);
        if (!tri)
            return fail(err, errlen, "%s: out of memory", path);
        for (int k = 0; k < 3; k++) {
            if (stl_expect(&s, path, "vertex", t, err, errlen))
                return -1;
            for (int c = 0; c < 3; c++)
                if (!next_tok(&s) || !tok_double(&s, &tri[3 * k + c]))
                    return fail(err, errlen, "%s:%d: bad vertex coordinate '%.40s' "
                                "(triangle %d)", path, s.line, s.tok, t);
        }
        if (!next_tok(&s))
            return fail(err, errlen, "%s:%d: unexpected end of file, expected 'endloop' "
                        "(triangle %d)", path, s.line, t);
        if (tok_is(&s, "vertex"))
            return fail(err, errlen, "%s:%d: triangle %d has more than 3 vertices", path,
                        s.line, t);
        if (!tok_is(&s, "endloop"))
            return fail(err, errlen, "%s:%d: expected 'endloop', got '%.40s' (triangle %d)",
                        path, s.line, s.tok, t);
        if (stl_expect(&s, path, "endfacet", t, err, errlen))
            return -1;
    }
    if (out->n == 0)
        return fail(err, errlen, "%s: no triangles in ASCII STL file", path);
    return 0;
}

static float le_float(const unsigned char *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                 (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static int read_stl_binary(const char *path, const unsigned char *buf, size_t len,
                           struct soup *out, char *err, size_t errlen)
{
    if (len < 84)
        return fail(err, errlen, "%s: truncated binary STL: %zu bytes, the header alone is 84",
                    path, len);
    uint32_t n = (uint32_t)buf[80] | (uint32_t)buf[81] << 8 | (uint32_t)buf[82] << 16 |
                 (uint32_t)buf[83] << 24;
    uint64_t need = 84 + 50 * (uint64_t)n;
    if (len < need)
        return fail(err, errlen, "%s: truncated binary STL: the header counts %u triangles "
                    "(%llu bytes), the file has %zu bytes (%zu complete triangles; triangle "
                    "%zu is cut)", path, n, (unsigned long long)need, len, (len - 84) / 50,
                    (len - 84) / 50);
    if (len > need)
        return fail(err, errlen, "%s: inconsistent triangle count: the binary STL header counts "
                    "%u triangles, the file size (%zu bytes) holds %zu", path, n, len,
                    (len - 84) / 50);
    if (n == 0)
        return fail(err, errlen, "%s: no triangles in binary STL file", path);
    if (n > 100000000u)
        return fail(err, errlen, "%s: %u triangles is more than this reader takes", path, n);
    for (uint32_t t = 0; t < n; t++) {
        double *tri = soup_add(out);
        if (!tri)
            return fail(err, errlen, "%s: out of memory", path);
        const unsigned char *p = buf + 84 + 50 * (size_t)t + 12;
        for (int c = 0; c < 9; c++)
            tri[c] = le_float(p + 4 * c);
    }
    return 0;
}

/* Legacy VTK values: ASCII tokens, or big-endian binary of the declared type
 * (the data of a BINARY block starts after the end of its header line). */
enum { VT_F32, VT_F64, VT_I32, VT_I64 };

static int vtk_type(const char *t)
{
    if (!strcasecmp(t, "float"))
        return VT_F32;
    if (!strcasecmp(t, "double"))
        return VT_F64;
    if (!strcasecmp(t, "int") || !strcasecmp(t, "vtktypeint32"))
        return VT_I32;
    if (!strcasecmp(t, "vtktypeint64") || !strcasecmp(t, "long"))
        return VT_I64;
    return -1;
}

static void vtk_bin_begin(struct scan *s)
{
    while (s->p < s->end && *s->p != '\n')
        s->p++;
    if (s->p < s->end) {
        s->p++;
        s->line++;
    }
}

static int vtk_value(struct scan *s, int bin, int type, double *v)
{
    if (!bin)
        return next_tok(s) && tok_double(s, v);
    size_t w = type == VT_F64 || type == VT_I64 ? 8 : 4;
    if ((size_t)(s->end - s->p) < w)
        return 0;
    const unsigned char *b = (const unsigned char *)s->p;
    uint64_t u = 0;
    for (size_t k = 0; k < w; k++)
        u = u << 8 | b[k];
    s->p += w;
    if (type == VT_F32) {
        uint32_t u32 = (uint32_t)u;
        float f;
        memcpy(&f, &u32, 4);
        *v = f;
    } else if (type == VT_F64) {
        double d;
        memcpy(&d, &u, 8);
        *v = d;
    } else if (type == VT_I32) {
        *v = (double)(int32_t)(uint32_t)u;
    } else {
        *v = (double)(int64_t)u;
    }
    return 1;
}

/* Cells of POLYGONS / CELLS: the 4.x layout (count n size, then "3 i j k"
 * per cell) or the 5.x one (count nOffsets nConnectivity, then OFFSETS and
 * CONNECTIVITY arrays). Every cell must be a triangle. */
static int vtk_cells(const char *path, struct scan *s, int bin, long npts, long *ncell_out,
                     int **cells_out, char *err, size_t errlen)
{
    double a, b;
    const char *kw = s->tok[0] == 'C' || s->tok[0] == 'c' ? "CELLS" : "POLYGONS";
    if (!next_tok(s) || !tok_double(s, &a) || a < 0 || a > 3e8 || !next_tok(s) ||
        !tok_double(s, &b) || b < 0)
        return fail(err, errlen, "%s:%d: bad %s line", path, s->line, kw);
    /* 5.x: OFFSETS follows */
    const char *save = s->p;
    int save_line = s->line;
    int v5 = next_tok(s) && tok_is(s, "offsets");
    if (!v5) {
        s->p = save;
        s->line = save_line;
    }
    long ncell = v5 ? (long)a - 1 : (long)a;
    if (ncell < 0)
        return fail(err, errlen, "%s:%d: bad %s line", path, s->line, kw);
    if ((long)b != (v5 ? 3 : 4) * ncell)
        return fail(err, errlen, "%s:%d: inconsistent triangle count: %ld cells of triangles "
                    "need a size of %ld, the file says %ld (only triangles are read)", path,
                    s->line, ncell, (v5 ? 3 : 4) * ncell, (long)b);
    int *cells = malloc((size_t)(ncell ? ncell : 1) * 3 * sizeof(int));
    if (!cells)
        return fail(err, errlen, "%s: out of memory", path);
    int rc = 0;
    double v;
    if (v5) {
        int type = next_tok(s) ? vtk_type(s->tok) : -1;
        if (type != VT_I32 && type != VT_I64)
            rc = fail(err, errlen, "%s:%d: OFFSETS: integer type expected", path, s->line);
        if (!rc && bin)
            vtk_bin_begin(s);
        for (long c = 0; !rc && c <= ncell; c++) {
            if (!vtk_value(s, bin, type, &v))
                rc = fail(err, errlen, "%s:%d: triangle %ld is missing (truncated file?)", path,
                          s->line, c);
            else if (v != 3.0 * c)
                rc = fail(err, errlen, "%s:%d: triangle %ld: cell has %g vertices (only "
                          "triangles are read)", path, s->line, c ? c - 1 : 0,
                          c ? v - 3.0 * (c - 1) : v);
        }
        if (!rc && (!next_tok(s) || !tok_is(s, "connectivity")))
            rc = fail(err, errlen, "%s:%d: expected CONNECTIVITY after OFFSETS", path, s->line);
        type = rc ? -1 : next_tok(s) ? vtk_type(s->tok) : -1;
        if (!rc && type != VT_I32 && type != VT_I64)
            rc = fail(err, errlen, "%s:%d: CONNECTIVITY: integer type expected", path, s->line);
        if (!rc && bin)
            vtk_bin_begin(s);
        for (long k = 0; !rc && k < 3 * ncell; k++) {
            if (!vtk_value(s, bin, type, &v))
                rc = fail(err, errlen, "%s:%d: triangle %ld is missing (truncated file?)", path,
                          s->line, k / 3);
            else if (v < 0 || v >= npts || v != floor(v))
                rc = fail(err, errlen, "%s:%d: triangle %ld: vertex index %g out of range (%ld "
                          "points)", path, s->line, k / 3, v, npts);
            else
                cells[k] = (int)v;
        }
    } else {
        if (bin)
            vtk_bin_begin(s);
        for (long c = 0; !rc && c < ncell; c++) {
            if (!vtk_value(s, bin, VT_I32, &v)) {
                rc = fail(err, errlen, "%s:%d: triangle %ld is missing (truncated file?)", path,
                          s->line, c);
                break;
            }
            if (v != 3) {
                rc = fail(err, errlen, "%s:%d: triangle %ld: cell has %g vertices (only "
                          "triangles are read)", path, s->line, c, v);
                break;
            }
            for (int k = 0; k < 3 && !rc; k++) {
                if (!vtk_value(s, bin, VT_I32, &v) || v != floor(v))
                    rc = fail(err, errlen, "%s:%d: triangle %ld: bad vertex index", path,
                              s->line, c);
                else if (v < 0 || v >= npts)
                    rc = fail(err, errlen, "%s:%d: triangle %ld: vertex index %g out of range "
                              "(%ld points)", path, s->line, c, v, npts);
                else
                    cells[3 * c + k] = (int)v;
            }
        }
    }
    if (rc) {
        free(cells);
        return rc;
    }
    *ncell_out = ncell;
    *cells_out = cells;
    return 0;
}

static int read_vtk(const char *path, const char *text, size_t len, struct soup *out,
                    char *err, size_t errlen)
{
    struct scan s = {text, text + len, 1, {0}};
    /* line 1: "# vtk DataFile Version x.y", line 2: title */
    const char *nl = memchr(s.p, '\n', len);
    if (!nl)
        return fail(err, errlen, "%s: not a legacy VTK file", path);
    s.p = nl + 1;
    s.line = 2;
    nl = memchr(s.p, '\n', (size_t)(s.end - s.p));
    if (!nl)
        return fail(err, errlen, "%s: legacy VTK file ends after its header", path);
    s.p = nl + 1;
    s.line = 3;
    if (!next_tok(&s) || !(tok_is(&s, "ascii") || tok_is(&s, "binary")))
        return fail(err, errlen, "%s:%d: expected ASCII or BINARY, got '%.40s'", path, s.line,
                    s.tok);
    int bin = tok_is(&s, "binary");
    if (!next_tok(&s) || !tok_is(&s, "dataset") || !next_tok(&s) ||
        !(tok_is(&s, "polydata") || tok_is(&s, "unstructured_grid")))
        return fail(err, errlen, "%s:%d: expected DATASET POLYDATA or UNSTRUCTURED_GRID", path,
                    s.line);
    int ugrid = tok_is(&s, "unstructured_grid");
    double *pts = NULL;
    long npts = -1;
    int *cells = NULL;
    long ncell = -1;
    int rc = 0;
    while (rc == 0 && next_tok(&s)) {
        double v;
        if (tok_is(&s, "points")) {
            int type;
            if (!next_tok(&s) || !tok_double(&s, &v) || v < 0 || v > 3e8 || !next_tok(&s) ||
                ((type = vtk_type(s.tok)) < 0 && bin)) {
                rc = fail(err, errlen, "%s:%d: bad POINTS line", path, s.line);
                break;
            }
            npts = (long)v;
            free(pts);
            pts = malloc((size_t)(npts ? npts : 1) * 3 * sizeof(double));
            if (!pts) {
                rc = fail(err, errlen, "%s: out of memory", path);
                break;
            }
            if (bin)
                vtk_bin_begin(&s);
            for (long i = 0; i < 3 * npts; i++)
                if (!vtk_value(&s, bin, type, &pts[i])) {
                    rc = fail(err, errlen, "%s:%d: POINTS: expected %ld coordinates, point %ld "
                              "is missing or bad", path, s.line, 3 * npts, i / 3);
                    break;
                }
        } else if (tok_is(&s, ugrid ? "cells" : "polygons")) {
            free(cells);
            cells = NULL;
            if (npts < 0) {
                rc = fail(err, errlen, "%s:%d: cells before POINTS", path, s.line);
                break;
            }
            rc = vtk_cells(path, &s, bin, npts, &ncell, &cells, err, errlen);
        } else if (ugrid && tok_is(&s, "cell_types")) {
            if (!next_tok(&s) || !tok_double(&s, &v) || (long)v != ncell) {
                rc = fail(err, errlen, "%s:%d: inconsistent triangle count: CELL_TYPES counts "
                          "%s, CELLS %ld", path, s.line, s.tok, ncell);
                break;
            }
            if (bin)
                vtk_bin_begin(&s);
            for (long c = 0; c < ncell; c++)
                if (!vtk_value(&s, bin, VT_I32, &v) || v != 5) {
                    rc = fail(err, errlen, "%s:%d: triangle %ld: VTK cell type %g is not a "
                              "triangle (5)", path, s.line, c, v);
                    break;
                }
        } else if (tok_is(&s, "field")) {
            /* dataset field data (e.g. TIME, CYCLE of our own dumps): skipped */
            double narr, nc, nt;
            if (!next_tok(&s) || !next_tok(&s) || !tok_double(&s, &narr) || narr < 0) {
                rc = fail(err, errlen, "%s:%d: bad FIELD line", path, s.line);
                break;
            }
            for (long k = 0; rc == 0 && k < (long)narr; k++) {
                int type;
                if (!next_tok(&s) || !next_tok(&s) || !tok_double(&s, &nc) || !next_tok(&s) ||
                    !tok_double(&s, &nt) || !next_tok(&s) || (type = vtk_type(s.tok)) < 0 ||
                    nc < 0 || nt < 0 || nc * nt > 1e9) {
                    rc = fail(err, errlen, "%s:%d: FIELD array %ld: bad header (numeric "
                              "arrays only)", path, s.line, k);
                    break;
                }
                if (bin)
                    vtk_bin_begin(&s);
                for (long q = 0; q < (long)(nc * nt); q++)
                    if (!vtk_value(&s, bin, type, &v)) {
                        rc = fail(err, errlen, "%s:%d: FIELD array %ld is cut", path, s.line,
                                  k);
                        break;
                    }
            }
        } else if (tok_is(&s, "metadata")) {
            /* information keys up to the next blank line: skipped */
            vtk_bin_begin(&s);  /* the rest of the METADATA line */
            while (s.p < s.end) {
                const char *e = memchr(s.p, '\n', (size_t)(s.end - s.p));
                if (!e)
                    break;
                int blank = 1;
                for (const char *q = s.p; q < e; q++)
                    blank &= isspace((unsigned char)*q) != 0;
                s.p = e + 1;
                s.line++;
                if (blank)
                    break;
            }
        } else if (tok_is(&s, "point_data") || tok_is(&s, "cell_data")) {
            break;  /* attributes are not needed */
        } else if (tok_is(&s, "vertices") || tok_is(&s, "lines") ||
                   tok_is(&s, "triangle_strips")) {
            rc = fail(err, errlen, "%s:%d: %s are not read (triangles as POLYGONS only)", path,
                      s.line, s.tok);
        } else {
            rc = fail(err, errlen, "%s:%d: unexpected '%.40s' in legacy VTK mesh", path, s.line,
                      s.tok);
        }
    }
    if (rc == 0 && npts < 0)
        rc = fail(err, errlen, "%s: no POINTS in legacy VTK file", path);
    if (rc == 0 && ncell <= 0)
        rc = fail(err, errlen, "%s: no triangles in legacy VTK file", path);
    for (long c = 0; rc == 0 && c < ncell; c++) {
        double *tri = soup_add(out);
        if (!tri) {
            rc = fail(err, errlen, "%s: out of memory", path);
            break;
        }
        for (int k = 0; k < 3; k++)
            memcpy(tri + 3 * k, pts + 3 * cells[3 * c + k], 3 * sizeof(double));
    }
    free(pts);
    free(cells);
    return rc;
}

int mesh_read(const char *path, double weld_tol, struct mesh *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    size_t len;
    unsigned char *buf = slurp(path, &len, err, errlen);
    if (!buf)
        return -1;
    if (len == 0) {
        free(buf);
        return fail(err, errlen, "%s: the mesh file is empty", path);
    }
    struct soup soup = {0};
    int rc;
    const char *text = (const char *)buf;
    size_t skip = 0;
    while (skip < len && isspace(buf[skip]))
        skip++;
    int has_nul = memchr(buf, 0, len) != NULL;
    if (len >= 5 && !strncmp(text, "# vtk", 5)) {
        rc = read_vtk(path, text, len, &soup, err, errlen);
    } else {
        int binary_fits = 0;
        if (len >= 84) {
            uint32_t n = (uint32_t)buf[80] | (uint32_t)buf[81] << 8 |
                         (uint32_t)buf[82] << 16 | (uint32_t)buf[83] << 24;
            binary_fits = len == 84 + 50 * (uint64_t)n;
        }
        int ascii = !binary_fits && !has_nul && len - skip >= 5 &&
                    !strncasecmp(text + skip, "solid", 5);
        rc = ascii ? read_stl_ascii(path, text, len, &soup, err, errlen)
                   : read_stl_binary(path, buf, len, &soup, err, errlen);
    }
    free(buf);
    if (rc == 0)
        rc = mesh_from_soup(path, soup.v, soup.n, weld_tol, m, err, errlen);
    free(soup.v);
    return rc;
}

/* ---- transforms ----------------------------------------------------------------- */

void mesh_scale(struct mesh *m, double s)
{
    for (int i = 0; i < 3 * m->nvert; i++)
        m->vert[i] *= s;
}

void mesh_move(struct mesh *m, const double d[3])
{
    for (int v = 0; v < m->nvert; v++)
        for (int k = 0; k < 3; k++)
            m->vert[3 * v + k] += d[k];
}

void mesh_rotation_matrix(const double a[3], double rad, double R[9])
{
    double c = cos(rad), s = sin(rad), t = 1.0 - c;
    double x = a[0], y = a[1], z = a[2];
    R[0] = t * x * x + c;
    R[1] = t * x * y - s * z;
    R[2] = t * x * z + s * y;
    R[3] = t * x * y + s * z;
    R[4] = t * y * y + c;
    R[5] = t * y * z - s * x;
    R[6] = t * x * z - s * y;
    R[7] = t * y * z + s * x;
    R[8] = t * z * z + c;
}

void mesh_rotate(struct mesh *m, const double axis[3], double deg)
{
    double R[9];
    mesh_rotation_matrix(axis, deg * M_PI / 180.0, R);
    for (int v = 0; v < m->nvert; v++) {
        double *p = m->vert + 3 * v, q[3];
        for (int r = 0; r < 3; r++)
            q[r] = R[3 * r] * p[0] + R[3 * r + 1] * p[1] + R[3 * r + 2] * p[2];
        memcpy(p, q, sizeof q);
    }
}

/* ---- bins ------------------------------------------------------------------------ */

void mesh_bins_free(struct mesh_bins *b)
{
    free(b->start);
    free(b->list);
    memset(b, 0, sizeof *b);
}

/* Visit the cells of triangle t (AABB grown by reach, then a plane-distance
 * cull): count (list NULL) or fill. */
static size_t bin_tri(const struct mesh *m, const struct mesh_bins *b, int t, double reach,
                      int *fill, int *list)
{
    const double *p[3];
    for (int k = 0; k < 3; k++)
        p[k] = m->vert + 3 * m->tri[3 * t + k];
    int lo[3], hi[3];
    for (int d = 0; d < 3; d++) {
        double mn = p[0][d], mx = p[0][d];
        for (int k = 1; k < 3; k++) {
            mn = p[k][d] < mn ? p[k][d] : mn;
            mx = p[k][d] > mx ? p[k][d] : mx;
        }
        lo[d] = (int)floor((mn - reach - b->lo[d]) / b->h);
        hi[d] = (int)floor((mx + reach - b->lo[d]) / b->h);
        lo[d] = lo[d] < 0 ? 0 : lo[d];
        hi[d] = hi[d] >= b->n[d] ? b->n[d] - 1 : hi[d];
    }
    double e1[3], e2[3], n[3];
    for (int d = 0; d < 3; d++) {
        e1[d] = p[1][d] - p[0][d];
        e2[d] = p[2][d] - p[0][d];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int d = 0; d < 3; d++)
        n[d] /= len;
    double slack = reach + 0.5 * sqrt(3.0) * b->h * (1 + 1e-9);
    size_t count = 0;
    for (int z = lo[2]; z <= hi[2]; z++)
        for (int y = lo[1]; y <= hi[1]; y++)
            for (int x = lo[0]; x <= hi[0]; x++) {
                double c[3] = {b->lo[0] + (x + 0.5) * b->h, b->lo[1] + (y + 0.5) * b->h,
                               b->lo[2] + (z + 0.5) * b->h};
                double dist = (c[0] - p[0][0]) * n[0] + (c[1] - p[0][1]) * n[1] +
                              (c[2] - p[0][2]) * n[2];
                if (fabs(dist) > slack)
                    continue;
                int cell = (z * b->n[1] + y) * b->n[0] + x;
                if (list)
                    list[b->start[cell] + fill[cell]++] = t;
                else
                    fill[cell]++;
                count++;
            }
    return count;
}

int mesh_bin(const struct mesh *m, double reach, struct mesh_bins *b, char *err, size_t errlen)
{
    memset(b, 0, sizeof *b);
    double lo[3], hi[3];
    for (int d = 0; d < 3; d++)
        lo[d] = hi[d] = m->vert[d];
    for (int v = 0; v < m->nvert; v++)
        for (int d = 0; d < 3; d++) {
            double x = m->vert[3 * v + d];
            lo[d] = x < lo[d] ? x : lo[d];
            hi[d] = x > hi[d] ? x : hi[d];
        }
    double ext = 0;
    for (int d = 0; d < 3; d++)
        ext = hi[d] - lo[d] > ext ? hi[d] - lo[d] : ext;
    if (!(reach > 0))
        reach = 1e-9 * (ext > 0 ? ext : 1);
    double h = 2 * reach;
    if (h < ext / 64)
        h = ext / 64;
    for (;;) {
        double cells = 1;
        for (int d = 0; d < 3; d++) {
            b->lo[d] = lo[d] - reach;
            double n = ceil((hi[d] + reach - b->lo[d]) / h);
            n = n < 1 ? 1 : n;
            b->n[d] = (int)n + 1;   /* one spare layer: floor() at the upper boundary */
            cells *= b->n[d];
        }
        if (cells <= 4194304.0)
            break;
        h *= 1.25;
    }
    b->h = h;
    int ncell = b->n[0] * b->n[1] * b->n[2];
    int *fill = calloc((size_t)ncell, sizeof *fill);
    b->start = calloc((size_t)ncell + 1, sizeof *b->start);
    if (!fill || !b->start) {
        free(fill);
        mesh_bins_free(b);
        return fail(err, errlen, "out of memory for %d mesh bins", ncell);
    }
    size_t total = 0;
    for (int t = 0; t < m->ntri; t++)
        total += bin_tri(m, b, t, reach, fill, NULL);
    if (total > 0x7fffffff) {
        free(fill);
        mesh_bins_free(b);
        return fail(err, errlen, "mesh bins would hold %zu entries (too many)", total);
    }
    for (int c = 0; c < ncell; c++)
        b->start[c + 1] = b->start[c] + fill[c];
    b->list = malloc((total ? total : 1) * sizeof *b->list);
    if (!b->list) {
        free(fill);
        mesh_bins_free(b);
        return fail(err, errlen, "out of memory for mesh bins");
    }
    memset(fill, 0, (size_t)ncell * sizeof *fill);
    for (int t = 0; t < m->ntri; t++)
        bin_tri(m, b, t, reach, fill, b->list);
    free(fill);
    return 0;
}

/* Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision
 * Detection 5.1.5: Voronoi regions of vertices, edges, face). */
static double tri_dist2(const double *a, const double *b, const double *c, const double *p)
{
    double ab[3], ac[3], ap[3], q[3];
    for (int d = 0; d < 3; d++) {
        ab[d] = b[d] - a[d];
        ac[d] = c[d] - a[d];
        ap[d] = p[d] - a[d];
    }
#define DOT(u, v) ((u)[0] * (v)[0] + (u)[1] * (v)[1] + (u)[2] * (v)[2])
    double d1 = DOT(ab, ap), d2 = DOT(ac, ap);
    double bp[3], cp[3];
    for (int d = 0; d < 3; d++) {
        bp[d] = p[d] - b[d];
        cp[d] = p[d] - c[d];
    }
    double d3 = DOT(ab, bp), d4 = DOT(ac, bp), d5 = DOT(ab, cp), d6 = DOT(ac, cp);
#undef DOT
    double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
    if (d1 <= 0 && d2 <= 0) {
        memcpy(q, a, sizeof q);
    } else if (d3 >= 0 && d4 <= d3) {
        memcpy(q, b, sizeof q);
    } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        double v = d1 / (d1 - d3);
        for (int d = 0; d < 3; d++)
            q[d] = a[d] + v * ab[d];
    } else if (d6 >= 0 && d5 <= d6) {
        memcpy(q, c, sizeof q);
    } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        double w = d2 / (d2 - d6);
        for (int d = 0; d < 3; d++)
            q[d] = a[d] + w * ac[d];
    } else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int d = 0; d < 3; d++)
            q[d] = b[d] + w * (c[d] - b[d]);
    } else {
        double den = 1.0 / (va + vb + vc), v = vb * den, w = vc * den;
        for (int d = 0; d < 3; d++)
            q[d] = a[d] + ab[d] * v + ac[d] * w;
    }
    double r2 = 0;
    for (int d = 0; d < 3; d++)
        r2 += (p[d] - q[d]) * (p[d] - q[d]);
    return r2;
}

int mesh_near(const struct mesh *m, const struct mesh_bins *b, const double p[3], double dist)
{
    int c[3];
    for (int d = 0; d < 3; d++) {
        double f = floor((p[d] - b->lo[d]) / b->h);
        if (f < 0 || f >= b->n[d])
            return 0; /* outside the grid: farther than reach from every triangle */
        c[d] = (int)f;
    }
    int cell = (c[2] * b->n[1] + c[1]) * b->n[0] + c[0];
    double d2 = dist * dist;
    for (int k = b->start[cell]; k < b->start[cell + 1]; k++) {
        int t = b->list[k];
        const int *v = m->tri + 3 * t;
        if (tri_dist2(m->vert + 3 * v[0], m->vert + 3 * v[1], m->vert + 3 * v[2], p) < d2)
            return 1;
    }
    return 0;
}
