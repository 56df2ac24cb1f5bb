/* atom_attr.c - per-atom attributes by name (atom_attr.h). */
#include "atom_attr.h"

#include <string.h>

#include "domain.h"
#include "error.h"

enum attr {
    A_ID, A_TYPE, A_MASS, A_X, A_Y, A_Z, A_XU, A_YU, A_ZU, A_IX, A_IY, A_IZ, A_VX, A_VY, A_VZ,
    A_FX, A_FY, A_FZ, A_RADIUS, A_DIAMETER, A_OMEGAX, A_OMEGAY, A_OMEGAZ, A_TQX, A_TQY, A_TQZ,
    A_TEMPERATURE, A_HEATFLOW, A_QUATW, A_QUATI, A_QUATJ, A_QUATK, A_SHAPEX, A_SHAPEY, A_SHAPEZ,
    A_ANGMOMX, A_ANGMOMY, A_ANGMOMZ, A_COUNT
};

static const char *const names[A_COUNT] = {
    "id", "type", "mass", "x", "y", "z", "xu", "yu", "zu", "ix", "iy", "iz", "vx", "vy", "vz",
    "fx", "fy", "fz", "radius", "diameter", "omegax", "omegay", "omegaz", "tqx", "tqy", "tqz",
    "temperature", "heatflow", "quatw", "quati", "quatj", "quatk", "shapex", "shapey", "shapez",
    "angmomx", "angmomy", "angmomz"};

const char atom_attr_names[] =
    "id type mass x y z xu yu zu ix iy iz vx vy vz fx fy fz radius diameter omegax omegay "
    "omegaz tqx tqy tqz temperature heatflow quatw quati quatj quatk shapex shapey shapez "
    "angmomx angmomy angmomz";

int atom_attr_find(const char *word)
{
    for (int j = 0; j < A_COUNT; j++)
        if (strcmp(word, names[j]) == 0)
            return j;
    return -1;
}

void atom_attr_check(struct gravel *g, int a, const char *word, const char *who)
{
    if (a >= A_QUATW && !g->atoms.ellipsoid_flag)
        gr_error(g, "%s: atom property %s needs atom_style ellipsoid superellipsoid", who, word);
    if ((a == A_TEMPERATURE && !(g->atoms.heat_flag & ATOM_HEAT_T)) ||
        (a == A_HEATFLOW && !(g->atoms.heat_flag & ATOM_HEAT_Q)))
        gr_error(g, "%s: atom property %s is not allocated (fix property/atom %s)", who, word,
                 word);
}

double atom_attr_value(const struct gravel *g, int a, int i)
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
