/* compute_reduce.c - `compute ID group reduce mode input1 input2 ...`:
 * reduce per-atom quantities over the atoms of the group, as LAMMPS' compute
 * reduce. mode = sum | min | max | ave | sumsq | avesq | sumabs | aveabs.
 * Inputs: x y z vx vy vz fx fy fz radius diameter mass omegax omegay omegaz
 * tqx tqy tqz, c_ID / c_ID[N] (a per-atom compute's vector, or column N of
 * its array; or a local compute's, e.g. pair/local: then every row counts,
 * whatever the group and region, as LAMMPS) or v_name (an atom-style
 * variable). One input gives a global scalar,
 * several a global vector (one element per input). Sum modes are extensive.
 * An empty group gives 0 for sums and averages, 1e20 for min and -1e20 for
 * max (LAMMPS' values).
 *
 * `compute ID group reduce/region region-ID mode input1 ...` (LAMMPS's
 * compute reduce/region) is the same over the atoms of the group that are
 * inside the region at evaluation time (region motion applied). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "compute.h"
#include "error.h"
#include "fix.h"
#include "region.h"
#include "variable.h"

enum mode { SUM, SUMSQ, SUMABS, MIN, MAX, AVE, AVESQ, AVEABS };

struct input {
    int field;                  /* index into fields[] or -1 for a compute */
    int var;                    /* v_name: cid holds the variable's name */
    char cid[GR_NAMELEN];       /* per-atom compute ID */
    int index;                  /* c_ID[N]: column N of a per-atom array; 0: vector */
    int local;                  /* c_ID of a local compute (rows, not atoms) */
    int fix;                    /* f_ID / f_ID[N] (cid holds the reference): a fix's
                                 * per-atom output */
};

struct reduce {
    char region[GR_NAMELEN];    /* reduce/region: its region, "" for reduce */
    enum mode mode;
    int n;
    struct input *in;
};

/* Per-atom attributes: array, stride, component, scale. */
static const struct {
    const char *name;
    int which, comp;
    double scale;
} fields[] = {
    {"x", 0, 0, 1},      {"y", 0, 1, 1},      {"z", 0, 2, 1},      {"vx", 1, 0, 1},
    {"vy", 1, 1, 1},     {"vz", 1, 2, 1},     {"fx", 2, 0, 1},     {"fy", 2, 1, 1},
    {"fz", 2, 2, 1},     {"omegax", 3, 0, 1}, {"omegay", 3, 1, 1}, {"omegaz", 3, 2, 1},
    {"tqx", 4, 0, 1},    {"tqy", 4, 1, 1},    {"tqz", 4, 2, 1},    {"radius", 5, 0, 1},
    {"diameter", 5, 0, 2}, {"mass", 6, 0, 1},
};
#define NFIELDS ((int)(sizeof fields / sizeof fields[0]))

static const struct {
    const char *name;
    enum mode mode;
} modes[] = {{"sum", SUM},     {"sumsq", SUMSQ}, {"sumabs", SUMABS}, {"min", MIN},
             {"max", MAX},     {"ave", AVE},     {"avesq", AVESQ},   {"aveabs", AVEABS}};

static void reduce_destroy(struct compute *c)
{
    struct reduce *r = c->data;
    if (r)
        free(r->in);
    free(r);
    c->data = NULL;
}

static void reduce_parse(struct gravel *g, struct compute *c, struct reduce *r, int argc,
                         char **argv);

static void reduce_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, "compute reduce expects a mode and at least one input");
    struct reduce *r = gr_calloc(g, 1, sizeof *r);
    c->data = r;
    reduce_parse(g, c, r, argc, argv);
}

static void reduce_region_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "compute reduce/region expects a region ID, a mode and at least one input");
    struct reduce *r = gr_calloc(g, 1, sizeof *r);
    c->data = r;
    region_get(g, argv[0]); /* must exist now, as LAMMPS */
    snprintf(r->region, sizeof r->region, "%s", argv[0]);
    reduce_parse(g, c, r, argc - 1, argv + 1);
}

/* mode input1 input2 ...: the part reduce and reduce/region share */
static void reduce_parse(struct gravel *g, struct compute *c, struct reduce *r, int argc,
                         char **argv)
{
    int m = -1;
    for (int k = 0; k < (int)(sizeof modes / sizeof modes[0]); k++)
        if (strcmp(argv[0], modes[k].name) == 0)
            m = k;
    if (m < 0)
        gr_error(g, "compute reduce: unknown mode '%.64s' (sum, min, max, ave, sumsq, avesq, "
                    "sumabs, aveabs)", argv[0]);
    r->mode = modes[m].mode;
    /* keywords after the inputs (LAMMPS): `inputs peratom|local` says which
     * kind every input is (without it, each c_ID is taken as it is) */
    int nin = argc, want = -1; /* -1: either kind, 0: per-atom, 1: local */
    for (int k = 1; k < argc; k++)
        if (strcmp(argv[k], "inputs") == 0 || strcmp(argv[k], "replace") == 0) {
            nin = k;
            break;
        }
    for (int k = nin; k < argc; k += 2) {
        if (strcmp(argv[k], "replace") == 0)
            gr_error(g, "compute reduce: keyword 'replace' is not supported");
        if (strcmp(argv[k], "inputs") != 0)
            gr_error(g, "compute reduce: unknown keyword '%.64s' (inputs)", argv[k]);
        if (k + 1 >= argc || (strcmp(argv[k + 1], "peratom") && strcmp(argv[k + 1], "local")))
            gr_error(g, "compute reduce: inputs expects peratom or local");
        want = strcmp(argv[k + 1], "local") == 0;
    }
    if (nin < 2)
        gr_error(g, "compute reduce expects a mode and at least one input");
    argc = nin;
    r->in = gr_calloc(g, (size_t)argc, sizeof *r->in);
    for (int k = 1; k < argc; k++) {
        const char *s = argv[k];
        struct input *in = &r->in[r->n];
        in->field = -1;
        for (int f = 0; f < NFIELDS; f++)
            if (strcmp(s, fields[f].name) == 0)
                in->field = f;
        if (in->field < 0) {
            if (strncmp(s, "v_", 2) == 0 && s[2]) {
                if (strlen(s + 2) >= GR_NAMELEN)
                    gr_error(g, "compute reduce: variable name '%.64s' is too long", s);
                in->var = 1;
                snprintf(in->cid, sizeof in->cid, "%s", s + 2);
                r->n++;
                continue;
            }
            if (strncmp(s, "f_", 2) == 0) { /* a fix's per-atom output: as LAMMPS, the fix
                                               * must exist now; init checks again */
                if (strlen(s) >= sizeof in->cid)
                    gr_error(g, "compute reduce: fix reference '%.64s' is too long", s);
                fix_peratom_check(g, s, "compute reduce");
                in->fix = 1;
                snprintf(in->cid, sizeof in->cid, "%s", s);
                r->n++;
                continue;
            }
            if (!compute_parse_ref(s, in->cid, &in->index))
                gr_error(g, "compute reduce: unknown input '%.64s'", s);
            if (strcmp(in->cid, c->id) == 0)
                gr_error(g, "compute reduce: compute %s cannot reduce itself", c->id);
            /* as LAMMPS: the compute must exist (per-atom or local) now; init
             * checks again */
            struct compute *ic = compute_get(g, in->cid, "compute reduce");
            in->local = want >= 0 ? want : ic->local_flag && !ic->peratom_flag;
            if (in->local)
                compute_local_check(g, in->cid, in->index, "compute reduce");
            else
                compute_peratom_check(g, in->cid, in->index, "compute reduce");
        }
        r->n++;
    }
    for (int k = 0; want == 1 && k < r->n; k++)
        if (!r->in[k].local) /* atom attributes, variables and fix outputs are per atom */
            gr_error(g, "compute reduce: inputs local takes only c_ID and c_ID[N] of local "
                        "computes: '%.64s' is per atom", argv[k + 1]);
    if (r->n == 1) {
        c->scalar_flag = 1;
        c->extscalar = r->mode == SUM || r->mode == SUMSQ || r->mode == SUMABS;
    } else {
        c->vector_flag = 1;
        c->size_vector = r->n;
        c->extvector = r->mode == SUM || r->mode == SUMSQ || r->mode == SUMABS;
    }
}

static void reduce_init(struct gravel *g, struct compute *c)
{
    struct reduce *r = c->data;
    for (int k = 0; k < r->n; k++) {
        if (r->in[k].field >= 0)
            continue;
        if (r->in[k].var) {
            var_check_atom(g, r->in[k].cid, "compute reduce");
            continue;
        }
        if (r->in[k].fix) {
            fix_peratom_check(g, r->in[k].cid, "compute reduce");
            continue;
        }
        if (r->in[k].local)
            compute_local_check(g, r->in[k].cid, r->in[k].index, "compute reduce");
        else
            compute_peratom_check(g, r->in[k].cid, r->in[k].index, "compute reduce");
    }
}

static double combine(enum mode mode, double acc, double v)
{
    switch (mode) {
    case SUM: case AVE: return acc + v;
    case SUMSQ: case AVESQ: return acc + v * v;
    case SUMABS: case AVEABS: return acc + fabs(v);
    case MIN: return v < acc ? v : acc;
    case MAX: return v > acc ? v : acc;
    }
    return acc;
}

/* Reduce one input over the group (a local input: over its rows). */
static double reduce_one(struct gravel *g, struct compute *c, const struct input *in)
{
    const struct atoms *a = &g->atoms;
    struct reduce *r = c->data;
    const double *src = NULL;
    double *vals = NULL;
    int stride = 1, comp = 0;
    double scale = 1.0;
    if (in->field >= 0) {
        const double *arrs[7] = {a->x, a->v, a->f, a->omega, a->torque, a->radius, a->rmass};
        int which = fields[in->field].which;
        src = arrs[which];
        stride = which <= 4 ? 3 : 1;
        comp = fields[in->field].comp;
        scale = fields[in->field].scale;
    } else if (in->var) {
        vals = var_atom_values(g, in->cid);
        src = vals;
    } else if (in->fix) {
        src = fix_peratom_ref(g, in->cid, &stride, "compute reduce");
    } else if (!in->local) {
        struct compute *pc = compute_get(g, in->cid, "compute reduce");
        src = compute_peratom_ref(g, pc, in->index, &stride, "compute reduce");
    }
    double acc = r->mode == MIN ? 1.0e20 : r->mode == MAX ? -1.0e20 : 0.0;
    bigint count = 0;
    if (in->local) { /* every row, in the compute's order (LAMMPS: no group or region) */
        struct compute *lc = compute_get(g, in->cid, "compute reduce");
        const double *rows;
        int nrow = compute_local(g, lc, &rows);
        int cols = lc->size_local_cols > 0 ? lc->size_local_cols : 1;
        const double *col = rows + (in->index > 0 ? in->index - 1 : 0);
        for (int k = 0; k < nrow; k++)
            acc = combine(r->mode, acc, col[(size_t)k * cols]);
        count = nrow;
        if ((r->mode == AVE || r->mode == AVESQ || r->mode == AVEABS) && count > 0)
            acc /= (double)count;
        return acc;
    }
    struct region *reg = NULL;
    if (r->region[0]) {
        reg = region_get(g, r->region);
        region_prematch(g, reg);
    }
    const int *order = atoms_tag_order(g);
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!(a->mask[i] & c->groupbit))
            continue;
        if (reg && !region_match(reg, a->x + 3 * i))
            continue;
        double v = scale * src[(size_t)stride * i + comp];
        count++;
        acc = combine(r->mode, acc, v);
    }
    free(vals);
    if ((r->mode == AVE || r->mode == AVESQ || r->mode == AVEABS) && count > 0)
        acc /= (double)count;
    return acc;
}

static double reduce_scalar(struct gravel *g, struct compute *c)
{
    reduce_init(g, c);
    return reduce_one(g, c, &((struct reduce *)c->data)->in[0]);
}

static void reduce_vector(struct gravel *g, struct compute *c)
{
    struct reduce *r = c->data;
    reduce_init(g, c);
    for (int k = 0; k < r->n; k++)
        c->vector[k] = reduce_one(g, c, &r->in[k]);
}

const struct compute_style compute_style_reduce = {
    .name = "reduce",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = reduce_create,
    .init = reduce_init,
    .scalar = reduce_scalar,
    .vector = reduce_vector,
    .destroy = reduce_destroy,
};

const struct compute_style compute_style_reduce_region = {
    .name = "reduce/region",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = reduce_region_create,
    .init = reduce_init,
    .scalar = reduce_scalar,
    .vector = reduce_vector,
    .destroy = reduce_destroy,
};
