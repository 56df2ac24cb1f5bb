/* test_program_cache.c - the program cache (issue 24): an entry is stored
 * only after it loads back, a damaged entry (empty, cut short, flipped
 * bytes, another key, a PoCL binary whose structure PoCL would assert on)
 * is removed and reported instead of reaching the driver, and a binary
 * taken while PoCL's own cache was cleared is never stored. */
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "engine.h"
#include "ocl.h"
#include "program_cache.h"
#include "test.h"

static char cachedir[] = "/tmp/gravel-pcache-XXXXXX";
static char pocldir[] = "/tmp/gravel-pocl-XXXXXX";

static const char *src = "__kernel void k1(__global int *a) { a[get_global_id(0)] = 1; }\n"
                         "__kernel void k2(__global int *a) { a[0] += 2; }\n";

static cl_program build_source(struct ocl *o, const char *opts)
{
    cl_int err;
    cl_program p = clCreateProgramWithSource(o->ctx, 1, &src, NULL, &err);
    if (p && clBuildProgram(p, 1, &o->device, opts, NULL, NULL) != CL_SUCCESS) {
        clReleaseProgram(p);
        p = NULL;
    }
    return p;
}

static unsigned char *slurp(const char *path, size_t *n)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    fseek(fp, 0, SEEK_END);
    *n = (size_t)ftell(fp);
    fseek(fp, 0, SEEK_SET);
    unsigned char *b = malloc(*n + 1);
    if (b && fread(b, 1, *n, fp) != *n) {
        free(b);
        b = NULL;
    }
    fclose(fp);
    return b;
}

static void spit(const char *path, const unsigned char *b, size_t n)
{
    FILE *fp = fopen(path, "wb");
    if (fp) {
        fwrite(b, 1, n, fp);
        fclose(fp);
    }
}

static void wr64(unsigned char *p, uint64_t v)
{
    for (int i = 0; i < 8; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

/* Re-seal an entry after its binary was edited: a valid length and checksum,
 * so only the structure check stands between the bytes and the driver. */
static void reseal(unsigned char *e, size_t n)
{
    wr64(e + 16, n - PCACHE_HEADER);
    wr64(e + 24, ocl_fnv(OCL_FNV_INIT, e + PCACHE_HEADER, n - PCACHE_HEADER));
}

static size_t nkernels(cl_program p)
{
    size_t nk = 0;
    clGetProgramInfo(p, CL_PROGRAM_NUM_KERNELS, sizeof nk, &nk, NULL);
    return nk;
}

static const uint64_t key = 0x0123456789abcdefull;
static unsigned char *good;
static size_t ngood;

TEST(store_after_loading_back)
{
    struct gravel *g = test_engine();
    struct ocl *o = &eng_get(g)->ocl;
    o->program = build_source(o, "-D STORE");
    CHECK(o->program != NULL);
    pcache_store(o, key, "-D STORE");
    char path[1000];
    CHECK(pcache_path(path, sizeof path, key));
    good = slurp(path, &ngood);
    CHECK(good && ngood > PCACHE_HEADER && memcmp(good, "GRVLPRG1", 8) == 0);
    const unsigned char *bin;
    size_t len;
    CHECK(good && pcache_entry_problem(good, ngood, key, &bin, &len) == NULL);
    cl_program p = pcache_load(g, o, key, "-D STORE");
    CHECK(p && nkernels(p) == 2);
    if (p)
        clReleaseProgram(p);
    gr_destroy(g);
}

/* Write `bytes` as the entry, load it: refused, removed, `why` reported. */
static void damaged(const char *name, const unsigned char *bytes, size_t n, const char *why)
{
    struct gravel *g = test_engine();
    struct ocl *o = &eng_get(g)->ocl;
    char path[1000];
    pcache_path(path, sizeof path, key);
    spit(path, bytes, n);
    const unsigned char *bin;
    size_t len;
    const char *got = pcache_entry_problem(bytes, n, key, &bin, &len);
    int ok = got && strstr(got, why);
    cl_program p = pcache_load(g, o, key, "-D STORE");
    ok = ok && p == NULL && access(path, F_OK) != 0;
    if (!ok)
        printf("  %s: expected '%s', got '%s'\n", name, why, got ? got : "(accepted)");
    CHECK(ok);
    if (p)
        clReleaseProgram(p);
    gr_destroy(g);
}

TEST(damaged_entries_removed)
{
    if (!good)
        return;
    unsigned char *e = malloc(ngood + 1);
    damaged("empty", good, 0, "empty file");
    damaged("header cut", good, 20, "shorter than its header");
    damaged("half", good, ngood / 2, "truncated");
    memcpy(e, good, ngood);
    e[ngood] = 'x';
    damaged("extended", e, ngood + 1, "length does not match");
    memcpy(e, good, ngood);
    for (size_t i = ngood / 2; i < ngood / 2 + 16; i++)
        e[i] ^= 0x5a;
    damaged("flipped", e, ngood, "checksum mismatch");
    memcpy(e, good, ngood);
    e[0] = 'X';
    damaged("magic", e, ngood, "not a gravel program cache entry");
    memcpy(e, good, ngood);
    wr64(e + 8, key + 1);
    damaged("key", e, ngood, "another key");
    free(e);
}

/* PoCL binaries that PoCL itself would abort on (assert in
 * pocl_binary_get_kernels_metadata), sealed with a valid checksum. */
TEST(pocl_structure_checked)
{
    if (!good || memcmp(good + PCACHE_HEADER, "poclbin", 8) != 0) {
        printf("SKIP pocl_structure_checked (the device is not PoCL)\n");
        return;
    }
    unsigned char *e = malloc(ngood);
    const unsigned char *b = good + PCACHE_HEADER;
    size_t hdr = 77 + (b[16] >= 11 && (b[24] & 2) ? 8 : 0);
    /* the program entry emptied, as when PoCL's cache was cleared */
    memcpy(e, good, ngood);
    size_t at = PCACHE_HEADER + hdr;
    uint64_t rootlen = 0;
    for (int i = 7; i >= 0; i--)
        rootlen = rootlen << 8 | e[at + i];
    size_t cut = (size_t)rootlen;
    memmove(e + at + 8, e + at + 8 + cut, ngood - (at + 8 + cut));
    wr64(e + at, 0);
    reseal(e, ngood - cut);
    damaged("empty program entry", e, ngood - cut, "empty program entry");
    /* a kernel record claiming more bytes than the binary holds */
    memcpy(e, good, ngood);
    size_t k0 = at + 8 + cut;
    wr64(e + k0, (uint64_t)ngood * 4);
    reseal(e, ngood);
    damaged("kernel record", e, ngood, "a kernel record does not fit");
    /* no kernels */
    memcpy(e, good, ngood);
    memset(e + PCACHE_HEADER + 20, 0, 4);
    reseal(e, ngood);
    damaged("no kernels", e, ngood, "no kernels");
    free(e);
}

/* PoCL serializes a program's binary from its own cache folder: emptied
 * between build and store, the binary comes out without its program entry.
 * It must not be stored (every later run would abort in PoCL). */
TEST(cleared_pocl_cache_not_stored)
{
    struct gravel *g = test_engine();
    struct ocl *o = &eng_get(g)->ocl;
    o->program = build_source(o, "-D CLEARED");
    CHECK(o->program != NULL);
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf %s/*", pocldir);
    CHECK(system(cmd) == 0);
    uint64_t k2 = key ^ 0xff;
    pcache_store(o, k2, "-D CLEARED");
    char path[1000];
    pcache_path(path, sizeof path, k2);
    CHECK(access(path, F_OK) != 0);
    size_t len = 0;
    clGetProgramInfo(o->program, CL_PROGRAM_BINARY_SIZES, sizeof len, &len, NULL);
    unsigned char *bin = malloc(len ? len : 1);
    unsigned char *bins[1] = {bin};
    clGetProgramInfo(o->program, CL_PROGRAM_BINARIES, sizeof bins, bins, NULL);
    if (len >= 8 && memcmp(bin, "poclbin", 8) == 0) {
        const char *why = pcache_pocl_problem(bin, len);
        CHECK(why && strstr(why, "empty program entry"));
    }
    free(bin);
    gr_destroy(g);
}

int main(void)
{
    /* both caches private: PoCL reads POCL_CACHE_DIR when it starts */
    if (!mkdtemp(cachedir) || !mkdtemp(pocldir))
        return 1;
    setenv("GRAVEL_CACHE_DIR", cachedir, 1);
    setenv("POCL_CACHE_DIR", pocldir, 1);
    RUN(store_after_loading_back);
    RUN(damaged_entries_removed);
    RUN(pocl_structure_checked);
    RUN(cleared_pocl_cache_not_stored);
    free(good);
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf %s %s", cachedir, pocldir);
    return system(cmd) == 0 ? 0 : 1;
}
