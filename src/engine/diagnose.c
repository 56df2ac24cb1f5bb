/* diagnose.c - descriptions of lost and non-finite particles (diagnose.h). */
#include "diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "pair.h"

/* What the upload kept of the run start (diag_keep_start), or NULL. */
static const struct start_copy *start_copy(const struct gravel *g)
{
    return g->eng && g->eng->start.valid ? &g->eng->start : NULL;
}

int diag_fast(const struct gravel *g, const double v[3], double radius)
{
    double s = hypot(hypot(v[0], v[1]), v[2]);
    return !isfinite(s) || (radius > 0 && s * g->dt > radius);
}

/* The velocity at the start of the run of the atom of tag when it was fast
 * (diag_fast) into v: 1, else 0. */
static int start_fast(const struct gravel *g, long long tag, double v[3])
{
    const struct start_copy *c = start_copy(g);
    for (int k = 0; c && k < c->nfast; k++)
        if (c->fast_tag[k] == tag) {
            memcpy(v, c->fast_v + 3 * k, 3 * sizeof *v);
            return 1;
        }
    return 0;
}

/* The largest finite velocity component at the start of the run (now,
 * outside a run). */
static double start_vmax(const struct gravel *g)
{
    const struct start_copy *c = start_copy(g);
    if (c)
        return c->vmax;
    double vmax = 0;
    for (int k = 0; k < 3 * g->atoms.n; k++)
        if (isfinite(g->atoms.v[k]))
            vmax = fmax(vmax, fabs(g->atoms.v[k]));
    return vmax;
}

/* Index of tag among n tags, or -1. */
static int index_of(const int64_t *tags, int n, long long tag)
{
    for (int i = 0; i < n; i++)
        if (tags[i] == tag)
            return i;
    return -1;
}

/* The radius of the atom of `tag` (host arrays, any order). */
static double radius_of(const struct gravel *g, long long tag)
{
    int i = index_of(g->atoms.tag, g->atoms.n, tag);
    return i >= 0 ? g->atoms.radius[i] : 0;
}

static double norm3(const double *a)
{
    return hypot(hypot(a[0], a[1]), a[2]); /* no overflow for huge components */
}

/* Displacement per step against the box: ", its speed S moves it D per
 * step (F box lengths in q)" for the dimension q where the ratio is largest. */
static void per_step(const struct gravel *g, const double v[3], char *out, size_t len)
{
    const double *lo = g->dom.lo, *hi = g->dom.hi;
    int qmax = 0;
    double rmax = -1;
    for (int q = 0; q < 3; q++) {
        double l = hi[q] - lo[q];
        double r = l > 0 ? fabs(v[q]) * g->dt / l : 0;
        if (r > rmax || isnan(r)) {
            rmax = r;
            qmax = q;
        }
    }
    snprintf(out, len, "; its speed %.4g moves it %.4g per step (%.3g box lengths in %c)",
             norm3(v), norm3(v) * g->dt, rmax, "xyz"[qmax]);
}

void diag_lost_atom(const struct gravel *g, long long tag, const double x[3],
                    const double v[3], char *out, size_t len)
{
    const struct domain *d = &g->dom;
    char face[160] = "";
    /* below the lo face, above the hi face (a triclinic box's faces tilt:
     * its lamda coordinates against 0 and 1) */
    int below[3], above[3];
    double lam[3];
    if (d->triclinic)
        domain_x2lamda(g, x, lam);
    for (int q = 0; q < 3; q++) {
        below[q] = d->triclinic ? !(lam[q] >= 0) : !(x[q] >= d->lo[q]);
        above[q] = d->triclinic ? !(lam[q] <= 1) : !(x[q] <= d->hi[q]);
    }
    for (int q = 0; q < 3 && !face[0]; q++) {
        if (d->periodic[q] && (below[q] || above[q]))
            snprintf(face, sizeof face, "moved more than a box length through the periodic %c "
                                        "boundaries in one step", "xyz"[q]);
        else if (below[q])
            snprintf(face, sizeof face, "crossed the %c lo boundary (%c) at %.10g", "xyz"[q],
                     d->bnd[q][0], d->lo[q]);
        else if (above[q])
            snprintf(face, sizeof face, "crossed the %c hi boundary (%c) at %.10g", "xyz"[q],
                     d->bnd[q][1], d->hi[q]);
    }
    if (!face[0])
        snprintf(face, sizeof face, "moved more than a box length in one step");
    char step[160];
    per_step(g, v, step, sizeof step);
    snprintf(out, len, "atom %lld at (%.10g, %.10g, %.10g) with velocity (%.6g, %.6g, %.6g) %s%s",
             tag, x[0], x[1], x[2], v[0], v[1], v[2], face, step);
}

int diag_nonfinite(const struct gravel *g, long long tag, const double x[3], const double v[3],
                   char *out, size_t len)
{
    int w = snprintf(out, len, "atom %lld has position (%g, %g, %g) and velocity (%g, %g, %g)",
                     tag, x[0], x[1], x[2], v[0], v[1], v[2]);
    size_t o = w > 0 && (size_t)w < len ? (size_t)w : len - 1;
    const struct start_copy *c = start_copy(g);
    long long start = (long long)g->firststep;
    for (int k = 0; c && k < c->nnear; k++) {
        const struct start_near *n = &c->near[k];
        if (n->tag != tag)
            continue;
        if (n->dist <= 1e-12 * (n->ri + n->rj)) {
            snprintf(out + o, len - o, "; at the start of the run (step %lld) atom %lld and atom "
                                       "%lld were at the same position (%.10g, %.10g, %.10g), "
                                       "so their contact has no normal direction",
                     start, tag, (long long)n->other, n->x[0], n->x[1], n->x[2]);
            return 1;
        }
        double overlap = n->ri + n->rj - n->dist, rs = fmin(n->ri, n->rj);
        snprintf(out + o, len - o, "; at the start of the run (step %lld) atom %lld "
                                   "overlapped atom %lld by %.3g (%.0f %% of the smaller "
                                   "radius %.4g; centres %.4g apart)",
                 start, tag, (long long)n->other, overlap, 100 * overlap / rs, rs, n->dist);
        return 1;
    }
    double radi = radius_of(g, tag);
    double vi[3];
    if (start_fast(g, tag, vi)) {
        char step[160];
        per_step(g, vi, step, sizeof step);
        snprintf(out + o, len - o, "; at the start of the run (step %lld) its velocity was "
                                   "(%.6g, %.6g, %.6g), more than its radius %.4g per step%s",
                 start, vi[0], vi[1], vi[2], radi, step);
        return 1;
    }
    return 0;
}

/* ", a particle centred on a wall's surface (fix ID style, ...: ...)" naming
 * the run's fixes with walls (FIX_WALL, the first four), else "" */
static void wall_cause(const struct gravel *g, char *out, size_t len)
{
    char ids[160] = "";
    size_t o = 0;
    int nw = 0;
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *f = g->styles.fix[i];
        if (!(f->style->flags & FIX_WALL))
            continue;
        if (nw++ < 4 && o < sizeof ids) {
            int w = snprintf(ids + o, sizeof ids - o, "%sfix %.32s %s", nw > 1 ? ", " : "",
                             f->id, f->style->name);
            o += w > 0 ? (size_t)w : 0;
        }
    }
    if (nw == 0)
        out[0] = '\0';
    else
        snprintf(out, len, ", a particle centred on a wall's surface (%s%s: such a contact has "
                           "no normal direction)", ids, nw > 4 ? ", ..." : "");
}

void diag_time_step(const struct gravel *g, char *out, size_t len)
{
    const struct pair *p = g->styles.pair;
    char wall[320];
    wall_cause(g, wall, sizeof wall);
    if (p && p->caps.collision_time && g->atoms.n > 0) {
        double m = 0, r = 0, vmax = 0;
        int64_t mtag = 0;
        /* lightest particle (the lowest tag of equals: any order of the arrays); the
         * fastest at the run start */
        for (int k = 0; k < g->atoms.n; k++) {
            double mk = g->atoms.rmass[k];
            if (m == 0 || mk < m || (mk == m && g->atoms.tag[k] < mtag)) {
                m = mk;
                r = g->atoms.radius[k];
                mtag = g->atoms.tag[k];
            }
        }
        vmax = start_vmax(g);
        double tc = pair_collision_time(&p->caps, m, r, vmax > 0 ? 2 * vmax : 0);
        if (isfinite(tc) && tc / g->dt >= 10)
            snprintf(out, len,
                     "; the time step %g resolves the estimated collision time %g of pair style "
                     "%s (%.3g steps per collision), so look at the configuration: particles "
                     "created inside each other%s, an absurd velocity or force, or a fix that "
                     "moves atoms", g->dt, tc, p->style->name, tc / g->dt, wall);
        else
            snprintf(out, len,
                     "; probable cause: the time step %g vs the estimated collision time %g of "
                     "pair style %s (%.3g steps per collision; at least ~10 are needed)",
                     g->dt, tc, p->style->name, tc / g->dt);
    } else {
        snprintf(out, len, "; probable cause: a time step (%g) too large for the forces, or "
                           "overlapping particles in the initial configuration%s", g->dt, wall);
    }
}

/* ---- the run start's scan (diag_keep_start) ----
 * Each atom's nearest neighbour under diag_nonfinite's metric (the box's
 * minimum image per periodic dimension, lowest index on ties), found in
 * cells of about the particle spacing by rings of growing Chebyshev
 * distance: a ring k + 1 holds no atom nearer than k cell widths, so the
 * search stops when that exceeds the nearest so far or the largest reach a
 * reported neighbour can have (its radius plus the largest radius). */
struct grid {
    int n[3];
    double lo[3], len[3], w[3], wmin;
    int periodic[3];
    int *head, *next, *stamp;
};

static int grid_coord(const struct grid *gr, int q, double x)
{
    double t = (x - gr->lo[q]) / gr->w[q];
    if (gr->periodic[q]) {
        t = fmod(t, (double)gr->n[q]);
        if (t < 0)
            t += gr->n[q];
    }
    if (!(t >= 0))
        return 0;
    return t >= gr->n[q] - 1 ? gr->n[q] - 1 : (int)t;
}

static int finite3(const double *x) { return isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]); }

/* Cells of width at least `width` (the box's width where that is 0), at most
 * 2 n + 8 of them. */
static void grid_make(struct gravel *g, struct grid *gr, double width)
{
    const struct atoms *at = &g->atoms;
    size_t ncell;
    for (;;) {
        ncell = 1;
        gr->wmin = INFINITY;
        for (int q = 0; q < 3; q++) {
            gr->lo[q] = g->dom.lo[q];
            gr->len[q] = g->dom.hi[q] - g->dom.lo[q];
            gr->periodic[q] = g->dom.periodic[q] && gr->len[q] > 0;
            double m = width > 0 && gr->len[q] > 0 ? floor(gr->len[q] / width) : 1;
            gr->n[q] = m >= 1 && m < 1 << 20 ? (int)m : m >= 1 ? 1 << 20 : 1;
            gr->w[q] = gr->len[q] > 0 ? gr->len[q] / gr->n[q] : 1;
            gr->wmin = fmin(gr->wmin, gr->w[q]);
            ncell *= (size_t)gr->n[q];
        }
        if (ncell <= 2 * (size_t)at->n + 8)
            break;
        width = width > 0 ? 1.26 * width : 1;
    }
    gr->head = gr_malloc(g, ncell * sizeof *gr->head);
    gr->stamp = gr_calloc(g, ncell, sizeof *gr->stamp);
    gr->next = gr_malloc(g, (size_t)at->n * sizeof *gr->next);
    memset(gr->head, -1, ncell * sizeof *gr->head);
    for (int i = at->n - 1; i >= 0; i--) { /* each cell's list in index order */
        gr->next[i] = -1;
        if (!finite3(at->x + 3 * i))
            continue;
        size_t c = 0;
        for (int q = 2; q >= 0; q--)
            c = c * (size_t)gr->n[q] + (size_t)grid_coord(gr, q, at->x[3 * i + q]);
        gr->next[i] = gr->head[c];
        gr->head[c] = i;
    }
}

/* diag_nonfinite's displacement from atom i to atom j (the minimum image
 * where periodic: below 0.4999 of the box, round() gives 0 and changes
 * nothing), and its squared length. */
static double start_dx(const struct gravel *g, const struct grid *gr, int i, int j, double dx[3])
{
    const double *x = g->atoms.x;
    for (int q = 0; q < 3; q++) {
        dx[q] = x[3 * j + q] - x[3 * i + q];
        if (gr->periodic[q] && !(fabs(dx[q]) < 0.4999 * gr->len[q]))
            dx[q] -= gr->len[q] * round(dx[q] / gr->len[q]);
    }
    return dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
}

/* The search of one atom: the nearest so far (diag_nonfinite's distance,
 * lowest index on ties) within `reach` (no atom beyond it can matter). */
struct probe {
    int i, jbest;
    double dbest, reach;
};

/* The atoms of cell c against the probe's best. The squared length only
 * screens (with a margin for its rounding): the distance compared is
 * diag_nonfinite's own. */
static void probe_cell(const struct gravel *g, const struct grid *gr, size_t c, struct probe *p)
{
    for (int j = gr->head[c]; j >= 0; j = gr->next[j]) {
        if (j == p->i)
            continue;
        double dx[3], d2 = start_dx(g, gr, p->i, j, dx);
        double lim = p->dbest < p->reach ? p->dbest : p->reach;
        if (d2 > lim * lim * (1 + 1e-9))
            continue;
        double dd = norm3(dx);
        if (dd < p->dbest || (dd == p->dbest && j < p->jbest)) {
            p->dbest = dd;
            p->jbest = j;
        }
    }
}

/* The cells of ring k (Chebyshev distance k) around cell c0, each once
 * (stamps: a periodic dimension of fewer than 2k + 1 cells is taken whole). */
static void ring(const struct gravel *g, struct grid *gr, const int c0[3], int k, struct probe *p)
{
    int lo[3], hi[3];
    for (int q = 0; q < 3; q++) {
        lo[q] = c0[q] - k;
        hi[q] = c0[q] + k;
        if (!gr->periodic[q]) {
            lo[q] = lo[q] < 0 ? 0 : lo[q];
            hi[q] = hi[q] > gr->n[q] - 1 ? gr->n[q] - 1 : hi[q];
        } else if (2 * k + 1 >= gr->n[q]) {
            lo[q] = 0;
            hi[q] = gr->n[q] - 1;
        }
    }
    for (int a = lo[2]; a <= hi[2]; a++) {
        int oa = abs(a - c0[2]) == k, ca = (a % gr->n[2] + gr->n[2]) % gr->n[2];
        for (int b = lo[1]; b <= hi[1]; b++) {
            int ob = oa || abs(b - c0[1]) == k, cb = (b % gr->n[1] + gr->n[1]) % gr->n[1];
            size_t row = ((size_t)ca * (size_t)gr->n[1] + (size_t)cb) * (size_t)gr->n[0];
            for (int d = lo[0]; d <= hi[0]; d++) {
                if (!ob && abs(d - c0[0]) != k)
                    continue; /* inside the ring: seen */
                size_t c = row + (size_t)((d % gr->n[0] + gr->n[0]) % gr->n[0]);
                if (gr->stamp[c] == p->i + 1)
                    continue;
                gr->stamp[c] = p->i + 1;
                probe_cell(g, gr, c, p);
            }
        }
    }
}

static void add_near(struct gravel *g, struct start_copy *c, int i, int j, double dist)
{
    const struct atoms *at = &g->atoms;
    if (c->nnear == c->near_cap) {
        c->near_cap = c->near_cap ? 2 * c->near_cap : 16;
        c->near = gr_realloc(g, c->near, (size_t)c->near_cap * sizeof *c->near);
    }
    struct start_near *n = &c->near[c->nnear++];
    n->tag = at->tag[i];
    n->other = at->tag[j];
    memcpy(n->x, at->x + 3 * i, sizeof n->x);
    n->dist = dist;
    n->ri = at->radius[i];
    n->rj = at->radius[j];
}

/* The atoms that diag_nonfinite would blame on their nearest neighbour. */
static void scan_near(struct gravel *g, struct start_copy *c)
{
    const struct atoms *at = &g->atoms;
    double rmax = 0, vol = 1;
    for (int i = 0; i < at->n; i++)
        if (isfinite(at->radius[i]))
            rmax = fmax(rmax, at->radius[i]);
    for (int q = 0; q < 3; q++)
        vol *= fmax(g->dom.hi[q] - g->dom.lo[q], 0);
    /* cells of the smallest diameter (point particles: the mean spacing) */
    double rmin = rmax;
    for (int i = 0; i < at->n; i++)
        if (at->radius[i] > 0 && at->radius[i] < rmin)
            rmin = at->radius[i];
    double spacing = vol > 0 && isfinite(vol) ? cbrt(vol / at->n) : 0;
    struct grid gr;
    grid_make(g, &gr, rmin > 0 ? 2 * rmin : spacing);
    for (int i = 0; i < at->n; i++) {
        if (!finite3(at->x + 3 * i))
            continue;
        int c0[3];
        for (int q = 0; q < 3; q++)
            c0[q] = grid_coord(&gr, q, at->x[3 * i + q]);
        /* a neighbour beyond r_i + r_max can neither overlap nor sit on it;
         * ring k + 1 holds none nearer than k cell widths */
        struct probe p = {i, -1, INFINITY, at->radius[i] + rmax};
        int kmax = gr.n[0] + gr.n[1] + gr.n[2];
        for (int k = 0; k <= kmax; k++) {
            ring(g, &gr, c0, k, &p);
            if (k * gr.wmin > p.dbest || k * gr.wmin >= p.reach)
                break;
        }
        int jbest = p.jbest;
        double dbest = p.dbest;
        if (jbest < 0)
            continue;
        double ri = at->radius[i], rj = at->radius[jbest], rs = fmin(ri, rj);
        if (dbest <= 1e-12 * (ri + rj) || (rs > 0 && ri + rj - dbest > 0.5 * rs))
            add_near(g, c, i, jbest, dbest);
    }
    free(gr.head);
    free(gr.next);
    free(gr.stamp);
}

void diag_free_start(struct start_copy *c)
{
    free(c->near);
    free(c->fast_tag);
    free(c->fast_v);
    memset(c, 0, sizeof *c);
}

void diag_keep_start(struct gravel *g)
{
    struct start_copy *c = &g->eng->start;
    const struct atoms *at = &g->atoms;
    diag_free_start(c);
    c->valid = 1;
    if (at->n == 0)
        return;
    scan_near(g, c);
    for (int i = 0; i < at->n; i++) {
        const double *v = at->v + 3 * i;
        for (int q = 0; q < 3; q++)
            if (isfinite(v[q]))
                c->vmax = fmax(c->vmax, fabs(v[q]));
        if (diag_fast(g, v, at->radius[i])) {
            if (c->nfast == c->fast_cap) {
                c->fast_cap = c->fast_cap ? 2 * c->fast_cap : 16;
                c->fast_tag = gr_realloc(g, c->fast_tag, (size_t)c->fast_cap * sizeof *c->fast_tag);
                c->fast_v = gr_realloc(g, c->fast_v, 3 * (size_t)c->fast_cap * sizeof *c->fast_v);
            }
            c->fast_tag[c->nfast] = at->tag[i];
            memcpy(c->fast_v + 3 * c->nfast, v, 3 * sizeof *v);
            c->nfast++;
        }
    }
}
