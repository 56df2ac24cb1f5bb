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

#include "atom_custom.h"
#include "compute.h"
#include "domain.h"
#include "error.h"

enum attr {
    A_ID, A_TYPE, A_MASS, A_X, A_Y, A_Z, A_XU, A_YU, A_ZU, A_IX, A_IY, A_IZ, A_VX, A_VY, A_VZ,
    A_FX, A_FY, A_FZ, A_RADIUS, A_DIAMETER, A_OMEGAX, A_OMEGAY, A_OMEGAZ, A_TQX, A_TQY, A_TQZ,
    A_TEMPERATURE, A_HEATFLOW, A_QUATW, A_QUATI, A_QUATJ, A_QUATK, A_SHAPEX, A_SHAPEY, A_SHAPEZ,
    A_ANGMOMX, A_ANGMOMY, A_ANGMOMZ, A_COUNT
};

static const char *const attr_names[A_COUNT] = {
    "id", "type", "mass", "x", "y", "z", "xu", "yu", "zu", "ix", "iy", "iz", "vx", "vy", "vz",
    "fx", "fy", "fz", "radius", "diameter", "omegax", "omegay", "omegaz", "tqx", "tqy", "tqz",
    "temperature", "heatflow", "quatw", "quati", "quatj", "quatk", "shapex", "shapey", "shapez",
    "angmomx", "angmomy", "angmomz"};

struct property {
    int n;
    int *attr;                  /* enum attr, or A_CUSTOM */
    char (*word)[GR_NAMELEN];   /* as given (a custom property is found again at use) */
};

enum { A_CUSTOM = A_COUNT + 1 };

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
        for (int j = 0; j < A_COUNT; j++)
            if (strcmp(argv[k], attr_names[j]) == 0)
                a = j;
        if (a < 0)
            gr_error(g, "compute property/atom: unknown attribute '%.64s' (id type mass x y z xu "
                        "yu zu ix iy iz vx vy vz fx fy fz radius diameter omegax omegay omegaz "
                        "tqx tqy tqz temperature heatflow quatw quati quatj quatk shapex shapey "
                        "shapez angmomx angmomy angmomz i_name d_name i2_name[k] d2_name[k])",
                     argv[k]);
        if (a >= A_QUATW && !g->atoms.ellipsoid_flag)
            gr_error(g, "compute property/atom: atom property %s needs atom_style ellipsoid "
                        "superellipsoid", argv[k]);
        if ((a == A_TEMPERATURE && !(g->atoms.heat_flag & ATOM_HEAT_T)) ||
            (a == A_HEATFLOW && !(g->atoms.heat_flag & ATOM_HEAT_Q)))
            gr_error(g, "compute property/atom: atom property %s is not allocated (fix "
                        "property/atom %s)", argv[k], argv[k]);
        p->attr[p->n++] = a;
    }
    c->peratom_flag = 1;
    c->size_peratom_cols = p->n == 1 ? 0 : p->n;
}

static double attr_value(const struct gravel *g, int a, int i)
{
    const struct atoms *at = &g->atoms;
    switch ((enum attr)a) {
    case A_ID: return (double)at->tag[i];
    case A_TYPE: return at->type[i];
    case A_MASS: return at->rmass[i];
    case A_X: case A_Y: case A_Z: return at->x[3 * i + a - A_X];
    case A_XU: case A_YU: case A_ZU: {
        double u[3];
        domain_unmap(g, at->x + 3 * i, at->image + 3 * i, u);
        return u[a - A_XU];
    }
    case A_IX: case A_IY: case A_IZ: return at->image[3 * i + a - A_IX];
    case A_VX: case A_VY: case A_VZ: return at->v[3 * i + a - A_VX];
    case A_FX: case A_FY: case A_FZ: return at->f[3 * i + a - A_FX];
    case A_RADIUS: return at->radius[i];
    case A_DIAMETER: return 2.0 * at->radius[i];
    case A_OMEGAX: case A_OMEGAY: case A_OMEGAZ: return at->omega[3 * i + a - A_OMEGAX];
    case A_TQX: case A_TQY: case A_TQZ: return at->torque[3 * i + a - A_TQX];
    case A_TEMPERATURE: return at->heat_flag & ATOM_HEAT_T ? at->temperature[i] : 0.0;
    case A_HEATFLOW: return at->heat_flag & ATOM_HEAT_Q ? at->heatflow[i] : 0.0;
    case A_QUATW: case A_QUATI: case A_QUATJ: case A_QUATK: return at->quat[4 * i + a - A_QUATW];
    case A_SHAPEX: case A_SHAPEY: case A_SHAPEZ: return 2.0 * at->shape[3 * i + a - A_SHAPEX];
    case A_ANGMOMX: case A_ANGMOMY: case A_ANGMOMZ: return at->angmom[3 * i + a - A_ANGMOMX];
    case A_COUNT: break;
    }
    return 0.0;
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
                                        : attr_value(g, p->attr[k], i);
    }
}

const struct compute_style compute_style_property_atom = {
    .name = "property/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = property_create,
    .peratom = property_peratom,
    .destroy = property_destroy,
};
