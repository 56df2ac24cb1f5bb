/* fix_particledistribution_discrete.h - LIGGGHTS's discrete distribution of
 * particle templates, read by the insertion fixes (fix_insert.h). */
#ifndef GR_FIX_PARTICLEDISTRIBUTION_DISCRETE_H
#define GR_FIX_PARTICLEDISTRIBUTION_DISCRETE_H

#include "fix_particletemplate_sphere.h"

/* One particle to insert: drawn by pdist_randomize, placed by the fix. */
struct ins_particle {
    int type;
    double radius, density, volume, mass;
    unsigned groupbit;          /* template | distribution (| inserting fix) */
    double x[3];                /* centre (a clump's: its centre of mass) */
    const struct ptemplate *tpl; /* its template (tpl->ms: a clump) */
    double quat[4];             /* a clump's orientation */
};

struct pdist {
    int seed;
    struct rng_park rng;
    int n;                      /* templates */
    struct ptemplate **tpl;
    char (*tpl_id)[GR_NAMELEN];
    double *w;                  /* number fractions (normalised) */
    int *order;                 /* templates by volume expectancy, largest first */
    int *parttogen;
    double *remainder;
    double volexpect, massexpect, maxrad, minrad;
    int maxtype, mintype;
    unsigned groupbit;
};

/* The distribution of fix `id`, or an error naming `who`. */
struct pdist *pdist_of(struct gravel *g, const char *id, const char *who);
/* LIGGGHTS randomize_list: ntotal particles split over the templates
 * (exact: floor of ntotal w_i, the gap by remainder-weighted draws of this
 * fix's stream; else int(ntotal w_i + u) each), each template drawing its
 * particles in template order; list[] gets them largest template first.
 * Returns the count (== ntotal when exact). list must hold
 * pdist_max_count(ntotal). */
int pdist_randomize(struct pdist *d, int ntotal, int exact, struct ins_particle *list);
int pdist_max_count(const struct pdist *d, int ntotal);

#endif
