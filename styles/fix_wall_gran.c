/* fix_wall_gran.c - `fix ID group wall/gran model Kn Kt gamman gammat xmu
 * dampflag wallstyle args [wiggle dim amplitude period | shear dim vshear]`:
 * frictional granular walls with LAMMPS 2021 fix wall/gran semantics
 * (fix_wall_gran.cpp, models hooke, hooke/history, hertz/history).
 *
 *   model      hooke | hooke/history | hertz/history (same laws as the pair
 *              styles gran/hooke etc.: the wall kernel calls their evaluators)
 *   Kt NULL    -> 2/7 Kn;  gammat NULL -> gamman/2;  dampflag 0 -> gammat = 0
 *   wallstyle  xplane lo hi | yplane lo hi | zplane lo hi  (NULL = no face)
 *              zcylinder R  (axis z through x = y = 0)
 *   wiggle d A T   the wall oscillates along d: position lo + A (1 - cos wt),
 *                  velocity A w sin wt, w = 2 pi / T, t from the fix's creation
 *   shear d v      the wall moves along d at v (position unchanged)
 *
 * Per-atom contact history (3 REAL, model with history) follows the atoms
 * through re-sorts as engine-managed per-atom state (src/fix.h). The force
 * and torque are added in post_force, as LAMMPS does (also at setup, without
 * history update). Unsupported LAMMPS options (model granular, wallstyle
 * region, keyword contacts) are rejected with a clear error. */
#include <math.h>
#include <string.h>

#include "args.h"
#include "engine.h"
#include "error.h"
#include "fix.h"

enum { W_XPLANE = 0, W_YPLANE = 1, W_ZPLANE = 2, W_ZCYLINDER = 3 };
enum { M_HOOKE, M_HOOKE_HISTORY, M_HERTZ_HISTORY };

#define WALL_BIG 1.0e20

struct wall {
    int model, history;
    double param[6];        /* GRAN layout: kn kt gamman gammat xmu limit(0) */
    int style;
    double lo, hi, cylradius;
    int wiggle, wshear, axis;
    double amplitude, period, omega, vshear;
    bigint time_origin;
    cl_kernel k;
    cl_mem dparam;
};

static const char *const model_kernel[] = {"wall_gran_hooke", "wall_gran_hooke_history",
                                           "wall_gran_hertz_history"};

static int parse_dim(struct gravel *g, const char *s, const char *kw)
{
    if (!strcmp(s, "x"))
        return 0;
    if (!strcmp(s, "y"))
        return 1;
    if (!strcmp(s, "z"))
        return 2;
    gr_error(g, "fix wall/gran %s: expected dimension x, y or z, got '%.64s'", kw, s);
}

static double parse_face(struct gravel *g, const char *s, double null_value, const char *what)
{
    if (!strcmp(s, "NULL"))
        return null_value;
    return arg_double(g, s, what);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix wall/gran expects model Kn Kt gamman gammat xmu dampflag wallstyle "
                    "args");
    struct wall w;
    memset(&w, 0, sizeof w);
    if (!strcmp(argv[0], "hooke"))
        w.model = M_HOOKE;
    else if (!strcmp(argv[0], "hooke/history"))
        w.model = M_HOOKE_HISTORY;
    else if (!strcmp(argv[0], "hertz/history"))
        w.model = M_HERTZ_HISTORY;
    else if (!strcmp(argv[0], "granular"))
        gr_error(g, "fix wall/gran model 'granular' is not supported (use hooke, "
                    "hooke/history or hertz/history)");
    else
        gr_error(g, "unknown fix wall/gran model '%.64s' (expected hooke, hooke/history or "
                    "hertz/history)", argv[0]);
    w.history = w.model != M_HOOKE;
    if (argc < 9)
        gr_error(g, "fix wall/gran %s expects Kn Kt gamman gammat xmu dampflag and a wall "
                    "style, got %d argument(s)", argv[0], argc - 1);
    double kn = arg_nonneg(g, argv[1], "Kn");
    double kt = !strcmp(argv[2], "NULL") ? kn * 2.0 / 7.0 : arg_nonneg(g, argv[2], "Kt");
    double gamman = arg_nonneg(g, argv[3], "gamma_n");
    double gammat = !strcmp(argv[4], "NULL") ? 0.5 * gamman : arg_nonneg(g, argv[4], "gamma_t");
    double xmu = arg_nonneg(g, argv[5], "xmu");
    if (xmu > 10000.0)
        gr_error(g, "fix wall/gran xmu must be between 0 and 10000, got %g", xmu);
    int dampflag = arg_int_range(g, argv[6], 0, 1, "dampflag");
    if (dampflag == 0)
        gammat = 0.0;
    if (w.history && kt == 0.0 && gammat > 0.0)
        gr_error(g, "fix wall/gran %s needs Kt > 0 when gamma_t > 0 (the sliding rescale "
                    "divides by Kt)", argv[0]);
    /* Hertz: LAMMPS divides Kn, Kt by nktv2p, which is 1 in lj, si and cgs units */
    w.param[0] = kn;
    w.param[1] = kt;
    w.param[2] = gamman;
    w.param[3] = gammat;
    w.param[4] = xmu;
    w.param[5] = 0.0;

    int i = 7;
    const char *ws = argv[i];
    if (!strcmp(ws, "xplane") || !strcmp(ws, "yplane") || !strcmp(ws, "zplane")) {
        arg_need(g, argc, i, 2, ws);
        w.style = ws[0] - 'x';
        w.lo = parse_face(g, argv[i + 1], -WALL_BIG, "wall lo position");
        w.hi = parse_face(g, argv[i + 2], WALL_BIG, "wall hi position");
        if (w.lo >= w.hi)
            gr_error(g, "fix wall/gran %s: lo (%g) must be below hi (%g)", ws, w.lo, w.hi);
        i += 3;
    } else if (!strcmp(ws, "zcylinder")) {
        arg_need(g, argc, i, 1, ws);
        w.style = W_ZCYLINDER;
        w.cylradius = arg_positive(g, argv[i + 1], "cylinder radius");
        i += 2;
    } else if (!strcmp(ws, "region")) {
        gr_error(g, "fix wall/gran wall style 'region' is not supported (use xplane, yplane, "
                    "zplane or zcylinder)");
    } else {
        gr_error(g, "unknown fix wall/gran wall style '%.64s' (expected xplane, yplane, zplane "
                    "or zcylinder)", ws);
    }
    while (i < argc) {
        if (!strcmp(argv[i], "wiggle")) {
            arg_need(g, argc, i, 3, "wiggle");
            w.axis = parse_dim(g, argv[i + 1], "wiggle");
            w.amplitude = arg_double(g, argv[i + 2], "wiggle amplitude");
            w.period = arg_positive(g, argv[i + 3], "wiggle period");
            w.wiggle = 1;
            i += 4;
        } else if (!strcmp(argv[i], "shear")) {
            arg_need(g, argc, i, 2, "shear");
            w.axis = parse_dim(g, argv[i + 1], "shear");
            w.vshear = arg_double(g, argv[i + 2], "shear velocity");
            w.wshear = 1;
            i += 3;
        } else if (!strcmp(argv[i], "contacts")) {
            gr_error(g, "fix wall/gran keyword 'contacts' is not supported");
        } else {
            gr_error(g, "unknown fix wall/gran keyword '%.64s' (expected wiggle or shear)",
                     argv[i]);
        }
    }
    if (w.style <= W_ZPLANE && g->dom.periodic[w.style])
        gr_error(g, "cannot use a %s wall in the periodic dimension %c", ws, 'x' + w.style);
    if (w.style == W_ZCYLINDER && (g->dom.periodic[0] || g->dom.periodic[1]))
        gr_error(g, "cannot use a zcylinder wall with periodic x or y");
    if (w.wiggle && w.wshear)
        gr_error(g, "cannot both wiggle and shear a wall");
    if (w.wiggle && w.style == W_ZCYLINDER && w.axis != 2)
        gr_error(g, "a zcylinder wall can only wiggle along z");
    if (w.wshear && w.style <= W_ZPLANE && w.axis == w.style)
        gr_error(g, "a %s wall cannot shear along its normal %c", ws, 'x' + w.axis);
    if (w.wiggle)
        w.omega = 2.0 * M_PI / w.period;
    w.time_origin = g->step;

    struct wall *pw = gr_malloc(g, sizeof *pw);
    *pw = w;
    f->data = pw;
    f->hooks = HOOK_POST_FORCE;
    f->needs = NEED_ROTATION;
    f->sources[f->nsources++] = "pair_gran_hooke.cl";
    f->sources[f->nsources++] = "pair_gran_hooke_history.cl";
    f->sources[f->nsources++] = "pair_gran_hertz_history.cl";
    f->sources[f->nsources++] = "fix_wall_gran.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct wall *w = f->data;
    struct engine *e = eng_get(g);
    w->k = eng_kernel(g, model_kernel[w->model]);
    f->peratom_bytes = w->history ? 3 * e->rsz : 0;
    /* parameters: re-uploaded every run (precision may change between runs) */
    if (w->dparam)
        clReleaseMemObject(w->dparam);
    w->dparam = NULL;
    w->dparam = eng_alloc(g, 8 * e->rsz, "fix wall/gran parameters");
    eng_write_reals(g, w->dparam, 6, w->param);
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct wall *w = f->data;
    struct dev_atoms *a = eng_atoms(g);
    double lo = w->lo, hi = w->hi, vwall[3] = {0, 0, 0};
    if (w->wiggle) {
        double arg = w->omega * (double)(g->step - w->time_origin) * g->dt;
        if (w->style == w->axis) {
            lo = w->lo + w->amplitude - w->amplitude * cos(arg);
            hi = w->hi + w->amplitude - w->amplitude * cos(arg);
        }
        vwall[w->axis] = w->amplitude * w->omega * sin(arg);
    } else if (w->wshear) {
        vwall[w->axis] = w->vshear;
    }
    int cyl_shear = w->style == W_ZCYLINDER && w->wshear && w->axis != 2;
    if (cyl_shear)
        vwall[0] = vwall[1] = vwall[2] = 0.0;   /* azimuthal, added per atom in the kernel */
    cl_kernel k = w->k;
    int i = 0;
    eng_arg_int(g, k, i++, a->n);
    eng_arg_uint(g, k, i++, f->groupbit);
    eng_arg_mem(g, k, i++, a->mask);
    eng_arg_mem(g, k, i++, a->x);
    eng_arg_mem(g, k, i++, a->v);
    eng_arg_mem(g, k, i++, a->omega);
    eng_arg_mem(g, k, i++, a->radius);
    eng_arg_mem(g, k, i++, a->rmass);
    eng_arg_mem(g, k, i++, a->f);
    eng_arg_mem(g, k, i++, a->torque);
    eng_arg_mem(g, k, i++, w->history ? f->peratom : a->f);
    eng_arg_int(g, k, i++, w->history);
    eng_arg_mem(g, k, i++, w->dparam);
    eng_arg_int(g, k, i++, w->style);
    eng_arg_real(g, k, i++, lo);
    eng_arg_real(g, k, i++, hi);
    eng_arg_real(g, k, i++, w->cylradius);
    eng_arg_real(g, k, i++, vwall[0]);
    eng_arg_real(g, k, i++, vwall[1]);
    eng_arg_real(g, k, i++, vwall[2]);
    eng_arg_int(g, k, i++, cyl_shear);
    eng_arg_real(g, k, i++, w->vshear);
    eng_arg_real(g, k, i++, g->dt);
    eng_arg_int(g, k, i++, !eng_in_setup(g));
    eng_launch(g, k, (size_t)a->n);
}

static void destroy(struct fix *f)
{
    struct wall *w = f->data;
    if (w && w->dparam)
        clReleaseMemObject(w->dparam);
    free(w);
    f->data = NULL;
}

/* Restart state (restart.c): the time origin of wiggle (the step the fix
 * was created at), so a re-created fix continues the same oscillation. */
static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const struct wall *w = f->data;
    int64_t origin = w->time_origin;
    if (buf && cap >= sizeof origin)
        memcpy(buf, &origin, sizeof origin);
    return sizeof origin;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct wall *w = f->data;
    int64_t origin;
    if (len != sizeof origin)
        gr_error(g, "fix %s: restart state of %zu bytes, expected %zu", f->id, len,
                 sizeof origin);
    memcpy(&origin, buf, sizeof origin);
    w->time_origin = origin;
}

const struct fix_style fix_style_wall_gran = {
    .name = "wall/gran",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
    .write_restart = write_restart,
    .read_restart = read_restart,
};
