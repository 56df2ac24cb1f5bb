/* fix_insert.h - the insertion machinery shared by LIGGGHTS's fix
 * insert/pack and insert/rate/region (fix_insert.c, after LIGGGHTS-PUBLIC
 * 3.8 FixInsert and FixInsertPack). A style file supplies its keywords and
 * the three questions LIGGGHTS's subclasses answer: the insertion
 * properties at the first run, how many particles this step, and how many
 * position attempts. */
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
    int (*reserve)(struct gravel *g, struct insert *in, bigint nsteps);  /* per insertion */
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
    int check_ol, all_in, exact_number, verbose, setup_done;
    int vstyle;
    double v[3], vfluct[3], omega[3];
    double maxrad;
    /* region (FixInsertPack) */
    char reg_id[GR_NAMELEN];
    struct region *reg;
    struct rng_park rrng;           /* the region's stream (LIGGGHTS Region::random) */
    int ntry_mc, ntotal_region, warn_region, check_border;
    double volfrac, masstotal_region, region_volume, insertion_ratio;
    /* work */
    struct ins_particle *list;
    int list_cap;
    double *near;                   /* x y z r */
    int nnear, near_cap;
};

/* Parse `seed S` and the keywords of LIGGGHTS FixInsert plus the style's
 * own (ops->keyword); set up f. */
void insert_create(struct gravel *g, struct fix *f, int argc, char **argv,
                   const struct insert_ops *ops);
/* The region keywords of FixInsertPack (region, volumefraction_region,
 * particles_in_region, mass_in_region, ntry_mc, warn_region,
 * check_dist_from_subdomain_border): a keyword hook for ops. */
int insert_region_keyword(struct gravel *g, struct insert *in, int argc, char **argv, int i);
/* FixInsertPack's region checks and Monte-Carlo region volume (the region
 * stream reset to seed + 12, ntry_mc points). */
void insert_region_setup(struct gravel *g, struct insert *in);
/* Error when the region's bounds leave the box and a face is fixed
 * (LIGGGHTS's bbox_extends_outside_box check). */
void insert_region_check_box(struct gravel *g, struct insert *in);
/* FixInsert::calc_ninsert_this: int(ninsert_per + u), capped by nparticles. */
int insert_ninsert_rate(struct gravel *g, struct insert *in);

void insert_init(struct gravel *g, struct fix *f);
void insert_pre_exchange(struct gravel *g, struct fix *f);
int insert_reserve(struct gravel *g, struct fix *f, bigint nsteps, double *rmax);
void insert_destroy(struct fix *f);
double insert_vector(struct gravel *g, struct fix *f, int i);
size_t insert_write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap);
void insert_read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len);

#endif
