/* par_restart.h - restart files on several MPI ranks (par_restart.c). */
#ifndef GR_PAR_RESTART_H
#define GR_PAR_RESTART_H

#include <stddef.h>

#include "state.h"

struct fix;
struct nbr_state;

/* Restart files on several ranks (src/io/restart.c). Between runs, after a
 * decomposed run and while the host atoms are the ones it left (same tags,
 * same order): its neighbor list as one process exports it (nbr_export's
 * form; rows of the host atoms, partners in tag order, the history with the
 * lower tag's sign, the reference positions and steps since the build) and
 * *exact = 1 when no per-atom value changed since; 0 (s empty) otherwise. */
int par_list_export(struct gravel *g, struct nbr_state *s, int *exact);
/* A fix's per-atom state of the host atoms left by the last decomposed run
 * (host order), or NULL. */
const unsigned char *par_fix_rows(const struct gravel *g, const struct fix *f);
/* read_restart, at the next run's start before the atoms are partitioned:
 * par_adopt_begin forgets what a run left; the file's list (rows of the host
 * atoms, nbr_state's form) becomes the history by tag pair, a fix's rows
 * (host order, device bytes) its saved state; with forces, each atom's
 * force and torque of the written step are kept by tag for
 * par_resume_forces, after the setup exchange. */
void par_adopt_begin(struct gravel *g);
void par_adopt_list(struct gravel *g, const struct nbr_state *s);
void par_adopt_fix_rows(struct gravel *g, struct fix *f, size_t bytes,
                        const unsigned char *rows);
void par_adopt_forces(struct gravel *g);
void par_resume_forces(struct gravel *g);

#endif
