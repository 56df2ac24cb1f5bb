/* dump_mesh.c - the mesh selection of the mesh dumps (dump_mesh.h). */
#include <stdlib.h>
#include <string.h>

#include "dump_mesh.h"
#include "error.h"
#include "fix_mesh_surface.h"

void dump_meshes_add(struct gravel *g, struct dump_meshes *dm, const char *id, const char *who)
{
    mesh_surface_get(g, id, who);
    dm->id = gr_realloc(g, dm->id, (size_t)(dm->n + 1) * sizeof *dm->id);
    snprintf(dm->id[dm->n++], GR_NAMELEN, "%s", id);
}

void dump_meshes_check(struct gravel *g, const struct dump_meshes *dm, const char *who)
{
    for (int i = 0; i < dm->n; i++)
        mesh_surface_get(g, dm->id[i], who);
}

int dump_meshes_list(struct gravel *g, const struct dump_meshes *dm, struct fix **out, int cap)
{
    int n = 0;
    if (dm->n) {
        for (int i = 0; i < dm->n && n < cap; i++)
            out[n++] = fix_find(g, dm->id[i]);
        return n;
    }
    for (int k = 0; k < g->styles.nfix && n < cap; k++)
        if (fix_is_mesh_surface(g->styles.fix[k]))
            out[n++] = g->styles.fix[k];
    return n;
}

void dump_meshes_free(struct dump_meshes *dm)
{
    free(dm->id);
    dm->id = NULL;
    dm->n = 0;
}
