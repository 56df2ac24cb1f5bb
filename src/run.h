/* run.h - the `run` command and the device engine that lives across runs.
 *
 * Between runs the host arrays in g->atoms are the truth. During a run the
 * device buffers are; run_sync_host() copies them back (in the current device
 * order: every per-atom array moves together, tags keep identity) for output
 * and variables. */
#ifndef GR_RUN_H
#define GR_RUN_H

#include "state.h"

/* What a finished run reports (thermo_footer prints it LAMMPS-style). */
struct run_stats {
    bigint nsteps;
    int natoms;
    double t_total;                 /* wall seconds of the loop */
    double t_pair, t_neigh, t_modify, t_output, t_other;
    bigint nbuilds, ndanger;
    double total_neighbors;         /* entries in the last list built */
    double max_overlap_frac;        /* largest overlap / radius: pairs at outputs,
                                     * walls and meshes at every step */
    /* worst collision resolution (src/accuracy.h): dt / t_col, 0 = none */
    double res_q, res_vn;
    bigint res_step;
    long long res_tag_i, res_tag_j; /* tag_j 0: res_wall, a wall fix */
    char res_wall[GR_NAMELEN];
    bigint nlaunch;                 /* kernel launches and fills in the loop */
    int ncontact;                   /* contacts of the last list built */
    double mem_peak;                /* most bytes of device buffers live during the run */
};

/* Device state -> host arrays; no-op when no run is active. */
void run_sync_host(struct gravel *g);
void engine_destroy(struct gravel *g);
/* rerun (src/rerun.c): the first snapshot is already in the host atoms;
 * each is set up and output without integrating, load() then puts the next
 * one into the host atoms and returns its step (-1: no more). firststep and
 * laststep are the run's bounds as time-dependent styles and thermo see
 * them. */
void run_rerun(struct gravel *g, bigint (*load)(struct gravel *, void *), void *ctx,
               bigint firststep, bigint laststep);

#endif
