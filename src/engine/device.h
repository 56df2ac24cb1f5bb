/* device.h - the device engine's state and the helpers styles use to launch
 * kernels: the bottom of everything that runs on the device.
 *
 * The engine lives across runs (g->eng). Its state (per-atom buffers in
 * device order, the run's kernels, the per-run records neighbor.c,
 * accuracy.c and fused.c keep in it, the run's statistics) is declared
 * here so that those modules and the styles need only this header; what a
 * run does with it (program assembly, upload, sync back, teardown) is
 * engine.h. */
#ifndef GR_DEVICE_H
#define GR_DEVICE_H

#include "lanes_tune.h"
#include "ocl.h"
#include "state.h"

/* Device per-atom arrays in device order (REAL = float or double). */
/* Device per-atom arrays in device order (REAL = float or double): one
 * buffer per row of the field table (atom_fields.h), NULL when the run does
 * not hold that field (its `when` column). x is relative to eng->origin. */
#define DEV_ATOM_MEMBER(name, ctype, dev, width, when, life, sect, what) cl_mem name;
struct dev_atoms {
    int n;                      /* atoms on the device */
    ATOM_FIELDS(DEV_ATOM_MEMBER)
    cl_mem xlo;                 /* REAL[3n]: low part of x in single precision, else NULL */
    cl_mem custom;              /* the custom properties' records (atoms.custom, raw
                                 * doubles), NULL when there are none */
    cl_mem custom_tmp;          /* the re-sort's scratch for them (never shared) */
    int custom_slots;           /* doubles per atom of custom */
    int shared;                 /* the buffers are the host arrays of g->atoms (engine.c) */
    uint64_t shared_key;        /* which host arrays (their addresses and capacity) */
};

struct nbr;                     /* neighbor.c */
struct acc;                     /* accuracy.c */
struct fix;

/* The run's fused stages (engine-owned; built by fused_setup, fused.h). */
struct fused_stages {
    cl_mem ops, prm;            /* int[FOP_W per op], REAL[] */
    int ninit, npost, nfinal, neos; /* ops: initial, then post, final, end_of_step */
    /* the tail (when post_force fused only a prefix): ops [tfirst, tfirst +
     * tpost) are the post_force fixes after the last unfused one, then
     * tfinal final_integrate and end_of_step ops; run by fused_tail after
     * the unfused post_force fixes (ntail = tpost + tfinal; 0: no tail) */
    int tfirst, tpost, tfinal;
    struct fix *store_fix;      /* the fused fix whose per-atom store ops use, or NULL */
    int lookahead;              /* 0: GRAVEL_LOOKAHEAD=0, no step opening in pair_gather */
    int on;                     /* 0: GRAVEL_FUSE=0, nothing fused (region walls: one
                                 * launch each, src/contact/wall_region.c) */
};

/* The fix calls of each hook for the current run (run.c). */
enum { NHOOK = 7 };
struct hook_call {
    struct fix *fix;
    void (*fn)(struct gravel *, struct fix *);
};
struct hook_lists {
    int n[NHOOK];
    struct hook_call *call[NHOOK];
    int nforce;                 /* fixes with force_reneighbor (fix pour) */
    struct fix **force;
};

#define GR_HIST_MAX 40 /* REALs of contact history per contact, at most */

/* What a finished run reports (thermo_footer prints it LAMMPS-style). */
/* One quantity over the ranks, as LAMMPS's Finish reports it: min, mean,
 * max, the %varavg imbalance sqrt(<t^2>/<t> - <t>) x 100 (0 for a mean under
 * 1 ms) and a 10-bin histogram of the ranks' values (one process: all in the
 * first bin). */
struct rank_spread {
    double min, avg, max, varavg;
    int histo[10];
};

enum { RUN_SEC_PAIR, RUN_SEC_NEIGH, RUN_SEC_OUTPUT, RUN_SEC_MODIFY, RUN_SEC_N };

struct run_stats {
    bigint nsteps;
    int natoms;
    double t_total;                 /* wall seconds of the loop */
    double t_pair, t_neigh, t_modify, t_output, t_other;
    bigint nbuilds, ndanger;
    bigint nspec, nspec_back;       /* rebuild decisions on speculation, steps gone back
                                     * (src/engine/neighbor.h, nbr_decide) */
    double total_neighbors;         /* entries in the last list built */
    double max_overlap_frac;        /* largest overlap / radius: pairs at outputs,
                                     * walls and meshes at every step */
    /* worst collision resolution (src/contact/accuracy.h): dt / t_col, 0 = none */
    double res_q, res_vn;
    bigint res_step;
    long long res_tag_i, res_tag_j; /* tag_j 0: res_wall, a wall fix */
    char res_wall[GR_NAMELEN];
    bigint nlaunch;                 /* kernel launches and fills in the loop */
    int ncontact;                   /* contacts of the last list built */
    double mem_peak;                /* most bytes of device buffers live during the run */
    /* several ranks (src/parallel/comm.h): per rank and step, the mean over
     * the ranks of the bytes and messages sent to other ranks (ghosts and
     * migration) and of the bytes each rank adds to collectives (sums,
     * gathers, decisions) and their number */
    double comm_bytes, comm_msgs, coll_bytes, coll_calls;
    /* ranks_spread 1: the footer's rows over the ranks, section times
     * (RUN_SEC_*), owned atoms and neighbor pairs per rank (0: one process,
     * output_finish takes them from the fields above) */
    int ranks_spread;
    struct rank_spread sec[RUN_SEC_N], atoms, neighs;
};

struct engine {
    struct ocl ocl;
    int ready;                  /* device chosen */
    int single;                 /* REAL = float; positions split hi + lo (SPLIT_POS) */
    int pair_lw;                /* contacts per work-item of pair_contacts (PAIR_LW) */
    int atom_lw;                /* particles per work-item of pair_gather (ATOM_LW) */
    int pair_tc;                /* the torque records hold each contact's tc (PAIR_TC:
                                 * the law has no rolling torque, kernels/pair_loop.cl) */
    char lanes_prologue[160];   /* kernels/lanes.cl's prologue at the pair width */
    double origin[3];           /* device positions are x - origin (0 in double) */
    size_t rsz;                 /* sizeof(REAL) */
    int rotation, history;      /* active features of the current run */
    int heat;                   /* the atoms store temperature and heatflow (HAS_HEAT) */
    cl_mem recq;                /* HAS_HEAT: the contacts' heat records (run.c) */
    size_t recq_cap;            /* ... their capacity in bytes */
    int hist_n;                 /* REALs of history per contact (HIST_N; 3 by default,
                                 * at most GR_HIST_MAX) */
    int nghost;                 /* decomposed run: ghost atoms behind the a.n owned ones
                                 * (src/parallel/par.h) */
    int hist_owner;             /* its last slot is LAMMPS's owner (-compat lammps2021) */
    int cap;                    /* per-atom buffer capacity */
    struct dev_atoms a;
    int active;                 /* inside a run: the device holds the truth */
    int setup;                  /* computing the setup forces (no history update) */
    int nkern, kern_cap;
    cl_kernel *kern;            /* every kernel created for this program */
    size_t *kern_wg;            /* its work-group size (queried once, at creation) */
    struct kern_memo *kern_memo; /* the arguments last set on it (device.c: a repeat is
                                  * not set again) */
    int kern_last;              /* the kernel last looked up (set_arg, work_group) */
    struct nbr *nbr;
    struct acc *acc;            /* collision-resolution records of the run */
    /* kept across runs: validity of the device neighbor list / history */
    /* what diagnose.c reads of the run start (diag_keep_start), made at the
     * upload, as the run then changes the host arrays: the atoms whose
     * nearest neighbour sat on them or overlapped them by more than half the
     * smaller radius; the largest finite velocity component; the atoms that
     * moved more than their radius per step (or were non-finite), with their
     * velocities. Only these: no copy of the positions (memory). */
    struct start_copy {
        int valid;
        int nnear, near_cap, nfast, fast_cap;
        struct start_near {
            int64_t tag, other; /* the atom and its nearest neighbour */
            double x[3];        /* the atom's position */
            double dist, ri, rj; /* centre distance, the two radii */
        } *near;
        double vmax;
        int64_t *fast_tag;
        double *fast_v;
    } start;
    uint64_t tag_sum;           /* checksum of the tags at the last sync; 0 = invalid */
    int n_at_sync;
    /* pair evaluation of the current run (run.c) */
    cl_mem pair_param;          /* packed per-type-pair parameters */
    cl_kernel k_pair, k_gather, k_tail, k_clear;
    /* the one-per-work-item forms beside lane ones (NULL: none; lanes_tune.h) */
    cl_kernel k_pair1, k_gather1, k_tail1;
    struct lanes_tune lanes;    /* which form each stage takes (lanes_tune.h) */
    cl_kernel k_virial;         /* pair_virial, for the pressure (src/engine/pressure.c) */
    cl_kernel k_energy;         /* pair_energy of a potential (src/contact/pair_energy.c) */
    double epair_snap;          /* the pair energy taken before a box change moved the
                                 * atoms: valid for step epair_snap_step only (-1: none) */
    bigint epair_snap_step;
    cl_kernel k_box_remap;      /* box_remap, for box changes in a run (src/engine/box_change.c) */
    cl_kernel k_box_flip;       /* box_image_flip, for box flips */
    /* the virial taken before a box change moved the atoms (pressure.h):
     * valid for step virial_snap_step only (-1: none); per particle too
     * (6 doubles each, device order) */
    double virial_snap[6];
    double *virial_snap_atoms;
    bigint virial_snap_step;
    /* velocity remap of a deforming box (box_change_vremap): LAMMPS's
     * h_rate (6 REAL) and the group it applies to (0: none) */
    cl_mem hrate;
    unsigned vgroup;
    cl_mem virial;              /* REAL[3 virial_cap]: its per-particle output */
    int virial_cap;
    struct fused_stages fused;  /* per-particle fix work inside those kernels */
    /* REAL[n] in device order: the mass pair and wall contacts use for
     * their effective mass (a rigid body's mass for its atoms, LAMMPS's
     * mass_rigid); NULL = rmass. Owned by the fix that sets it. */
    cl_mem contact_mass;
    double insert_rmax;         /* largest radius fixes may insert this run (fix reserve) */
    struct hook_lists hooks;    /* the other fix work, per hook (run.c) */
    /* eng_tag_order: the device tags last read and their order */
    int64_t *tag_seen;
    int *tag_order;
    int tag_n, tag_cap;
    /* GRAVEL_PROFILE: device time per kernel name, printed at destroy */
    int nprof;
    char prof_name[48][40];
    double prof_sec[48];
    long prof_calls[48];
    /* statistics of the current run */
    struct run_stats st;
};

/* Device state of g, creating the device on first use. */
struct engine *eng_get(struct gravel *g);
/* eng_get for a run that expects `atoms` per process: a device chosen now
 * is PoCL's serial one for a small scene (ocl_init). */
struct engine *eng_open(struct gravel *g, long atoms);
/* The current per-atom buffers. */
struct dev_atoms *eng_atoms(struct gravel *g);
/* 1 during the setup force computation of a run (no history update). */
int eng_in_setup(struct gravel *g);

/* Kernel `name` from the run's program; released by the engine
 * (eng_release_kernels: every kernel created so far). */
cl_kernel eng_kernel(struct gravel *g, const char *name);
void eng_release_kernels(struct engine *e);
/* Device bytes per atom of a field-table row (atom_fields.h) whose host
 * elements have size hsz. */
size_t eng_field_bytes(const struct gravel *g, enum atom_field_dev dev, size_t hsz, int width);
/* Checked argument setters. eng_arg_real converts to the run's REAL. */
void eng_arg_mem(struct gravel *g, cl_kernel k, int i, cl_mem m);
void eng_arg_int(struct gravel *g, cl_kernel k, int i, int v);
void eng_arg_uint(struct gravel *g, cl_kernel k, int i, unsigned v);
void eng_arg_real(struct gravel *g, cl_kernel k, int i, double v);
void eng_arg_local(struct gravel *g, cl_kernel k, int i, size_t bytes);
/* a struct passed by value, laid out as the kernel's (src/engine/kargs.c) */
void eng_arg_bytes(struct gravel *g, cl_kernel k, int i, size_t bytes, const void *p);
/* Launch a 1-D kernel over n work-items (no-op for n = 0). */
void eng_launch(struct gravel *g, cl_kernel k, size_t n);
/* Checked device allocation and transfers (blocking). */
cl_mem eng_alloc(struct gravel *g, size_t bytes, const char *what);
void eng_write(struct gravel *g, cl_mem m, size_t off, size_t bytes, const void *src);
void eng_read(struct gravel *g, cl_mem m, size_t off, size_t bytes, void *dst);
void eng_fill_zero(struct gravel *g, cl_mem m, size_t bytes);
void eng_finish(struct gravel *g);
/* Host doubles <-> device REALs through a scratch buffer. */
void eng_write_reals(struct gravel *g, cl_mem m, size_t count, const double *src);
/* The same from REAL element `first` on. */
void eng_write_reals_at(struct gravel *g, cl_mem m, size_t first, size_t count,
                        const double *src);
void eng_read_reals(struct gravel *g, cl_mem m, size_t count, double *dst);
/* Positions: host doubles <-> the device's x (and xlo), relative to origin;
 * writes atoms first .. first + n - 1 from src (their 3n coordinates). */
void eng_write_positions(struct gravel *g, const struct dev_atoms *s, int first, int n,
                         const double *src);
void eng_read_positions(struct gravel *g, const struct dev_atoms *s, int n, double *dst);
/* A lab-frame coordinate of dimension q as a device REAL argument (x - origin). */
void eng_arg_coord(struct gravel *g, cl_kernel k, int i, int q, double v);
/* Bind the low position part as argument i when positions are split
 * (kernels with POS_LO_PARAM, their last argument); no-op otherwise. */
void eng_arg_pos_lo(struct gravel *g, cl_kernel k, int i);

/* During a run: ord[k] = the device index of the atom with the k-th
 * smallest tag (reads the device tags; the order is recomputed only when
 * they moved), so host sums over per-atom device values can run in tag
 * order without run_sync_host. */
const int *eng_tag_order(struct gravel *g);

#endif
