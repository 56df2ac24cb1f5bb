/* force_values.c - fix setforce's and fix addforce's values, kernel and
 * global vector (force_values.h). */
#include "force_values.h"

#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "par_sum.h"
#include "variable.h"

void force_values_parse(struct gravel *g, struct force_values *fv, char **argv, int allow_null,
                        const char *who)
{
    static const char *const name[3] = {"fx", "fy", "fz"};
    fv->on = 0;
    for (int d = 0; d < 3; d++) {
        const char *a = argv[d];
        if (!strcmp(a, "NULL")) {
            if (!allow_null)
                gr_error(g, "%s: %s NULL is not allowed (give a number or v_name)", who,
                         name[d]);
            continue;
        }
        fv->on |= 1 << d;
        if (a[0] == 'v' && a[1] == '_') {
            if (!a[2] || strlen(a + 2) >= GR_NAMELEN)
                gr_error(g, "%s: %s: v_name needs a variable name, got '%.64s'", who, name[d], a);
            fv->var[d] = gr_strdup(g, a + 2);
        } else {
            fv->v[d] = arg_double(g, a, name[d]);
        }
    }
}

void force_values_create(struct gravel *g, struct fix *f, struct force_values *fv, int argc,
                         char **argv, const char *who)
{
    if (argc < 3)
        gr_error(g, "%s expects fx fy fz (each a number, NULL or v_name)", who);
    if (argc > 3) {
        if (!strcmp(argv[3], "region"))
            gr_error(g, "%s: keyword region is not supported yet (define a group of the "
                        "region's atoms: group ID region R)", who);
        gr_error(g, "%s: unknown keyword '%.64s'", who, argv[3]);
    }
    force_values_parse(g, fv, argv, 1, who);
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_setforce.cl";
}

void force_values_init(struct gravel *g, struct fix *f, struct force_values *fv,
                       const char *who)
{
    for (int d = 0; d < 3; d++) {
        if (!fv->var[d])
            continue;
        if (!var_exists(g, fv->var[d]))
            gr_error(g, "%s %s: variable '%s' does not exist", who, f->id, fv->var[d]);
        if (var_is_atom(g, fv->var[d]))
            gr_error(g, "%s %s: variable '%s' is atom-style: not supported yet (give an "
                        "equal-style variable)", who, f->id, fv->var[d]);
        if (!var_is_equal(g, fv->var[d]))
            gr_error(g, "%s %s: variable '%s' is not equal-style", who, f->id, fv->var[d]);
    }
    f->peratom_bytes = 3 * g->eng->rsz; /* the force before the fix */
    fv->k = eng_kernel(g, "force_set_add");
}

void force_values_apply(struct gravel *g, struct fix *f, struct force_values *fv, int add)
{
    for (int d = 0; d < 3; d++)
        if (fv->var[d])
            fv->v[d] = var_compute_equal(g, fv->var[d]);
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = fv->k;
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->f);
    eng_arg_mem(g, k, 4, f->peratom);
    eng_arg_int(g, k, 5, fv->on);
    eng_arg_int(g, k, 6, add);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, 7 + d, fv->v[d]);
    eng_launch(g, k, (size_t)a->n);
}

double force_values_original(struct gravel *g, struct fix *f, int d)
{
    return fix_peratom_sum(g, f, 3, d);
}

double fix_peratom_sum(struct gravel *g, struct fix *f, int width, int col)
{
    if (!g->eng || !f->peratom || g->eng->a.n == 0)
        return 0.0; /* no run yet: LAMMPS's zeros */
    struct engine *e = g->eng;
    const int n = e->a.n;
    const int *ord = eng_tag_order(g); /* reads the device tags into e->tag_seen */
    double *r = gr_malloc(g, (size_t)width * n * sizeof *r + 1);
    eng_read_reals(g, f->peratom, (size_t)width * n, r);
    struct par_sum s = {0}; /* every rank's atoms, in tag order */
    for (int k = 0; k < n; k++)
        par_sum_add(g, &s, e->tag_seen[ord[k]], r[(size_t)width * ord[k] + col]);
    free(r);
    return par_sum_total(g, &s);
}

void force_values_free(struct force_values *fv)
{
    for (int d = 0; d < 3; d++)
        free(fv->var[d]);
}
