/* fix_insert.c - the insertion step of LIGGGHTS's insertion fixes
 * (LIGGGHTS-PUBLIC 3.8 FixInsert, FixInsertPack), drawing LIGGGHTS's random
 * numbers in LIGGGHTS's order on one process, so that a deck inserts the
 * particles LIGGGHTS inserts (count, sizes, positions, velocities, tags).
 *
 * Streams (Park-Miller, no warm-up): the fix's own (seed): the count draw
 * of volumefraction_region / mass_in_region / particle rates, the velocity
 * draws of vel uniform|gaussian; the distribution's: the split over the
 * templates; each template's: radius then density; the region's (reset to
 * seed + 12 at the first run): the Monte-Carlo region volume (ntry_mc
 * points, 3 draws each) and the positions (3 draws per try in the region's
 * bounds, clipped to the box, until the point is in the region, with all_in
 * yes also not within the particle radius of its surface).
 *
 * A step (pre_exchange at next_reneighbor): n = the style's count; the
 * distribution splits n (exact unless random_distribute uncorrelated);
 * with overlapcheck yes the particles are placed in list order (largest
 * template first), each retried at new points until it touches no existing
 * atom (periodic images included) and no particle placed before (touching
 * counts), within maxtry tries in all (a try within the radius of a box
 * face is redrawn, LIGGGHTS's check_dist_from_subdomain_border); the first
 * particle that finds no place ends the step ("Less insertions than
 * requested"). Placed particles become atoms with tags max + 1, ..., mask
 * all + the groups of the template, the distribution and this fix, mass
 * 4/3 pi r^3 density, the vel and omega values. A clump (particletemplate/
 * multisphere) is placed by its centre of mass, turned by `orientation`,
 * checked sphere by sphere, and becomes its spheres' atoms plus a body of
 * fix multisphere. Full contract: doc/styles/fix_insert_pack.md. */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "fix_insert.h"
#include "fix_particletemplate_multisphere.h"
#include "fix_rigid_small.h"
#include "log.h"
#include "molecule.h"
#include "par.h"
#include "par_sum.h"
#include "region.h"
#include "rigid_math.h"

#define SEED_OFFSET 12

static double num(struct gravel *g, int argc, char **argv, int i, const char *what)
{
    if (i >= argc)
        gr_error(g, "%s is missing", what);
    return arg_double(g, argv[i], what);
}

static int yesno(struct gravel *g, const struct insert *in, int argc, char **argv, int i)
{
    arg_need(g, argc, i, 1, argv[i]);
    if (!strcmp(argv[i + 1], "yes"))
        return 1;
    if (!strcmp(argv[i + 1], "no"))
        return 0;
    gr_error(g, "%s: expecting 'yes' or 'no' after '%s', got '%.64s'", in->ops->who, argv[i],
             argv[i + 1]);
}

/* FixInsert's keywords at argv[i]: words consumed, 0 if not one of them. */
static int base_keyword(struct gravel *g, struct insert *in, int argc, char **argv, int i)
{
    const char *k = argv[i], *who = in->ops->who;
    if (!strcmp(k, "distributiontemplate")) {
        arg_need(g, argc, i, 1, k);
        in->dist = pdist_of(g, argv[i + 1], who);
        snprintf(in->dist_id, sizeof in->dist_id, "%s", argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "maxattempt")) {
        arg_need(g, argc, i, 1, k);
        in->maxattempt = arg_int(g, argv[i + 1], k);
        if (in->maxattempt < 1)
            gr_error(g, "%s: maxattempt must be >= 1, got %s", who, argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "nparticles") || !strcmp(k, "mass")) {
        arg_need(g, argc, i, 1, k);
        if (!strcmp(argv[i + 1], "INF"))
            in->ninsert_exists = 0;
        else if (k[0] == 'n') {
            double v = arg_double(g, argv[i + 1], k);
            if (!(v >= 0 && v < 2147483647.0))
                gr_error(g, "%s: nparticles must be a count >= 0, got %s", who, argv[i + 1]);
            in->ninsert = (int)v;
        } else {
            in->massinsert = arg_double(g, argv[i + 1], k);
            if (!(in->massinsert >= 0 && isfinite(in->massinsert)))
                gr_error(g, "%s: mass must be >= 0, got %s", who, argv[i + 1]);
        }
        return 2;
    }
    if (!strcmp(k, "massrate") || !strcmp(k, "particlerate")) {
        arg_need(g, argc, i, 1, k);
        double v = arg_double(g, argv[i + 1], k);
        if (!(v >= 0 && isfinite(v)))
            gr_error(g, "%s: %s must be >= 0, got %s", who, k, argv[i + 1]);
        if (k[0] == 'm')
            in->massflowrate = v;
        else
            in->nflowrate = v;
        return 2;
    }
    if (!strcmp(k, "insert_every") || !strcmp(k, "every") || !strcmp(k, "insert_every_time")) {
        arg_need(g, argc, i, 1, k);
        if (!strcmp(argv[i + 1], "once"))
            in->insert_every = 0;
        else if (!strcmp(k, "insert_every_time")) {
            double t = arg_double(g, argv[i + 1], k);
            double n = t / g->dt;
            if (!(n >= 0 && n < 2147483647.0))
                gr_error(g, "%s: insert_every_time %s is not a usable number of steps of %g",
                         who, argv[i + 1], g->dt);
            in->insert_every = (int)n;
        } else
            in->insert_every = arg_int(g, argv[i + 1], k);
        if (in->insert_every < 0)
            gr_error(g, "%s: insert_every must be >= 0, got %s", who, argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "start")) {
        arg_need(g, argc, i, 1, k);
        in->first_ins_step = arg_int(g, argv[i + 1], k);
        if (in->first_ins_step < g->step + 1)
            gr_error(g, "%s: 'start' step can not be before current step (%s <= %lld)", who,
                     argv[i + 1], (long long)g->step);
        return 2;
    }
    if (!strcmp(k, "overlapcheck")) {
        in->check_ol = yesno(g, in, argc, argv, i);
        return 2;
    }
    if (!strcmp(k, "all_in")) {
        in->all_in = yesno(g, in, argc, argv, i);
        return 2;
    }
    if (!strcmp(k, "verbose")) {
        in->verbose = yesno(g, in, argc, argv, i);
        return 2;
    }
    if (!strcmp(k, "compress_tags")) {
        if (yesno(g, in, argc, argv, i))
            gr_error(g, "%s: compress_tags yes (renumbering every atom's tag) is not supported",
                     who);
        return 2;
    }
    if (!strcmp(k, "random_distribute")) {
        arg_need(g, argc, i, 1, k);
        if (!strcmp(argv[i + 1], "exact"))
            in->exact_number = 1;
        else if (!strcmp(argv[i + 1], "uncorrelated"))
            in->exact_number = 0;
        else
            gr_error(g, "%s: random_distribute must be exact or uncorrelated, got '%.64s'", who,
                     argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "vel")) {
        if (i + 1 >= argc)
            gr_error(g, "%s: not enough keyword for 'vel'", who);
        const char *s = argv[i + 1];
        int nv;
        if (!strcmp(s, "constant"))
            in->vstyle = INS_V_CONSTANT, nv = 3;
        else if (!strcmp(s, "uniform"))
            in->vstyle = INS_V_UNIFORM, nv = 6;
        else if (!strcmp(s, "gaussian"))
            in->vstyle = INS_V_GAUSSIAN, nv = 6;
        else
            gr_error(g, "%s: expecting keyword 'constant' or 'uniform' or 'gaussian' after "
                        "keyword 'vel', got '%.64s'", who, s);
        for (int d = 0; d < 3; d++)
            in->v[d] = num(g, argc, argv, i + 2 + d, "vel value");
        for (int d = 0; nv == 6 && d < 3; d++)
            in->vfluct[d] = num(g, argc, argv, i + 5 + d, "vel fluctuation");
        return 2 + nv;
    }
    if (!strcmp(k, "omega")) {
        if (i + 1 >= argc || strcmp(argv[i + 1], "constant"))
            gr_error(g, "%s: expecting keyword 'constant' after keyword 'omega'", who);
        for (int d = 0; d < 3; d++)
            in->omega[d] = num(g, argc, argv, i + 2 + d, "omega value");
        return 5;
    }
    if (!strcmp(k, "orientation")) {
        arg_need(g, argc, i, 1, k);
        const char *s = argv[i + 1];
        if (!strcmp(s, "random") || !strcmp(s, "template")) {
            in->quat_random = s[0] == 'r';
            return 2;
        }
        if (strcmp(s, "constant"))
            gr_error(g, "%s: expecting 'random', template' or 'constant' after keyword "
                        "'orientation', got '%.64s'", who, s);
        for (int d = 0; d < 4; d++)
            in->quat[d] = num(g, argc, argv, i + 2 + d, "orientation constant value");
        double n2 = in->quat[0] * in->quat[0] + in->quat[1] * in->quat[1] +
                    in->quat[2] * in->quat[2] + in->quat[3] * in->quat[3];
        if (fabs(n2 - 1.) > 1e-10)
            gr_error(g, "%s: quaternion not valid (orientation constant %s %s %s %s is not of "
                        "unit length)", who, argv[i + 2], argv[i + 3], argv[i + 4], argv[i + 5]);
        in->quat_random = 0;
        return 6;
    }
    if (!strcmp(k, "set_property"))
        gr_error(g, "%s: set_property (a per-atom property at insertion) is not supported",
                 who);
    return 0;
}

int insert_region_keyword(struct gravel *g, struct insert *in, int argc, char **argv, int i)
{
    const char *k = argv[i], *who = in->ops->who;
    if (!strcmp(k, "region")) {
        arg_need(g, argc, i, 1, k);
        in->reg = region_find(g, argv[i + 1]);
        if (!in->reg)
            gr_error(g, "%s: region ID does not exist: %.64s", who, argv[i + 1]);
        snprintf(in->reg_id, sizeof in->reg_id, "%s", argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "volumefraction_region")) {
        in->volfrac = num(g, argc, argv, i + 1, k);
        if (in->volfrac < 0. || in->volfrac > 1.)
            gr_error(g, "%s: Invalid volumefraction %s (0..1)", who, argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "particles_in_region")) {
        arg_need(g, argc, i, 1, k);
        in->ntotal_region = arg_int(g, argv[i + 1], k);
        if (in->ntotal_region <= 0)
            gr_error(g, "%s: 'ntotal_region' > 0 required, got %s", who, argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "mass_in_region")) {
        in->masstotal_region = num(g, argc, argv, i + 1, k);
        if (!(in->masstotal_region > 0.) || !isfinite(in->masstotal_region))
            gr_error(g, "%s: 'masstotal_region' > 0 required, got %s", who, argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "ntry_mc")) {
        arg_need(g, argc, i, 1, k);
        in->ntry_mc = arg_int(g, argv[i + 1], k);
        if (in->ntry_mc < 1000)
            gr_error(g, "%s: ntry_mc must be > 1000, got %s", who, argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "warn_region")) {
        in->warn_region = yesno(g, in, argc, argv, i);
        return 2;
    }
    if (!strcmp(k, "check_dist_from_subdomain_border")) {
        in->check_border = yesno(g, in, argc, argv, i);
        return 2;
    }
    return 0;
}

void insert_create(struct gravel *g, struct fix *f, int argc, char **argv,
                   const struct insert_ops *ops)
{
    const char *who = ops->who;
    if (g->dom.dimension != 3)
        gr_error(g, "%s: Can use fix insert for 3d simulations only", who);
    if (g->dom.triclinic)
        gr_error(g, "%s: Cannot use with triclinic box", who);
    if (argc < 4)
        gr_error(g, "%s: not enough arguments (expected seed S distributiontemplate ID ...)",
                 who);
    struct insert *in = f->data ? f->data : gr_calloc(g, 1, sizeof *in);
    f->data = in;
    in->ops = ops;
    if (strcmp(argv[0], "seed"))
        gr_error(g, "%s: expecting keyword 'seed', got '%.64s'", who, argv[0]);
    in->seed = liggghts_seed(g, argv[1], who);
    rng_park_init(&in->rng, in->seed);
    in->rrng_seed = in->seed + SEED_OFFSET;
    /* LIGGGHTS's defaults */
    in->ninsert_exists = 1;
    in->insert_every = -1;
    in->first_ins_step = g->step + 1;
    in->maxattempt = 50;
    in->check_ol = 1;
    in->exact_number = 1;
    in->verbose = 1;
    in->most_recent = -1;
    in->ntry_mc = 100000;
    in->warn_region = 1;
    in->check_border = 1;
    in->quat[0] = 1.0;
    for (int i = 2; i < argc;) {
        int used = base_keyword(g, in, argc, argv, i);
        if (!used && ops->keyword)
            used = ops->keyword(g, in, argc, argv, i);
        if (!used)
            gr_error(g, "%s: unknown keyword '%.64s'", who, argv[i]);
        i += used;
    }
    /* FixInsert::sanity_check */
    if (!in->dist)
        gr_error(g, "%s: have to define a 'distributiontemplate'", who);
    if (in->ninsert > 0 && in->massinsert > 0.)
        gr_error(g, "%s: must not define both 'nparticles' and 'mass'", who);
    if (in->nflowrate > 0. && in->massflowrate > 0.)
        gr_error(g, "%s: must not define both 'particlerate' and 'massrate'", who);
    if (in->insert_every == 0 && (in->massflowrate > 0. || in->nflowrate > 0.))
        gr_error(g, "%s: must not define 'particlerate' or 'massrate' for 'insert_every' = 0",
                 who);
    int nseed = 2 + in->dist->n;
    for (int a = 0; a < nseed; a++)
        for (int b = 0; b < a; b++) {
            int sa = a == 0 ? in->seed : a == 1 ? in->dist->seed : in->dist->tpl[a - 2]->seed;
            int sb = b == 0 ? in->seed : b == 1 ? in->dist->seed : in->dist->tpl[b - 2]->seed;
            if (sa == sb)
                gr_error(g, "Fix %s, ID %s: Random number generation: It is required that all "
                            "the random seeds of this fix insert/*, the random seed of particle "
                            "distribution fix (id %s) and all random seeds of the fix "
                            "particletemplate/* commands it uses are different (seed %d is "
                            "used twice)", f->style->name, f->id, in->dist_id, sa);
        }
    in->maxrad = in->dist->maxrad;
    f->force_reneighbor = 1;
    f->next_reneighbor = in->first_ins_step;
    f->hooks = HOOK_PRE_EXCHANGE; /* no time_depend: reset_timestep moves the schedule */
}

/* ---- the region (LIGGGHTS Region: extent, match_cut, volume_mc) -------- */

/* 1 when x (inside r) lies within cut of r's surface (LAMMPS/LIGGGHTS
 * surface_interior: block faces, cylinder wall r > 0 and ends, sphere). */
static int near_surface(const struct region *r, const double x[3], double cut)
{
    const double *p = r->p;
    const char *s = r->style->name;
    if (!strcmp(s, "block")) {
        if (x[0] < p[0] || x[0] > p[1] || x[1] < p[2] || x[1] > p[3] || x[2] < p[4] ||
            x[2] > p[5])
            return 0;
        for (int d = 0; d < 3; d++)
            if (x[d] - p[2 * d] < cut || p[2 * d + 1] - x[d] < cut)
                return 1;
        return 0;
    }
    if (!strcmp(s, "cylinder")) {
        static const int trans[3][2] = {{1, 2}, {0, 2}, {0, 1}};
        int d = r->dim, t1 = trans[d][0], t2 = trans[d][1];
        double d1 = x[t1] - p[0], d2 = x[t2] - p[1], rr = sqrt(d1 * d1 + d2 * d2);
        if (rr > p[2] || x[d] < p[3] || x[d] > p[4])
            return 0;
        return (p[2] - rr < cut && rr > 0.0) || x[d] - p[3] < cut || p[4] - x[d] < cut;
    }
    /* sphere */
    double dx = x[0] - p[0], dy = x[1] - p[1], dz = x[2] - p[2];
    double rr = sqrt(dx * dx + dy * dy + dz * dz);
    if (rr > p[3] || rr == 0.0)
        return 0;
    return p[3] - rr < cut;
}

static int in_box(const struct gravel *g, const double x[3])
{
    for (int d = 0; d < 3; d++)
        if (x[d] < g->dom.lo[d] || x[d] > g->dom.hi[d])
            return 0;
    return 1;
}

void insert_region_check_box(struct gravel *g, struct insert *in)
{
    const struct region *r = in->reg;
    const double small = 1e-8; /* LIGGGHTS region.cpp SMALL */
    int out = 0;
    for (int d = 0; d < 3; d++)
        if (r->bbox_lo[d] + small < g->dom.lo[d] || r->bbox_lo[d] + small > g->dom.hi[d] ||
            r->bbox_hi[d] - small < g->dom.lo[d] || r->bbox_hi[d] - small > g->dom.hi[d])
            out = 1;
    if (!out)
        return;
    for (int d = 0; d < 3; d++)
        for (int s = 0; s < 2; s++)
            if (g->dom.bnd[d][s] == 'f')
                gr_error(g, "%s: Insertion region %s extends outside simulation box and a fixed "
                            "boundary is used. Please use non-fixed boundaries in this case only",
                         in->ops->who, r->id);
}

/* LIGGGHTS's Region::volume_mc: ntry_mc points of the region's bounds from
 * the region stream (3 draws each); the volume is the share in the region
 * and the box times the bounds' volume. */
static void region_volume_mc(struct gravel *g, struct insert *in)
{
    const char *who = in->ops->who;
    struct region *r = in->reg;
    const double *lo = r->bbox_lo, *hi = r->bbox_hi;
    long n_in = 0;
    region_prematch(g, r);
    for (int i = 0; i < in->ntry_mc; i++) {
        double x[3];
        for (int d = 0; d < 3; d++)
            x[d] = lo[d] + rng_park_uniform(&in->rrng) * (hi[d] - lo[d]);
        if (in_box(g, x) && region_match(r, x))
            n_in++;
    }
    if (n_in == 0)
        gr_error(g, "%s: Unable to calculate region volume of %s: region volume is too small "
                    "or out of domain, or the particles are too large for all_in yes", who,
                 r->id);
    double vbox = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    in->region_volume = (double)n_in / (double)in->ntry_mc * vbox;
    if (!(in->region_volume > 0.) || !isfinite(in->region_volume))
        gr_error(g, "%s: Region volume calculation with MC failed (%g)", who, in->region_volume);
}

void insert_region_setup(struct gravel *g, struct insert *in)
{
    const char *who = in->ops->who;
    if (!in->reg_id[0])
        gr_error(g, "%s: must define an insertion region", who);
    in->reg = region_find(g, in->reg_id);
    if (!in->reg)
        gr_error(g, "%s: regions used by this command must not be deleted (%s)", who,
                 in->reg_id);
    struct region *r = in->reg;
    if (!r->bbox || !r->interior)
        gr_error(g, "%s: Impossible to generate random points on region %s with incomputable "
                    "bounding box", who, r->id);
    if (region_dynamic(r))
        gr_error(g, "%s: dynamic regions are not allowed (%s)", who, r->id);
    const char *s = r->style->name;
    if (in->all_in && strcmp(s, "block") && strcmp(s, "cylinder") && strcmp(s, "sphere"))
        gr_error(g, "%s: all_in yes needs the distance to the region surface: region %s is "
                    "%s (supported: block, cylinder, sphere)", who, r->id, s);
    if (r->openflag)
        gr_error(g, "%s: region %s has open faces (it matches every point)", who, r->id);
    gr_print(g, "INFO: Resetting random generator for region %s\n", r->id);
    rng_park_init(&in->rrng, in->rrng_seed);
    region_volume_mc(g, in);
}

int insert_box_changes(const struct gravel *g)
{
    for (int d = 0; d < 3; d++)
        for (int e = 0; e < 2; e++)
            if (g->dom.bnd[d][e] == 's' || g->dom.bnd[d][e] == 'm')
                return 1;
    return 0;
}

double insert_region_fraction(struct gravel *g, struct insert *in)
{
    if (insert_box_changes(g))
        region_volume_mc(g, in);
    return 1.0;
}

void insert_rate_counts(struct gravel *g, struct insert *in, double tiny)
{
    const char *who = in->ops->who;
    const struct pdist *d = in->dist;
    if (in->ninsert == 0 && in->ninsert_exists) {
        if (in->massinsert > 0.) {
            double n = (in->massinsert + tiny) / d->massexpect;
            if (!(n < 2147483647.0))
                gr_error(g, "%s: mass %g is too many particles", who, in->massinsert);
            in->ninsert = (int)n;
        } else
            gr_error(g, "%s: must define either 'nparticles' or 'mass'", who);
    }
    if (in->nflowrate == 0.) {
        if (in->massflowrate == 0.)
            gr_error(g, "%s: must define either 'massrate' or 'particlerate'", who);
        in->nflowrate = in->massflowrate / d->massexpect;
    } else
        in->massflowrate = in->nflowrate * d->massexpect;
    in->ninsert_per = in->nflowrate * ((double)in->insert_every * g->dt);
    if (in->ninsert_exists)
        in->massinsert = (double)in->ninsert * d->massexpect;
    if (!(in->ninsert_per < 1e9))
        gr_error(g, "%s: %g particles per insertion step is too many", who, in->ninsert_per);
}

int insert_maxtry(const struct insert *in, int n)
{
    double t = (double)n * in->maxattempt;
    return t < 2147483647.0 ? (int)t : 2147483647;
}

int insert_rate_reserve(const struct gravel *g, const struct insert *in)
{
    /* before the first run's setup the rate is not yet derived */
    double rate = in->nflowrate > 0 ? in->nflowrate : in->massflowrate / in->dist->massexpect;
    double per = rate * (double)in->insert_every * g->dt + 1;
    return per < 1e9 ? (int)per : 1000000000;
}

int insert_ninsert_rate(struct gravel *g, struct insert *in)
{
    if (in->ninsert_per == 0.)
        gr_error(g, "%s: ninsert_per == 0.", in->ops->who);
    int n = (int)(in->ninsert_per + rng_park_uniform(&in->rng));
    if (in->ninsert_exists && in->ninserted + n > in->ninsert)
        n = in->ninsert - in->ninserted;
    return n;
}

/* A random point of the region within the box (LIGGGHTS generate_random and
 * generate_random_shrinkby_cut with the sub-domain = the box). */
void insert_region_point(struct gravel *g, struct insert *in, double cut, double x[3])
{
    const struct region *r = in->reg;
    double lo[3], hi[3];
    for (int d = 0; d < 3; d++) {
        lo[d] = r->bbox_lo[d] > g->dom.lo[d] ? r->bbox_lo[d] : g->dom.lo[d];
        hi[d] = r->bbox_hi[d] < g->dom.hi[d] ? r->bbox_hi[d] : g->dom.hi[d];
        if (lo[d] >= hi[d])
            gr_error(g, "%s: Impossible to generate random points: region %s lies outside the "
                        "box", in->ops->who, r->id);
    }
    if (in->all_in)
        for (int d = 0; d < 3; d++)
            if (r->bbox_hi[d] - r->bbox_lo[d] < 2. * cut)
                gr_error(g, "%s: Impossible to generate random points within region %s - region "
                            "too small (smaller than twice the particle cutoff %g)",
                         in->ops->who, r->id, cut);
    for (long tries = 0;; tries++) {
        if (tries > 100000000L)
            gr_error(g, "%s: found no point in region %s in 1e8 tries", in->ops->who, r->id);
        for (int d = 0; d < 3; d++)
            x[d] = lo[d] + rng_park_uniform(&in->rrng) * (hi[d] - lo[d]);
        if (!region_match(r, x))
            continue;
        if (in->all_in && near_surface(r, x, cut))
            continue;
        return;
    }
}

int insert_in_subdomain(const struct gravel *g, const double x[3])
{
    for (int d = 0; d < 3; d++)
        if (!(x[d] >= g->dom.lo[d] && x[d] < g->dom.hi[d]))
            return 0;
    return 1;
}

double insert_dist_box(const struct gravel *g, const double x[3])
{
    double dlo = INFINITY, dhi = INFINITY;
    for (int d = 0; d < 3; d++) {
        double a = fabs(g->dom.lo[d] - x[d]), b = fabs(g->dom.hi[d] - x[d]);
        dlo = a < dlo ? a : dlo;
        dhi = b < dhi ? b : dhi;
    }
    return dlo < dhi ? dlo : dhi;
}

int insert_region_redraw(const struct gravel *g, const struct insert *in, const double x[3],
                         double r)
{
    return in->check_ol && in->check_border && insert_dist_box(g, x) < r;
}

int insert_region_nearby(const struct gravel *g, const struct insert *in, const double x[3],
                         double r)
{
    (void)g;
    const double *lo = in->reg->bbox_lo, *hi = in->reg->bbox_hi, cut = r + 2 * in->maxrad;
    for (int d = 0; d < 3; d++)
        if (x[d] < lo[d] - cut || x[d] > hi[d] + cut)
            return 0;
    return 1;
}

static void near_add(struct gravel *g, struct insert *in, const double x[3], double r)
{
    if (in->nnear == in->near_cap) {
        in->near_cap = in->near_cap ? 2 * in->near_cap : 256;
        in->near = gr_realloc(g, in->near, (size_t)in->near_cap * 4 * sizeof(double));
    }
    double *q = in->near + 4 * in->nnear++;
    q[0] = x[0], q[1] = x[1], q[2] = x[2], q[3] = r;
}

/* The existing atoms and their periodic images that the style calls near
 * (LIGGGHTS's load_xnear over local and ghost atoms). */
static void load_near(struct gravel *g, struct insert *in)
{
    const struct atoms *a = &g->atoms;
    in->nnear = 0;
    for (int i = 0; i < a->n; i++)
        for (int sx = -1; sx <= 1; sx++)
            for (int sy = -1; sy <= 1; sy++)
                for (int sz = -1; sz <= 1; sz++) {
                    int s[3] = {sx, sy, sz}, ok = 1;
                    double x[3];
                    for (int d = 0; d < 3 && ok; d++) {
                        if (s[d] && !g->dom.periodic[d])
                            ok = 0;
                        x[d] = a->x[3 * i + d] + s[d] * (g->dom.hi[d] - g->dom.lo[d]);
                    }
                    if (ok && in->ops->nearby(g, in, x, a->radius[i]))
                        near_add(g, in, x, a->radius[i]);
                }
    if (par_on(g)) { /* several ranks: every rank's near atoms, on every rank (any
                      * order: the overlap test asks only whether one overlaps) */
        double *rows = gr_malloc(g, (size_t)(in->nnear + 1) * 4 * sizeof(double));
        memcpy(rows, in->near, (size_t)in->nnear * 4 * sizeof(double));
        int all = par_gather_rows(g, &rows, in->nnear, 4);
        in->nnear = 0;
        for (int k = 0; k < all; k++)
            near_add(g, in, rows + 4 * k, rows[4 * k + 3]);
        free(rows);
    }
}

static int overlaps(const struct insert *in, const double x[3], double r)
{
    for (int i = 0; i < in->nnear; i++) {
        const double *q = in->near + 4 * i;
        double dx = x[0] - q[0], dy = x[1] - q[1], dz = x[2] - q[2];
        double rs = r + q[3];
        if (dx * dx + dy * dy + dz * dz <= rs * rs)
            return 1;
    }
    return 0;
}

/* A particle's orientation after its velocity draws: LIGGGHTS's
 * random_unit_quat from the fix's stream (orientation random; drawn for
 * spheres too, as LIGGGHTS, though only clumps turn), else the fixed one
 * (template: identity). */
static void orientation(struct insert *in, double quat[4])
{
    if (!in->quat_random) {
        memcpy(quat, in->quat, 4 * sizeof(double));
        return;
    }
    double u1 = rng_park_uniform(&in->rng), u2 = rng_park_uniform(&in->rng),
           u3 = rng_park_uniform(&in->rng);
    double h1 = sqrt(1. - u1), h2 = sqrt(u1);
    quat[0] = h1 * sin(2. * M_PI * u2);
    quat[1] = h1 * cos(2. * M_PI * u2);
    quat[2] = h2 * sin(2. * M_PI * u3);
    quat[3] = h2 * cos(2. * M_PI * u3);
}

/* LIGGGHTS's check_near_set_x_v_omega: a particle is refused when it
 * overlaps anything near (a clump: when any of its spheres does); placed,
 * it (each sphere) joins the near list. */
static int fits(struct gravel *g, struct insert *in, const struct ins_particle *p)
{
    const struct mstemplate *c = p->tpl ? p->tpl->ms : NULL;
    if (!c) {
        if (overlaps(in, p->x, p->radius))
            return 0;
        near_add(g, in, p->x, p->radius);
        return 1;
    }
    double rot[3][3], x[3];
    rm_quat_to_mat(p->quat, rot);
    for (int k = 0; k < c->nspheres; k++) {
        mstemplate_sphere(c, rot, p->x, k, x);
        if (overlaps(in, x, c->rs[k]))
            return 0;
    }
    for (int k = 0; k < c->nspheres; k++) {
        mstemplate_sphere(c, rot, p->x, k, x);
        near_add(g, in, x, c->rs[k]);
    }
    return 1;
}

static void random_velocity(struct insert *in, double v[3])
{
    for (int d = 0; d < 3; d++)
        v[d] = in->v[d];
    if (in->vstyle == INS_V_UNIFORM)
        for (int d = 0; d < 3; d++)
            v[d] = in->v[d] + in->vfluct[d] * 2.0 * (rng_park_uniform(&in->rng) - 0.50);
    else if (in->vstyle == INS_V_GAUSSIAN)
        for (int d = 0; d < 3; d++)
            v[d] = in->v[d] + in->vfluct[d] * rng_park_gaussian(&in->rng);
}

static void velocity(struct insert *in, double v[3])
{
    if (in->ops->velocity)
        in->ops->velocity(in, v);
    else
        random_velocity(in, v);
}

/* One try of LIGGGHTS's x_v_omega: candidates until one is not refused or
 * the step's tries run out; 1 when x holds a usable candidate. */
static int try_point(struct gravel *g, struct insert *in, double r, double x[3], long *ntry,
                     long maxtry)
{
    do {
        in->ops->point(g, in, r, x);
        (*ntry)++;
    } while (*ntry < maxtry && in->ops->redraw(g, in, x, r));
    return *ntry < maxtry;
}

/* x_v_omega of FixInsertPack and FixInsertStream: positions (and
 * velocities) of list[0..n); returns how many were placed (the first
 * ones). vel[] gets their velocities. Without the overlap check every
 * particle gets one try (a failed one is skipped); with it, particles are
 * placed in list order until the tries run out. */
static int place(struct gravel *g, struct insert *in, int n, double *vel)
{
    int placed = 0;
    long ntry = 0, maxtry = in->ops->maxtry(in, n);
    if (!in->check_ol) {
        for (int k = 0; k < n; k++) {
            struct ins_particle *p = in->list + placed;
            if (try_point(g, in, p->radius, p->x, &ntry, maxtry)) {
                velocity(in, vel + 3 * placed);
                orientation(in, p->quat);
                placed++;
            }
        }
        return placed;
    }
    while (ntry < maxtry && placed < n) {
        struct ins_particle *p = in->list + placed;
        int ok = 0;
        while (!ok && ntry < maxtry) {
            if (!try_point(g, in, p->radius, p->x, &ntry, maxtry))
                break;
            velocity(in, vel + 3 * placed);
            orientation(in, p->quat);
            ok = fits(g, in, p);
        }
        if (ok)
            placed++;
    }
    return placed;
}

/* A placed clump: its spheres become atoms (tags after *tag, mass M/n each,
 * the velocity vel; on several ranks each kept by its brick's owner) and a
 * body of fix multisphere on every rank (LIGGGHTS
 * ParticleToInsertMultisphere::insert). */
static void add_clump(struct gravel *g, struct fix *f, const struct ins_particle *p,
                      const double vel[3], int64_t *tag)
{
    const struct mstemplate *c = p->tpl->ms;
    const struct molecule *m = c->mol;
    struct fix *ms = fix_find_style(g, "multisphere");
    if (!ms)
        gr_error(g, "%s %s: Multi-sphere particle inserted: You have to use exactly one fix "
                    "multisphere.", ((struct insert *)f->data)->ops->who, f->id);
    struct atoms *a = &g->atoms;
    double rot[3][3], xgeom[3];
    rm_quat_to_mat(p->quat, rot);
    int first = a->n;
    int64_t tagprev = *tag;
    double *xs = gr_malloc(g, 3 * sizeof(double) * (size_t)c->nspheres);
    const unsigned mask = 1u | p->groupbit | f->groupbit;
    for (int k = 0; k < c->nspheres; k++) {
        double *x = xs + 3 * k;
        mstemplate_sphere(c, rot, p->x, k, x);
        ++*tag;
        if (!par_owns(g, x)) /* several ranks: each sphere kept by its brick's owner */
            continue;
        int i = atoms_add(g, *tag, m->type[k], x, m->radius[k], m->rmass[k]);
        a->mask[i] = mask;
        for (int d = 0; d < 3; d++)
            a->v[3 * i + d] = vel[d];
    }
    for (int d = 0; d < 3; d++) /* the geometric centre: rot (center - com) + xcm */
        xgeom[d] = p->x[d] + rot[d][0] * (m->center[0] - m->com[0]) +
                   rot[d][1] * (m->center[1] - m->com[1]) + rot[d][2] * (m->center[2] - m->com[2]);
    int body = rigid_small_add_body(g, ms, m, first, tagprev, xs, 3, mask, xgeom, vel, p->quat);
    free(xs);
    rigid_small_hold(ms, body, c->fflag, c->tflag);
}

/* The distribution and its templates again by ID: they may have been
 * unfixed or replaced since. */
static void relink(struct gravel *g, struct insert *in)
{
    in->dist = pdist_of(g, in->dist_id, in->ops->who);
    for (int i = 0; i < in->dist->n; i++)
        in->dist->tpl[i] = ptemplate_of(g, in->dist->tpl_id[i], in->ops->who);
}

void insert_init(struct gravel *g, struct fix *f)
{
    struct insert *in = f->data;
    relink(g, in);
    if (in->reg_id[0]) {
        in->reg = region_find(g, in->reg_id);
        if (!in->reg)
            gr_error(g, "%s %s: regions used by this command must not be deleted (%s)",
                     in->ops->who, f->id, in->reg_id);
    }
    if (f->next_reneighbor > 0 && f->next_reneighbor < g->step)
        gr_error(g, "%s %s: 'start' step can not be before current step", in->ops->who, f->id);
    for (int i = 0; i < in->dist->n; i++)
        if (in->dist->tpl[i]->ms) {
            if (!fix_find_style(g, "multisphere"))
                gr_error(g, "%s %s: template %s is a clump (particletemplate/multisphere): "
                            "fix multisphere is required", in->ops->who, f->id,
                         in->dist->tpl_id[i]);
            if (in->ops->finalize && in->vstyle != INS_V_CONSTANT) /* insert/stream */
                gr_error(g, "%s %s: Currently only fix insert/stream with multisphere particles "
                            "only supports constant velocity", in->ops->who, f->id);
            if (in->omega[0] != 0. || in->omega[1] != 0. || in->omega[2] != 0.)
                gr_error(g, "%s %s: omega with particletemplate/multisphere clumps is not "
                            "supported", in->ops->who, f->id);
        }
    if (in->setup_done)
        return;
    /* FixInsert::setup, once */
    in->setup_done = 1;
    in->ops->properties(g, in);
    if (in->ninsert_exists) {
        if (in->ninsert <= in->ninsert_per)
            in->final_ins_step = in->first_ins_step;
        else
            in->final_ins_step = in->first_ins_step +
                (bigint)((double)in->ninsert / in->ninsert_per) * (double)in->insert_every;
        gr_print(g, "INFO: Particle insertion %s: %f particles every %d steps - particle rate "
                    "%f, (mass rate %e)\n      %d particles (mass %e) within %lld steps\n",
                 f->id, in->ninsert_per, in->insert_every, in->nflowrate, in->massflowrate,
                 in->ninsert, in->massinsert, (long long)(in->final_ins_step - in->first_ins_step));
    } else {
        in->final_ins_step = -1;
        if (in->massflowrate > 0.)
            gr_print(g, "INFO: Particle insertion %s: %f particles every %d steps - particle "
                        "rate %f, (mass rate %e)\n", f->id, in->ninsert_per, in->insert_every,
                     in->nflowrate, in->massflowrate);
        else
            gr_print(g, "INFO: Particle insertion %s: inserting every %d steps\n", f->id,
                     in->insert_every);
    }
}

static void schedule_next(struct fix *f, struct insert *in)
{
    if (in->insert_every && (!in->ninsert_exists || in->ninserted < in->ninsert))
        f->next_reneighbor += in->insert_every;
    else
        f->next_reneighbor = 0;
}

void insert_pre_exchange(struct gravel *g, struct fix *f)
{
    struct insert *in = f->data;
    if (f->next_reneighbor != g->step || in->most_recent == g->step)
        return;
    in->most_recent = g->step;
    run_sync_host(g);
    int n = in->ops->ninsert_this(g, in);
    int exact = in->exact_number;
    if (in->ninsert_exists && in->ninserted + n >= in->ninsert) {
        n = in->ninsert - in->ninserted;
        if (n < 0)
            n = 0;
        exact = in->exact_number = 1;
    }
    /* distribute_ninsert_this on one process: int(fraction n + u) */
    double frac = in->ops->fraction ? in->ops->fraction(g, in) : 1.0;
    if (!exact)
        n = (int)(frac * (double)n + rng_park_uniform(&in->rng));
    int cap = pdist_max_count(in->dist, n);
    if (cap > in->list_cap) {
        in->list = gr_realloc(g, in->list, (size_t)cap * sizeof *in->list);
        in->list_cap = cap;
    }
    n = pdist_randomize(in->dist, n, exact, in->list);
    if (n == 0) {
        if (in->nflowrate > 0. || in->massflowrate > 0.)
            gr_warn(g, "Particle insertion: Inserting no particle - check particle insertion "
                       "settings (fix %s at step %lld)", f->id, (long long)g->step);
        if (in->insert_every && (!in->ninsert_exists || in->ninserted < in->ninsert))
            f->next_reneighbor += in->insert_every;
        else if (in->insert_every == 0)
            f->next_reneighbor = 0;
        return;
    }
    in->nnear = 0;
    if (in->check_ol)
        load_near(g, in);
    double *vel = gr_calloc(g, 3 * (size_t)n, sizeof(double));
    int placed = place(g, in, n, vel);
    struct atoms *a = &g->atoms;
    int nold = a->n;
    int64_t tag = par_max_atom_tag(g);
    in->tag_first = tag + 1;
    in->nplaced = placed;
    double mass_now = 0;
    for (int k = 0; k < placed; k++) {
        const struct ins_particle *p = in->list + k;
        if (p->tpl && p->tpl->ms) {
            add_clump(g, f, p, vel + 3 * k, &tag);
        } else if (!par_owns(g, p->x)) { /* several ranks: every rank placed the same
                                          * particles; the brick's owner keeps it */
            ++tag;
        } else {
            int i = atoms_add(g, ++tag, p->type, p->x, p->radius, p->mass);
            a->mask[i] = 1u | p->groupbit | f->groupbit;
            for (int d = 0; d < 3; d++) {
                a->v[3 * i + d] = vel[3 * k + d];
                if (a->omega)
                    a->omega[3 * i + d] = in->omega[d];
            }
        }
        mass_now += p->mass;
    }
    free(vel);
    eng_append(g, nold);
    if (in->ops->finalize) /* every new atom: a clump's spheres too */
        in->ops->finalize(g, f, nold, a->n - nold);
    in->ninserted += placed;
    in->massinserted += mass_now;
    if (in->verbose)
        gr_print(g, "INFO: Particle insertion %s: inserted %d particle templates (mass %e) at "
                    "step %lld\n - a total of %d particle templates (mass %e) inserted so far.\n",
                 f->id, placed, mass_now, (long long)g->step, in->ninserted, in->massinserted);
    if (placed < n)
        gr_warn(g, "Particle insertion: Less insertions than requested (fix %s at step %lld: "
                   "%d of %d)", f->id, (long long)g->step, placed, n);
    schedule_next(f, in);
}

int insert_reserve(struct gravel *g, struct fix *f, bigint nsteps, double *rmax)
{
    struct insert *in = f->data;
    relink(g, in); /* reserve comes before init: the distribution may be a new one */
    *rmax = in->dist->maxrad;
    bigint next = f->next_reneighbor, last = g->step + nsteps;
    if (next <= g->step || next > last)
        return 0;
    double per = (double)in->ops->reserve(g, in, nsteps) + in->dist->n + 2;
    int atoms_per = 1; /* a clump inserts its spheres */
    for (int i = 0; i < in->dist->n; i++)
        if (in->dist->tpl[i]->ms && in->dist->tpl[i]->ms->nspheres > atoms_per)
            atoms_per = in->dist->tpl[i]->ms->nspheres;
    bigint steps = in->insert_every > 0 ? (last - next) / in->insert_every + 1 : 1;
    double total = per * (double)steps;
    /* the total is known once the first run's setup has derived it (mass M) */
    if (in->ninsert_exists && in->setup_done &&
        total > in->ninsert - in->ninserted + in->dist->n + 2.0)
        total = in->ninsert - in->ninserted + in->dist->n + 2.0;
    total *= atoms_per;
    if (!(total < 2e9))
        gr_error(g, "%s %s: up to %g insertions in this run are too many", in->ops->who, f->id,
                 total);
    return (int)total;
}

double insert_vector(struct gravel *g, struct fix *f, int i)
{
    (void)g;
    const struct insert *in = f->data;
    return i == 1 ? (double)in->ninserted : i == 2 ? in->massinserted : 0.0;
}

void insert_destroy(struct fix *f)
{
    struct insert *in = f->data;
    if (in) {
        free(in->list);
        free(in->near);
    }
    free(in);
}

void insert_reset_step(struct gravel *g, struct fix *f, bigint shift)
{
    (void)g;
    struct insert *in = f->data;
    if (f->next_reneighbor > 0) /* LIGGGHTS's FixInsert::reset_timestep (a stopped fix stays so) */
        f->next_reneighbor += shift;
    in->clock_shift += shift;
}

/* Restart state: the streams, counts and schedule (LIGGGHTS writes the
 * stream, ninserted, first step, next step and mass inserted), and the step
 * it was written at: the next insertion moves with the reset_timestep
 * commands between read_restart and the run, as in LIGGGHTS, where the
 * state is restored when the fix is defined. Files without that step
 * (older builds) are read as written at the current step. */
struct insert_saved {
    struct rng_park rng, rrng;
    int ninserted, ninsert, exact_number, setup_done;
    double massinserted, massinsert, region_volume, ninsert_per, nflowrate, massflowrate;
    int64_t first_ins_step, final_ins_step, most_recent, next_reneighbor;
    int64_t step, clock_shift;
};
#define SAVED_OLD offsetof(struct insert_saved, step)

size_t insert_write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    const struct insert *in = f->data;
    struct insert_saved s;
    memset(&s, 0, sizeof s);
    s.rng = in->rng, s.rrng = in->rrng;
    s.ninserted = in->ninserted, s.ninsert = in->ninsert;
    s.exact_number = in->exact_number, s.setup_done = in->setup_done;
    s.massinserted = in->massinserted, s.massinsert = in->massinsert;
    s.region_volume = in->region_volume, s.ninsert_per = in->ninsert_per;
    s.nflowrate = in->nflowrate, s.massflowrate = in->massflowrate;
    s.first_ins_step = in->first_ins_step, s.final_ins_step = in->final_ins_step;
    s.most_recent = in->most_recent, s.next_reneighbor = f->next_reneighbor;
    s.step = g->step;
    s.clock_shift = in->clock_shift;
    if (buf && cap >= sizeof s)
        memcpy(buf, &s, sizeof s);
    return sizeof s;
}

void insert_read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct insert *in = f->data;
    struct insert_saved s;
    if (len != sizeof s && len != SAVED_OLD)
        gr_error(g, "fix %s: restart state of %zu bytes, expected %zu", f->id, len, sizeof s);
    s.step = g->step;
    s.clock_shift = 0;
    memcpy(&s, buf, len);
    in->rng = s.rng, in->rrng = s.rrng;
    in->ninserted = s.ninserted, in->ninsert = s.ninsert;
    in->exact_number = s.exact_number, in->setup_done = s.setup_done;
    in->massinserted = s.massinserted, in->massinsert = s.massinsert;
    in->region_volume = s.region_volume, in->ninsert_per = s.ninsert_per;
    in->nflowrate = s.nflowrate, in->massflowrate = s.massflowrate;
    in->first_ins_step = s.first_ins_step, in->final_ins_step = s.final_ins_step;
    in->most_recent = s.most_recent;
    f->next_reneighbor = s.next_reneighbor;
    in->clock_shift = s.clock_shift;
    rng_park_init(&in->rrng, in->rrng_seed); /* LIGGGHTS reseeds it (region, mesh) */
    insert_reset_step(g, f, g->step - s.step);
}
