/* neighbor.h - device neighbor lists: binning, sort by cell, full Verlet list
 * with skin, rebuild decisions, periodic wrap, shrink-wrap, lost atoms and
 * contact history carried across rebuilds (by partner tag).
 *
 * List layout: atom-major, nlist[i maxn + k] (k < ncount[i]) is the device
 * index of i's k-th neighbor; with history, shear[3 (i maxn + k) ..] is the
 * tangential displacement of that contact. */
#ifndef GR_NEIGHBOR_H
#define GR_NEIGHBOR_H

#include "engine.h"

struct nbr_list {
    cl_mem nlist, ncount, shear;
    int maxn;
    double L[3];            /* periodic lengths (0 = not periodic), for minimum image */
};

/* Run start: kernels and work buffers for the current program and atoms. */
void nbr_setup(struct gravel *g);
/* Forget the list (atoms changed): the next build transfers no history. */
void nbr_invalidate(struct gravel *g);
void nbr_free(struct gravel *g);
/* Per step: LAMMPS Neighbor::decide() (every/delay/check/once, distance
 * check by device reduction) and a non-finite check that stops the run with
 * the step, tag and probable cause. Returns 1 when a rebuild is due. */
int nbr_decide(struct gravel *g);
/* Wrap periodic atoms, shrink-wrap, drop lost atoms (per thermo_modify
 * lost), re-sort all per-atom arrays by cell and build the list. */
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
 * periodic lengths from the box. Arrays are caller-owned (free with
 * nbr_state_free). */
struct nbr_state {
    int n, maxn, ago, history;
    int *ncount;            /* [n] */
    int *nlist;             /* [n maxn] */
    double *shear;          /* [3 n maxn], NULL without history */
    double *xhold;          /* [3 n] */
};
int nbr_export(struct gravel *g, struct nbr_state *s);
void nbr_import(struct gravel *g, const struct nbr_state *s);
void nbr_state_free(struct nbr_state *s);

#endif
