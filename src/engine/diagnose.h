/* diagnose.h - what a stopped run saw, for its error message: the particle
 * that left the box or became non-finite, its neighbour and its speed.
 *
 * Pure functions over the host state; neighbor.c reads the device values of
 * the particle and calls them. What they need of the state at the start of
 * the current run (g->firststep) is kept by diag_keep_start at the upload
 * (struct start_copy of device.h): the atoms whose nearest neighbour sat on
 * them or overlapped them deeply, and the fast ones; no copy of the
 * positions. */
#ifndef GR_DIAGNOSE_H
#define GR_DIAGNOSE_H

#include <stddef.h>

#include "state.h"

/* "atom T at (x, y, z) with velocity (vx, vy, vz) crossed the z lo boundary
 * (f) at 0: ..." for a lost atom with the given device position and
 * velocity, followed by its displacement per step against the box length. */
void diag_lost_atom(const struct gravel *g, long long tag, const double x[3],
                    const double v[3], char *out, size_t len);

/* For the atom of `tag` that became non-finite (device position x and
 * velocity v now): what the start of the run shows about it, into out:
 * another atom at the same position, an overlap deeper than half the smaller
 * radius, or a speed that moves it more than its radius per step. Returns 1
 * when such a cause was seen, 0 otherwise (out then holds the atom's values
 * only). */
int diag_nonfinite(const struct gravel *g, long long tag, const double x[3], const double v[3],
                   char *out, size_t len);

/* 1 when velocity v moves an atom of this radius more than its radius per
 * step, or is not finite: what diag_nonfinite blames at the run start. */
int diag_fast(const struct gravel *g, const double v[3], double radius);

/* "; probable cause: ..." from the time step against the collision time of
 * the contact model. When the time step resolves the collision (>= 10 steps
 * per collision) the time step is not blamed: the text says so and points
 * at the configuration instead. */
void diag_time_step(const struct gravel *g, char *out, size_t len);

/* At the run's upload, before the run changes the host arrays: what
 * diag_nonfinite and diag_time_step read of the run start, into
 * g->eng->start (a host scan, O(n) for particles of similar size);
 * diag_free_start releases it. */
struct start_copy;
void diag_keep_start(struct gravel *g);
void diag_free_start(struct start_copy *c);

#endif
