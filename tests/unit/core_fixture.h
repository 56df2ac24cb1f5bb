/* core_fixture.h - scenes for the core tests built directly in C (box,
 * atoms, groups), so the core is tested without the state commands. */
#ifndef CORE_FIXTURE_H
#define CORE_FIXTURE_H

#include <math.h>
#include <stdlib.h>

#include "atoms.h"
#include "engine.h"
#include "gravel.h"
#include "neighbor.h"
#include "run.h"
#include "test.h"

/* Box lo..hi with boundary string like "ppf" (same flag on both faces). */
static inline void fx_box(struct gravel *g, const double lo[3], const double hi[3],
                          const char *bnd, int ntypes)
{
    for (int d = 0; d < 3; d++) {
        g->dom.lo[d] = lo[d];
        g->dom.hi[d] = hi[d];
        g->dom.minlo[d] = lo[d];
        g->dom.minhi[d] = hi[d];
        g->dom.bnd[d][0] = g->dom.bnd[d][1] = bnd[d];
        g->dom.periodic[d] = bnd[d] == 'p';
    }
    g->dom.box_exists = 1;
    atoms_set_ntypes(g, ntypes);
}

/* A group named `name` (next free bit); returns its index. */
static inline int fx_group(struct gravel *g, const char *name)
{
    int i = g->groups.n++;
    snprintf(g->groups.name[i], GR_NAMELEN, "%s", name);
    g->groups.used[i] = 1;
    return i;
}

static inline double fx_rand(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return ((*s >> 8) & 0xffffff) / (double)0x1000000;
}

/* n spheres at random non-overlapping-ish positions (a jittered lattice with
 * spacing a), radii in [rlo, rhi], density 1, random velocities of size v. */
static inline void fx_spheres(struct gravel *g, int nx, int ny, int nz, double a, double rlo,
                              double rhi, double v, unsigned seed)
{
    unsigned s = seed;
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                double x[3] = {g->dom.lo[0] + a * (i + 0.5) + 0.1 * a * (fx_rand(&s) - 0.5),
                               g->dom.lo[1] + a * (j + 0.5) + 0.1 * a * (fx_rand(&s) - 0.5),
                               g->dom.lo[2] + a * (k + 0.5) + 0.1 * a * (fx_rand(&s) - 0.5)};
                double r = rlo + (rhi - rlo) * fx_rand(&s);
                int id = atoms_add(g, 0, 1, x, r, 4.0 / 3.0 * M_PI * r * r * r);
                for (int d = 0; d < 3; d++)
                    g->atoms.v[3 * id + d] = v * (fx_rand(&s) - 0.5);
            }
}

/* Total of a host per-atom 3-vector array. */
static inline void fx_sum3(const struct gravel *g, const double *a, double out[3])
{
    out[0] = out[1] = out[2] = 0;
    for (int i = 0; i < g->atoms.n; i++)
        for (int d = 0; d < 3; d++)
            out[d] += a[3 * i + d];
}

/* Host arrays sorted by tag: position of tag t (1-based tags 1..n assumed). */
static inline int fx_index_of(const struct gravel *g, int64_t tag)
{
    return atoms_find_tag(&g->atoms, tag);
}

#endif
