/* restart.h - binary restart files: `write_restart`, `read_restart`,
 * `restart N file [file2]` (LAMMPS syntax), and the exact continuation of a
 * run from such a file.
 *
 * The format (doc/restart.md) is versioned, endian-checked and checksummed;
 * a file is verified completely before anything is applied, and written
 * under a temporary name that is renamed into place when complete.
 *
 * What read_restart restores at once: units, dimension, box, boundaries,
 * lattice, groups, atom types and masses, every per-atom array, step, time,
 * time step, neighbor settings, the pair style and its coefficients. What it
 * keeps pending until the setup of the next run (restart_resume): the
 * contact history and neighbor list (by partner tag), the per-atom and
 * global state of fixes (applied to fixes re-created with the same ID and
 * style, as LAMMPS does), and, when nothing changed since the file was
 * written, the list build state and the forces of the written step, so the
 * continued run is bit-identical to the uninterrupted one. */
#ifndef GR_RESTART_H
#define GR_RESTART_H

#include "state.h"

#define RESTART_FORMAT_VERSION 4u
#define RESTART_ENDIAN_MARKER 0x01020304u
#define RESTART_MAGIC "GRAVELRS"
#define RESTART_HEADER_BYTES 32

void cmd_write_restart(struct gravel *g, int argc, char **argv);
void cmd_read_restart(struct gravel *g, int argc, char **argv);
void cmd_restart(struct gravel *g, int argc, char **argv);

/* Write the current state to `path` (no wildcard expansion): payload in
 * memory, then path.tmp.<pid>, fsync, rename. Errors through gr_error; the
 * previous file at `path` survives any failure. */
void restart_write(struct gravel *g, const char *path);

/* Whether restart_step writes a file at this step. */
int restart_due(const struct gravel *g, bigint step);
/* Run loop, after each step: writes the `restart` files when the step is a
 * multiple of N. Cheap when not due. */
void restart_step(struct gravel *g);

/* Run setup, after fix init, per-atom state allocation and nbr_setup: apply
 * what read_restart left pending. Returns 0 when the list must be built as
 * usual (the restored history is then carried over by partner tag), 1 when
 * the restored list is the exact one (skip the setup rebuild), 2 when also
 * the forces on the device are those the continued run would use (skip the
 * setup force computation). */
int restart_resume(struct gravel *g);

/* Several MPI ranks, at the next run's start before the atoms are
 * partitioned: the pending list, history and fixes' per-atom state go to
 * the decomposition by tag (par.h), which carries them with the atoms;
 * restart_resume then applies the rest and returns the same levels (the
 * setup exchange always rebuilds the list; at 2 the forces come back with
 * par_resume_forces). */
void restart_adopt_ranks(struct gravel *g);

/* Free restart settings and pending state (clear, destroy). */
void restart_free(struct gravel *g);

#endif
