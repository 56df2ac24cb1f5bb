/* read_dump.h - snapshots of native LAMMPS text dumps read back into the
 * host atoms: the `read_dump` command and the snapshot source of `rerun`
 * (LAMMPS 2021 ReadDump + ReaderNative, one process).
 *
 * A reader owns its open file and buffers: callers put it under an error
 * boundary and rd_destroy() it on every path. */
#ifndef GR_READ_DUMP_H
#define GR_READ_DUMP_H

#include "state.h"

struct rdump;

/* Files and the read_dump arguments after Nstep (fields, then keywords,
 * `format native` last); raises on bad arguments, nothing is opened yet. */
struct rdump *rd_create(struct gravel *g, int nfile, char **files, int argc, char **argv);
void rd_destroy(struct rdump *rd);
/* The first snapshot with step >= nrequest (exact: == nrequest) across the
 * files in order, left positioned at its header; -1 if none. */
bigint rd_seek(struct gravel *g, struct rdump *rd, bigint nrequest, int exact);
/* The next snapshot after ncurrent, at most nlast, a multiple of nevery
 * (0: any) and every nskip-th of those (rerun's first/last/every/skip). */
bigint rd_next(struct gravel *g, struct rdump *rd, bigint ncurrent, bigint nlast, int nevery,
               int nskip);
/* Read the snapshot at the reader's position into the host atoms:
 * purge/replace/trim/add, box, remap and shrink-wrap (not the timestep).
 * The counts of the last call are in rd_counts (before, snapshot, purged,
 * replaced, trimmed, added). */
void rd_atoms(struct gravel *g, struct rdump *rd);
void rd_counts(const struct rdump *rd, bigint out[6]);

#endif
