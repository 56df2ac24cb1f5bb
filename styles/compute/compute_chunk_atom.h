/* compute_chunk_atom.h - what fix ave/chunk reads from a
 * `compute ID group chunk/atom bin/1d|bin/2d|bin/3d|bin/sphere|bin/cylinder
 * ...` (its bins and each atom's chunk), styles/compute/compute_chunk_atom.c. */
#ifndef GR_COMPUTE_CHUNK_ATOM_H
#define GR_COMPUTE_CHUNK_ATOM_H

#include "compute.h"

/* Bins in shells about a centre (bin/sphere) or an axis (bin/cylinder) */
enum chunk_radial { CHUNK_RADIAL_NONE, CHUNK_RADIAL_SPHERE, CHUNK_RADIAL_CYLINDER };

struct chunk_grid {
    enum chunk_radial radial;   /* NONE: the chunks are the rectangular bins */
    int ndim;                   /* 1, 2 or 3 rectangular binned dimensions (a cylinder's
                                   axis: 1, a sphere: 0) */
    int dim[3];                 /* box dimension of binned dimension m */
    int nlayers[3];             /* bins along binned dimension m */
    double offset[3], delta[3]; /* lower edge and width of the bins (box units,
                                   or fractions of the box with units reduced) */
    int reduced;                /* units reduced */
    int discard_no;             /* discard no: out-of-range atoms clamped into the end bins */
    int nchunk;                 /* product of nlayers */
    double volume;              /* LAMMPS's chunk_volume_scalar (box units^3) */
    const double *volumes;      /* [nchunk] each chunk's volume (radial bins: LAMMPS's
                                   chunk_volume_vec), NULL: every chunk `volume` */
    int ncoord;                 /* coordinates per chunk (radial: sphere 1, cylinder 2) */
    const double *coord;        /* [nchunk][ncoord] bin centres, LAMMPS order: the
                                   last binned dimension varies fastest; radial bins:
                                   the shell's mid radius (then the axial centre) */
    const int *ids;             /* compress yes: [nchunk] each chunk's original ID
                                   (NULL: chunk k is ID k) */
};

/* The chunk/atom compute `id`, or an error naming `who`. */
struct compute *chunk_atom_get(struct gravel *g, const char *id, const char *who);
/* Coordinates per chunk (LAMMPS ncoord), known from the arguments. */
int chunk_atom_ncoord(const struct compute *c);
/* bin/sphere or bin/cylinder (NONE for every other style), from the arguments. */
enum chunk_radial chunk_atom_radial(const struct compute *c);
/* 1 with compress yes (the grid's ids are the original chunk IDs). */
int chunk_atom_compressed(const struct compute *c);
/* Lay out the bins on the current box (LAMMPS setup_chunks); returns the
 * grid, valid until the next call. nchunk once: laid out at the first call
 * only. */
const struct chunk_grid *chunk_atom_setup(struct gravel *g, struct compute *c);
/* Chunk of every host atom (1..nchunk, 0 = excluded: outside the group or
 * region, or discarded), on the grid of the last chunk_atom_setup. */
const int *chunk_atom_assign(struct gravel *g, struct compute *c);
/* Each chunk's mass-weighted mean of u (3 per atom: velocities, or unwrapped
 * positions when u is NULL) over the atoms in groupbit with ichunk > 0, summed
 * in atom-ID order: mean[3 nchunk] (0 for a chunk without mass) and, when
 * mass is not NULL, mass[nchunk]. Host arrays. */
void chunk_mass_mean(struct gravel *g, unsigned groupbit, const int *ichunk, int nchunk,
                     const double *u, double *mean, double *mass);
/* LAMMPS's lock: while the fix `fix_id` (averaging over chunks) holds it,
 * the layout (nchunk, bins) stays as its epoch's first sample set it, for
 * every reader; another fix's lock is an error (a fix that is gone holds
 * none). */
void chunk_atom_lock(struct gravel *g, struct compute *c, const char *fix_id);
void chunk_atom_unlock(struct compute *c, const char *fix_id);

#endif
