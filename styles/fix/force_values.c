/* force_values.c - fix setforce's and fix addforce's values, kernel and
 * global vector (force_values.h). */
#include "force_values.h"

#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "domain.h"
#include "engine.h"
#include "error.h"
#include "par_sum.h"
#include "region.h"
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
    for (int i = 3; i < argc; i += 2) {
        if (strcmp(argv[i], "region"))
            gr_error(g, "%s: unknown keyword '%.64s' (expected region)", who, argv[i]);
        force_values_region(g, fv, argc, argv, i, who);
    }
    force_values_parse(g, fv, argv, 1, who);
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_setforce.cl";
}

void force_values_region(struct gravel *g, struct force_values *fv, int argc, char **argv, int i,
                         const char *who)
{
    if (i + 1 >= argc)
        gr_error(g, "%s: keyword region needs a region ID", who);
    if (!region_find(g, argv[i + 1]))
        gr_error(g, "%s: region %.64s does not exist", who, argv[i + 1]);
    free(fv->region);
    fv->region = gr_strdup(g, argv[i + 1]);
}

/* fv->sel and its device copy: the group's atoms inside the region now
 * (LAMMPS's prematch, then match per atom) */
static void select_region(struct gravel *g, struct fix *f, struct force_values *fv)
{
    struct engine *e = g->eng;
    const int n = e->a.n;
    struct region *r = region_find(g, fv->region);
    if (!r)
        gr_error(g, "fix %s: region %s does not exist", f->id, fv->region);
    region_prematch(g, r);
    double *x = gr_malloc(g, 3 * (size_t)n * sizeof *x + 1);
    cl_uint *mask = gr_malloc(g, (size_t)n * sizeof *mask + 1);
    eng_read_positions(g, &e->a, n, x);
    eng_read(g, e->a.mask, 0, (size_t)n * sizeof *mask, mask);
    free(fv->sel);
    fv->sel = gr_malloc(g, (size_t)n * sizeof *fv->sel + 1);
    for (int i = 0; i < n; i++)
        fv->sel[i] = (mask[i] & f->groupbit) && region_match(r, x + 3 * (size_t)i);
    free(x);
    free(mask);
    if (!fv->dsel || fv->dsel_n < (size_t)n) {
        if (fv->dsel)
            clReleaseMemObject(fv->dsel);
        fv->dsel_n = (size_t)n + (size_t)n / 8 + 16;
        fv->dsel = eng_alloc(g, fv->dsel_n * sizeof(cl_uint), "fix force region atoms");
    }
    if (n > 0)
        eng_write(g, fv->dsel, 0, (size_t)n * sizeof(cl_uint), fv->sel);
}

int force_values_took(const struct fix *f, const struct force_values *fv, const cl_uint *mask,
                      int i)
{
    return fv->region ? (int)fv->sel[i] : (mask[i] & f->groupbit) != 0;
}

void force_values_init(struct gravel *g, struct fix *f, struct force_values *fv,
                       const char *who)
{
    for (int d = 0; d < 3; d++) {
        if (!fv->var[d])
            continue;
        if (!var_exists(g, fv->var[d]))
            gr_error(g, "%s %s: variable '%s' does not exist", who, f->id, fv->var[d]);
        fv->atom[d] = var_is_atom(g, fv->var[d]);
        if (fv->atom[d] && !fv->allow_atom)
            gr_error(g, "%s %s: variable '%s' is atom-style: LAMMPS's fix aveforce takes "
                        "equal-style variables only", who, f->id, fv->var[d]);
        if (!fv->atom[d] && !var_is_equal(g, fv->var[d]))
            gr_error(g, "%s %s: variable '%s' is not equal-style%s", who, f->id, fv->var[d],
                     fv->allow_atom ? " or atom-style" : "");
    }
    if (fv->evar) {
        if (!var_exists(g, fv->evar))
            gr_error(g, "%s %s: variable '%s' does not exist", who, f->id, fv->evar);
        if (!var_is_atom(g, fv->evar))
            gr_error(g, "%s %s: energy variable '%s' is not atom-style", who, f->id, fv->evar);
        if (!fv->var[0] && !fv->var[1] && !fv->var[2])
            gr_error(g, "%s %s: cannot use variable energy with constant force (LAMMPS)", who,
                     f->id);
    }
    f->peratom_bytes = 3 * g->eng->rsz; /* the force before the fix */
    fv->k = eng_kernel(g, "force_set_add");
}

int force_values_peratom(const struct force_values *fv)
{
    return fv->atom[0] || fv->atom[1] || fv->atom[2] || fv->evar;
}

/* The atom-style components' values on the device (the others: v) and,
 * for addforce's scalar, each selected atom's energy with its ID. */
static void atom_values(struct gravel *g, struct fix *f, struct force_values *fv)
{
    struct engine *e = g->eng;
    const int n = e->a.n;
    double *col[4] = {NULL, NULL, NULL, NULL};
    run_sync_host(g); /* positions and images for the energies */
    for (int d = 0; d < 3; d++)
        if (fv->atom[d])
            col[d] = var_atom_values(g, fv->var[d]); /* syncs the host atoms first */
    if (fv->evar)
        col[3] = var_atom_values(g, fv->evar);
    const struct atoms *a = &g->atoms;
    double *val = gr_malloc(g, 3 * ((size_t)n + 1) * sizeof *val);
    free(fv->eatom);
    free(fv->etag);
    fv->eatom = gr_malloc(g, ((size_t)n + 1) * sizeof *fv->eatom);
    fv->etag = gr_malloc(g, ((size_t)n + 1) * sizeof *fv->etag);
    fv->ne = 0;
    for (int i = 0; i < n; i++) {
        for (int d = 0; d < 3; d++)
            val[3 * (size_t)i + d] = col[d] ? col[d][i] : fv->v[d];
        if (!force_values_took(f, fv, a->mask, i))
            continue;
        double en = 0.0, u[3];
        if (col[3]) {
            en = col[3][i];
        } else {
            domain_unmap(g, a->x + 3 * (size_t)i, a->image + 3 * (size_t)i, u);
            for (int d = 0; d < 3; d++)
                if (fv->on & (1 << d))
                    en -= val[3 * (size_t)i + d] * u[d];
        }
        fv->eatom[fv->ne] = en;
        fv->etag[fv->ne++] = a->tag[i];
    }
    if (!fv->dval || fv->dval_n < (size_t)n) {
        if (fv->dval)
            clReleaseMemObject(fv->dval);
        fv->dval_n = (size_t)n + (size_t)n / 8 + 16;
        fv->dval = eng_alloc(g, 3 * fv->dval_n * e->rsz, "fix force atom-style values");
    }
    if (n > 0)
        eng_write_reals(g, fv->dval, 3 * (size_t)n, val);
    free(val);
    for (int k = 0; k < 4; k++)
        free(col[k]);
}

struct tagged_energy {
    int64_t tag;
    double e;
};

static int by_tag(const void *a, const void *b)
{
    const int64_t x = ((const struct tagged_energy *)a)->tag;
    const int64_t y = ((const struct tagged_energy *)b)->tag;
    return (x > y) - (x < y);
}

double force_values_energy(struct gravel *g, const struct force_values *fv)
{
    struct tagged_energy *r = gr_malloc(g, ((size_t)fv->ne + 1) * sizeof *r);
    for (int k = 0; k < fv->ne; k++)
        r[k] = (struct tagged_energy){fv->etag[k], fv->eatom[k]};
    qsort(r, (size_t)fv->ne, sizeof *r, by_tag); /* they come in device order */
    struct par_sum s = {0};
    for (int k = 0; k < fv->ne; k++)
        par_sum_add(g, &s, r[k].tag, r[k].e);
    free(r);
    return par_sum_total(g, &s);
}

void force_values_prepare(struct gravel *g, struct fix *f, struct force_values *fv)
{
    for (int d = 0; d < 3; d++)
        if (fv->var[d] && !fv->atom[d])
            fv->v[d] = var_compute_equal(g, fv->var[d]);
    if (fv->region)
        select_region(g, f, fv);
    if (force_values_peratom(fv))
        atom_values(g, f, fv);
}

void force_values_launch(struct gravel *g, struct fix *f, struct force_values *fv, int on,
                         const double v[3], int add)
{
    struct dev_atoms *a = eng_atoms(g);
    const int per = !v && force_values_peratom(fv);
    if (!v)
        v = fv->v;
    cl_kernel k = fv->k;
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, fv->region ? 1u : f->groupbit);
    eng_arg_mem(g, k, 2, fv->region ? fv->dsel : a->mask);
    eng_arg_mem(g, k, 3, a->f);
    eng_arg_mem(g, k, 4, f->peratom);
    eng_arg_int(g, k, 5, on);
    eng_arg_int(g, k, 6, add);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, 7 + d, v[d]);
    eng_arg_int(g, k, 10, per);
    eng_arg_mem(g, k, 11, per ? fv->dval : a->f); /* unread without per-atom values */
    eng_launch(g, k, (size_t)a->n);
}

void force_values_apply(struct gravel *g, struct fix *f, struct force_values *fv, int add)
{
    force_values_prepare(g, f, fv);
    force_values_launch(g, f, fv, fv->on, NULL, add);
}

double force_values_original(struct gravel *g, struct fix *f, int d)
{
    return fix_peratom_sum(g, f, 3, d);
}

double fix_peratom_sum(struct gravel *g, struct fix *f, int width, int col)
{
    if (!g->eng)
        return 0.0; /* no run yet: LAMMPS's zeros */
    struct engine *e = g->eng;
    const int n = f->peratom ? e->a.n : 0;
    struct par_sum s = {0}; /* every rank's atoms, in tag order */
    if (n > 0) { /* a rank without atoms still takes part in the sum */
        const int *ord = eng_tag_order(g); /* reads the device tags into e->tag_seen */
        double *r = gr_malloc(g, (size_t)width * n * sizeof *r);
        eng_read_reals(g, f->peratom, (size_t)width * n, r);
        for (int k = 0; k < n; k++)
            par_sum_add(g, &s, e->tag_seen[ord[k]], r[(size_t)width * ord[k] + col]);
        free(r);
    }
    return par_sum_total(g, &s);
}

void force_values_free(struct force_values *fv)
{
    for (int d = 0; d < 3; d++)
        free(fv->var[d]);
    free(fv->region);
    free(fv->sel);
    if (fv->dsel)
        clReleaseMemObject(fv->dsel);
    free(fv->evar);
    free(fv->eatom);
    free(fv->etag);
    if (fv->dval)
        clReleaseMemObject(fv->dval);
}
