/* ocl.h - the OpenCL layer: device choice, checked calls, program build with
 * an on-disk binary cache.
 *
 * Every OpenCL call goes through OCL_CHECK (or ocl_check), which raises a
 * gr_error naming the call and the CL error name. One struct ocl per engine;
 * ocl_release() frees everything it created. */
#ifndef GR_OCL_H
#define GR_OCL_H

#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>

#include "state.h"

struct ocl {
    cl_platform_id platform;
    cl_device_id device;
    cl_context ctx;
    cl_command_queue queue;
    cl_program program;         /* the run's program (NULL until ocl_build) */
    uint64_t program_key;       /* hash of sources + options + device of `program` */
    char name[256];             /* device name as the driver reports it */
    char version[256];          /* driver + platform version (part of the cache key) */
    int is_gpu;
    int serial;                 /* PoCL's serial CPU device (ocl_init: -device serial, or a
                                 * scene under OCL_SERIAL_ATOMS atoms by default) */
    int threads;                /* PoCL threads this rank asked for, sharing its node's
                                 * cores with the other ranks there (0: not asked) */
    int host_unified;           /* a CPU device on host memory (CL_DEVICE_HOST_UNIFIED_MEMORY):
                                 * buffers may be the host's arrays (ocl_wrap); env
                                 * GRAVEL_HOST_SHARE=0 turns that off */
    int fp64;                   /* device supports cl_khr_fp64 */
    int pcache;                 /* gravel's program cache is in use (pcache_wanted) */
    int cache_hit;              /* last ocl_build loaded a cached binary */
    int profile;                /* env GRAVEL_PROFILE: time every kernel (device.c) */
    size_t max_alloc;           /* CL_DEVICE_MAX_MEM_ALLOC_SIZE */
    size_t global_mem;          /* CL_DEVICE_GLOBAL_MEM_SIZE, or env GRAVEL_DEVICE_MEMORY
                                 * (bytes) when that is less */
    int atoms_hint;             /* atoms the buffers are sized for (error messages) */
    size_t wg;                  /* work-group size of every launch (device.c): env
                                 * GRAVEL_WORKGROUP, else 128 capped by the device */
    int lanes_double;           /* contacts per work-item of a lane-generic law (kernels/
                                 * lanes.cl) in double and in single: env GRAVEL_LANES
                                 * (ocl.c, ocl_lanes), 4 on a CPU by default */
    int lanes_float;
};

/* Bytes in live device buffers of this process, and the most at once since
 * ocl_mem_reset_peak() (counted by buffer destructor callbacks). */
long long ocl_mem_live(void);
long long ocl_mem_peak(void);
void ocl_mem_reset_peak(void);

/* Address space this process may still take under its limit (ulimit -v),
 * with the limit in *limit; SIZE_MAX (both) when there is none. */
size_t ocl_address_left(size_t *limit);

/* Symbolic name of a CL error code ("CL_OUT_OF_RESOURCES"). */
const char *ocl_errname(cl_int err);
/* Raise "<call> failed: <CL error name>" unless err == CL_SUCCESS. */
void ocl_check(struct gravel *g, cl_int err, const char *call);
#define OCL_CHECK(g, call) ocl_check((g), (call), #call)

/* Scenes of fewer atoms per process run on PoCL's serial device by default. */
#define OCL_SERIAL_ATOMS 1500

/* Pick the device: `want` is "", "cpu", "serial", "gpu" or a device index
 * over all platforms; "" falls back to env GRAVEL_DEVICE and then to the
 * first CPU device (PoCL), else the first device: PoCL's serial device for
 * fewer than OCL_SERIAL_ATOMS `atoms` (-1: unknown). Creates context and
 * in-order queue. */
void ocl_init(struct gravel *g, struct ocl *o, const char *want, long atoms);

/* Build (or load from the cache) one program from `n` named sources
 * concatenated in order, with compiler `options`. A build failure raises an
 * error with the compiler log, naming the source file the first error line
 * points into. No-op when the current program has the same key. */
void ocl_build(struct gravel *g, struct ocl *o, int n, const char *const *names,
               const char *const *texts, const char *options);

/* Kernel `name` of the current program (checked). */
cl_kernel ocl_kernel(struct gravel *g, struct ocl *o, const char *name);
/* Checked buffer allocation; size 0 allocates a minimal buffer. */
cl_mem ocl_alloc(struct gravel *g, struct ocl *o, size_t bytes, const char *what);
/* A buffer that is the host memory at `host` (CL_MEM_USE_HOST_PTR; aligned
 * to the device's CL_DEVICE_MEM_BASE_ADDR_ALIGN so the runtime keeps no
 * copy of its own). Not counted in ocl_mem_live: it takes no new memory. */
cl_mem ocl_wrap(struct gravel *g, struct ocl *o, void *host, size_t bytes, const char *what);
/* Release every object (safe on a zeroed or partly built struct). */
void ocl_release(struct ocl *o);

/* 64-bit FNV-1a of p[0..n) continuing from h (start with OCL_FNV_INIT):
 * the program's cache key and the cache entries' checksum. */
#define OCL_FNV_INIT 1469598103934665603ull
uint64_t ocl_fnv(uint64_t h, const void *p, size_t n);

#endif
