/* fix_property_global.c - LIGGGHTS's `fix ID group property/global name form
 * values...`: a named global property (material constants and model
 * settings) that other styles read by name at run start
 * (styles/fix/fix_property_global.h). Forms, as LIGGGHTS parses them
 * (fix_property_global.cpp):
 *   scalar v                     one value (thermo f_ID)
 *   vector v1 v2 ...             any number of values (thermo f_ID[i])
 *   peratomtype|atomtype v1 ..   one value per atom type
 *   matrix ncols v11 v12 ...     row-major, the count a multiple of ncols
 *   peratomtypepair|atomtypepair N v11 .. vNN
 *                                an N x N symmetric matrix (type pairs)
 * Names are unique over the property/global fixes (LIGGGHTS: "There is
 * already a fix that registers a variable of the same name"). Whether a
 * property is long enough for the atom types is checked by its reader. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix.h"
#include "fix_property_global.h"

extern const struct fix_style fix_style_property_global;

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "fix property/global expects a property name, a form (scalar, vector, "
                    "peratomtype, matrix or peratomtypepair) and values");
    if (strlen(argv[0]) >= sizeof ((struct fpg *)0)->name)
        gr_error(g, "fix property/global: property name '%.64s...' too long", argv[0]);
    struct fpg p;
    memset(&p, 0, sizeof p);
    strcpy(p.name, argv[0]);
    const char *form = argv[1];
    if (!strcmp(form, "scalar"))
        p.form = FPG_SCALAR;
    else if (!strcmp(form, "vector"))
        p.form = FPG_VECTOR;
    else if (!strcmp(form, "peratomtype") || !strcmp(form, "atomtype"))
        p.form = FPG_PERATOMTYPE;
    else if (!strcmp(form, "matrix"))
        p.form = FPG_MATRIX;
    else if (!strcmp(form, "peratomtypepair") || !strcmp(form, "atomtypepair"))
        p.form = FPG_PERATOMTYPEPAIR;
    else
        gr_error(g, "fix property/global: unknown form '%.64s' (valid forms are scalar, vector, "
                    "atomtype/peratomtype, matrix, or atomtypepair/peratomtypepair)", form);
    int first = 2;
    if (p.form == FPG_MATRIX || p.form == FPG_PERATOMTYPEPAIR) {
        p.ncol = arg_int(g, argv[2], "fix property/global number of columns");
        if (p.ncol < 1)
            gr_error(g, "fix property/global %s: the number of columns must be >= 1, got %d",
                     p.name, p.ncol);
        first = 3;
    }
    p.n = argc - first;
    if (p.n < 1)
        gr_error(g, "fix property/global %s: not enough arguments (no values)", p.name);
    if (p.form == FPG_SCALAR && p.n != 1)
        gr_error(g, "fix property/global %s scalar: expected 1 value, got %d", p.name, p.n);
    for (int k = 0; k < p.n; k++) /* errors before anything is allocated */
        (void)arg_double(g, argv[first + k], "fix property/global value");
    p.v = gr_malloc(g, (size_t)p.n * sizeof(double));
    for (int k = 0; k < p.n; k++)
        p.v[k] = arg_double(g, argv[first + k], "fix property/global value");
    if (p.ncol && p.n % p.ncol) {
        free(p.v);
        gr_error(g, "fix property/global %s: the number of values (%d) must be a multiple of "
                    "nCols (%d)", p.name, p.n, p.ncol);
    }
    if (p.form == FPG_PERATOMTYPEPAIR) {
        int bad = p.n != p.ncol * p.ncol;
        for (int i = 0; !bad && i < p.ncol; i++)
            for (int j = 0; j < p.ncol; j++)
                bad |= p.v[i * p.ncol + j] != p.v[j * p.ncol + i];
        if (bad) {
            free(p.v);
            gr_error(g, "fix property/global %s: per-atomtype property matrix must be symmetric, "
                        "i.e. N atom types require you to define N columns and N rows with N*N "
                        "total values", p.name);
        }
    }
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *o = g->styles.fix[i];
        if (o != f && o->style == &fix_style_property_global && strcmp(o->id, f->id) &&
            !strcmp(((const struct fpg *)o->data)->name, p.name)) {
            free(p.v);
            gr_error(g, "fix property/global: fix %s already registers a variable of the same "
                        "name (%s)", o->id, p.name);
        }
    }
    struct fpg *d = gr_malloc(g, sizeof *d);
    *d = p;
    f->data = d;
}

static void destroy(struct fix *f)
{
    struct fpg *d = f->data;
    if (d)
        free(d->v);
    free(d);
    f->data = NULL;
}

/* thermo f_ID (scalar) and f_ID[i] (vector forms; matrices flattened) */
static double scalar(struct gravel *g, struct fix *f)
{
    (void)g;
    return ((const struct fpg *)f->data)->v[0];
}

static double vector(struct gravel *g, struct fix *f, int i)
{
    const struct fpg *d = f->data;
    if (i < 1 || i > d->n)
        gr_error(g, "fix %s (property/global %s): index %d out of range 1..%d", f->id, d->name, i,
                 d->n);
    return d->v[i - 1];
}

const struct fix_style fix_style_property_global = {
    .name = "property/global",
    .create = create,
    .destroy = destroy,
    .scalar = scalar,
    .size_vector = 1 << 30,
    .vector = vector,
};

const struct fpg *fpg_find(struct gravel *g, const char *name)
{
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *o = g->styles.fix[i];
        if (o->style == &fix_style_property_global && !strcmp(((const struct fpg *)o->data)->name,
                                                                name))
            return o->data;
    }
    return NULL;
}

static const struct fpg *need(struct gravel *g, const char *name, const char *who)
{
    const struct fpg *p = fpg_find(g, name);
    if (!p)
        gr_error(g, "%s requires a fix property/global that defines %s", who, name);
    return p;
}

double fpg_scalar(struct gravel *g, const char *name, const char *who)
{
    const struct fpg *p = need(g, name, who);
    if (p->form != FPG_SCALAR)
        gr_error(g, "%s: property %s must be defined as a scalar (fix property/global %s "
                    "scalar value)", who, name, name);
    return p->v[0];
}

const double *fpg_pertype(struct gravel *g, const char *name, int nt, const char *who)
{
    const struct fpg *p = need(g, name, who);
    if (p->form != FPG_PERATOMTYPE && p->form != FPG_VECTOR)
        gr_error(g, "%s: property %s must be defined per atom type (fix property/global %s "
                    "peratomtype v1 ... vN)", who, name, name);
    if (p->n < nt)
        gr_error(g, "%s: property %s has %d value(s), %d atom type(s) need one each", who, name,
                 p->n, nt);
    return p->v;
}

double fpg_pair(struct gravel *g, const char *name, int nt, int I, int J, const char *who)
{
    const struct fpg *p = need(g, name, who);
    if (p->form != FPG_PERATOMTYPEPAIR && p->form != FPG_MATRIX)
        gr_error(g, "%s: property %s must be defined per atom type pair (fix property/global %s "
                    "peratomtypepair N v11 ... vNN)", who, name, name);
    if (p->ncol < nt || p->n / p->ncol < nt)
        gr_error(g, "%s: property %s is a %d x %d matrix, %d atom type(s) need %d x %d", who,
                 name, p->n / p->ncol, p->ncol, nt, nt, nt);
    return p->v[(size_t)(I - 1) * p->ncol + (J - 1)];
}
