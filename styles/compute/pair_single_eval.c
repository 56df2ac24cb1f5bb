/* pair_single_eval.c - the pair style's single() over host pairs
 * (pair_single_eval.h). */
#include "pair_single_eval.h"

#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "fix.h"
#include "pair.h"
#include "par.h"

/* Several ranks (the atoms gathered in tag order for the output step): the
 * history of each pair from every rank's contacts by tag pair, seen from i
 * (the lower tag, the contact's owner on every rank as on one process), as
 * host_pairs_history gives it on one process; pairs in no list get zeros. */
static int history_ranks(struct gravel *g, const struct host_pair *p, int np, double *hist)
{
    int64_t *tags = gr_malloc(g, (2 * (size_t)np + 1) * sizeof *tags);
    for (int k = 0; k < np; k++) {
        tags[2 * k] = g->atoms.tag[p[k].i];
        tags[2 * k + 1] = g->atoms.tag[p[k].j];
    }
    int hw = par_pair_history(g, np, tags, HOST_PAIRS_HIST_MAX, hist);
    free(tags);
    return hw;
}

void pair_single_eval(struct gravel *g, const struct pair_caps *caps, const struct host_pair *p,
                      int np, double *eng, double *fpair, double *sv)
{
    const struct atoms *a = &g->atoms;
    const unsigned frozen = fix_frozen_groupbit(g);
    double *hist = NULL;
    int hw = 0;
    if ((sv || caps->single_hist) && np > 0) {
        hist = gr_malloc(g, (size_t)np * HOST_PAIRS_HIST_MAX * sizeof *hist);
        hw = par_gathered(g) ? history_ranks(g, p, np, hist) : host_pairs_history(g, p, np, hist);
    }
    for (int k = 0; k < np; k++) {
        const int i = p[k].i, j = p[k].j;
        struct pair_single s;
        s.itype = a->type[i];
        s.jtype = a->type[j];
        memcpy(s.del, p[k].del, sizeof s.del);
        s.rsq = p[k].rsq;
        s.radi = a->radius[i];
        s.radj = a->radius[j];
        memcpy(s.vi, a->v + 3 * i, sizeof s.vi);
        memcpy(s.vj, a->v + 3 * j, sizeof s.vj);
        s.mi = a->rmass[i];
        s.mj = a->rmass[j];
        s.frozen_i = (a->mask[i] & frozen) != 0;
        s.frozen_j = (a->mask[j] & frozen) != 0;
        memcpy(s.omi, a->omega + 3 * i, sizeof s.omi);
        memcpy(s.omj, a->omega + 3 * j, sizeof s.omj);
        s.hist = hw > 0 ? hist + (size_t)k * hw : NULL;
        s.sv = sv ? sv + (size_t)k * PAIR_SINGLE_SV : NULL;
        if (s.sv)
            memset(s.sv, 0, PAIR_SINGLE_SV * sizeof *s.sv);
        double f = 0.0;
        const double e = caps->single(caps->single_of, &s, &f);
        if (eng)
            eng[k] = e;
        fpair[k] = f;
    }
    free(hist);
}
