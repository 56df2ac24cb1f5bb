/* atom_origin.h - each atom's unwrapped position when a fix was defined,
 * kept by atom ID (fix move's and fix spring/self's x0, LAMMPS's
 * xoriginal): taken from the host atoms of the fix's group, kept in
 * restart files, and put on the device relative to the run's origin (split
 * in two floats when positions are) for the fix's kernels, which find an
 * atom's by its ID (ntab IDs; an atom beyond them has none). */
#ifndef GR_ATOM_ORIGIN_H
#define GR_ATOM_ORIGIN_H

#include "ocl.h"
#include "state.h"
#include "tag_ref.h"

struct atom_origin {
    struct tag_ref x0;          /* by atom ID */
    cl_mem tab, tablo;          /* x0 - origin on the device (tablo: low parts) */
    int64_t ntab;
    int stale;                  /* the device's copy is to be (re)written */
};

/* The unwrapped positions of the host atoms in groupbit, now. */
void atom_origin_take(struct gravel *g, struct atom_origin *o, unsigned groupbit);
/* At a run's setup: every atom of groupbit has an origin (else an error
 * naming the fix `who` `id`); the device copy is rewritten at the first
 * atom_origin_device of the run (read_restart may still replace x0). */
void atom_origin_setup(struct gravel *g, struct atom_origin *o, unsigned groupbit,
                       const char *who, const char *id);
/* The device copy, written first when stale. */
void atom_origin_device(struct gravel *g, struct atom_origin *o);
/* Per host atom: its origin (3 values, 0 outside groupbit), in *out
 * (grown as needed); returns *out. */
const double *atom_origin_values(struct gravel *g, const struct atom_origin *o,
                                 unsigned groupbit, double **out);
/* Restart bytes: the count, then (ID, x0) of every atom that has one;
 * write returns the size (nothing written when buf is NULL or cap short),
 * read checks len. */
size_t atom_origin_write(const struct atom_origin *o, unsigned char *buf, size_t cap);
void atom_origin_read(struct gravel *g, struct atom_origin *o, const unsigned char *buf,
                      size_t len, const char *id);
void atom_origin_free(struct atom_origin *o);

#endif
