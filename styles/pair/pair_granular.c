/* pair_granular.c - `pair_style granular [cutoff]` with `pair_coeff I J
 * normal-model args [damping model] tangential model args [rolling sds ...]
 * [twisting marshall | sds ...] [limit_damping] [synchronized_verlet] [cutoff c]`: LAMMPS's
 * pair granular with its argument conversions and mixing, as today's LAMMPS
 * computes it (GranularModel, gran_sub_mod_*.cpp; tsuji's sqrt(2), per
 * sub-model mixing, the /static tangential models) and, with -compat
 * lammps2021 (o->c2021), as 29 Sep 2021's pair_granular.cpp did; the
 * evaluators are in kernels/pair_granular.cl.
 *
 * Coefficients as LAMMPS stores them: hertz/material, dmt, jkr keep
 * kn = 4/3 E* of the pair's own E, nu (E* = 1 / (2 (1 - nu^2) / E)); a NULL
 * Mindlin kt is 8 G* (G* = 1 / (4 (2 - nu)(1 + nu) / E)); damping tsuji turns
 * the restitution coefficient e into 1.2728 - 4.2783 e + 11.087 e^2 - 22.348 e^3
 * + 27.467 e^4 - 18.022 e^5 + 4.8218 e^6, times sqrt(2) (not with -compat
 * lammps2021). A type pair without its own pair_coeff mixes from I I and J J
 * at run start (which must use the same sub-models), as today's LAMMPS
 * (mix_today) or, -compat lammps2021, as LAMMPS 2021: kn geometric (hooke,
 * hertz) or 1 / ((1 - nu_I^2)/E_I + (1 - nu_J^2)/E_J) (material models: no
 * 4/3), every other coefficient geometric, the sub-models reset. LAMMPS
 * 2024's damping coeff_restitution takes e in the normal damping slot and
 * keeps damp = -2 ln e / sqrt(pi^2 + ln^2 e) (hooke) or -sqrt(3/2) 2
 * sqrt(5/6) ln e / sqrt(pi^2 + ln^2 e) (hertz, hertz/material; refused with
 * dmt, jkr), which the kernel multiplies by sqrt(m Fne / delta); two such
 * types mix as today's LAMMPS does (mix_today) even with -compat lammps2021.
 *
 * synchronized_verlet (today's LAMMPS): p[GR_SYNC], the half-step normal
 * in the kernel; refused with linear_nohistory (GranularModel::init) and
 * under -compat lammps2021; a mixed pair runs without it (mix_coeffs).
 *
 * mdr (today's LAMMPS GranSubModNormalMDR with damping mdr): read here, its
 * per-atom bookkeeping and normal force computed by fix granular/mdr
 * (styles/fix/fix_granular_mdr.c), which pair_coeff creates; the kernel
 * reads that force from the contact's history row (GR_H_MDR).
 *
 * The scene's kernel holds only the sub-models some type pair uses
 * (describe()): see the build options in kernels/pair_granular.cl. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "coeff_check.h"
#include "collision_time.h"
#include "command.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "pair.h"
#include "pair_granular.h"

struct gr_tab {
    int nt;
    struct gr_one *p;           /* nt x nt, both (I, J) and (J, I) */
    double dt;                  /* the run's time step (single(): synchronized_verlet) */
};

static const char *const nname[] = {"hooke", "hertz", "hertz/material", "dmt", "jkr"};
static const char *const dname[] = {"velocity", "mass_velocity", "viscoelastic", "tsuji",
                                    "coeff_restitution"};
static const char *const tname[] = {"linear_nohistory", "linear_history", "mindlin",
                                    "mindlin_rescale", "mindlin/force",
                                    "mindlin_rescale/force", "linear_history/static",
                                    "mindlin/static", "linear_history_classic",
                                    "mindlin_classic"};
#define GR_NTANG ((int)(sizeof tname / sizeof *tname))

/* a model LAMMPS 2021 lacks (damping coeff_restitution, the classic
 * tangential models): mixed as today's LAMMPS even with -compat lammps2021 */
static int after_2021(const struct gr_one *o)
{
    return o->dm == GR_D_COEFF_RESTITUTION || o->tm == GR_T_HISTORY_CLASSIC ||
           o->tm == GR_T_MINDLIN_CLASSIC || o->nm == GR_N_MDR;
}

/* the /static models: a static and a dynamic friction coefficient */
static int tang_static(int tm)
{
    return tm == GR_T_HISTORY_STATIC || tm == GR_T_MINDLIN_STATIC;
}

static void destroy(struct pair *p)
{
    struct gr_tab *t = p->data;
    if (t)
        free(t->p);
    free(t);
    p->data = NULL;
}

/* pair_style granular [cutoff] */
static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    if (argc > 1)
        gr_error(g, "pair_style granular takes at most one argument (a global cutoff), got %d",
                 argc);
    p->coef[0] = argc == 1 ? arg_positive(g, argv[0], "granular cutoff") : -1.0;
}

static struct gr_tab *tables(struct gravel *g, struct pair *p)
{
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    struct gr_tab *t = p->data;
    if (t && t->nt == nt)
        return t;
    destroy(p);
    t = gr_calloc(g, 1, sizeof *t);
    t->nt = nt;
    t->p = gr_calloc(g, (size_t)nt * nt, sizeof *t->p);
    p->data = t;
    return t;
}

static struct gr_one *at(const struct gr_tab *t, int i, int j)
{
    return &t->p[(size_t)(i - 1) * t->nt + (j - 1)];
}

/* LAMMPS mix_stiffnessE / mix_stiffnessG */
static double mixE(double Ei, double Ej, double ni, double nj)
{
    return 1 / ((1 - ni * ni) / Ei + (1 - nj * nj) / Ej);
}

static double mixG(double Ei, double Ej, double ni, double nj)
{
    return 1 / ((2 * (2 - ni) * (1 + ni) / Ei) + (2 * (2 - nj) * (1 + nj) / Ej));
}

static double num(struct gravel *g, char **argv, int argc, int i, const char *what,
                  const char *who)
{
    if (i >= argc)
        gr_error(g, "%s: missing %s", who, what);
    return arg_double(g, argv[i], what);
}

static int lookup(const char *s, const char *const *names, int n)
{
    for (int k = 0; k < n; k++)
        if (!strcmp(s, names[k]))
            return k;
    return -1;
}

static int in_list(const char *s, const char *const *list)
{
    for (int k = 0; list && list[k]; k++)
        if (!strcmp(s, list[k]))
            return 1;
    return 0;
}

double granular_tsuji(double e, int lammps2021)
{
    double d = 1.2728 - 4.2783 * e + 11.087 * e * e - 22.348 * e * e * e + 27.467 * pow(e, 4) -
               18.022 * pow(e, 5) + 4.8218 * pow(e, 6);
    return lammps2021 ? d : d * M_SQRT2;
}

/* LAMMPS's sub-model names gravel does not have: a clear refusal (`what`
 * names the category) instead of "unknown model". `none` is LAMMPS's
 * placeholder of an unset sub-model, which its GranularModel::init refuses
 * for the normal, damping and tangential models with this message. */
static void refuse_known(struct gravel *g, const char *who, const char *what, const char *s)
{
    /* epa_linear, epa_nonlinear: described by a development branch of LAMMPS's
     * documentation (Luding 2008; Thakur et al. 2014), in no LAMMPS source or
     * release stored here; the slash spellings of gravel's earlier notes too */
    static const char *const later[] = {"epa_linear", "epa_nonlinear", "epa/linear",
                                        "epa/nonlinear", NULL};
    if (!strcmp(s, "none"))
        gr_error(g, "%s: Must specify %s granular model (LAMMPS refuses '%s' for the normal, "
                    "damping and tangential models)", who, what, s);
    if (in_list(s, later))
        gr_error(g, "%s: %s model '%s' of LAMMPS's pair granular is not supported by gravel",
                 who, what, s);
}

/* `mdr E nu Y gamma psi_b eta_n0` (today's LAMMPS GranSubModNormalMDR; the
 * sixth value was a restitution coefficient before LAMMPS's February 2025
 * patch and is now the damping coefficient eta_n0 of `damping mdr`): read
 * into o and checked with LAMMPS's own messages (coeffs_to_local). Returns
 * the number of words taken. */
static int mdr_normal(struct gravel *g, struct gr_one *o, char **argv, int argc, int i,
                      const char *who)
{
    static const char *const what[] = {"Young's modulus E", "Poisson's ratio nu",
                                       "yield stress Y", "effective surface energy gamma",
                                       "critical confinement ratio psi_b",
                                       "damping coefficient eta_n0"};
    double c[6];
    for (int k = 0; k < 6; k++)
        c[k] = num(g, argv, argc, i + 1 + k, what[k], who);
    if (c[0] <= 0)
        gr_error(g, "%s: Illegal MDR normal model, Young's modulus must be greater than 0", who);
    if (c[1] < 0 || c[1] > 0.5)
        gr_error(g, "%s: Illegal MDR normal model, Poisson's ratio must be between 0 and 0.5",
                 who);
    if (c[2] < 0)
        gr_error(g, "%s: Illegal MDR normal model, yield stress must be greater than or equal "
                    "to 0", who);
    if (c[3] < 0)
        gr_error(g, "%s: Illegal MDR normal model, effective surface energy must be greater "
                    "than or equal to 0", who);
    if (c[4] < 0 || c[4] > 1)
        gr_error(g, "%s: Illegal MDR normal model, psi_b must be between 0 and 1.0", who);
    if (c[5] < 0)
        gr_error(g, "%s: Illegal MDR normal model, damping coefficent must be greater than or "
                    "equal to 0", who);
    o->nm = GR_N_MDR;
    o->E = c[0];
    o->nu = c[1];
    o->Y = c[2];
    o->gamma = c[3];
    o->psi_b = c[4];
    o->damp = c[5];
    return 7;
}

/* `damping mdr d_type` (GranSubModDampingMDR): LAMMPS truncates d_type to an
 * integer and takes 1 (eta_n0 sqrt(m_eff 2 E_eff a)) or 2 (eta_n0). Returns
 * the number of words taken. */
static int mdr_damping(struct gravel *g, struct gr_one *o, char **argv, int argc, int i,
                       const char *who)
{
    const double d = num(g, argv, argc, i + 2, "damping type (damping mdr)", who);
    if (!(fabs(d) < 1e9) || ((int)d != 1 && (int)d != 2))
        gr_error(g, "%s: Illegal MDR damping model, damping type must an integer equal to 1 or 2",
                 who);
    o->dm = GR_D_MDR;
    o->dtype = (int)d;
    return 3;
}

/* The mdr normal model and damping mdr go only together (the damping
 * models' init in LAMMPS). Walls: fix wall/gran/region takes mdr, fix
 * wall/gran refuses it (styles/fix/fix_wall_gran.c). */
static void mdr_pairing(struct gravel *g, const struct gr_one *o, const char *who)
{
    if (o->nm == GR_N_MDR && o->dm != GR_D_MDR)
        gr_error(g, "%s: Only damping mdr may be used with the mdr normal model", who);
    if (o->dm == GR_D_MDR && o->nm != GR_N_MDR)
        gr_error(g, "%s: Damping mdr can only be used with mdr normal model", who);
}

double granular_coeff_restitution(double e, int nm)
{
    const double l = log(e), root = sqrt(M_PI * M_PI + l * l);
    if (nm == GR_N_HOOKE)
        return -2 * l / root;
    /* sqrt(3/2) 2 sqrt(5/6): the Hertz stiffness dF/ddelta = 3/2 kn a */
    return -1.22474487139158894067 * 1.82574185835055380345 * l / root;
}

/* coeff_restitution: the restitution coefficient of o (its normal damping
 * slot, checked in (0, 1] by check_ranges) into the damping coefficient;
 * LAMMPS refuses it with a cohesive normal model (GranSubModDampingTsuji:
 * allow_cohesion = 0) */
static void coeff_restitution(struct gravel *g, struct gr_one *o, const char *who)
{
    if (o->nm == GR_N_DMT || o->nm == GR_N_JKR)
        gr_error(g, "%s: Cannot use coeff_restitution model with a cohesive normal model, %s",
                 who, nname[o->nm]);
    o->damp = granular_coeff_restitution(o->e, o->nm);
}

/* tsuji: today's LAMMPS refuses it with a cohesive normal model
 * (GranSubModDampingTsuji: allow_cohesion = 0; LAMMPS 2021 took it) */
static void tsuji(struct gravel *g, struct gr_one *o, const char *who)
{
    if (!o->c2021 && (o->nm == GR_N_DMT || o->nm == GR_N_JKR))
        gr_error(g, "%s: Cannot use tsuji model with a cohesive normal model, %s (LAMMPS "
                    "29Sep2021 took it: -compat lammps2021)", who, nname[o->nm]);
    o->damp = granular_tsuji(o->e, o->c2021);
}

/* The coefficients as given, before any conversion (coeff_check.h): every
 * stiffness, damping, friction and cohesion >= 0 as LAMMPS's sub-models ask;
 * the material models' E > 0 and Poisson's ratio in (-1, 0.5] (E* and G*
 * divide by E and 1 - nu^2); the damping slot holds a restitution
 * coefficient for tsuji ([0, 1]) and coeff_restitution ((0, 1], ln e). */
static void check_ranges(struct gravel *g, const struct gr_one *o, int kt_null,
                         const char *who)
{
    if (o->nm == GR_N_MDR) { /* checked with LAMMPS's words by mdr_normal */
    } else if (o->nm >= GR_N_HERTZ_MATERIAL) {
        coeff_check(g, who, "Young's modulus E", o->E, CR_POSITIVE);
        coeff_check(g, who, "Poisson's ratio", o->nu, CR_POISSON);
    } else {
        coeff_check(g, who, "normal stiffness kn", o->kn, CR_NONNEG);
    }
    if (o->dm == GR_D_TSUJI)
        coeff_check(g, who, "restitution coefficient e (damping tsuji)", o->damp, CR_UNIT);
    else if (o->dm == GR_D_COEFF_RESTITUTION)
        coeff_check(g, who, "restitution coefficient e (damping coeff_restitution)", o->damp,
                    CR_RESTITUTION);
    else if (o->dm != GR_D_MDR)
        coeff_check(g, who, "normal damping", o->damp, CR_NONNEG);
    if (o->nm == GR_N_DMT || o->nm == GR_N_JKR)
        coeff_check(g, who, o->nm == GR_N_JKR ? "surface energy" : "cohesion", o->coh,
                    CR_NONNEG);
    if (!kt_null)
        coeff_check(g, who, "tangential stiffness kt", o->kt, CR_NONNEG);
    coeff_check(g, who, "tangential damping", o->gt, CR_NONNEG);
    coeff_check(g, who, tang_static(o->tm) ? "static friction coefficient"
                                           : "friction coefficient", o->mu, CR_NONNEG);
    if (tang_static(o->tm))
        coeff_check(g, who, "dynamic friction coefficient", o->mud, CR_NONNEG);
    coeff_check(g, who, "rolling stiffness", o->kr, CR_NONNEG);
    coeff_check(g, who, "rolling damping", o->gr, CR_NONNEG);
    coeff_check(g, who, "rolling friction coefficient", o->mur, CR_NONNEG);
    coeff_check(g, who, "twisting stiffness", o->kw, CR_NONNEG);
    coeff_check(g, who, "twisting damping", o->gw, CR_NONNEG);
    coeff_check(g, who, "twisting friction coefficient", o->muw, CR_NONNEG);
}

int granular_parse(struct gravel *g, struct gr_one *po, int argc, char **argv,
                   const char *const *stop, int allow_cutoff, const char *who)
{
    struct gr_one o;
    memset(&o, 0, sizeof o);
    o.nm = o.tm = -1;
    o.dm = GR_D_VISCOELASTIC;
    o.rm = GR_R_NONE;
    o.wm = GR_W_NONE;
    o.cutoff = -1;
    o.c2021 = g->opt.lammps2021;
    int kt_null = 0;
    int i = 0;
    while (i < argc) {
        const char *k = argv[i];
        if (in_list(k, stop))
            break;
        int m = lookup(k, nname, 5);
        refuse_known(g, who, "normal", k);
        if (!strcmp(k, "mdr")) {
            i += mdr_normal(g, &o, argv, argc, i, who);
        } else if (m >= 0) {
            o.nm = m;
            o.kn = num(g, argv, argc, i + 1, m <= GR_N_HERTZ ? "normal stiffness kn" : "E", who);
            o.damp = num(g, argv, argc, i + 2, "normal damping", who);
            if (m >= GR_N_HERTZ_MATERIAL) {
                o.E = o.kn;
                o.nu = num(g, argv, argc, i + 3, "Poisson's ratio", who);
            }
            if (m >= GR_N_DMT)
                o.coh = num(g, argv, argc, i + 4, "cohesion (surface energy)", who);
            i += m <= GR_N_HERTZ ? 3 : m == GR_N_HERTZ_MATERIAL ? 4 : 5;
        } else if (!strcmp(k, "damping")) {
            arg_need(g, argc, i, 1, k);
            if (!strcmp(argv[i + 1], "mdr")) {
                i += mdr_damping(g, &o, argv, argc, i, who);
                continue;
            }
            o.dm = lookup(argv[i + 1], dname, 5);
            refuse_known(g, who, "damping", argv[i + 1]);
            if (o.dm < 0)
                gr_error(g, "%s: unknown damping model '%.64s' (expected velocity, "
                            "mass_velocity, viscoelastic, tsuji or coeff_restitution)", who,
                         argv[i + 1]);
            i += 2;
        } else if (!strcmp(k, "tangential")) {
            arg_need(g, argc, i, 1, k);
            o.tm = lookup(argv[i + 1], tname, GR_NTANG);
            refuse_known(g, who, "tangential", argv[i + 1]);
            if (o.tm < 0)
                gr_error(g, "%s: unknown tangential model '%.64s' (expected "
                            "linear_nohistory, linear_history, mindlin, mindlin_rescale, "
                            "mindlin/force, mindlin_rescale/force, linear_history/static, "
                            "mindlin/static, linear_history_classic or mindlin_classic)", who,
                         argv[i + 1]);
            if (o.tm == GR_T_NOHISTORY) {
                o.kt = 0;
                o.gt = num(g, argv, argc, i + 2, "tangential damping", who);
                o.mu = num(g, argv, argc, i + 3, "friction coefficient", who);
                i += 4;
                continue;
            }
            if (i + 2 < argc && !strcmp(argv[i + 2], "NULL") &&
                (o.tm == GR_T_HISTORY_CLASSIC || o.tm == GR_T_MINDLIN_CLASSIC))
                gr_error(g, "%s: Illegal linear tangential model: %s takes no NULL kt (LAMMPS "
                            "reads it as -1)", who, tname[o.tm]);
            if (i + 2 < argc && !strcmp(argv[i + 2], "NULL") && o.tm >= GR_T_MINDLIN &&
                o.tm != GR_T_HISTORY_STATIC) {
                if (o.nm == GR_N_HERTZ || o.nm == GR_N_HOOKE)
                    gr_error(g, "NULL setting for Mindlin tangential stiffness requires a "
                                "normal contact model that specifies material properties");
                kt_null = 1;
            } else {
                o.kt = num(g, argv, argc, i + 2, "tangential stiffness kt", who);
                kt_null = 0;
            }
            o.gt = num(g, argv, argc, i + 3, "tangential damping", who);
            if (tang_static(o.tm)) { /* kt xt mu_static mu_dynamic */
                o.mu = num(g, argv, argc, i + 4, "static friction coefficient", who);
                o.mud = num(g, argv, argc, i + 5, "dynamic friction coefficient", who);
                i += 6;
                continue;
            }
            o.mu = num(g, argv, argc, i + 4, "friction coefficient", who);
            i += 5;
        } else if (!strcmp(k, "rolling")) {
            arg_need(g, argc, i, 1, k);
            if (!strcmp(argv[i + 1], "none")) {
                o.rm = GR_R_NONE;
                i += 2;
            } else if (!strcmp(argv[i + 1], "sds")) {
                o.rm = GR_R_SDS;
                o.kr = num(g, argv, argc, i + 2, "rolling stiffness", who);
                o.gr = num(g, argv, argc, i + 3, "rolling damping", who);
                o.mur = num(g, argv, argc, i + 4, "rolling friction coefficient", who);
                i += 5;
            } else {
                gr_error(g, "%s: unknown rolling model '%.64s' (expected sds "
                            "or none)", who, argv[i + 1]);
            }
        } else if (!strcmp(k, "twisting")) {
            arg_need(g, argc, i, 1, k);
            if (!strcmp(argv[i + 1], "none")) {
                o.wm = GR_W_NONE;
                i += 2;
            } else if (!strcmp(argv[i + 1], "marshall")) {
                o.wm = GR_W_MARSHALL;
                i += 2;
            } else if (!strcmp(argv[i + 1], "sds")) {
                o.wm = GR_W_SDS;
                o.kw = num(g, argv, argc, i + 2, "twisting stiffness", who);
                o.gw = num(g, argv, argc, i + 3, "twisting damping", who);
                o.muw = num(g, argv, argc, i + 4, "twisting friction coefficient", who);
                i += 5;
            } else {
                gr_error(g, "%s: unknown twisting model '%.64s' (expected "
                            "marshall, sds or none)", who, argv[i + 1]);
            }
        } else if (!strcmp(k, "heat")) { /* LAMMPS 2023 GranSubModHeat* */
            arg_need(g, argc, i, 1, k);
            static const char *const hname[] = {"none", "area", "radius"};
            o.hm = lookup(argv[i + 1], hname, 3);
            if (o.hm < 0)
                gr_error(g, "%s: unknown heat model '%.64s' (expected none, area or radius)", who,
                         argv[i + 1]);
            if (o.hm == GR_H_NONE) {
                o.hk = 0;
                i += 2;
            } else {
                o.hk = coeff_check(g, who,
                                   o.hm == GR_H_AREA ? "heat transfer coefficient (heat area)"
                                                     : "conductivity (heat radius)",
                                   num(g, argv, argc, i + 2, "heat coefficient", who),
                                   CR_NONNEG);
                i += 3;
            }
        } else if (allow_cutoff && !strcmp(k, "cutoff")) {
            o.cutoff = coeff_check(g, who, "cutoff", num(g, argv, argc, i + 1, "cutoff", who),
                                   CR_POSITIVE);
            i += 2;
        } else if (!strcmp(k, "limit_damping")) {
            o.ld = 1;
            i++;
        } else if (!strcmp(k, "synchronized_verlet")) {
            if (o.c2021)
                gr_error(g, "%s: synchronized_verlet is not in LAMMPS 29Sep2021's pair "
                            "granular (-compat lammps2021)", who);
            o.sync = 1;
            i++;
        } else {
            gr_error(g, "%s: unknown keyword '%.64s' (expected a normal model "
                        "hooke, hertz, hertz/material, dmt or jkr, or damping, tangential, "
                        "rolling, twisting, heat, %slimit_damping or synchronized_verlet)",
                     who, k, allow_cutoff ? "cutoff, " : "");
        }
    }
    if (o.nm < 0 || o.tm < 0)
        gr_error(g, "%s: must specify normal or tangential contact model", who);
    mdr_pairing(g, &o, who);
    check_ranges(g, &o, kt_null, who);
    o.e = o.damp;
    if (o.dm == GR_D_TSUJI)
        tsuji(g, &o, who);
    if (o.dm == GR_D_COEFF_RESTITUTION)
        coeff_restitution(g, &o, who);
    if (tang_static(o.tm) && o.wm == GR_W_MARSHALL)
        gr_error(g, "%s: twisting marshall takes its friction from the tangential model, "
                    "which %s does not define (LAMMPS leaves it unset); use twisting sds",
                 who, tname[o.tm]);
    /* GranularModel::init: only the sub-models that project their history
     * twice may run synchronized (allow_synchronization; linear_nohistory
     * has no history to project) */
    if (o.sync && o.tm == GR_T_NOHISTORY)
        gr_error(g, "%s: Cannot use synchronized verlet with a non-synchronized tangential "
                    "model, %s", who, tname[o.tm]);
    if (o.ld && o.nm == GR_N_JKR)
        gr_error(g, "Illegal %.*s command, Cannot limit damping with JKR model",
                 (int)strcspn(who, " "), who);
    if (o.ld && o.nm == GR_N_DMT)
        gr_error(g, "Illegal %.*s command, Cannot limit damping with DMT model",
                 (int)strcspn(who, " "), who);
    if (o.nm >= GR_N_HERTZ_MATERIAL)
        o.kn = 4.0 / 3.0 * mixE(o.E, o.E, o.nu, o.nu);
    if (kt_null)
        o.kt = 8 * mixG(o.E, o.E, o.nu, o.nu);
    o.ktnull = kt_null;
    o.set = 1;
    *po = o;
    return i;
}

/* pair_coeff I J model args ... (LAMMPS's keywords, any order) */
static void coeff(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi,
                  int argc, char **argv)
{
    struct gr_one o;
    granular_parse(g, &o, argc, argv, NULL, 1, "pair_coeff granular");
    struct gr_tab *t = tables(g, p);
    for (int I = ilo; I <= ihi; I++)
        for (int J = jlo > I ? jlo : I; J <= jhi; J++)
            *at(t, I, J) = *at(t, J, I) = o;
    p->coeff_set = 1;
    /* mdr keeps per-atom state in fix granular/mdr: created as LAMMPS's
     * GranSubModNormalMDR::init creates it when there is none */
    if (o.nm == GR_N_MDR && !fix_find_style(g, "granular/mdr")) {
        char id[] = "MDR", grp[] = "all", st[] = "granular/mdr";
        char *fargv[] = {id, grp, st};
        cmd_fix(g, 3, fargv);
    }
}

static double geo(double a, double b) { return sqrt(a * b); }

/* LAMMPS pulloff_distance: the JKR overlap at pull-off (negative) */
static double pulloff(const struct gr_one *o, double reff)
{
    if (reff <= 0)
        return 0;
    double E = o->kn * 0.75;
    double a = cbrt(9 * M_PI * o->coh * reff * reff / (4 * E));
    return a * a / reff - 2 * sqrt(M_PI * o->coh * a / E);
}

/* Today's LAMMPS mixing (since the 2023 GranularModel; also every
 * pair of a model LAMMPS 2021 lacks: coeff_restitution, the classic tangential
 * models): GranularModel::
 * mix_coeffs, then init: every sub-model kept; the damping slot (e for tsuji
 * and coeff_restitution), nu, cohesion and every other coefficient
 * geometric; the material models' E* = 1 / ((1 - nu_I^2)/E_I + (1 -
 * nu_J^2)/E_J) and kn = 4/3 E*; a NULL Mindlin kt (on either side) 8 G* of
 * the mixed E* and nu; limit_damping if either has it; then e converted. */
static void mix_today(const struct gr_one *a, const struct gr_one *b, struct gr_one *m)
{
    if (a->nm >= GR_N_HERTZ_MATERIAL) {
        m->E = mixE(a->E, b->E, a->nu, b->nu);
        m->nu = geo(a->nu, b->nu);
        m->kn = 4.0 / 3.0 * m->E;
    } else {
        m->kn = geo(a->kn, b->kn);
    }
    m->e = geo(a->e, b->e);
    if (a->dm == GR_D_COEFF_RESTITUTION)
        m->damp = granular_coeff_restitution(m->e, m->nm);
    else if (a->dm == GR_D_TSUJI)
        m->damp = granular_tsuji(m->e, 0);
    else
        m->damp = m->e;
    m->coh = geo(a->coh, b->coh);
    m->mud = geo(a->mud, b->mud);
    m->ktnull = a->ktnull || b->ktnull;
    m->kt = m->ktnull ? 8 * mixG(m->E, m->E, m->nu, m->nu) : geo(a->kt, b->kt);
    m->gt = geo(a->gt, b->gt);
    m->mu = geo(a->mu, b->mu);
    m->kr = geo(a->kr, b->kr);
    m->gr = geo(a->gr, b->gr);
    m->mur = geo(a->mur, b->mur);
    m->kw = geo(a->kw, b->kw);
    m->gw = geo(a->gw, b->gw);
    m->muw = geo(a->muw, b->muw);
    m->ld = a->ld || b->ld;
    m->hk = geo(a->hk, b->hk);
    m->cutoff = -1;
    m->sync = 0; /* mix_coeffs carries limit_damping only: a mixed model runs unsynchronized */
}

/* Run start: mix unset pairs (LAMMPS init_one); the JKR reach. */
static void init(struct gravel *g, struct pair *p)
{
    struct gr_tab *t = p->data;
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    if (!t || t->nt != nt)
        gr_error(g, "pair style granular: pair_coeff must be given (after the box defines %d "
                    "atom type(s))", nt);
    t->dt = g->dt;
    for (int i = 1; i <= nt; i++)
        for (int j = i; j <= nt; j++) {
            struct gr_one *o = at(t, i, j);
            if (o->set == 1 || pair_type_absent(p, i) || pair_type_absent(p, j))
                continue; /* absent types (hybrid none): no particle has them */
            const struct gr_one *a = at(t, i, i), *b = at(t, j, j);
            if (a->set != 1 || b->set != 1)
                gr_error(g, "all pair coeffs are not set: pair granular needs pair_coeff %d %d "
                            "(or %d %d and %d %d to mix from)", i, j, i, i, j, j);
            if (a->nm != b->nm || a->dm != b->dm || a->tm != b->tm || a->rm != b->rm ||
                a->wm != b->wm || a->hm != b->hm)
                gr_error(g, "Granular pair style functional forms are different, cannot mix "
                            "coefficients for types %d and %d. This combination must be set "
                            "explicitly via a pair_coeff command", i, j);
            struct gr_one m = *a;
            m.set = 2;
            if (after_2021(a) || !a->c2021 || !b->c2021) {
                mix_today(a, b, &m);
                *at(t, i, j) = *at(t, j, i) = m;
                continue;
            }
            /* LAMMPS 2021 init_one tests and mixes with the sub-models of the
             * (I, J) entry, which it never sets: its freshly allocated tables
             * hold 0 there, i.e. hooke, velocity damping, linear_nohistory,
             * no rolling, no twisting, no limit_damping */
            m.nm = GR_N_HOOKE;
            m.dm = GR_D_VELOCITY;
            m.tm = GR_T_NOHISTORY;
            m.rm = GR_R_NONE;
            m.wm = GR_W_NONE;
            m.kn = geo(a->kn, b->kn);
            m.damp = geo(a->damp, b->damp);
            m.coh = geo(a->coh, b->coh);
            m.kt = geo(a->kt, b->kt);
            m.gt = geo(a->gt, b->gt);
            m.mu = geo(a->mu, b->mu);
            m.kr = geo(a->kr, b->kr);
            m.gr = geo(a->gr, b->gr);
            m.mur = geo(a->mur, b->mur);
            m.kw = geo(a->kw, b->kw);
            m.gw = geo(a->gw, b->gw);
            m.muw = geo(a->muw, b->muw);
            /* heat (LAMMPS 2023, GranularModel::mix_coeffs): the model kept, the
             * coefficient geometric; LAMMPS 2021 had none */
            m.hm = a->hm;
            m.hk = geo(a->hk, b->hk);
            /* LAMMPS keeps the I I limit_damping flag of whichever pair was set last; 0 */
            m.ld = 0;
            m.cutoff = -1;
            *at(t, i, j) = *at(t, j, i) = m;
        }
    for (int i = 1; i <= nt; i++)
        for (int j = i; j <= nt; j++)
            if (at(t, i, j)->set == 2 && (at(t, i, i)->sync || at(t, j, j)->sync))
                gr_warn(g, "pair granular: types %d %d mixed from %d %d and %d %d run without "
                           "synchronized_verlet, as LAMMPS's GranularModel::mix_coeffs leaves "
                           "it (give pair_coeff %d %d ... synchronized_verlet to have it)",
                        i, j, i, i, j, j, i, j);
            else if (at(t, i, j)->set == 2 && at(t, i, j)->c2021 &&
                     !after_2021(at(t, i, j)))
                gr_warn(g, "pair granular: types %d %d mixed as LAMMPS 29Sep2021 does: hooke, "
                           "velocity damping and linear_nohistory with the geometric means of "
                           "the %d %d and %d %d coefficients (give pair_coeff %d %d for other "
                           "sub-models)", i, j, i, i, j, j, i, j);
    /* heat conduction needs both per-atom properties (LAMMPS init_style) */
    for (int i = 1; i <= nt; i++)
        for (int j = i; j <= nt; j++)
            if (at(t, i, j)->hm != GR_H_NONE) {
                if (!(g->atoms.heat_flag & ATOM_HEAT_T))
                    gr_error(g, "Heat conduction in pair granular requires atom style with "
                                "temperature property (fix property/atom temperature heatflow)");
                if (!(g->atoms.heat_flag & ATOM_HEAT_Q))
                    gr_error(g, "Heat conduction in pair granular requires atom style with "
                                "heatflow property (fix property/atom temperature heatflow)");
            }
    /* LAMMPS 2021 builds its list to r_i + r_j + skin: a jkr contact stretched
     * beyond the skin is lost at the next rebuild, before its pull-off */
    double rmax = 0, poff = 0;
    for (int k = 0; k < g->atoms.n; k++)
        rmax = fmax(rmax, g->atoms.radius[k]);
    for (int i = 1; i <= nt; i++)
        for (int j = 1; j <= nt; j++)
            if (at(t, i, j)->nm == GR_N_JKR)
                poff = fmax(poff, -pulloff(at(t, i, j), 0.5 * rmax));
    if (poff > g->neigh.skin)
        gr_warn(g, "pair granular: the jkr pull-off distance (up to %g) exceeds the neighbor "
                   "skin %g: as in LAMMPS 2021, a contact stretched beyond the skin is lost "
                   "at the next neighbor rebuild (a larger skin lets it reach its pull-off)",
                poff, g->neigh.skin);
}

static void pack(const struct pair *p, int itype, int jtype, double *q)
{
    granular_pack(at(p->data, itype, jtype), q);
}

void granular_pack(const struct gr_one *o, double *q)
{
    q[GR_NMODEL] = o->nm;
    q[GR_DMODEL] = o->dm;
    q[GR_TMODEL] = o->tm;
    q[GR_RMODEL] = o->rm;
    q[GR_WMODEL] = o->wm;
    q[GR_LIMIT] = o->ld;
    q[GR_KN] = o->kn;
    q[GR_DAMP] = o->damp;
    q[GR_COH] = o->coh;
    q[GR_KT] = o->kt;
    q[GR_GT] = o->gt;
    q[GR_MU] = o->mu;
    q[GR_KR] = o->kr;
    q[GR_GR] = o->gr;
    q[GR_MUR] = o->mur;
    q[GR_KW] = o->kw;
    q[GR_GW] = o->gw;
    q[GR_MUW] = o->muw;
    q[GR_MUD] = o->mud;
    q[GR_2021] = o->c2021;
    q[GR_HMODEL] = o->hm;
    q[GR_HK] = o->hk;
    q[GR_SYNC] = o->sync;
    q[GR_MDR_DTYPE] = o->dtype;
}

/* What the scene uses: bit masks per category and the history layout. */
struct gr_use {
    int n, d, t, r, w;
    int tang_hist, rescale;
    int sync;                   /* some pair has synchronized_verlet */
    int h_a, h_roll, h_twist, h_touch, h_dyn, h_mdr, width;
};

static struct gr_use uses(const struct pair *p)
{
    struct gr_use u;
    memset(&u, 0, sizeof u);
    const struct gr_tab *t = p->data;
    for (int i = 1; t && i <= t->nt; i++)
        for (int j = 1; j <= t->nt; j++) {
            const struct gr_one *o = at(t, i, j);
            if (!o->set)
                continue;
            u.n |= 1 << o->nm;
            u.d |= 1 << o->dm;
            u.t |= 1 << o->tm;
            u.r |= 1 << o->rm;
            u.w |= 1 << o->wm;
            u.sync |= o->sync;
        }
    u.tang_hist = (u.t & ~(1 << GR_T_NOHISTORY)) != 0;
    u.rescale = (u.t & (1 << GR_T_MINDLIN_RESCALE | 1 << GR_T_MINDLIN_RESCALE_FORCE)) != 0;
    int off = u.tang_hist ? 3 : 0;
    u.h_a = u.rescale ? off++ : -1;
    u.h_roll = (u.r >> GR_R_SDS) & 1 ? (off += 3) - 3 : -1;
    u.h_twist = u.w & ~(1 << GR_W_NONE) ? off++ : -1;
    u.h_touch = (u.n >> GR_N_JKR) & 1 ? off++ : -1;
    u.h_dyn = u.t & (1 << GR_T_HISTORY_STATIC | 1 << GR_T_MINDLIN_STATIC) ? off++ : -1;
    u.h_mdr = (u.n >> GR_N_MDR) & 1 ? (off += MH_N) - MH_N : -1;
    u.width = off;
    return u;
}

/* LAMMPS 2021 init_one: r_i + r_j plus the (negative) JKR pull-off overlap,
 * or the pair's cutoff, or the style's global one */
static double lammps2021_cut(const struct pair *p, int i, int j, double ri, double rj)
{
    const struct gr_one *o = at(p->data, i, j);
    if (o->cutoff >= 0)
        return o->cutoff;
    if (p->coef[0] >= 0)
        return p->coef[0];
    double c = ri + rj;
    if (o->nm == GR_N_JKR && ri + rj > 0)
        c += pulloff(o, ri * rj / (ri + rj));
    return c;
}

/* LAMMPS 2021 PairGranular::single, normal part (plus LAMMPS 2024's
 * coeff_restitution damping): fforce = Fntot / r with Fntot = Fne - damp
 * factor v_n (limit_damping: >= 0), 0 beyond touch (jkr: beyond the
 * pull-off distance); with synchronized_verlet v_n on the half-step normal,
 * as today's single() runs calculate_forces. No energy. */
static double granular_single(const struct pair *p, const struct pair_single *s,
                              double *fforce)
{
    const struct gr_one *o = at(p->data, s->itype, s->jtype);
    if (!o->set) { /* a cross pair before the first run mixed it */
        *fforce = NAN;
        return NAN;
    }
    double radsum = s->radi + s->radj;
    double Reff = radsum > 0 ? s->radi * s->radj / radsum : 0.0;
    double E = o->kn;
    int touch;
    *fforce = 0.0;
    if (o->nm == GR_N_JKR) {
        E *= 0.75;
        double a0 = cbrt(9.0 * M_PI * o->coh * Reff * Reff / (4 * E));
        double dist = radsum + a0 * a0 / Reff - 2 * sqrt(M_PI * o->coh * a0 / E);
        touch = s->rsq <= dist * dist;
    } else {
        touch = s->rsq <= radsum * radsum;
    }
    if (!touch)
        return 0.0;
    double r = sqrt(s->rsq), rinv = 1.0 / r;
    double vnnr = 0;
    if (o->sync) { /* the normal rate on the half-step normal (kernels/pair_granular.cl) */
        const double h = 0.5 * ((const struct gr_tab *)p->data)->dt;
        double d[3], vr[3];
        for (int k = 0; k < 3; k++) {
            vr[k] = s->vi[k] - s->vj[k];
            d[k] = s->del[k] - h * vr[k];
        }
        const double inv = 1.0 / sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        vnnr = vr[0] * (d[0] * inv) + vr[1] * (d[1] * inv) + vr[2] * (d[2] * inv);
    } else {
        for (int d = 0; d < 3; d++)
            vnnr += (s->vi[d] - s->vj[d]) * s->del[d] * rinv;
    }
    if (o->nm == GR_N_MDR) { /* the step's force and area, which fix granular/mdr stored:
                              * the positions have not moved since (LAMMPS recomputes them
                              * without history update, to the same values) */
        const double *h = s->hist ? s->hist + uses(p).h_mdr : NULL;
        if (!h)
            return 0.0;
        const double sc = h[MH_DAMP_SCALE];
        const double dp = o->dtype == 1 ? o->damp * sc : (sc == 0.0 ? 0.0 : o->damp);
        double Fntot = h[MH_FN] - dp * vnnr;
        if (o->ld && Fntot < 0.0)
            Fntot = 0.0;
        *fforce = Fntot * rinv;
        if (s->sv)
            s->sv[12] = h[MH_AC_AVG];
        return 0.0;
    }
    double meff = s->mi * s->mj / (s->mi + s->mj);
    if (s->frozen_i)
        meff = s->mj;
    if (s->frozen_j)
        meff = s->mi;
    double delta = radsum - r, dR = delta * Reff, a, knfac, Fne;
    if (o->nm == GR_N_JKR) {
        double R2 = Reff * Reff, dR2 = dR * dR, coh = o->coh;
        double t0 = coh * coh * R2 * R2 * E, t1 = 27.0 * M_PI * M_PI * t0;
        double t2 = 8 * dR * dR2 * E * E * E, t3 = 4 * dR2 * E;
        double t4 = cbrt(t1 + t2 + 3.0 * sqrt(3.0) * M_PI * sqrt(fmax(0, t0 * (t1 + 2 * t2))));
        double t5 = t3 / t4 + t4 / E, t6 = sqrt(fmax(0, 2 * dR + t5));
        a = (t6 + sqrt(fmax(0, 4 * dR - t5 + 6.0 * sqrt(6.0) * coh * M_PI * R2 / (E * t6)))) /
            sqrt(6.0);
        double a2 = a * a;
        knfac = o->kn * a;
        Fne = knfac * a2 / Reff - 2 * M_PI * a2 * sqrt(4 * coh * E / (M_PI * a));
    } else {
        knfac = E;
        Fne = knfac * delta;
        a = sqrt(dR);
        if (o->nm != GR_N_HOOKE) {
            Fne *= a;
            knfac *= a;
        }
        if (o->nm == GR_N_DMT)
            Fne -= 4 * M_PI * o->coh * Reff;
    }
    double damp;
    switch (o->dm) {
    case GR_D_VELOCITY: damp = 1; break;
    case GR_D_MASS_VELOCITY: damp = meff; break;
    case GR_D_VISCOELASTIC: damp = a * meff; break;
    case GR_D_TSUJI: damp = sqrt(meff * knfac); break;
    case GR_D_COEFF_RESTITUTION:
        damp = delta > 0 ? sqrt(fmax(0, meff * Fne / delta)) : 0;
        break;
    default: damp = 0; break;
    }
    double Fntot = Fne - o->damp * damp * vnnr;
    if (o->ld && Fntot < 0.0)
        Fntot = 0.0;
    *fforce = Fntot * rinv;
    return 0.0;
}

/* Collision time of one type pair's model for two equal spheres (m* = m/2,
 * R* = r/2) at normal speed vn, undamped (damping lengthens a collision, so
 * this is the bound a time step must resolve), the formulas of
 * kernels/collision_time.h the kernel's granular_tcol uses: hooke, the
 * linear spring's half period; hertz, hertz/material, dmt and jkr, Johnson's
 * Hertz time of kn = 4/3 E* (JKR's elastic part; DMT's cohesion adds a
 * constant force). vn <= 0: the impact speed 1e-3 sqrt(E* / rho). 0: none. */
static double model_tcol(const struct gr_one *o, double m, double r, double vn)
{
    if (!(o->kn > 0))
        return 0;
    if (o->nm == GR_N_HOOKE)
        return tcol_linear(o->kn, 0, 0.5 * m);
    if (!(vn > 0))
        vn = 1e-3 * sqrt(0.75 * o->kn / (m / (4.0 / 3.0 * M_PI * r * r * r)));
    return tcol_hertz(o->kn, 0.5 * r, 0.5 * m, vn);
}

/* pair.h's collision time: the shortest of the type pairs' (every pair's
 * model may act between two spheres of this size); INFINITY when none has
 * one (kn = 0) */
static double collision_time(const struct pair *p, double m, double r, double vn)
{
    const struct gr_tab *t = p->data;
    double best = INFINITY;
    for (int i = 1; t && i <= t->nt; i++)
        for (int j = i; j <= t->nt; j++) {
            const struct gr_one *o = at(t, i, j);
            double tc = o->set ? model_tcol(o, m, r, vn) : 0;
            if (tc > 0 && tc < best)
                best = tc;
        }
    return best;
}

/* The sub-models the type pairs use decide the program (the GR*_USED
 * masks, see kernels/pair_granular.cl) and the history row's layout; JKR
 * pairs hold beyond touch, within the list of r_i + r_j + skin (LAMMPS 2021:
 * no reach beyond touch). Rolling and twisting history are adjacent (uses()):
 * the slots LAMMPS 2021 negates at an owner change. */
static void describe(const struct pair *p, struct pair_caps *c)
{
    struct gr_use u = uses(p);
    pair_caps_source(c, "gran_heat.cl");
    pair_caps_source(c, "pair_granular.cl");
    c->eval_row = "granular_eval";
    c->rotation = 1;
    c->history = u.width > 0;
    c->hist_n = u.width > 0 ? u.width : 3;
    c->flip_lo = u.h_roll >= 0 ? u.h_roll : u.h_twist;
    c->flip_n = (u.h_roll >= 0 ? 3 : 0) + (u.h_twist >= 0 ? 1 : 0);
    c->lammps2021_cut = lammps2021_cut;
    c->cut2021_of = p;
    c->single = granular_single;
    c->single_of = p;
    if (u.h_mdr >= 0) { /* LAMMPS's 12 granular values, then the mdr model's contact area */
        c->single_extra = 13;
        c->single_hist = 1;
    }
    c->tcol_of = p;
    c->collision_time = collision_time;
    if ((u.n >> GR_N_JKR) & 1) {
        c->beyond = 1;
        pair_caps_reach(c, 0.0, 1.0);
    }
    pair_caps_define(c, "GRN_USED", "%d", u.n);
    pair_caps_define(c, "GRD_USED", "%d", u.d);
    pair_caps_define(c, "GRT_USED", "%d", u.t);
    pair_caps_define(c, "GRR_USED", "%d", u.r);
    pair_caps_define(c, "GRW_USED", "%d", u.w);
    if ((u.n >> GR_N_JKR) & 1) {
        pair_caps_define(c, "GRN_HAS_JKR", NULL);
        pair_caps_define(c, "GR_H_TOUCH", "%d", u.h_touch);
    }
    if ((u.n >> GR_N_DMT) & 1)
        pair_caps_define(c, "GRN_HAS_DMT", NULL);
    if (u.tang_hist)
        pair_caps_define(c, "GR_TANG_HISTORY", NULL);
    if (u.h_a >= 0)
        pair_caps_define(c, "GR_H_A", "%d", u.h_a);
    if (u.h_roll >= 0)
        pair_caps_define(c, "GR_H_ROLL", "%d", u.h_roll);
    if (u.h_twist >= 0)
        pair_caps_define(c, "GR_H_TWIST", "%d", u.h_twist);
    if (u.h_dyn >= 0)
        pair_caps_define(c, "GR_H_DYN", "%d", u.h_dyn);
    if (u.h_mdr >= 0)
        pair_caps_define(c, "GR_H_MDR", "%d", u.h_mdr);
    if (u.sync)
        pair_caps_define(c, "GR_SYNC_USED", NULL);
}

int granular_mdr_model(struct gravel *g, const struct pair *p, double mat[7])
{
    const struct gr_tab *t = p->data;
    const struct gr_one *m = NULL;
    int other = 0;
    for (int i = 1; t && i <= t->nt; i++)
        for (int j = 1; j <= t->nt; j++) {
            const struct gr_one *o = at(t, i, j);
            if (!o->set)
                continue;
            if (o->nm != GR_N_MDR) {
                other = 1;
                continue;
            }
            if (m && (m->E != o->E || m->nu != o->nu || m->Y != o->Y ||
                      m->gamma != o->gamma || m->psi_b != o->psi_b || m->e != o->e ||
                      m->dtype != o->dtype))
                gr_error(g, "fix granular/mdr: Cannot currently define multiple MDR normal "
                            "models in the pairstyle (types %d %d differ)", i, j);
            m = o;
        }
    if (!m)
        return -1;
    if (other)
        gr_error(g, "fix granular/mdr: Cannot combine MDR normal model with a different normal "
                    "model in the pairstyle");
    mat[0] = m->E;
    mat[1] = m->nu;
    mat[2] = m->Y;
    mat[3] = m->gamma;
    mat[4] = m->psi_b;
    mat[5] = m->damp;
    mat[6] = m->dtype;
    return uses(p).h_mdr;
}

const struct pair_style pair_style_granular = {
    .name = "granular",
    .nparam = GR_NPARAM,
    .settings = settings,
    .pack = pack,
    .coeff = coeff,
    .init = init,
    .describe = describe,
    .destroy = destroy,
};
