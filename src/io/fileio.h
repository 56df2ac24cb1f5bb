/* fileio.h - reading input files safely: scripts, data, restart, mesh files.
 *
 * Contracts:
 *  - fio_open_read() never blocks (a FIFO with no writer is rejected, not
 *    waited on) and never hands back a directory or a device: with
 *    `streams` 0 only regular files are accepted; with `streams` 1 (the
 *    `-in` script) pipes, FIFOs and terminals are accepted too, directories
 *    and block devices are not. On failure it returns NULL and *why names the
 *    reason ("is a directory", "is a FIFO, not a regular file", strerror).
 *  - fio_getline() reads one line ending in "\n", "\r\n" or a lone "\r"
 *    (files saved by old Mac editors), without its line break; NUL bytes are
 *    kept (the caller decides). It returns the length, FIO_EOF at the end of
 *    the input with nothing read, or FIO_ERR on a read error or when the
 *    buffer cannot grow, with errno set: a failure is never an end of input.
 *    `max` > 0 bounds the line length (FIO_ERR with errno EFBIG). */
#ifndef GR_FILEIO_H
#define GR_FILEIO_H

#include <stdio.h>
#include <sys/types.h>

#define FIO_EOF (-1)
#define FIO_ERR (-2)

FILE *fio_open_read(const char *path, int streams, const char **why);
ssize_t fio_getline(FILE *fp, char **buf, size_t *cap, size_t max);
/* Read a whole regular file (fio_open_read's checks: no FIFO, device or
 * directory) of at most `max` bytes into a new buffer with a NUL after its
 * *len bytes. NULL on failure, with the reason in why[whylen] ("is a FIFO
 * (named pipe), not a regular file", "is N bytes, more than the limit of M
 * bytes", strerror): the size is checked before anything is allocated. */
unsigned char *fio_read_all(const char *path, size_t max, size_t *len, char *why,
                            size_t whylen);
/* Open a file for writing (truncated, or appended to) whose first failed
 * write stores its errno in *errp (a stdio stream forgets why a buffered
 * write failed). Write failures also set the stream's error flag; closing
 * reports a failed close. NULL with *why on failure to open. The file is
 * written in place by the write-through rule of outfile.h (of_open_fd). */
FILE *fio_open_write_checked(const char *path, int append, int *errp, const char **why);
/* Write all n bytes of s to the end of `path` (created if missing, emptied
 * first unless `append`) in one write; on failure the file is cut back to
 * its previous length, so no partial line is left. 0 or an errno; *opened
 * says whether the failure came after the file was opened. */
int fio_append_whole(const char *path, int append, const char *s, size_t n, int *opened);
/* Length of a UTF-8 byte-order mark at the start of s (3 or 0). */
size_t fio_bom(const char *s, size_t n);

#endif
