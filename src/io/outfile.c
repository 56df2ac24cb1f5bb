/* outfile.c - opening, writing and finishing output files: atomic
 * replacement for regular files, write-through for everything else, symlinks
 * followed, every write checked (issue 24; the rule is in outfile.h). */
#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "comm.h"

/* ---- where the bytes go --------------------------------------------------- */

/* The target of symlink `link` as a path usable from here (a relative
 * target is taken against the link's folder). malloc'd, NULL with errno. */
static char *link_target(const char *link, size_t hint)
{
    size_t cap = hint + 2 > 64 ? hint + 2 : 64;
    char *t = NULL;
    for (;;) {
        char *p = realloc(t, cap);
        if (!p) {
            free(t);
            errno = ENOMEM;
            return NULL;
        }
        t = p;
        ssize_t n = readlink(link, t, cap);
        if (n < 0) {
            free(t);
            return NULL;
        }
        if ((size_t)n < cap) {
            t[n] = '\0';
            break;
        }
        cap *= 2;
    }
    const char *slash = strrchr(link, '/');
    if (t[0] == '/' || !slash)
        return t;
    size_t dl = (size_t)(slash - link) + 1, tl = strlen(t);
    char *full = malloc(dl + tl + 1);
    if (full) {
        memcpy(full, link, dl);
        memcpy(full + dl, t, tl + 1);
    } else {
        errno = ENOMEM;
    }
    free(t);
    return full;
}

int of_resolve(const char *path, char **final, int *through)
{
    *final = NULL;
    *through = 0;
    char *cur = strdup(path);
    if (!cur)
        return ENOMEM;
    for (int hops = 0;; hops++) {
        struct stat st;
        int r = lstat(cur, &st);
        if (r != 0 || !S_ISLNK(st.st_mode)) {
            /* missing (or unreadable: the open reports why): a new regular file */
            *through = r == 0 && !S_ISREG(st.st_mode);
            *final = cur;
            return 0;
        }
        if (hops >= OF_MAXLINKS) {
            free(cur);
            return ELOOP;
        }
        char *next = link_target(cur, (size_t)st.st_size);
        if (!next) {
            int e = errno;
            free(cur);
            return e;
        }
        free(cur);
        cur = next;
    }
}

/* ---- checked streams ------------------------------------------------------- */

struct sink {
    int fd;
    int *errp;
};

static ssize_t sink_write(void *cookie, const char *buf, size_t n)
{
    struct sink *k = cookie;
    size_t done = 0;
    while (done < n) {
        ssize_t w = write(k->fd, buf + done, n - done);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            if (!*k->errp)
                *k->errp = w < 0 ? errno : ENOSPC;
            return -1;
        }
        done += (size_t)w;
    }
    return (ssize_t)n;
}

static int sink_seek(void *cookie, off64_t *pos, int whence)
{
    struct sink *k = cookie;
    off_t r = lseek(k->fd, (off_t)*pos, whence);
    if (r < 0)
        return -1;
    *pos = (off64_t)r;
    return 0;
}

static int sink_close(void *cookie)
{
    struct sink *k = cookie;
    int rc = close(k->fd);
    if (rc != 0 && !*k->errp)
        *k->errp = errno;
    free(k);
    return rc;
}

FILE *of_stream(int fd, int *errp)
{
    *errp = 0;
    struct sink *k = malloc(sizeof *k);
    if (!k) {
        close(fd);
        errno = ENOMEM;
        return NULL;
    }
    k->fd = fd;
    k->errp = errp;
    cookie_io_functions_t io = {NULL, sink_write, sink_seek, sink_close};
    FILE *fp = fopencookie(k, "w", io);
    if (!fp) {
        int e = errno;
        close(fd);
        free(k);
        errno = e;
    }
    return fp;
}

/* ---- opening in place ------------------------------------------------------- */

/* open(2) for writing that waits a bounded time for a FIFO's reader. */
static int open_waiting(const char *path, int flags)
{
    struct timespec nap = {0, 10 * 1000 * 1000};
    for (int waited = 0;; waited += 10) {
        int fd = open(path, flags);
        if (fd >= 0 || errno != ENXIO || waited >= OF_FIFO_WAIT_MS)
            return fd;
        struct stat st;
        if (stat(path, &st) != 0 || !S_ISFIFO(st.st_mode))
            return -1; /* a socket or a device without a driver: ENXIO now */
        nanosleep(&nap, NULL);
        errno = ENXIO;
    }
}

/* of_open_fd on a path without symlinks in its last component. */
static int open_fd_final(const char *path, int append)
{
    int fl = O_WRONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK | O_NOFOLLOW | (append ? O_APPEND : 0);
    int fd = -1;
    for (int tries = 0; fd < 0 && tries < 3; tries++) {
        /* an existing file of any kind is opened as it is; only a missing
         * name is created, and O_CREAT only ever creates a regular file */
        fd = open_waiting(path, fl);
        if (fd < 0 && errno == ENOENT)
            fd = open(path, fl | O_CREAT | O_EXCL, 0666);
        if (fd < 0 && errno != EEXIST)
            return -1;
    }
    if (fd < 0)
        return -1;
    struct stat st;
    int f = fcntl(fd, F_GETFL);
    if (f < 0 || fcntl(fd, F_SETFL, f & ~O_NONBLOCK) != 0 || fstat(fd, &st) != 0 ||
        (S_ISREG(st.st_mode) && !append && ftruncate(fd, 0) != 0)) {
        int e = errno;
        close(fd);
        errno = e;
        return -1;
    }
    return fd;
}

int of_open_fd(const char *path, int append)
{
    char *final;
    int through;
    int e = comm_rank() == 0 ? of_resolve(path, &final, &through)
                             : (final = strdup("/dev/null")) ? 0 : ENOMEM;
    if (e) {
        errno = e;
        return -1;
    }
    int fd = open_fd_final(final, append);
    e = errno;
    free(final);
    errno = e;
    return fd;
}

/* ---- atomic or through ------------------------------------------------------ */

static void set_failed(struct ofile *o, const char *name)
{
    snprintf(o->failed, sizeof o->failed, "%s", name);
}

static void of_clear(struct ofile *o)
{
    free(o->final);
    free(o->tmp);
    o->final = o->tmp = NULL;
    o->fp = NULL;
    o->fd = -1;
}

/* Append the content of regular file `from` (if it exists) to fd. */
static int copy_file(const char *from, int fd)
{
    int in = open(from, O_RDONLY | O_CLOEXEC | O_NOCTTY);
    if (in < 0)
        return errno == ENOENT ? 0 : errno;
    char buf[65536];
    int err = 0;
    for (;;) {
        ssize_t r = read(in, buf, sizeof buf);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0) {
            err = r < 0 ? errno : 0;
            break;
        }
        for (ssize_t done = 0; done < r && !err;) {
            ssize_t w = write(fd, buf + done, (size_t)(r - done));
            if (w < 0 && errno == EINTR)
                continue;
            if (w <= 0)
                err = w < 0 ? errno : ENOSPC;
            else
                done += w;
        }
        if (err)
            break;
    }
    close(in);
    return err;
}

/* Create the temporary beside the final target: a regular file (a leftover
 * temporary is emptied; a non-regular one is refused, never removed), with
 * the permissions of the file it will replace. -1 with errno. */
static int open_temp(const char *tmp, const char *final)
{
    int fd = open(tmp, O_WRONLY | O_CREAT | O_CLOEXEC | O_NOCTTY | O_NOFOLLOW | O_NONBLOCK,
                  0666);
    if (fd < 0)
        return -1;
    struct stat st, old;
    int f = fcntl(fd, F_GETFL);
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        errno = EEXIST;
        return -1;
    }
    if (f < 0 || fcntl(fd, F_SETFL, f & ~O_NONBLOCK) != 0 || ftruncate(fd, 0) != 0 ||
        (stat(final, &old) == 0 && S_ISREG(old.st_mode) &&
         fchmod(fd, old.st_mode & 07777) != 0)) {
        int e = errno;
        close(fd);
        unlink(tmp);
        errno = e;
        return -1;
    }
    return fd;
}

/* of_open's failure exit: name the file, release everything. */
static int open_failed(struct ofile *o, const char *name, int e)
{
    set_failed(o, name);
    of_clear(o);
    return e;
}

int of_open(struct ofile *o, const char *path, const char *suffix, enum of_mode mode)
{
    memset(o, 0, sizeof *o);
    o->fd = -1;
    if (!*path)
        return open_failed(o, path, ENOENT); /* never a bare "<suffix>" file */
    int through;
    int e = comm_rank() == 0 ? of_resolve(path, &o->final, &through)
                             : (through = 1, (o->final = strdup("/dev/null")) ? 0 : ENOMEM);
    if (e)
        return open_failed(o, path, e);
    int fd = -1;
    if (!through) {
        size_t n = strlen(o->final) + strlen(suffix) + 1;
        if (!(o->tmp = malloc(n)))
            return open_failed(o, path, ENOMEM);
        snprintf(o->tmp, n, "%s%s", o->final, suffix);
        fd = open_temp(o->tmp, o->final);
        e = errno;
        struct stat st;
        if (fd < 0 && (e == EACCES || e == EPERM || e == EROFS) && stat(o->final, &st) == 0 &&
            S_ISREG(st.st_mode)) {
            /* a folder that takes no temporary: write the file in place */
            free(o->tmp);
            o->tmp = NULL;
            through = 1;
        } else if (fd < 0) {
            return open_failed(o, o->tmp, e);
        } else if (mode == OF_CONTINUE && (e = copy_file(o->final, fd)) != 0) {
            close(fd);
            unlink(o->tmp);
            o->copying = 1;
            return open_failed(o, o->final, e);
        }
    }
    if (through && (fd = open_fd_final(o->final, mode == OF_CONTINUE)) < 0)
        return open_failed(o, o->final, errno);
    o->fp = of_stream(fd, &o->err); /* closes fd on failure */
    if (!o->fp) {
        e = errno;
        if (o->tmp)
            unlink(o->tmp);
        return open_failed(o, o->tmp ? o->tmp : o->final, e);
    }
    o->fd = fd;
    return 0;
}

int of_through(const struct ofile *o)
{
    return o->tmp == NULL;
}

int of_flush(struct ofile *o)
{
    if (!o->fp)
        return 0;
    if (fflush(o->fp) != 0 || ferror(o->fp))
        return o->err ? o->err : EIO;
    return 0;
}

int of_commit(struct ofile *o, int flags)
{
    if (!o->fp) {
        of_clear(o);
        return 0;
    }
    int e = of_flush(o);
    if (!e && o->tmp && (flags & OF_SYNC) && fsync(o->fd) != 0)
        e = errno;
    if (fclose(o->fp) != 0 && !e)
        e = o->err ? o->err : EIO;
    o->fp = NULL;
    if (!e && o->tmp) {
        /* the target may have changed kind since it was opened: never
         * rename over a file that is not regular */
        struct stat st;
        if (lstat(o->final, &st) == 0 && !S_ISREG(st.st_mode))
            e = EEXIST;
        else if (rename(o->tmp, o->final) != 0)
            e = errno;
    }
    if (e && o->tmp && !(flags & OF_KEEP))
        unlink(o->tmp);
    of_clear(o);
    return e;
}

void of_abort(struct ofile *o)
{
    if (o->fp)
        fclose(o->fp);
    if (o->tmp)
        unlink(o->tmp);
    of_clear(o);
}
