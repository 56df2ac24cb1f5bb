/* dump_mesh.h - what the mesh dumps (dump mesh/vtk, dump mesh/stl) share:
 * the fix mesh/surface meshes they write, as listed by ID after the file
 * name or else every mesh/surface fix in the order of definition. */
#ifndef GR_DUMP_MESH_H
#define GR_DUMP_MESH_H

#include "fix.h"

struct dump_meshes {
    int n;                      /* listed IDs (0: every mesh) */
    char (*id)[GR_NAMELEN];
};

/* Add mesh ID id to the list (an error naming who unless it is a fix
 * mesh/surface). */
void dump_meshes_add(struct gravel *g, struct dump_meshes *dm, const char *id, const char *who);
/* Run setup: every listed ID is still a mesh/surface fix. */
void dump_meshes_check(struct gravel *g, const struct dump_meshes *dm, const char *who);
/* The mesh fixes to write, at most cap: the listed ones in list order, else
 * every mesh/surface fix in fix order. */
int dump_meshes_list(struct gravel *g, const struct dump_meshes *dm, struct fix **out, int cap);
void dump_meshes_free(struct dump_meshes *dm);

#endif
