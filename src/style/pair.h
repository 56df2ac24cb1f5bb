/* pair.h - pair styles: the contact law between two particles in contact.
 *
 * A style is a descriptor (struct pair_style) in styles/pair_<ident>.c, one
 * PAIR(keyword, ident) row in styles/styles.def, and a pure evaluator in
 * kernels/pair_<ident>.cl:
 *
 *   void <ident>_eval(const struct contact *c, __global const REAL *param,
 *                     REAL3 *shear, REAL3 *force_i, REAL3 *torque_i);
 *   REAL <ident>_eval_tcol(const struct contact *c, __global const REAL *param,
 *                          REAL vn);      (collision time, see below)
 *
 * struct contact (kernels/common.cl) carries del = x_i - x_j, rsq, radii,
 * radsum, reff = radi radj / radsum, vr = v_i - v_j, omega_i, omega_j, meff,
 * dt and shearupdate. The evaluator returns the whole force on i and the
 * torque on i; it must be exactly antisymmetric under i <-> j so that the
 * force on j (computed by j's own loop) is exactly minus the force on i.
 * `param` points at this type pair's `nparam` packed REALs, produced by
 * pack() on the host (layout: an enum in kernels/param_layout.h). fix
 * wall/gran and fix wall/pair call the same evaluators with the wall as
 * particle j (radj = 0, radsum = reff = radi, omj = 0, meff = m_i).
 *
 * Life cycle: settings() at pair_style, coeff() at pair_coeff; at every run
 * start pair_setup() calls init() (check, mix) and then describe(), which
 * fills the style's capabilities record (struct pair_caps below: rotation,
 * history width, reach and cut-offs, approach, energy, kernel sources, build
 * options, collision time); pair_pack() then packs the parameters, before
 * the fixes initialise. The core reads the record only; it never calls
 * another style hook and never names a style.
 *
 * One shared neighbor-loop kernel (kernels/pair_loop.cl) calls PAIR_EVAL. */
#ifndef GR_PAIR_H
#define GR_PAIR_H

#include "state.h"

#define PAIR_MAXPARAM 8
#define PAIR_MAXCOEF 8
#define PAIR_MAXTERMS 4     /* terms fused by hybrid/overlay */

struct pair;

/* One pair's state for pair_caps.single: del = x_i - x_j (minimum image),
 * rsq = |del|^2, radii, velocities, masses; frozen_i/j: in fix freeze's
 * group (meff is then the other particle's mass, as LAMMPS). */
struct pair_single {
    int itype, jtype;
    double del[3], rsq;
    double radi, radj;
    double vi[3], vj[3];
    double mi, mj;
    int frozen_i, frozen_j;
    double omi[3], omj[3];  /* angular velocities (the extra values only) */
    const double *hist;     /* the contact's history seen from i, NULL: none yet */
    double *sv;             /* NULL, or room for single_extra extra values (LAMMPS's
                             * svector: compute pair/local p1 .. pN) */
};

/* ---- the capabilities record: what a style answers at run set-up --------
 *
 * Every question the core asks a pair style is answered ONCE per run, in
 * one call: pair_setup() (run start, src/engine/engine.c) runs the style's init(),
 * then its describe(), which fills this record; the core (engine, neighbor,
 * run, output, walls) reads only the record and never calls a style hook or
 * names a style. hybrid and hybrid/overlay describe each term and merge the
 * terms' records in their own describe(). Fields a style leaves alone stay
 * 0 / NULL, which always means "no".
 *
 * The run program: the engine includes `sources` and assembles every build
 * option in one place (eng_prepare): PAIR_EVAL=eval or PAIR_EVAL_ROW=eval_row,
 * PAIR_APPROACH, PAIR_ENERGY=energy, the style's own `def` entries (sub-model
 * switches, composed terms) in order, then HAS_COHESION with COH_REACH_A/B
 * (the largest reach terms) and PAIR_TYPECUT.
 *
 * The collision time (contract): collision_time(tcol_of, m, r, vn) is the
 * duration of a head-on collision of two equal particles of mass m and
 * radius r (m* = m/2, R* = r/2) approaching at normal speed vn (0: the law's
 * own fallback), INFINITY when there is none (overdamped, no stiffness); it
 * sizes the run-start time-step report, the -check accuracy map and the
 * energy-drift footer. Each law's formula exists once, as a pure function of
 * (law coefficients, m*, R*, vn) in kernels/collision_time.h, which the host
 * includes and the engine prepends to every program; the law's kernel
 * <eval>_tcol(c, param, vn) (the accuracy records, kernels/accuracy.cl)
 * calls the same function with the contact's m*, R* and speed. */
#define PAIR_MAXDEF 24

struct pair_caps {
    int nparam;                 /* packed REALs per type pair */
    /* ---- the run program ---- */
    int nsources;               /* kernel sources, in order */
    const char *sources[PAIR_MAXTERMS + 2]; /* + granular's gran_heat.cl */
    const char *eval;           /* 3-vector evaluator (PAIR_EVAL), or NULL */
    const char *eval_row;       /* history-row evaluator (PAIR_EVAL_ROW, pair granular) */
    const char *eval_lanes;     /* eval's law in lane-generic form (kernels/gran_law.cl,
                                 * PAIR_EVAL_LANES=<name>_w): the pair kernel then takes
                                 * the device's lanes of contacts per work-item; NULL: one */
    int approach;               /* also takes pairs one drift from contact (PAIR_APPROACH;
                                 * linear/restitution, kernels/contact_normal.cl) */
    const char *energy;         /* potential energy function REAL f(REAL rsq, param), 0 at
                                 * and beyond the cut-off (pair colloid; src/contact/pair_energy.c);
                                 * NULL: contact forces only */
    int ndef;                   /* the style's own build options, NAME or NAME=VALUE */
    struct pair_def {
        char name[32];
        char value[40];
    } def[PAIR_MAXDEF];
    /* ---- state the run keeps ---- */
    int rotation;               /* needs omega and torque */
    int sym_torque;             /* no rolling torque: every contact's torques are
                                 * -radi tc and -radj tc (struct contact_force tr = 0) */
    int history;                /* keeps per-contact history ... */
    int hist_n;                 /* ... of hist_n REAL (3 when none; at most GR_HIST_MAX) */
    int flip_lo, flip_n;        /* history slots [flip_lo, flip_lo + flip_n) that LAMMPS
                                 * 2021 negates when a pair changes owner at a rebuild
                                 * although they are symmetric (pair granular: rolling,
                                 * twisting); gravel keeps them unless -compat lammps2021 */
    /* ---- reach ---- */
    int beyond;                 /* some term acts beyond body contact (cohesion, JKR,
                                 * colloid): the loop hands it every listed pair */
    int nreach;                 /* reach bounds A + B radsum of such terms: the largest */
    double reach_a[PAIR_MAXTERMS], reach_b[PAIR_MAXTERMS]; /* centre distance they act at */
    const struct pair *cut_of;  /* per-type-pair cut-off (a potential, pair colloid): */
    double (*type_cut)(const struct pair *p, int itype, int jtype); /* type_cut(cut_of,..) */
    /* LAMMPS 2021's init_one cut-off of type pair (i, j) whose largest radii
     * are ri, rj (-compat lammps2021 neighbor bins); NULL: ri + rj */
    double (*lammps2021_cut)(const struct pair *p, int i, int j, double ri, double rj);
    const struct pair *cut2021_of;
    /* ---- diagnostics ---- */
    const struct pair *tcol_of; /* the contact law's term (hybrid: the first with one) */
    double (*collision_time)(const struct pair *p, double m, double r, double vn);
    int conservative;           /* these coefficients conserve energy (elastic normal law,
                                 * no friction or damping): the footer reports the drift */
    const struct pair *energy_of; /* elastic energy of a contact of overlap delta > 0 */
    double (*contact_energy)(const struct pair *p, double delta, double reff);
    /* LAMMPS's Pair::single, for compute pair/local: the pair's energy
     * (returned) and fforce, the normal force over the distance (LAMMPS's
     * fpair: F_i = del fforce), of two particles at the state in `s`, with
     * the velocities of the moment (LAMMPS evaluates it at output time, not
     * at force time); 0 beyond contact. NULL: the style has none. */
    const struct pair *single_of;
    double (*single)(const struct pair *p, const struct pair_single *s, double *fforce);
    int single_extra;           /* extra values single() fills in s->sv (0: none) */
    int single_hist;            /* single() reads the contact's stored history for the
                                 * force too (s->hist; pair granular's mdr) */
    /* why this law's forces turn non-finite, named by a run that stops on a
     * non-finite atom (pair colloid: its overlap stop); NULL: the generic
     * diagnosis (diagnose.h) */
    const char *nonfinite_cause;
    /* ---- a law evaluated on the host (pair granular/superellipsoid, first
     * landing): the run builds no device pair program; after the device
     * clears the forces each step, host_forces(g, p) writes every atom's
     * force and torque into the device buffers (engine order). NULL: the
     * device pipeline above. */
    void (*host_forces)(struct gravel *g, const struct pair *p);
};

/* A style's descriptor: lifecycle hooks plus ONE description call. */
struct pair_style {
    const char *name;           /* "gran/hooke/history" */
    int nparam;                 /* packed REALs per type pair */
    /* pair_style arguments (after the style name). */
    void (*settings)(struct gravel *g, struct pair *p, int argc, char **argv);
    /* `pair_coeff I J args...` for types ilo..ihi x jlo..jhi, LAMMPS's
     * semantics: set the pairs (I, J) with I in ilo..ihi, J in
     * max(jlo, I)..jhi (so I <= J; pair.c has swapped `pair_coeff 2 1` and
     * checked that at least one pair is set), and their mirrors (J, I).
     * NULL: the style has no per-type coefficients; pair_coeff takes no
     * arguments after the types and only records which pairs were named
     * (every I I must be, at run, as LAMMPS requires). */
    void (*coeff)(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi,
                  int argc, char **argv);
    /* Run start: validate coefficients, mix cross terms (before describe and pack). */
    void (*init)(struct gravel *g, struct pair *p);
    /* Fill the capabilities record (above) for these coefficients; c arrives
     * zeroed with c->nparam set. Also called before init() by the -check
     * accuracy map, for the collision time only. */
    void (*describe)(const struct pair *p, struct pair_caps *c);
    /* Fill param[0..nparam) for type pair (i, j) from p->coef. */
    void (*pack)(const struct pair *p, int itype, int jtype, double *param);
    /* hybrid, hybrid/overlay: the composed terms (pair_modify pair SUBSTYLE);
     * NULL for a single law. */
    int (*terms)(const struct pair *p, const struct pair **terms);
    /* 1: a surface sub-style of pair_style hybrid (LAMMPS 4 Jul 2026's
     * surf/granular): its pair_coeff gives the models of particle/surface
     * type pairs, which fix surface/local reads (g->styles.surf); never in
     * the pair loop. */
    int surface;
    /* Release p->data. */
    void (*destroy)(struct pair *p);
    /* Restart state beyond coef[] that the style keeps in p->data (pair
     * granular/superellipsoid: its per-type models and its contact history;
     * restart section 14, doc/restart.md). state_write(p, part, buf, cap)
     * returns the byte count of part (PAIR_STATE_COEFF: what the forces
     * depend on, hashed into the restart's force fingerprint;
     * PAIR_STATE_HISTORY: what the run carries), writing it when buf is not
     * NULL and cap suffices; an explicit byte layout (no struct padding).
     * state_read(coeff, ncoeff, hist, nhist, err, errlen) parses both parts
     * into a new p->data (the style's destroy() frees it, given a struct
     * pair holding it), or returns NULL with the reason in err: read_restart
     * verifies the file before it applies anything. NULL hooks: none. */
    size_t (*state_write)(const struct pair *p, int part, unsigned char *buf, size_t cap);
    void *(*state_read)(const unsigned char *coeff, size_t ncoeff, const unsigned char *hist,
                        size_t nhist, char *err, size_t errlen);
};

enum { PAIR_STATE_COEFF, PAIR_STATE_HISTORY };

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
    /* `pair_style hybrid LAW args surf/granular`: the one law stands alone
     * (one_of_hybrid); its pair_coeff lines name it after the types (pair_coeff
     * 1 1 LAW ...), and `pair_coeff I I none` marks type I absent: no particle
     * may have it (fix surface/local's surface types), its pairs are not set */
    int one_of_hybrid;
    unsigned char *none;        /* nt x nt: pair_coeff I J none (one_of_hybrid) */
    int none_nt;
    struct pair_caps caps;      /* pair_setup(): the run's capabilities record */
};

void pair_free(struct gravel *g);
/* 1 when type t is absent from pair p (one_of_hybrid with pair_coeff t t none):
 * its pairs need no coefficients (run start checks that no atom has it). */
int pair_type_absent(const struct pair *p, int t);
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

/* ---- the core's interface: set-up, then the record ---- */
/* Run start (eng_prepare): check that every I I was named, run the style's
 * init(), then fill g->styles.pair->caps through its describe(). */
void pair_setup(struct gravel *g);
/* The record of p as it stands (describe() alone, no init): the -check
 * accuracy map asks for the collision time before any run. */
void pair_describe(const struct pair *p, struct pair_caps *c);
/* The packed parameters of every type pair (nt x nt blocks of caps.nparam,
 * row-major in (I, J)), malloc'd; errors when no pair_coeff was given. Run
 * start, after pair_setup and before the fixes initialise. */
double *pair_pack(struct gravel *g, int *ntypes);
/* Neighbor cut-off without skin for a pair of radius sum `radsum`: radsum
 * unless a term reaches farther (caps.reach_*). */
double pair_reach(const struct gravel *g, double radsum);
/* The largest type-pair cut-off (caps.type_cut) between types of the masks
 * (bit t-1 = type t; ~0u: every type), 0 when the style has none. */
double pair_type_cut_max(const struct gravel *g, unsigned imask, unsigned jmask);
/* caps.collision_time at (m, r, vn), or NAN when the style has none. */
double pair_collision_time(const struct pair_caps *c, double m, double r, double vn);

/* ---- for describe() and composed styles ---- */
/* Append a kernel source (once). */
void pair_caps_source(struct pair_caps *c, const char *file);
/* Append the build option NAME (value NULL) or NAME=value (printf format). */
void pair_caps_define(struct pair_caps *c, const char *name, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Record a reach bound A + B radsum of a term that acts beyond contact. */
void pair_caps_reach(struct pair_caps *c, double a, double b);

/* Index of packed gran parameters (GRAN_*): kernels/param_layout.h, shared
 * with the kernels. */
#include "param_layout.h"

#endif
