/* comm.c - MPI for bin/gravel-mpi (GR_MPI), one process for bin/gravel.
 * The only file that names MPI: the Makefile compiles it twice. */
#include "comm.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef GR_MPI
#include <mpi.h>
#endif

struct keyed {
    int64_t key;
    double v;
};

static int by_key(const void *a, const void *b)
{
    int64_t x = ((const struct keyed *)a)->key, y = ((const struct keyed *)b)->key;
    return (x > y) - (x < y);
}

static double count_[4]; /* comm_counters */

void comm_counters(double c[4])
{
    for (int k = 0; k < 4; k++)
        c[k] = count_[k];
}

void comm_counters_reset(void) { memset(count_, 0, sizeof count_); }

#ifdef GR_MPI

static void collective(size_t bytes)
{
    count_[2] += (double)bytes;
    count_[3] += 1;
}

static int rank_, size_ = 1, local_rank_, local_size_ = 1;

int comm_init(int *argc, char ***argv)
{
    /* a rank waiting for another yields its core (OpenMPI spins otherwise,
     * taking the core the other rank's PoCL threads compute on); the
     * environment's own setting wins */
    setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
    MPI_Init(argc, argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm node; /* the ranks that share this node's memory */
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
    MPI_Comm_rank(node, &local_rank_);
    MPI_Comm_size(node, &local_size_);
    MPI_Comm_free(&node);
    return rank_;
}

void comm_finalize(void) { MPI_Finalize(); }
_Noreturn void comm_abort(int code)
{
    MPI_Abort(MPI_COMM_WORLD, code);
    exit(code);
}
int comm_rank(void) { return rank_; }
int comm_size(void) { return size_; }
int comm_local_rank(void) { return local_rank_; }
int comm_local_size(void) { return local_size_; }
int comm_parallel_build(void) { return 1; }
void comm_barrier(void) { MPI_Barrier(MPI_COMM_WORLD); }

long long comm_sum_ll(long long v)
{
    long long s = 0;
    collective(sizeof v);
    MPI_Allreduce(&v, &s, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    return s;
}

int comm_max_int(int v)
{
    int s = 0;
    collective(sizeof v);
    MPI_Allreduce(&v, &s, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return s;
}

void comm_minmax(double *lo, double *hi, int n)
{
    collective(2 * (size_t)n * sizeof(double));
    MPI_Allreduce(MPI_IN_PLACE, lo, n, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, hi, n, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
}

void comm_bcast(void *buf, size_t bytes)
{
    if (bytes > INT_MAX)
        comm_abort(1);
    if (rank_ == 0)
        collective(bytes);
    MPI_Bcast(buf, (int)bytes, MPI_BYTE, 0, MPI_COMM_WORLD);
}

/* byte counts as MPI's ints, and their displacements */
static int counts(const size_t *bytes, int *cnt, int *disp)
{
    size_t off = 0;
    for (int r = 0; r < size_; r++) {
        if (bytes[r] > INT_MAX || off > INT_MAX)
            return 0;
        cnt[r] = (int)bytes[r];
        disp[r] = (int)off;
        off += bytes[r];
    }
    return off <= INT_MAX;
}

size_t comm_alltoallv(void *const *send, const size_t *sendbytes, void **recv, size_t *recvbytes)
{
    int p = size_;
    int *sc = malloc(4 * (size_t)p * sizeof(int));
    unsigned long long *sb = calloc(2 * (size_t)p, sizeof *sb);
    if (!sc || !sb) {
        free(sc);
        free(sb);
        *recv = NULL;
        return (size_t)-1;
    }
    int *sd = sc + p, *rc = sc + 2 * p, *rd = sc + 3 * p;
    for (int r = 0; r < p; r++)
        sb[r] = sendbytes[r];
    MPI_Alltoall(sb, 1, MPI_UNSIGNED_LONG_LONG, sb + p, 1, MPI_UNSIGNED_LONG_LONG,
                 MPI_COMM_WORLD);
    size_t total = 0, stot = 0;
    for (int r = 0; r < p; r++) {
        recvbytes[r] = (size_t)sb[p + r];
        total += recvbytes[r];
        stot += sendbytes[r];
    }
    if (!counts(sendbytes, sc, sd) || !counts(recvbytes, rc, rd))
        comm_abort(1); /* over 2 GiB in one exchange */
    /* one contiguous send buffer */
    char *sbuf = malloc(stot ? stot : 1), *rbuf = malloc(total ? total : 1);
    if (!sbuf || !rbuf) {
        free(sbuf);
        free(rbuf);
        free(sc);
        free(sb);
        *recv = NULL;
        return (size_t)-1;
    }
    for (int r = 0; r < p; r++)
        if (sendbytes[r]) {
            memcpy(sbuf + sd[r], send[r], sendbytes[r]);
            if (r != rank_) {
                count_[0] += (double)sendbytes[r];
                count_[1] += 1;
            }
        }
    MPI_Alltoallv(sbuf, sc, sd, MPI_BYTE, rbuf, rc, rd, MPI_BYTE, MPI_COMM_WORLD);
    free(sbuf);
    free(sc);
    free(sb);
    if (!total) {
        free(rbuf);
        rbuf = NULL;
    }
    *recv = rbuf;
    return total;
}

size_t comm_allgatherv(const void *send, size_t bytes, void **all)
{
    int p = size_;
    unsigned long long mine = bytes, *each = malloc((size_t)p * sizeof *each);
    int *cnt = malloc(2 * (size_t)p * sizeof(int));
    size_t *b = malloc((size_t)p * sizeof *b);
    if (!each || !cnt || !b) {
        free(each);
        free(cnt);
        free(b);
        *all = NULL;
        return (size_t)-1;
    }
    MPI_Allgather(&mine, 1, MPI_UNSIGNED_LONG_LONG, each, 1, MPI_UNSIGNED_LONG_LONG,
                  MPI_COMM_WORLD);
    size_t total = 0;
    for (int r = 0; r < p; r++) {
        b[r] = (size_t)each[r];
        total += b[r];
    }
    if (!counts(b, cnt, cnt + p))
        comm_abort(1);
    char *buf = malloc(total ? total : 1);
    if (!buf) {
        free(each);
        free(cnt);
        free(b);
        *all = NULL;
        return (size_t)-1;
    }
    collective(bytes);
    MPI_Allgatherv(send, (int)bytes, MPI_BYTE, buf, cnt, cnt + p, MPI_BYTE, MPI_COMM_WORLD);
    free(each);
    free(cnt);
    free(b);
    *all = buf;
    return total;
}

double comm_sum_in_key_order(int n, const int64_t *key, const double *v)
{
    if (size_ == 1) {
        double s = 0;
        for (int k = 0; k < n; k++)
            s += v[k];
        return s;
    }
    struct keyed *mine = malloc(((size_t)n + 1) * sizeof *mine), *all = NULL;
    if (!mine)
        return NAN;
    for (int k = 0; k < n; k++) {
        mine[k].key = key[k];
        mine[k].v = v[k];
    }
    size_t bytes = comm_allgatherv(mine, (size_t)n * sizeof *mine, (void **)&all);
    free(mine);
    if (bytes == (size_t)-1)
        return NAN;
    size_t m = bytes / sizeof *all;
    double s = 0;
    if (m) {
        qsort(all, m, sizeof *all, by_key);
        for (size_t k = 0; k < m; k++)
            s += all[k].v;
    }
    free(all);
    return s;
}

#else /* one process */

int comm_init(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    return 0;
}
void comm_finalize(void) {}
_Noreturn void comm_abort(int code) { exit(code); }
int comm_rank(void) { return 0; }
int comm_size(void) { return 1; }
int comm_local_rank(void) { return 0; }
int comm_local_size(void) { return 1; }
int comm_parallel_build(void) { return 0; }
void comm_barrier(void) {}
long long comm_sum_ll(long long v) { return v; }
int comm_max_int(int v) { return v; }
void comm_minmax(double *lo, double *hi, int n)
{
    (void)lo;
    (void)hi;
    (void)n;
}
void comm_bcast(void *buf, size_t bytes)
{
    (void)buf;
    (void)bytes;
}

size_t comm_alltoallv(void *const *send, const size_t *sendbytes, void **recv, size_t *recvbytes)
{
    recvbytes[0] = sendbytes[0];
    *recv = NULL;
    if (!sendbytes[0])
        return 0;
    if (!(*recv = malloc(sendbytes[0])))
        return (size_t)-1;
    memcpy(*recv, send[0], sendbytes[0]);
    return sendbytes[0];
}

size_t comm_allgatherv(const void *send, size_t bytes, void **all)
{
    if (!(*all = malloc(bytes ? bytes : 1)))
        return (size_t)-1;
    memcpy(*all, send, bytes);
    return bytes;
}

double comm_sum_in_key_order(int n, const int64_t *key, const double *v)
{
    (void)key;
    (void)by_key;
    double s = 0;
    for (int k = 0; k < n; k++)
        s += v[k];
    return s;
}

#endif
