/* delete_atoms.c - `delete_atoms style args [compress yes|no] [bond no]
 * [mol no]` as LAMMPS (delete_atoms.cpp), atom_style sphere:
 *   group G                  every atom of group G
 *   region R                 every atom inside region R
 *   overlap cut G1 G2        each atom of G1 closer than cut (centre to
 *                            centre, minimum image) to an atom of G2 that is
 *                            not itself deleted: atoms are visited in storage
 *                            order, so of two overlapping atoms of both groups
 *                            the first is deleted and the second kept; a
 *                            partner across a periodic face (a ghost in
 *                            LAMMPS) counts unless both atoms are candidates
 *                            and i has the larger tag
 *   porosity R f seed        (LAMMPS 2021) each atom inside R with a
 *                            RanMars(seed) draw <= f, draws in storage order
 *   random fraction|count V exact G R|NULL seed
 *                            (LAMMPS 2022 syntax) in group G and region R:
 *                            `fraction f no` a RanMars(seed) draw <= f per
 *                            atom; `fraction f yes` exactly floor(f N) and
 *                            `count n yes|no` exactly n of the N candidates,
 *                            by RanMars select_subset (as set type/subset)
 * Deleted atoms are replaced by the last atom (LAMMPS's AtomVec::copy
 * order). compress yes (default) renumbers the remaining atoms 1..N in
 * storage order (LAMMPS tag_extend); molecules and bonds do not exist
 * (mol yes, bond yes are errors). Prints "Deleted N atoms, new total = M". */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "command.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "group.h"
#include "log.h"
#include "random.h"
#include "region.h"

/* Cells of at least `cut` over the atoms, for the overlap search. */
struct cells {
    int nc[3];
    double lo[3], w[3];
    int *head, *next;
};

static int cell_of(const struct cells *c, const double x[3], int d)
{
    int k = (int)floor((x[d] - c->lo[d]) / c->w[d]);
    return k < 0 ? 0 : k >= c->nc[d] ? c->nc[d] - 1 : k;
}

static void cells_build(struct gravel *g, struct cells *c, double cut)
{
    const struct atoms *a = &g->atoms;
    long total = 1;
    for (int d = 0; d < 3; d++) {
        double lo = g->dom.lo[d], hi = g->dom.hi[d];
        for (int i = 0; i < a->n; i++) {
            lo = fmin(lo, a->x[3 * i + d]);
            hi = fmax(hi, a->x[3 * i + d]);
        }
        double len = hi - lo;
        int nc = len > 0 ? (int)(len / cut) : 1;
        if (nc < 1)
            nc = 1;
        if (nc > 1024)
            nc = 1024;
        c->nc[d] = nc;
        c->lo[d] = lo;
        c->w[d] = len > 0 ? len / nc : 1.0;
        total *= nc;
    }
    c->head = gr_malloc(g, (size_t)total * sizeof(int));
    c->next = gr_malloc(g, (size_t)(a->n > 0 ? a->n : 1) * sizeof(int));
    for (long k = 0; k < total; k++)
        c->head[k] = -1;
    for (int i = a->n - 1; i >= 0; i--) {
        long k = cell_of(c, a->x + 3 * i, 0) +
                 (long)c->nc[0] * (cell_of(c, a->x + 3 * i, 1) +
                                   (long)c->nc[1] * cell_of(c, a->x + 3 * i, 2));
        c->next[i] = c->head[k];
        c->head[k] = i;
    }
}

/* Does i have a partner j (group2, within cut) that makes LAMMPS delete it? */
static int overlap_hit(struct gravel *g, const struct cells *c, int i, double cutsq,
                       unsigned b1, unsigned b2, const char *dlist)
{
    const struct atoms *a = &g->atoms;
    const double *xi = a->x + 3 * i;
    int ci[3], span[3];
    /* a tilted box: an image across y (z) is shifted along x (and y), so
     * those dimensions visit every cell */
    const struct domain *dm = &g->dom;
    int all[3] = {dm->xy != 0.0 || dm->xz != 0.0, dm->yz != 0.0, 0};
    for (int d = 0; d < 3; d++) {
        ci[d] = cell_of(c, xi, d);
        /* a periodic dimension with few cells: visit them all (images wrap) */
        if (all[d] && c->nc[d] > 3)
            span[d] = c->nc[d];
        else
            span[d] = c->nc[d] <= 3 ? c->nc[d] : 3;
    }
    for (int dz = 0; dz < span[2]; dz++)
        for (int dy = 0; dy < span[1]; dy++)
            for (int dx = 0; dx < span[0]; dx++) {
                int cc[3], off[3] = {dx, dy, dz}, skip = 0;
                for (int d = 0; d < 3; d++) {
                    int k = c->nc[d] <= 3 || span[d] == c->nc[d] ? off[d] : ci[d] - 1 + off[d];
                    if (k < 0 || k >= c->nc[d]) {
                        if (!domain_contact_periodic(g, d)) {
                            skip = 1;
                            break;
                        }
                        k = (k + c->nc[d]) % c->nc[d];
                    }
                    cc[d] = k;
                }
                if (skip)
                    continue;
                long k = cc[0] + (long)c->nc[0] * (cc[1] + (long)c->nc[1] * cc[2]);
                for (int j = c->head[k]; j >= 0; j = c->next[j]) {
                    if (j == i || !(a->mask[j] & b2))
                        continue;
                    double del[3], raw[3];
                    for (int d = 0; d < 3; d++)
                        del[d] = raw[d] = xi[d] - a->x[3 * j + d];
                    domain_minimum_image(g, del);
                    if (del[0] * del[0] + del[1] * del[1] + del[2] * del[2] >= cutsq)
                        continue;
                    int ghost = del[0] != raw[0] || del[1] != raw[1] || del[2] != raw[2];
                    if (!ghost) {
                        if (dlist[j])
                            continue;
                    } else if ((a->mask[i] & b2) && (a->mask[j] & b1)) {
                        if (a->tag[i] > a->tag[j])
                            continue;
                    }
                    return 1;
                }
            }
    return 0;
}

static void delete_overlap(struct gravel *g, double cut, int g1, int g2, char *dlist)
{
    struct atoms *a = &g->atoms;
    unsigned b1 = group_bit(g1), b2 = group_bit(g2);
    struct cells c = {0};
    /* the cells and their scratch are freed on error by the caller's unwind:
     * nothing below raises */
    cells_build(g, &c, cut);
    for (int i = 0; i < a->n; i++)
        if ((a->mask[i] & b1) && overlap_hit(g, &c, i, cut * cut, b1, b2, dlist))
            dlist[i] = 1;
    free(c.head);
    free(c.next);
}

/* Exactly n of the candidates (cand[i] = 1), LAMMPS's select_subset. */
static void delete_subset(struct gravel *g, const char *cand, bigint n, int seed, char *dlist)
{
    struct atoms *a = &g->atoms;
    int count = 0;
    for (int i = 0; i < a->n; i++)
        count += cand[i];
    if (n > count)
        gr_error(g, "delete_atoms random: count %lld is more than the %d candidate atoms",
                 (long long)n, count);
    int *flag = gr_malloc(g, (size_t)(count > 0 ? count : 1) * sizeof(int));
    int *work = malloc((size_t)(count > 0 ? count : 1) * sizeof(int));
    if (!work) {
        free(flag);
        gr_error(g, "out of memory");
    }
    struct rng_mars rm;
    rng_mars_init(&rm, seed);
    rng_mars_select_subset(&rm, n, count, flag, work);
    for (int i = 0, k = 0; i < a->n; i++)
        if (cand[i])
            dlist[i] = (char)flag[k++];
    free(flag);
    free(work);
}

static int parse_seed(struct gravel *g, const char *s)
{
    return arg_int_range(g, s, 1, 900000000, "random seed");
}

void cmd_delete_atoms(struct gravel *g, int argc, char **argv)
{
    domain_require_box(g);
    struct atoms *a = &g->atoms;
    const char *style = argv[0];
    int nstyle;
    if (!strcmp(style, "group") || !strcmp(style, "region"))
        nstyle = 2;
    else if (!strcmp(style, "overlap"))
        nstyle = 4;
    else if (!strcmp(style, "porosity"))
        nstyle = 4;
    else if (!strcmp(style, "random"))
        nstyle = 7;
    else
        gr_error(g, "unknown style '%.32s': expected group, region, overlap, porosity or random",
                 style);
    if (argc < nstyle)
        gr_error(g, "style %s needs %d arguments, got %d", style, nstyle - 1, argc - 1);
    int compress = 1;
    for (int i = nstyle; i < argc; i += 2) {
        const char *kw = argv[i];
        arg_need(g, argc, i, 1, kw);
        if (!strcmp(kw, "compress")) {
            compress = arg_yesno(g, argv[i + 1], kw);
        } else if (!strcmp(kw, "mol") || !strcmp(kw, "bond")) {
            if (arg_yesno(g, argv[i + 1], kw))
                gr_error(g, "%s yes: atom_style sphere has no molecules or bonds", kw);
        } else {
            gr_error(g, "unknown keyword '%.32s' (compress, mol, bond)", kw);
        }
    }

    /* compress renumbers the atoms left: a fix holding atoms by their IDs
     * (rigid/small) would then hold other atoms (reset_atom_ids refuses the
     * same, as LAMMPS) */
    for (int k = 0; compress && k < g->styles.nfix; k++) {
        const struct fix *f = g->styles.fix[k];
        if (f->style->flags & FIX_STORES_IDS)
            gr_error(g, "compress yes would renumber the atoms that fix %s (%s) holds by their "
                        "IDs: use compress no",
                     f->id, f->style->name);
    }

    /* validate every argument before deleting anything */
    struct region *r = NULL;
    int g1 = 0, g2 = 0, seed = 0, exact = 0, count_style = 0;
    double cut = 0, frac = 0;
    bigint count = 0;
    if (!strcmp(style, "group")) {
        g1 = arg_group(g, argv[1]);
    } else if (!strcmp(style, "region")) {
        r = region_get(g, argv[1]);
    } else if (!strcmp(style, "overlap")) {
        cut = arg_positive(g, argv[1], "overlap cutoff");
        g1 = arg_group(g, argv[2]);
        g2 = arg_group(g, argv[3]);
    } else if (!strcmp(style, "porosity")) {
        r = region_get(g, argv[1]);
        frac = arg_double(g, argv[2], "porosity fraction");
        if (frac < 0 || frac > 1)
            gr_error(g, "porosity fraction must be in [0, 1], got %s", argv[2]);
        seed = parse_seed(g, argv[3]);
    } else {
        if (!strcmp(argv[1], "fraction")) {
            frac = arg_double(g, argv[2], "fraction");
            if (frac < 0 || frac > 1)
                gr_error(g, "fraction must be in [0, 1], got %s", argv[2]);
        } else if (!strcmp(argv[1], "count")) {
            count_style = 1;
            count = arg_bigint(g, argv[2], "count");
            if (count < 0)
                gr_error(g, "count must not be negative, got %s", argv[2]);
        } else {
            gr_error(g, "random needs fraction or count, got '%.32s'", argv[1]);
        }
        exact = arg_yesno(g, argv[3], "exact flag");
        g1 = arg_group(g, argv[4]);
        if (strcmp(argv[5], "NULL"))
            r = region_get(g, argv[5]);
        seed = parse_seed(g, argv[6]);
    }

    int n0 = a->n;
    char *dlist = gr_calloc(g, (size_t)(n0 > 0 ? n0 : 1), 1);
    char *cand = calloc((size_t)(n0 > 0 ? n0 : 1), 1); /* random: the candidates */
    if (!cand) {
        free(dlist);
        gr_error(g, "out of memory");
    }
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        free(dlist);
        free(cand);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    unsigned b1 = group_bit(g1);
    if (!strcmp(style, "group")) {
        for (int i = 0; i < n0; i++)
            dlist[i] = (a->mask[i] & b1) != 0;
    } else if (!strcmp(style, "region")) {
        for (int i = 0; i < n0; i++)
            dlist[i] = (char)region_match(r, a->x + 3 * i);
    } else if (!strcmp(style, "overlap")) {
        delete_overlap(g, cut, g1, g2, dlist);
    } else if (!strcmp(style, "porosity")) {
        struct rng_mars rm;
        rng_mars_init(&rm, seed);
        for (int i = 0; i < n0; i++)
            if (region_match(r, a->x + 3 * i))
                dlist[i] = rng_mars_uniform(&rm) <= frac;
    } else {
        int ncand = 0;
        for (int i = 0; i < n0; i++) {
            cand[i] = (a->mask[i] & b1) && (!r || region_match(r, a->x + 3 * i));
            ncand += cand[i];
        }
        if (!count_style && !exact) {
            struct rng_mars rm;
            rng_mars_init(&rm, seed);
            for (int i = 0; i < n0; i++)
                if (cand[i])
                    dlist[i] = rng_mars_uniform(&rm) <= frac;
        } else {
            bigint want = count_style ? count : (bigint)(frac * ncand);
            delete_subset(g, cand, want, seed, dlist);
        }
    }
    g->err.jmp = outer;
    free(cand);

    /* LAMMPS's order: the last atom moves into each deleted slot */
    for (int i = 0; i < a->n;) {
        if (dlist[i]) {
            dlist[i] = dlist[a->n - 1];
            atoms_remove(g, i);
        } else {
            i++;
        }
    }
    free(dlist);
    int64_t maxtag = 0;
    if (compress) {
        for (int i = 0; i < a->n; i++)
            a->tag[i] = i + 1;
        maxtag = a->n;
    } else {
        for (int i = 0; i < a->n; i++)
            if (a->tag[i] > maxtag)
                maxtag = a->tag[i];
    }
    a->maxtag = maxtag;
    gr_print(g, "Deleted %d atoms, new total = %d\n", n0 - a->n, a->n);
}
