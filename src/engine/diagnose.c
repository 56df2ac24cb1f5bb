/* diagnose.c - descriptions of lost and non-finite particles (diagnose.h). */
#include "diagnose.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "device.h"
#include "domain.h"
#include "pair.h"

/* Positions and tags at the start of the run: the host arrays, or the
 * engine's copy when the run's device buffers are those arrays (engine.h). */
struct start_view {
    int n;
    const double *x;
    const int64_t *tag;
};

static const struct start_copy *start_copy(const struct gravel *g)
{
    return g->eng && g->eng->start.x ? &g->eng->start : NULL;
}

static struct start_view start_of_run(const struct gravel *g)
{
    const struct start_copy *c = start_copy(g);
    if (c)
        return (struct start_view){c->n, c->x, c->tag};
    return (struct start_view){g->atoms.n, g->atoms.x, g->atoms.tag};
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
    const double *src = NULL;
    if (c) {
        for (int k = 0; k < c->nfast && !src; k++)
            if (c->fast_tag[k] == tag)
                src = c->fast_v + 3 * k;
    } else {
        for (int i = 0; i < g->atoms.n && !src; i++)
            if (g->atoms.tag[i] == tag && diag_fast(g, g->atoms.v + 3 * i, g->atoms.radius[i]))
                src = g->atoms.v + 3 * i;
    }
    if (src)
        memcpy(v, src, 3 * sizeof *v);
    return src != NULL;
}

/* The largest finite velocity component at the start of the run. */
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
    const struct start_view a = start_of_run(g);
    int i = index_of(a.tag, a.n, tag);
    if (i < 0)
        return 0;
    const double *xi = a.x + 3 * i;
    double radi = radius_of(g, tag);
    long long start = (long long)g->firststep;
    /* the nearest other atom at the start of the run (periodic images) */
    int jmin = -1;
    double dmin = INFINITY;
    for (int j = 0; j < a.n; j++) {
        if (j == i)
            continue;
        double dx[3];
        for (int q = 0; q < 3; q++) {
            dx[q] = a.x[3 * j + q] - xi[q];
            double l = g->dom.hi[q] - g->dom.lo[q];
            if (g->dom.periodic[q] && l > 0)
                dx[q] -= l * round(dx[q] / l);
        }
        double dd = norm3(dx);
        if (dd < dmin) {
            dmin = dd;
            jmin = j;
        }
    }
    if (jmin >= 0) {
        double ri = radi, rj = radius_of(g, a.tag[jmin]);
        double overlap = ri + rj - dmin, rs = ri < rj ? ri : rj;
        if (dmin <= 1e-12 * (ri + rj)) {
            snprintf(out + o, len - o, "; at the start of the run (step %lld) atom %lld and atom "
                                       "%lld were at the same position (%.10g, %.10g, %.10g), "
                                       "so their contact has no normal direction",
                     start, tag, (long long)a.tag[jmin], xi[0], xi[1], xi[2]);
            return 1;
        }
        if (rs > 0 && overlap > 0.5 * rs) {
            snprintf(out + o, len - o, "; at the start of the run (step %lld) atom %lld "
                                       "overlapped atom %lld by %.3g (%.0f %% of the smaller "
                                       "radius %.4g; centres %.4g apart)",
                     start, tag, (long long)a.tag[jmin], overlap, 100 * overlap / rs, rs, dmin);
            return 1;
        }
    }
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

void diag_time_step(const struct gravel *g, char *out, size_t len)
{
    const struct pair *p = g->styles.pair;
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
                     "created inside each other, an absurd velocity or force, or a fix that "
                     "moves atoms", g->dt, tc, p->style->name, tc / g->dt);
        else
            snprintf(out, len,
                     "; probable cause: the time step %g vs the estimated collision time %g of "
                     "pair style %s (%.3g steps per collision; at least ~10 are needed)",
                     g->dt, tc, p->style->name, tc / g->dt);
    } else {
        snprintf(out, len, "; probable cause: a time step (%g) too large for the forces, or "
                           "overlapping particles in the initial configuration", g->dt);
    }
}
