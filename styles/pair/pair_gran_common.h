/* pair_gran_common.h - what the three LAMMPS gran styles (gran/hooke,
 * gran/hooke/history, gran/hertz/history) share (styles/pair/pair_gran_common.c). */
#ifndef GR_PAIR_GRAN_COMMON_H
#define GR_PAIR_GRAN_COMMON_H

#include "pair.h"

/* `Kn Kt gamman gammat xmu dampflag [limit_damping]` with LAMMPS defaults. */
void pair_gran_settings(struct gravel *g, struct pair *p, int argc, char **argv);
void pair_gran_pack(const struct pair *p, int itype, int jtype, double *param);
/* Their record: kernel source, evaluator, its lane-generic law
 * (kernels/gran_law.cl), history (0/1); rotation, the collision time,
 * energy conservation and the elastic energy. */
void pair_gran_describe(const struct pair *p, struct pair_caps *c, const char *source,
                        const char *eval, const char *law, int history);

#endif
