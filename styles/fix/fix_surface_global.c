/* fix_surface_global.c - `fix ID group surface/global input stl stype smol
 * FILE [input ...] model ptype stype fstyle args [model ...] [keyword value
 * ...]`: LAMMPS 4 Jul 2026's global granular surfaces (GRANSURF package),
 * 3d triangles, mapped onto gravel's mesh walls: the triangles of each
 * surface molecule ID become one triangle mesh (src/state/mesh.c: welding,
 * validation) and the fix is a `fix wall/gran <model> mesh` on those meshes
 * (styles/fix/fix_wall_gran.c, wall_gran_create_own), so the contact search,
 * the one contact body, its laws and history are the mesh wall's.
 *
 *   input stl stype smol FILE   triangles of an STL file (ASCII or binary),
 *                               surface type stype, molecule ID smol; repeatable
 *   input mol ID                the triangles of a molecule template (Points,
 *                               Triangles: their own types and molecule IDs)
 *   model ptype stype fstyle args   fstyle hooke | hooke/history | hertz/history
 *                               Kn Kt gamma_n gamma_t xmu dampflag, or granular
 *                               <pair granular's pair_coeff sub-models>; ptype and
 *                               stype take LAMMPS's asterisk ranges; every
 *                               (particle type, surface type) pair needs one, a
 *                               later one wins (LAMMPS). gravel applies one model
 *                               to every pair: models that differ are refused.
 *   smaxtype N, smaxmol N       largest surface type / molecule ID (checked)
 *   flat deg                    0..90; gravel's mesh contact (nearest feature of
 *                               each cluster of touching triangles) does not use
 *                               it: a value other than LAMMPS's 1 degree warns
 *   neighbor nsq | bin          contact search; no effect on the result here
 *   temperature T               the surface temperature of a heat sub-model
 *
 * As in LAMMPS both sides of a triangle act, the surface is the partner j
 * of a wall contact (radj = 0, meff = m_i, the wall stiffness formulas of
 * pair granular's walls), and triangles of different molecules never merge
 * contacts. `fix_modify ID move smol none | linear Vx Vy Vz | wiggle Ax Ay Az
 * T | rotate Px Py Pz Rx Ry Rz T | transrot Vx Vy Vz Px Py Pz Rx Ry Rz T`
 * moves the molecules smol (LAMMPS comma/asterisk list) from where they
 * stand, timed from that command (fix move's formulas, exact at every step:
 * fix_mesh_surface.c composes the pose). `fix_modify ID type/region stype
 * REGION` and `mol/region smol REGION` (LAMMPS 4 Jul 2026) set the type or
 * molecule ID of the triangles whose centroid is in REGION (region_assign).
 * Refused: 2d line surfaces, `move
 * variable`, mol/region after a run or a move, JKR (LAMMPS refuses it too),
 * more than MESH_WALLS_MAX molecule IDs. No restart state
 * (LAMMPS writes none). */
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix_wall_gran.h"
#include "surface_common.h"
#include "log.h"
#include "molecule.h"
#include "region.h"
#include "rigid_math.h"


static const char *const sg_options[] = {"smaxtype", "smaxmol", "flat", "neighbor",
                                         "temperature", NULL};

static int is_option(const char *s)
{
    for (int k = 0; sg_options[k]; k++)
        if (!strcmp(s, sg_options[k]))
            return 1;
    return 0;
}

struct sg_model {
    int plo, phi, slo, shi;
    int first, nword;           /* its fstyle and args: argv[first .. first + nword) */
};

static int same_model(char **argv, const struct sg_model *a, const struct sg_model *b)
{
    if (a->nword != b->nword)
        return 0;
    for (int k = 0; k < a->nword; k++)
        if (strcmp(argv[a->first + k], argv[b->first + k]))
            return 0;
    return 1;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (g->dom.dimension == 2)
        gr_error(g, "fix surface/global: 2d line-segment surfaces are not supported by gravel "
                    "(3d triangles only)");
    struct sg_build *b = gr_calloc(g, 1, sizeof *b);
    f->data = b; /* freed by destroy() if an error follows */
    f->hooks = 0;
    int i = sg_parse_inputs(g, b, argc, argv, "fix surface/global");
    /* models */
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    struct sg_model mod[64];
    int nmod = 0;
    while (i < argc && !strcmp(argv[i], "model")) {
        arg_need(g, argc, i, 3, "model");
        if (nmod == 64)
            gr_error(g, "fix surface/global: more than 64 model keywords");
        struct sg_model *m = &mod[nmod++];
        arg_type_range(g, argv[i + 1], nt, &m->plo, &m->phi);
        arg_range(g, argv[i + 2], SG_MAXSURFTYPE, &m->slo, &m->shi, "surface type");
        m->first = i + 3;
        const char *fs = argv[m->first];
        if (strcmp(fs, "hooke") && strcmp(fs, "hooke/history") && strcmp(fs, "hertz/history") &&
            strcmp(fs, "granular"))
            gr_error(g, "fix surface/global model: unknown fstyle '%.64s' (expected hooke, "
                        "hooke/history, hertz/history or granular)", fs);
        int j = m->first + 1;
        while (j < argc && strcmp(argv[j], "model") && !is_option(argv[j]))
            j++;
        m->nword = j - m->first;
        i = j;
    }
    if (!nmod)
        gr_error(g, "Fix surface/global command requires model keyword");
    int maxtype = 0, maxmol = 0;
    for (int t = 0; t < b->ntri; t++) {
        maxtype = b->ttype[t] > maxtype ? b->ttype[t] : maxtype;
        maxmol = b->tmol[t] > maxmol ? b->tmol[t] : maxmol;
    }
    const char *temperature = NULL;
    for (; i < argc; i += 2) {
        const char *kw = argv[i];
        if (!is_option(kw))
            gr_error(g, "unknown fix surface/global keyword '%.64s' (expected smaxtype, smaxmol, "
                        "flat, neighbor or temperature after the input and model keywords)", kw);
        arg_need(g, argc, i, 1, kw);
        const char *v = argv[i + 1];
        if (!strcmp(kw, "smaxtype")) {
            int s = arg_int(g, v, "smaxtype");
            if (s > SG_MAXSURFTYPE)
                gr_error(g, "Fix surface/global smaxtype > MAXSURFTYPE (%d)", SG_MAXSURFTYPE);
            if (s < maxtype)
                gr_error(g, "Fix surface/global smaxtype < input surf types (%d)", maxtype);
            maxtype = s;
        } else if (!strcmp(kw, "smaxmol")) {
            int s = arg_int(g, v, "smaxmol");
            if (s < maxmol)
                gr_error(g, "fix surface/global smaxmol < input surf molecule IDs (%d)", maxmol);
            maxmol = s;
        } else if (!strcmp(kw, "flat")) {
            double a = arg_double(g, v, "flat");
            if (a < 0.0 || a > 90.0)
                gr_error(g, "Invalid value for fix surface/global flat (%g: 0 to 90 degrees)", a);
            if (a != 1.0)
                gr_warn(g, "fix %s: flat %g has no effect: gravel's mesh walls keep the nearest "
                           "feature of touching triangles, whatever their angle", f->id, a);
        } else if (!strcmp(kw, "neighbor")) {
            if (strcmp(v, "nsq") && strcmp(v, "bin"))
                gr_error(g, "fix surface/global neighbor expects nsq or bin, got '%.64s'", v);
        } else {
            temperature = v;
        }
    }
    /* the model of every type pair (LAMMPS types2model: the last one wins) */
    const struct sg_model *used = NULL;
    for (int p = 1; p <= nt; p++)
        for (int s = 1; s <= maxtype; s++) {
            const struct sg_model *w = NULL;
            for (int k = 0; k < nmod; k++) {
                int shi = mod[k].shi == SG_MAXSURFTYPE ? maxtype : mod[k].shi;
                if (p >= mod[k].plo && p <= mod[k].phi && s >= mod[k].slo && s <= shi)
                    w = &mod[k];
            }
            if (!w)
                gr_error(g, "Fix surface/global type pair is missing a granular model "
                            "(particle type %d, surface type %d)", p, s);
            if (used && !same_model(argv, used, w))
                gr_error(g, "fix surface/global: the models of the type pairs differ (particle "
                            "type %d, surface type %d has its own); gravel applies one model to "
                            "every particle/surface type pair", p, s);
            used = w;
        }
    for (int k = 1; strcmp(argv[used->first], "granular") && k < used->nword; k++)
        if (!strcmp(argv[used->first + k], "limit_damping"))
            gr_error(g, "fix surface/global: limit_damping with the classic model %s is not "
                        "supported (use granular ... limit_damping)", argv[used->first]);
    sg_make_wall(g, f, b, used->nword, argv + used->first, temperature, maxtype, maxmol);
    f->needs |= NEED_ROTATION; /* LAMMPS: requires atom attributes radius and omega */
}

/* Bake mesh ms's current pose into its vertices (its motions then start
 * from here, as LAMMPS's fix_modify move starts from the current points). */
static void bake_pose(struct gravel *g, struct mesh_surface *ms)
{
    struct mesh_pose p;
    mesh_surface_pose_of(g, ms, NULL, &p);
    for (int v = 0; v < ms->m.nvert; v++) {
        double *x = ms->m.vert + 3 * v, y[3];
        for (int r = 0; r < 3; r++)
            y[r] = p.R[3 * r] * x[0] + p.R[3 * r + 1] * x[1] + p.R[3 * r + 2] * x[2] + p.d[r];
        memcpy(x, y, sizeof y);
    }
    mesh_surface_normals(g, ms);
    ms->nmotion = 0;
}

static double move_num(struct gravel *g, const char *s, const char *what)
{
    return strcmp(s, "NULL") ? arg_double(g, s, what) : 0.0; /* NULL: no motion along it */
}

/* The centroid of triangle t of mesh ms where it stands now. */
static void tri_centroid(struct gravel *g, struct mesh_surface *ms, int t, double c[3])
{
    struct mesh_pose p;
    mesh_surface_pose_of(g, ms, NULL, &p);
    double x0[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        for (int q = 0; q < 3; q++)
            x0[q] += ms->m.vert[3 * ms->m.tri[3 * t + k] + q] / 3.0;
    mesh_pose_point(&p, x0, c);
}

/* mol/region: the wall's own meshes replaced by those of b (the same
 * triangles with their new molecule IDs); b is freed, also on an error. */
static void regroup(struct gravel *g, struct mesh_walls *mw, struct sg_build *b)
{
    int smaxtype = mw->own[0]->smaxtype, smaxmol = mw->own[0]->smaxmol;
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        sg_build_free(b);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    sg_build_meshes(g, b);
    g->err.jmp = outer;
    mesh_walls_release(mw); /* frees the old meshes and their device copies */
    memset(mw->wm, 0, sizeof mw->wm);
    for (int m = 0; m < b->n; m++) {
        b->ms[m]->smaxtype = smaxtype;
        b->ms[m]->smaxmol = smaxmol;
        mw->own[m] = b->ms[m];
    }
    mw->n = b->n;
    b->n = 0;
    sg_build_free(b);
}

/* fix_modify ID type/region stype REGION | mol/region smol REGION (LAMMPS 4
 * Jul 2026): the triangles whose centroid is in the region take that type
 * or molecule ID. gravel applies one model to every type pair, each type
 * up to smaxtype already checked to have it: a type changes nothing in the
 * forces. A molecule ID regroups the meshes (one per ID), before any run
 * and any fix_modify move. */
static int region_assign(struct gravel *g, struct fix *f, int argc, char **argv)
{
    int istype = !strcmp(argv[0], "type/region");
    arg_need(g, argc, 0, 2, argv[0]);
    struct mesh_walls *mw = wall_gran_meshes(f);
    int hi = istype ? mw->own[0]->smaxtype : mw->own[0]->smaxmol;
    int v = arg_int(g, argv[1], istype ? "surface type" : "surface molecule ID");
    if (v <= 0 || v > hi)
        gr_error(g, "Invalid fix_modify %s surf %s %d (1..%d: fix surface/global %s)", argv[0],
                 istype ? "type" : "mol", v, hi, istype ? "smaxtype" : "smaxmol");
    struct region *r = region_find(g, argv[2]);
    if (!r)
        gr_error(g, "Fix_modify %s region %.64s does not exist", argv[0], argv[2]);
    region_prematch(g, r);
    int ntri = 0;
    for (int m = 0; m < mw->n; m++) {
        ntri += mw->own[m]->m.ntri;
        if (!istype && (mw->own[m]->nmotion || mw->wm[m].tri))
            gr_error(g, "fix_modify %s mol/region after a run or a fix_modify move is not "
                        "supported by gravel (it regroups the surfaces: give it first)", f->id);
    }
    struct sg_build *b = NULL;
    if (!istype) {
        b = gr_calloc(g, 1, sizeof *b);
        b->soup = malloc((size_t)ntri * 9 * sizeof *b->soup);
        b->ttype = malloc((size_t)ntri * sizeof *b->ttype);
        b->tmol = malloc((size_t)ntri * sizeof *b->tmol);
        b->cap = ntri;
        b->who = "fix_modify mol/region";
        if (!b->soup || !b->ttype || !b->tmol) {
            sg_build_free(b);
            gr_error(g, "fix_modify mol/region: out of memory for %d triangles", ntri);
        }
    }
    int count = 0;
    for (int m = 0; m < mw->n; m++) {
        const struct mesh *ms = &mw->own[m]->m;
        for (int t = 0; t < ms->ntri; t++) {
            double c[3];
            tri_centroid(g, mw->own[m], t, c);
            int in = region_match(r, c);
            count += in;
            const int *k = ms->tri + 3 * t;
            if (b)
                sg_soup_add(b, ms->vert + 3 * k[0], ms->vert + 3 * k[1], ms->vert + 3 * k[2],
                         mw->own[m]->type, in ? v : mw->own[m]->mol);
        }
    }
    if (b)
        regroup(g, mw, b);
    gr_print(g, "Fix_modify %s:\n  %d surfs assigned to %s %d\n", argv[0], count,
             istype ? "type" : "mol", v);
    return 3;
}

/* fix_modify ID move smol mstyle args | type/region ... | mol/region ... */
static int modify_param(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (!strcmp(argv[0], "type/region") || !strcmp(argv[0], "mol/region"))
        return region_assign(g, f, argc, argv);
    if (strcmp(argv[0], "move"))
        return 0;
    arg_need(g, argc, 0, 2, "move");
    struct mesh_walls *mw = wall_gran_meshes(f);
    int maxmol = 0;
    for (int m = 0; m < mw->n; m++)
        maxmol = mw->own[m]->mol > maxmol ? mw->own[m]->mol : maxmol;
    /* the molecules: comma-separated LAMMPS ranges */
    int sel[MESH_WALLS_MAX] = {0};
    char list[256];
    snprintf(list, sizeof list, "%s", argv[1]);
    for (char *tok = strtok(list, ","); tok; tok = strtok(NULL, ",")) {
        int lo, hi;
        arg_range(g, tok, maxmol, &lo, &hi, "surface molecule ID");
        for (int m = 0; m < mw->n; m++)
            sel[m] |= mw->own[m]->mol >= lo && mw->own[m]->mol <= hi;
    }
    const char *st = argv[2];
    struct mesh_motion mo[MESH_OWN_MOTIONS];
    memset(mo, 0, sizeof mo);
    int nmo = 0, used;
    if (!strcmp(st, "none")) {
        used = 3;
    } else if (!strcmp(st, "linear") || !strcmp(st, "wiggle")) {
        int wig = st[0] == 'w';
        arg_need(g, argc, 2, wig ? 4 : 3, st);
        mo[0].kind = wig ? MOVE_WIGGLE : MOVE_LINEAR;
        for (int k = 0; k < 3; k++)
            mo[0].v[k] = move_num(g, argv[3 + k], wig ? "wiggle amplitude" : "linear velocity");
        if (wig)
            mo[0].period = arg_positive(g, argv[6], "wiggle period");
        nmo = 1;
        used = wig ? 7 : 6;
    } else if (!strcmp(st, "rotate") || !strcmp(st, "transrot")) {
        int tr = st[0] == 't';
        arg_need(g, argc, 2, tr ? 10 : 7, st);
        const int o = tr ? 6 : 3;
        mo[0].kind = MOVE_ROTATE;
        for (int k = 0; k < 3; k++) {
            mo[0].origin[k] = arg_double(g, argv[o + k], "rotate point");
            mo[0].axis[k] = arg_double(g, argv[o + 3 + k], "rotate axis");
        }
        if (rm_unit_axis(mo[0].axis, mo[0].axis))
            gr_error(g, "Zero length rotation vector with fix_modify %s move %s", f->id, st);
        mo[0].period = arg_positive(g, argv[o + 6], "rotate period");
        nmo = 1;
        if (tr) { /* the axis through P translates at V: rotate, then linear */
            mo[1].kind = MOVE_LINEAR;
            for (int k = 0; k < 3; k++)
                mo[1].v[k] = arg_double(g, argv[3 + k], "transrot velocity");
            nmo = 2;
        }
        used = o + 7;
    } else if (!strcmp(st, "variable")) {
        gr_error(g, "fix_modify %s move variable is not supported by gravel's fix "
                    "surface/global (linear, wiggle, rotate, transrot or none)", f->id);
    } else {
        gr_error(g, "fix_modify %s move: unknown style '%.64s' (expected none, linear, wiggle, "
                    "rotate, transrot or variable)", f->id, st);
    }
    for (int m = 0; m < mw->n; m++) {
        if (!sel[m])
            continue;
        bake_pose(g, mw->own[m]);
        for (int k = 0; k < nmo; k++) {
            mw->own[m]->motion[k] = mo[k];
            mw->own[m]->motion[k].time_origin = g->step;
        }
        mw->own[m]->nmotion = nmo;
    }
    return used;
}

/* reset_timestep: the motions keep their own clocks */
static void reset_step(struct gravel *g, struct fix *f, bigint shift)
{
    fix_style_wall_gran.reset_step(g, f, shift);
    struct mesh_walls *mw = wall_gran_meshes(f);
    for (int m = 0; m < mw->n; m++)
        for (int k = 0; k < mw->own[m]->nmotion; k++)
            mw->own[m]->motion[k].time_origin += shift;
}

const struct fix_style fix_style_surface_global = {
    .name = "surface/global",
    .create = create,
    .init = sg_init,
    .post_force = sg_post_force,
    .destroy = sg_destroy,
    .modify_param = modify_param,
    .reset_step = reset_step,
};
