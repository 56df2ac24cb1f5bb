/* compute_group_group.c - `compute ID group1 group/group group2 [pair yes|no]
 * [kspace yes|no] [boundary yes|no] [molecule off|inter|intra]`: the pair
 * interaction between two groups, as LAMMPS's compute group/group:
 *
 *   scalar     the pair energy of every pair with one atom in each group
 *   vector[3]  the force group2 exerts on group1: sum of del fpair over those
 *              pairs, del = x_1 - x_2 (minimum image)
 *
 * both extensive. A pair is one of host_pairs_local's (r below the pair
 * style's type-pair cut-off, pairs neigh_modify exclude removes left out),
 * fpair and the energy the pair style's single-pair evaluation at the
 * current positions, velocities and contact history (pair_single_eval), as
 * LAMMPS's Pair::single: for the granular styles the normal contact force
 * only, energy 0. A pair whose atoms are each in both groups adds its energy
 * and no force (the two orientations cancel, as in LAMMPS). molecule inter
 * (intra) keeps the pairs of different (equal) molecule IDs. kspace yes is
 * refused (gravel has no long-range solver); boundary only concerns kspace. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "compute.h"
#include "error.h"
#include "group.h"
#include "host_pairs.h"
#include "pair.h"
#include "pair_single_eval.h"

#define WHO "compute group/group"

enum { MOL_OFF, MOL_INTER, MOL_INTRA };

struct group_group {
    char group2[GR_NAMELEN];
    int pair, molecule;
};

static void gg_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, WHO " expects a second group ID");
    if (group_find(g, argv[0]) < 0)
        gr_error(g, WHO ": group '%.64s' does not exist", argv[0]);
    struct group_group *gg = gr_calloc(g, 1, sizeof *gg);
    c->data = gg;
    snprintf(gg->group2, sizeof gg->group2, "%s", argv[0]);
    gg->pair = 1;
    for (int i = 1; i < argc; i++) {
        const char *kw = argv[i];
        arg_need(g, argc, i, 1, kw);
        const char *v = argv[++i];
        if (!strcmp(kw, "pair"))
            gg->pair = arg_yesno(g, v, "pair");
        else if (!strcmp(kw, "kspace")) {
            if (arg_yesno(g, v, "kspace"))
                gr_error(g, WHO ": kspace yes needs a long-range solver, which gravel does not "
                            "have (kspace no)");
        } else if (!strcmp(kw, "boundary"))
            arg_yesno(g, v, "boundary");
        else if (!strcmp(kw, "molecule")) {
            if (!strcmp(v, "off"))
                gg->molecule = MOL_OFF;
            else if (!strcmp(v, "inter"))
                gg->molecule = MOL_INTER;
            else if (!strcmp(v, "intra"))
                gg->molecule = MOL_INTRA;
            else
                gr_error(g, WHO ": molecule must be off, inter or intra, got '%.32s'", v);
            if (gg->molecule != MOL_OFF && !g->atoms.molecule_flag)
                gr_error(g, WHO ": molecule %s needs molecule IDs (atom_style hybrid sphere "
                            "molecular)", v);
        } else
            gr_error(g, WHO ": unknown keyword '%.32s' (pair, kspace, boundary, molecule)", kw);
    }
    c->scalar_flag = 1;
    c->extscalar = 1;
    c->vector_flag = 1;
    c->size_vector = 3;
    c->extvector = 1;
}

static void gg_check(struct gravel *g, struct compute *c, struct pair_caps *caps)
{
    struct group_group *gg = c->data;
    if (group_find(g, gg->group2) < 0)
        gr_error(g, WHO " %s: group '%.64s' no longer exists", c->id, gg->group2);
    if (!gg->pair)
        return;
    const struct pair *p = g->styles.pair;
    if (!p)
        gr_error(g, WHO " %s needs a pair style (or pair no)", c->id);
    pair_describe(p, caps);
    if (!caps->single)
        gr_error(g, WHO " %s: pair style %s has no single-pair evaluation here (gran/hooke, "
                    "gran/hooke/history, gran/hertz/history and granular do)",
                 c->id, p->style->name);
}

static void gg_init(struct gravel *g, struct compute *c)
{
    struct pair_caps caps;
    gg_check(g, c, &caps);
}

/* the energy, returned, and the force on group 1, into force[3] */
static double gg_compute(struct gravel *g, struct compute *c, double force[3])
{
    struct group_group *gg = c->data;
    double energy = 0;
    force[0] = force[1] = force[2] = 0;
    struct pair_caps caps;
    gg_check(g, c, &caps);
    if (!gg->pair)
        return 0;
    const unsigned b1 = c->groupbit, b2 = group_bit(group_find(g, gg->group2));
    const struct atoms *a = &g->atoms;
    struct host_pair *p;
    int np = host_pairs_local(g, b1 | b2, 0, &p, WHO);
    int m = 0; /* the pairs across the groups, in host_pairs' order */
    for (int k = 0; k < np; k++) {
        const unsigned mi = a->mask[p[k].i], mj = a->mask[p[k].j];
        const int ij = (mi & b1) && (mj & b2), ji = (mj & b1) && (mi & b2);
        if (!ij && !ji)
            continue;
        if (gg->molecule != MOL_OFF &&
            (a->mol[p[k].i] == a->mol[p[k].j]) != (gg->molecule == MOL_INTRA))
            continue;
        p[m++] = p[k];
    }
    double *eng = gr_calloc(g, 2 * (size_t)m + 1, sizeof *eng), *fpair = eng + m;
    pair_single_eval(g, &caps, p, m, eng, fpair, NULL);
    for (int k = 0; k < m; k++) {
        const unsigned mi = a->mask[p[k].i], mj = a->mask[p[k].j];
        const int ij = (mi & b1) && (mj & b2), ji = (mj & b1) && (mi & b2);
        energy += eng[k];
        for (int d = 0; d < 3; d++) { /* the force on group 1's side */
            if (ij)
                force[d] += p[k].del[d] * fpair[k];
            if (ji)
                force[d] -= p[k].del[d] * fpair[k];
        }
    }
    free(eng);
    free(p);
    return energy;
}

static double gg_scalar(struct gravel *g, struct compute *c)
{
    double force[3];
    return gg_compute(g, c, force);
}

static void gg_vector(struct gravel *g, struct compute *c)
{
    gg_compute(g, c, c->vector);
}

/* several ranks: the gathered atoms in tag order and every rank's contact
 * history by tag pair, as one process */
const struct compute_style compute_style_group_group = {
    .name = "group/group",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = gg_create,
    .init = gg_init,
    .scalar = gg_scalar,
    .vector = gg_vector,
};
