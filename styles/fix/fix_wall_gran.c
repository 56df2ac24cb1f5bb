/* fix_wall_gran.c - `fix ID group wall/gran model Kn Kt gamman gammat xmu
 * dampflag wallstyle args [wiggle dim amplitude period | shear dim vshear]`:
 * frictional granular walls with LAMMPS 2021 fix wall/gran semantics
 * (fix_wall_gran.cpp, models hooke, hooke/history, hertz/history, granular).
 *
 *   model      hooke | hooke/history | hertz/history (same laws as the pair
 *              styles gran/hooke etc.: the wall kernel calls their evaluators)
 *              | granular <sub-models> (pair granular's, below)
 *   Kt NULL    -> 2/7 Kn;  gammat NULL -> gamman/2;  dampflag 0 -> gammat = 0
 *   wallstyle  xplane lo hi | yplane lo hi | zplane lo hi  (NULL = no face)
 *              zcylinder R  (axis z through x = y = 0)
 *              mesh n_meshes N meshes ID ...  (LIGGGHTS: triangle meshes of fix
 *              mesh/surface, moved by fix move/mesh; kernels/wall.cl MESH_KERNEL)
 *   wiggle d A T   the wall oscillates along d: position lo + A (1 - cos wt),
 *                  velocity A w sin wt, w = 2 pi / T, t from the fix's creation
 *   shear d v      the wall moves along d at v (position unchanged)
 *
 * Per-atom contact history (3 REAL, model with history; granular: its width) follows the atoms
 * through re-sorts as engine-managed per-atom state (src/style/fix.h). The force
 * and torque are added in post_force, as LAMMPS does (also at setup, without
 * history update). fix wall/gran/region (same create, `region ID` as the
 * wall style; kernels/wall_region.cl) takes the surface of a region as the
 * wall. Model granular (`granular <sub-models> wallstyle ...`) takes pair
 * granular's sub-models (granular_parse) with LAMMPS 2021's wall conversions
 * and a history row of its sub-models' width per wall element / region slot
 * (parse_granular); jkr walls hold beyond touch to the pull-off distance
 * (the jkr rows of kernels/wall_gran_kernels.h). Meshes take model granular too (not jkr).
 * A granular `heat area|radius k` sub-model conducts heat between the wall,
 * at `temperature T` (required with it, as LAMMPS 2023), and the atoms
 * (kernels/gran_heat.cl, kernels/wall.cl WALL_HEAT_*). Unsupported
 * LAMMPS options (keyword contacts) are rejected with a clear error.
 *
 * LIGGGHTS's form: `fix ID group wall/gran model M tangential T [cohesion C]
 * [rolling_friction R] [settings] primitive type W xplane|yplane|zplane p |
 * xcylinder|ycylinder|zcylinder R c1 c2` or `... mesh n_meshes N meshes ID...`
 * [shear dim v]:
 * pair gran's models (styles/pair/pair_gran.h, kernels/pair_gran.cl) with
 * the materials of (particle type, wall type W; a mesh's own type) from fix
 * property/global, packed at every run as a table by type pair. A primitive
 * plane at p acts on both sides (LIGGGHTS's primitive walls: the contact
 * normal points from the plane to the particle), the cylinder inside and
 * outside.
 *
 * fix surface/global (styles/fix/fix_surface_global.c) is this fix on
 * meshes it owns: its model words come here through wall_gran_create_own
 * (fix_wall_gran.h), with no wall style. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>

#include "args.h"
#include "coeff_check.h"
#include "device.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "wall_gran_kernels.h"
#include "pair.h"
#include "pair_gran.h"
#include "pair_granular.h"
#include "region.h"
#include "run.h"
#include "variable.h"
#include "fix_mesh_surface.h"
#include "fix_wall_gran.h"
#include "wall.h"
#include "wall_region.h"

enum { W_XPLANE = 0, W_YPLANE = 1, W_ZPLANE = 2, W_CYLINDER = 3, W_MESH = 4, W_REGION = 5 };


struct wall {
    enum wall_gran_model model;
    int history;                /* REAL per wall contact (0: none) */
    int nparam;
    double param[GRW_NPARAM];   /* kernels/param_layout.h: GRAN_* (kn kt gamman gammat xmu
                                 * limit) or, model granular, GR_* and GRW_* */
    int style;
    double lo, hi, cylradius;
    int wiggle, wshear, axis;
    double amplitude, period, omega, vshear;
    bigint time_origin;
    struct wall_law law;
    const char *kname;          /* law.kernel's name (a row of wall_gran_kernel) */
    struct lg_model lg;         /* model ...: LIGGGHTS's model (WG_LIGGGHTS) */
    int wtype;                  /* its primitive's type (0: a mesh's own) */
    int cylaxis;                /* W_CYLINDER: its axis (LAMMPS: z; LIGGGHTS: x, y or z) */
    double cx, cy;              /* its axis's coordinates in dimensions cylaxis + 1 and
                                 * cylaxis + 2 (mod 3) (LIGGGHTS: any; LAMMPS: 0 0) */
    double *table;              /* WG_LIGGGHTS: nt x nt x LG_NPARAM, rebuilt at init */
    int table_nt;
    struct mesh_walls mesh;     /* wallstyle mesh */
    char region_id[GR_NAMELEN]; /* fix wall/gran/region */
    char region_style[32];      /* the region's style and sub-region count at the */
    int region_nsub;            /* previous run (LAMMPS warns when they change) */
    struct region *region;      /* looked up at every init (region delete) */
    int inits;                  /* runs set up so far (-compat lammps2021: tsuji) */
    int heat, twall_set;        /* a granular heat sub-model; `temperature T` given */
    double twall;               /* the wall's temperature (LAMMPS 2023 Twall) */
    char tvar[GR_NAMELEN];      /* `temperature v_name`: an equal-style variable, */
                                /* evaluated at every post_force as LAMMPS does */
    struct wall_region wreg;
    /* restart: the region's previous displacement and angle per node
     * (LAMMPS Region::prev), applied when the region matches at init */
    int rs_pending, rs_n;
    char rs_style[32];
    double rs_prev[WALL_REGION_MAXNODE][4];
    double *contacts_host;      /* `contacts`: the host copy peratom_values returns */
    size_t contacts_cap;        /* atoms the device buffer law.contacts holds */
    int mdr;                    /* the granular mdr normal model (fix granular/mdr's walls) */
    double mdr_par[7];          /* its E nu Y gamma psi_b eta_n0 and damping mdr type */
};

/* the kernels, by source, model and jkr (kernels/wall_gran_kernels.h) */
static const struct {
    const char *name;
    enum wall_gran_source source;
    enum wall_gran_model model;
    int jkr;
} wall_gran_kernel[] = {
#define WG_ROW(name, source, model, jkr) {#name, source, model, jkr},
    WALL_GRAN_KERNELS(WG_ROW)
#undef WG_ROW
};

/* LIGGGHTS's `model ...` form, in either of its kernel forms */
static int liggghts_model(enum wall_gran_model m)
{
    return m == WG_LIGGGHTS || m == WG_LIGGGHTS_ROW;
}

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

/* hooke | hooke/history | hertz/history Kn Kt gamman gammat xmu dampflag;
 * returns the index of the wall style */
static int parse_classic(struct gravel *g, struct wall *pw, int argc, char **argv)
{
    struct wall w = *pw;
    w.history = w.model != WG_HOOKE ? 3 : 0;
    w.nparam = GRAN_NPARAM;
    if (argc < (w.mesh.own[0] ? 7 : 9))
        gr_error(g, "fix wall/gran %s expects Kn Kt gamman gammat xmu dampflag and a wall "
                    "style, got %d argument(s)", argv[0], argc - 1);
    const char *who = "fix wall/gran";
    double kn = coeff_arg(g, who, argv[1], "Kn", CR_NONNEG);
    double kt = !strcmp(argv[2], "NULL") ? kn * 2.0 / 7.0
                                          : coeff_arg(g, who, argv[2], "Kt", CR_NONNEG);
    double gamman = coeff_arg(g, who, argv[3], "gamma_n", CR_NONNEG);
    double gammat = !strcmp(argv[4], "NULL") ? 0.5 * gamman
                                             : coeff_arg(g, who, argv[4], "gamma_t", CR_NONNEG);
    double xmu = coeff_upto(g, who, "xmu", arg_double(g, argv[5], "xmu"), 10000.0);
    int dampflag = arg_int_range(g, argv[6], 0, 1, "dampflag");
    if (dampflag == 0)
        gammat = 0.0;
    if (w.history && kt == 0.0 && gammat > 0.0)
        gr_error(g, "fix wall/gran %s needs Kt > 0 when gamma_t > 0 (the sliding rescale "
                    "divides by Kt)", argv[0]);
    /* Hertz: LAMMPS divides Kn, Kt by nktv2p, which is 1 in lj, si and cgs units */
    w.param[GRAN_KN] = kn;
    w.param[GRAN_KT] = kt;
    w.param[GRAN_GAMMAN] = gamman;
    w.param[GRAN_GAMMAT] = gammat;
    w.param[GRAN_XMU] = xmu;
    w.param[GRAN_LIMIT] = 0.0;

    *pw = w;
    return 7;
}

/* granular <normal model args> [damping ...] tangential ... [rolling ...]
 * [twisting ...] [limit_damping]: pair granular's sub-models (the wall's
 * own E and nu), history laid out as LAMMPS 2021 sizes it for a wall:
 * 3 tangential (a history model), 1 contact radius (mindlin_rescale), 3
 * rolling, 1 twisting; returns the number of words parsed */
static int parse_granular(struct gravel *g, struct wall *w, int argc, char **argv)
{
    static const char *const stop[] = {"xplane", "yplane", "zplane", "zcylinder", "region",
                                       "mesh", "temperature", NULL};
    struct gr_one o;
    int n = granular_parse(g, &o, argc, argv, stop, 0,
                           w->mesh.own[0] ? "fix surface/global model granular"
                                          : "fix wall/gran granular");
    /* LAMMPS's fix wall/gran (and its region and surface forms) parses no
     * synchronized_verlet, and its GranularModel keeps the full-step normal
     * for a WALL contact */
    if (o.sync)
        gr_error(g, "%s: Unknown fix wall/gran keyword synchronized_verlet (LAMMPS's granular "
                    "walls have no half-step normal; it is a pair_coeff granular keyword)",
                 w->mesh.own[0] ? "fix surface/global model granular" : "fix wall/gran granular");
    int kt_null = 0;
    for (int k = 0; k + 2 < n; k++)
        if (!strcmp(argv[k], "tangential") && !strcmp(argv[k + 2], "NULL"))
            kt_null = 1;
    /* The wall's own E, nu (no mixing with the particle's). Today's LAMMPS
     * (GranSubMod::mix_stiffnessE_wall, mix_stiffnessG_wall): kn = 4/3 E /
     * (2 (1 - nu^2)), a NULL Mindlin kt = 8 E / (4 (2 - nu)(1 + nu)).
     * -compat lammps2021: LAMMPS 2021 FixWallGran's formulas, kn = 4/3 E /
     * (2 (1 - nu)) (its FOURTHIRDS constant), kt = E/4 (2 - nu) (1 + nu)
     * (checked against lmp: granular_wall_* in tests/reference/wall_gran and
     * wall_gran_region) */
    if (o.nm >= GR_N_HERTZ_MATERIAL)
        o.kn = g->opt.lammps2021 ? o.E / (2 * (1 - o.nu)) * 1.333333333333333
                                 : 4.0 / 3.0 * (o.E / (2 * (1 - o.nu * o.nu)));
    if (kt_null)
        o.kt = g->opt.lammps2021 ? o.E / 4 * (2 - o.nu) * (1 + o.nu)
                                 : 8.0 * (o.E / (4.0 * (2 - o.nu) * (1 + o.nu)));
    w->nparam = GRW_NPARAM;
    granular_pack(&o, w->param);
    int off = 0;
    w->mdr = o.nm == GR_N_MDR;
    if (w->mdr) {
        const double par[7] = {o.E, o.nu, o.Y, o.gamma, o.psi_b, o.damp, o.dtype};
        memcpy(w->mdr_par, par, sizeof par);
    }
    int tang = o.tm != GR_T_NOHISTORY;
    w->param[GRW_TANG] = tang;
    off += tang ? 3 : 0;
    w->param[GRW_HA] = o.tm == GR_T_MINDLIN_RESCALE || o.tm == GR_T_MINDLIN_RESCALE_FORCE
                           ? off++ : -1;
    w->param[GRW_HROLL] = o.rm == GR_R_SDS ? (off += 3) - 3 : -1;
    w->param[GRW_HTWIST] = o.wm != GR_W_NONE ? off++ : -1;
    /* jkr: the touch flag, last (as pair granular's row; LAMMPS keeps it first) */
    w->param[GRW_HTOUCH] = o.nm == GR_N_JKR ? off++ : -1;
    w->param[GRW_HDYN] = o.tm == GR_T_HISTORY_STATIC || o.tm == GR_T_MINDLIN_STATIC ? off++ : -1;
    /* mdr: the step's force and damping scale, last (the tangential history
     * is at the row's start); the contact's mdr state is fix granular/mdr's
     * (styles/fix/fix_granular_mdr.c) */
    w->param[GRW_HMDR] = o.nm == GR_N_MDR ? (off += MHW_N) - MHW_N : -1;
    w->param[GRW_JKR2021] = g->opt.lammps2021;
    w->param[GRW_WIDTH] = off;
    w->history = off;
    return n;
}

/* fix surface/global: the wall is the n meshes in w->mesh.own (LAMMPS
 * refuses models acting beyond contact there) */
static void own_meshes(struct gravel *g, struct fix *f, struct wall *w, int n)
{
    if (w->mdr)
        gr_error(g, "MDR model currently only supports fix wall/gran/region, not fix "
                    "surface/global");
    if (w->model == WG_GRANULAR && (int)w->param[GR_NMODEL] == GR_N_JKR)
        gr_error(g, "Granular models that extend beyond contact (e.g. JKR) not currently "
                    "supported (fix surface/global)");
    w->style = W_MESH;
    w->mesh.n = n;
    for (int m = 0; m < n; m++)
        snprintf(w->mesh.id[m], GR_NAMELEN, "%s", f->id);
}

/* own: the n meshes of fix surface/global (wall_gran_create_own), else NULL */
static void create_wall(struct gravel *g, struct fix *f, int argc, char **argv,
                        struct mesh_surface **own, int n)
{
    if (argc < 1)
        gr_error(g, "fix wall/gran expects model Kn Kt gamman gammat xmu dampflag wallstyle "
                    "args");
    struct wall w;
    memset(&w, 0, sizeof w);
    for (int m = 0; own && m < n; m++)
        w.mesh.own[m] = own[m];
    if (!strcmp(argv[0], "hooke"))
        w.model = WG_HOOKE;
    else if (!strcmp(argv[0], "hooke/history"))
        w.model = WG_HOOKE_HISTORY;
    else if (!strcmp(argv[0], "hertz/history"))
        w.model = WG_HERTZ_HISTORY;
    else if (!strcmp(argv[0], "model"))
        w.model = WG_LIGGGHTS;
    else if (!strcmp(argv[0], "granular"))
        w.model = WG_GRANULAR;
    else
        gr_error(g, "unknown fix wall/gran model '%.64s' (expected hooke, hooke/history, "
                    "hertz/history or granular)", argv[0]);
    int i;
    const char *ws = "mesh";    /* the wall style's word (errors) */
    if (w.model == WG_LIGGGHTS) {
        static const char *const stop[] = {"primitive", "mesh", NULL};
        if (!strcmp(f->style->name, "wall/gran/region"))
            gr_error(g, "fix wall/gran/region: LIGGGHTS's 'model ...' form is not supported "
                        "(use fix wall/gran model ... primitive or mesh)");
        i = lg_parse(g, &w.lg, argc, argv, stop, "fix wall/gran");
        w.history = w.lg.tm ? 3 : 0;
        const int nh = LG_NORMAL_HIST(w.lg.nm);
        if (w.lg.roll >= LG_R_EPSD || nh) {
            /* the row form (kernels/pair_gran.cl gran_model_eval_row): the normal model's
             * state (hooke/hysteresis, thornton_ning), the shear, then an epsd model's
             * spring torque */
            w.model = WG_LIGGGHTS_ROW;
            w.history = nh + 3 + (w.lg.roll >= LG_R_EPSD ? 3 : 0);
        }
        if (i >= argc)
            gr_error(g, "fix wall/gran model ...: missing the wall ('primitive type T ...' or "
                        "'mesh n_meshes N meshes ...') after the model");
        if (!strcmp(argv[i], "primitive")) {
            arg_need(g, argc, i, 3, "primitive");
            if (strcmp(argv[i + 1], "type"))
                gr_error(g, "fix wall/gran primitive: expected 'type T', got '%.64s'",
                         argv[i + 1]);
            w.wtype = arg_int(g, argv[i + 2], "primitive wall type");
            if (w.wtype < 1 || (g->atoms.ntypes > 0 && w.wtype > g->atoms.ntypes))
                gr_error(g, "fix wall/gran primitive type %d is out of range 1..%d (the wall's "
                            "material must be one of the box's atom types)", w.wtype,
                         g->atoms.ntypes);
            i += 3;
            if (i >= argc)
                gr_error(g, "fix wall/gran primitive: missing the primitive (xplane, yplane, "
                            "zplane, xcylinder, ycylinder or zcylinder)");
            const char *ps = ws = argv[i];
            if (!strcmp(ps, "xplane") || !strcmp(ps, "yplane") || !strcmp(ps, "zplane")) {
                arg_need(g, argc, i, 1, ps);
                w.style = ps[0] - 'x';
                w.lo = arg_double(g, argv[i + 1], "plane position");
                w.hi = WALL_FAR;
                i += 2;
            } else if (!strcmp(ps, "xcylinder") || !strcmp(ps, "ycylinder") ||
                       !strcmp(ps, "zcylinder")) {
                /* LIGGGHTS: R, then the axis's centre in the next two dimensions
                 * (cyclic: x -> y z, y -> z x, z -> x y) */
                static const char *const centre[3][2] = {{"cylinder centre y", "cylinder centre z"},
                                                         {"cylinder centre z", "cylinder centre x"},
                                                         {"cylinder centre x", "cylinder centre y"}};
                arg_need(g, argc, i, 3, ps);
                w.style = W_CYLINDER;
                w.cylaxis = ps[0] - 'x';
                w.cylradius = arg_positive(g, argv[i + 1], "cylinder radius");
                w.cx = arg_double(g, argv[i + 2], centre[w.cylaxis][0]);
                w.cy = arg_double(g, argv[i + 3], centre[w.cylaxis][1]);
                i += 4;
            } else {
                gr_error(g, "fix wall/gran primitive '%.64s' is not supported (xplane, yplane, "
                            "zplane, xcylinder, ycylinder or zcylinder)", ps);
            }
        } else if (strcmp(argv[i], "mesh")) {
            gr_error(g, "fix wall/gran model ...: unknown keyword '%.64s' (expected primitive "
                        "or mesh)", argv[i]);
        } else {
            w.style = W_MESH;
            i = mesh_surface_parse_list(g, argc, argv, i, w.mesh.id, MESH_WALLS_MAX, &w.mesh.n,
                                        "fix wall/gran mesh");
        }
        goto options;
    }
    if (w.model == WG_GRANULAR) {
        i = 1 + parse_granular(g, &w, argc - 1, argv + 1);
        if (own) {
            own_meshes(g, f, &w, n);
            goto options;
        }
        if (i >= argc)
            gr_error(g, "fix wall/gran granular: missing the wall style (xplane, yplane, "
                        "zplane, zcylinder or region) after the model");
    } else {
        i = parse_classic(g, &w, argc, argv);
        if (own) {
            own_meshes(g, f, &w, n);
            goto options;
        }
    }
    ws = argv[i];
    int is_region = !strcmp(f->style->name, "wall/gran/region");
    if (w.mdr && !is_region) /* LAMMPS's FixGranularMDR::setup_pre_force */
        gr_error(g, "MDR model currently only supports fix wall/gran/region, not fix wall/gran");
    if (is_region != !strcmp(ws, "region"))
        gr_error(g, is_region ? "fix wall/gran/region expects 'region ID' after the "
                                "coefficients, got '%.64s'"
                              : "fix wall/gran: wall style '%.64s' belongs to fix "
                                "wall/gran/region",
                 ws);
    if (is_region) {
        arg_need(g, argc, i, 1, ws);
        w.style = W_REGION;
        const char *id = argv[i + 1];
        if (strlen(id) >= GR_NAMELEN)
            gr_error(g, "fix wall/gran/region: region ID too long");
        region_get(g, id);
        strcpy(w.region_id, id);
        i += 2;
    } else if (!strcmp(ws, "xplane") || !strcmp(ws, "yplane") || !strcmp(ws, "zplane")) {
        arg_need(g, argc, i, 2, ws);
        w.style = ws[0] - 'x';
        w.lo = parse_face(g, argv[i + 1], -WALL_FAR, "wall lo position");
        w.hi = parse_face(g, argv[i + 2], WALL_FAR, "wall hi position");
        if (w.lo >= w.hi)
            gr_error(g, "fix wall/gran %s: lo (%g) must be below hi (%g)", ws, w.lo, w.hi);
        i += 3;
    } else if (!strcmp(ws, "zcylinder")) {
        arg_need(g, argc, i, 1, ws);
        w.style = W_CYLINDER;
        w.cylaxis = 2;
        w.cylradius = arg_positive(g, argv[i + 1], "cylinder radius");
        i += 2;
    } else if (!strcmp(ws, "mesh")) {
        /* LIGGGHTS: mesh n_meshes N meshes ID1 ... IDN */
        if (w.model == WG_GRANULAR && (int)w.param[GR_NMODEL] == GR_N_JKR)
            gr_error(g, "fix wall/gran mesh: the granular jkr normal model is not supported for "
                        "meshes (hooke, hertz, hertz/material or dmt are)");
        w.style = W_MESH;
        i = mesh_surface_parse_list(g, argc, argv, i, w.mesh.id, MESH_WALLS_MAX, &w.mesh.n,
                                    "fix wall/gran mesh");
    } else {
        gr_error(g, "unknown fix wall/gran wall style '%.64s' (expected xplane, yplane, zplane, "
                    "zcylinder or mesh)", ws);
    }
options:
    w.heat = w.model == WG_GRANULAR && (int)w.param[GR_HMODEL] != GR_H_NONE;
    while (i < argc) {
        if (liggghts_model(w.model) && !strcmp(argv[i], "store_force")) {
            arg_need(g, argc, i, 1, "store_force");
            if (arg_yesno(g, argv[i + 1], "store_force"))
                gr_error(g, "fix wall/gran keyword 'store_force yes' is not supported");
            i += 2;
        } else if (liggghts_model(w.model) && !strcmp(argv[i], "wiggle")) {
            gr_error(g, "fix wall/gran model ...: LIGGGHTS has no wiggle (use shear, or fix "
                        "move/mesh on a mesh)");
        } else if (!strcmp(argv[i], "temperature")) { /* LAMMPS 2023: the wall's temperature */
            arg_need(g, argc, i, 1, "temperature");
            if (!strncmp(argv[i + 1], "v_", 2)) {
                if (strlen(argv[i + 1] + 2) >= sizeof w.tvar || !argv[i + 1][2])
                    gr_error(g, "fix wall/gran temperature: bad variable name '%.64s'",
                             argv[i + 1]);
                strcpy(w.tvar, argv[i + 1] + 2);
            } else {
                w.twall = arg_double(g, argv[i + 1], "wall temperature");
            }
            w.twall_set = 1;
            i += 2;
        } else if (!strcmp(argv[i], "wiggle")) {
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
        } else if (!strcmp(argv[i], "contacts")) { /* LAMMPS 2023: the per-atom array */
            if (w.style == W_MESH || liggghts_model(w.model))
                gr_error(g, "fix wall/gran keyword 'contacts' is LAMMPS's, for its plane, "
                            "zcylinder and region walls (not meshes or LIGGGHTS's 'model ...' "
                            "form)");
            w.law.contacts_on = 1;
            i += 1;
        } else if (w.style == W_REGION) {
            gr_error(g, "unknown fix wall/gran/region keyword '%.64s'", argv[i]);
        } else if (w.style == W_MESH) {
            gr_error(g, own ? "fix surface/global model %s: unexpected word '%.64s'"
                            : "unknown fix wall/gran mesh keyword '%.64s'",
                     own ? argv[0] : argv[i], argv[i]);
        } else {
            gr_error(g, "unknown fix wall/gran keyword '%.64s' (expected wiggle or shear)",
                     argv[i]);
        }
    }
    if (w.heat != w.twall_set)
        gr_error(g, "Must define wall temperature with heat model (fix wall/gran granular ... "
                    "heat area|radius k ... temperature T)");
    if (w.style == W_REGION && (w.wiggle || w.wshear))
        gr_error(g, "fix wall/gran/region: no wiggle or shear (move the region with its move "
                    "and rotate keywords)");
    if (w.style == W_MESH && (w.wiggle || w.wshear))
        gr_error(g, "fix wall/gran mesh: wiggle and shear do not apply to meshes (use fix "
                    "move/mesh)");
    /* LAMMPS refuses a wall across a periodic dimension; LIGGGHTS's primitive walls
     * (model ...) are allowed there and act on the atoms' positions in the box */
    const int lg = liggghts_model(w.model);
    if (!lg && w.style <= W_ZPLANE && g->dom.periodic[w.style])
        gr_error(g, "cannot use a %s wall in the periodic dimension %c", ws, 'x' + w.style);
    if (!lg && w.style == W_CYLINDER && (g->dom.periodic[(w.cylaxis + 1) % 3] ||
                                         g->dom.periodic[(w.cylaxis + 2) % 3]))
        gr_error(g, "cannot use a %s wall with periodic %c or %c", ws,
                 'x' + (w.cylaxis + 1) % 3, 'x' + (w.cylaxis + 2) % 3);
    if (w.wiggle && w.wshear)
        gr_error(g, "cannot both wiggle and shear a wall");
    if (w.wiggle && w.style == W_CYLINDER && w.axis != w.cylaxis)
        gr_error(g, "a %s wall can only wiggle along %c", ws, 'x' + w.cylaxis);
    if (w.wshear && w.style <= W_ZPLANE && w.axis == w.style)
        gr_error(g, "a %s wall cannot shear along its normal %c", ws, 'x' + w.axis);
    if (w.wiggle)
        w.omega = 2.0 * M_PI / w.period;
    w.time_origin = g->step;

    struct wall *pw = gr_malloc(g, sizeof *pw);
    *pw = w;
    f->data = pw;
    f->peratom_flag = w.law.contacts_on;
    f->size_peratom_cols = w.law.contacts_on ? WALL_CONTACT_W : 0;
    f->hooks = HOOK_POST_FORCE;
    /* a plane, cylinder or mesh: its geometry a function of the step (a mesh's
     * pose: fix move/mesh), its kernel halts */
    f->halts = w.style != W_REGION && !w.tvar[0];
    f->needs = NEED_ROTATION;
    f->sources[f->nsources++] = "pair_gran_hooke.cl";
    f->sources[f->nsources++] = "pair_gran_hooke_history.cl";
    f->sources[f->nsources++] = "pair_gran_hertz_history.cl";
    f->sources[f->nsources++] = "gran_heat.cl";
    f->sources[f->nsources++] = "pair_granular.cl";
    f->sources[f->nsources++] = "pair_gran.cl";
    f->sources[f->nsources++] = "wall.cl";
    f->sources[f->nsources++] = "wall_region.cl";
    f->sources[f->nsources++] = "wall_gran_kernels.h";
    f->sources[f->nsources++] = "fix_wall_gran.cl";
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    create_wall(g, f, argc, argv, NULL, 0);
}

void wall_gran_create_own(struct gravel *g, struct fix *f, int argc, char **argv,
                          struct mesh_surface **own, int n)
{
    create_wall(g, f, argc, argv, own, n);
}

struct mesh_walls *wall_gran_meshes(struct fix *f)
{
    return &((struct wall *)f->data)->mesh;
}

/* The wall at the current step: wiggle moves the faces along the axis and
 * gives the surface velocity; shear moves the surface tangentially (a
 * cylinder sheared across its axis turns, per atom: LAMMPS's zcylinder at
 * surface speed vshear, LIGGGHTS's at angular velocity vshear). */
static struct wall_geom geometry(struct gravel *g, const struct wall *w)
{
    struct wall_geom geom = {0};
    double lo = w->lo, hi = w->hi;
    if (w->wiggle) {
        double arg = w->omega * (double)(g->step - w->time_origin) * g->dt;
        if (w->style == w->axis) {
            lo = w->lo + w->amplitude - w->amplitude * cos(arg);
            hi = w->hi + w->amplitude - w->amplitude * cos(arg);
        }
        geom.v[w->axis] = w->amplitude * w->omega * sin(arg);
    } else if (w->wshear) {
        geom.v[w->axis] = w->vshear;
    }
    if (w->style == W_CYLINDER) {
        geom.kind = WALL_CYLINDER;
        geom.axis = w->cylaxis;
        geom.radius = w->cylradius;
        geom.cx = w->cx;
        geom.cy = w->cy;
        geom.cyl_shear = !w->wshear || w->axis == w->cylaxis ? CYL_SHEAR_NONE
                         : liggghts_model(w->model)         ? CYL_SHEAR_OMEGA
                                                            : CYL_SHEAR_SPEED;
        geom.vshear = w->vshear;
        if (geom.cyl_shear)
            geom.v[0] = geom.v[1] = geom.v[2] = 0.0;
    } else {
        geom.kind = WALL_PLANE;
        geom.axis = w->style;
        geom.lo = lo;
        geom.hi = hi;
    }
    return geom;
}

int wall_gran_mdr(const struct fix *f, struct wall_mdr *out)
{
    if (strcmp(f->style->name, "wall/gran/region") && strcmp(f->style->name, "wall/gran"))
        return 0;
    const struct wall *w = f->data;
    if (!w || !w->mdr || w->style != W_REGION)
        return 0;
    memcpy(out->par, w->mdr_par, sizeof out->par);
    out->region = w->region;
    out->hoff = (int)w->param[GRW_HMDR];
    out->hw = w->history;
    out->slots = w->wreg.slots;
    return 1;
}

void wall_gran_mdr_probe(struct gravel *g, struct fix *f, cl_mem out)
{
    struct wall *w = f->data;
    wall_region_probe(g, f, &w->wreg, w->region, out);
}

static int region_nodes(const struct region *r) { return r->nsub ? r->nsub : 1; }

static struct region *region_node(struct region *r, int k) { return r->nsub ? r->sub[k] : r; }

/* restart: the region's motion state when the restart file's region is the
 * same (style and node count), else a warning (LAMMPS resets the motion) */
static void restore_motion(struct gravel *g, struct fix *f, struct wall *w)
{
    if (!w->rs_pending || !w->region)
        return;
    w->rs_pending = 0;
    if (strcmp(w->rs_style, w->region->style->name) != 0 ||
        w->rs_n != region_nodes(w->region)) {
        gr_warn(g, "fix %s: region %s differs from the restart file's, resetting its motion",
                f->id, w->region_id);
        return;
    }
    for (int k = 0; k < w->rs_n; k++)
        memcpy(region_node(w->region, k)->prev, w->rs_prev[k], sizeof w->rs_prev[k]);
}

static void init(struct gravel *g, struct fix *f)
{
    struct wall *w = f->data;
    struct engine *e = eng_get(g);
    const enum wall_gran_source source = w->style == W_MESH     ? WG_MESH
                                         : w->style == W_REGION ? WG_REGION
                                                                : WG_WALL;
    /* a jkr wall is held beyond touch */
    const int jkr = w->model == WG_GRANULAR && (int)w->param[GR_NMODEL] == GR_N_JKR;
    const char *kname = NULL;
    for (size_t k = 0; k < sizeof wall_gran_kernel / sizeof *wall_gran_kernel; k++)
        if (wall_gran_kernel[k].source == source && wall_gran_kernel[k].model == w->model &&
            wall_gran_kernel[k].jkr == jkr)
            kname = wall_gran_kernel[k].name;
    if (!kname)
        gr_error(g, "internal error: fix %s: no wall/gran kernel for this wall and model", f->id);
    w->law.kernel = eng_kernel(g, kname);
    w->kname = kname;
    w->law.history = w->history;
    w->law.by_type = 0;
    w->law.nparam = 0;
    w->law.inclusive = 1;
    if (w->heat && !(g->atoms.heat_flag & ATOM_HEAT_T))
        gr_error(g, "Heat conduction in fix wall/gran requires atom style with temperature "
                    "property (fix property/atom temperature heatflow)");
    if (w->heat && !(g->atoms.heat_flag & ATOM_HEAT_Q))
        gr_error(g, "Heat conduction in fix wall/gran requires atom style with heatflow "
                    "property (fix property/atom temperature heatflow)");
    w->law.heat = w->heat;
    w->law.twall = w->twall;
    if (w->tvar[0]) { /* LAMMPS's FixWallGran::init checks */
        if (!var_exists(g, w->tvar))
            gr_error(g, "Variable %s for fix wall/gran does not exist", w->tvar);
        if (!var_is_equal(g, w->tvar))
            gr_error(g, "Variable %s for fix wall/gran must be an equal style variable", w->tvar);
    }
    if (liggghts_model(w->model)) { /* the table by (particle type, wall type) */
        int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
        char who[GR_NAMELEN + 32];
        snprintf(who, sizeof who, "fix %s (wall/gran)", f->id);
        if (w->wtype > nt)
            gr_error(g, "%s: primitive type %d is beyond the %d atom type(s)", who, w->wtype, nt);
        lg_check(g, &w->lg, nt, who);
        free(w->table);
        w->table = gr_calloc(g, (size_t)nt * nt * LG_NPARAM, sizeof(double));
        w->table_nt = nt;
        for (int I = 1; I <= nt; I++)
            for (int J = 1; J <= nt; J++)
                lg_pack(g, &w->lg, nt, I, J, 1,
                        w->table + ((size_t)(I - 1) * nt + (J - 1)) * LG_NPARAM, who);
        lg_check_yield(g, &w->lg, w->table, nt, w->style == W_MESH ? -1 : w->wtype, who);
        w->law.by_type = w->style == W_MESH ? 0 : -w->wtype;
        w->law.nparam = LG_NPARAM;
    }
    /* -compat lammps2021: FixWallGran::init converts a tsuji restitution at
     * every run, so each later run converts the converted value again */
    if (w->inits++ > 0 && g->opt.lammps2021 && w->model == WG_GRANULAR &&
        (int)w->param[GR_DMODEL] == GR_D_TSUJI)
        w->param[GR_DAMP] = granular_tsuji(w->param[GR_DAMP], 1);
    /* parameters: re-uploaded every run (precision may change between runs) */
    if (w->law.param)
        clReleaseMemObject(w->law.param);
    w->law.param = NULL;
    if (liggghts_model(w->model)) {
        size_t nq = (size_t)w->table_nt * w->table_nt * LG_NPARAM;
        w->law.param = eng_alloc(g, nq * e->rsz, "fix wall/gran parameters");
        eng_write_reals(g, w->law.param, nq, w->table);
    } else {
        w->law.param = eng_alloc(g, (size_t)w->nparam * e->rsz, "fix wall/gran parameters");
        eng_write_reals(g, w->law.param, (size_t)w->nparam, w->param);
    }
    if (w->style == W_MESH) {
        f->peratom_bytes = mesh_walls_init(g, f, &w->mesh, w->history);
        return;
    }
    if (w->style == W_REGION) {
        struct region *r = region_find(g, w->region_id);
        if (!r)
            gr_error(g, "fix %s: region '%s' for fix wall/gran/region does not exist", f->id,
                     w->region_id);
        if (w->region && (strcmp(w->region_style, r->style->name) != 0 ||
                          w->region_nsub != r->nsub))
            gr_warn(g, "fix %s: region %s was re-defined between runs, resetting its motion",
                       f->id, w->region_id);
        w->region = r;
        snprintf(w->region_style, sizeof w->region_style, "%s", r->style->name);
        w->region_nsub = r->nsub;
        restore_motion(g, f, w);
        char who[GR_NAMELEN + 32];
        snprintf(who, sizeof who, "fix %s (wall/gran/region)", f->id);
        f->peratom_bytes = wall_region_init(g, &w->wreg, r, &w->law, who);
        return;
    }
    struct wall_geom geom = geometry(g, w);
    f->peratom_bytes = wall_peratom_bytes(g, &geom, &w->law);
}

/* `contacts`: a device record per atom for this launch (cleared by it) */
static void contacts_reserve(struct gravel *g, struct wall *w)
{
    if (!w->law.contacts_on)
        return;
    const size_t n = (size_t)eng_atoms(g)->n;
    if (w->law.contacts && w->contacts_cap >= n && n > 0)
        return;
    if (w->law.contacts)
        clReleaseMemObject(w->law.contacts);
    w->contacts_cap = n > 0 ? n : 1;
    w->law.contacts = eng_alloc(g, w->contacts_cap * WALL_CONTACT_W * eng_get(g)->rsz,
                                "fix wall/gran contacts");
}

/* f_ID[1..8] (LAMMPS's per-atom array of `contacts`): the last launch's
 * records, the contact point in box coordinates; zero for an atom the wall
 * has not seen (before a run, atoms added since) */
static const double *contacts_values(struct gravel *g, struct fix *f)
{
    struct wall *w = f->data;
    const size_t n = (size_t)g->atoms.n, nw = n * WALL_CONTACT_W;
    double *v = realloc(w->contacts_host, (nw ? nw : 1) * sizeof *v);
    if (!v)
        gr_error(g, "fix %s: out of memory for its contacts", f->id);
    w->contacts_host = v;
    memset(v, 0, nw * sizeof *v);
    if (!w->law.contacts || !g->eng || (size_t)g->eng->a.n != n || w->contacts_cap < n)
        return v;
    run_sync_host(g); /* host order = device order */
    eng_read_reals(g, w->law.contacts, nw, v);
    for (size_t i = 0; i < n; i++)
        if (v[i * WALL_CONTACT_W] != 0)
            for (int q = 0; q < 3; q++)
                v[i * WALL_CONTACT_W + 4 + q] += g->eng->origin[q];
    return v;
}

/* A wall's state for this step's launch: twall (`temperature v_name`) and
 * the `contacts` records. */
static void launch_prepare(struct gravel *g, struct wall *w)
{
    if (w->tvar[0]) /* the kernels take twall as an argument at this launch */
        w->law.twall = var_compute_equal(g, w->tvar);
    contacts_reserve(g, w);
}

/* Whether fix o is a region wall of f's law (a kernel of the same name) */
static int region_same_law(const struct fix *o, const struct fix *f)
{
    const struct wall *wo = o->data, *wf = f->data;
    return o->style == f->style && wo->style == W_REGION && wo->kname == wf->kname;
}

/* The region walls one launch runs (src/contact/wall_region.c): the runs of
 * region walls of one law among the post_force calls, cut into sets of
 * RS_MAXWALL from the first (of 1 with GRAVEL_FUSE=0). Fills set and returns its size when region
 * wall f leads one, 0 when f is in the set of a fix called before it. */
static int region_set(struct gravel *g, struct fix *f, struct region_wall *set)
{
    int n = 0, k = 0, first;
    const struct hook_call *call = run_post_force_calls(g, &n), alone = {f, NULL};
    while (k < n && call[k].fix != f)
        k++;
    if (k == n) { /* not among the calls: on its own */
        call = &alone;
        k = 0;
        n = 1;
    }
    for (first = k; first > 0 && region_same_law(call[first - 1].fix, f); first--)
        ;
    const int most = g->eng->fused.on ? RS_MAXWALL : 1; /* GRAVEL_FUSE=0: one each */
    if ((k - first) % most)
        return 0;
    int nw = 0;
    for (; nw < most && k + nw < n; nw++) {
        struct fix *m = nw ? call[k + nw].fix : f;
        if (nw && !region_same_law(m, f))
            break;
        struct wall *w = m->data;
        launch_prepare(g, w);
        set[nw] = (struct region_wall){m, &w->wreg, w->region, &w->law};
    }
    return nw;
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct wall *w = f->data;
    if (w->style == W_REGION) {
        struct region_wall set[RS_MAXWALL];
        int nw = region_set(g, f, set);
        if (nw)
            wall_region_apply(g, set, nw);
        return;
    }
    launch_prepare(g, w);
    if (w->style == W_MESH) {
        mesh_walls_apply(g, f, &w->mesh, &w->law, liggghts_model(w->model));
        return;
    }
    struct wall_geom geom = geometry(g, w);
    wall_apply(g, f, &geom, &w->law);
}

static void destroy(struct fix *f)
{
    struct wall *w = f->data;
    if (w && w->law.param)
        clReleaseMemObject(w->law.param);
    if (w && w->law.contacts)
        clReleaseMemObject(w->law.contacts);
    if (w)
        free(w->contacts_host);
    if (w) {
        free(w->table);
        mesh_walls_release(&w->mesh);
        wall_region_release(&w->wreg);
    }
    free(w);
    f->data = NULL;
}

/* Restart state (restart.c): the time origin of wiggle (the step the fix
 * was created at), so a re-created fix continues the same oscillation; for
 * wall/gran/region also the region's style, node count and previous
 * displacement and angle per node (its wall velocity continues). */
#define RS_REGION (32 + sizeof(int32_t))

static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const struct wall *w = f->data;
    int64_t origin = w->time_origin;
    struct region *r = w->style == W_REGION ? region_find(g, w->region_id) : NULL;
    int32_t n = r ? region_nodes(r) : 0;
    size_t len = sizeof origin + (r ? RS_REGION + (size_t)n * 4 * sizeof(double) : 0);
    if (!buf || cap < len)
        return len;
    memcpy(buf, &origin, sizeof origin);
    if (r) {
        unsigned char *b = buf + sizeof origin;
        char st[32] = {0};
        snprintf(st, sizeof st, "%s", r->style->name);
        memcpy(b, st, 32);
        memcpy(b + 32, &n, sizeof n);
        for (int k = 0; k < n; k++)
            memcpy(b + RS_REGION + (size_t)k * 4 * sizeof(double), region_node(r, k)->prev,
                   4 * sizeof(double));
    }
    return len;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct wall *w = f->data;
    int64_t origin;
    if (len < sizeof origin)
        gr_error(g, "fix %s: restart state of %zu bytes, expected at least %zu", f->id, len,
                 sizeof origin);
    memcpy(&origin, buf, sizeof origin);
    w->time_origin = origin;
    if (len == sizeof origin)
        return;
    int32_t n = 0;
    if (len >= sizeof origin + RS_REGION)
        memcpy(&n, buf + sizeof origin + 32, sizeof n);
    if (w->style != W_REGION || n < 1 || n > WALL_REGION_MAXNODE ||
        len != sizeof origin + RS_REGION + (size_t)n * 4 * sizeof(double))
        gr_error(g, "fix %s: restart state of %zu bytes does not match this fix", f->id, len);
    const unsigned char *b = buf + sizeof origin;
    memcpy(w->rs_style, b, 32);
    w->rs_style[31] = '\0';
    w->rs_n = n;
    for (int k = 0; k < n; k++)
        memcpy(w->rs_prev[k], b + RS_REGION + (size_t)k * 4 * sizeof(double),
               4 * sizeof(double));
    w->rs_pending = 1;
    restore_motion(g, f, w);
}

/* reset_timestep: wiggle keeps its own clock (step - time_origin), so the
 * wall goes on oscillating from where it stood (LAMMPS 2021 restarts it) */
static void reset_step(struct gravel *g, struct fix *f, bigint shift)
{
    (void)g;
    ((struct wall *)f->data)->time_origin += shift;
}

const struct fix_style fix_style_wall_gran_region = {
    .name = "wall/gran/region",
    .flags = FIX_WALL,
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
    .write_restart = write_restart,
    .read_restart = read_restart,
    .reset_step = reset_step,
    .peratom_values = contacts_values,
};

const struct fix_style fix_style_wall_gran = {
    .name = "wall/gran",
    .flags = FIX_WALL,
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
    .write_restart = write_restart,
    .read_restart = read_restart,
    .reset_step = reset_step,
    .peratom_values = contacts_values,
};
