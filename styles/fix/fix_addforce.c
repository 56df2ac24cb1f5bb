/* fix_addforce.c - `fix ID group addforce fx fy fz [every N] [region ID]
 * [energy v_name]`: LAMMPS's fix addforce: after the forces of the step
 * (post_force, and at a run's setup), on steps that are multiples of N
 * (default 1), the value (a number, an equal-style v_name evaluated then,
 * or an atom-style v_name: each atom's own) is added to the group's forces.
 * Global scalar (f_ID, extensive; `fix_modify ID energy yes` adds it to
 * pe): the potential energy -sum (fx xu + fy yu + fz zu) over the group's
 * unwrapped positions, in tag order: with numbers and equal-style values
 * those of the step it is read (with every N > 1 LAMMPS keeps the last
 * application's); with an atom-style component, or with `energy v_name`
 * (an atom-style variable: each atom's energy, summed), those of the last
 * application, as LAMMPS. Global vector (f_ID[1..3]): the group's total
 * force before the fix at its last application (force_values.h). `region
 * ID`: only the group's atoms inside the region take the force and count in
 * the energy (LAMMPS). */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force_values.h"
#include "par_sum.h"
#include "region.h"

#define WHO "fix addforce"

struct addforce {
    struct force_values fv;
    int every;
};

static void destroy(struct fix *f)
{
    struct addforce *a = f->data;
    if (a) {
        force_values_free(&a->fv);
        free(a);
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "fix addforce expects fx fy fz (each a number or v_name) [every N] "
                    "[region ID]");
    struct addforce *a = gr_calloc(g, 1, sizeof *a);
    f->data = a;
    a->every = 1;
    a->fv.allow_atom = 1;
    for (int i = 3; i < argc; i += 2) {
        if (!strcmp(argv[i], "every")) {
            arg_need(g, argc, i, 1, "every");
            a->every = arg_int(g, argv[i + 1], "every");
            if (a->every <= 0)
                gr_error(g, "fix addforce: every must be positive, got %d", a->every);
        } else if (!strcmp(argv[i], "region")) {
            force_values_region(g, &a->fv, argc, argv, i, WHO);
        } else if (!strcmp(argv[i], "energy")) {
            arg_need(g, argc, i, 1, "energy");
            const char *e = argv[i + 1];
            if (strncmp(e, "v_", 2) || !e[2] || strlen(e + 2) >= GR_NAMELEN)
                gr_error(g, "fix addforce: energy must be v_name, got '%.64s'", e);
            free(a->fv.evar);
            a->fv.evar = gr_strdup(g, e + 2);
        } else {
            gr_error(g, "fix addforce: unknown keyword '%.64s' (expected every, region, energy)",
                     argv[i]);
        }
    }
    force_values_parse(g, &a->fv, argv, 0, WHO);
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_setforce.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct addforce *a = f->data;
    force_values_init(g, f, &a->fv, WHO);
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct addforce *a = f->data;
    if (g->step % a->every == 0)
        force_values_apply(g, f, &a->fv, 1);
}

/* -sum (fx xu + fy yu + fz zu) over the group (with a region, its atoms
 * inside it now), xu unwrapped, in tag order (the host atoms are current
 * when a scalar is read) */
static double scalar(struct gravel *g, struct fix *f)
{
    const struct addforce *a = f->data;
    if (force_values_peratom(&a->fv)) /* the last application's, as LAMMPS */
        return force_values_energy(g, &a->fv);
    const struct atoms *at = &g->atoms;
    const int *ord = atoms_tag_order(g);
    struct region *r = NULL;
    if (a->fv.region) {
        if (!(r = region_find(g, a->fv.region)))
            gr_error(g, "fix %s: region %s does not exist", f->id, a->fv.region);
        region_prematch(g, r);
    }
    struct par_sum e = {0}; /* every rank's atoms, in tag order */
    for (int k = 0; k < at->n; k++) {
        const int i = ord[k];
        if (!(at->mask[i] & f->groupbit) || (r && !region_match(r, at->x + 3 * i)))
            continue;
        double u[3];
        domain_unmap(g, at->x + 3 * i, at->image + 3 * i, u);
        par_sum_add(g, &e, at->tag[i],
                    -(a->fv.v[0] * u[0] + a->fv.v[1] * u[1] + a->fv.v[2] * u[2]));
    }
    return par_sum_total(g, &e);
}

static double vector(struct gravel *g, struct fix *f, int i)
{
    return force_values_original(g, f, i - 1);
}

const struct fix_style fix_style_addforce = {
    .name = "addforce",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
    .scalar = scalar,
    .energy_global = 1,
    .size_vector = 3,
    .vector = vector,
};
