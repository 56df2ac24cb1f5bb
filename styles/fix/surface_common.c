/* surface_common.c - the triangles and the mesh wall of fix surface/global
 * and fix surface/local (surface_common.h): STL files and molecule
 * templates read into one triangle soup with per-triangle surface types and
 * molecule IDs, one mesh per molecule ID (src/state/mesh.c welds and
 * validates), and the fix wall/gran mesh wall of those meshes. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix_wall_gran.h"
#include "molecule.h"
#include "surface_common.h"

void sg_build_free(struct sg_build *b)
{
    if (!b)
        return;
    for (int m = 0; m < b->n; m++) {
        mesh_surface_free(b->ms[m]);
        free(b->ms[m]);
    }
    if (b->has_pending)
        mesh_free(&b->pending);
    free(b->model);
    free(b->soup);
    free(b->ttype);
    free(b->tmol);
    free(b);
}

/* room for n more triangles */
static void soup_reserve(struct gravel *g, struct sg_build *b, int n)
{
    if (b->ntri + n <= b->cap)
        return;
    int cap = 2 * (b->ntri + n);
    double *s = realloc(b->soup, (size_t)cap * 9 * sizeof *s);
    int *t = s ? realloc(b->ttype, (size_t)cap * sizeof *t) : NULL;
    int *o = t ? realloc(b->tmol, (size_t)cap * sizeof *o) : NULL;
    if (s)
        b->soup = s;
    if (t)
        b->ttype = t;
    if (o)
        b->tmol = o;
    if (!o)
        gr_error(g, "%s: out of memory for %d triangles", b->who, b->ntri + n);
    b->cap = cap;
}

void sg_soup_add(struct sg_build *b, const double *p0, const double *p1, const double *p2,
                     int stype, int smol)
{
    double *d = b->soup + 9 * (size_t)b->ntri;
    memcpy(d, p0, 3 * sizeof *d);
    memcpy(d + 3, p1, 3 * sizeof *d);
    memcpy(d + 6, p2, 3 * sizeof *d);
    b->ttype[b->ntri] = stype;
    b->tmol[b->ntri++] = smol;
}

/* input stl stype smol FILE: append its triangles */
static void read_stl(struct gravel *g, struct sg_build *b, int stype, int smol, const char *file)
{
    struct mesh m;
    char err[512];
    if (mesh_read(file, 0, &m, err, sizeof err))
        gr_error(g, "%s input stl: %s", b->who, err);
    b->pending = m; /* build_free frees it if soup_reserve fails */
    b->has_pending = 1;
    soup_reserve(g, b, m.ntri);
    for (int t = 0; t < m.ntri; t++)
        sg_soup_add(b, m.vert + 3 * m.tri[3 * t], m.vert + 3 * m.tri[3 * t + 1],
                 m.vert + 3 * m.tri[3 * t + 2], stype, smol);
    b->has_pending = 0;
    mesh_free(&m);
}

/* input mol ID: the triangles of a molecule template (their own types and
 * molecule IDs) */
static void read_mol(struct gravel *g, struct sg_build *b, const char *id, const char *who)
{
    const struct molecule *mol = molecule_find(g, id);
    if (!mol)
        gr_error(g, "%s input mol: molecule template ID %.64s does not exist", who, id);
    if (!mol->ntris)
        gr_error(g, "%s input mol: molecule template %s has no triangles (Points and "
                    "Triangles sections)", who, id);
    for (int t = 0; t < mol->ntris; t++)
        if (mol->tri_type[t] > SG_MAXSURFTYPE)
            gr_error(g, "%s input mol: triangle %d of template %s has type %d (at most %d)",
                     who, t + 1, id, mol->tri_type[t], SG_MAXSURFTYPE);
    soup_reserve(g, b, mol->ntris);
    for (int t = 0; t < mol->ntris; t++) {
        const int *c = mol->tri + 3 * t;
        sg_soup_add(b, mol->points + 3 * c[0], mol->points + 3 * c[1], mol->points + 3 * c[2],
                 mol->tri_type[t], mol->tri_mol[t]);
    }
}

void sg_build_meshes(struct gravel *g, struct sg_build *b)
{
    double *soup = gr_malloc(g, (size_t)b->ntri * 9 * sizeof *soup);
    for (int mol = 0;;) {
        int next = 0; /* the smallest molecule ID above mol */
        for (int t = 0; t < b->ntri; t++)
            if (b->tmol[t] > mol && (!next || b->tmol[t] < next))
                next = b->tmol[t];
        if (!next)
            break;
        mol = next;
        if (b->n == MESH_WALLS_MAX) {
            free(soup);
            gr_error(g, "%s: more than %d surface molecule IDs (gravel makes "
                        "one mesh wall per molecule ID, at most %d)", b->who, MESH_WALLS_MAX,
                     MESH_WALLS_MAX);
        }
        int nt = 0, type = 0;
        for (int t = 0; t < b->ntri; t++)
            if (b->tmol[t] == mol) {
                memcpy(soup + 9 * (size_t)nt++, b->soup + 9 * (size_t)t, 9 * sizeof *soup);
                type = type ? type : b->ttype[t];
            }
        struct mesh_surface *ms = gr_calloc(g, 1, sizeof *ms);
        b->ms[b->n++] = ms;
        char name[64], err[512];
        snprintf(name, sizeof name, "surface molecule %d", mol);
        if (mesh_from_soup(name, soup, nt, 0, &ms->m, err, sizeof err) ||
            mesh_check_range(&ms->m, name, err, sizeof err)) {
            free(soup);
            gr_error(g, "%s: %s", b->who, err);
        }
        mesh_surface_normals(g, ms);
        ms->type = type;
        ms->mol = mol;
        ms->cache_step = -1;
    }
    free(soup);
}

int sg_parse_inputs(struct gravel *g, struct sg_build *b, int argc, char **argv,
                    const char *who)
{
    b->who = who;
    int i = 0;
    while (i < argc && !strcmp(argv[i], "input")) {
        arg_need(g, argc, i, 1, "input");
        if (!strcmp(argv[i + 1], "stl")) {
            arg_need(g, argc, i, 4, "input stl");
            int stype = arg_int_range(g, argv[i + 2], 1, SG_MAXSURFTYPE, "surface type");
            int smol = arg_int_range(g, argv[i + 3], 1, 1 << 30, "surface molecule ID");
            read_stl(g, b, stype, smol, argv[i + 4]);
            i += 5;
        } else if (!strcmp(argv[i + 1], "mol")) {
            arg_need(g, argc, i, 2, "input mol");
            read_mol(g, b, argv[i + 2], who);
            i += 3;
        } else {
            gr_error(g, "%s input: unknown source '%.64s' (expected stl or mol)", who,
                     argv[i + 1]);
        }
    }
    if (!b->ntri)
        gr_error(g, "%s command requires input keyword", who);
    return i;
}

void sg_make_wall(struct gravel *g, struct fix *f, struct sg_build *b, int nword, char **words,
                  const char *temperature, int maxtype, int maxmol)
{
    sg_build_meshes(g, b);
    b->ms[0]->model = b->model;
    b->model = NULL;
    for (int m = 0; m < b->n; m++) {
        b->ms[m]->smaxtype = maxtype;
        b->ms[m]->smaxmol = maxmol;
    }
    /* the wall: the model's words, then temperature T */
    char *w[512];
    if (nword + 2 > (int)(sizeof w / sizeof *w))
        gr_error(g, "fix %s: model of %d words is too long", f->style->name, nword);
    int nw = 0;
    for (int k = 0; k < nword; k++)
        w[nw++] = words[k];
    if (temperature) {
        w[nw++] = "temperature";
        w[nw++] = (char *)temperature;
    }
    wall_gran_create_own(g, f, nw, w, b->ms, b->n);
    b->n = 0; /* the wall holds the meshes now */
    sg_build_free(b);
}

void sg_destroy(struct fix *f)
{
    if (f->hooks) /* the wall was made */
        fix_style_wall_gran.destroy(f);
    else
        sg_build_free(f->data);
    f->data = NULL;
}

void sg_init(struct gravel *g, struct fix *f)
{
    if (f->hooks) /* fix surface/local makes its wall at run start (prepare) */
        fix_style_wall_gran.init(g, f);
}

void sg_post_force(struct gravel *g, struct fix *f) { fix_style_wall_gran.post_force(g, f); }
