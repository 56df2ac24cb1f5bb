/* program_cache.c - built OpenCL programs kept on disk between runs, each
 * entry verified before the driver sees it (format in program_cache.h). */
#include "program_cache.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "error.h"
#include "fileio.h"
#include "outfile.h"

static const char magic[8] = {'G', 'R', 'V', 'L', 'P', 'R', 'G', '1'};
#define MAX_ENTRY ((size_t)512 << 20) /* PoCL's own binaries stop at 256 MiB */

int pcache_wanted(struct gravel *g, const struct ocl *o)
{
    const char *env = getenv("GRAVEL_PROGRAM_CACHE");
    if (env && *env) {
        if (strcmp(env, "0") && strcmp(env, "1"))
            gr_error(g, "GRAVEL_PROGRAM_CACHE must be 0 or 1, got '%.32s'", env);
        return env[0] == '1';
    }
    char name[256] = "";
    clGetPlatformInfo(o->platform, CL_PLATFORM_NAME, sizeof name, name, NULL);
    name[sizeof name - 1] = '\0';
    const char *pk = getenv("POCL_KERNEL_CACHE");
    return !strstr(name, "Portable Computing Language") || (pk && !strcmp(pk, "0"));
}

int pcache_dir(char *buf, size_t n)
{
    const char *d = getenv("GRAVEL_CACHE_DIR");
    if (d && *d) {
        snprintf(buf, n, "%s", d);
        return 1;
    }
    d = getenv("XDG_CACHE_HOME");
    if (d && *d) {
        snprintf(buf, n, "%s/gravel", d);
        return 1;
    }
    d = getenv("HOME");
    if (d && *d) {
        snprintf(buf, n, "%s/.cache/gravel", d);
        return 1;
    }
    return 0;
}

int pcache_path(char *buf, size_t n, uint64_t key)
{
    char dir[900];
    if (!pcache_dir(dir, sizeof dir))
        return 0;
    snprintf(buf, n, "%s/%016llx.gbin", dir, (unsigned long long)key);
    return 1;
}

/* mkdir -p; failures only disable the cache. */
static int make_dirs(const char *path)
{
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", path);
    for (char *p = tmp + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            if (mkdir(tmp, 0755) != 0 && errno != EEXIST)
                return 0;
            *p = '/';
        }
    return mkdir(tmp, 0755) == 0 || errno == EEXIST;
}

/* ---- the checks ------------------------------------------------------------------ */

static uint64_t rd64(const unsigned char *p)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--)
        v = v << 8 | p[i];
    return v;
}

static uint32_t rd32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static void wr64(unsigned char *p, uint64_t v)
{
    for (int i = 0; i < 8; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

const char *pcache_entry_problem(const unsigned char *buf, size_t n, uint64_t key,
                                 const unsigned char **bin, size_t *len)
{
    if (n == 0)
        return "empty file";
    if (n < PCACHE_HEADER)
        return "shorter than its header";
    if (memcmp(buf, magic, sizeof magic) != 0)
        return "not a gravel program cache entry";
    if (rd64(buf + 8) != key)
        return "built for another key";
    uint64_t l = rd64(buf + 16);
    if (l == 0)
        return "empty binary";
    if (l != n - PCACHE_HEADER)
        return "length does not match the file (truncated or extended)";
    if (rd64(buf + 24) != ocl_fnv(OCL_FNV_INIT, buf + PCACHE_HEADER, (size_t)l))
        return "checksum mismatch (damaged bytes)";
    *bin = buf + PCACHE_HEADER;
    *len = (size_t)l;
    if (l >= 8 && memcmp(*bin, "poclbin", 8) == 0)
        return pcache_pocl_problem(*bin, *len);
    return NULL;
}

/* A sequence of serialized files filling p[0..n): each a u32 name length
 * (> 0), the name, a u32 content length and the content. */
static const char *files_problem(const unsigned char *p, uint64_t n, int nonempty)
{
    uint64_t at = 0;
    while (at < n) {
        if (n - at < 4)
            return "PoCL binary: a file entry is cut short";
        uint32_t nl = rd32(p + at);
        at += 4;
        if (nl == 0)
            return "PoCL binary: a file entry has no name";
        if (nl > n - at || n - at - nl < 4)
            return "PoCL binary: a file entry runs past its section";
        at += nl;
        uint32_t cl = rd32(p + at);
        at += 4;
        if (cl > n - at)
            return "PoCL binary: a file's content runs past its section";
        if (cl == 0 && nonempty)
            return "PoCL binary: the program file is empty";
        at += cl;
    }
    return NULL;
}

/* Layout (PoCL 3.x-7.x, lib/CL/pocl_binary.c, format versions 9 to 11):
 * "poclbin\0", u64 device id, u32 version, u32 kernels, u64 flags, u32 root
 * entries, a 41-byte build hash (SHA-1 in hex and a NUL), from version 11 a
 * u64 when flag bit 1 is set; then per root entry a u64 length (never 0:
 * PoCL asserts) and files; then per kernel a u64 record size (from the
 * record's start), the u64 size of its trailing files, a u32 arginfo size,
 * a u32 name length and the name, ... Other versions are left to PoCL. */
const char *pcache_pocl_problem(const unsigned char *b, size_t n)
{
    enum { HDR = 36 + 41, KHDR = 24 };
    if (n < HDR || memcmp(b, "poclbin", 8) != 0)
        return "PoCL binary: no PoCL header";
    uint32_t version = rd32(b + 16), nk = rd32(b + 20), nroot = rd32(b + 32);
    uint64_t flags = rd64(b + 24);
    if (version < 9 || version > 11)
        return NULL;
    if (nk == 0)
        return "PoCL binary: no kernels";
    if (nroot == 0 && version < 11)
        return "PoCL binary: no program entry";
    uint64_t at = HDR + (version >= 11 && (flags & 2) ? 8 : 0);
    if (at > n)
        return "PoCL binary: cut short in its header";
    for (uint32_t r = 0; r < nroot; r++) {
        if (n - at < 8)
            return "PoCL binary: cut short in its program entries";
        uint64_t len = rd64(b + at);
        at += 8;
        if (len == 0)
            return "PoCL binary: an empty program entry (PoCL's cache was cleared while it was "
                   "made)";
        if (len > n - at)
            return "PoCL binary: a program entry runs past the end";
        const char *why = files_problem(b + at, len, 1);
        if (why)
            return why;
        at += len;
    }
    for (uint32_t k = 0; k < nk; k++) {
        if (n - at < KHDR)
            return "PoCL binary: cut short in its kernels";
        uint64_t ss = rd64(b + at), bs = rd64(b + at + 8);
        uint32_t nl = rd32(b + at + 20);
        if (ss > n - at || ss < KHDR || nl == 0 || nl > ss - KHDR || bs > ss - KHDR - nl)
            return "PoCL binary: a kernel record does not fit";
        if (bs > 0) {
            const char *why = files_problem(b + at + ss - bs, bs, 0);
            if (why)
                return why;
        }
        at += ss;
    }
    return at == n ? NULL : "PoCL binary: bytes after the last kernel";
}

/* ---- one build at a time per program ------------------------------------------------ */

#define LOCK_WAIT_S 300

int pcache_build_lock(uint64_t key)
{
    char dir[900], path[1000];
    if (!pcache_dir(dir, sizeof dir) || !make_dirs(dir))
        return -1;
    snprintf(path, sizeof path, "%s/build-%02u.lock", dir, (unsigned)(key % 64));
    int fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
        return -1;
    /* a holder that never ends its build (stopped, hung) delays a run by at
     * most LOCK_WAIT_S, after which it builds without the lock */
    for (int tries = 0; flock(fd, LOCK_EX | LOCK_NB) != 0; tries++) {
        if ((errno != EWOULDBLOCK && errno != EINTR) || tries >= LOCK_WAIT_S * 20) {
            close(fd);
            return -1;
        }
        usleep(50000);
    }
    return fd;
}

void pcache_build_unlock(int fd)
{
    if (fd >= 0)
        close(fd); /* releases the lock */
}

/* ---- loading ----------------------------------------------------------------------- */

/* The whole regular file at path (malloc'd), NULL if missing or unreadable;
 * *n its size (0 for an empty file, which comes back as a 1-byte buffer). */
static unsigned char *slurp(const char *path, size_t *n)
{
    const char *why;
    FILE *fp = fio_open_read(path, 0, &why);
    if (!fp)
        return NULL;
    struct stat st;
    unsigned char *buf = NULL;
    if (fstat(fileno(fp), &st) == 0 && (uint64_t)st.st_size <= MAX_ENTRY) {
        *n = (size_t)st.st_size;
        buf = malloc(*n ? *n : 1);
        if (buf && fread(buf, 1, *n, fp) != *n) {
            free(buf);
            buf = NULL;
        }
    }
    fclose(fp);
    return buf;
}

/* The number of kernels of a built program (0 when it has none or the
 * driver cannot say). */
static size_t kernel_count(cl_program p)
{
    size_t nk = 0;
    if (clGetProgramInfo(p, CL_PROGRAM_NUM_KERNELS, sizeof nk, &nk, NULL) != CL_SUCCESS)
        return 0;
    return nk;
}

/* Create and build a program from a binary the checks above accepted;
 * NULL if the driver refuses it or it has no kernels. */
static cl_program from_binary(struct ocl *o, const unsigned char *bin, size_t len,
                              const char *options)
{
    cl_int st = CL_SUCCESS, err = CL_SUCCESS;
    cl_program p = clCreateProgramWithBinary(o->ctx, 1, &o->device, &len, &bin, &st, &err);
    if (!p)
        return NULL;
    if (err != CL_SUCCESS || st != CL_SUCCESS ||
        clBuildProgram(p, 1, &o->device, options, NULL, NULL) != CL_SUCCESS ||
        kernel_count(p) == 0) {
        clReleaseProgram(p);
        return NULL;
    }
    return p;
}

cl_program pcache_load(struct gravel *g, struct ocl *o, uint64_t key, const char *options)
{
    char path[1000];
    if (!pcache_path(path, sizeof path, key))
        return NULL;
    size_t n = 0;
    unsigned char *buf = slurp(path, &n);
    if (!buf)
        return NULL;
    const unsigned char *bin = NULL;
    size_t len = 0;
    const char *why = pcache_entry_problem(buf, n, key, &bin, &len);
    cl_program p = why ? NULL : from_binary(o, bin, len, options);
    free(buf);
    if (!p) {
        unlink(path);
        gr_warn(g, "program cache entry %s is damaged (%s): removed, building from source",
                path, why ? why : "the OpenCL driver refused it");
    }
    return p;
}

/* ---- storing ------------------------------------------------------------------------ */

void pcache_store(struct ocl *o, uint64_t key, const char *options)
{
    char dir[900], path[1000];
    if (!pcache_dir(dir, sizeof dir) || !pcache_path(path, sizeof path, key))
        return;
    size_t len = 0;
    if (clGetProgramInfo(o->program, CL_PROGRAM_BINARY_SIZES, sizeof len, &len, NULL) !=
            CL_SUCCESS || len == 0 || len > MAX_ENTRY - PCACHE_HEADER)
        return;
    unsigned char *buf = malloc(PCACHE_HEADER + len);
    if (!buf)
        return;
    unsigned char *bins[1] = {buf + PCACHE_HEADER};
    memcpy(buf, magic, sizeof magic);
    wr64(buf + 8, key);
    wr64(buf + 16, len);
    const unsigned char *bin;
    size_t blen;
    cl_program back = NULL;
    if (clGetProgramInfo(o->program, CL_PROGRAM_BINARIES, sizeof bins, bins, NULL) ==
        CL_SUCCESS) {
        wr64(buf + 24, ocl_fnv(OCL_FNV_INIT, buf + PCACHE_HEADER, len));
        /* the entry as a later run will see it: verified, then loaded back */
        if (!pcache_entry_problem(buf, PCACHE_HEADER + len, key, &bin, &blen))
            back = from_binary(o, bin, blen, options);
    }
    struct stat st;
    int usable = lstat(path, &st) != 0 || S_ISREG(st.st_mode); /* never a device or FIFO */
    if (back && usable && kernel_count(back) == kernel_count(o->program) && make_dirs(dir)) {
        char suffix[32];
        snprintf(suffix, sizeof suffix, ".tmp%ld", (long)getpid());
        struct ofile f;
        if (of_open(&f, path, suffix, OF_TRUNC) == 0) {
            fwrite(buf, 1, PCACHE_HEADER + len, f.fp);
            of_commit(&f, 0);
        }
    }
    if (back)
        clReleaseProgram(back);
    free(buf);
}
