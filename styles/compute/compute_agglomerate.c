/* compute_agglomerate.c - `compute ID group agglomerate [file F] [minsize N]`:
 * agglomerates as in Andrews (2018), source document 000 sec. 6.2.1: sets of
 * particles connected by body contact (|x_i - x_j| < r_i + r_j; effect-surface
 * overlap alone does not join), single particles included as agglomerates of
 * size 1 with void fraction 0.
 *
 * Global vector (thermo: c_ID[1] .. c_ID[5]), over agglomerates of at least
 * `minsize` particles (default 1):
 *   [1] number of agglomerates
 *   [2] mean size (particles per agglomerate)
 *   [3] standard deviation of the size (population)
 *   [4] largest size
 *   [5] mean void fraction, 1 - sum V_p / V_bs (000 eq. 6.6), V_bs the volume
 *       of the exact minimum enclosing sphere of the member spheres
 *       (compute_agglomerate_mes.c)
 * `file F` writes the size histogram at every evaluation on a new timestep:
 *   "# step N_agglomerates" then one "size count" line per occurring size.
 *
 * Method (host, O(N)): a cell grid of cell size >= the largest contact
 * distance 2 r_max, contacts of the group's atoms found over the 27
 * neighbour cells with minimum image in periodic dimensions, union-find with
 * path halving and union by size; members of each agglomerate are unwrapped
 * across periodic boundaries by a breadth-first walk over its contacts so the
 * enclosing sphere sees the cluster whole. The result is cached per step
 * and atom state (thermo reads the five values one by one). Cost: 10^6
 * particles in one touching cluster ~1.5 s, 10^6 isolated ~0.3 s. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "compute.h"
#include "compute_agglomerate_mes.h"
#include "error.h"
#include "fileio.h"
#include "host_pairs.h"

struct agg {
    char *file;
    FILE *fp;
    int fp_err; /* errno of the first failed write to fp */
    int minsize;
    long long last_step;
    /* thermo asks for c_ID[1] .. c_ID[5] one by one: the clustering is
     * redone only when the step or the atoms (positions, radii, groups)
     * changed since the last evaluation */
    int cached;
    long long cache_step;
    uint64_t cache_hash;
    double cache[5];
};

/* FNV-1a over the bytes the result depends on. */
static uint64_t state_hash(const struct gravel *g, unsigned groupbit)
{
    const struct atoms *a = &g->atoms;
    uint64_t h = 1469598103934665603ull ^ (uint64_t)a->n ^ ((uint64_t)groupbit << 32);
    const unsigned char *blocks[2] = {(const unsigned char *)a->x,
                                      (const unsigned char *)a->radius};
    size_t len[2] = {3 * (size_t)a->n * sizeof(double), (size_t)a->n * sizeof(double)};
    for (int b = 0; b < 2; b++)
        for (size_t k = 0; k < len[b]; k++) {
            h ^= blocks[b][k];
            h *= 1099511628211ull;
        }
    for (int i = 0; i < a->n; i++) {
        h ^= (uint64_t)((a->mask[i] & groupbit) != 0);
        h *= 1099511628211ull;
    }
    for (int q = 0; q < 3; q++) {
        double L[2] = {g->dom.lo[q], g->dom.hi[q]};
        const unsigned char *p = (const unsigned char *)L;
        for (size_t k = 0; k < sizeof L; k++) {
            h ^= p[k];
            h *= 1099511628211ull;
        }
    }
    return h;
}

static void destroy(struct compute *c)
{
    struct agg *a = c->data;
    if (a) {
        if (a->fp)
            fclose(a->fp);
        free(a->file);
        free(a);
    }
    c->data = NULL;
}

static void create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    struct agg *a = gr_calloc(g, 1, sizeof *a);
    c->data = a;
    a->minsize = 1;
    a->last_step = -1;
    for (int i = 0; i < argc; i += 2) {
        if (!strcmp(argv[i], "file")) {
            arg_need(g, argc, i, 1, "file");
            free(a->file);
            a->file = gr_strdup(g, argv[i + 1]);
        } else if (!strcmp(argv[i], "minsize")) {
            arg_need(g, argc, i, 1, "minsize");
            a->minsize = arg_int_range(g, argv[i + 1], 1, 1 << 30, "minsize");
        } else {
            gr_error(g, "unknown compute agglomerate keyword '%.64s' (expected file or minsize)",
                     argv[i]);
        }
    }
    if (a->file) {
        const char *why;
        a->fp = fio_open_write_checked(a->file, 0, &a->fp_err, &why);
        if (!a->fp)
            gr_error(g, "compute agglomerate: cannot open histogram file '%.200s': %s", a->file,
                     why);
        fprintf(a->fp, "# Agglomerate size histogram (compute %s agglomerate)\n"
                       "# Timestep Number-of-agglomerates\n# size count\n", c->id);
        if (fflush(a->fp) != 0 || ferror(a->fp))
            gr_error(g, "compute agglomerate: cannot write histogram file '%.200s': %s",
                     a->file, strerror(a->fp_err ? a->fp_err : EIO));
    }
    c->vector_flag = 1;
    c->size_vector = 5;
    c->extvector = 0;
}

static int find(int *parent, int i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

static void unite(int *parent, int *size, int i, int j)
{
    i = find(parent, i);
    j = find(parent, j);
    if (i == j)
        return;
    if (size[i] < size[j]) {
        int t = i;
        i = j;
        j = t;
    }
    parent[j] = i;
    size[i] += size[j];
}

/* Minimum image of d for periodic length L (0: not periodic). */
static double minimg(double d, double L)
{
    if (L > 0) {
        if (d > 0.5 * L)
            d -= L * floor(d / L + 0.5);
        else if (d < -0.5 * L)
            d -= L * floor(d / L + 0.5);
    }
    return d;
}

struct edges {
    int n, cap;
    int *ij;
};

static void edge_add(struct gravel *g, struct edges *e, int i, int j)
{
    if (e->n == e->cap) {
        e->cap = e->cap ? 2 * e->cap : 1024;
        e->ij = gr_realloc(g, e->ij, (size_t)e->cap * 2 * sizeof *e->ij);
    }
    e->ij[2 * e->n] = i;
    e->ij[2 * e->n + 1] = j;
    e->n++;
}

struct contact_ctx {
    const int *idx;
    const double *L;
    struct edges *e;
};

/* One candidate pair of host_pairs_scan: an edge when the spheres touch. */
static void contact_visit(struct gravel *g, int k, int kk, void *vctx)
{
    const struct contact_ctx *c = vctx;
    const struct atoms *at = &g->atoms;
    int i = c->idx[k], j = c->idx[kk];
    double rsq = 0;
    for (int q = 0; q < 3; q++) {
        double dq = minimg(at->x[3 * i + q] - at->x[3 * j + q], c->L[q]);
        rsq += dq * dq;
    }
    double rs = at->radius[i] + at->radius[j];
    if (rsq < rs * rs)
        edge_add(g, c->e, k, kk);
}

/* Every body contact among the listed atoms (idx[0..m)), through the cell
 * grid of cells >= the largest diameter. */
static void contacts(struct gravel *g, const int *idx, int m, const double L[3],
                     struct edges *e)
{
    double rmax = 0;
    for (int k = 0; k < m; k++)
        rmax = fmax(rmax, g->atoms.radius[idx[k]]);
    struct contact_ctx c = {idx, L, e};
    host_pairs_scan(g, idx, m, 2 * rmax > 0 ? 2 * rmax : 1, contact_visit, &c);
}

static void cluster(struct gravel *g, struct compute *c);

static void vector(struct gravel *g, struct compute *c)
{
    struct agg *ag = c->data;
    uint64_t h = state_hash(g, c->groupbit);
    if (ag->cached && ag->cache_step == (long long)g->step && ag->cache_hash == h) {
        memcpy(c->vector, ag->cache, sizeof ag->cache);
        return;
    }
    cluster(g, c);
    memcpy(ag->cache, c->vector, sizeof ag->cache);
    ag->cache_step = (long long)g->step;
    ag->cache_hash = h;
    ag->cached = 1;
}

/* The clustering and statistics: fills c->vector, writes the histogram. */
static void cluster(struct gravel *g, struct compute *c)
{
    struct agg *ag = c->data;
    const struct atoms *at = &g->atoms;
    double L[3];
    if (g->dom.xy != 0.0 || g->dom.xz != 0.0 || g->dom.yz != 0.0)
        gr_error(g, "compute %s agglomerate: tilted triclinic boxes are not supported", c->id);
    for (int q = 0; q < 3; q++)
        L[q] = g->dom.periodic[q] ? g->dom.hi[q] - g->dom.lo[q] : 0.0;
    /* in tag order: the pairs, the unions and the walks, and so every digit,
     * depend on the atoms only, not on their memory order (several ranks
     * gather them in tag order, one process holds them in device order) */
    const int *ord = atoms_tag_order(g);
    int m = 0;
    int *idx = gr_malloc(g, (size_t)(at->n > 0 ? at->n : 1) * sizeof *idx);
    for (int k = 0; k < at->n; k++)
        if (at->mask[ord[k]] & c->groupbit)
            idx[m++] = ord[k];
    struct edges e = {0, 0, NULL};
    if (m > 0)
        contacts(g, idx, m, L, &e);
    size_t mm = (size_t)(m > 0 ? m : 1);
    int *parent = gr_malloc(g, mm * sizeof *parent);
    int *size = gr_malloc(g, mm * sizeof *size);
    for (int k = 0; k < m; k++) {
        parent[k] = k;
        size[k] = 1;
    }
    for (int t = 0; t < e.n; t++)
        unite(parent, size, e.ij[2 * t], e.ij[2 * t + 1]);
    /* adjacency (CSR) for the unwrapping walk */
    int *deg = gr_calloc(g, mm + 1, sizeof *deg);
    for (int t = 0; t < e.n; t++) {
        deg[e.ij[2 * t] + 1]++;
        deg[e.ij[2 * t + 1] + 1]++;
    }
    for (int k = 0; k < m; k++)
        deg[k + 1] += deg[k];
    int *adj = gr_malloc(g, (size_t)(2 * e.n > 0 ? 2 * e.n : 1) * sizeof *adj);
    int *fill = gr_malloc(g, mm * sizeof *fill);
    memcpy(fill, deg, mm * sizeof *fill);
    for (int t = 0; t < e.n; t++) {
        int a = e.ij[2 * t], b = e.ij[2 * t + 1];
        adj[fill[a]++] = b;
        adj[fill[b]++] = a;
    }
    free(fill);
    int *root = gr_malloc(g, mm * sizeof *root);
    for (int k = 0; k < m; k++)
        root[k] = find(parent, k);
    int nagg = 0, largest = 0, maxsize = 0;
    double ssum = 0, ssq = 0, vsum = 0;
    for (int k = 0; k < m; k++)
        if (root[k] == k && size[k] > maxsize)
            maxsize = size[k];
    long *hist = gr_calloc(g, (size_t)maxsize + 1, sizeof *hist);
    double *pos = gr_malloc(g, 3 * mm * sizeof *pos);
    double *rad = gr_malloc(g, mm * sizeof *rad);
    int *queue = gr_malloc(g, mm * sizeof *queue);
    int *slot = gr_malloc(g, mm * sizeof *slot);
    for (int k = 0; k < m; k++)
        slot[k] = -1;
    for (int k = 0; k < m; k++) {
        if (root[k] != k)
            continue;
        int sz = size[k];
        hist[sz]++;
        if (sz < ag->minsize)
            continue;
        nagg++;
        ssum += sz;
        ssq += (double)sz * sz;
        if (sz > largest)
            largest = sz;
        if (sz == 1)
            continue; /* void fraction 0 */
        /* breadth-first walk from k, unwrapping across periodic faces */
        int head = 0, tail = 0;
        queue[tail++] = k;
        slot[k] = 0;
        for (int q = 0; q < 3; q++)
            pos[q] = at->x[3 * idx[k] + q];
        rad[0] = at->radius[idx[k]];
        int nin = 1;
        double vp = rad[0] * rad[0] * rad[0];
        while (head < tail) {
            int a = queue[head++];
            for (int s = deg[a]; s < deg[a + 1]; s++) {
                int b = adj[s];
                if (slot[b] >= 0)
                    continue;
                slot[b] = nin;
                for (int q = 0; q < 3; q++)
                    pos[3 * nin + q] =
                        pos[3 * slot[a] + q] +
                        minimg(at->x[3 * idx[b] + q] - at->x[3 * idx[a] + q], L[q]);
                rad[nin] = at->radius[idx[b]];
                vp += rad[nin] * rad[nin] * rad[nin];
                nin++;
                queue[tail++] = b;
            }
        }
        double cen[3], R;
        agg_min_sphere(nin, pos, rad, cen, &R, queue);
        vsum += 1.0 - vp / (R * R * R);
    }
    double n = nagg;
    double mean = nagg ? ssum / n : 0.0;
    double var = nagg ? ssq / n - mean * mean : 0.0;
    c->vector[0] = nagg;
    c->vector[1] = mean;
    c->vector[2] = var > 0 ? sqrt(var) : 0.0;
    c->vector[3] = largest;
    c->vector[4] = nagg ? vsum / n : 0.0;
    int werr = 0;
    if (ag->fp && (long long)g->step != ag->last_step) {
        ag->last_step = (long long)g->step;
        fprintf(ag->fp, "%lld %d\n", (long long)g->step, nagg);
        for (int s = ag->minsize; s <= maxsize; s++)
            if (hist[s])
                fprintf(ag->fp, "%d %ld\n", s, hist[s]);
        if (fflush(ag->fp) != 0 || ferror(ag->fp))
            werr = ag->fp_err ? ag->fp_err : EIO;
    }
    free(hist);
    free(pos);
    free(rad);
    free(queue);
    free(slot);
    free(root);
    free(adj);
    free(deg);
    free(parent);
    free(size);
    free(e.ij);
    free(idx);
    if (werr) /* a histogram cut short (disk full) is an error, not a quiet gap */
        gr_error(g, "compute agglomerate: cannot write histogram file '%.200s': %s", ag->file,
                 strerror(werr));
}

const struct compute_style compute_style_agglomerate = {
    .name = "agglomerate",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = create,
    .vector = vector,
    .destroy = destroy,
};
