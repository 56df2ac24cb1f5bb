/* compute_pair_local.c - `compute ID group pair/local value1 value2 ...
 * [cutoff type|radius]`: one row per pair of group atoms within the
 * cut-off, as LAMMPS's compute pair/local. Values:
 *   dist            |x_i - x_j|
 *   eng             the pair style's energy of the pair (0 for granular laws)
 *   force           r fpair: the normal force (positive when repulsive)
 *   fx fy fz        del fpair: the normal force on i (del = x_i - x_j)
 * where fpair is the pair style's Pair::single (pair_caps.single), evaluated
 * with the current positions and velocities at output time, as LAMMPS does:
 * for gran/hooke, gran/hooke/history, gran/hertz/history and granular the
 * normal contact force (the tangential force is not in fx fy fz, as in
 * LAMMPS), 0 for pairs not in contact. Other pair styles give dist only.
 * pN: the style's N-th extra single() value (LAMMPS's svector), for
 * gran/hooke/history and gran/hertz/history: p1..p3 the tangential force
 * on i from the contact's stored history (the engine's, read back), p4 its
 * magnitude, p5..p7 the normal and p8..p10 the tangential relative
 * velocity.
 *
 * Rows: pairs with r < the type-pair cut-off (cutoff type, LAMMPS's
 * default) or r < r_i + r_j (cutoff radius), host_pairs_local; ordered by
 * (lower atom ID, higher), i the lower: LAMMPS lists them in its neighbor
 * list's order. One value gives a local vector, several a local array. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "compute.h"
#include "error.h"
#include "fix.h"
#include "host_pairs.h"
#include "pair.h"
#include "pair_single_eval.h"

enum { V_DIST, V_ENG, V_FORCE, V_FX, V_FY, V_FZ, V_P };
static const char *const names[] = {"dist", "eng", "force", "fx", "fy", "fz"};
#define PL_MAXVAL 32

struct pair_local {
    int n, v[PL_MAXVAL];        /* V_*, or V_P + m for pN (m = N - 1) */
    int radius;             /* cutoff radius */
    int needs_single;
};

static const struct pair *pl_pair(struct gravel *g, struct compute *c, struct pair_caps *caps);

static void pl_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    struct pair_local *pl = gr_calloc(g, 1, sizeof *pl);
    c->data = pl;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "cutoff")) {
            if (i + 1 >= argc)
                gr_error(g, "compute pair/local: cutoff expects type or radius");
            if (!strcmp(argv[i + 1], "type"))
                pl->radius = 0;
            else if (!strcmp(argv[i + 1], "radius"))
                pl->radius = 1;
            else
                gr_error(g, "compute pair/local: cutoff must be type or radius, got '%.64s'",
                         argv[i + 1]);
            i++;
            continue;
        }
        int k = -1;
        for (int q = 0; q < (int)(sizeof names / sizeof names[0]); q++)
            if (!strcmp(argv[i], names[q]))
                k = q;
        if (k < 0 && argv[i][0] == 'p' && argv[i][1] >= '1' && argv[i][1] <= '9') {
            char *end;
            long m = strtol(argv[i] + 1, &end, 10);
            if (*end || m < 1 || m > PAIR_SINGLE_SV)
                gr_error(g, "compute pair/local: invalid value '%.64s' (pN: N from 1)", argv[i]);
            k = V_P + (int)m - 1;
        }
        if (k < 0)
            gr_error(g, "compute pair/local: unknown value '%.64s' (dist eng force fx fy fz, "
                        "keyword cutoff)", argv[i]);
        if (pl->n == PL_MAXVAL)
            gr_error(g, "compute pair/local: at most %d values", PL_MAXVAL);
        pl->v[pl->n++] = k;
        if (k != V_DIST)
            pl->needs_single = 1;
    }
    if (pl->n == 0)
        gr_error(g, "compute pair/local expects at least one value (dist eng force fx fy fz)");
    c->local_flag = 1;
    c->size_local_cols = pl->n > 1 ? pl->n : 0;
    if (g->styles.pair) { /* checked again at each use: the pair style may change */
        struct pair_caps caps;
        pl_pair(g, c, &caps);
    }
}

static const struct pair *pl_pair(struct gravel *g, struct compute *c, struct pair_caps *caps)
{
    const struct pair *p = g->styles.pair;
    if (!p)
        gr_error(g, "compute pair/local %s needs a pair style", c->id);
    pair_describe(p, caps);
    struct pair_local *pl = c->data;
    int maxp = 0;
    for (int q = 0; q < pl->n; q++)
        if (pl->v[q] >= V_P && pl->v[q] - V_P + 1 > maxp)
            maxp = pl->v[q] - V_P + 1;
    if (maxp > 0 && caps->single && maxp > caps->single_extra)
        gr_error(g, "compute pair/local %s: p%d is out of range: pair style %s has %d extra "
                    "values%s", c->id, maxp, p->style->name, caps->single_extra,
                 caps->single_extra ? "" : " here (gran/hooke/history and gran/hertz/history "
                                          "have 10)");
    if (pl->needs_single && !caps->single)
        gr_error(g, "compute pair/local %s: eng, force, fx, fy, fz need the pair style's "
                    "single-pair evaluation, which pair style %s does not have here (gran/hooke, "
                    "gran/hooke/history, gran/hertz/history and granular do); dist works with "
                    "any",
                 c->id, p->style->name);
    return p;
}

static void pl_init(struct gravel *g, struct compute *c)
{
    struct pair_caps caps;
    pl_pair(g, c, &caps);
}

static void pl_local(struct gravel *g, struct compute *c)
{
    struct pair_local *pl = c->data;
    struct pair_caps caps;
    pl_pair(g, c, &caps);
    struct host_pair *p;
    int np = host_pairs_local(g, c->groupbit, pl->radius, &p, "compute pair/local");
    int nc = pl->n > 1 ? pl->n : 1;
    int wants_sv = 0;
    for (int q = 0; q < pl->n; q++)
        wants_sv |= pl->v[q] >= V_P;
    double *eng = gr_calloc(g, (size_t)np + 1, sizeof *eng);
    double *fpair = gr_calloc(g, (size_t)np + 1, sizeof *fpair);
    double *sv = wants_sv ? gr_calloc(g, (size_t)np * PAIR_SINGLE_SV + 1, sizeof *sv) : NULL;
    if (pl->needs_single)
        pair_single_eval(g, &caps, p, np, eng, fpair, sv);
    double *out = compute_local_rows(g, c, np);
    for (int k = 0; k < np; k++) {
        double r = sqrt(p[k].rsq);
        for (int q = 0; q < pl->n; q++) {
            double v = 0.0;
            switch (pl->v[q]) {
            case V_DIST: v = r; break;
            case V_ENG: v = eng[k]; break;
            case V_FORCE: v = r * fpair[k]; break;
            case V_FX: v = p[k].del[0] * fpair[k]; break;
            case V_FY: v = p[k].del[1] * fpair[k]; break;
            case V_FZ: v = p[k].del[2] * fpair[k]; break;
            default: v = sv[(size_t)k * PAIR_SINGLE_SV + (pl->v[q] - V_P)]; break;
            }
            out[(size_t)k * nc + q] = v;
        }
    }
    free(p);
    free(eng);
    free(fpair);
    free(sv);
}

/* several ranks: every value from the gathered atoms as one process (pairs in
 * atom-ID order); pN from every rank's contact history by tag pair */
const struct compute_style compute_style_pair_local = {
    .name = "pair/local",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = pl_create,
    .init = pl_init,
    .local = pl_local,
};
