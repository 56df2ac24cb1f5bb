/* pair_gran.c - LIGGGHTS's `pair_style gran model M tangential T [cohesion C]
 * [rolling_friction R] [surface default] [setting on|off ...]` with
 * `pair_coeff * *`: the contact models of LIGGGHTS 3.8 (evaluator
 * kernels/pair_gran.cl; docs doc/styles/pair_gran_model.md). The material
 * constants come from `fix property/global` (styles/fix/fix_property_global.h)
 * and are mixed at every run start into per-type-pair parameters (LG_*), as
 * LIGGGHTS's global_properties.cpp does:
 *   Y*  = 1 / ((1 - nu_i^2) / Y_i + (1 - nu_j^2) / Y_j)
 *   G*  = 1 / (2 (2 - nu_i)(1 + nu_i) / Y_i + 2 (2 - nu_j)(1 + nu_j) / Y_j)
 *   beta = ln e / sqrt(ln^2 e + pi^2)      (e = coefficientRestitution(i, j))
 * M: hertz (youngsModulus, poissonsRatio, coefficientRestitution), hooke
 * (those and characteristicVelocity), hertz/stiffness and hooke/stiffness
 * (kn, kt, gamman, gammat; with absolute_damping gamman_abs, gammat_abs);
 * T: history | no_history (coefficientFriction); C: sjkr | sjkr2
 * (cohesionEnergyDensity); R: cdt (coefficientRollingFriction), epsd and
 * epsd3 (that and coefficientRollingViscousDamping; epsd3 also the scalar
 * rollingStiffness), epsd2 (coefficientRollingFriction). Settings:
 * tangential_damping (on), limitForce (off), ktToKnUser (hooke, off),
 * absolute_damping (hooke/stiffness, off), torsionTorque (rolling, off).
 * hooke/hysteresis (those of hooke and coefficientMaxElasticStiffness,
 * coefficientAdhesionStiffness, coefficientPlasticityDepth; pairs only)
 * keeps the largest overlap in its history row, thornton_ning (hertz's
 * materials, surfaceEnergy per type pair, coefficientYieldRatio per type; no
 * rolling friction) its seven-REAL state, luding (LoadingStiffness,
 * UnloadingStiffness, coefficientAdhesionStiffness, coefficientPlasticityDepth,
 * pullOffForce, coefficientRestitution; limitForce on by default) the largest
 * overlap, the epsd models their spring
 * torque after the shear (PAIR_EVAL_ROW: [normal state] shear [torque]).
 * Not supported (clear errors): other surface models, the heating and
 * energy-tracking settings. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "collision_time.h"
#include "error.h"
#include "fix_heat_gran.h"
#include "fix_property_global.h"
#include "pair.h"
#include "pair_gran.h"

static const struct {
    const char *name;
    int nm;
} normal_models[] = {
    {"hertz", LG_N_HERTZ},
    {"hooke", LG_N_HOOKE},
    {"hertz/stiffness", LG_N_HERTZ_STIFFNESS},
    {"hooke/stiffness", LG_N_HOOKE_STIFFNESS},
    {"hooke/hysteresis", LG_N_HOOKE_HYSTERESIS},
    {"thornton_ning", LG_N_THORNTON_NING},
    {"luding", LG_N_LUDING},
};

static int in_list(const char *s, const char *const *list)
{
    for (; list && *list; list++)
        if (!strcmp(s, *list))
            return 1;
    return 0;
}

static int onoff(struct gravel *g, const char *s, const char *key, const char *who)
{
    if (!strcmp(s, "on") || !strcmp(s, "yes"))
        return 1;
    if (!strcmp(s, "off") || !strcmp(s, "no"))
        return 0;
    gr_error(g, "%s: expected on or off after '%s', got '%.64s'", who, key, s);
}

int lg_parse(struct gravel *g, struct lg_model *m, int argc, char **argv,
             const char *const *stop, const char *who)
{
    memset(m, 0, sizeof *m);
    m->nm = -1;
    m->tm = -1;
    m->tdamp = 1;
    int limit_given = 0;
    int i = 0;
    while (i < argc && !in_list(argv[i], stop)) {
        const char *kw = argv[i];
        if (i + 1 >= argc)
            gr_error(g, "%s: missing the value after '%s'", who, kw);
        const char *v = argv[i + 1];
        if (!strcmp(kw, "model")) {
            for (size_t k = 0; k < sizeof normal_models / sizeof *normal_models; k++)
                if (!strcmp(v, normal_models[k].name))
                    m->nm = normal_models[k].nm;
            if (m->nm < 0)
                gr_error(g, "%s: model '%.64s' is not supported (gravel has hertz, hooke, "
                            "hertz/stiffness, hooke/stiffness, hooke/hysteresis, "
                            "thornton_ning, luding)", who, v);
        } else if (!strcmp(kw, "tangential")) {
            if (!strcmp(v, "history"))
                m->tm = 1;
            else if (!strcmp(v, "no_history"))
                m->tm = 0;
            else
                gr_error(g, "%s: tangential model '%.64s' is not supported (history or "
                            "no_history)", who, v);
        } else if (!strcmp(kw, "cohesion")) {
            if (!strcmp(v, "sjkr"))
                m->coh = LG_C_SJKR;
            else if (!strcmp(v, "sjkr2"))
                m->coh = LG_C_SJKR2;
            else if (!strcmp(v, "off"))
                m->coh = LG_C_NONE;
            else
                gr_error(g, "%s: cohesion model '%.64s' is not supported (sjkr, sjkr2 or off)",
                         who, v);
        } else if (!strcmp(kw, "rolling_friction")) {
            static const char *const rolling[] = {"off", "cdt", "epsd", "epsd2", "epsd3"};
            m->roll = -1;
            for (int k = 0; k < 5; k++)
                if (!strcmp(v, rolling[k]))
                    m->roll = k; /* LG_R_NONE .. LG_R_EPSD3 */
            if (m->roll < 0)
                gr_error(g, "%s: rolling_friction model '%.64s' is not supported (cdt, epsd, "
                            "epsd2, epsd3 or off)", who, v);
        } else if (!strcmp(kw, "surface")) {
            if (strcmp(v, "default"))
                gr_error(g, "%s: surface model '%.64s' is not supported (default)", who, v);
        } else if (!strcmp(kw, "tangential_damping")) {
            m->tdamp = onoff(g, v, kw, who);
        } else if (!strcmp(kw, "limitForce")) {
            m->limit = onoff(g, v, kw, who);
            limit_given = 1;
        } else if (!strcmp(kw, "ktToKnUser")) {
            m->kttokn = onoff(g, v, kw, who);
        } else if (!strcmp(kw, "absolute_damping")) {
            m->absdamp = onoff(g, v, kw, who);
        } else if (!strcmp(kw, "torsionTorque")) {
            m->torsion = onoff(g, v, kw, who);
        } else if (!strcmp(kw, "viscous") || !strcmp(kw, "tangential_reduce") ||
                   !strncmp(kw, "heating", 7) || !strcmp(kw, "computeElasticPotential") ||
                   !strcmp(kw, "computeDissipatedEnergy") ||
                   !strcmp(kw, "disableNormalWhenBonded")) {
            if (onoff(g, v, kw, who))
                gr_error(g, "%s: setting '%s on' is not supported (only off)", who, kw);
        } else {
            gr_error(g, "%s: unknown keyword '%.64s'", who, kw);
        }
        i += 2;
    }
    if (m->nm < 0)
        gr_error(g, "%s: expected 'model hertz|hooke|hertz/stiffness|hooke/stiffness|"
                    "hooke/hysteresis|thornton_ning|luding'", who);
    if (m->nm == LG_N_LUDING && !limit_given)
        m->limit = 1; /* luding's limitForce is on by default (LIGGGHTS) */
    if (m->tm < 0)
        gr_error(g, "%s: expected 'tangential history|no_history' after the model", who);
    if (m->nm == LG_N_THORNTON_NING && m->roll != LG_R_NONE)
        gr_error(g, "%s: rolling_friction with model thornton_ning is not supported (LIGGGHTS "
                    "3.8's thornton_ning leaves the normal stiffness the rolling models read "
                    "unset)", who);
    return i;
}

void lg_to_coef(const struct lg_model *m, double *c)
{
    c[0] = m->nm;
    c[1] = m->tm;
    c[2] = m->coh;
    c[3] = m->roll;
    c[4] = m->tdamp | m->limit << 1 | m->kttokn << 2 | m->absdamp << 3 | m->torsion << 4;
}

void lg_from_coef(struct lg_model *m, const double *c)
{
    int f = (int)c[4];
    m->nm = (int)c[0];
    m->tm = (int)c[1];
    m->coh = (int)c[2];
    m->roll = (int)c[3];
    m->tdamp = f & 1;
    m->limit = f >> 1 & 1;
    m->kttokn = f >> 2 & 1;
    m->absdamp = f >> 3 & 1;
    m->torsion = f >> 4 & 1;
}

static int material_model(const struct lg_model *m)
{
    return m->nm == LG_N_HERTZ || m->nm == LG_N_HOOKE || m->nm == LG_N_HOOKE_HYSTERESIS ||
           m->nm == LG_N_THORNTON_NING;
}

/* hooke's stiffness from the characteristic velocity */
static int hooke_model(const struct lg_model *m)
{
    return m->nm == LG_N_HOOKE || m->nm == LG_N_HOOKE_HYSTERESIS;
}

static const char *const hysteresis_props[3] = {"coefficientMaxElasticStiffness",
                                                "coefficientAdhesionStiffness",
                                                "coefficientPlasticityDepth"};

/* LIGGGHTS's sanity limits on a Young's modulus (global_properties.cpp),
 * lifted by `soft_particles yes` and `hard_particles yes`; lj units have none. */
static void youngs_sanity(struct gravel *g, double Y)
{
    const int si = g->dom.units == UNITS_SI, cgs = g->dom.units == UNITS_CGS;
    if (!g->atoms.allow_soft && ((si && Y < 5e6) || (cgs && Y < 5e7)))
        gr_error(g, "youngsModulus >= %s required for %s units (use command 'soft_particles "
                    "yes' to override)", si ? "5e6" : "5e7", si ? "SI" : "CGS");
    if (!g->atoms.allow_hard && ((si && Y > 1e9) || (cgs && Y > 1e10)))
        gr_error(g, "youngsModulus <= %s required for %s units (use command 'hard_particles "
                    "yes' to override)", si ? "1e9" : "1e10", si ? "SI" : "CGS");
}

void lg_check(struct gravel *g, const struct lg_model *m, int nt, const char *who)
{
    if (material_model(m)) {
        const double *Y = fpg_pertype(g, "youngsModulus", nt, who);
        const double *nu = fpg_pertype(g, "poissonsRatio", nt, who);
        for (int t = 0; t < nt; t++) {
            if (!(Y[t] > 0) || !isfinite(Y[t]))
                gr_error(g, "%s: youngsModulus of type %d must be > 0, got %g", who, t + 1, Y[t]);
            youngs_sanity(g, Y[t]);
            if (!(nu[t] >= 0 && nu[t] <= 0.5))
                gr_error(g, "%s: 0 <= poissonsRatio <= 0.5 required (type %d: %g)", who, t + 1,
                         nu[t]);
        }
        for (int I = 1; I <= nt; I++)
            for (int J = 1; J <= nt; J++) {
                double e = fpg_pair(g, "coefficientRestitution", nt, I, J, who);
                if (!(e > 0.05 && e <= 1))
                    gr_error(g, "%s: 0.05 < coefficientRestitution <= 1 required (types %d %d: "
                                "%g)", who, I, J, e);
            }
        if (m->nm == LG_N_HOOKE_HYSTERESIS)
            for (int k = 0; k < 3; k++)
                for (int I = 1; I <= nt; I++)
                    for (int J = 1; J <= nt; J++) {
                        double v = fpg_pair(g, hysteresis_props[k], nt, I, J, who);
                        if ((k == 0 ? !(v > 1) : !(v >= 0)) || !isfinite(v))
                            gr_error(g, "%s: %s must be %s (types %d %d: %g)", who,
                                     hysteresis_props[k], k == 0 ? "> 1" : ">= 0", I, J, v);
                    }
        if (m->nm == LG_N_THORNTON_NING) {
            const double *yr = fpg_pertype(g, "coefficientYieldRatio", nt, who);
            for (int t = 0; t < nt; t++)
                if (!(yr[t] >= 0 && yr[t] <= 1))
                    gr_error(g, "%s: 0 <= coefficientYieldRatio <= 1 required (type %d: %g)",
                             who, t + 1, yr[t]);
            for (int I = 1; I <= nt; I++)
                for (int J = 1; J <= nt; J++) {
                    double v = fpg_pair(g, "surfaceEnergy", nt, I, J, who);
                    if (!(v >= 0) || !isfinite(v))
                        gr_error(g, "%s: surfaceEnergy must be >= 0 (types %d %d: %g)", who, I,
                                 J, v);
                }
        }
        if (hooke_model(m)) {
            double cv = fpg_scalar(g, "characteristicVelocity", who);
            if (!(cv > 0) || !isfinite(cv))
                gr_error(g, "%s: characteristicVelocity must be > 0, got %g", who, cv);
        }
    } else if (m->nm == LG_N_LUDING) {
        static const char *const names[] = {"LoadingStiffness", "UnloadingStiffness",
                                            "coefficientAdhesionStiffness",
                                            "coefficientPlasticityDepth", "pullOffForce",
                                            "coefficientRestitution"};
        for (int k = 0; k < 6; k++)
            for (int I = 1; I <= nt; I++)
                for (int J = 1; J <= nt; J++) {
                    double v = fpg_pair(g, names[k], nt, I, J, who);
                    /* UnloadingStiffness 1: (k2 + kc)/(k2 - kn) divides by 0 (LIGGGHTS
                     * goes NaN); the pull-off force may have either sign */
                    int ok = k == 0   ? v > 0
                             : k == 1 ? v > 1
                             : k == 4 ? 1
                             : k == 5 ? v > 0.05 && v <= 1
                                      : v >= 0;
                    if (!ok || !isfinite(v))
                        gr_error(g, "%s: %s must be %s (types %d %d: %g)", who, names[k],
                                 k == 0 ? "> 0" : k == 1 ? "> 1" : k == 4 ? "finite"
                                 : k == 5 ? "in (0.05, 1]" : ">= 0", I, J, v);
                }
    } else {
        const char *gn = m->absdamp && m->nm == LG_N_HOOKE_STIFFNESS ? "gamman_abs" : "gamman";
        const char *gt = m->absdamp && m->nm == LG_N_HOOKE_STIFFNESS ? "gammat_abs" : "gammat";
        const char *names[] = {"kn", "kt", gn, gt};
        for (int k = 0; k < 4; k++)
            for (int I = 1; I <= nt; I++)
                for (int J = 1; J <= nt; J++) {
                    double v = fpg_pair(g, names[k], nt, I, J, who);
                    if (!(v >= 0) || !isfinite(v))
                        gr_error(g, "%s: %s must be >= 0 (types %d %d: %g)", who, names[k], I,
                                 J, v);
                }
    }
    const int rvisc = m->roll == LG_R_EPSD || m->roll == LG_R_EPSD3;
    const char *pp[] = {"coefficientFriction", m->coh ? "cohesionEnergyDensity" : NULL,
                        m->roll ? "coefficientRollingFriction" : NULL,
                        rvisc ? "coefficientRollingViscousDamping" : NULL};
    for (int k = 0; k < 4; k++)
        if (pp[k])
            for (int I = 1; I <= nt; I++)
                for (int J = 1; J <= nt; J++) {
                    double v = fpg_pair(g, pp[k], nt, I, J, who);
                    if (!(v >= 0) || !isfinite(v))
                        gr_error(g, "%s: %s must be >= 0 (types %d %d: %g)", who, pp[k], I, J,
                                 v);
                }
    if (m->roll == LG_R_EPSD3) { /* LIGGGHTS: >= 1 in SI units */
        double k = fpg_scalar(g, "rollingStiffness", who);
        if (!(k >= 0) || !isfinite(k) || (g->dom.units == UNITS_SI && k < 1))
            gr_error(g, "%s: rollingStiffness must be >= 0 (>= 1 for SI units), got %g", who,
                     k);
    }
}

void lg_pack(struct gravel *g, const struct lg_model *m, int nt, int I, int J, int wall,
             double *q, const char *who)
{
    memset(q, 0, LG_NPARAM * sizeof *q);
    q[LG_NMODEL] = m->nm;
    if (material_model(m)) {
        const double *Y = fpg_pertype(g, "youngsModulus", nt, who);
        const double *nu = fpg_pertype(g, "poissonsRatio", nt, who);
        const double Yi = Y[I - 1], Yj = Y[J - 1], vi = nu[I - 1], vj = nu[J - 1];
        q[LG_YEFF] = 1. / ((1. - pow(vi, 2.)) / Yi + (1. - pow(vj, 2.)) / Yj);
        q[LG_GEFF] = 1. / (2. * (2. - vi) * (1. + vi) / Yi + 2. * (2. - vj) * (1. + vj) / Yj);
        const double l = log(fpg_pair(g, "coefficientRestitution", nt, I, J, who));
        q[LG_LOGE] = l;
        q[LG_BETA] = l / sqrt(pow(l, 2.) + pow(M_PI, 2.));
        if (hooke_model(m))
            q[LG_CHARV] = fpg_scalar(g, "characteristicVelocity", who);
        if (m->nm == LG_N_THORNTON_NING) {
            q[LG_GSURF] = fpg_pair(g, "surfaceEnergy", nt, I, J, who);
            q[LG_YRATIO] = fpg_pertype(g, "coefficientYieldRatio", nt, who)[I - 1];
        }
        if (m->nm == LG_N_HOOKE_HYSTERESIS) {
            q[LG_K2MAX] = fpg_pair(g, hysteresis_props[0], nt, I, J, who);
            q[LG_KC] = fpg_pair(g, hysteresis_props[1], nt, I, J, who);
            q[LG_PHIF] = fpg_pair(g, hysteresis_props[2], nt, I, J, who);
        }
    } else if (m->nm == LG_N_LUDING) {
        q[LG_KN] = fpg_pair(g, "LoadingStiffness", nt, I, J, who);
        q[LG_K2MAX] = fpg_pair(g, "UnloadingStiffness", nt, I, J, who);
        q[LG_KC] = fpg_pair(g, "coefficientAdhesionStiffness", nt, I, J, who);
        q[LG_PHIF] = fpg_pair(g, "coefficientPlasticityDepth", nt, I, J, who);
        q[LG_FADH] = fpg_pair(g, "pullOffForce", nt, I, J, who);
        q[LG_LOGE] = log(fpg_pair(g, "coefficientRestitution", nt, I, J, who));
    } else {
        const int abs = m->absdamp && m->nm == LG_N_HOOKE_STIFFNESS;
        q[LG_KN] = fpg_pair(g, "kn", nt, I, J, who);
        q[LG_KT] = fpg_pair(g, "kt", nt, I, J, who);
        q[LG_GN] = fpg_pair(g, abs ? "gamman_abs" : "gamman", nt, I, J, who);
        q[LG_GT] = fpg_pair(g, abs ? "gammat_abs" : "gammat", nt, I, J, who);
        q[LG_ABSDAMP] = abs;
    }
    q[LG_TDAMP] = m->tdamp;
    q[LG_LIMIT] = m->limit;
    q[LG_KTTOKN] = m->kttokn && m->nm == LG_N_HOOKE;
    q[LG_TMODEL] = m->tm;
    q[LG_MU] = fpg_pair(g, "coefficientFriction", nt, I, J, who);
    q[LG_COH] = m->coh;
    if (m->coh)
        q[LG_CED] = fpg_pair(g, "cohesionEnergyDensity", nt, I, J, who);
    q[LG_ROLL] = m->roll;
    if (m->roll)
        q[LG_RMU] = fpg_pair(g, "coefficientRollingFriction", nt, I, J, who);
    if (m->roll == LG_R_EPSD || m->roll == LG_R_EPSD3)
        q[LG_RVISC] = fpg_pair(g, "coefficientRollingViscousDamping", nt, I, J, who);
    q[LG_RSTIFF] = m->roll == LG_R_EPSD3 ? fpg_scalar(g, "rollingStiffness", who) : 2.25;
    q[LG_RINERTIA] = g->dom.dimension == 2 ? 1.5 : 1.4;
    q[LG_TORSION] = m->torsion;
    q[LG_WALL] = wall;
    if (!wall)  /* fix heat/gran's conduction; walls exchange no heat */
        q[LG_HEAT] = heat_gran_conduction(g, nt, I, J, &q[LG_HC], &q[LG_HAREA]);
}

/* thornton_ning's yield stress of a contact (kernels/pair_gran.cl
 * lg_thornton_ning), from the packed set q */
static double tn_yield_stress(const double *q, double ri, double reff)
{
    const double E = q[LG_YEFF], a = ri * q[LG_YRATIO];
    return 2. * E * a / (M_PI * reff) - sqrt(2. * q[LG_GSURF] * E / (M_PI * a));
}

void lg_check_yield(struct gravel *g, const struct lg_model *m, const double *table, int nt,
                    int jwall, const char *who)
{
    if (m->nm != LG_N_THORNTON_NING)
        return;
    const struct atoms *at = &g->atoms;
    double *rmin = gr_calloc(g, 2 * (size_t)nt, sizeof *rmin), *rmax = rmin + nt;
    for (int t = 0; t < nt; t++)
        rmin[t] = INFINITY;
    for (int i = 0; i < at->n; i++) {
        const int t = at->type[i] - 1;
        if (t >= 0 && t < nt) {
            rmin[t] = fmin(rmin[t], at->radius[i]);
            rmax[t] = fmax(rmax[t], at->radius[i]);
        }
    }
    const int wall = jwall != 0;
    for (int I = 1; I <= nt; I++)
        for (int J = jwall > 0 ? jwall : 1; J <= (jwall > 0 ? jwall : nt); J++) {
            const double ri = rmin[I - 1], rj = wall ? 0 : rmax[J - 1];
            if (!isfinite(ri) || (!wall && !(rj > 0)))
                continue; /* no atoms of a type */
            const double *q = table + ((size_t)(I - 1) * nt + (J - 1)) * LG_NPARAM;
            const double reff = wall ? ri : ri * rj / (ri + rj);
            const double ys = tn_yield_stress(q, ri, reff);
            if (!(ys > 0)) {
                free(rmin);
                gr_error(g, "%s: model thornton_ning: the yield stress of a type %d atom of "
                            "radius %g against %s %d%s is %g, not > 0 (2 Y* a_y / (pi reff) - "
                            "sqrt(2 surfaceEnergy Y* / (pi a_y)), a_y = radius x "
                            "coefficientYieldRatio): raise coefficientYieldRatio or lower "
                            "surfaceEnergy (LIGGGHTS: Invalid yield stress)", who, I, ri,
                         wall ? "a wall of type" : "type", J, wall ? "" : " (its largest)",
                         ys);
            }
        }
    free(rmin);
}

/* ---- the pair style ---- */

/* p->data: the packed table of the last init (nt x nt x LG_NPARAM) */
struct lg_table {
    int nt;
    double *q;
};

static void destroy(struct pair *p)
{
    struct lg_table *t = p->data;
    if (t)
        free(t->q);
    free(t);
    p->data = NULL;
}

static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    struct lg_model m;
    lg_parse(g, &m, argc, argv, NULL, "pair_style gran"); /* every word (no stop list) */
    lg_to_coef(&m, p->coef);
}

static void init(struct gravel *g, struct pair *p)
{
    struct lg_model m;
    lg_from_coef(&m, p->coef);
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    lg_check(g, &m, nt, "pair_style gran");
    destroy(p);
    struct lg_table *t = gr_calloc(g, 1, sizeof *t);
    p->data = t;
    t->nt = nt;
    t->q = gr_calloc(g, (size_t)nt * nt * LG_NPARAM, sizeof(double));
    for (int I = 1; I <= nt; I++)
        for (int J = 1; J <= nt; J++)
            lg_pack(g, &m, nt, I, J, 0, t->q + ((size_t)(I - 1) * nt + (J - 1)) * LG_NPARAM,
                    "pair_style gran");
    lg_check_yield(g, &m, t->q, nt, 0, "pair_style gran");
}

static void pack(const struct pair *p, int itype, int jtype, double *param)
{
    const struct lg_table *t = p->data;
    memcpy(param, t->q + ((size_t)(itype - 1) * t->nt + (jtype - 1)) * LG_NPARAM,
           LG_NPARAM * sizeof *param);
}

/* Run-start collision time of two equal spheres of type 1 (m* = m/2,
 * R* = r/2): Johnson's Hertz time for the hertz models, the linear spring's
 * half period for the hooke ones; INFINITY before the first init. */
static double collision_time(const struct pair *p, double m, double r, double vn)
{
    const struct lg_table *t = p->data;
    if (!t)
        return INFINITY;
    const double *q = t->q;
    double meff = 0.5 * m, reff = 0.5 * r;
    switch ((int)q[LG_NMODEL]) {
    case LG_N_HERTZ:
    case LG_N_THORNTON_NING: /* its Hertz loading */
        if (!(vn > 0))
            vn = 1e-3 * sqrt(q[LG_YEFF] / (m / (4.0 / 3.0 * M_PI * r * r * r)));
        return tcol_hertz(4.0 / 3.0 * q[LG_YEFF], reff, meff, vn);
    case LG_N_HERTZ_STIFFNESS:
        if (!(q[LG_KN] > 0))
            return INFINITY;
        if (!(vn > 0))
            vn = 1e-3 * sqrt(q[LG_KN] / (m / (4.0 / 3.0 * M_PI * r * r * r)));
        return tcol_hertz(q[LG_KN], reff, meff, vn);
    case LG_N_HOOKE:
    case LG_N_HOOKE_HYSTERESIS: {
        double sr = sqrt(reff), Y = q[LG_YEFF], cv = q[LG_CHARV];
        double kn = 16. / 15. * sr * Y * pow(15. * meff * cv * cv / (16. * sr * Y), 0.2);
        return tcol_linear(kn, 0, meff);
    }
    default:
        return q[LG_KN] > 0 ? tcol_linear(q[LG_KN], 0, meff) : INFINITY;
    }
}

static void describe(const struct pair *p, struct pair_caps *c)
{
    struct lg_model m;
    lg_from_coef(&m, p->coef);
    pair_caps_source(c, "pair_gran.cl");
    c->rotation = 1;
    const int nh = LG_NORMAL_HIST(m.nm), epsd = m.roll >= LG_R_EPSD;
    if (nh || epsd) { /* [the normal model's state] the shear [the spring torque] */
        c->eval_row = "gran_model_eval_row";
        c->history = 1;
        c->hist_n = nh + 3 + 3 * epsd;
    } else {
        c->eval = "gran_model_eval";
        c->history = m.tm;
    }
    /* LIGGGHTS resets a pair's history in surfacesClose only, which its
     * pair loop calls for rsq < contactDistanceFactor^2 radsum^2 past the
     * contact test: never with the factor 1 of spheres. A pair that
     * separates keeps its history (shear, hysteresis's largest overlap,
     * thornton_ning's state)
     * while it stays in the neighbor lists, and finds it on touching again
     * (doc/styles/pair_gran_model.md). */
    if (c->history)
        pair_caps_define(c, "PAIR_HIST_KEEP", "1");
    c->tcol_of = p;
    c->collision_time = collision_time;
}

const struct pair_style pair_style_gran = {
    .name = "gran",
    .nparam = LG_NPARAM,
    .settings = settings,
    .init = init,
    .destroy = destroy,
    .pack = pack,
    .describe = describe,
};
