/* pair.h - pair styles: the contact law between two particles in contact.
 *
 * A style is a descriptor (struct pair_style) in styles/pair_<ident>.c and a
 * pure evaluator in kernels/pair_<ident>.cl:
 *
 *   void <ident>_eval(const struct contact *c, __global const REAL *param,
 *                     REAL3 *shear, REAL3 *force_i, REAL3 *torque_i);
 *
 * struct contact (kernels/common.cl) carries del = x_i - x_j, rsq, radii,
 * radsum, reff = radi radj / radsum, vr = v_i - v_j, omega_i, omega_j, meff,
 * dt and shearupdate. The evaluator returns the whole force on i and the
 * torque on i; it must be exactly antisymmetric under i <-> j so that the
 * force on j (computed by j's own loop) is exactly minus the force on i.
 * `param` points at this type pair's `nparam` packed REALs, produced by
 * pack() on the host. fix wall/gran calls the same evaluators with the wall as
 * particle j (radj = 0, radsum = reff = radi, omj = 0, meff = m_i).
 *
 * One shared neighbor-loop kernel (kernels/pair_loop.cl) calls PAIR_EVAL. */
#ifndef GR_PAIR_H
#define GR_PAIR_H

#include "gravel.h"

#define PAIR_MAXPARAM 8
#define PAIR_MAXCOEF 8

struct pair;

struct pair_style {
    const char *name;           /* "gran/hooke/history" */
    const char *source;         /* "pair_gran_hooke_history.cl" */
    const char *eval;           /* evaluator function, "gran_hooke_history_eval" */
    int history;                /* needs per-contact shear history (3 REAL / contact) */
    int rotation;               /* needs omega and torque */
    int nparam;                 /* packed REALs per type pair */
    /* pair_style arguments (after the style name). */
    void (*settings)(struct gravel *g, struct pair *p, int argc, char **argv);
    /* Fill param[0..nparam) for type pair (i, j) from p->coef. */
    void (*pack)(const struct pair *p, int itype, int jtype, double *param);
    /* Estimated duration of a binary collision of two particles of mass m and
     * radius r approaching at speed vn (for time-step diagnostics). */
    double (*collision_time)(const struct pair *p, double m, double r, double vn);
};

struct pair {
    const struct pair_style *style;
    double coef[PAIR_MAXCOEF];  /* style-defined (gran: kn kt gamman gammat xmu dampflag limit) */
    int coeff_set;              /* pair_coeff * * was given */
};

void pair_free(struct gravel *g);
/* The registered style with this name, or NULL (restart.c). */
const struct pair_style *pair_style_find(const char *name);

/* Shared by the three gran styles (pair_gran_common.c in styles/):
 * `Kn Kt gamman gammat xmu dampflag [limit_damping]` with LAMMPS defaults. */
void pair_gran_settings(struct gravel *g, struct pair *p, int argc, char **argv);
void pair_gran_pack(const struct pair *p, int itype, int jtype, double *param);

/* Index of packed gran parameters. */
enum { GRAN_KN, GRAN_KT, GRAN_GAMMAN, GRAN_GAMMAT, GRAN_XMU, GRAN_LIMIT, GRAN_NPARAM };

#endif
