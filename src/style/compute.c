/* compute.c - the compute registry (built from styles/styles.def), the
 * `compute` and `uncompute` commands, and evaluation of c_ID references. */
#include "compute.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "ref.h"

#define PAIR(k, i)
#define FIX(k, i)
#define DUMP(k, i)
#define REGION(k, i)
#define COMPUTE(k, i) extern const struct compute_style compute_style_##i;
#include "styles.def"
#undef COMPUTE

static const struct compute_style *const compute_styles[] = {
#define COMPUTE(k, i) &compute_style_##i,
#include "styles.def"
#undef COMPUTE
    NULL};
#undef PAIR
#undef FIX
#undef DUMP
#undef REGION

void compute_temp_arg(struct gravel *g, const char *arg, char *id, const char *who)
{
    if (strlen(arg) >= GR_NAMELEN)
        gr_error(g, "%s: temperature ID is too long", who);
    snprintf(id, GR_NAMELEN, "%s", strcmp(arg, "NULL") ? arg : "");
}

void compute_virial_terms(struct gravel *g, int argc, char **argv, int *keflag, int *virialflag,
                          const char *who)
{
    static const char *const none[] = {"fix", "bond", "angle", "dihedral", "improper", "kspace"};
    *keflag = *virialflag = argc == 0;
    for (int i = 0; i < argc; i++) {
        int known = !strcmp(argv[i], "ke") || !strcmp(argv[i], "pair") ||
                    !strcmp(argv[i], "virial");
        for (size_t k = 0; k < sizeof none / sizeof *none; k++)
            known |= !strcmp(argv[i], none[k]);
        if (!known)
            gr_error(g, "%s: unknown keyword '%.64s' (ke, pair, bond, angle, dihedral, improper, "
                        "kspace, fix, virial)", who, argv[i]);
        if (!strcmp(argv[i], "ke"))
            *keflag = 1;
        else if (!strcmp(argv[i], "pair") || !strcmp(argv[i], "virial"))
            *virialflag = 1;
    }
}

struct temp_state *compute_temp_named(struct gravel *g, const char *id, const char *who)
{
    if (!id[0])
        return NULL;
    if (!strcmp(id, "thermo_temp") && !compute_find(g, "thermo_temp"))
        return &g->thermo.temp; /* LAMMPS's implicit thermo_temp */
    struct compute *t = compute_get(g, id, who);
    if (!t->temp)
        gr_error(g, "%s: compute %s (%s) is not a temperature", who, t->id, t->style->name);
    return t->temp;
}

double compute_mvv2e(const struct gravel *g)
{
    /* lj, si and cgs are all self-consistent mass/velocity/energy systems */
    (void)g;
    return 1.0;
}

struct compute *compute_find(struct gravel *g, const char *id)
{
    for (int i = 0; i < g->styles.ncompute; i++)
        if (strcmp(g->styles.compute[i]->id, id) == 0)
            return g->styles.compute[i];
    return NULL;
}

struct compute *compute_get(struct gravel *g, const char *id, const char *who)
{
    struct compute *c = compute_find(g, id);
    if (!c)
        gr_error(g, "%s refers to unknown compute ID '%.64s'", who, id);
    return c;
}

static void compute_delete(struct compute *c)
{
    if (!c)
        return;
    if (c->style && c->style->destroy)
        c->style->destroy(c);
    else
        free(c->data); /* plain state (e.g. a temperature's struct temp_state) */
    free(c->vector);
    free(c->peratom);
    free(c->local);
    free(c->array);
    free(c);
}

/* IDs are letters, digits and underscores, like LAMMPS. */
static void check_id(struct gravel *g, const char *id)
{
    size_t n = strlen(id);
    if (n == 0 || n >= GR_NAMELEN)
        gr_error(g, "compute ID must have 1 to %d characters", GR_NAMELEN - 1);
    for (size_t k = 0; k < n; k++)
        if (!isalnum((unsigned char)id[k]) && id[k] != '_')
            gr_error(g, "compute ID '%.64s' may contain only letters, digits and underscores",
                     id);
}

int compute_style_known(const char *name)
{
    for (int k = 0; compute_styles[k]; k++)
        if (!strcmp(compute_styles[k]->name, name))
            return 1;
    return 0;
}

void cmd_compute(struct gravel *g, int argc, char **argv)
{
    check_id(g, argv[0]);
    if (compute_find(g, argv[0]))
        gr_error(g, "compute ID '%.64s' already exists; use uncompute first", argv[0]);
    int igroup = arg_group(g, argv[1]);
    const struct compute_style *st = NULL;
    for (int k = 0; compute_styles[k]; k++)
        if (strcmp(compute_styles[k]->name, argv[2]) == 0)
            st = compute_styles[k];
    if (!st) {
        char known[512] = "";
        for (int k = 0; compute_styles[k]; k++) {
            strncat(known, k ? ", " : "", sizeof known - strlen(known) - 1);
            strncat(known, compute_styles[k]->name, sizeof known - strlen(known) - 1);
        }
        gr_error(g, "unknown compute style '%.64s' (known: %s)", argv[2], known);
    }

    struct compute *c = gr_calloc(g, 1, sizeof *c);
    strcpy(c->id, argv[0]);
    c->style = st;
    c->igroup = igroup;
    c->groupbit = 1u << igroup;

    /* register first so a failing create is cleaned up by compute_free_all
     * rather than leaked across the longjmp */
    struct styles *s = &g->styles;
    if (s->ncompute == s->ncompute_cap) {
        int cap = s->ncompute_cap ? 2 * s->ncompute_cap : 8;
        struct compute **p = realloc(s->compute, (size_t)cap * sizeof *p);
        if (!p) {
            free(c);
            gr_error(g, "out of memory");
        }
        s->compute = p;
        s->ncompute_cap = cap;
    }
    s->compute[s->ncompute++] = c;

    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        /* creation failed: unregister, free, and pass the error on */
        g->err.jmp = outer;
        s->ncompute--;
        compute_delete(c);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    st->create(g, c, argc - 3, argv + 3);
    g->err.jmp = outer;
    if (c->vector_flag && !c->vector)
        c->vector = gr_calloc(g, (size_t)(c->size_vector > 0 ? c->size_vector : 1),
                              sizeof(double));
}

void cmd_uncompute(struct gravel *g, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, "expected: uncompute ID");
    struct styles *s = &g->styles;
    for (int i = 0; i < s->ncompute; i++) {
        if (strcmp(s->compute[i]->id, argv[0]) != 0)
            continue;
        compute_delete(s->compute[i]);
        memmove(s->compute + i, s->compute + i + 1,
                (size_t)(s->ncompute - i - 1) * sizeof *s->compute);
        s->ncompute--;
        return;
    }
    gr_error(g, "unknown compute ID '%.64s'", argv[0]);
}

double compute_scalar(struct gravel *g, struct compute *c)
{
    if (!c->scalar_flag)
        gr_error(g, "compute %s (%s) does not produce a global scalar", c->id, c->style->name);
    return c->style->scalar(g, c);
}

const double *compute_vector(struct gravel *g, struct compute *c)
{
    if (!c->vector_flag)
        gr_error(g, "compute %s (%s) does not produce a global vector", c->id, c->style->name);
    c->style->vector(g, c);
    return c->vector;
}

const double *compute_array(struct gravel *g, struct compute *c)
{
    if (!c->array_flag)
        gr_error(g, "compute %s (%s) does not produce a global array", c->id, c->style->name);
    c->style->array(g, c);
    return c->array;
}

const double *compute_peratom(struct gravel *g, struct compute *c)
{
    if (!c->peratom_flag)
        gr_error(g, "compute %s (%s) does not produce per-atom values", c->id,
                 c->style->name);
    int cols = c->size_peratom_cols > 0 ? c->size_peratom_cols : 1;
    int n = g->atoms.n;
    if (n > c->peratom_cap || !c->peratom) {
        int cap = n > 16 ? n : 16;
        double *p = realloc(c->peratom, (size_t)cap * cols * sizeof(double));
        if (!p)
            gr_error(g, "out of memory for compute %s", c->id);
        c->peratom = p;
        c->peratom_cap = cap;
    }
    c->style->peratom(g, c);
    return c->peratom;
}

double *compute_local_rows(struct gravel *g, struct compute *c, int rows)
{
    int cols = c->size_local_cols > 0 ? c->size_local_cols : 1;
    if (rows > c->local_cap || !c->local) {
        int cap = rows > 16 ? rows : 16;
        double *p = realloc(c->local, (size_t)cap * cols * sizeof(double));
        if (!p)
            gr_error(g, "out of memory for compute %s", c->id);
        c->local = p;
        c->local_cap = cap;
    }
    c->size_local_rows = rows;
    return c->local;
}

int compute_local(struct gravel *g, struct compute *c, const double **data)
{
    if (!c->local_flag)
        gr_error(g, "compute %s (%s) does not produce local values", c->id, c->style->name);
    compute_local_rows(g, c, 0);
    c->style->local(g, c);
    *data = c->local;
    return c->size_local_rows;
}

void compute_local_check(struct gravel *g, const char *id, int index, const char *who)
{
    struct compute *c = compute_get(g, id, who);
    if (!c->local_flag)
        gr_error(g, "%s: compute %s (%s) does not produce local values", who, c->id,
                 c->style->name);
    if (index == 0 && c->size_local_cols > 0)
        gr_error(g, "%s: compute %s has %d local columns; use c_%s[N]", who, c->id,
                 c->size_local_cols, c->id);
    if (index > 0 && c->size_local_cols == 0)
        gr_error(g, "%s: compute %s has one local value per row; use c_%s", who, c->id, c->id);
    if (index > c->size_local_cols)
        gr_error(g, "%s: c_%s[%d] is out of range: compute %s has %d local columns", who,
                 c->id, index, c->id, c->size_local_cols);
}

void compute_peratom_check(struct gravel *g, const char *id, int index, const char *who)
{
    struct compute *c = compute_get(g, id, who);
    if (!c->peratom_flag)
        gr_error(g, "%s: compute %s (%s) does not produce per-atom values", who, c->id,
                 c->style->name);
    if (index == 0 && c->size_peratom_cols > 0)
        gr_error(g, "%s: compute %s has %d per-atom columns; use c_%s[N]", who, c->id,
                 c->size_peratom_cols, c->id);
    if (index > 0 && c->size_peratom_cols == 0)
        gr_error(g, "%s: compute %s has one per-atom value; use c_%s", who, c->id, c->id);
    if (index > c->size_peratom_cols)
        gr_error(g, "%s: c_%s[%d] is out of range: compute %s has %d per-atom columns", who,
                 c->id, index, c->id, c->size_peratom_cols);
}

const double *compute_peratom_ref(struct gravel *g, struct compute *c, int index, int *stride,
                                  const char *who)
{
    compute_peratom_check(g, c->id, index, who);
    const double *p = compute_peratom(g, c);
    *stride = c->size_peratom_cols > 0 ? c->size_peratom_cols : 1;
    return index > 0 ? p + (index - 1) : p;
}

int compute_parse_ref2(const char *ref, char *id, int *index, int *col)
{
    return ref_parse(ref, 'c', id, index, col);
}

int compute_parse_ref(const char *ref, char *id, int *index)
{
    int col;
    return compute_parse_ref2(ref, id, index, &col) && col == 0;
}

double *compute_array_rows(struct gravel *g, struct compute *c, int rows)
{
    int cols = c->size_array_cols > 0 ? c->size_array_cols : 1;
    if (rows > c->array_cap || !c->array) {
        int cap = rows > 16 ? rows : 16;
        double *p = realloc(c->array, (size_t)cap * cols * sizeof(double));
        if (!p)
            gr_error(g, "out of memory for compute %s", c->id);
        c->array = p;
        c->array_cap = cap;
    }
    c->size_array_rows = rows;
    return c->array;
}

void compute_ref_check(struct gravel *g, const char *ref, const char *who)
{
    char id[GR_NAMELEN];
    int index, col;
    if (!compute_parse_ref2(ref, id, &index, &col))
        gr_error(g, "%s: invalid compute reference '%.64s' (use c_ID, c_ID[N] or c_ID[I][J])",
                 who, ref);
    struct compute *c = compute_get(g, id, who);
    if (col > 0) {
        if (!c->array_flag)
            gr_error(g, "%s: compute %s (%s) does not produce a global array", who, id,
                     c->style->name);
        if (col > c->size_array_cols)
            gr_error(g, "%s: %s is out of range: compute %s has %d columns", who, ref, id,
                     c->size_array_cols);
        return;
    }
    if (index == 0 && !c->scalar_flag)
        gr_error(g, "%s: compute %s (%s) does not produce a global scalar%s", who, id,
                 c->style->name, c->vector_flag ? "; use c_ID[N] for its vector" : "");
    if (index > 0 && !c->vector_flag)
        gr_error(g, "%s: compute %s (%s) does not produce a global vector", who, id,
                 c->style->name);
    if (index > 0 && index > c->size_vector && !c->size_vector_variable)
        gr_error(g, "%s: %s is out of range: compute %s has %d values", who, ref, id,
                 c->size_vector);
}

double compute_ref_value(struct gravel *g, const char *ref, long long norm, const char *who)
{
    char id[GR_NAMELEN];
    int index, col;
    compute_ref_check(g, ref, who);
    compute_parse_ref2(ref, id, &index, &col);
    struct compute *c = compute_find(g, id);
    double v;
    int ext;
    if (col > 0) {
        compute_array(g, c);
        if (index > c->size_array_rows)
            gr_error(g, "%s: %s is out of range: compute %s has %d rows now", who, ref, id,
                     c->size_array_rows);
        v = c->array[(size_t)(index - 1) * c->size_array_cols + (col - 1)];
        ext = c->extarray;
    } else if (index == 0) {
        v = compute_scalar(g, c);
        ext = c->extscalar;
    } else {
        const double *vec = compute_vector(g, c);
        if (index > c->size_vector)
            gr_error(g, "%s: %s is out of range: compute %s has %d values now", who, ref, id,
                     c->size_vector);
        v = vec[index - 1];
        ext = c->extvector;
    }
    if (norm > 0 && ext)
        v /= (double)norm;
    return v;
}

void compute_init_all(struct gravel *g)
{
    for (int i = 0; i < g->styles.ncompute; i++) {
        struct compute *c = g->styles.compute[i];
        if (c->style->init)
            c->style->init(g, c);
    }
}

void compute_free_all(struct gravel *g)
{
    for (int i = 0; i < g->styles.ncompute; i++)
        compute_delete(g->styles.compute[i]);
    free(g->styles.compute);
    g->styles.compute = NULL;
    g->styles.ncompute = g->styles.ncompute_cap = 0;
}
