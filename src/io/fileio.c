/* fileio.c - opening and reading input files without blocking, without
 * reading devices, and without mistaking a read error for the end of input
 * (issue 12, items 1-3). */
#include "fileio.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "outfile.h"

static const char *kind_problem(mode_t m, int streams)
{
    if (S_ISREG(m))
        return NULL;
    if (S_ISDIR(m))
        return "is a directory";
    if (S_ISFIFO(m))
        return streams ? NULL : "is a FIFO (named pipe), not a regular file";
    if (S_ISCHR(m))
        return streams ? NULL : "is a character device, not a regular file";
    if (S_ISBLK(m))
        return "is a block device, not a regular file";
    if (S_ISSOCK(m))
        return streams ? NULL : "is a socket, not a regular file";
    return "is not a regular file";
}

FILE *fio_open_read(const char *path, int streams, const char **why)
{
    *why = NULL;
    /* O_NONBLOCK: opening a FIFO without a writer must not wait; the flag is
     * cleared again once the type is known to be acceptable */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        *why = strerror(errno);
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        *why = strerror(errno);
        close(fd);
        return NULL;
    }
    const char *bad = kind_problem(st.st_mode, streams);
    if (bad) {
        *why = bad;
        close(fd);
        return NULL;
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl < 0 || fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) != 0) {
        *why = strerror(errno);
        close(fd);
        return NULL;
    }
    FILE *fp = fdopen(fd, "r");
    if (!fp) {
        *why = strerror(errno);
        close(fd);
    }
    return fp;
}

ssize_t fio_getline(FILE *fp, char **buf, size_t *cap, size_t max)
{
    size_t n = 0;
    int c;
    errno = 0;
    for (;;) {
        c = getc_unlocked(fp);
        if (c == EOF || c == '\n')
            break;
        if (c == '\r') {
            int d = getc_unlocked(fp);
            if (d != '\n' && d != EOF)
                ungetc(d, fp);
            break;
        }
        if (max && n >= max) {
            errno = EFBIG;
            return FIO_ERR;
        }
        if (n + 2 > *cap) {
            size_t nc = *cap ? 2 * *cap : 256;
            char *p = realloc(*buf, nc);
            if (!p) {
                errno = ENOMEM;
                return FIO_ERR;
            }
            *buf = p;
            *cap = nc;
        }
        (*buf)[n++] = (char)c;
    }
    if (c == EOF && ferror(fp)) {
        if (!errno)
            errno = EIO;
        return FIO_ERR;
    }
    if (c == EOF && n == 0)
        return FIO_EOF;
    if (!*buf) {
        *buf = malloc(1);
        if (!*buf) {
            errno = ENOMEM;
            return FIO_ERR;
        }
        *cap = 1;
    }
    (*buf)[n] = '\0';
    return (ssize_t)n;
}

unsigned char *fio_read_all(const char *path, size_t max, size_t *len, char *why,
                            size_t whylen)
{
    const char *bad;
    FILE *fp = fio_open_read(path, 0, &bad);
    if (!fp) {
        snprintf(why, whylen, "%s", bad);
        return NULL;
    }
    struct stat st;
    if (fstat(fileno(fp), &st) != 0) {
        snprintf(why, whylen, "%s", strerror(errno));
        fclose(fp);
        return NULL;
    }
    if ((unsigned long long)st.st_size > max) {
        snprintf(why, whylen, "is %lld bytes, more than the limit of %zu bytes",
                 (long long)st.st_size, max);
        fclose(fp);
        return NULL;
    }
    /* sized by the file, but read to its end: it may have grown (or shrunk) */
    size_t cap = (size_t)st.st_size + 1, n = 0;
    unsigned char *buf = malloc(cap + 1);
    while (buf) {
        n += fread(buf + n, 1, cap - n, fp);
        if (n < cap || ferror(fp))
            break;
        if (n > max)
            break;
        size_t nc = cap * 2 > max + 1 ? max + 1 : cap * 2;
        unsigned char *nb = realloc(buf, nc + 1);
        if (!nb) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = nb;
        cap = nc;
    }
    int err = ferror(fp) ? (errno ? errno : EIO) : 0;
    fclose(fp);
    if (!buf || err || n > max) {
        if (!buf)
            snprintf(why, whylen, "%s", strerror(ENOMEM));
        else if (err)
            snprintf(why, whylen, "%s", strerror(err));
        else
            snprintf(why, whylen, "grew to more than the limit of %zu bytes while read", max);
        free(buf);
        return NULL;
    }
    buf[n] = 0;
    *len = n;
    return buf;
}

FILE *fio_open_write_checked(const char *path, int append, int *errp, const char **why)
{
    *why = NULL;
    *errp = 0;
    int fd = of_open_fd(path, append);
    FILE *fp = fd < 0 ? NULL : of_stream(fd, errp);
    if (!fp)
        *why = strerror(errno);
    return fp;
}

int fio_append_whole(const char *path, int append, const char *s, size_t n, int *opened)
{
    *opened = 0;
    int fd = of_open_fd(path, append);
    if (fd < 0)
        return errno;
    *opened = 1;
    struct stat st;
    off_t before = fstat(fd, &st) == 0 && S_ISREG(st.st_mode) ? st.st_size : -1;
    size_t done = 0;
    int err = 0;
    while (done < n) {
        ssize_t w = write(fd, s + done, n - done);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            err = w < 0 ? errno : ENOSPC;
            break;
        }
        done += (size_t)w;
    }
    if (err && done > 0 && before >= 0 && ftruncate(fd, before) != 0) {
        /* the partial line stays; the error below still says the write failed */
    }
    if (close(fd) != 0 && !err)
        err = errno;
    return err;
}

size_t fio_bom(const char *s, size_t n)
{
    return n >= 3 && (unsigned char)s[0] == 0xEF && (unsigned char)s[1] == 0xBB &&
                   (unsigned char)s[2] == 0xBF
               ? 3
               : 0;
}
