/* engine.h - what a run does with the device engine (device.h): build the
 * program for the active styles, upload the host atoms, append inserted
 * ones, copy the device state back, and release it all.
 *
 * At each `run` the engine builds the program for the active styles,
 * uploads the host atoms, and from then on the device holds the truth until
 * run_sync_host() copies it back. Atoms are re-sorted by cell at neighbor
 * rebuilds (atom_modify sort); every per-atom array moves together, tags
 * keep identity. */
#ifndef GR_ENGINE_H
#define GR_ENGINE_H

#include "device.h"
#include "state.h"

/* Build the program for the active styles; upload the host atoms. */
void eng_prepare(struct gravel *g);
void eng_upload(struct gravel *g);
/* Device bytes of one atom slot of the run's per-atom set (every field the
 * run holds, src/state/atom_fields.h, and the custom properties' record with
 * its re-sort scratch). */
size_t eng_atom_bytes(struct gravel *g);
/* 1 when the run's per-atom device buffers are the host arrays (a CPU
 * device on host memory, double precision; env GRAVEL_HOST_SHARE=0: never):
 * eng_atom_bytes() is then the custom properties' re-sort scratch only (0
 * without them), and the run keeps a copy of the start's
 * positions, velocities and tags on the host (diagnose.h). */
int eng_shares_host(struct gravel *g);
/* Make sure the per-atom set holds at least n atoms (exactly n when it
 * grows; contents not kept). */
void eng_reserve(struct gravel *g, int n);
/* The fixes' per-atom state (fix.h), the one allocation path: each fix with
 * peratom_bytes gets zero-filled buffers of the run's capacity unless it
 * holds big enough ones and keep (the atoms are those the state belongs to).
 * Called at upload (before fix init) and after fix init (keep = 1: only
 * state declared there is new). */
void eng_fix_state(struct gravel *g, int keep);
/* During a run: the host atoms nold .. g->atoms.n - 1 (just added behind
 * the atoms of the last run_sync_host) go to the device behind the others;
 * existing atoms, their contacts and history are untouched, the new ones'
 * fix per-atom state is zero. The caller forces a neighbor rebuild on this
 * step. The capacity must hold them (fix reserve at run start). */
void eng_append(struct gravel *g, int nold);
/* During a run, after run_sync_host: the host's custom property values of
 * the device's atoms to the device (a fix wrote them on the host). */
void eng_put_custom(struct gravel *g);

/* A decomposed run's rebuild (src/parallel/par.c): the host atoms 0 ..
 * nlocal + nghost - 1 (owned, then ghosts) to the device, which grows as
 * needed (the fixes' per-atom state too, contents kept); the device's atom
 * count becomes nlocal. */
void eng_reload(struct gravel *g, int nlocal, int nghost);

/* Device state -> host arrays; no-op when no run is active. Between runs
 * the host arrays in g->atoms are the truth; during a run the device
 * buffers are. Copies in the current device order (every per-atom array
 * moves together, tags keep identity), for output and variables. */
void run_sync_host(struct gravel *g);
/* Release the device engine and what it owns (neighbor lists, accuracy
 * records, fused stages, fix per-atom state). */
void engine_destroy(struct gravel *g);

#endif
