/* surface_common.h - what fix surface/global and fix surface/local (LAMMPS
 * 4 Jul 2026, GRANSURF) share: their triangles (STL files, molecule
 * templates) gathered per surface type and molecule ID, one mesh per
 * molecule ID, and the fix wall/gran mesh wall made of those meshes
 * (styles/fix/surface_common.c). */
#ifndef GR_STYLE_SURFACE_COMMON_H
#define GR_STYLE_SURFACE_COMMON_H

#include "fix_mesh_surface.h"

#define SG_MAXSURFTYPE 1024     /* LAMMPS's MAXSURFTYPE */

/* The triangles while a command is parsed (f->data until the wall takes
 * the meshes built from them). */
struct sg_build {
    int n;
    struct mesh_surface *ms[MESH_WALLS_MAX];
    double *soup;               /* 9 per triangle */
    int *ttype, *tmol;
    int ntri, cap;
    struct mesh pending;        /* an STL file being appended (has_pending) */
    int has_pending;
    const char *who;            /* the command, for errors ("fix surface/global") */
    char *model;                /* fix surface/local: its model words, joined (owned) */
};

void sg_build_free(struct sg_build *b);
/* append one triangle (corners p0, p1, p2) of type and molecule ID (room
 * reserved: cap) */
void sg_soup_add(struct sg_build *b, const double *p0, const double *p1, const double *p2,
                 int stype, int smol);
/* one mesh per molecule ID, in ascending ID order (b->ms, b->n) */
void sg_build_meshes(struct gravel *g, struct sg_build *b);
/* `input stl stype smol FILE` and `input mol ID` keywords from argv[0]:
 * their triangles appended to b; returns the index after them; an error
 * naming `who` when there are none. */
int sg_parse_inputs(struct gravel *g, struct sg_build *b, int argc, char **argv,
                    const char *who);
/* f becomes the mesh wall of b's triangles (one mesh per molecule ID, b
 * freed; b->model goes to the first mesh), its model the words (hooke ... |
 * granular ...) and temperature T (NULL: none); maxtype, maxmol: the fix's
 * smaxtype and smaxmol. */
void sg_make_wall(struct gravel *g, struct fix *f, struct sg_build *b, int nword, char **words,
                  const char *temperature, int maxtype, int maxmol);
/* the fix hooks of such a fix: the wall's once made (f->hooks), else the
 * triangles' */
void sg_destroy(struct fix *f);
void sg_init(struct gravel *g, struct fix *f);
void sg_post_force(struct gravel *g, struct fix *f);

#endif
