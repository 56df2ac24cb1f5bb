/* peratom_input.h - one per-atom input of a fix that reads the atoms (fix
 * ave/atom, fix store/state), as LAMMPS's: an attribute by name (x y z vx
 * vy vz fx fy fz for ave/atom; every atom_attr.h name for store/state), a
 * custom property i_name / d_name (store/state), c_ID / c_ID[I] of a
 * per-atom compute, f_ID / f_ID[I] of a fix's per-atom output, v_name of
 * an atom-style variable. Wildcards are expanded by the caller (ref.h). */
#ifndef GR_PERATOM_INPUT_H
#define GR_PERATOM_INPUT_H

#include "state.h"

enum peratom_attrs { PERATOM_XVF, PERATOM_ALL }; /* which attribute names are inputs */

struct peratom_input {
    char kind;                  /* 'a' an attribute, 'p' a custom property, 'c', 'f', 'v' */
    int index;                  /* the attribute; I of [I] */
    char id[GR_NAMELEN];
    char word[GR_NAMELEN + 24]; /* as given */
};

/* Parse `word` into *in; an error naming `who` when it is none of the inputs
 * `attrs` allows (the message lists `usage`). */
void peratom_input_parse(struct gravel *g, const char *word, enum peratom_attrs attrs,
                         struct peratom_input *in, const char *usage, const char *who);
/* At run setup: the compute, fix, variable or property exists and has the
 * per-atom output asked for (errors name `who` and the fix `id`). */
void peratom_input_check(struct gravel *g, const struct peratom_input *in, const char *who,
                         const char *id);
/* Its value on every host atom now: p[i * *stride]; *owned (or NULL) is
 * the caller's to free. */
const double *peratom_input_values(struct gravel *g, const struct peratom_input *in, int *stride,
                                   double **owned, const char *who);

#endif
