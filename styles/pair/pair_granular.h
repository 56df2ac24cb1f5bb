/* pair_granular.h - the sub-models of LAMMPS's granular contact model
 * (pair_style granular as today's LAMMPS has it, or 29 Sep 2021's with
 * -compat lammps2021), shared by the pair style
 * (styles/pair/pair_granular.c) and fix wall/gran granular
 * (styles/fix/fix_wall_gran.c): one contact's model, its parsing and packing. */
#ifndef GR_PAIR_GRANULAR_H
#define GR_PAIR_GRANULAR_H

#include "state.h"
#include "param_layout.h"

struct gr_one {
    int set;                    /* 1 = pair_coeff, 2 = mixed at run start */
    int nm, dm, tm, rm, wm, ld; /* sub-models (GR_N_* ...), limit_damping */
    double kn, damp, coh, E, nu;
    double kt, gt, mu, kr, gr, mur, kw, gw, muw;
    double mud;                 /* /static tangential models: dynamic friction (mu: static) */
    int c2021;                  /* -compat lammps2021: LAMMPS 29Sep2021's conversions */
    double cutoff;              /* -1: none */
    double e;                   /* tsuji, coeff_restitution: e as given (mixed, then converted) */
    int ktnull;                 /* the Mindlin kt was NULL (8 G*) */
    int hm;                     /* heat model GR_H_* (LAMMPS 2023: heat area|radius k) */
    double hk;                  /* its coefficient */
    int sync;                   /* synchronized_verlet given (pair granular only: the
                                 * walls and surf/granular refuse it) */
    double Y, gamma, psi_b;     /* mdr: yield stress, surface energy, bulk trigger (with E,
                                 * nu; damp holds its eta_n0) */
    int dtype;                  /* damping mdr's type, 1 or 2 */
};

/* Parse the sub-model keywords of argv[0..argc) into *o as LAMMPS does
 * (`normal args [damping m] tangential m args [rolling ...] [twisting ...]
 * [heat none|area h|radius k] [limit_damping] [synchronized_verlet]`, plus
 * `cutoff c` where allow_cutoff); parsing stops at the
 * first word in stop (NULL-terminated list, or NULL). kn of the material
 * models is 4/3 E* of (E, nu) and a NULL Mindlin kt 8 G*; tsuji's e becomes
 * its damping coefficient, and so does coeff_restitution's (by the normal
 * model; not with the cohesive dmt, jkr). `who` names the command in errors. Returns the
 * index of the first word not parsed. */
int granular_parse(struct gravel *g, struct gr_one *o, int argc, char **argv,
                   const char *const *stop, int allow_cutoff, const char *who);
/* The GR_NPARAM coefficients of o (kernels/param_layout.h). */
void granular_pack(const struct gr_one *o, double *q);
/* Tsuji's damping coefficient for restitution e (LAMMPS's polynomial fit,
 * Marshall 2009 eq. 53), times sqrt(2) unless lammps2021 (LAMMPS 2 Sep 2026,
 * GranSubModDampingTsuji::init: Tsuji 1992's effective-mass convention). */
double granular_tsuji(double e, int lammps2021);
/* damping coeff_restitution (LAMMPS 2024 GranSubModDampingCoeffRestitution::
 * init): the damping coefficient of restitution e for normal model nm,
 * -2 ln e / sqrt(pi^2 + ln^2 e) for hooke (the linear spring-dashpot's exact
 * one), -sqrt(3/2) 2 sqrt(5/6) ln e / sqrt(pi^2 + ln^2 e) for the others
 * (the Hertz one); the kernel multiplies it by sqrt(m Fne / delta). */
double granular_coeff_restitution(double e, int nm);

struct pair;
/* The mdr model of pair granular p (fix granular/mdr, LAMMPS's
 * setup_pre_force checks): -1 when no type pair uses mdr; else every type
 * pair must be that one model (errors with LAMMPS's words otherwise), mat
 * gets E, nu, Y, gamma, psi_b, damping mdr's eta_n0 and type, and the return is the offset of the mdr block
 * in the history row (kernels/param_layout.h, enum mdr_hist). */
int granular_mdr_model(struct gravel *g, const struct pair *p, double mat[7]);

#endif
