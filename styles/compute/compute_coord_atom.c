/* compute_coord_atom.c - `compute ID group coord/atom cutoff Rc [group
 * group2-ID] [typeN ...]`: per-atom coordination numbers, as LAMMPS's
 * compute coord/atom with cstyle cutoff: for an atom i of the group, the
 * number of atoms j of group2 (default all) with |x_i - x_j| < Rc (minimum
 * image) whose type is in range N; 0 for atoms outside the group. typeN is
 * a type or a range (2, *, 1*3, 2*, *4); none = one range "*". One range
 * gives a per-atom vector, several a per-atom array with one column each.
 * Unlike LAMMPS, Rc may exceed the pair cut-off (pairs come from a host
 * cell search, src/contact/host_pairs.c). The orientorder cstyle is not
 * supported. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "compute.h"
#include "error.h"
#include "host_pairs.h"

#define COORD_MAXCOL 64

struct coord {
    double cut;
    unsigned jbit;
    int ncol, lo[COORD_MAXCOL], hi[COORD_MAXCOL];
};

static void coord_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "compute coord/atom expects a cstyle: cutoff Rc [group ID] [typeN ...]");
    if (!strcmp(argv[0], "orientorder"))
        gr_error(g, "compute coord/atom: cstyle orientorder is not supported (needs compute "
                    "orientorder/atom); use cutoff");
    if (strcmp(argv[0], "cutoff"))
        gr_error(g, "compute coord/atom: unknown cstyle '%.64s' (expected cutoff)", argv[0]);
    if (argc < 2)
        gr_error(g, "compute coord/atom cutoff expects the cut-off distance Rc");
    struct coord *cd = gr_calloc(g, 1, sizeof *cd);
    c->data = cd;
    cd->cut = arg_positive(g, argv[1], "coord/atom cutoff");
    cd->jbit = 1u;
    int i = 2;
    if (i < argc && !strcmp(argv[i], "group")) {
        arg_need(g, argc, i, 1, "group");
        cd->jbit = 1u << arg_group(g, argv[i + 1]);
        i += 2;
    }
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    if (i == argc) {
        cd->ncol = 1;
        cd->lo[0] = 1;
        cd->hi[0] = nt;
    }
    for (; i < argc; i++) {
        if (cd->ncol == COORD_MAXCOL)
            gr_error(g, "compute coord/atom: at most %d type ranges", COORD_MAXCOL);
        arg_type_range(g, argv[i], nt, &cd->lo[cd->ncol], &cd->hi[cd->ncol]);
        cd->ncol++;
    }
    c->peratom_flag = 1;
    c->size_peratom_cols = cd->ncol > 1 ? cd->ncol : 0;
}

static void coord_peratom(struct gravel *g, struct compute *c)
{
    const struct atoms *a = &g->atoms;
    const struct coord *cd = c->data;
    const int nc = cd->ncol;
    for (int k = 0; k < a->n * nc; k++)
        c->peratom[k] = 0.0;
    struct host_pair *p;
    int np = host_pairs_find(g, cd->cut, c->groupbit, cd->jbit, &p, "compute coord/atom");
    for (int k = 0; k < np; k++) {
        int ij[2] = {p[k].i, p[k].j};
        for (int s = 0; s < 2; s++) {
            int i = ij[s], j = ij[1 - s];
            if (!(a->mask[i] & c->groupbit) || !(a->mask[j] & cd->jbit))
                continue;
            for (int m = 0; m < nc; m++)
                if (a->type[j] >= cd->lo[m] && a->type[j] <= cd->hi[m])
                    c->peratom[(size_t)i * nc + m] += 1.0;
        }
    }
    free(p);
}

const struct compute_style compute_style_coord_atom = {
    .name = "coord/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = coord_create,
    .peratom = coord_peratom,
};
