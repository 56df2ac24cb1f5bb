/* neighbor.h - device neighbor lists: binning, sort by cell, full Verlet list
 * with skin, rebuild decisions, periodic wrap, shrink-wrap, lost atoms and
 * contact history carried across rebuilds (by partner tag).
 *
 * Each pair in the list is one contact of the pipeline (doc/contact_pipeline.md,
 * kernels/pair_loop.cl), evaluated once; its history is stored once and
 * follows the pair (owner and partner) through rebuilds and re-sorts. */
#ifndef GR_NEIGHBOR_H
#define GR_NEIGHBOR_H

#include "device.h"

struct nbr_list {
    /* full rows in ascending partner tag: nlist[i maxn + k] (k < ncount[i])
     * is the device index of i's k-th neighbor; ioff[i] the rows' packed
     * offsets (sum of the counts before i) */
    cl_mem nlist, ncount, nown, ioff;
    int maxn;
    /* contacts, owned by the lower tag: i owns coff[i] .. coff[i + 1] - 1,
     * its last nown[i] row slots in order; ci/cj the two atoms; row slot
     * k < ncount[i] - nown[i] of i (a lower-tag partner's contact) is
     * contact pcon[ioff[i] - coff[i] + k]; shear (HIST_N REAL, history
     * only) seen from ci; rec the records of the step (REC_W REAL per
     * contact: the owner's force, then with rotation the torques or tc,
     * kernels/pair_loop.cl); quiet[c] (one byte) = 1 when contact c did
     * not act at its last evaluation and its record holds the zeros
     * written then */
    cl_mem coff, ci, cj, pcon, quiet, shear, rec;
    int ncontact;
    double L[3];            /* periodic lengths (0 = not periodic), for minimum image */
    double tilt[3];         /* tilt factors xy xz yz of the current box (0: orthogonal) */
};

/* The records of every contact are unknown (a run starts, a restart
 * restored the list): the next evaluation writes every contact's records
 * (nbr_list.quiet = 0), and the zero record after them, which pair_gather
 * reads for a quiet contact's, is written again. */
void nbr_quiet_reset(struct gravel *g);
/* Kernel arguments a .. a + 5: the list's periodic lengths Lx Ly Lz, then
 * the tilts xy xz yz (kernels/common.cl, "Triclinic boxes"). Returns a + 6. */
int nbr_arg_box(struct gravel *g, cl_kernel k, int a, const struct nbr_list *l);
/* The box changed during a run (src/engine/box_change.c): refresh the list's
 * periodic lengths and tilts from g->dom, so that minimum images use the
 * new box, and make the next nbr_decide count the box's corner motion
 * since the last build (LAMMPS's Neighbor::check_distance box check). */
void nbr_box_changed(struct gravel *g);

/* Run start: kernels and work buffers for the current program and atoms. */
void nbr_setup(struct gravel *g);
/* Forget the list (atoms changed): the next build transfers no history. */
void nbr_invalidate(struct gravel *g);
/* The atoms' radii changed during the run (fix adapt; the host arrays hold
 * them, in device order, after run_sync_host): the cut-offs follow the new
 * largest radii and the next step rebuilds the list, so that no contact of
 * grown atoms is missed. */
void nbr_radii_changed(struct gravel *g);
void nbr_free(struct gravel *g);
/* Per step: LAMMPS Neighbor::decide() (every/delay/check/once, distance
 * check by device reduction) and a non-finite check that stops the run with
 * the step, tag and probable cause. Returns 1 when a rebuild is due. With
 * forced (a fix's next_reneighbor is this step) it returns 1 before the
 * every/delay count advances, as LAMMPS (no dangerous-build count).
 *
 * plain: nothing but the step's kernels runs until the next decision (the
 * step's pair_gather opens the next step: src/engine/run.c). Such a step
 * whose opening already ran may be decided on speculation (not on the serial
 * device, nor under MPI, and only with every 1 delay 0 check yes): no
 * rebuild, without reading the flags, its kernels bound to halt
 * (nbr_halt_args) if an opening since the last read asked for a rebuild.
 * The next decision that reads the flags checks them all; when one failed
 * it puts g->step and g->time back to that step, whose opening then
 * decides (a rebuild, or the non-finite stop): the caller's step count
 * follows g->step. The results are those of deciding every step. */
int nbr_decide(struct gravel *g, int forced, int plain);
/* The halt of this step's pair kernels (KARGS_halt of kernels/kernel_args.h):
 * the stamps of the steps decided on speculation, or never. */
struct halt_args;
void nbr_halt_args(struct gravel *g, struct halt_args *h);
/* The arguments of a step's opening for pair_gather (kernels/atom_step.cl).
 * With ahead, the next step's opening runs in this step's pair_gather
 * (src/engine/run.c, step_lookahead): it gets a new stamp and the next
 * nbr_decide only reads the flags; without, the arguments are bound unused.
 * nbr_step_reset forgets an opening run ahead (a run's start). */
struct atom_step_args;
void nbr_step_args(struct gravel *g, struct atom_step_args *a, int ahead);
void nbr_step_reset(struct gravel *g);
/* Atoms nold .. nnew - 1 were appended to the device arrays (eng_append):
 * they own no previous contacts, so the next rebuild's history transfer
 * finds none for them. */
void nbr_atoms_appended(struct gravel *g, int nold, int nnew);
/* Wrap periodic atoms, shrink-wrap, drop lost atoms (per thermo_modify
 * lost), re-sort all per-atom arrays by cell (atom_modify sort) and build
 * the list and its contacts. */
void nbr_rebuild(struct gravel *g);
/* The current list (valid after a build). */
const struct nbr_list *nbr_list(struct gravel *g);
/* Sum of list lengths (host reduction of the counts). */
double nbr_total(struct gravel *g);
/* Largest overlap / min radius over the current contacts. */
double nbr_max_overlap(struct gravel *g);

/* Device exclusive prefix scan of m ints: out[0..m] (out[m] = total). For
 * tests and the sort. Kernels must be set up (nbr_setup). */
void nbr_scan(struct gravel *g, cl_mem in, cl_mem out, int m);

/* Restart support (restart.c): the list in host form, partners as device
 * indices in list order. nbr_export fills s from the current list (0 = no
 * list built this engine); nbr_import installs s as the current, built list
 * (old_valid: the next rebuild transfers its history by partner tag) with
 * the reference positions and the steps since the build, and sets the
 * periodic lengths from the box; it returns 0 and installs nothing when the
 * rows are not symmetric (j in i's row without i in j's). Arrays are caller-owned (free with
 * nbr_state_free). */
struct nbr_state {
    int n, maxn, ago, history;  /* history: REALs per contact (0: none) */
    int *ncount;            /* [n] */
    int *nlist;             /* [n maxn] */
    double *shear;          /* [history n maxn], NULL without history */
    double *xhold;          /* [3 n] */
};
int nbr_export(struct gravel *g, struct nbr_state *s);
/* The reference positions of the last build of slots 0 .. n-1 (absolute,
 * double) into out[3n]; returns the steps since that build, -1 (nothing
 * read) when no list is built. */
int nbr_xhold_read(struct gravel *g, int n, double *out);
/* A decomposed run's rebuild: hist (the device's bytes, HIST_N REAL per
 * current contact) becomes the contacts' history, kept only where the
 * rebuild's transfer keeps it (pairs that overlap now). */
void nbr_history_install(struct gravel *g, const void *hist);
int nbr_import(struct gravel *g, const struct nbr_state *s);
void nbr_state_free(struct nbr_state *s);
/* The pair force of every contact of the current list at its last
 * evaluation (the records pair_contacts wrote: zero for a contact that did
 * not act), read back in contact order: ci[k] and cj[k] the two atoms
 * (device indices = host indices after run_sync_host), f[3k .. 3k+2] the
 * force on ci[k] from cj[k] (cj[k] receives its negative) and, when t is
 * not NULL, t[3k .. 3k+2] the torque on ci[k] (0 without rotation). Returns
 * the count (the arrays malloc'd, caller frees), or -1 when no list is
 * built for the current atoms (nothing allocated). */
int nbr_contact_forces(struct gravel *g, int **ci, int **cj, double **f, double **t);

/* The list's box for a kernel's BOX argument (kernels/kernel_args.h):
 * Lx Ly Lz (0 = not periodic) and the tilts xy xz yz. */
void nbr_list_box(const struct nbr_list *l, double box[6]);

/* Memory (src/engine/memfit.c): device bytes per atom slot (reference
 * positions, cell and sort indices, counts, offsets and the list rows), per
 * contact (partners, history, records), the contact
 * capacity allocated for ncontact contacts, and the bytes held now. */
size_t nbr_atom_bytes(struct gravel *g);
size_t nbr_contact_bytes(struct gravel *g);
size_t nbr_capacity(size_t ncontact);
size_t nbr_held_bytes(struct gravel *g);

#endif
