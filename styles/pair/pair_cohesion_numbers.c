/* pair_cohesion_numbers.c - the dimensionless numbers of a cohesive
 * particle-laden flow, logged at run setup when fix drag and pair_style
 * cohesion are both active (Andrews 2018, source document 000, sec. 6.1.2-3):
 *
 *   Stk = rho_p d_p^2 u_0 / (18 mu l_0)                         (eq. 6.4)
 *     u_0 = mean flow speed (Taylor-Green: 0.7839 A), l_0 = vortex diameter pi/a
 *   Sy  = L_e sqrt(kc) / (e sqrt(L_e^2 kc + u^2 m))             (eq. 6.5)
 *     L_e = d_e - d_b, u = mean particle speed, m = mean particle mass,
 *     e = restitution of the linear/restitution contact term; also at
 *     u = the mean flow speed, as 000 table 6.2 evaluates it
 *
 * Means are over all atoms (host arrays, run start); L_e and kc are those of
 * a pair of two mean-size particles of type 1. */
#include <math.h>
#include <string.h>

#include "error.h"
#include "fix.h"
#include "fix_drag.h"
#include "log.h"
#include "pair.h"
#include "pair_cohesion.h"
#include "pair_cohesion_numbers.h"

/* The linear contact term of the scene: linear/restitution (coef[0] = ke,
 * coef[1] = e, styles/pair/pair_linear_restitution.c) or gran/hooke(/history)
 * (coef[0] = kn); NULL if there is none. */
static const struct pair *linear_contact(const struct gravel *g)
{
    const struct pair *p = g->styles.pair, *t[PAIR_MAXTERMS];
    int n = 1;
    t[0] = p;
    if (p->style->terms)
        n = p->style->terms(p, t);
    for (int k = 0; k < n; k++)
        if (!strcmp(t[k]->style->name, "linear/restitution") ||
            !strcmp(t[k]->style->name, "gran/hooke") ||
            !strcmp(t[k]->style->name, "gran/hooke/history"))
            return t[k];
    return NULL;
}

/* Restitution coefficient of a linear/restitution term, or 0. */
static double restitution(const struct gravel *g)
{
    const struct pair *c = linear_contact(g);
    return c && !strcmp(c->style->name, "linear/restitution") ? c->coef[1] : 0;
}

void pair_cohesion_overlap_check(struct gravel *g, const struct pair *coh)
{
    const struct pair *c = linear_contact(g);
    if (!c || g->atoms.n == 0)
        return;
    double rsum = 0;
    for (int i = 0; i < g->atoms.n; i++)
        rsum += g->atoms.radius[i];
    double rmean = rsum / g->atoms.n, db = 2 * rmean, kc, ke = c->coef[0];
    double de = pair_cohesion_effect_distance(coh, 1, 1, rmean, rmean, &kc);
    if (de <= db || kc <= 0)
        return;
    if (kc >= ke || kc * de >= ke * db) { /* still attractive at full overlap */
        gr_warn(g, "cohesion stiffness kc = %g is not below the contact stiffness %g of %s: "
                   "cohesion overpowers the contact and particles can pass through each other",
                kc, ke, c->style->name);
        return;
    }
    /* resting pair: ke delta = kc (d_e - d_b + delta) */
    double delta = kc * (de - db) / (ke - kc);
    gr_print(g, "Cohesion: a resting pair of mean-size type-1 particles overlaps by %g "
                "(%.3g %% of the contact distance %g; kc %g vs contact stiffness %g)\n",
             delta, 100 * delta / db, db, kc, ke);
    if (delta > 0.1 * db)
        gr_warn(g, "cohesion pulls resting particles %.3g %% of their contact distance into "
                   "each other (kc %g close to the contact stiffness %g)",
                100 * delta / db, kc, ke);
}

void pair_cohesion_dimensionless(struct gravel *g, const struct pair *coh)
{
    struct fix *f = fix_find_style(g, "drag");
    double mu, u0, l0;
    if (!f || !fix_drag_scales(f, &mu, &u0, &l0) || g->atoms.n == 0)
        return;
    const struct atoms *a = &g->atoms;
    double rsum = 0, msum = 0, rhosum = 0, dsq = 0, usum = 0;
    for (int i = 0; i < a->n; i++) {
        double r = a->radius[i], m = a->rmass[i];
        rsum += r;
        msum += m;
        rhosum += m / (4.0 / 3.0 * M_PI * r * r * r);
        dsq += 4 * r * r;
        usum += sqrt(a->v[3 * i] * a->v[3 * i] + a->v[3 * i + 1] * a->v[3 * i + 1] +
                     a->v[3 * i + 2] * a->v[3 * i + 2]);
    }
    double nn = a->n, rmean = rsum / nn, mmean = msum / nn, rho = rhosum / nn;
    double umean = usum / nn;
    if (l0 > 0 && mu > 0)
        gr_print(g, "Stokes number Stk = %.4g (000 eq. 6.4: rho_p %g, d_p^2 %g, u_0 = 0.7839 A "
                    "= %g, mu %g, l_0 = pi/a = %g)\n",
                 rho * (dsq / nn) * u0 / (18 * mu * l0), rho, dsq / nn, u0, mu, l0);
    else
        gr_print(g, "Stokes number: not defined for a uniform flow (no length scale); "
                    "tau_p = %g\n", rho * (dsq / nn) / (18 * mu));
    double kc;
    double le = pair_cohesion_effect_distance(coh, 1, 1, rmean, rmean, &kc) - 2 * rmean;
    double e = restitution(g);
    if (!(e > 0)) {
        gr_print(g, "Stickiness number: needs the restitution of a linear/restitution "
                    "contact term (not in this pair style)\n");
        return;
    }
    double sy = le * sqrt(kc) / (e * sqrt(le * le * kc + umean * umean * mmean));
    gr_print(g, "Stickiness number Sy = %.4g (000 eq. 6.5: L_e = d_e - d_b = %g, kc %g, e %g, "
                "mean particle speed %g, mean mass %g; Sy > 1: a head-on collision sticks)\n",
             sy, le, kc, e, umean, mmean);
    /* 000 table 6.2 evaluates eq. 6.5 at the mean flow speed (0.7839 A) */
    if (u0 > 0)
        gr_print(g, "Stickiness number at the mean flow speed %g: Sy = %.4g (000 table 6.2 "
                    "convention)\n", u0, le * sqrt(kc) / (e * sqrt(le * le * kc + u0 * u0 * mmean)));
}
