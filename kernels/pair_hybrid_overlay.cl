/* pair_hybrid_overlay.cl - the fused evaluator of pair_style hybrid/overlay
 * (styles/pair/pair_hybrid_overlay.c): one neighbor loop (pair_loop.cl) calls
 * hybrid_overlay_eval, which calls each composed term in turn and sums forces
 * and torques. Build options (set by the host):
 *   PAIR_TERMS=n                 number of terms (1..4)
 *   PAIR_TERMk=<ident>_eval      the k-th evaluator
 *   PAIR_TERMk_OFF=o             its parameters start at param + o
 *   PAIR_TERMk_CONTACT=0|1       1: a contact law, called only while the
 *                                bodies touch (rsq < radsum^2); 0: gates
 *                                itself (cohesion, reaches beyond contact)
 *   PAIR_TERMk_HIST=0|1          1: owns the contact's shear history slot
 *                                (zeroed when the bodies do not touch)
 * At most one term owns history. Terms without history get a scratch slot.
 *
 * pair_style hybrid: hybrid_eval calls only the term whose index is
 * param[0] (the type pair's sub-style, -1 none); several terms may own the
 * history slot (a pair uses one), a term without history zeroes it. */

#ifdef PAIR_TERMS
#define HYBRID_TERM(EVAL, OFF, CONTACT, HIST)                                                  \
    if (!(CONTACT) || touch) {                                                                 \
        REAL3 scratch = (REAL3)(0);                                                            \
        EVAL(c, param + (OFF), (HIST) ? shear : &scratch, &term);                              \
        sum.f += term.f;                                                                       \
        sum.tc += term.tc;                                                                     \
        sum.tr += term.tr;                                                                     \
    } else if (HIST) {                                                                         \
        *shear = (REAL3)(0);                                                                   \
    }

static inline void hybrid_overlay_eval(const struct contact *c, __global const REAL *param,
                                       REAL3 *shear, struct contact_force *out)
{
    const int touch = c->rsq < c->radsum * c->radsum;
    struct contact_force sum, term;
    sum.f = sum.tc = sum.tr = (REAL3)(0);
    CONTACT_HEAT_ZERO(sum); /* no term conducts heat (pair granular is not a term) */
    HYBRID_TERM(PAIR_TERM0, PAIR_TERM0_OFF, PAIR_TERM0_CONTACT, PAIR_TERM0_HIST)
#if PAIR_TERMS > 1
    HYBRID_TERM(PAIR_TERM1, PAIR_TERM1_OFF, PAIR_TERM1_CONTACT, PAIR_TERM1_HIST)
#endif
#if PAIR_TERMS > 2
    HYBRID_TERM(PAIR_TERM2, PAIR_TERM2_OFF, PAIR_TERM2_CONTACT, PAIR_TERM2_HIST)
#endif
#if PAIR_TERMS > 3
    HYBRID_TERM(PAIR_TERM3, PAIR_TERM3_OFF, PAIR_TERM3_CONTACT, PAIR_TERM3_HIST)
#endif
    *out = sum;
}

/* collision time (kernels/accuracy.cl): the shortest of the terms' */
#define HYBRID_TCOL(EVAL, OFF)                                                                 \
    {                                                                                          \
        const REAL t_ = TCOL_OF(EVAL)(c, param + (OFF), vn);                                   \
        if (t_ > (REAL)0 && (tc == (REAL)0 || t_ < tc))                                        \
            tc = t_;                                                                           \
    }

static inline REAL hybrid_overlay_eval_tcol(const struct contact *c, __global const REAL *param,
                                            const REAL vn)
{
    REAL tc = 0;
    HYBRID_TCOL(PAIR_TERM0, PAIR_TERM0_OFF)
#if PAIR_TERMS > 1
    HYBRID_TCOL(PAIR_TERM1, PAIR_TERM1_OFF)
#endif
#if PAIR_TERMS > 2
    HYBRID_TCOL(PAIR_TERM2, PAIR_TERM2_OFF)
#endif
#if PAIR_TERMS > 3
    HYBRID_TCOL(PAIR_TERM3, PAIR_TERM3_OFF)
#endif
    return tc;
}

#define HYBRID_PICK(K, EVAL, OFF, CONTACT, HIST)                                               \
    if (sel == (K)) {                                                                          \
        if (!(CONTACT) || touch) {                                                             \
            REAL3 scratch = (REAL3)(0);                                                        \
            EVAL(c, param + (OFF), (HIST) ? shear : &scratch, out);                            \
            if (!(HIST))                                                                       \
                *shear = (REAL3)(0);                                                           \
            return;                                                                            \
        }                                                                                      \
    }

static inline void hybrid_eval(const struct contact *c, __global const REAL *param,
                               REAL3 *shear, struct contact_force *out)
{
    const int touch = c->rsq < c->radsum * c->radsum;
    const int sel = (int)param[0];
    HYBRID_PICK(0, PAIR_TERM0, PAIR_TERM0_OFF, PAIR_TERM0_CONTACT, PAIR_TERM0_HIST)
#if PAIR_TERMS > 1
    HYBRID_PICK(1, PAIR_TERM1, PAIR_TERM1_OFF, PAIR_TERM1_CONTACT, PAIR_TERM1_HIST)
#endif
#if PAIR_TERMS > 2
    HYBRID_PICK(2, PAIR_TERM2, PAIR_TERM2_OFF, PAIR_TERM2_CONTACT, PAIR_TERM2_HIST)
#endif
#if PAIR_TERMS > 3
    HYBRID_PICK(3, PAIR_TERM3, PAIR_TERM3_OFF, PAIR_TERM3_CONTACT, PAIR_TERM3_HIST)
#endif
    /* none, or a contact law while the bodies do not touch */
    out->f = out->tc = out->tr = (REAL3)(0);
    *shear = (REAL3)(0);
}

/* collision time of pair_style hybrid (kernels/accuracy.cl): the selected term's */
#define HYBRID_PICK_TCOL(K, EVAL, OFF)                                                         \
    if (sel == (K))                                                                            \
        return TCOL_OF(EVAL)(c, param + (OFF), vn);

static inline REAL hybrid_eval_tcol(const struct contact *c, __global const REAL *param,
                                    const REAL vn)
{
    const int sel = (int)param[0];
    HYBRID_PICK_TCOL(0, PAIR_TERM0, PAIR_TERM0_OFF)
#if PAIR_TERMS > 1
    HYBRID_PICK_TCOL(1, PAIR_TERM1, PAIR_TERM1_OFF)
#endif
#if PAIR_TERMS > 2
    HYBRID_PICK_TCOL(2, PAIR_TERM2, PAIR_TERM2_OFF)
#endif
#if PAIR_TERMS > 3
    HYBRID_PICK_TCOL(3, PAIR_TERM3, PAIR_TERM3_OFF)
#endif
    return 0; /* none */
}
#endif /* PAIR_TERMS */
