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

#include "state.h"

#define PAIR_MAXPARAM 8
#define PAIR_MAXCOEF 8
#define PAIR_MAXTERMS 4     /* terms fused by hybrid/overlay */

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
    /* 1 when these coefficients conserve energy: elastic normal law, no
     * friction or damping (the run footer then reports the energy drift).
     * NULL: never. */
    int (*conservative)(const struct pair *p);
    /* Elastic energy of a contact of overlap delta > 0 and R* = reff (with it). */
    double (*contact_energy)(const struct pair *p, double delta, double reff);
    /* ---- composition and cohesion (cohesion helper; all optional) ---- */
    /* Acts beyond body contact (cohesion): the loop hands it every listed
     * pair and the evaluator gates itself; the neighbor cut-off grows to
     * reach(). Contact styles (0) are called only for touching pairs. */
    int beyond_contact;
    /* 1: the evaluator also takes pairs (and plane and cylinder wall
     * elements) apart that one drift at their normal rate brings into or
     * out of contact, with c->approach set (build option PAIR_APPROACH;
     * linear/restitution's exact two-body impulse, kernels/contact_normal.cl). */
    int approach;
    /* Largest centre distance at which this style acts, for a pair of radius
     * sum `radsum`: an affine upper bound A + B radsum over all type pairs. */
    double (*reach)(const struct pair *p, double radsum);
    /* `pair_coeff I J args...` for types ilo..ihi x jlo..jhi, LAMMPS's
     * semantics: set the pairs (I, J) with I in ilo..ihi, J in
     * max(jlo, I)..jhi (so I <= J; pair.c has swapped `pair_coeff 2 1` and
     * checked that at least one pair is set), and their mirrors (J, I).
     * NULL: the style has no per-type coefficients; pair_coeff takes no
     * arguments after the types and only records which pairs were named
     * (every I I must be, at run, as LAMMPS requires). */
    void (*coeff)(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi,
                  int argc, char **argv);
    /* Run start: validate coefficients, mix cross terms (before pack). */
    void (*init)(struct gravel *g, struct pair *p);
    /* hybrid/overlay: source files and build options of the composed terms. */
    const char *(*source_n)(const struct pair *p, int k);
    int (*defines)(const struct pair *p, char *buf, size_t len);
    /* REALs of contact history per contact when history is set (NULL: 3);
     * at most GR_HIST_MAX. pair granular sizes it from the sub-models. */
    int (*history_size)(const struct pair *p);
    /* Acts beyond body contact for these coefficients (JKR of pair granular):
     * as beyond_contact, decided at run start (after init). NULL: never. */
    int (*beyond)(const struct pair *p);
    /* History slots [*first, *first + return) that LAMMPS 2021 negates when a
     * pair changes owner at a rebuild although they are symmetric in the two
     * atoms (pair granular: rolling and twisting); gravel keeps them unless
     * run with -compat lammps2021. NULL or 0: none. */
    int (*lammps2021_flip)(const struct pair *p, int *first);
    /* LAMMPS 2021's init_one cut-off of type pair (i, j) whose largest radii
     * are ri, rj (its neighbor bins follow from it). NULL: ri + rj. */
    double (*lammps2021_cut)(const struct pair *p, int i, int j, double ri, double rj);
    /* Release p->data. */
    void (*destroy)(struct pair *p);
    /* A potential (pair colloid): the kernel function returning the pair
     * energy REAL f(REAL rsq, __global const REAL *param), 0 at and beyond
     * the cut-off (thermo epair, pe, etotal: src/pair_energy.c). NULL: the
     * style has no potential energy (granular contacts). */
    const char *energy;
    /* Cut-off of the type pair (a potential with per-type cut-offs, pair
     * colloid): the neighbor list then holds pairs within it plus the skin,
     * whatever the radii (after init). NULL: the radii decide. */
    double (*type_cut)(const struct pair *p, int itype, int jtype);
};

struct pair {
    const struct pair_style *style;
    double coef[PAIR_MAXCOEF];  /* style-defined (gran: kn kt gamman gammat xmu dampflag limit) */
    int coeff_set;              /* some pair_coeff was given (or restored) */
    unsigned char *setflag;     /* styles without a coeff hook: nt x nt pairs
                                 * named by pair_coeff (NULL after a restart:
                                 * coeff_set alone then says "all") */
    int setflag_nt;
    int mix_arithmetic;         /* pair_modify mix arithmetic (styles that mix) */
    int shift;                  /* pair_modify shift yes (styles with an energy) */
    void *data;                 /* style-owned (per-type tables, composed terms) */
};

void pair_free(struct gravel *g);
/* The registered style with this name, or NULL (restart.c). */
const struct pair_style *pair_style_find(const char *name);

/* ---- composition helpers (pair.c) ---- */
/* For the pair_coeff I J ranges, LAMMPS's loop: calls visit(I, J) for every
 * I in ilo..ihi and J in max(jlo, I)..jhi; returns how many. */
int pair_coeff_each(int ilo, int ihi, int jlo, int jhi, void (*visit)(int, int, void *),
                    void *ctx);
/* The first type I whose I I entry is 0 in an nt x nt flag table, or 0. */
int pair_first_unset_diag(const unsigned char *flag, int nt);
/* Parse `style args...` into *p (settings of that style); errors name the style. */
void pair_create(struct gravel *g, struct pair *p, const struct pair_style *st, int argc,
                 char **argv);
/* Release a pair's style data (not the struct itself). */
void pair_release(struct pair *p);
/* What the run needs from the pair style(s): rotation, contact history, a
 * term that acts beyond body contact (cohesion: HAS_COHESION). */
int pair_needs_rotation(const struct pair *p);
int pair_needs_history(const struct pair *p);
/* REALs of history per contact (3 unless a style sizes it). */
int pair_history_size(const struct pair *p);
int pair_has_cohesion(const struct pair *p);
/* Neighbor cut-off without skin for a pair of radius sum `radsum`: radsum
 * unless a cohesion term reaches farther. */
double pair_reach(const struct gravel *g, double radsum);
/* The largest type-pair cut-off of the pair style(s) between types of the
 * masks (bit t-1 = type t; ~0u: every type), 0 when none has type_cut. */
double pair_type_cut_max(const struct gravel *g, unsigned imask, unsigned jmask);
/* k-th kernel source of the pair style (NULL past the last). */
const char *pair_source(const struct pair *p, int k);
/* " -D HAS_COHESION -D COH_REACH_A=.. -D COH_REACH_B=.." when a term acts
 * beyond contact (else nothing); returns the length written. */
int pair_cohesion_defines(const struct pair *p, char *buf, size_t len);
/* Append the pair's build options (" -D PAIR_EVAL=..." ...) to buf. */
int pair_defines(const struct pair *p, char *buf, size_t len);
/* Run start: validate and mix coefficients (style init). */
void pair_prepare(struct gravel *g);
/* The composed terms of a hybrid/overlay pair (styles/pair_hybrid_overlay.c). */
int pair_hybrid_terms(const struct pair *p, const struct pair **terms);

/* Shared by the three gran styles (pair_gran_common.c in styles/):
 * `Kn Kt gamman gammat xmu dampflag [limit_damping]` with LAMMPS defaults. */
void pair_gran_settings(struct gravel *g, struct pair *p, int argc, char **argv);
void pair_gran_pack(const struct pair *p, int itype, int jtype, double *param);

/* Index of packed gran parameters (GRAN_*): kernels/param_layout.h, shared
 * with the kernels. */
#include "param_layout.h"

#endif
