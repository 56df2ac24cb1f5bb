/* compute_pair_gran_local.h - the columns of a compute pair/gran/local, for
 * the dump that draws its contacts (dump local/gran/vtk). */
#ifndef GR_COMPUTE_PAIR_GRAN_LOCAL_H
#define GR_COMPUTE_PAIR_GRAN_LOCAL_H

#include "compute.h"

/* The keywords, in the order of their columns (LIGGGHTS's) */
enum pgl_value { PG_POS, PG_VEL, PG_ID, PG_F, PG_FN, PG_FT, PG_T, PG_TN, PG_TT, PG_HIST,
                 PG_AREA, PG_DELTA, PG_CP, PG_N };

/* 1 when c is a compute pair/gran/local; then at[k] is the first column of
 * keyword k (enum pgl_value), -1 when it is off. */
int pgl_columns(const struct compute *c, int at[PG_N]);

#endif
