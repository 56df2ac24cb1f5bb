/* compute_stress_atom.c - `compute ID group stress/atom temp-ID [keyword
 * ...]`: the per-atom stress tensor times volume, as LAMMPS's compute
 * stress/atom, 6 columns xx yy zz xy xz yz:
 *   S_ab = -(mvv2e m v_a v_b + W_ab) nktv2p
 * with W the atom's half of its contacts' pair virial (pressure_virial_atoms,
 * the per-atom form of compute pressure's W: summed over the atoms it is
 * that virial). Keywords choose the terms: ke the kinetic one, pair or
 * virial the pair virial; fix and the molecular terms (bond ... kspace)
 * add none, as in compute pressure; none given = all. temp-ID names a
 * temperature compute or is NULL: gravel's temperatures remove no velocity
 * bias, so the velocities are the atoms' own either way. Atoms outside the
 * group get zeros. One process (it reads the device's contacts). */
#include <stdlib.h>
#include <string.h>

#include "compute.h"
#include "error.h"
#include "pressure.h"

struct stress_atom {
    char temp_id[GR_NAMELEN];
    int keflag, pairflag;
};

static void create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "compute stress/atom needs a temperature compute ID (or NULL)");
    struct stress_atom *s = gr_calloc(g, 1, sizeof *s);
    c->data = s;
    compute_temp_arg(g, argv[0], s->temp_id, "compute stress/atom");
    compute_virial_terms(g, argc - 1, argv + 1, &s->keflag, &s->pairflag,
                         "compute stress/atom");
    c->peratom_flag = 1;
    c->size_peratom_cols = 6;
}

/* temp-ID, when given, must name a temperature (LAMMPS checks it at init) */
static void init(struct gravel *g, struct compute *c)
{
    const struct stress_atom *s = c->data;
    compute_temp_named(g, s->temp_id, "compute stress/atom");
}

static void peratom(struct gravel *g, struct compute *c)
{
    const struct stress_atom *s = c->data;
    const struct atoms *a = &g->atoms;
    double *st = c->peratom;
    if (s->pairflag)
        pressure_virial_atoms(g, st);
    else
        memset(st, 0, 6 * (size_t)a->n * sizeof *st);
    const double mvv2e = compute_mvv2e(g), nktv2p = 1.0; /* lj, si, cgs (pressure.h) */
    for (int i = 0; i < a->n; i++) {
        double *r = st + 6 * (size_t)i;
        if (!(a->mask[i] & c->groupbit)) {
            memset(r, 0, 6 * sizeof *r);
            continue;
        }
        if (s->keflag) { /* LAMMPS's order: (mvv2e m v_a) v_b added to the virial */
            const double onemass = mvv2e * a->rmass[i], *v = a->v + 3 * (size_t)i;
            r[0] += onemass * v[0] * v[0];
            r[1] += onemass * v[1] * v[1];
            r[2] += onemass * v[2] * v[2];
            r[3] += onemass * v[0] * v[1];
            r[4] += onemass * v[0] * v[2];
            r[5] += onemass * v[1] * v[2];
        }
        for (int k = 0; k < 6; k++)
            r[k] *= -nktv2p;
    }
}

const struct compute_style compute_style_stress_atom = {
    .name = "stress/atom",
    .ranks = COMPUTE_RANKS_NO,
    .create = create,
    .init = init,
    .peratom = peratom,
};
