/* compute_property_atom.c - `compute ID group property/atom attr1 attr2 ...`:
 * per-atom attributes as a compute, as LAMMPS' compute property/atom, for
 * compute reduce and dump custom. One attribute gives a per-atom vector
 * (c_ID), several a per-atom array (c_ID[N] = attribute N). Atoms outside
 * the group get 0. Attributes: id type mass x y z xu yu zu ix iy iz vx vy vz
 * fx fy fz radius diameter omegax omegay omegaz tqx tqy tqz, and temperature,
 * heatflow (LAMMPS 2023; fix property/atom temperature heatflow), quatw quati
 * quatj quatk shapex shapey shapez (diameters) angmomx angmomy angmomz (atom_style
 * ellipsoid superellipsoid), and the custom properties i_name d_name i2_name[k]
 * d2_name[k] (fix property/atom). */
#include <stdlib.h>
#include <string.h>

#include "atom_attr.h"
#include "atom_custom.h"
#include "compute.h"
#include "error.h"

struct property {
    int n;
    int *attr;                  /* atom_attr_find's, or A_CUSTOM */
    char (*word)[GR_NAMELEN];   /* as given (a custom property is found again at use) */
};

enum { A_CUSTOM = -2 };

static void property_destroy(struct compute *c)
{
    struct property *p = c->data;
    if (p) {
        free(p->attr);
        free(p->word);
    }
    free(p);
    c->data = NULL;
}

static void property_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "compute property/atom needs at least one attribute");
    struct property *p = gr_calloc(g, 1, sizeof *p);
    c->data = p;
    p->attr = gr_calloc(g, (size_t)argc, sizeof *p->attr);
    p->word = gr_calloc(g, (size_t)argc, sizeof *p->word);
    for (int k = 0; k < argc; k++) {
        int a = -1;
        struct custom_ref ref;
        snprintf(p->word[k], sizeof p->word[k], "%.63s", argv[k]);
        if (custom_ref_parse(g, argv[k], "compute property/atom", &ref, NULL)) {
            p->attr[p->n++] = A_CUSTOM;
            continue;
        }
        a = atom_attr_find(argv[k]);
        if (a < 0)
            gr_error(g, "compute property/atom: unknown attribute '%.64s' (%s i_name d_name "
                        "i2_name[k] d2_name[k])", argv[k], atom_attr_names);
        atom_attr_check(g, a, argv[k], "compute property/atom");
        p->attr[p->n++] = a;
    }
    c->peratom_flag = 1;
    c->size_peratom_cols = p->n == 1 ? 0 : p->n;
}

static void property_peratom(struct gravel *g, struct compute *c)
{
    const struct property *p = c->data;
    const struct atoms *a = &g->atoms;
    struct custom_ref ref[p->n > 0 ? p->n : 1];
    for (int k = 0; k < p->n; k++)
        if (p->attr[k] == A_CUSTOM) /* where the property is now (unfix: an error) */
            custom_ref_parse(g, p->word[k], "compute property/atom", &ref[k], NULL);
    for (int i = 0; i < a->n; i++) {
        int in = (a->mask[i] & c->groupbit) != 0;
        for (int k = 0; k < p->n; k++)
            c->peratom[(size_t)i * p->n + k] =
                !in                     ? 0.0
                : p->attr[k] == A_CUSTOM ? custom_get(a, ref[k], i)
                                        : atom_attr_value(g, p->attr[k], i);
    }
}

const struct compute_style compute_style_property_atom = {
    .name = "property/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = property_create,
    .peratom = property_peratom,
    .destroy = property_destroy,
};
