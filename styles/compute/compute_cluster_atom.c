/* compute_cluster_atom.c - `compute ID group cluster/atom Rc`: per-atom
 * cluster ID, as LAMMPS's compute cluster/atom: atoms of the group are in
 * one cluster when a chain of group atoms joins them with each link closer
 * than Rc (minimum image); the cluster ID is the smallest atom ID of the
 * cluster, 0 for atoms outside the group. Unlike LAMMPS, Rc may exceed the
 * pair cut-off (pairs come from a host cell search,
 * src/contact/host_pairs.c). */
#include <stdlib.h>

#include "args.h"
#include "compute.h"
#include "error.h"
#include "host_pairs.h"

static void cluster_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, "compute cluster/atom expects one argument, the cut-off Rc, got %d", argc);
    double *cut = gr_calloc(g, 1, sizeof *cut);
    c->data = cut;
    *cut = arg_positive(g, argv[0], "cluster/atom cutoff");
    c->peratom_flag = 1;
}

static int root(int *parent, int i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

static void cluster_peratom(struct gravel *g, struct compute *c)
{
    const struct atoms *a = &g->atoms;
    const double cut = *(const double *)c->data;
    int n = a->n;
    int *parent = gr_malloc(g, (size_t)(n > 0 ? n : 1) * sizeof *parent);
    for (int i = 0; i < n; i++)
        parent[i] = i;
    struct host_pair *p;
    int np = host_pairs_find(g, cut, c->groupbit, c->groupbit, &p, "compute cluster/atom");
    for (int k = 0; k < np; k++) {
        int ri = root(parent, p[k].i), rj = root(parent, p[k].j);
        if (ri == rj)
            continue;
        /* the root carries the smallest tag of its set */
        if (a->tag[ri] < a->tag[rj])
            parent[rj] = ri;
        else
            parent[ri] = rj;
    }
    free(p);
    for (int i = 0; i < n; i++)
        c->peratom[i] = (a->mask[i] & c->groupbit) ? (double)a->tag[root(parent, i)] : 0.0;
    free(parent);
}

const struct compute_style compute_style_cluster_atom = {
    .name = "cluster/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = cluster_create,
    .peratom = cluster_peratom,
};
