/* compute_rattlers_atom.c - `compute ID group rattlers/atom type|radius
 * Nmin Ntries`: LAMMPS's (GRANULAR, 2023) rattlers of a packing, the
 * particles held by fewer than Nmin contacts with non-rattlers, found by
 * repeated removal: per-atom 1 for a rattler, 0 else; global scalar the
 * number of rattlers (extensive).
 *
 * Each pass counts, for every pair of group atoms that are both not yet
 * rattlers and closer than the cut-off (type: the pair style's type-pair
 * cut-off, LAMMPS's cutsq; radius: r_i + r_j; host_pairs_local, pairs
 * neigh_modify exclude removes left out), a contact on each side; then every
 * atom with fewer than Nmin contacts becomes a rattler (atoms outside the
 * group too, which count no contacts: LAMMPS marks them in the first pass).
 * Passes repeat until none is added, at most Ntries times (then LAMMPS's
 * warning "Rattler calculation failed to converge within max tries"). A pair
 * style acting beyond contact (cohesion, JKR, colloid) is refused, as
 * LAMMPS refuses its beyond_contact styles. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "compute.h"
#include "error.h"
#include "host_pairs.h"
#include "pair.h"

#define WHO "compute rattlers/atom"

struct rattlers {
    int radius;             /* cutoff radius (else type) */
    int nmin, ntries;
};

static void rt_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc != 3)
        gr_error(g, WHO " expects type|radius Nmin Ntries, got %d arguments", argc);
    struct rattlers *r = gr_calloc(g, 1, sizeof *r);
    c->data = r;
    if (!strcmp(argv[0], "type"))
        r->radius = 0;
    else if (!strcmp(argv[0], "radius"))
        r->radius = 1;
    else
        gr_error(g, WHO ": cut-off style must be type or radius, got '%.32s'", argv[0]);
    r->nmin = arg_int(g, argv[1], "Nmin (contacts a non-rattler needs)");
    r->ntries = arg_int(g, argv[2], "Ntries (passes at most)");
    c->scalar_flag = 1;
    c->extscalar = 1;
    c->peratom_flag = 1;
    c->size_peratom_cols = 0;
}

static void rt_init(struct gravel *g, struct compute *c)
{
    const struct pair *p = g->styles.pair;
    if (!p)
        gr_error(g, WHO " %s: no pair style is defined", c->id);
    struct pair_caps caps;
    pair_describe(p, &caps);
    if (caps.beyond)
        gr_error(g, WHO " %s does not support pair styles that act beyond contact (%s)", c->id,
                 p->style->name);
}

/* every host atom's flag into flag[] (1 rattler); returns the rattlers */
static int find(struct gravel *g, struct compute *c, double *flag)
{
    const struct rattlers *r = c->data;
    const struct atoms *a = &g->atoms;
    rt_init(g, c);
    struct host_pair *p;
    const int np = host_pairs_local(g, c->groupbit, r->radius, &p, WHO);
    int *count = gr_calloc(g, (size_t)a->n + 1, sizeof *count);
    for (int i = 0; i < a->n; i++)
        flag[i] = 0.0;
    int changed = 1, n = 0;
    for (int pass = 0; pass < r->ntries; pass++) {
        memset(count, 0, (size_t)a->n * sizeof *count);
        for (int k = 0; k < np; k++)
            if (flag[p[k].i] == 0.0 && flag[p[k].j] == 0.0) {
                count[p[k].i]++;
                count[p[k].j]++;
            }
        changed = 0;
        for (int i = 0; i < a->n; i++)
            if (count[i] < r->nmin && flag[i] == 0.0) {
                flag[i] = 1.0;
                n++;
                changed = 1;
            }
        if (!changed)
            break;
    }
    if (changed)
        gr_warn(g, "compute %s: Rattler calculation failed to converge within max tries (%d)",
                c->id, r->ntries);
    free(count);
    free(p);
    return n;
}

static void rt_peratom(struct gravel *g, struct compute *c)
{
    find(g, c, c->peratom);
}

static double rt_scalar(struct gravel *g, struct compute *c)
{
    double *flag = gr_malloc(g, ((size_t)g->atoms.n + 1) * sizeof *flag);
    const int n = find(g, c, flag);
    free(flag);
    return n;
}

/* several ranks: the pairs of every rank's atoms gathered, as one process */
const struct compute_style compute_style_rattlers_atom = {
    .name = "rattlers/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = rt_create,
    .init = rt_init,
    .scalar = rt_scalar,
    .peratom = rt_peratom,
};
