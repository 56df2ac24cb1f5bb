/* compute_contact_atom.c - `compute ID group contact/atom [group2-ID]`:
 * per-atom number of contacts, as LAMMPS's compute contact/atom (the
 * optional group2 of LAMMPS 2023): for an atom i of the group, the number
 * of atoms j of group2 (default all) that touch it, |x_i - x_j| <= r_i +
 * r_j (minimum image); 0 for atoms outside the group. Contacts with walls
 * do not count. Pairs from a host cell search (src/contact/host_pairs.c). */
#include <stdlib.h>

#include "args.h"
#include "compute.h"
#include "error.h"
#include "host_pairs.h"

static void contact_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc > 1)
        gr_error(g, "compute contact/atom takes at most one argument (group2-ID), got %d",
                 argc);
    int jgroup = argc == 1 ? arg_group(g, argv[0]) : 0;
    c->data = gr_calloc(g, 1, sizeof(unsigned));
    *(unsigned *)c->data = 1u << jgroup;
    c->peratom_flag = 1;
}

static void contact_peratom(struct gravel *g, struct compute *c)
{
    const struct atoms *a = &g->atoms;
    const unsigned jbit = *(const unsigned *)c->data;
    double rmax = 0;
    for (int i = 0; i < a->n; i++) {
        c->peratom[i] = 0.0;
        if (a->radius[i] > rmax)
            rmax = a->radius[i];
    }
    if (rmax <= 0)
        return;
    struct host_pair *p;
    /* <= radsum: search a hair beyond the largest radius sum */
    int np = host_pairs_find(g, 2 * rmax * (1 + 1e-12) + 1e-300, c->groupbit, jbit, &p,
                             "compute contact/atom");
    for (int k = 0; k < np; k++) {
        int i = p[k].i, j = p[k].j;
        double rs = a->radius[i] + a->radius[j];
        if (p[k].rsq > rs * rs)
            continue;
        if ((a->mask[i] & c->groupbit) && (a->mask[j] & jbit))
            c->peratom[i] += 1.0;
        if ((a->mask[j] & c->groupbit) && (a->mask[i] & jbit))
            c->peratom[j] += 1.0;
    }
    free(p);
}

const struct compute_style compute_style_contact_atom = {
    .name = "contact/atom",
    .ranks = COMPUTE_RANKS_GATHER, /* whole counts: any order gives the same values */
    .create = contact_create,
    .peratom = contact_peratom,
};
