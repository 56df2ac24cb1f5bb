/* outfile.h - the one place output files are opened, written and finished.
 *
 * The write-through rule (doc/output.md, "Crash-safe files"):
 *  - a symlink is followed to its final target (relative links against the
 *    link's folder, at most OF_MAXLINKS links); the bytes go there and the
 *    link stays a link;
 *  - a regular file, or a name that does not exist yet, is replaced
 *    atomically: the data go to a temporary beside the final target
 *    (<final><suffix>) that is renamed over it only when complete, so a
 *    failed or interrupted write leaves the previous file intact;
 *  - anything else (a character or block device, a FIFO, a socket) is
 *    written through: opened O_WRONLY without O_CREAT, never renamed over,
 *    never removed, and no non-regular file is ever created. A FIFO with no
 *    reader is waited for OF_FIFO_WAIT_MS, then refused (no hang);
 *  - a regular file whose folder does not allow a temporary (EACCES, EPERM,
 *    EROFS) is written through in place, as LAMMPS writes every file;
 *  - on several MPI ranks only rank 0 writes: the others write to /dev/null
 *    (the host atoms are whole on every rank between runs, src/parallel/);
 *    of_open_fd's files too (logs, print, fix ave and histogram files).
 * Every write is checked: the stream of an open ofile records the errno of
 * its first failed write, and of_commit()/of_flush() report it. */
#ifndef GR_OUTFILE_H
#define GR_OUTFILE_H

#include <stdio.h>

#define OF_MAXLINKS 40
#define OF_FIFO_WAIT_MS 5000

enum of_mode {
    OF_TRUNC,    /* start empty */
    OF_CONTINUE  /* keep what the target holds and append to it */
};

/* An output being written. It must not be copied or moved while open (its
 * stream records write errors into it). */
struct ofile {
    FILE *fp;     /* the stream to write (NULL when closed) */
    int err;      /* errno of the first failed write, 0 if none */
    char *final;  /* the file that receives the bytes (symlinks resolved) */
    char *tmp;    /* the temporary renamed over `final` at commit; NULL: written through */
    int fd;       /* the descriptor under fp (fsync) */
    int copying;  /* after a failed of_open: 1 if copying the old content failed */
    char failed[512]; /* after a failed of_open: the name it could not open or copy */
};

/* of_commit flags */
#define OF_SYNC 1 /* fsync the temporary before the rename */
#define OF_KEEP 2 /* on failure keep the temporary (it holds the new data) */

/* Where the bytes for `path` go: its final target with symlinks resolved
 * (malloc'd into *final), and in *through whether that target must be
 * written through (exists and is not a regular file). 0 or an errno (ELOOP
 * for a symlink loop, ENOMEM). */
int of_resolve(const char *path, char **final, int *through);

/* Open `path` for writing by the rule above; `suffix` names the temporary
 * (e.g. ".tmp"). 0 or an errno; on failure o->failed names the file it could
 * not open (or copy, with o->copying), o->fp is NULL and nothing is left to
 * abort or remove. */
int of_open(struct ofile *o, const char *path, const char *suffix, enum of_mode mode);
/* Flush and report the first write error (0 or an errno); stays open. */
int of_flush(struct ofile *o);
/* Flush, close, fsync with OF_SYNC (temporaries only: devices need none)
 * and rename the temporary over the target. 0 or an errno; on failure the
 * temporary is removed (kept with OF_KEEP) and the target is as before. The
 * ofile is closed either way; a closed ofile commits as 0. */
int of_commit(struct ofile *o, int flags);
/* Close and remove the temporary: the target stays as it was. */
void of_abort(struct ofile *o);
/* 1 while the ofile writes through (no temporary). */
int of_through(const struct ofile *o);

/* Open `path` for writing in place (logs, print and fix ave files):
 * symlinks resolved by of_resolve, only regular files created, a FIFO waited
 * for as above. `append`: O_APPEND, else truncated. A descriptor or -1 with
 * errno set. */
int of_open_fd(const char *path, int append);
/* A stdio stream over descriptor fd (taken over: closing the stream closes
 * it) that stores the errno of its first failed write in *errp and seeks
 * where fd can; NULL with errno set (fd closed). */
FILE *of_stream(int fd, int *errp);

#endif
