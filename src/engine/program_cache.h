/* program_cache.h - the on-disk cache of built OpenCL programs.
 *
 * An entry is `<dir>/<key>.gbin`: a 32-byte header (magic "GRVLPRG1", the
 * build key, the binary's length and its FNV-1a hash, little-endian) and the
 * device binary. An entry is trusted only when every header field verifies
 * and, for a PoCL binary, its serialized structure is whole (PoCL asserts on
 * a malformed binary inside clCreateProgramWithBinary and aborts the
 * process, so nothing unverified is ever handed to it). A binary is stored
 * only after it has been loaded back (created, built, kernels counted), and
 * is written by outfile.h's rule (temporary + rename). A damaged entry is
 * removed with one warning and the program is rebuilt from source. */
#ifndef GR_PROGRAM_CACHE_H
#define GR_PROGRAM_CACHE_H

#include <stddef.h>
#include <stdint.h>

#include "ocl.h"

#define PCACHE_HEADER 32

/* Whether runs on o's device read and write the cache: env
 * GRAVEL_PROGRAM_CACHE=1 or 0; by default not on PoCL with its own kernel
 * cache on (POCL_KERNEL_CACHE unset or not 0), which keeps every compiled
 * kernel itself: there, fetching the binary to store (CL_PROGRAM_BINARIES)
 * compiles every kernel of the program once more, most of a cold build's
 * time. Any other value of the variable is an error. */
int pcache_wanted(struct gravel *g, const struct ocl *o);

/* Directory of the program cache (env GRAVEL_CACHE_DIR, else
 * $XDG_CACHE_HOME/gravel, else ~/.cache/gravel) into buf; 0 if none. */
int pcache_dir(char *buf, size_t n);
/* The entry file of `key` in buf; 0 when there is no cache directory. */
int pcache_path(char *buf, size_t n, uint64_t key);

/* Serialize the builds of one program among processes: take (and wait for)
 * the lock of `key` (one of 64 files `build-NN.lock` in the cache
 * directory, by key), so that ranks or runs starting the same program at
 * once compile it once and the others take it from the driver's or gravel's
 * cache; after 300 s of waiting it goes on without the lock. Returns the
 * descriptor to give to pcache_build_unlock, -1 when there is no lock (no
 * cache directory, or the wait ran out). Not collective. */
int pcache_build_lock(uint64_t key);
void pcache_build_unlock(int fd);

/* The cached program of `key`, built with `options` and holding kernels;
 * NULL when there is none, or when the entry is damaged (it is removed with
 * a warning naming the reason). */
cl_program pcache_load(struct gravel *g, struct ocl *o, uint64_t key, const char *options);
/* Store the binary of o->program (built from source) under `key` once it
 * has loaded back with the same number of kernels. A failure only leaves
 * the cache without the entry. */
void pcache_store(struct ocl *o, uint64_t key, const char *options);

/* What is wrong with the entry bytes buf[0..n) for `key` (NULL if nothing);
 * on success *bin, *len give the binary inside. */
const char *pcache_entry_problem(const unsigned char *buf, size_t n, uint64_t key,
                                 const unsigned char **bin, size_t *len);
/* What is wrong with the structure of PoCL binary b[0..n) (NULL if nothing):
 * the checks PoCL makes with assert() when it loads one. */
const char *pcache_pocl_problem(const unsigned char *b, size_t n);

#endif
