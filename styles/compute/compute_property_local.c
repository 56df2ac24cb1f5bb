/* compute_property_local.c - `compute ID group property/local attribute
 * ... [cutoff type|radius]`: per-pair attributes, as LAMMPS's compute
 * property/local with its pair attributes:
 *   patom1 patom2   the atom IDs of the pair
 *   ptype1 ptype2   their types
 * one row per pair of group atoms within the cut-off, the same rows as
 * compute pair/local (host_pairs_local: cutoff type, LAMMPS's default, or
 * cutoff radius; ordered by the lower atom ID, atom 1 the lower). LAMMPS's
 * neighbor-list attributes (natom1 natom2 ntype1 ntype2: pairs within the
 * list's cut-off at its last build) and its bond, angle, dihedral and
 * improper attributes are refused: gravel's neighbor list is the engine's
 * and its atom styles have no bonds. One attribute gives a local vector,
 * several a local array. */
#include <stdlib.h>
#include <string.h>

#include "compute.h"
#include "error.h"
#include "host_pairs.h"

#define PR_MAXVAL 32
enum { A_ATOM1, A_ATOM2, A_TYPE1, A_TYPE2 };

struct prop_local {
    int n, v[PR_MAXVAL];
    int radius;
};

static void pr_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    static const char *const names[] = {"patom1", "patom2", "ptype1", "ptype2"};
    struct prop_local *pr = gr_calloc(g, 1, sizeof *pr);
    c->data = pr;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "cutoff")) {
            if (i + 1 >= argc)
                gr_error(g, "compute property/local: cutoff expects type or radius");
            if (!strcmp(argv[i + 1], "type"))
                pr->radius = 0;
            else if (!strcmp(argv[i + 1], "radius"))
                pr->radius = 1;
            else
                gr_error(g, "compute property/local: cutoff must be type or radius, got "
                            "'%.64s'", argv[i + 1]);
            i++;
            continue;
        }
        int k = -1;
        for (int q = 0; q < 4; q++)
            if (!strcmp(argv[i], names[q]))
                k = q;
        if (k < 0 && (!strncmp(argv[i], "natom", 5) || !strncmp(argv[i], "ntype", 5)))
            gr_error(g, "compute property/local: '%.64s' (pairs of LAMMPS's neighbor list, skin "
                        "included, as of its last build) is not supported; use patom1 patom2 "
                        "ptype1 ptype2", argv[i]);
        if (k < 0 && strchr("badi", argv[i][0]) &&
            (strstr(argv[i], "atom") || strstr(argv[i], "type")))
            gr_error(g, "compute property/local: '%.64s' needs bonds, angles, dihedrals or "
                        "impropers, which gravel's atom styles do not have", argv[i]);
        if (k < 0)
            gr_error(g, "compute property/local: unknown attribute '%.64s' (patom1 patom2 "
                        "ptype1 ptype2, keyword cutoff)", argv[i]);
        if (pr->n == PR_MAXVAL)
            gr_error(g, "compute property/local: at most %d attributes", PR_MAXVAL);
        pr->v[pr->n++] = k;
    }
    if (pr->n == 0)
        gr_error(g, "compute property/local expects at least one attribute (patom1 patom2 "
                    "ptype1 ptype2)");
    c->local_flag = 1;
    c->size_local_cols = pr->n > 1 ? pr->n : 0;
}

static void pr_local(struct gravel *g, struct compute *c)
{
    struct prop_local *pr = c->data;
    const struct atoms *a = &g->atoms;
    struct host_pair *p;
    int np = host_pairs_local(g, c->groupbit, pr->radius, &p, "compute property/local");
    int nc = pr->n > 1 ? pr->n : 1;
    double *out = compute_local_rows(g, c, np);
    for (int k = 0; k < np; k++)
        for (int q = 0; q < pr->n; q++) {
            int i = p[k].i, j = p[k].j;
            double v = 0;
            switch (pr->v[q]) {
            case A_ATOM1: v = (double)a->tag[i]; break;
            case A_ATOM2: v = (double)a->tag[j]; break;
            case A_TYPE1: v = a->type[i]; break;
            case A_TYPE2: v = a->type[j]; break;
            }
            out[(size_t)k * nc + q] = v;
        }
    free(p);
}

const struct compute_style compute_style_property_local = {
    .name = "property/local",
    .ranks = COMPUTE_RANKS_GATHER, /* pairs of the gathered atoms, in atom-ID order */
    .create = pr_create,
    .local = pr_local,
};
