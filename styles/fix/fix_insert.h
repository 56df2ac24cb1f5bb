/* fix_insert.h - the insertion machinery shared by LIGGGHTS's fix
 * insert/pack, insert/rate/region and insert/stream (fix_insert.c, after
 * LIGGGHTS-PUBLIC 3.8 FixInsert and FixInsertPack). A style file supplies
 * its keywords and the questions LIGGGHTS's subclasses answer: the
 * insertion properties at the first run, how many particles this step, how
 * many position attempts, where a candidate lies (the insertion volume),
 * which tries are refused, which existing atoms the overlap check needs,
 * and what happens to the placed atoms. */
#ifndef GR_FIX_INSERT_H
#define GR_FIX_INSERT_H

#include "fix_particledistribution_discrete.h"

struct fix;
struct region;
struct insert;

struct insert_ops {
    const char *who;                /* "fix insert/pack" */
    /* keyword at argv[i]: the words consumed, or 0 if not its keyword */
    int (*keyword)(struct gravel *g, struct insert *in, int argc, char **argv, int i);
    void (*properties)(struct gravel *g, struct insert *in);   /* first run setup */
    int (*ninsert_this)(struct gravel *g, struct insert *in);
    int (*maxtry)(const struct insert *in, int n);
    /* particles per insertion step, at most; called before the steps between
     * insertions (in->insert_every) are read, so a style may derive them here */
    int (*reserve)(struct gravel *g, struct insert *in, bigint nsteps);
    /* One candidate centre x for a particle of radius r (LIGGGHTS's
     * generate_random of the subclass). */
    void (*point)(struct gravel *g, struct insert *in, double r, double x[3]);
    /* 1: candidate x (radius r) is refused and drawn again; each draw is a
     * try of the step's maxtry. */
    int (*redraw)(const struct gravel *g, const struct insert *in, const double x[3], double r);
    /* 1: an existing atom (or periodic image) at x of radius r goes into the
     * overlap check's list (LIGGGHTS's is_nearby). */
    int (*nearby)(const struct gravel *g, const struct insert *in, const double x[3], double r);
    /* Optional: the velocity of a placed particle (default: vel constant,
     * uniform or gaussian, drawn from the fix's stream). */
    void (*velocity)(struct insert *in, double v[3]);
    /* Optional: FixInsert::insertion_fraction, asked on every insertion step
     * after the count and before the split (default 1, no draws). */
    double (*fraction)(struct gravel *g, struct insert *in);
    /* Optional: the n atoms just placed are device atoms first .. first+n-1
     * (LIGGGHTS's finalize_insertion). */
    void (*finalize)(struct gravel *g, struct fix *f, int first, int n);
};

enum { INS_V_CONSTANT, INS_V_UNIFORM, INS_V_GAUSSIAN };

struct insert {
    const struct insert_ops *ops;
    int seed;
    struct rng_park rng;            /* the fix's stream: counts, velocities */
    char dist_id[GR_NAMELEN];
    struct pdist *dist;
    /* FixInsert */
    int maxattempt, ninsert_exists, ninsert, ninserted;
    double massinsert, massinserted, nflowrate, massflowrate, ninsert_per;
    int insert_every;               /* 0: once, -1: not given */
    bigint first_ins_step, final_ins_step, most_recent;
    bigint clock_shift;             /* sum of the reset_timestep shifts since the fix began:
                                       step - clock_shift runs on without jumps */
    int check_ol, all_in, exact_number, verbose, setup_done;
    int64_t tag_first;              /* the insertion step's first new atom ID, and how many */
    int nplaced;                    /* particles it placed (on every rank, ops->finalize) */
    int vstyle;
    double v[3], vfluct[3], omega[3];
    int quat_random;                /* orientation random (else quat: template = identity) */
    double quat[4];
    double maxrad;
    /* region (FixInsertPack) */
    char reg_id[GR_NAMELEN];
    struct region *reg;
    struct rng_park rrng;           /* the region's stream (LIGGGHTS Region::random), or
                                       insert/stream's face mesh's (TriMesh::random_) */
    int rrng_seed;                  /* its seed, at setup and after read_restart (seed + 12;
                                       the mesh's 179424799) */
    int ntry_mc, ntotal_region, warn_region, check_border;
    double volfrac, masstotal_region, region_volume, insertion_ratio;
    /* work */
    struct ins_particle *list;
    int list_cap;
    double *near;                   /* x y z r */
    int nnear, near_cap;
};

/* Parse `seed S` and the keywords of LIGGGHTS FixInsert plus the style's
 * own (ops->keyword); set up f. f->data, when the style set it, is its
 * zeroed state beginning with a struct insert; else one is allocated. */
void insert_create(struct gravel *g, struct fix *f, int argc, char **argv,
                   const struct insert_ops *ops);
/* The region keywords of FixInsertPack (region, volumefraction_region,
 * particles_in_region, mass_in_region, ntry_mc, warn_region,
 * check_dist_from_subdomain_border): a keyword hook for ops. */
int insert_region_keyword(struct gravel *g, struct insert *in, int argc, char **argv, int i);
/* FixInsertPack's region checks and Monte-Carlo region volume (the region
 * stream reset to seed + 12, ntry_mc points). */
void insert_region_setup(struct gravel *g, struct insert *in);
/* 1 when the box may change during a run (a shrink-wrapped boundary:
 * LIGGGHTS's domain->box_change). */
int insert_box_changes(const struct gravel *g);
/* FixInsertPack::insertion_fraction on one process (the fraction hook of
 * the region styles): 1; with a changing box the Monte-Carlo region volume
 * is drawn again first (ntry_mc points of the region stream). */
double insert_region_fraction(struct gravel *g, struct insert *in);
/* Error when the region's bounds leave the box and a face is fixed
 * (LIGGGHTS's bbox_extends_outside_box check). */
void insert_region_check_box(struct gravel *g, struct insert *in);
/* The region styles' point, redraw and nearby (ops): a random point of
 * the region within the box (all_in yes: not within r of its surface); a
 * try within r of a box face is redrawn when overlapcheck and
 * check_dist_from_subdomain_border are on; atoms within 2 maxrad + r of
 * the region's bounds are near. */
void insert_region_point(struct gravel *g, struct insert *in, double r, double x[3]);
int insert_region_redraw(const struct gravel *g, const struct insert *in, const double x[3],
                         double r);
int insert_region_nearby(const struct gravel *g, const struct insert *in, const double x[3],
                         double r);
/* LIGGGHTS's Domain::is_in_subdomain and dist_subbox_borders on one
 * process: x in [lo, hi) of the box; the distance to the nearest box face. */
int insert_in_subdomain(const struct gravel *g, const double x[3]);
double insert_dist_box(const struct gravel *g, const double x[3]);
/* The counts of the rate styles (insert/rate/region, insert/stream):
 * nparticles, or int((mass + tiny) / E[mass]); particlerate, or massrate /
 * E[mass]; ninsert_per = rate insert_every dt; the total mass. */
void insert_rate_counts(struct gravel *g, struct insert *in, double tiny);
/* n maxattempt tries (FixInsert's maxtry), capped at INT_MAX. */
int insert_maxtry(const struct insert *in, int n);
/* The rate styles' particles per insertion step, at most: rate x insert_every
 * x dt + 1. */
int insert_rate_reserve(const struct gravel *g, const struct insert *in);
/* FixInsert::calc_ninsert_this: int(ninsert_per + u), capped by nparticles. */
int insert_ninsert_rate(struct gravel *g, struct insert *in);

void insert_init(struct gravel *g, struct fix *f);
void insert_pre_exchange(struct gravel *g, struct fix *f);
int insert_reserve(struct gravel *g, struct fix *f, bigint nsteps, double *rmax);
void insert_destroy(struct fix *f);
double insert_vector(struct gravel *g, struct fix *f, int i);
/* reset_timestep moved the step counter: the next insertion moves with it
 * (LIGGGHTS's FixInsert::reset_timestep; the other steps stay), and so
 * does clock_shift. */
void insert_reset_step(struct gravel *g, struct fix *f, bigint shift);
size_t insert_write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap);
void insert_read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len);

#endif
