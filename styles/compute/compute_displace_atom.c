/* compute_displace_atom.c - `compute ID group displace/atom`: LAMMPS's
 * compute displace/atom: per atom of the group its displacement from its
 * position when the compute was defined, both unwrapped through the image
 * flags: a per-atom array of 4 columns dx dy dz |d| (0 for atoms outside
 * the group). The reference positions are kept by atom ID; an atom of the
 * group without one (created later) takes its current position at its
 * first evaluation, as LAMMPS's set_arrays. Not in restart files (LAMMPS
 * keeps them in its fix STORE); the `refresh` keyword is refused. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "compute.h"
#include "domain.h"
#include "error.h"
#include "tag_ref.h"

struct displace {
    struct tag_ref ref; /* reference positions by tag */
};

static void displace_destroy(struct compute *c)
{
    struct displace *d = c->data;
    if (d)
        tag_ref_free(&d->ref);
    free(d);
    c->data = NULL;
}

static void displace_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc > 0) {
        if (!strcmp(argv[0], "refresh"))
            gr_error(g, "compute displace/atom: keyword refresh is not supported yet");
        gr_error(g, "compute displace/atom: unknown keyword '%.64s'", argv[0]);
    }
    struct displace *d = gr_calloc(g, 1, sizeof *d);
    c->data = d;
    const struct atoms *a = &g->atoms;
    tag_ref_reserve(g, &d->ref, a->maxtag);
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & c->groupbit))
            continue;
        const int64_t t = a->tag[i];
        tag_ref_reserve(g, &d->ref, t);
        d->ref.have[t] = 1;
        domain_unmap(g, a->x + 3 * i, a->image + 3 * i, d->ref.v + 3 * t);
    }
    c->peratom_flag = 1;
    c->size_peratom_cols = 4;
}

static void displace_peratom(struct gravel *g, struct compute *c)
{
    struct displace *d = c->data;
    const struct atoms *a = &g->atoms;
    for (int i = 0; i < a->n; i++) {
        double *out = c->peratom + 4 * i;
        if (!(a->mask[i] & c->groupbit)) {
            out[0] = out[1] = out[2] = out[3] = 0.0;
            continue;
        }
        double u[3];
        domain_unmap(g, a->x + 3 * i, a->image + 3 * i, u);
        const int64_t t = a->tag[i];
        tag_ref_reserve(g, &d->ref, t);
        double *r = d->ref.v + 3 * t;
        if (!d->ref.have[t]) {
            d->ref.have[t] = 1;
            memcpy(r, u, 3 * sizeof *r);
        }
        const double dx = u[0] - r[0], dy = u[1] - r[1], dz = u[2] - r[2];
        out[0] = dx;
        out[1] = dy;
        out[2] = dz;
        out[3] = sqrt(dx * dx + dy * dy + dz * dz);
    }
}

const struct compute_style compute_style_displace_atom = {
    .name = "displace/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = displace_create,
    .peratom = displace_peratom,
    .destroy = displace_destroy,
};
