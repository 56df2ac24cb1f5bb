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
 * over exact duplicates and a hashed grid, expected linear time: weld());
 * welded vertices are numbered in order of first appearance in the file, so
 * ids are stable for a given file. */
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
/* Coordinates and edge lengths must stay within [1e-75, 1e75] (edges: when
 * not 0): a triangle's squared area (~ edge^4) is then a normal double. */
#define COORD_MAX MESH_COORD_MAX
#define EDGE_MIN 1e-75

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

/* ---- welding --------------------------------------------------------------------
 * Raw vertices i, j are one vertex when they are linked by a chain of pairs
 * with |dx| <= tol and dx^2 + dy^2 + dz^2 <= tol^2 (the components of that
 * graph). Found by hashing, in expected time linear in the vertex count:
 * exact duplicates first (one representative each, however many copies), then a
 * grid of cells of side h >= 0.55 tol over the representatives, so that linked
 * points lie at most 2 cells apart; when h is 0.55 tol every two points of
 * one cell are linked (0.95 tol apart at most), so a cell is one component
 * without a pair test. A welded vertex is numbered by the first raw vertex of
 * its component in file order and takes that vertex's coordinates. */

struct khash {          /* open addressing: key (3 x 64 bit) -> group number */
    uint64_t *key;      /* 3 per group, in order of first appearance */
    int *slot;          /* cap entries: group + 1, 0 = empty */
    size_t cap;
    int n;
};

static uint64_t mix64(uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

static size_t khash_pos(const struct khash *h, const uint64_t k[3])
{
    return (size_t)mix64(k[0] ^ mix64(k[1] ^ mix64(k[2]))) & (h->cap - 1);
}

static int khash_init(struct khash *h, int nmax)
{
    h->cap = 16;
    while (h->cap < 2 * (size_t)nmax)
        h->cap *= 2;
    h->n = 0;
    h->slot = calloc(h->cap, sizeof *h->slot);
    h->key = malloc((size_t)(nmax ? nmax : 1) * 3 * sizeof *h->key);
    return h->slot && h->key ? 0 : -1;
}

static void khash_free(struct khash *h)
{
    free(h->slot);
    free(h->key);
    memset(h, 0, sizeof *h);
}

/* The group of key k, or -1 if none (insert = 0); with insert = 1 a new key
 * gets the next group number (room for nmax groups was reserved). */
static int khash_get(struct khash *h, const uint64_t k[3], int insert)
{
    for (size_t p = khash_pos(h, k);; p = (p + 1) & (h->cap - 1)) {
        int s = h->slot[p] - 1;
        if (s < 0) {
            if (!insert)
                return -1;
            memcpy(h->key + 3 * (size_t)h->n, k, 3 * sizeof *k);
            h->slot[p] = h->n + 1;
            return h->n++;
        }
        const uint64_t *q = h->key + 3 * (size_t)s;
        if (q[0] == k[0] && q[1] == k[1] && q[2] == k[2])
            return s;
    }
}

static int weld_linked(const double *p, const double *q, double tol)
{
    double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
    return fabs(dx) <= tol && dx * dx + dy * dy + dz * dz <= tol * tol;
}

/* Pair tests between the points of cells a and b (a == b: within one cell). */
static void weld_cells(const double *soup, const int *rep, const int *cstart, const int *cpts,
                       int a, int b, double tol, int clique, int *parent)
{
    for (int i = cstart[a]; i < cstart[a + 1]; i++)
        for (int j = a == b ? i + 1 : cstart[b]; j < cstart[b + 1]; j++) {
            int u = cpts[i], v = cpts[j];
            if (clique && uf_find(parent, u) == uf_find(parent, v))
                return; /* the two cells are one component already */
            if (uf_find(parent, u) != uf_find(parent, v) &&
                weld_linked(soup + 3 * (size_t)rep[u], soup + 3 * (size_t)rep[v], tol))
                uf_union(parent, u, v);
        }
}

/* Weld nraw raw vertices (bounding box lo..hi): id[i] = welded vertex of raw
 * vertex i, root[v] = the raw vertex whose coordinates vertex v takes;
 * returns the welded vertex count, or -1 when out of memory. */
static int weld(const double *soup, int nraw, double tol, const double lo[3],
                const double hi[3], int *id, int *root)
{
    struct khash ex = {0}, cells = {0};
    int *rep = NULL, *parent = NULL, *cell = NULL, *cstart = NULL, *cpts = NULL, nv = -1;
    if (khash_init(&ex, nraw))
        goto out;
    /* exact duplicates: raw vertex i -> representative group id[i] */
    for (int i = 0; i < nraw; i++) {
        uint64_t k[3];
        for (int d = 0; d < 3; d++) {
            double x = soup[3 * (size_t)i + d] + 0.0; /* -0 -> +0 */
            memcpy(&k[d], &x, sizeof x);
        }
        id[i] = khash_get(&ex, k, 1);
    }
    int nu = ex.n;
    rep = malloc((size_t)nu * sizeof *rep);
    parent = malloc((size_t)nu * sizeof *parent);
    cell = malloc((size_t)nu * sizeof *cell);
    if (!rep || !parent || !cell || khash_init(&cells, nu))
        goto out;
    for (int i = nraw - 1; i >= 0; i--)
        rep[id[i]] = i;   /* the first raw vertex with these coordinates */
    double ext = 0;
    for (int d = 0; d < 3; d++)
        ext = hi[d] - lo[d] > ext ? hi[d] - lo[d] : ext;
    double h = 0.55 * tol;
    int clique = 1;
    if (!(h >= ext * 0x1p-40)) { /* keep cell numbers small: < 2^41 per axis */
        h = ext * 0x1p-40;
        clique = 0;
    }
    if (!(h > 0))
        h = 1;   /* every point is one point */
    for (int u = 0; u < nu; u++) {
        uint64_t k[3];
        for (int d = 0; d < 3; d++)
            k[d] = (uint64_t)(int64_t)floor((soup[3 * (size_t)rep[u] + d] - lo[d]) / h);
        cell[u] = khash_get(&cells, k, 1);
        parent[u] = u;
    }
    /* points of each cell (CSR, ascending) */
    int nc = cells.n;
    cstart = calloc((size_t)nc + 1, sizeof *cstart);
    cpts = malloc((size_t)nu * sizeof *cpts);
    if (!cstart || !cpts)
        goto out;
    for (int u = 0; u < nu; u++)
        cstart[cell[u] + 1]++;
    for (int c = 0; c < nc; c++)
        cstart[c + 1] += cstart[c];
    for (int u = 0; u < nu; u++)
        cpts[cstart[cell[u]]++] = u;
    for (int c = nc; c > 0; c--)
        cstart[c] = cstart[c - 1];
    cstart[0] = 0;
    for (int c = 0; c < nc; c++) /* within cells first: a cell is then one component */
        if (clique)
            for (int i = cstart[c] + 1; i < cstart[c + 1]; i++)
                uf_union(parent, cpts[cstart[c]], cpts[i]);
        else
            weld_cells(soup, rep, cstart, cpts, c, c, tol, 0, parent);
    for (int c = 0; c < nc; c++) {
        /* each neighbouring cell pair once: offsets after (0,0,0) in z, y, x order */
        const uint64_t *k = cells.key + 3 * (size_t)c;
        for (int dz = 0; dz <= 2; dz++)
            for (int dy = dz ? -2 : 0; dy <= 2; dy++)
                for (int dx = dz || dy ? -2 : 1; dx <= 2; dx++) {
                    uint64_t q[3] = {k[0] + (uint64_t)(int64_t)dx, k[1] + (uint64_t)(int64_t)dy,
                                     k[2] + (uint64_t)(int64_t)dz};
                    int b = khash_get(&cells, q, 0);
                    if (b >= 0)
                        weld_cells(soup, rep, cstart, cpts, c, b, tol, clique, parent);
                }
    }
    /* number the components by their first raw vertex (the smallest
     * representative: uf_union keeps the smallest index as the root) */
    for (int u = 0; u < nu; u++)
        cell[u] = -1;
    nv = 0;
    for (int i = 0; i < nraw; i++) {
        int r = uf_find(parent, id[i]);
        if (cell[r] < 0) {
            root[nv] = rep[r];
            cell[r] = nv++;
        }
        id[i] = cell[r];
    }
out:
    khash_free(&ex);
    khash_free(&cells);
    free(rep);
    free(parent);
    free(cell);
    free(cstart);
    free(cpts);
    return nv;
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
        for (int c = 0; c < 9; c++) {
            double x = soup[9 * t + c];
            if (!isfinite(x))
                return fail(err, errlen, "%s: triangle %d: vertex %d is not finite (NaN or inf)",
                            name, t, c / 3);
            if (fabs(x) > COORD_MAX)
                return fail(err, errlen, "%s: triangle %d: vertex %d has coordinate %g, beyond "
                            "%g: its area would overflow double precision", name, t, c / 3, x,
                            COORD_MAX);
        }
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
    for (int t = 0; t < ntri; t++) {
        double e = 0;   /* the longest edge component */
        for (int k = 0; k < 3; k++)
            for (int d = 0; d < 3; d++)
                e = fmax(e, fabs(soup[9 * t + 3 * k + d] - soup[9 * t + 3 * ((k + 1) % 3) + d]));
        if (e > tol && e < EDGE_MIN)
            return fail(err, errlen, "%s: triangle %d: degenerate at this scale: its edges "
                        "(%g) are shorter than %g, where its area underflows double precision",
                        name, t, e, EDGE_MIN);
    }

    int *id = malloc((size_t)nraw * sizeof *id);
    int *root = malloc((size_t)nraw * sizeof *root);
    int nvert = id && root ? weld(soup, nraw, tol, lo, hi, id, root) : -1;
    if (nvert < 0) {
        free(id);
        free(root);
        return fail(err, errlen, "%s: out of memory for %d triangles", name, ntri);
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
        free(id);
        free(root);
        free(edges);
        mesh_free(m);
        return fail(err, errlen, "%s: out of memory for %d triangles", name, ntri);
    }
    for (int v = 0; v < nvert; v++)
        memcpy(m->vert + 3 * v, soup + 3 * (size_t)root[v], 3 * sizeof(double));
    memcpy(m->tri, id, (size_t)nraw * sizeof(int));
    free(id);
    free(root);

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

/* Token scanner over text with line numbers. A token longer than tok holds,
 * or one with a NUL byte in it, is kept cut but marked (bad), so that it
 * never reads as a keyword or a number. */
enum { TOK_OK, TOK_LONG, TOK_NUL };
struct scan {
    const char *p, *end;
    int line;
    char tok[128];
    int bad;        /* TOK_OK, TOK_LONG or TOK_NUL */
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
    s->bad = TOK_OK;
    while (s->p < s->end && !isspace((unsigned char)*s->p)) {
        if (*s->p == 0)
            s->bad = TOK_NUL;
        else if (n + 1 < sizeof s->tok)
            s->tok[n++] = *s->p;
        else if (s->bad == TOK_OK)
            s->bad = TOK_LONG;
        s->p++;
    }
    s->tok[n] = 0;
    return 1;
}

/* Why the current token cannot be what was expected, beyond its text. */
static const char *tok_why(const struct scan *s)
{
    return s->bad == TOK_LONG  ? " (a token longer than 127 characters)"
           : s->bad == TOK_NUL ? " (a token with a NUL byte: binary data in a text file)"
                               : "";
}

/* 1 if the current token ran up to the end of a file that does not end in
 * white space: the file was cut in the middle of it. */
static int tok_cut(const struct scan *s)
{
    return s->p == s->end;
}

static int tok_is(const struct scan *s, const char *w)
{
    if (s->bad)
        return 0;
    const char *a = s->tok;
    while (*a && *w && tolower((unsigned char)*a) == *w)
        a++, w++;
    return !*a && !*w;
}

static int tok_double(const struct scan *s, double *v)
{
    char *e;
    if (s->bad)
        return 0;
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

/* The message for triangle t when `what` was expected: the file ended
 * (have = 0), ended in the middle of the current token, or holds a wrong one. */
static int stl_fail(const struct scan *s, int have, const char *path, const char *what, int t,
                    char *err, size_t errlen)
{
    if (!have)
        return fail(err, errlen, "%s:%d: unexpected end of file: the file is cut short in "
                    "triangle %d, expected %s", path, s->line, t, what);
    if (tok_cut(s))
        return fail(err, errlen, "%s:%d: the file is cut short in triangle %d: it ends in "
                    "'%.40s', expected %s", path, s->line, t, s->tok, what);
    return fail(err, errlen, "%s:%d: expected %s, got '%.40s'%s (triangle %d)", path, s->line,
                what, s->tok, tok_why(s), t);
}

static int stl_expect(struct scan *s, const char *path, const char *w, int t, char *err,
                      size_t errlen)
{
    int have = next_tok(s);
    if (have && tok_is(s, w))
        return 0;
    char what[32];
    snprintf(what, sizeof what, "'%s'", w);
    return stl_fail(s, have, path, what, t, err, errlen);
}

/* The next token as a number of triangle t. */
static int stl_number(struct scan *s, const char *path, const char *what, int t, double *v,
                      char *err, size_t errlen)
{
    int have = next_tok(s);
    if (have && tok_double(s, v) && !tok_cut(s))
        return 0;
    return stl_fail(s, have, path, what, t, err, errlen);
}

static int read_stl_ascii(const char *path, const char *text, size_t len, struct soup *out,
                          char *err, size_t errlen)
{
    struct scan s = {text, text + len, 1, {0}, TOK_OK};
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
            return fail(err, errlen, "%s:%d: expected 'facet' or 'endsolid', got '%.40s'%s "
                        "(triangle %d)", path, s.line, s.tok, tok_why(&s), t);
        if (!in_solid)
            return fail(err, errlen, "%s:%d: 'facet' outside 'solid' (triangle %d)", path,
                        s.line, t);
        if (stl_expect(&s, path, "normal", t, err, errlen))
            return -1;
        for (int c = 0; c < 3; c++) {
            double dummy;
            if (stl_number(&s, path, "a facet normal component", t, &dummy, err, errlen))
                return -1;
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
                if (stl_number(&s, path, "a vertex coordinate", t, &tri[3 * k + c], err,
                               errlen))
                    return -1;
        }
        int have = next_tok(&s);
        if (have && tok_is(&s, "vertex"))
            return fail(err, errlen, "%s:%d: triangle %d has more than 3 vertices", path,
                        s.line, t);
        if (!have || !tok_is(&s, "endloop"))
            return stl_fail(&s, have, path, "'endloop'", t, err, errlen);
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
    /* at least "3 i j k" (or an offset and "i j k") and a separator per
     * triangle, or 16 bytes of binary values: a large count that cannot fit
     * is refused before it is allocated (a small one is left to the reading,
     * which names the first missing triangle) */
    if (ncell > 4096 && ncell * (bin ? 16 : 8) > (long)(s->end - s->p) + 1)
        return fail(err, errlen, "%s:%d: %s: %ld triangles cannot fit in the %ld bytes left in "
                    "the file (cut short?)", path, s->line, kw, ncell, (long)(s->end - s->p));
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
    struct scan s = {text, text + len, 1, {0}, TOK_OK};
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
            if (npts >= 0) { /* the cells read so far index the first one */
                rc = fail(err, errlen, "%s:%d: a second POINTS section", path, s.line);
                break;
            }
            if (!next_tok(&s) || !tok_double(&s, &v) || v < 0 || v > 3e8 || !next_tok(&s) ||
                ((type = vtk_type(s.tok)) < 0 && bin)) {
                rc = fail(err, errlen, "%s:%d: bad POINTS line", path, s.line);
                break;
            }
            npts = (long)v;
            /* at least "x y z" and a separator per point, or 3 binary values:
             * a large count that cannot fit is refused before it is allocated
             * (a small one is left to the reading, which names the point) */
            long per = bin ? 3 * (type == VT_F64 || type == VT_I64 ? 8 : 4) : 6;
            if (npts > 4096 && npts * per > (long)(s.end - s.p) + 1) {
                rc = fail(err, errlen, "%s:%d: POINTS: %ld points cannot fit in the %ld bytes "
                          "left in the file (cut short?)", path, s.line, npts,
                          (long)(s.end - s.p));
                break;
            }
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

/* Text with at most 1 % NUL bytes, or one (a text file that picked up a
 * stray NUL, not a binary STL, whose header padding and floats are not text):
 * 1, with the first NUL's offset and line in *nul_at / *nul_line (-1: none). */
static int text_like(const unsigned char *b, size_t len, long *nul_at, int *nul_line)
{
    size_t nul = 0;
    int line = 1;
    *nul_at = -1;
    *nul_line = 0;
    for (size_t i = 0; i < len; i++) {
        unsigned char c = b[i];
        if (c == 0) {
            if (!nul++) {
                *nul_at = (long)i;
                *nul_line = line;
            }
        } else if (!(c >= 32 && c < 127) && !isspace(c)) {
            return 0;
        }
        line += c == '\n';
    }
    return nul <= 1 || nul * 100 <= len;
}

/* The message for a file that is neither binary STL (size not 84 + 50 n)
 * nor legacy VTK, when it is text: an ASCII STL with a NUL byte, or no mesh. */
static int text_not_mesh(const char *path, const unsigned char *buf, size_t len, size_t skip,
                         long nul_at, int nul_line, char *err, size_t errlen)
{
    if (len - skip >= 5 && !strncasecmp((const char *)buf + skip, "solid", 5))
        return fail(err, errlen, "%s:%d: ASCII STL file with a NUL byte (offset %ld): a text "
                    "file must not hold binary data", path, nul_line, nul_at);
    char head[24];
    size_t n = 0;
    for (size_t i = skip; i < len && n + 1 < sizeof head && buf[i] != '\n'; i++)
        head[n++] = buf[i] ? (char)buf[i] : ' ';
    head[n] = 0;
    return fail(err, errlen, "%s: not a mesh file: text that starts with '%s'%s (expected "
                "'solid' of an ASCII STL, '# vtk' of a legacy VTK file, or a binary STL of 84 "
                "+ 50 n bytes)", path, head, nul_at >= 0 ? " and holds a NUL byte" : "");
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
        long nul_at;
        int nul_line;
        if (ascii)
            rc = read_stl_ascii(path, text, len, &soup, err, errlen);
        else if (!binary_fits && text_like(buf, len, &nul_at, &nul_line))
            rc = text_not_mesh(path, buf, len, skip, nul_at, nul_line, err, errlen);
        else
            rc = read_stl_binary(path, buf, len, &soup, err, errlen);
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

int mesh_check_range(const struct mesh *m, const char *name, char *err, size_t errlen)
{
    for (int v = 0; v < m->nvert; v++)
        for (int d = 0; d < 3; d++)
            if (!(fabs(m->vert[3 * v + d]) <= COORD_MAX))
                return fail(err, errlen, "%s: scale, move or rotate puts vertex %d at (%g, %g, "
                            "%g), beyond %g: triangle areas would overflow double precision",
                            name, v, m->vert[3 * v], m->vert[3 * v + 1], m->vert[3 * v + 2],
                            COORD_MAX);
    for (int t = 0; t < m->ntri; t++) {
        const double *a = m->vert + 3 * m->tri[3 * t], *b = m->vert + 3 * m->tri[3 * t + 1],
                     *c = m->vert + 3 * m->tri[3 * t + 2];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
        double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        if (!(nn > 0) || !isfinite(nn))
            return fail(err, errlen, "%s: scale, move or rotate leaves triangle %d without an "
                        "area in double precision (its normal is undefined)", name, t);
    }
    return 0;
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
    /* the grid spans the box grown by reach and cells of 2 reach: both finite */
    if (!isfinite(2 * reach + ext))
        return fail(err, errlen, "distance %g is too large for the mesh grid (its extent, the "
                    "mesh grown by it on both sides, overflows double precision)", reach);
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
