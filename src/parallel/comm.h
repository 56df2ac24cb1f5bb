/* comm.h - the processes of a run. bin/gravel-mpi is built with GR_MPI and
 * talks MPI (OpenMPI or MPICH) through these calls only; bin/gravel links
 * the one-process versions (comm_size() == 1, every call a copy or no-op),
 * so the serial build needs no MPI at all.
 *
 * Every call is collective over all ranks unless it says otherwise. Byte
 * counts per message must stay below 2^31 (checked: an error names it). */
#ifndef GR_COMM_H
#define GR_COMM_H

#include <stddef.h>
#include <stdint.h>

/* Start (MPI_Init) and stop the processes; comm_init returns the rank. */
int comm_init(int *argc, char ***argv);
void comm_finalize(void);
/* Not collective: end every rank now with this exit status (MPI_Abort). */
_Noreturn void comm_abort(int code);
int comm_rank(void);
int comm_size(void);
/* Not collective: this rank among the ranks on its node (shared memory),
 * and their number (one process: 0 and 1). */
int comm_local_rank(void);
int comm_local_size(void);
/* 1 when this binary can run on several ranks (built with GR_MPI). */
int comm_parallel_build(void);

void comm_barrier(void);
long long comm_sum_ll(long long v);
int comm_max_int(int v);
/* elementwise min of lo[0..n-1] and max of hi[0..n-1] over the ranks */
void comm_minmax(double *lo, double *hi, int n);
/* rank 0's bytes to every rank */
void comm_bcast(void *buf, size_t bytes);

/* Personalized exchange: send[r] (sendbytes[r] bytes) to rank r; on return
 * *recv holds what every rank sent here, rank by rank (recvbytes[r] from
 * rank r), malloc'd (free it; NULL when nothing arrived). Returns the total
 * received. size: comm_size() entries each. NULL on allocation failure
 * sets *recv NULL and returns (size_t)-1. */
size_t comm_alltoallv(void *const *send, const size_t *sendbytes, void **recv,
                      size_t *recvbytes);
/* Every rank's bytes, rank by rank, to every rank: *all malloc'd, total
 * returned ((size_t)-1 on allocation failure). */
size_t comm_allgatherv(const void *send, size_t bytes, void **all);

/* What this rank sent since the last reset: bytes and messages to other
 * ranks in personalized exchanges (c[0], c[1]); bytes it put into
 * collectives (gathers, reductions, broadcasts) and their number (c[2],
 * c[3]). Not collective. */
void comm_counters(double c[4]);
void comm_counters_reset(void);

/* The sum of the values v[k] of keys key[k] over every rank, added in
 * ascending key order (keys unique over the ranks): the same bits as one
 * process adding the same values in key order, on any number of ranks.
 * The caller on one process passes them in key order. Returns the sum on
 * every rank; NAN when memory ran out. */
double comm_sum_in_key_order(int n, const int64_t *key, const double *v);

#endif
