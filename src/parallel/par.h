/* par.h - a run decomposed over MPI ranks (bin/gravel-mpi, doc/parallel.md).
 *
 * Between runs every rank holds every atom on the host, in tag order (the
 * script's commands run the same on each rank). At a run's start each rank
 * keeps the atoms of its brick (decomp.h); on the device its owned atoms
 * sit in slots 0 .. nlocal-1 (engine a.n) and copies of other ranks' atoms
 * within the ghost cut-off (the neighbor cut-off, skin included) behind
 * them, nghost of them. At a neighbor rebuild the owned atoms that left the
 * brick move to their new rank with their contact history, and the ghosts
 * are chosen again; on the other steps the ghosts' positions, velocities
 * and angular velocities come from their owners, as raw device bytes.
 *
 * Every contact between an owned atom and a ghost is evaluated on both
 * ranks from the same bits, and each particle sums its contacts in partner
 * tag order, so the trajectory is bit-identical on any number of ranks;
 * the host sums of thermo add per-atom terms in global tag order
 * (comm_sum_in_key_order). At a run's end every rank gathers all atoms.
 *
 * On one rank (bin/gravel, or bin/gravel-mpi -np 1) none of this runs. */
#ifndef GR_PAR_H
#define GR_PAR_H

#include <stdint.h>

#include "decomp.h"
#include "state.h"

struct par_hist;
struct fix;

/* a fix's per-atom state of every atom at the last run's end (tag order) */
struct par_saved {
    struct fix *fix;
    size_t bytes;           /* per atom */
    unsigned char *state;
};
#define PAR_MAXSAVED 32

struct par {
    struct decomp dc;
    int on;                 /* the current run is decomposed (comm_size() > 1) */
    double cut;             /* ghost cut-off of the run */
    int nghost;
    int *sendn, *soff, *sendidx; /* ghosts sent to each rank: owned indices */
    int *recvn;             /* ghosts received from each rank, in slot order */
    int list_current;       /* the device's contacts index the current atoms */
    int64_t *tags_built;    /* the tags of the owned and ghost slots at the last build */
    int nlocal_built;
    struct par_hist *hist;  /* contact history by tag pair across a rebuild or runs */
    uint64_t tags_at_end;   /* tag set the saved history belongs to (0: none) */
    struct par_saved saved[PAR_MAXSAVED];
    int nsaved;
    int *kept;              /* run start: the kept atoms' rows in the last run's end set */
    unsigned balance_dims;  /* fix balance: the next exchange balances these dimensions */
    int balance_rcb;        /* fix balance rcb: the next exchange tiles the box again */
    double balance_thresh;
    /* fix balance's weight and out keywords (NULL: by count, no file): the
     * atoms' weights (balance_weight.h's bal_weight_compute) and the boxes'
     * file after a balance, through the fix (par does not call up) */
    void *balance_ctx;
    double *(*balance_weigh)(struct gravel *g, void *ctx, int n, const double *cost_time,
                             const double *cost_neigh, const long *nown);
    void (*balance_out)(struct gravel *g, void *ctx);
    double run_cost;        /* this run's Pair + Neigh wall time so far (weight time) */
    double balance_time_last; /* run_cost at the last fix balance */
    double last_cost;       /* the last run's Pair + Neigh time and neighbor pairs, */
    double last_neigh;      /* this rank's (balance weight time, neigh) */
    int gathered;           /* par_gather_begin: g->atoms is every rank's, local holds ours */
    struct atoms local;
    /* what the last decomposed run left for a restart file (ended = 1) */
    int ended;
    double *xhold_end;      /* its list's reference positions, host order (3 per atom) */
    int ago_end;            /* steps since that list's build */
    uint64_t host_hash;     /* atoms_fingerprint of the host atoms at its end */
    /* read_restart on several ranks: forces of the written step, by tag */
    int nresume;
    double *resume_ft;      /* per atom: tag (as a double's bits), force, torque */
};

/* `processors Px Py Pz`: the grid's counts (checked against the rank count
 * at the next run). */
void cmd_processors(struct gravel *g, int argc, char **argv);
void cmd_comm_style(struct gravel *g, int argc, char **argv);
/* This gravel's parallel state (created on first use). */
struct par *par_state(struct gravel *g);
void par_free(struct gravel *g);
/* 1 while a decomposed run is active */
int par_on(const struct gravel *g);
/* 1 while g->atoms holds every rank's atoms for an output step (par_gather_begin) */
int par_gathered(const struct gravel *g);
/* Every rank's atoms (collective while a decomposed run is active and its
 * atoms are not gathered): LAMMPS's natoms, as thermo_modify norm divides by. */
long long par_natoms(const struct gravel *g);
/* Ghost slots behind the owned atoms on the device (0 when not decomposed). */
int par_nghost(const struct gravel *g);

/* Hash of the atoms' tags in host order (the set and the order). */
uint64_t par_tag_set_key(const struct atoms *a);
/* Stop a decomposed run: why (a style, a keyword) cannot run across ranks yet. */
_Noreturn void par_refuse(struct gravel *g, const char *why);
/* 1 when fix f's global values are the same on every rank of a decomposed
 * run (mesh/surface and mesh/surface/stress: force and torque summed over
 * the ranks in tag order; the insertion fixes' counts, which every rank
 * keeps whole; gravity's and heat/gran's energies, summed in tag order;
 * the ave fixes, whose compute inputs are sampled as one process); others
 * may hold one rank's part. */
int par_fix_value_global(const struct fix *f);
/* Run start, before the upload: refuse what cannot run across ranks yet,
 * choose the grid and keep the atoms of this rank's brick. */
void par_run_begin(struct gravel *g);
/* Run start, after the fixes' init: their per-atom state as the last run
 * left it, when the atoms are the same (as one process keeps it). */
void par_fix_state_restore(struct gravel *g);
/* A neighbor rebuild, after the periodic wrap: owned atoms to their ranks
 * with their contacts' history, ghosts chosen and everything uploaded
 * (owned, then ghosts). The ghost cut-off is cut. */
void par_exchange(struct gravel *g, double cut);
/* After the contacts are built: their history from the tag pairs. */
void par_history_restore(struct gravel *g);
/* Every step that does not rebuild: the ghosts' x, v, omega (and temperature
 * in a heat-conducting scene) from their owners. */
void par_forward(struct gravel *g);
/* The ghosts' radius and mass from their owners (fix adapt changed them
 * between rebuilds). */
void par_forward_radii(struct gravel *g);
/* Run end: every rank's host holds all atoms in tag order. */
void par_run_end(struct gravel *g);
/* Output steps of a decomposed run (dumps): every rank's atoms, all fields,
 * in tag order in g->atoms, sums and syncs as one process, until
 * par_gather_end restores this rank's own. No device work in between. */
void par_gather_begin(struct gravel *g);
void par_gather_end(struct gravel *g);
/* A restart file during a decomposed run (`restart N`): as par_gather_begin,
 * with what par_list_export and par_fix_rows hand the file, until
 * par_snapshot_end. */
void par_snapshot_begin(struct gravel *g);
void par_snapshot_end(struct gravel *g);

/* rerun on several ranks. Before a snapshot is read: every rank's atoms in
 * tag order on the host, the contacts' history and the fixes' per-atom
 * state saved by tag (the device untouched). No snapshot followed:
 * par_rerun_keep returns to this rank's atoms. One was read into the whole
 * set: par_rerun_scatter keeps this rank's brick of it (then eng_upload and
 * par_fix_state_restore, and the next build exchanges ghosts and history). */
void par_rerun_gather(struct gravel *g);
void par_rerun_keep(struct gravel *g);
void par_rerun_scatter(struct gravel *g);
/* An output step of a decomposed run (par_gathered): the stored history of
 * each pair (tags[2k], tags[2k+1]) from every rank's contacts by tag pair,
 * hist[k * width + d] as doubles, as compute pair/local's pN read it (a
 * contact is owned by its lower tag, as on one process; a pair in no list
 * gets zeros). Returns the width, 0 without history (or over maxw).
 * Collective: every rank calls it with its gathered set's pairs. */
int par_pair_history(struct gravel *g, int np, const int64_t *tags, int maxw, double *hist);

#endif
