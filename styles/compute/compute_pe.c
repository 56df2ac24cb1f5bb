/* compute_pe.c - the potential energies, as LAMMPS's:
 *   compute ID all pe [pair] [bond] [angle] [dihedral] [improper] [kspace] [fix]
 *       global scalar (extensive): the pair style's energy (thermo epair;
 *       granular contact laws have none, 0 as LAMMPS) and, with `fix`, the
 *       energies of the fixes with fix_modify energy yes; no keyword: all.
 *       Molecular and long-range terms are 0 (gravel has none). Group all.
 *   compute ID group pe/atom [keywords as above]
 *       per atom: half of each of its pairs' energies (LAMMPS's eatom); the
 *       other terms and fixes add nothing per atom here (0).
 *   compute ID group pair pstyle [evalue]
 *       global scalar (extensive): the energy of pair style pstyle, the
 *       active one (evalue epair or evdwl: its energy; ecoul: 0); its
 *       global vector (pvector) is empty for every style here.
 * Their values are those of the step they are read on (during a run; 0
 * before one, as LAMMPS's energies are until a run sets them up). */
#include <stdlib.h>
#include <string.h>

#include "compute.h"
#include "error.h"
#include "fix.h"
#include "group.h"
#include "pair.h"
#include "pair_energy.h"

struct pe {
    int pair, fix;       /* the terms counted */
};

/* the keywords (pair bond angle dihedral improper kspace fix; none: all) */
static void pe_terms(struct gravel *g, struct pe *p, int argc, char **argv, const char *who)
{
    static const char *const kw[] = {"pair", "bond", "angle", "dihedral", "improper",
                                     "kspace", "fix", NULL};
    if (argc == 0) {
        p->pair = p->fix = 1;
        return;
    }
    for (int i = 0; i < argc; i++) {
        int k = 0;
        while (kw[k] && strcmp(kw[k], argv[i]))
            k++;
        if (!kw[k])
            gr_error(g, "%s: unknown keyword '%.64s' (pair bond angle dihedral improper "
                        "kspace fix)",
                     who, argv[i]);
        p->pair |= k == 0;
        p->fix |= k == 6;
    }
}

static void pe_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (c->igroup != 0)
        gr_error(g, "compute pe must use group all");
    struct pe *p = gr_calloc(g, 1, sizeof *p);
    c->data = p;
    pe_terms(g, p, argc, argv, "compute pe");
    c->scalar_flag = 1;
    c->extscalar = 1;
}

static double pe_scalar(struct gravel *g, struct compute *c)
{
    const struct pe *p = c->data;
    return (p->pair ? pair_energy(g) : 0.0) + (p->fix ? fix_energy_sum(g) : 0.0);
}

static void peatom_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    struct pe *p = gr_calloc(g, 1, sizeof *p);
    c->data = p;
    pe_terms(g, p, argc, argv, "compute pe/atom");
    c->peratom_flag = 1;
}

static void peatom_peratom(struct gravel *g, struct compute *c)
{
    const struct pe *p = c->data;
    const struct atoms *a = &g->atoms;
    double *e = c->peratom;
    memset(e, 0, (size_t)a->n * sizeof *e);
    if (p->pair)
        pair_energy_atoms(g, e); /* host order = device order: the host arrays are synced */
    for (int i = 0; i < a->n; i++)
        if (!(a->mask[i] & c->groupbit))
            e[i] = 0.0;
}

struct pair_e {
    char style[GR_NAMELEN];
    int coul;            /* evalue ecoul: 0 */
};

static void cpair_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1 || argc > 3)
        gr_error(g, "compute pair expects pstyle [nsub] [evalue], got %d arguments", argc);
    struct pair_e *p = gr_calloc(g, 1, sizeof *p);
    c->data = p;
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, "compute pair: pair style '%.64s...' is too long", argv[0]);
    strcpy(p->style, argv[0]);
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "epair") || !strcmp(argv[i], "evdwl"))
            p->coul = 0;
        else if (!strcmp(argv[i], "ecoul"))
            p->coul = 1;
        else
            gr_error(g, "compute pair: '%.64s': sub-style numbers (nsub) and evalues other "
                        "than epair, evdwl, ecoul are not supported",
                     argv[i]);
    }
    c->scalar_flag = 1;
    c->extscalar = 1;
}

static void cpair_init(struct gravel *g, struct compute *c)
{
    const struct pair_e *p = c->data;
    const struct pair *ps = g->styles.pair;
    if (!ps || strcmp(ps->style->name, p->style))
        gr_error(g, "unrecognized pair style %s in compute pair %s (the active pair style is "
                    "%s; sub-styles of hybrid are not supported)",
                 p->style, c->id, ps ? ps->style->name : "none");
}

static double cpair_scalar(struct gravel *g, struct compute *c)
{
    const struct pair_e *p = c->data;
    cpair_init(g, c);
    return p->coul ? 0.0 : pair_energy(g);
}

const struct compute_style compute_style_pe = {
    .name = "pe",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = pe_create,
    .scalar = pe_scalar,
};

const struct compute_style compute_style_pe_atom = {
    .name = "pe/atom",
    .ranks = COMPUTE_RANKS_NO,
    .create = peatom_create,
    .peratom = peatom_peratom,
};

const struct compute_style compute_style_pair = {
    .name = "pair",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = cpair_create,
    .init = cpair_init,
    .scalar = cpair_scalar,
};
