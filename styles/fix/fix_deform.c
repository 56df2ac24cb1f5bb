/* fix_deform.c - `fix ID group deform N param style args ... [remap x|none]
 * [flip yes|no] [units lattice|box]`: change the box every N steps during a
 * run, as LAMMPS 2021's fix deform (end_of_step; run start/stop are the
 * run's first and last steps).
 *
 *   x|y|z   final lo hi | delta dlo dhi | scale f | vel V | erate R |
 *           trate R | volume | wiggle A Tp
 *   xy|xz|yz final t | delta dt | vel V | erate R | trate R | wiggle A Tp
 *
 * Each style gives the target bounds (tilt) at step s of the run as LAMMPS:
 * linear in delta = (s - first) / (last - first) between the start (the box
 * at the run's first step) and the stop value, except trate and wiggle
 * (exponential and sinusoidal in the elapsed time) and volume (the length
 * that keeps the start volume given the other dimensions). A tilt target is
 * moved by whole box lengths to the one closest to the current tilt, with
 * LAMMPS's arithmetic (the bits matter). Lattice units (the default) scale
 * final, delta, vel and wiggle values by the lattice spacings (x for xy and
 * xz, y for yz). The change goes through box_change_apply (src/engine/box_change.h):
 * remap x (default) keeps the group's atoms at their lamda coordinates,
 * remap none leaves them, remap v leaves them and sets LAMMPS's h_rate
 * (g->dom.h_rate): group atoms crossing a periodic face get v -/+ h_rate
 * per period, and contacts through a periodic image see the image's
 * streaming velocity (Lees-Edwards; box_change.h).
 *
 * flip yes (default): a tilt beyond half its box length (x for xy and xz,
 * y for yz) flips the box at the next step, before its neighbor rebuild, as
 * LAMMPS (tilt -/+ the length, image flags kept consistent:
 * box_change_flip). Not supported (clear errors): the variable style, and
 * with flip no a tilt beyond half its box length (gravel's minimum image
 * needs the flipped box). */
#include <math.h>
#include <string.h>

#include "args.h"
#include "box_change.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_deform.h"

enum { REMAP_V = 2 }; /* besides BOX_REMAP_NONE / BOX_REMAP_X */
enum { NONE = 0, FINAL, DELTA, SCALE, VEL, ERATE, TRATE, VOLUME, WIGGLE };
enum { ONE_FROM_ONE, ONE_FROM_TWO, TWO_FROM_ONE };

/* one of the six parameters x y z yz xz xy (LAMMPS's set[] order: 3 yz, 4 xz, 5 xy) */
struct set {
    int style, substyle, fixed, dynamic1, dynamic2;
    double flo, fhi, dlo, dhi, scale, vel, rate, amplitude, tperiod;
    double ftilt, dtilt;
    double lo_start, hi_start, lo_stop, hi_stop, lo_target, hi_target;
    double tilt_start, tilt_stop, tilt_target;
    double vol_start;
};

struct deform {
    int nevery, remap, flip, scaled;
    int rates_vary;             /* some trate or wiggle: h_rate changes each step */
    int flip_pending, fxy, fxz, fyz; /* a flip to do at the next step's pre_exchange */
    struct box_target flip_box;
    struct set set[6];
};

static const char *const pname[6] = {"x", "y", "z", "yz", "xz", "xy"};

static int param_index(const char *w)
{
    for (int i = 0; i < 6; i++)
        if (!strcmp(w, pname[i]))
            return i;
    return -1;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    domain_require_box(g);
    if (argc < 2)
        gr_error(g, "fix deform expects N and at least one parameter (x y z xy xz yz)");
    struct deform *d = gr_calloc(g, 1, sizeof *d);
    f->data = d;
    d->nevery = arg_int_range(g, argv[0], 1, 1 << 30, "fix deform N");
    d->remap = BOX_REMAP_X;
    d->flip = 1;
    d->scaled = 1;
    int i = 1;
    while (i < argc) {
        int p = param_index(argv[i]);
        if (p < 0)
            break;
        struct set *s = &d->set[p];
        if (s->style)
            gr_error(g, "fix deform: %s is given twice", argv[i]);
        arg_need(g, argc, i, 1, argv[i]);
        const char *st = argv[i + 1];
        int tilt = p >= 3;
#define NEED(k) arg_need(g, argc, i + 1, k, st)
        if (!strcmp(st, "final")) {
            s->style = FINAL;
            if (tilt) {
                NEED(1);
                s->ftilt = arg_double(g, argv[i + 2], "final tilt");
                i += 3;
            } else {
                NEED(2);
                s->flo = arg_double(g, argv[i + 2], "final lo");
                s->fhi = arg_double(g, argv[i + 3], "final hi");
                if (!(s->flo < s->fhi))
                    gr_error(g, "fix deform %s final: lo must be below hi", pname[p]);
                i += 4;
            }
        } else if (!strcmp(st, "delta")) {
            s->style = DELTA;
            if (tilt) {
                NEED(1);
                s->dtilt = arg_double(g, argv[i + 2], "delta tilt");
                i += 3;
            } else {
                NEED(2);
                s->dlo = arg_double(g, argv[i + 2], "delta lo");
                s->dhi = arg_double(g, argv[i + 3], "delta hi");
                i += 4;
            }
        } else if (!strcmp(st, "scale") && !tilt) {
            NEED(1);
            s->style = SCALE;
            s->scale = arg_positive(g, argv[i + 2], "scale factor");
            i += 3;
        } else if (!strcmp(st, "vel")) {
            NEED(1);
            s->style = VEL;
            s->vel = arg_double(g, argv[i + 2], "velocity");
            i += 3;
        } else if (!strcmp(st, "erate") || !strcmp(st, "trate")) {
            NEED(1);
            s->style = st[0] == 'e' ? ERATE : TRATE;
            s->rate = arg_double(g, argv[i + 2], "rate");
            i += 3;
        } else if (!strcmp(st, "volume") && !tilt) {
            s->style = VOLUME;
            i += 2;
        } else if (!strcmp(st, "wiggle")) {
            NEED(2);
            s->style = WIGGLE;
            s->amplitude = arg_double(g, argv[i + 2], "wiggle amplitude");
            s->tperiod = arg_positive(g, argv[i + 3], "wiggle period");
            i += 4;
        } else if (!strcmp(st, "variable")) {
            gr_error(g, "fix deform %s variable is not supported", pname[p]);
        } else {
            gr_error(g, "fix deform %s: unknown style '%.32s' (%s)", pname[p], st,
                     tilt ? "final, delta, vel, erate, trate, wiggle"
                          : "final, delta, scale, vel, erate, trate, volume, wiggle");
        }
#undef NEED
    }
    for (; i < argc; i += 2) {
        const char *kw = argv[i];
        arg_need(g, argc, i, 1, kw);
        const char *v = argv[i + 1];
        if (!strcmp(kw, "remap")) {
            if (!strcmp(v, "x"))
                d->remap = BOX_REMAP_X;
            else if (!strcmp(v, "none"))
                d->remap = BOX_REMAP_NONE;
            else if (!strcmp(v, "v"))
                d->remap = REMAP_V;
            else
                gr_error(g, "fix deform remap must be x, v or none, got '%.32s'", v);
        } else if (!strcmp(kw, "flip")) {
            d->flip = arg_yesno(g, v, "flip");
        } else if (!strcmp(kw, "units")) {
            d->scaled = domain_parse_units_kw(g, v);
        } else {
            gr_error(g, "unknown fix deform keyword or parameter '%.32s' (x y z xy xz yz, "
                        "remap, flip, units)", kw);
        }
    }
    int any = 0;
    for (int p = 0; p < 6; p++)
        any |= d->set[p].style != NONE;
    if (!any)
        gr_error(g, "fix deform needs at least one parameter (x y z xy xz yz)");
    /* LAMMPS's checks */
    const struct domain *dm = &g->dom;
    for (int p = 0; p < 3; p++)
        if (d->set[p].style && !dm->periodic[p] &&
            (dm->bnd[p][0] == BND_S || dm->bnd[p][0] == BND_M || dm->bnd[p][1] == BND_S ||
             dm->bnd[p][1] == BND_M))
            gr_error(g, "cannot use fix deform on a shrink-wrapped boundary (%s)", pname[p]);
    for (int p = 3; p < 6; p++) {
        if (!d->set[p].style)
            continue;
        if (!dm->triclinic)
            gr_error(g, "fix deform tilt factors require a triclinic box (change_box all "
                        "triclinic)");
        int across = p == 5 ? 1 : 2; /* xy needs y periodic, xz/yz need z */
        if (!dm->periodic[across])
            gr_error(g, "cannot use fix deform tilt on a shrink-wrapped or fixed %c boundary",
                     "xyz"[across]);
    }
    if (dm->dimension == 2 && (d->set[2].style || d->set[3].style || d->set[4].style))
        gr_error(g, "fix deform cannot change z, xz or yz of a 2d simulation");
    /* volume: which dimensions it follows */
    for (int p = 0; p < 3; p++) {
        struct set *s = &d->set[p];
        if (s->style != VOLUME)
            continue;
        int o1 = (p + 1) % 3, o2 = (p + 2) % 3;
        int s1 = d->set[o1].style, s2 = d->set[o2].style;
        if (s1 == NONE) {
            if (s2 == NONE || s2 == VOLUME)
                gr_error(g, "fix deform volume setting is invalid");
            s->substyle = ONE_FROM_ONE;
            s->fixed = o1;
            s->dynamic1 = o2;
        } else if (s2 == NONE) {
            if (s1 == VOLUME)
                gr_error(g, "fix deform volume setting is invalid");
            s->substyle = ONE_FROM_ONE;
            s->fixed = o2;
            s->dynamic1 = o1;
        } else if (s1 == VOLUME) {
            if (s2 == VOLUME)
                gr_error(g, "fix deform volume setting is invalid");
            s->substyle = TWO_FROM_ONE;
            s->fixed = o1;
            s->dynamic1 = o2;
        } else if (s2 == VOLUME) {
            s->substyle = TWO_FROM_ONE;
            s->fixed = o2;
            s->dynamic1 = o1;
        } else {
            s->substyle = ONE_FROM_TWO;
            s->dynamic1 = o1;
            s->dynamic2 = o2;
        }
    }
    /* lattice units scale final, delta, vel and wiggle (LAMMPS: only when some
     * parameter uses one of them) */
    int need = 0;
    for (int p = 0; p < 6; p++) {
        int st = d->set[p].style;
        need |= st == FINAL || st == DELTA || st == VEL || st == WIGGLE;
    }
    for (int p = 0; p < 6; p++)
        d->rates_vary |= d->set[p].style == TRATE || d->set[p].style == WIGGLE;
    double sc[3];
    domain_unit_scale(g, need && d->scaled, sc);
    for (int p = 0; p < 6; p++) {
        struct set *s = &d->set[p];
        double k = p < 3 ? sc[p] : p == 3 ? sc[1] : sc[0];
        s->flo *= k;
        s->fhi *= k;
        s->dlo *= k;
        s->dhi *= k;
        s->vel *= k;
        s->amplitude *= k;
        s->ftilt *= k;
        s->dtilt *= k;
    }
    f->hooks = HOOK_END_OF_STEP | HOOK_PRE_EXCHANGE;
    /* no time_depend: the targets are timed from the run's first step, so
     * reset_timestep leaves them alone (LAMMPS 2021 allows it too) */
    f->force_reneighbor = 1;
    if (d->remap == REMAP_V)
        snprintf(f->defines, sizeof f->defines, "VREMAP");
}

static void init(struct gravel *g, struct fix *f)
{
    struct deform *d = f->data;
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i] != f && g->styles.fix[i]->style == f->style)
            gr_error(g, "more than one fix deform");
    const struct domain *dm = &g->dom;
    d->flip_pending = 0;
    f->next_reneighbor = 0;
    double delt = (double)(g->laststep - g->firststep) * g->dt;
    for (int i = 0; i < 3; i++) {
        struct set *s = &d->set[i];
        s->lo_start = dm->lo[i];
        s->hi_start = dm->hi[i];
        s->vol_start = (dm->hi[0] - dm->lo[0]) * (dm->hi[1] - dm->lo[1]) * (dm->hi[2] - dm->lo[2]);
        if (s->style == FINAL) {
            s->lo_stop = s->flo;
            s->hi_stop = s->fhi;
        } else if (s->style == DELTA) {
            s->lo_stop = s->lo_start + s->dlo;
            s->hi_stop = s->hi_start + s->dhi;
        } else if (s->style == SCALE) {
            double shift = 0.5 * s->scale * (s->hi_start - s->lo_start);
            s->lo_stop = 0.5 * (s->lo_start + s->hi_start) - shift;
            s->hi_stop = 0.5 * (s->lo_start + s->hi_start) + shift;
        } else if (s->style == VEL) {
            s->lo_stop = s->lo_start - 0.5 * delt * s->vel;
            s->hi_stop = s->hi_start + 0.5 * delt * s->vel;
        } else if (s->style == ERATE) {
            double shift = 0.5 * delt * s->rate * (s->hi_start - s->lo_start);
            s->lo_stop = s->lo_start - shift;
            s->hi_stop = s->hi_start + shift;
            if (s->hi_stop <= s->lo_stop)
                gr_error(g, "final box dimension due to fix deform is < 0.0");
        } else if (s->style == TRATE) {
            double shift = 0.5 * ((s->hi_start - s->lo_start) * exp(s->rate * delt));
            s->lo_stop = 0.5 * (s->lo_start + s->hi_start) - shift;
            s->hi_stop = 0.5 * (s->lo_start + s->hi_start) + shift;
        } else if (s->style == WIGGLE) {
            double shift = 0.5 * s->amplitude * sin(2 * M_PI * delt / s->tperiod);
            s->lo_stop = s->lo_start - shift;
            s->hi_stop = s->hi_start + shift;
        }
    }
    /* LAMMPS's h_rate for the constant-rate styles (the others per step) */
    double *hr = g->dom.h_rate;
    for (int i = 0; i < 3; i++) {
        const struct set *s = &d->set[i];
        hr[i] = 0.0;
        if (delt != 0.0 && (s->style == FINAL || s->style == DELTA || s->style == SCALE ||
                            s->style == VEL || s->style == ERATE))
            hr[i] = (s->hi_stop - s->hi_start) / delt - (s->lo_stop - s->lo_start) / delt;
    }
    for (int i = 3; i < 6; i++) {
        struct set *s = &d->set[i];
        s->tilt_start = i == 5 ? dm->xy : i == 4 ? dm->xz : dm->yz;
        if (s->style == FINAL)
            s->tilt_stop = s->ftilt;
        else if (s->style == DELTA)
            s->tilt_stop = s->tilt_start + s->dtilt;
        else if (s->style == VEL)
            s->tilt_stop = s->tilt_start + delt * s->vel;
        else if (s->style == ERATE) {
            const struct set *b = &d->set[i == 5 ? 1 : 2];
            s->tilt_stop = s->tilt_start + delt * s->rate * (b->hi_start - b->lo_start);
        } else if (s->style == TRATE) {
            if (s->tilt_start == 0.0)
                gr_error(g, "cannot use fix deform trate on a box with zero tilt");
            s->tilt_stop = s->tilt_start * exp(s->rate * delt);
        } else if (s->style == WIGGLE)
            s->tilt_stop = s->tilt_start + s->amplitude * sin(2 * M_PI * delt / s->tperiod);
        hr[i] = 0.0;
        if (delt != 0.0 && (s->style == FINAL || s->style == DELTA || s->style == VEL ||
                            s->style == ERATE))
            hr[i] = (s->tilt_stop - s->tilt_start) / delt;
    }
    /* LAMMPS: a yz that would flip while xy changes is refused (the flips
     * would change xz continuously) */
    const struct set *yz = &d->set[3], *ys = &d->set[1];
    if (yz->style && d->set[5].style) {
        double lo = yz->tilt_stop, hi = yz->tilt_stop;
        if (yz->style == WIGGLE) { /* LAMMPS's extreme tilts of the wiggle in the run */
            double a = yz->amplitude, shift = a * sin(2 * M_PI * delt / yz->tperiod);
            double q = delt / yz->tperiod, t0 = yz->tilt_start;
            if (a >= 0.0) {
                lo = q < 0.5 ? t0 : q < 0.75 ? t0 - shift : t0 - a;
                hi = q < 0.25 ? t0 + shift : t0 + a;
            } else {
                lo = q < 0.25 ? t0 - shift : t0 - a;
                hi = q < 0.5 ? t0 : q < 0.75 ? t0 + shift : t0 + a;
            }
        }
        int flag = lo / (ys->hi_start - ys->lo_start) < -0.5 ||
                   hi / (ys->hi_start - ys->lo_start) > 0.5;
        if (ys->style)
            flag |= lo / (ys->hi_stop - ys->lo_stop) < -0.5 || hi / (ys->hi_stop - ys->lo_stop) > 0.5;
        if (flag)
            gr_error(g, "fix deform is changing yz too much with xy");
    }
    g->dom.vremap_group = d->remap == REMAP_V ? f->groupbit : 0;
}

/* LAMMPS's FixDeform::end_of_step, the targets of this step */
static void targets(struct gravel *g, struct deform *d)
{
    const struct domain *dm = &g->dom;
    double *hr = g->dom.h_rate;
    struct set *set = d->set;
    double delta = (double)(g->step - g->firststep);
    if (delta != 0.0)
        delta /= (double)(g->laststep - g->firststep);
    double delt = (double)(g->step - g->firststep) * g->dt;
    for (int i = 0; i < 3; i++) {
        struct set *s = &set[i];
        if (s->style == NONE) {
            s->lo_target = dm->lo[i];
            s->hi_target = dm->hi[i];
        } else if (s->style == TRATE) {
            hr[i] = s->rate * (dm->hi[i] - dm->lo[i]);
            s->lo_target = 0.5 * (s->lo_start + s->hi_start) -
                           0.5 * ((s->hi_start - s->lo_start) * exp(s->rate * delt));
            s->hi_target = 0.5 * (s->lo_start + s->hi_start) +
                           0.5 * ((s->hi_start - s->lo_start) * exp(s->rate * delt));
        } else if (s->style == WIGGLE) {
            hr[i] = 2 * M_PI / s->tperiod * s->amplitude * cos(2 * M_PI * delt / s->tperiod);
            s->lo_target = s->lo_start - 0.5 * s->amplitude * sin(2 * M_PI * delt / s->tperiod);
            s->hi_target = s->hi_start + 0.5 * s->amplitude * sin(2 * M_PI * delt / s->tperiod);
        } else if (s->style != VOLUME) {
            s->lo_target = s->lo_start + delta * (s->lo_stop - s->lo_start);
            s->hi_target = s->hi_start + delta * (s->hi_stop - s->hi_start);
        }
    }
    for (int i = 0; i < 3; i++) {
        struct set *s = &set[i];
        if (s->style != VOLUME)
            continue;
        const struct set *d1 = &set[s->dynamic1];
        double mid = 0.5 * (s->lo_start + s->hi_start), half;
        if (s->substyle == ONE_FROM_ONE) {
            const struct set *fx = &set[s->fixed];
            half = 0.5 * (s->vol_start / (d1->hi_target - d1->lo_target) /
                          (fx->hi_start - fx->lo_start));
        } else if (s->substyle == ONE_FROM_TWO) {
            const struct set *d2 = &set[s->dynamic2];
            half = 0.5 * (s->vol_start / (d1->hi_target - d1->lo_target) /
                          (d2->hi_target - d2->lo_target));
        } else {
            const struct set *fx = &set[s->fixed];
            half = 0.5 * sqrt(s->vol_start / (d1->hi_target - d1->lo_target) /
                              (fx->hi_start - fx->lo_start) * (s->hi_start - s->lo_start));
        }
        s->lo_target = mid - half;
        s->hi_target = mid + half;
    }
    if (!dm->triclinic)
        return;
    double h[6];
    domain_h(g, h);
    for (int i = 3; i < 6; i++) {
        struct set *s = &set[i];
        if (s->style == NONE)
            s->tilt_target = i == 5 ? dm->xy : i == 4 ? dm->xz : dm->yz;
        else if (s->style == TRATE) {
            s->tilt_target = s->tilt_start * exp(s->rate * delt);
            hr[i] = s->rate * h[i];
        } else if (s->style == WIGGLE) {
            s->tilt_target = s->tilt_start + s->amplitude * sin(2 * M_PI * delt / s->tperiod);
            hr[i] = 2 * M_PI / s->tperiod * s->amplitude * cos(2 * M_PI * delt / s->tperiod);
        } else
            s->tilt_target = s->tilt_start + delta * (s->tilt_stop - s->tilt_start);
        /* the target closest to the current tilt, whole box lengths apart */
        int idenom = i == 3 ? 1 : 0;
        double denom = set[idenom].hi_target - set[idenom].lo_target;
        double current = h[i] / h[idenom];
        while (s->tilt_target / denom - current > 0.0)
            s->tilt_target -= denom;
        while (s->tilt_target / denom - current < 0.0)
            s->tilt_target += denom;
        if (fabs(s->tilt_target / denom - 1.0 - current) < fabs(s->tilt_target / denom - current))
            s->tilt_target -= denom;
    }
}

static void end_of_step(struct gravel *g, struct fix *f)
{
    struct deform *d = f->data;
    if (g->step % d->nevery)
        return;
    targets(g, d);
    struct box_target b;
    box_current(g, &b);
    for (int i = 0; i < 3; i++)
        if (d->set[i].style) {
            b.lo[i] = d->set[i].lo_target;
            b.hi[i] = d->set[i].hi_target;
        }
    if (g->dom.triclinic) {
        if (d->set[3].style)
            b.yz = d->set[3].tilt_target;
        if (d->set[4].style)
            b.xz = d->set[4].tilt_target;
        if (d->set[5].style)
            b.xy = d->set[5].tilt_target;
        double xprd = b.hi[0] - b.lo[0], yprd = b.hi[1] - b.lo[1];
        double xinv = 1.0 / xprd, yinv = 1.0 / yprd;
        if (b.yz * yinv < -0.5 || b.yz * yinv > 0.5 || b.xz * xinv < -0.5 ||
            b.xz * xinv > 0.5 || b.xy * xinv < -0.5 || b.xy * xinv > 0.5) {
            if (!d->flip)
                gr_error(g, "fix %s deform: with flip no the tilt reached more than half its "
                            "box length at step %lld (xy %g xz %g yz %g): gravel's minimum "
                            "image needs flip yes", f->id, (long long)g->step, b.xy, b.xz, b.yz);
            /* LAMMPS's flip, done at the next step before its rebuild */
            struct box_target fb = b;
            int fxy = 0, fxz = 0, fyz = 0;
            if (g->dom.periodic[1]) {
                if (fb.yz * yinv < -0.5) {
                    fb.yz += yprd;
                    fb.xz += fb.xy;
                    fyz = 1;
                } else if (fb.yz * yinv > 0.5) {
                    fb.yz -= yprd;
                    fb.xz -= fb.xy;
                    fyz = -1;
                }
            }
            if (g->dom.periodic[0]) {
                if (fb.xz * xinv < -0.5) {
                    fb.xz += xprd;
                    fxz = 1;
                }
                if (fb.xz * xinv > 0.5) {
                    fb.xz -= xprd;
                    fxz = -1;
                }
                if (fb.xy * xinv < -0.5) {
                    fb.xy += xprd;
                    fxy = 1;
                }
                if (fb.xy * xinv > 0.5) {
                    fb.xy -= xprd;
                    fxy = -1;
                }
            }
            if (fxy || fxz || fyz) {
                d->flip_pending = 1;
                d->fxy = fxy;
                d->fxz = fxz;
                d->fyz = fyz;
                d->flip_box = fb;
                f->next_reneighbor = g->step + 1;
            }
        }
    }
    box_change_apply(g, &b, d->remap == BOX_REMAP_X ? BOX_REMAP_X : BOX_REMAP_NONE,
                     f->groupbit);
    if (d->remap == REMAP_V && d->rates_vary)
        box_change_rates(g);
}

/* the flip scheduled by the previous step (LAMMPS's pre_exchange): the box
 * gets the flipped tilts, the image flags follow, and this step's rebuild
 * wraps the atoms into the flipped box */
static void pre_exchange(struct gravel *g, struct fix *f)
{
    struct deform *d = f->data;
    if (!d->flip_pending)
        return;
    d->flip_pending = 0;
    /* the bounds are the current ones: the flip changes the tilts only */
    struct box_target b;
    box_current(g, &b);
    b.xy = d->flip_box.xy;
    b.xz = d->flip_box.xz;
    b.yz = d->flip_box.yz;
    box_change_flip(g, &b, d->fxy, d->fxz, d->fyz);
}

int fix_deform_changes(const struct fix *f, int p)
{
    const struct deform *d = f->data;
    return d && p >= 0 && p < 6 && d->set[p].style != NONE;
}

const struct fix_style fix_style_deform = {
    .name = "deform",
    .flags = FIX_BOX_CHANGE,
    .create = create,
    .init = init,
    .end_of_step = end_of_step,
    .pre_exchange = pre_exchange,
};
