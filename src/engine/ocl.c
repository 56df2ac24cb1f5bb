/* ocl.c - OpenCL device choice, checked calls and the program cache.
 *
 * Built programs are cached on disk under a 64-bit FNV-1a hash of (sources,
 * options, device name, driver and platform version) by program_cache.c,
 * which verifies every entry before the driver sees it. */
#include "ocl.h"

#include <errno.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "comm.h"
#include "error.h"
#include "program_cache.h"

const char *ocl_errname(cl_int err)
{
    switch (err) {
#define E(x) case x: return #x;
    E(CL_SUCCESS) E(CL_DEVICE_NOT_FOUND) E(CL_DEVICE_NOT_AVAILABLE) E(CL_COMPILER_NOT_AVAILABLE)
    E(CL_MEM_OBJECT_ALLOCATION_FAILURE) E(CL_OUT_OF_RESOURCES) E(CL_OUT_OF_HOST_MEMORY)
    E(CL_PROFILING_INFO_NOT_AVAILABLE) E(CL_MEM_COPY_OVERLAP) E(CL_IMAGE_FORMAT_MISMATCH)
    E(CL_IMAGE_FORMAT_NOT_SUPPORTED) E(CL_BUILD_PROGRAM_FAILURE) E(CL_MAP_FAILURE)
    E(CL_MISALIGNED_SUB_BUFFER_OFFSET) E(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST)
    E(CL_COMPILE_PROGRAM_FAILURE) E(CL_LINKER_NOT_AVAILABLE) E(CL_LINK_PROGRAM_FAILURE)
    E(CL_DEVICE_PARTITION_FAILED) E(CL_KERNEL_ARG_INFO_NOT_AVAILABLE) E(CL_INVALID_VALUE)
    E(CL_INVALID_DEVICE_TYPE) E(CL_INVALID_PLATFORM) E(CL_INVALID_DEVICE) E(CL_INVALID_CONTEXT)
    E(CL_INVALID_QUEUE_PROPERTIES) E(CL_INVALID_COMMAND_QUEUE) E(CL_INVALID_HOST_PTR)
    E(CL_INVALID_MEM_OBJECT) E(CL_INVALID_IMAGE_FORMAT_DESCRIPTOR) E(CL_INVALID_IMAGE_SIZE)
    E(CL_INVALID_SAMPLER) E(CL_INVALID_BINARY) E(CL_INVALID_BUILD_OPTIONS) E(CL_INVALID_PROGRAM)
    E(CL_INVALID_PROGRAM_EXECUTABLE) E(CL_INVALID_KERNEL_NAME) E(CL_INVALID_KERNEL_DEFINITION)
    E(CL_INVALID_KERNEL) E(CL_INVALID_ARG_INDEX) E(CL_INVALID_ARG_VALUE) E(CL_INVALID_ARG_SIZE)
    E(CL_INVALID_KERNEL_ARGS) E(CL_INVALID_WORK_DIMENSION) E(CL_INVALID_WORK_GROUP_SIZE)
    E(CL_INVALID_WORK_ITEM_SIZE) E(CL_INVALID_GLOBAL_OFFSET) E(CL_INVALID_EVENT_WAIT_LIST)
    E(CL_INVALID_EVENT) E(CL_INVALID_OPERATION) E(CL_INVALID_GL_OBJECT) E(CL_INVALID_BUFFER_SIZE)
    E(CL_INVALID_MIP_LEVEL) E(CL_INVALID_GLOBAL_WORK_SIZE) E(CL_INVALID_PROPERTY)
    E(CL_INVALID_IMAGE_DESCRIPTOR) E(CL_INVALID_COMPILER_OPTIONS) E(CL_INVALID_LINKER_OPTIONS)
    E(CL_INVALID_DEVICE_PARTITION_COUNT)
#undef E
    case -1001: return "CL_PLATFORM_NOT_FOUND_KHR (no OpenCL platform: is pocl-opencl-icd installed?)";
    default: return "unknown OpenCL error";
    }
}

void ocl_check(struct gravel *g, cl_int err, const char *call)
{
    if (err != CL_SUCCESS) {
        char name[96];
        size_t len = strcspn(call, "(");
        if (len > sizeof name - 1)
            len = sizeof name - 1;
        memcpy(name, call, len);
        name[len] = '\0';
        gr_error(g, "OpenCL %s failed: %s (%d)", name, ocl_errname(err), (int)err);
    }
}

/* All devices of all platforms, in platform order. */
static int list_devices(struct gravel *g, cl_platform_id *plat, cl_device_id *dev, int max)
{
    cl_uint np = 0;
    cl_int err = clGetPlatformIDs(0, NULL, &np);
    if (err != CL_SUCCESS || np == 0)
        gr_error(g, "no OpenCL platform found (%s): install pocl-opencl-icd "
                    "(apt-get install -y pocl-opencl-icd ocl-icd-opencl-dev)", ocl_errname(err));
    cl_platform_id ps[16];
    if (np > 16)
        np = 16;
    OCL_CHECK(g, clGetPlatformIDs(np, ps, NULL));
    int n = 0;
    for (cl_uint p = 0; p < np; p++) {
        cl_uint nd = 0;
        if (clGetDeviceIDs(ps[p], CL_DEVICE_TYPE_ALL, 0, NULL, &nd) != CL_SUCCESS)
            continue;
        cl_device_id ds[32];
        if (nd > 32)
            nd = 32;
        if (clGetDeviceIDs(ps[p], CL_DEVICE_TYPE_ALL, nd, ds, NULL) != CL_SUCCESS)
            continue;
        for (cl_uint d = 0; d < nd && n < max; d++) {
            plat[n] = ps[p];
            dev[n++] = ds[d];
        }
    }
    if (n == 0)
        gr_error(g, "no OpenCL device found on any platform");
    return n;
}

/* The lane widths (struct ocl): env GRAVEL_LANES = 1, 2, 4, 8 or 16, or
 * "device" (the device's preferred vector width of the precision); by
 * default OCL_LANES on a CPU device, capped by that preferred width, and 1
 * on a GPU, whose lanes are its work-items. Measured on PoCL 3.1 (AVX-512,
 * doc/benchmark.md, lanes that skip apart groups): 4 lanes take the dense
 * packing 1.4x faster than 1, the chute 1.03x, the gas 0.95x, in both
 * precisions; 8 and 16 lose on every deck. */
#define OCL_LANES 4

static void ocl_lanes(struct gravel *g, struct ocl *o)
{
    cl_uint wd = 1, wf = 1;
    const char *env = getenv("GRAVEL_LANES");
    if (!o->is_gpu && (!env || !*env || !strcmp(env, "device"))) {
        clGetDeviceInfo(o->device, CL_DEVICE_PREFERRED_VECTOR_WIDTH_DOUBLE, sizeof wd, &wd, NULL);
        clGetDeviceInfo(o->device, CL_DEVICE_PREFERRED_VECTOR_WIDTH_FLOAT, sizeof wf, &wf, NULL);
        if (!env || !*env) {
            wd = wd < OCL_LANES ? wd : OCL_LANES;
            wf = wf < OCL_LANES ? wf : OCL_LANES;
        }
    } else if (env && *env && strcmp(env, "device")) {
        char *end;
        long v = strtol(env, &end, 10);
        if (*end || (v != 1 && v != 2 && v != 4 && v != 8 && v != 16))
            gr_error(g, "GRAVEL_LANES must be 1, 2, 4, 8 or 16 contacts per work-item, or "
                        "device, got '%.32s'", env);
        wd = wf = (cl_uint)v;
    }
    o->lanes_double = 1;
    o->lanes_float = 1;
    while (o->lanes_double < 16 && (cl_uint)o->lanes_double * 2 <= wd)
        o->lanes_double *= 2;
    while (o->lanes_float < 16 && (cl_uint)o->lanes_float * 2 <= wf)
        o->lanes_float *= 2;
}

/* Whether the run takes PoCL's serial CPU device ("basic": kernels run in
 * the calling thread) instead of its threaded one: when asked (`serial`),
 * or by default (no device named) for a scene of fewer than
 * OCL_SERIAL_ATOMS atoms per process, where the threaded device's hand-off
 * to its worker threads and back (45-70 us per wait on PoCL 3.1 here)
 * costs more than a second core gains (doc/opencl.md, Serial device). Never
 * when the environment already names PoCL's devices (POCL_DEVICES). */
static int serial_wanted(const char *want, long atoms)
{
    const char *pd = getenv("POCL_DEVICES");
    if (pd && *pd)
        return 0;
    if (want && *want)
        return !strcmp(want, "serial");
    return atoms >= 0 && atoms < OCL_SERIAL_ATOMS;
}

/* Ranks that share a node share its cores: unless the environment says
 * otherwise, each rank's PoCL threads are the cores it may run on (its
 * binding), at most the node's cores over its ranks, at least one, so that
 * N ranks do not start N threads per core (doc/parallel.md, On a CPU).
 * Set before PoCL lists its devices (it reads the variable then); returns
 * the count set (0: none), to be taken back after. */
static int share_cores(void)
{
    const char *set = getenv("POCL_MAX_PTHREAD_COUNT");
    int ranks = comm_local_size();
    if (ranks < 2 || (set && *set))
        return 0;
    long online = sysconf(_SC_NPROCESSORS_ONLN);
    int threads = online > 0 ? (int)(online / ranks) : 1;
    cpu_set_t mask;
    if (sched_getaffinity(0, sizeof mask, &mask) == 0 && CPU_COUNT(&mask) < threads)
        threads = CPU_COUNT(&mask);
    threads = threads > 1 ? threads : 1;
    char v[16];
    snprintf(v, sizeof v, "%d", threads);
    setenv("POCL_MAX_PTHREAD_COUNT", v, 1);
    return threads;
}

void ocl_init(struct gravel *g, struct ocl *o, const char *want, long atoms)
{
    cl_platform_id plat[64];
    cl_device_id dev[64];
    if (!want || !*want)
        want = getenv("GRAVEL_DEVICE");
    /* PoCL reads POCL_DEVICES once, when the platform is first listed; the
     * variable is taken back after it, so no child process inherits it */
    o->serial = serial_wanted(want, atoms);
    if (o->serial)
        setenv("POCL_DEVICES", "basic", 1);
    o->threads = o->serial ? 0 : share_cores();
    int n = list_devices(g, plat, dev, 64);
    if (o->serial)
        unsetenv("POCL_DEVICES");
    if (o->threads)
        unsetenv("POCL_MAX_PTHREAD_COUNT");
    if (!want || !*want || !strcmp(want, "serial"))
        want = "cpu";
    int pick = -1;
    if (!strcmp(want, "cpu") || !strcmp(want, "gpu")) {
        cl_device_type t = !strcmp(want, "cpu") ? CL_DEVICE_TYPE_CPU : CL_DEVICE_TYPE_GPU;
        /* GPUs round-robin over the ranks of a node: its k-th rank takes the
         * (k mod count)-th GPU (one process: the first) */
        int nt = 0, skip = 0;
        for (int i = 0; i < n; i++) {
            cl_device_type dt;
            nt += clGetDeviceInfo(dev[i], CL_DEVICE_TYPE, sizeof dt, &dt, NULL) == CL_SUCCESS &&
                  (dt & t);
        }
        if (t == CL_DEVICE_TYPE_GPU && nt > 0)
            skip = comm_local_rank() % nt;
        for (int i = 0; i < n && pick < 0; i++) {
            cl_device_type dt;
            if (clGetDeviceInfo(dev[i], CL_DEVICE_TYPE, sizeof dt, &dt, NULL) == CL_SUCCESS &&
                (dt & t) && skip-- == 0)
                pick = i;
        }
        if (pick < 0 && !strcmp(want, "gpu"))
            gr_error(g, "-device gpu: no GPU OpenCL device found (%d device(s) present)", n);
        if (pick < 0)
            pick = 0;
    } else {
        char *end;
        long k = strtol(want, &end, 10);
        if (*end || end == want || k < 0 || k >= n)
            gr_error(g, "-device '%s': expected cpu, serial, gpu or a device index 0..%d", want,
                     n - 1);
        pick = (int)k;
    }
    o->platform = plat[pick];
    o->device = dev[pick];
    OCL_CHECK(g, clGetDeviceInfo(o->device, CL_DEVICE_NAME, sizeof o->name, o->name, NULL));
    char drv[128] = "", pv[120] = "";
    OCL_CHECK(g, clGetDeviceInfo(o->device, CL_DRIVER_VERSION, sizeof drv, drv, NULL));
    OCL_CHECK(g, clGetPlatformInfo(o->platform, CL_PLATFORM_VERSION, sizeof pv, pv, NULL));
    snprintf(o->version, sizeof o->version, "%s / %s", drv, pv);
    cl_device_type dt;
    OCL_CHECK(g, clGetDeviceInfo(o->device, CL_DEVICE_TYPE, sizeof dt, &dt, NULL));
    o->is_gpu = (dt & CL_DEVICE_TYPE_GPU) != 0;
    cl_bool unified = CL_FALSE;
    clGetDeviceInfo(o->device, CL_DEVICE_HOST_UNIFIED_MEMORY, sizeof unified, &unified, NULL);
    const char *share = getenv("GRAVEL_HOST_SHARE");
    o->host_unified = !o->is_gpu && unified && !(share && !strcmp(share, "0"));
    char ext[4096] = "";
    clGetDeviceInfo(o->device, CL_DEVICE_EXTENSIONS, sizeof ext, ext, NULL);
    ext[sizeof ext - 1] = '\0';
    o->fp64 = strstr(ext, "cl_khr_fp64") != NULL;
    o->pcache = pcache_wanted(g, o);
    cl_int err;
    o->ctx = clCreateContext(NULL, 1, &o->device, NULL, NULL, &err);
    ocl_check(g, err, "clCreateContext");
    cl_ulong maxalloc = 0, gmem = 0;
    clGetDeviceInfo(o->device, CL_DEVICE_MAX_MEM_ALLOC_SIZE, sizeof maxalloc, &maxalloc, NULL);
    clGetDeviceInfo(o->device, CL_DEVICE_GLOBAL_MEM_SIZE, sizeof gmem, &gmem, NULL);
    o->max_alloc = (size_t)maxalloc;
    o->global_mem = (size_t)gmem;
    const char *cap = getenv("GRAVEL_DEVICE_MEMORY");
    if (cap && *cap) { /* a smaller device, e.g. to try a GPU's size on the CPU */
        char *end;
        double v = strtod(cap, &end);
        if (*end || !(v >= 1 << 20) || v > 1e18)
            gr_error(g, "GRAVEL_DEVICE_MEMORY must be a number of bytes >= 1048576, got '%.32s'",
                     cap);
        if (!o->global_mem || (size_t)v < o->global_mem)
            o->global_mem = (size_t)v;
    }
    size_t maxwg = 1;
    OCL_CHECK(g, clGetDeviceInfo(o->device, CL_DEVICE_MAX_WORK_GROUP_SIZE, sizeof maxwg, &maxwg,
                                 NULL));
    o->wg = 128;
    const char *wg = getenv("GRAVEL_WORKGROUP");
    if (wg && *wg) {
        char *end;
        long v = strtol(wg, &end, 10);
        if (*end || v < 1 || v > 65536)
            gr_error(g, "GRAVEL_WORKGROUP must be a work-group size 1..65536, got '%.32s'", wg);
        o->wg = (size_t)v;
    }
    if (o->wg > maxwg)
        o->wg = maxwg;
    ocl_lanes(g, o);
    const char *prof = getenv("GRAVEL_PROFILE");
    o->profile = prof && *prof && strcmp(prof, "0");
    o->queue = clCreateCommandQueue(o->ctx, o->device,
                                    o->profile ? CL_QUEUE_PROFILING_ENABLE : 0, &err);
    ocl_check(g, err, "clCreateCommandQueue");
}

uint64_t ocl_fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *c = p;
    for (size_t i = 0; i < n; i++) {
        h ^= c[i];
        h *= 1099511628211ull;
    }
    return h;
}

/* Map a line number of the concatenated source back to its file. */
static const char *source_of_line(int n, const char *const *names, const char *const *texts,
                                  long line, long *local)
{
    long start = 1;
    for (int i = 0; i < n; i++) {
        long lines = 0;
        for (const char *c = texts[i]; *c; c++)
            lines += *c == '\n';
        lines += 1; /* the separator newline */
        if (line < start + lines) {
            *local = line - start + 1;
            return names[i];
        }
        start += lines;
    }
    *local = line;
    return "?";
}

void ocl_build(struct gravel *g, struct ocl *o, int n, const char *const *names,
               const char *const *texts, const char *options)
{
    uint64_t key = OCL_FNV_INIT;
    for (int i = 0; i < n; i++) {
        key = ocl_fnv(key, names[i], strlen(names[i]) + 1);
        key = ocl_fnv(key, texts[i], strlen(texts[i]) + 1);
    }
    key = ocl_fnv(key, options, strlen(options) + 1);
    key = ocl_fnv(key, o->name, strlen(o->name) + 1);
    key = ocl_fnv(key, o->version, strlen(o->version) + 1);
    o->cache_hit = 0;
    if (o->program && o->program_key == key) {
        o->cache_hit = 1;
        return;
    }
    if (o->program) {
        clReleaseProgram(o->program);
        o->program = NULL;
    }
    cl_int err;
    /* held until the build ends: a process starting the same program waits,
     * then finds it in a cache; released before any error */
    const int lock = pcache_build_lock(key);
    cl_program cached = o->pcache ? pcache_load(g, o, key, options) : NULL;
    if (cached) {
        pcache_build_unlock(lock);
        o->program = cached;
        o->program_key = key;
        o->cache_hit = 1;
        return;
    }
    /* concatenate with a newline between files */
    size_t total = 1;
    for (int i = 0; i < n; i++)
        total += strlen(texts[i]) + 1;
    char *src = gr_malloc(g, total), *w = src;
    for (int i = 0; i < n; i++) {
        size_t l = strlen(texts[i]);
        memcpy(w, texts[i], l);
        w += l;
        *w++ = '\n';
    }
    *w = '\0';
    const char *srcs[1] = {src};
    cl_program p = clCreateProgramWithSource(o->ctx, 1, srcs, NULL, &err);
    free(src);
    if (err == CL_SUCCESS)
        err = clBuildProgram(p, 1, &o->device, options, NULL, NULL);
    pcache_build_unlock(lock);
    if (!p)
        ocl_check(g, err, "clCreateProgramWithSource");
    if (err != CL_SUCCESS) {
        size_t len = 0;
        clGetProgramBuildInfo(p, o->device, CL_PROGRAM_BUILD_LOG, 0, NULL, &len);
        char *log = calloc(len + 1, 1);
        if (log)
            clGetProgramBuildInfo(p, o->device, CL_PROGRAM_BUILD_LOG, len, log, NULL);
        clReleaseProgram(p);
        /* find the first "<source>:LINE:" reference to name the style's file */
        const char *file = "?";
        long local = 0;
        const char *m = log ? strstr(log, ":") : NULL;
        while (m) {
            char *end;
            long line = strtol(m + 1, &end, 10);
            if (end != m + 1 && *end == ':') {
                file = source_of_line(n, names, texts, line, &local);
                break;
            }
            m = strchr(m + 1, ':');
        }
        char shortlog[700];
        snprintf(shortlog, sizeof shortlog, "%s", log ? log : "(no log)");
        if (g->screen)
            fprintf(stderr, "OpenCL build log:\n%s\n", log ? log : "(no log)");
        if (g->logfile)
            fprintf(g->logfile, "OpenCL build log:\n%s\n", log ? log : "(no log)");
        free(log);
        gr_error(g, "OpenCL program build failed (%s) in kernels/%s line %ld, options '%s': %s",
                 ocl_errname(err), file, local, options, shortlog);
    }
    o->program = p;
    o->program_key = key;
    if (o->pcache)
        pcache_store(o, key, options);
}

cl_kernel ocl_kernel(struct gravel *g, struct ocl *o, const char *name)
{
    cl_int err;
    cl_kernel k = clCreateKernel(o->program, name, &err);
    if (err != CL_SUCCESS)
        gr_error(g, "OpenCL clCreateKernel(%s) failed: %s", name, ocl_errname(err));
    return k;
}

/* Process-wide, so a callback that runs after its engine is gone is safe. */
static _Atomic long long mem_live, mem_peak;

long long ocl_mem_live(void) { return atomic_load(&mem_live); }
long long ocl_mem_peak(void) { return atomic_load(&mem_peak); }
void ocl_mem_reset_peak(void) { atomic_store(&mem_peak, atomic_load(&mem_live)); }

static void CL_CALLBACK on_release(cl_mem m, void *data)
{
    (void)m;
    atomic_fetch_sub(&mem_live, (long long)(size_t)data);
}

size_t ocl_address_left(size_t *limit)
{
    struct rlimit rl;
    *limit = SIZE_MAX;
    if (getrlimit(RLIMIT_AS, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY)
        return SIZE_MAX;
    *limit = (size_t)rl.rlim_cur;
    unsigned long pages = 0;
    FILE *fp = fopen("/proc/self/statm", "r");
    if (!fp)
        return SIZE_MAX;
    if (fscanf(fp, "%lu", &pages) != 1)
        pages = 0;
    fclose(fp);
    size_t used = (size_t)pages * (size_t)sysconf(_SC_PAGESIZE);
    return used < *limit ? *limit - used : 0;
}

cl_mem ocl_alloc(struct gravel *g, struct ocl *o, size_t bytes, const char *what)
{
    if (bytes == 0)
        bytes = 16;
    /* stop cleanly before the OpenCL runtime runs out of memory (PoCL aborts) */
    size_t limit, left = ocl_address_left(&limit);
    if (left != SIZE_MAX && bytes + ((size_t)16 << 20) > left)
        gr_error(g, "cannot allocate %zu bytes for the %s: the process may allocate only %zu "
                    "more bytes under its address-space limit of %zu bytes (ulimit -v); %lld "
                    "bytes of device buffers are in use", bytes, what, left, limit,
                 ocl_mem_live());
    if (o->global_mem && (size_t)ocl_mem_live() + bytes > o->global_mem)
        gr_error(g, "cannot allocate %zu bytes for the %s: the device has %zu bytes of global "
                    "memory (CL_DEVICE_GLOBAL_MEM_SIZE) and %lld are in use", bytes, what,
                 o->global_mem, ocl_mem_live());
    if (o->max_alloc && bytes > o->max_alloc) {
        char fit[128] = "";
        if (o->atoms_hint > 0)
            snprintf(fit, sizeof fit, "; at %d atoms, about %.0f atoms would fit", o->atoms_hint,
                     (double)o->atoms_hint * (double)o->max_alloc / (double)bytes);
        gr_error(g, "one buffer of %zu bytes for the %s is more than the device's largest "
                    "allocation (CL_DEVICE_MAX_MEM_ALLOC_SIZE = %zu bytes)%s", bytes, what,
                 o->max_alloc, fit);
    }
    cl_int err;
    cl_mem m = clCreateBuffer(o->ctx, CL_MEM_READ_WRITE, bytes, NULL, &err);
    if (err != CL_SUCCESS)
        gr_error(g, "OpenCL clCreateBuffer for %s (%zu bytes) failed: %s", what, bytes,
                 ocl_errname(err));
    if (clSetMemObjectDestructorCallback(m, on_release, (void *)bytes) == CL_SUCCESS) {
        long long now = atomic_fetch_add(&mem_live, (long long)bytes) + (long long)bytes;
        long long peak = atomic_load(&mem_peak);
        while (now > peak && !atomic_compare_exchange_weak(&mem_peak, &peak, now))
            ;
    }
    return m;
}

cl_mem ocl_wrap(struct gravel *g, struct ocl *o, void *host, size_t bytes, const char *what)
{
    cl_int err;
    cl_mem m = clCreateBuffer(o->ctx, CL_MEM_READ_WRITE | CL_MEM_USE_HOST_PTR, bytes ? bytes : 16,
                              host, &err);
    if (err != CL_SUCCESS)
        gr_error(g, "OpenCL clCreateBuffer over the host's %s (%zu bytes) failed: %s", what,
                 bytes, ocl_errname(err));
    return m;
}

void ocl_release(struct ocl *o)
{
    if (o->program)
        clReleaseProgram(o->program);
    if (o->queue)
        clReleaseCommandQueue(o->queue);
    if (o->ctx)
        clReleaseContext(o->ctx);
    memset(o, 0, sizeof *o);
}
