/* accuracy.h - collision resolution and wall overlap of the contacts that
 * happen during a run (kernels/accuracy.cl).
 *
 * Each contact evaluation updates a record (pair contact: per contact;
 * wall and mesh contacts: per particle) with the largest dt / t_col seen,
 * t_col the contact law's two-body collision time at the contact's relative
 * normal speed, and (walls) the largest overlap / radius. acc_collect
 * reduces the records in a fixed order and clears them; the run calls it
 * before each neighbor rebuild (contacts and atoms are renumbered there), at
 * output steps and at the end. It warns once per run when a collision is
 * resolved by fewer than 10 steps and stops the run below 2 unless forced
 * (`run N force yes`), naming the step, the two particles (or particle and
 * wall fix) and their normal speed. */
#ifndef GR_ACCURACY_H
#define GR_ACCURACY_H

#include "state.h"
#include "ocl.h"

struct fix;

/* The worst contact of a run so far. */
struct acc_worst {
    double q;               /* largest dt / t_col (0: no collision seen) */
    double vn;              /* its relative normal speed */
    bigint step;            /* the step it was seen */
    long long tag_i, tag_j; /* the two particles (tag_j 0: a wall) */
    char wall[GR_NAMELEN];  /* the wall fix, for a wall contact */
    double wall_ov;         /* largest wall or mesh overlap / radius */
};

/* Run start: records sized for the atoms and contacts, cleared; the run's
 * worst reset. `force`: do not stop below 2 steps per collision. */
void acc_begin(struct gravel *g, int force);
/* Before each force computation: grow the records with the atoms/contacts. */
void acc_reserve(struct gravel *g);
/* Reduce and clear the records; warn or stop (see header). */
void acc_collect(struct gravel *g);
/* The run's worst so far. */
const struct acc_worst *acc_worst(struct gravel *g);
/* Pair kernel arguments: the contact records, and the step offset. */
cl_mem acc_pair_rec(struct gravel *g);
cl_mem acc_pair_step(struct gravel *g);
int acc_step(const struct gravel *g);
/* Wall kernel arguments (kernels/kernel_args.h KARGS_wall_atoms, wall_own): the
 * particles' wall records, their steps, and the code of fix f's walls. */
cl_mem acc_wall_rec(struct gravel *g);
cl_mem acc_wall_step(struct gravel *g);
int acc_wall_code(const struct gravel *g, const struct fix *f);
/* Memory (src/engine/memfit.c): device bytes of one pair contact's record,
 * and the bytes the records hold now. */
size_t acc_contact_bytes(struct gravel *g);
size_t acc_held_bytes(struct gravel *g);
void acc_free(struct gravel *g);

#endif
