/* fix_surface_local.c - `fix ID group surface/local input stl stype smol
 * FILE | input mol ID [input ...]`: LAMMPS 4 Jul 2026's local granular
 * surfaces (GRANSURF), 3d triangles, on gravel's mesh walls as fix
 * surface/global (styles/fix/surface_common.c: one mesh per molecule ID,
 * the contact body, laws and history of fix wall/gran's mesh walls).
 *
 * In LAMMPS the triangles are particles (atom_style tri, their surface type
 * an atom type) and `pair_style hybrid granular surf/granular` with
 * `pair_coeff P S surf/granular <sub-models>` gives the particle/surface
 * model. gravel keeps the triangles out of the atoms: a surface type is an
 * atom type no particle has (`pair_coeff S S none`), and at every run start
 * (prepare) the fix reads the surf/granular models of its type pairs
 * (styles/pair/pair_surf_granular.c) and makes its wall of them, the first
 * time; a later run with other surf/granular coefficients is an error. As
 * for fix surface/global, one model serves every type pair: models that
 * differ are refused. Refused: `NULL` (triangles of a data file), 2d line
 * segments, a particle with a surface type. No restart state, no output,
 * no fix_modify (LAMMPS: none). */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix_wall_gran.h"
#include "pair_surf_granular.h"
#include "surface_common.h"

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (g->dom.dimension == 2)
        gr_error(g, "fix surface/local: 2d line-segment surfaces are not supported by gravel "
                    "(3d triangles only)");
    if (argc >= 1 && strcmp(argv[0], "input"))
        gr_error(g, "fix surface/local %.64s: gravel reads `input stl stype smol FILE` and "
                    "`input mol ID` (LAMMPS 4 Jul 2026); triangles of a data file (NULL, "
                    "atom_style tri) are not supported", argv[0]);
    struct sg_build *b = gr_calloc(g, 1, sizeof *b);
    f->data = b; /* freed by destroy() if an error follows */
    f->hooks = 0;
    int i = sg_parse_inputs(g, b, argc, argv, "fix surface/local");
    if (i < argc)
        gr_error(g, "unknown fix surface/local keyword '%.64s' (it takes input keywords only)",
                 argv[i]);
    for (int t = 0; t < b->ntri; t++)
        if (b->ttype[t] > g->atoms.ntypes)
            gr_error(g, "fix surface/local: surface type %d is beyond the box's %d atom types "
                        "(local surfaces take atom types, as LAMMPS's triangle particles)",
                     b->ttype[t], g->atoms.ntypes);
    f->needs |= NEED_ROTATION; /* LAMMPS: requires atom attributes radius and omega */
}

/* the model words of the particle/surface type pairs (one for all), joined */
static char *model_of(struct gravel *g, const unsigned char *is_surf, char ***words, int *nw)
{
    int nt = g->atoms.ntypes, np = 0;
    char *joined = NULL;
    for (int p = 1; p <= nt; p++) {
        if (is_surf[p])
            continue;
        np++;
        for (int s = 1; s <= nt; s++) {
            if (!is_surf[s])
                continue;
            char **w;
            int n = surf_granular_model(g, p, s, &w);
            if (n < 0) {
                free(joined);
                gr_error(g, "fix surface/local: no pair_coeff %d %d surf/granular (particle type "
                            "%d, surface type %d: pair_style hybrid granular surf/granular)",
                         p < s ? p : s, p < s ? s : p, p, s);
            }
            size_t len = 1;
            for (int k = 0; k < n; k++)
                len += strlen(w[k]) + 1;
            char *j = gr_calloc(g, len, 1);
            for (int k = 0; k < n; k++) {
                strcat(j, w[k]);
                strcat(j, k + 1 < n ? " " : "");
            }
            if (joined && strcmp(joined, j)) {
                free(joined);
                free(j);
                gr_error(g, "fix surface/local: the surf/granular models of the type pairs "
                            "differ (particle type %d, surface type %d has its own); gravel "
                            "applies one model to every particle/surface type pair", p, s);
            }
            free(joined);
            joined = j;
            *words = w;
            *nw = n;
        }
    }
    if (!np)
        gr_error(g, "fix surface/local: every atom type is a surface type; the particles need "
                    "one of their own");
    return joined;
}

/* Run start: the wall, from the surf/granular models (first run), or the
 * check that they did not change. */
static void prepare(struct gravel *g, struct fix *f)
{
    unsigned char is_surf[SG_MAXSURFTYPE + 1] = {0};
    struct mesh_walls *mw = f->hooks ? wall_gran_meshes(f) : NULL;
    if (mw) {
        for (int m = 0; m < mw->n; m++)
            is_surf[mw->own[m]->type] = 1;
    } else {
        const struct sg_build *b = f->data;
        for (int t = 0; t < b->ntri; t++)
            is_surf[b->ttype[t]] = 1;
    }
    for (int k = 0; k < g->atoms.n; k++)
        if (is_surf[g->atoms.type[k]])
            gr_error(g, "fix surface/local: atom %lld has type %d, a surface type of the "
                        "triangles (gravel's triangles are not atoms: no particle may have it)",
                     (long long)g->atoms.tag[k], g->atoms.type[k]);
    char **words = NULL;
    int nw = 0;
    char *model = model_of(g, is_surf, &words, &nw);
    if (mw) {
        int same = !strcmp(model, mw->own[0]->model);
        free(model);
        if (!same)
            gr_error(g, "fix surface/local %s: the surf/granular coefficients changed since "
                        "its first run (gravel makes its wall once)", f->id);
        return;
    }
    char *w[256];
    if (nw + 1 > (int)(sizeof w / sizeof *w)) {
        free(model);
        gr_error(g, "fix surface/local: model of %d words is too long", nw);
    }
    w[0] = "granular";
    for (int k = 0; k < nw; k++)
        w[k + 1] = words[k];
    int maxtype = 0, maxmol = 0;
    const struct sg_build *b = f->data;
    for (int t = 0; t < b->ntri; t++) {
        maxtype = b->ttype[t] > maxtype ? b->ttype[t] : maxtype;
        maxmol = b->tmol[t] > maxmol ? b->tmol[t] : maxmol;
    }
    ((struct sg_build *)f->data)->model = model; /* kept by the first mesh */
    sg_make_wall(g, f, f->data, nw + 1, w, NULL, maxtype, maxmol);
}

static void reset_step(struct gravel *g, struct fix *f, bigint shift)
{
    if (f->hooks)
        fix_style_wall_gran.reset_step(g, f, shift);
}

const struct fix_style fix_style_surface_local = {
    .name = "surface/local",
    .create = create,
    .prepare = prepare,
    .init = sg_init,
    .post_force = sg_post_force,
    .destroy = sg_destroy,
    .reset_step = reset_step,
};
