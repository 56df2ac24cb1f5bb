/* reset_atom_ids.c - `reset_atom_ids [sort yes|no]` as LAMMPS 2021
 * (reset_atom_ids.cpp), one process:
 * atoms are first wrapped into the periodic box and shrink-wrapped faces
 * refitted (LAMMPS's pbc + reset_box); then the IDs become 1..N
 *   sort no (default)  in storage order (LAMMPS's tag_extend)
 *   sort yes           in spatial order: the atoms' bounding box, grown by
 *                      1e-4 of its length per side (a flat extent first
 *                      widened to 1), is cut into cubic bins holding about
 *                      10 atoms each (N / 10 + 1 bins); bins are numbered x
 *                      fastest, then z slowest, and inside a bin atoms are
 *                      ordered by x, then y, then z (a stable sort: ties
 *                      keep storage order), as LAMMPS's rendezvous sort.
 * Prints "Resetting atom IDs ...". Refused while a fix holds atoms by their
 * IDs (FIX_STORES_IDS: fix rigid/small), as LAMMPS. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "command.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "log.h"

struct sortkey {
    long long bin;
    double x[3];
    int i;
};

static int by_bin_then_coords(const void *pa, const void *pb)
{
    const struct sortkey *a = pa, *b = pb;
    if (a->bin != b->bin)
        return a->bin < b->bin ? -1 : 1;
    for (int d = 0; d < 3; d++)
        if (a->x[d] != b->x[d])
            return a->x[d] < b->x[d] ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i); /* stable, as LAMMPS's merge sort */
}

static void sort_ids(struct gravel *g)
{
    struct atoms *a = &g->atoms;
    int n = a->n, dim = g->dom.dimension;
    if (n == 0)
        return;
    double lo[3] = {1e20, 1e20, 1e20}, hi[3] = {-1e20, -1e20, -1e20};
    for (int i = 0; i < n; i++)
        for (int d = 0; d < 3; d++) {
            lo[d] = fmin(lo[d], a->x[3 * i + d]);
            hi[d] = fmax(hi[d], a->x[3 * i + d]);
        }
    if (dim == 2)
        lo[2] = hi[2] = 0.0;
    for (int d = 0; d < 3; d++)
        if (lo[d] == hi[d]) {
            lo[d] -= 0.5;
            hi[d] += 0.5;
        }
    /* LAMMPS grows lo first, then hi from the grown length */
    for (int d = 0; d < 3; d++)
        lo[d] -= 0.0001 * (hi[d] - lo[d]);
    for (int d = 0; d < 3; d++)
        hi[d] += 0.0001 * (hi[d] - lo[d]);
    long long nest = n / 10 + 1;
    double vol = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    if (dim == 3)
        vol *= hi[2] - lo[2];
    double bin = pow(vol / (double)nest, 1.0 / dim);
    int nb[3];
    for (int d = 0; d < 3; d++)
        nb[d] = (int)((hi[d] - lo[d]) / bin) + 1;
    double inv[3] = {1.0 / (hi[0] - lo[0]), 1.0 / (hi[1] - lo[1]),
                     dim == 2 ? 0.0 : 1.0 / (hi[2] - lo[2])};
    struct sortkey *k = gr_malloc(g, (size_t)n * sizeof *k);
    for (int i = 0; i < n; i++) {
        int ib[3];
        for (int d = 0; d < 3; d++) {
            k[i].x[d] = a->x[3 * i + d];
            ib[d] = (int)((a->x[3 * i + d] - lo[d]) * inv[d] * nb[d]);
        }
        k[i].bin = (long long)ib[2] * nb[1] * nb[0] + (long long)ib[1] * nb[0] + ib[0];
        k[i].i = i;
    }
    qsort(k, (size_t)n, sizeof *k, by_bin_then_coords);
    for (int r = 0; r < n; r++)
        a->tag[k[r].i] = r + 1;
    free(k);
}

void cmd_reset_atom_ids(struct gravel *g, int argc, char **argv)
{
    domain_require_box(g);
    int sort = 0;
    for (int i = 0; i < argc; i += 2) {
        if (strcmp(argv[i], "sort"))
            gr_error(g, "unknown keyword '%.32s' (sort)", argv[i]);
        arg_need(g, argc, i, 1, argv[i]);
        sort = arg_yesno(g, argv[i + 1], "sort");
    }
    /* LAMMPS: "Cannot use reset_atoms id with a fix ... storing atom IDs" */
    for (int k = 0; k < g->styles.nfix; k++) {
        const struct fix *f = g->styles.fix[k];
        if (f->style->flags & FIX_STORES_IDS)
            gr_error(g, "cannot reset atom IDs while fix %s (%s) holds atoms by their IDs (as "
                        "LAMMPS; unfix it first)",
                     f->id, f->style->name);
    }
    gr_print(g, "Resetting atom IDs ...\n");
    struct atoms *a = &g->atoms;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < a->n; i++) {
        domain_remap(g, a->x + 3 * i, a->image + 3 * i);
        for (int q = 0; q < 3; q++) {
            lo[q] = fmin(lo[q], a->x[3 * i + q]);
            hi[q] = fmax(hi[q], a->x[3 * i + q]);
        }
    }
    domain_shrink_wrap(g, lo, hi);
    if (sort)
        sort_ids(g);
    else
        for (int i = 0; i < a->n; i++)
            a->tag[i] = i + 1;
    a->maxtag = a->n;
}
