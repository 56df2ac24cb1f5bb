/* pair_gran_common.c - arguments and parameter packing shared by the three
 * LAMMPS granular pair styles (gran/hooke, gran/hooke/history,
 * gran/hertz/history), with LAMMPS 2021 semantics (pair_gran_hooke_history.cpp
 * settings()): Kn Kt gamman gammat xmu dampflag [limit_damping];
 * Kt NULL -> 2/7 Kn, gammat NULL -> gamman / 2, dampflag 0 -> gammat = 0. */
#include <math.h>
#include <string.h>

#include "args.h"
#include "coeff_check.h"
#include "collision_time.h"
#include "error.h"
#include "pair_gran_common.h"

enum { C_KN, C_KT, C_GAMMAN, C_GAMMAT, C_XMU, C_DAMPFLAG, C_LIMIT };

void pair_gran_settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    const char *name = p->style->name;
    if (argc != 6 && argc != 7)
        gr_error(g, "pair_style %s expects Kn Kt gamman gammat xmu dampflag [limit_damping], "
                    "got %d argument(s)", name, argc);
    double kn = coeff_arg(g, NULL, argv[0], "Kn", CR_NONNEG);
    double kt = !strcmp(argv[1], "NULL") ? kn * 2.0 / 7.0
                                          : coeff_arg(g, NULL, argv[1], "Kt", CR_NONNEG);
    double gamman = coeff_arg(g, NULL, argv[2], "gamma_n", CR_NONNEG);
    double gammat = !strcmp(argv[3], "NULL") ? 0.5 * gamman
                                             : coeff_arg(g, NULL, argv[3], "gamma_t", CR_NONNEG);
    double xmu = coeff_upto(g, NULL, "xmu", arg_double(g, argv[4], "xmu"), 10000.0);
    int dampflag = arg_int_range(g, argv[5], 0, 1, "dampflag");
    if (dampflag == 0)
        gammat = 0.0;
    int limit = 0;
    if (argc == 7) {
        if (strcmp(argv[6], "limit_damping"))
            gr_error(g, "unknown pair_style %s keyword '%.64s' (expected limit_damping)", name,
                     argv[6]);
        limit = 1;
    }
    p->coef[C_KN] = kn;
    p->coef[C_KT] = kt;
    p->coef[C_GAMMAN] = gamman;
    p->coef[C_GAMMAT] = gammat;
    p->coef[C_XMU] = xmu;
    p->coef[C_DAMPFLAG] = dampflag;
    p->coef[C_LIMIT] = limit;
}

void pair_gran_pack(const struct pair *p, int itype, int jtype, double *param)
{
    (void)itype;
    (void)jtype;
    param[GRAN_KN] = p->coef[C_KN];
    param[GRAN_KT] = p->coef[C_KT];
    param[GRAN_GAMMAN] = p->coef[C_GAMMAN];
    param[GRAN_GAMMAT] = p->coef[C_GAMMAT];
    param[GRAN_XMU] = p->coef[C_XMU];
    param[GRAN_LIMIT] = p->coef[C_LIMIT];
}

/* gamman = 0 and xmu = 0: the normal spring alone (any tangential force is
 * capped at xmu F_n) */
static int pair_gran_conservative(const struct pair *p)
{
    return p->coef[C_GAMMAN] == 0.0 && p->coef[C_XMU] == 0.0;
}

/* Elastic energy of a contact: hooke F = kn delta, hertz F = kn sqrt(R*) delta^1.5 */
static double pair_gran_contact_energy(const struct pair *p, double delta, double reff)
{
    if (!strcmp(p->style->name, "gran/hertz/history"))
        return 0.4 * p->coef[C_KN] * sqrt(reff) * delta * delta * sqrt(delta);
    return 0.5 * p->coef[C_KN] * delta * delta;
}

/* Run-start collision time of two equal spheres (m* = m/2, R* = r/2), the
 * laws' formulas of kernels/collision_time.h: hooke, the damped linear
 * oscillator; hertz, the same at the secant stiffness of an undamped impact
 * at vn. INFINITY when overdamped. */
static double collision_time(const struct pair *p, double m, double r, double vn)
{
    double meff = 0.5 * m, kn = p->coef[C_KN], gn = p->coef[C_GAMMAN], t;
    if (!strcmp(p->style->name, "gran/hertz/history")) {
        if (vn <= 0)
            vn = 1e-3 * sqrt(kn * r * r / m);
        t = tcol_hertz_secant(kn, gn, 0.5 * r, meff, vn);
    } else {
        t = tcol_linear(kn, gn, meff);
    }
    return t > 0 ? t : INFINITY;
}

/* LAMMPS 2021 PairGranHookeHistory::single / PairGranHertzHistory::single:
 * fforce = kn (radsum - r) / r - meff gamman vn.del / r^2, times
 * sqrt(delta R*) for hertz, clipped at 0 with limit_damping; no energy.
 * With s->sv (history styles): LAMMPS's 10 extra values, the tangential
 * force from the stored history, -(kt shear + meff gammat vtr) (hertz: times
 * sqrt(delta R*)) capped at xmu |F_n| (fs1 fs2 fs3 fs), then vn and vt. */
static double pair_gran_single(const struct pair *p, const struct pair_single *s,
                               double *fforce)
{
    double radsum = s->radi + s->radj;
    *fforce = 0.0;
    if (s->rsq >= radsum * radsum)
        return 0.0;
    double r = sqrt(s->rsq), rinv = 1.0 / r, rsqinv = 1.0 / s->rsq;
    double vnnr = (s->vi[0] - s->vj[0]) * s->del[0] + (s->vi[1] - s->vj[1]) * s->del[1] +
                  (s->vi[2] - s->vj[2]) * s->del[2];
    double meff = s->mi * s->mj / (s->mi + s->mj);
    if (s->frozen_i)
        meff = s->mj;
    if (s->frozen_j)
        meff = s->mi;
    double damp = meff * p->coef[C_GAMMAN] * vnnr * rsqinv;
    double ccel = p->coef[C_KN] * (radsum - r) * rinv - damp;
    if (!strcmp(p->style->name, "gran/hertz/history"))
        ccel *= sqrt((radsum - r) * s->radi * s->radj / radsum);
    if (p->coef[C_LIMIT] != 0.0 && ccel < 0.0)
        ccel = 0.0;
    *fforce = ccel;
    if (s->sv) {
        const double *d = s->del;
        double vr[3], vn[3], vt[3], wr[3], vtr[3], f[3];
        double poly = 1.0;
        if (!strcmp(p->style->name, "gran/hertz/history"))
            poly = sqrt((radsum - r) * s->radi * s->radj / radsum);
        for (int k = 0; k < 3; k++) {
            vr[k] = s->vi[k] - s->vj[k];
            vn[k] = d[k] * vnnr * rsqinv;
            vt[k] = vr[k] - vn[k];
            wr[k] = (s->radi * s->omi[k] + s->radj * s->omj[k]) * rinv;
        }
        vtr[0] = vt[0] - (d[2] * wr[1] - d[1] * wr[2]);
        vtr[1] = vt[1] - (d[0] * wr[2] - d[2] * wr[0]);
        vtr[2] = vt[2] - (d[1] * wr[0] - d[0] * wr[1]);
        const double zero[3] = {0, 0, 0}, *h = s->hist ? s->hist : zero;
        double shrmag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        for (int k = 0; k < 3; k++)
            f[k] = -poly * (p->coef[C_KT] * h[k] + meff * p->coef[C_GAMMAT] * vtr[k]);
        double fs = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        double fn = p->coef[C_XMU] * fabs(ccel * r);
        if (fs > fn) {
            if (shrmag != 0.0) {
                for (int k = 0; k < 3; k++)
                    f[k] *= fn / fs;
                fs *= fn / fs;
            } else {
                f[0] = f[1] = f[2] = fs = 0.0;
            }
        }
        for (int k = 0; k < 3; k++) {
            s->sv[k] = f[k];
            s->sv[4 + k] = vn[k];
            s->sv[7 + k] = vt[k];
        }
        s->sv[3] = fs;
    }
    return 0.0;
}

void pair_gran_describe(const struct pair *p, struct pair_caps *c, const char *source,
                        const char *eval, const char *law, int history)
{
    pair_caps_source(c, source);
    c->eval = eval;
    c->eval_lanes = law;
    c->rotation = 1;
    c->sym_torque = 1; /* gran_common.cl: tr = 0 */
    c->history = history;
    c->tcol_of = p;
    c->collision_time = collision_time;
    c->conservative = pair_gran_conservative(p);
    c->energy_of = p;
    c->contact_energy = pair_gran_contact_energy;
    c->single_of = p;
    c->single = pair_gran_single;
    c->single_extra = history ? 10 : 0; /* gran/hooke: LAMMPS's single() reads a history */
}
