/* pair_gran.h - LIGGGHTS's contact model selection (`model M tangential T
 * [cohesion C] [rolling_friction R] [surface default] [setting on|off ...]`),
 * shared by `pair_style gran` (styles/pair/pair_gran.c) and `fix wall/gran
 * model ...` (styles/fix/fix_wall_gran.c): parsing, and the packing of one
 * (particle type, partner type) parameter set (LG_*, kernels/param_layout.h)
 * from the fix property/global materials (LIGGGHTS's mixing). */
#ifndef GR_PAIR_GRAN_H
#define GR_PAIR_GRAN_H

#include "state.h"
#include "param_layout.h"

struct lg_model {
    int nm;                     /* LG_N_* */
    int tm;                     /* 1 history, 0 no_history */
    int coh;                    /* LG_C_* */
    int roll;                   /* LG_R_* */
    int tdamp, limit, kttokn, absdamp, torsion; /* settings (0/1) */
};

/* Parse argv[0..argc) (`model ...` onwards) into *m; parsing stops at the
 * first word in stop (NULL-terminated, or NULL). Returns the index of the
 * first word not parsed. Unsupported models and settings are errors naming
 * `who`. */
int lg_parse(struct gravel *g, struct lg_model *m, int argc, char **argv,
             const char *const *stop, const char *who);
/* The model's settings as 5 doubles (restart: pair->coef) and back. */
void lg_to_coef(const struct lg_model *m, double *c);
void lg_from_coef(struct lg_model *m, const double *c);
/* Check that every property the model reads exists for nt types (errors
 * name `who`); then pack the set of particle type I against partner type J
 * (wall: 1 for a wall of type J) into q[LG_NPARAM]. */
void lg_check(struct gravel *g, const struct lg_model *m, int nt, const char *who);
void lg_pack(struct gravel *g, const struct lg_model *m, int nt, int I, int J, int wall,
             double *q, const char *who);
/* thornton_ning: stop (naming `who`) where a contact of the atoms present
 * would have a yield stress <= 0 (LIGGGHTS stops at the contact), the
 * smallest atom of each type against the largest of each (jwall > 0:
 * against a wall of type jwall instead, < 0: walls of every type); table:
 * the packed sets, nt x nt. Other models: nothing. */
void lg_check_yield(struct gravel *g, const struct lg_model *m, const double *table, int nt,
                    int jwall, const char *who);

#endif
