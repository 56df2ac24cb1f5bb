/* fix_wall_pair.c - `fix ID group wall/pair xplane|yplane|zplane lo hi`:
 * flat, stationary walls whose contact law is the active pair style, a
 * front-end of the wall stage of the contact pipeline (src/contact/wall.c,
 * kernels/wall.cl, kernel wall_pair). The pair law (PAIR_EVAL, or PAIR_EVAL_ROW
 * with its whole history row: pair granular) sees the wall as
 * particle j with the contract of src/style/pair.h: radj = 0, radsum = reff = radi,
 * omega_j = 0, v_j = 0, meff = m_i (the wall is infinitely heavy), and the
 * parameters of type pair (itype, itype). lo or hi may be NULL (no face).
 * Like LAMMPS fix wall/gran, only the nearer face acts on a particle; with a
 * history pair style the contact history is kept per (atom, face).
 * fix wall/gran keeps the LAMMPS models; this fix gives every pair style of
 * gravel (linear/restitution, hertz/mindlin, ...) a wall with the same law.
 *
 * `fix ID group wall/pair mesh n_meshes N meshes ID ...`: the same law
 * against triangle meshes (fix mesh/surface; kernel mesh_pair), with the
 * parameters of type pair (itype, mesh type) and, for rolling resistance,
 * the mesh's angular velocity as omega_j. */
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fix_mesh_surface.h"
#include "pair.h"
#include "wall.h"

struct wallp {
    struct wall_geom geom;
    struct wall_law law;
    struct mesh_walls mesh;     /* mesh.n > 0: mesh walls */
};

static double face(struct gravel *g, const char *s, double null_value, const char *what)
{
    return !strcmp(s, "NULL") ? null_value : arg_double(g, s, what);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct wallp *w = gr_calloc(g, 1, sizeof *w);
    f->data = w;
    if (argc >= 1 && !strcmp(argv[0], "mesh")) {
        int i = mesh_surface_parse_list(g, argc, argv, 0, w->mesh.id, MESH_WALLS_MAX,
                                        &w->mesh.n, "fix wall/pair mesh");
        if (i < argc)
            gr_error(g, "fix wall/pair mesh: unexpected argument '%.64s'", argv[i]);
        f->hooks = HOOK_POST_FORCE;
        f->sources[f->nsources++] = "wall.cl";
        return;
    }
    if (argc != 3)
        gr_error(g, "fix wall/pair expects xplane|yplane|zplane lo hi or mesh n_meshes N "
                    "meshes ID ..., got %d argument(s)", argc);
    w->geom.kind = WALL_PLANE;
    if (!strcmp(argv[0], "xplane"))
        w->geom.axis = 0;
    else if (!strcmp(argv[0], "yplane"))
        w->geom.axis = 1;
    else if (!strcmp(argv[0], "zplane"))
        w->geom.axis = 2;
    else
        gr_error(g, "unknown fix wall/pair wall style '%.64s' (expected xplane, yplane or "
                    "zplane)", argv[0]);
    double lo = face(g, argv[1], -WALL_FAR, "wall lo position");
    double hi = face(g, argv[2], WALL_FAR, "wall hi position");
    w->geom.lo = lo;
    w->geom.hi = hi;
    if (!(lo < hi))
        gr_error(g, "fix wall/pair %s: lo (%g) must be below hi (%g)", argv[0], lo, hi);
    if (lo == -WALL_FAR && hi == WALL_FAR)
        gr_error(g, "fix wall/pair %s: lo and hi are both NULL (no wall)", argv[0]);
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "wall.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct wallp *w = f->data;
    if (!g->styles.pair)
        gr_error(g, "fix %s wall/pair needs a pair style: the wall uses its contact law",
                 f->id);
    const struct pair_caps *pc = &g->styles.pair->caps;
    if (pc->eval_row && pc->beyond) /* pair granular jkr: its hold beyond touch */
        gr_error(g, "fix %s wall/pair: pair style %s acts beyond contact (jkr), which a "
                    "wall/pair wall does not model; use fix wall/gran granular ... jkr",
                 f->id, g->styles.pair->style->name);
    w->law.kernel = eng_kernel(g, w->mesh.n ? "mesh_pair" : "wall_pair");
    w->law.param = g->eng->pair_param; /* packed for this run before the fixes' init */
    w->law.by_type = 1;
    /* the law's history row (pair granular: its sub-models' width, without
     * the -compat lammps2021 owner slot; the 3-vector laws: 3) */
    struct engine *e = g->eng;
    w->law.history = e->history ? e->hist_n - e->hist_owner : 0;
    if (w->law.history > WALL_HMAX)
        gr_error(g, "fix %s wall/pair: the pair style's %d REAL of contact history exceed a "
                    "wall's %d", f->id, w->law.history, WALL_HMAX);
    w->law.inclusive = 0;
    if (w->mesh.n)
        f->peratom_bytes = mesh_walls_init(g, f, &w->mesh, w->law.history);
    else
        f->peratom_bytes = wall_peratom_bytes(g, &w->geom, &w->law);
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct wallp *w = f->data;
    if (w->mesh.n)
        mesh_walls_apply(g, f, &w->mesh, &w->law, 1);
    else
        wall_apply(g, f, &w->geom, &w->law);
}

static void destroy(struct fix *f)
{
    struct wallp *w = f->data;
    if (w)
        mesh_walls_release(&w->mesh);
    free(w);
    f->data = NULL;
}

const struct fix_style fix_style_wall_pair = {
    .name = "wall/pair",
    .flags = FIX_WALL,
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
};
