/* variable.c - the variable store: styles index, loop, string, equal, format,
 * getenv; the `variable` and `next` semantics of LAMMPS; the random stream of
 * random()/normal(): as LAMMPS, one RanMars (src/core/random.c) shared by every
 * formula, seeded by the seed of the first call; later seeds are checked but
 * do not restart it (LAMMPS Variable::randomequal).
 *
 * Variables live in a small array (scripts define tens, not thousands), looked
 * up by name. Loop variables store only their range, so `loop 1000000000`
 * costs nothing. Every definition is validated completely before anything is
 * changed, so a failed `variable` command leaves the store as it was. */
#include "variable.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "expr.h"
#include "log.h"
#include "random.h"

enum vstyle { V_INDEX, V_LOOP, V_STRING, V_EQUAL, V_FORMAT, V_GETENV, V_ATOM };
static const char *style_names[] = {"index", "loop", "string", "equal", "format", "getenv",
                                    "atom"};

struct var {
    char *name;
    enum vstyle style;
    int nval;               /* index: number of values; loop: count */
    char **val;             /* index: values; string/equal/getenv: [0]; format: [0] var, [1] fmt */
    int which;              /* current index (0-based) */
    long first;             /* loop: first value */
    int pad;                /* loop: zero-pad width, 0 = none */
};

struct vars {
    int n, cap;
    struct var *v;
    char *ret;              /* var_retrieve's text */
    size_t retcap;
    int mars_on;            /* the random()/normal() stream exists */
    struct rng_mars mars;
};

struct vars *var_create(void)
{
    return calloc(1, sizeof(struct vars));
}

static void var_free_one(struct var *v)
{
    free(v->name);
    int nv = v->style == V_INDEX ? v->nval : v->style == V_FORMAT ? 2
           : v->style == V_LOOP ? 0 : 1;
    for (int i = 0; i < nv; i++)
        free(v->val[i]);
    free(v->val);
}

void var_destroy(struct vars *vs)
{
    if (!vs)
        return;
    for (int i = 0; i < vs->n; i++)
        var_free_one(&vs->v[i]);
    free(vs->v);
    free(vs->ret);
    free(vs);
}

int var_count(const struct gravel *g)
{
    return g->vars->n;
}

static struct var *find(struct gravel *g, const char *name)
{
    struct vars *vs = g->vars;
    for (int i = 0; i < vs->n; i++)
        if (strcmp(vs->v[i].name, name) == 0)
            return &vs->v[i];
    return NULL;
}

int var_exists(struct gravel *g, const char *name)
{
    return find(g, name) != NULL;
}

static void remove_var(struct gravel *g, struct var *v)
{
    struct vars *vs = g->vars;
    var_free_one(v);
    int i = (int)(v - vs->v);
    memmove(&vs->v[i], &vs->v[i + 1], (size_t)(vs->n - i - 1) * sizeof *vs->v);
    vs->n--;
}

static void check_name(struct gravel *g, const char *name)
{
    if (!*name)
        gr_error(g, "variable name is empty");
    if (strlen(name) >= GR_NAMELEN)
        gr_error(g, "variable name '%.64s...' is longer than %d characters", name, GR_NAMELEN - 1);
    for (const char *p = name; *p; p++)
        if (!isalnum((unsigned char)*p) && *p != '_')
            gr_error(g, "variable name '%s' may contain only letters, digits and '_'", name);
}

/* Environment variable names: the characters of ours, but of any length
 * (the name is the environment's, not a gravel variable's). */
static void check_env_name(struct gravel *g, const char *name)
{
    if (!*name)
        gr_error(g, "environment variable name is empty");
    for (const char *p = name; *p; p++)
        if (!isalnum((unsigned char)*p) && *p != '_')
            gr_error(g, "environment variable name '%.64s' may contain only letters, digits "
                        "and '_'", name);
}

/* Append a new, empty variable; the caller fills it. Allocation happens
 * before any field is set, so an out-of-memory error leaves no half entry. */
static struct var *append(struct gravel *g, const char *name, enum vstyle style, int nval)
{
    struct vars *vs = g->vars;
    char *dupname = gr_strdup(g, name);
    /* loop variables store only their range: no value slots */
    int nslots = style == V_LOOP ? 1 : nval > 0 ? nval : 1;
    char **val = calloc((size_t)nslots, sizeof(char *));
    if (!val) {
        free(dupname);
        gr_error(g, "out of memory");
    }
    if (vs->n == vs->cap) {
        int cap = vs->cap ? 2 * vs->cap : 16;
        struct var *nv = realloc(vs->v, (size_t)cap * sizeof *nv);
        if (!nv) {
            free(dupname);
            free(val);
            gr_error(g, "out of memory");
        }
        vs->v = nv;
        vs->cap = cap;
    }
    struct var *v = &vs->v[vs->n++];
    memset(v, 0, sizeof *v);
    v->name = dupname;
    v->style = style;
    v->val = val;
    v->nval = nval;
    return v;
}

/* Copy values into v->val; on allocation failure remove v and raise. */
static void fill(struct gravel *g, struct var *v, int n, char **values)
{
    for (int i = 0; i < n; i++) {
        v->val[i] = strdup(values[i]);
        if (!v->val[i]) {
            remove_var(g, v);
            gr_error(g, "out of memory");
        }
    }
}

void var_set_index(struct gravel *g, const char *name, int n, char **values)
{
    check_name(g, name);
    if (n < 1)
        gr_error(g, "index variable '%s' needs at least one value", name);
    struct var *old = find(g, name);
    if (old)
        remove_var(g, old); /* the command line redefines */
    struct var *v = append(g, name, V_INDEX, n);
    fill(g, v, n, values);
}

static long loop_bound(struct gravel *g, const char *s, const char *what)
{
    bigint x = arg_bigint(g, s, what);
    if (x < 1 || x > 2000000000)
        gr_error(g, "%s must be between 1 and 2000000000, got %s", what, s);
    return (long)x;
}

void var_define(struct gravel *g, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, "expected: variable NAME STYLE ARGS... or variable NAME delete");
    const char *name = argv[0], *style = argv[1];
    check_name(g, name);
    struct var *old = find(g, name);
    if (strcmp(style, "delete") == 0) {
        if (argc != 2)
            gr_error(g, "'variable %s delete' takes no further arguments", name);
        if (old) /* deleting an undefined variable is not an error, as LAMMPS */
            remove_var(g, old);
        return;
    }
    int s = -1;
    for (int i = 0; i < 7; i++)
        if (strcmp(style, style_names[i]) == 0)
            s = i;
    if (s < 0)
        gr_error(g, "unknown variable style '%.64s' (expected index, loop, string, equal, "
                 "format, getenv, atom or delete)", style);
    int nargs = argc - 2;
    char **a = argv + 2;
    if (old && (int)old->style != s && !(s == V_INDEX || s == V_LOOP))
        gr_error(g, "variable '%s' is already defined as %s-style; cannot redefine it as %s "
                 "(use 'variable %s delete' first)", name, style_names[old->style], style, name);
    switch (s) {
    case V_INDEX:
        if (nargs < 1)
            gr_error(g, "index variable '%s' needs at least one value", name);
        if (old)
            return; /* LAMMPS: an existing index/loop variable is kept (-var wins) */
        fill(g, append(g, name, V_INDEX, nargs), nargs, a);
        return;
    case V_LOOP: {
        int pad = 0;
        if (nargs >= 1 && strcmp(a[nargs - 1], "pad") == 0) {
            pad = 1;
            nargs--;
        }
        if (nargs < 1 || nargs > 2)
            gr_error(g, "expected: variable %s loop N [pad] or variable %s loop N1 N2 [pad]",
                     name, name);
        long lo = 1, hi;
        if (nargs == 1) {
            hi = loop_bound(g, a[0], "loop count N");
        } else {
            lo = loop_bound(g, a[0], "loop start N1");
            hi = loop_bound(g, a[1], "loop end N2");
            if (hi < lo)
                gr_error(g, "loop end N2 = %ld is smaller than start N1 = %ld", hi, lo);
        }
        if (old)
            return;
        struct var *v = append(g, name, V_LOOP, (int)(hi - lo + 1));
        v->first = lo;
        if (pad)
            v->pad = snprintf(NULL, 0, "%ld", hi);
        return;
    }
    case V_STRING:
    case V_EQUAL:
    case V_ATOM:
    case V_GETENV:
        if (nargs != 1)
            gr_error(g, "%s variable '%s' takes exactly one value, got %d (quote text that "
                     "contains spaces)", style, name, nargs);
        if (s == V_GETENV) /* an environment variable's name, not one of ours */
            check_env_name(g, a[0]);
        break;
    case V_FORMAT:
        if (nargs != 2)
            gr_error(g, "expected: variable %s format EQUAL_VARIABLE FORMAT", name);
        check_name(g, a[0]);
        if (!expr_format_ok(a[1]))
            gr_error(g, "invalid format '%.64s': expected one %%f, %%e or %%g conversion (with "
                     "optional flags, width and precision)", a[1]);
        break;
    }
    if (old)
        remove_var(g, old);
    fill(g, append(g, name, (enum vstyle)s, nargs), nargs, a);
}

int var_next(struct gravel *g, const char *name)
{
    struct var *v = find(g, name);
    if (!v)
        gr_error(g, "variable '%s' is not defined", name);
    if (v->style != V_INDEX && v->style != V_LOOP)
        gr_error(g, "variable '%s' is %s-style; only index and loop variables have a next value",
                 name, style_names[v->style]);
    if (++v->which >= v->nval) {
        remove_var(g, v);
        return 1;
    }
    return 0;
}

static const char *set_ret(struct gravel *g, const char *s)
{
    struct vars *vs = g->vars;
    size_t n = strlen(s) + 1;
    if (n > vs->retcap) {
        char *r = realloc(vs->ret, n);
        if (!r)
            gr_error(g, "out of memory");
        vs->ret = r;
        vs->retcap = n;
    }
    memmove(vs->ret, s, n);
    return vs->ret;
}

static const char *retrieve_depth(struct gravel *g, const char *name, int depth)
{
    struct var *v = find(g, name);
    if (!v)
        return NULL;
    char buf[1400];
    switch (v->style) {
    case V_INDEX:
        return v->val[v->which];
    case V_LOOP:
        snprintf(buf, sizeof buf, "%0*ld", v->pad, v->first + v->which);
        return set_ret(g, buf);
    case V_STRING:
        return v->val[0];
    case V_GETENV: {
        const char *e = getenv(v->val[0]);
        return set_ret(g, e ? e : "");
    }
    case V_EQUAL:
        snprintf(buf, sizeof buf, "%.15g", expr_eval_depth(g, v->val[0], depth + 1));
        return set_ret(g, buf);
    case V_ATOM:
        gr_error(g, "atom-style variable '%s' has one value per atom: use it as v_%s where "
                    "per-atom values are read (dump custom, compute reduce, group, set, "
                    "velocity)", name, name);
    case V_FORMAT: {
        const char *fmt = v->val[1]; /* validated by expr_format_ok at definition */
        double x = var_compute_equal_depth(g, v->val[0], depth + 1);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
        snprintf(buf, sizeof buf, fmt, x);
#pragma GCC diagnostic pop
        return set_ret(g, buf);
    }
    }
    return NULL;
}

const char *var_retrieve(struct gravel *g, const char *name)
{
    return retrieve_depth(g, name, 0);
}

double var_compute_equal_depth(struct gravel *g, const char *name, int depth)
{
    struct var *v = find(g, name);
    if (!v)
        gr_error(g, "variable '%s' is not defined (in v_%s)", name, name);
    if (depth > 200)
        gr_error(g, "variables nested more than 200 levels deep, at v_%s (do variables refer "
                 "to each other in a cycle?)", name);
    if (v->style == V_EQUAL)
        return expr_eval_depth(g, v->val[0], depth);
    if (v->style == V_ATOM)
        gr_error(g, "atom-style variable v_%s used where one value is needed (an equal-style "
                    "formula, thermo, $())", name);
    if (v->style == V_FORMAT)
        return var_compute_equal_depth(g, v->val[0], depth + 1);
    if (v->style == V_LOOP)
        return (double)(v->first + v->which);
    /* stable text (not the retrieve buffer, which nested lookups reuse) */
    const char *text = v->style == V_INDEX ? v->val[v->which]
                     : v->style == V_GETENV ? getenv(v->val[0]) : v->val[0];
    if (!text)
        gr_error(g, "environment variable '%s' of getenv variable '%s' is not set", v->val[0],
                 name);
    if (arg_is_number(text))
        return strtod(text, NULL);
    /* a string/index value that holds a formula is evaluated, as LAMMPS does */
    return expr_eval_depth(g, text, depth + 1);
}

bigint var_next_step(struct gravel *g, const char *name, bigint step, const char *who)
{
    if (!var_exists(g, name))
        gr_error(g, "%s '%s' is not defined", who, name);
    double v = var_compute_equal(g, name);
    if (!(v > (double)step && v < 9223372036854775808.0))
        gr_error(g, "%s '%s' returned %g, which is not a step after %lld", who, name, v,
                 (long long)step);
    bigint next = (bigint)v;
    return next > step ? next : step + 1; /* a step just after: (double)step rounded up */
}

double var_compute_equal(struct gravel *g, const char *name)
{
    return var_compute_equal_depth(g, name, 0);
}

int var_is_atom(struct gravel *g, const char *name)
{
    struct var *v = find(g, name);
    return v && v->style == V_ATOM;
}

int var_is_equal(struct gravel *g, const char *name)
{
    struct var *v = find(g, name);
    return v && v->style == V_EQUAL;
}

void var_compute_atom_depth(struct gravel *g, const char *name, double *out, int depth)
{
    struct var *v = find(g, name);
    if (!v)
        gr_error(g, "variable '%s' is not defined (in v_%s)", name, name);
    if (v->style != V_ATOM)
        gr_error(g, "variable '%s' is %s-style; per-atom values need an atom-style variable",
                 name, style_names[v->style]);
    if (depth > 200)
        gr_error(g, "variables nested more than 200 levels deep, at v_%s (do variables refer "
                 "to each other in a cycle?)", name);
    expr_eval_atoms(g, v->val[0], out, depth);
}

void var_compute_atom(struct gravel *g, const char *name, double *out)
{
    var_compute_atom_depth(g, name, out, 0);
}

double *var_atom_values(struct gravel *g, const char *name)
{
    double *v = gr_malloc(g, ((size_t)g->atoms.n + 1) * sizeof *v);
    jmp_buf *outer = g->err.jmp, here;
    g->err.jmp = &here;
    if (setjmp(here)) {
        g->err.jmp = outer;
        free(v);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    var_compute_atom(g, name, v);
    g->err.jmp = outer;
    return v;
}

void var_check_atom(struct gravel *g, const char *name, const char *who)
{
    struct var *v = find(g, name);
    if (!v)
        gr_error(g, "%s: variable '%s' is not defined", who, name);
    if (v->style != V_ATOM)
        gr_error(g, "%s: variable '%s' is %s-style, not atom-style", who, name,
                 style_names[v->style]);
}

void var_print_all(struct gravel *g)
{
    struct vars *vs = g->vars;
    gr_print(g, "Variables: %d\n", vs->n);
    for (int i = 0; i < vs->n; i++) {
        struct var *v = &vs->v[i];
        switch (v->style) {
        case V_INDEX:
            gr_print(g, "  %s index (%d of %d) = %s\n", v->name, v->which + 1, v->nval,
                     v->val[v->which]);
            break;
        case V_LOOP:
            gr_print(g, "  %s loop %ld..%ld = %ld\n", v->name, v->first,
                     v->first + v->nval - 1, v->first + v->which);
            break;
        case V_FORMAT:
            gr_print(g, "  %s format %s '%s'\n", v->name, v->val[0], v->val[1]);
            break;
        default:
            gr_print(g, "  %s %s '%s'\n", v->name, style_names[v->style], v->val[0]);
            break;
        }
    }
}

static struct rng_mars *stream(struct gravel *g, long seed)
{
    struct vars *vs = g->vars;
    if (!vs->mars_on) {
        if (seed < 1 || seed > 900000000)
            gr_error(g, "random seed %ld: the first seed of random()/normal() must be "
                        "between 1 and 900000000 (Marsaglia generator)", seed);
        rng_mars_init(&vs->mars, (int)seed);
        vs->mars_on = 1;
    }
    return &vs->mars;
}

double var_random_uniform(struct gravel *g, long seed)
{
    return rng_mars_uniform(stream(g, seed));
}

double var_random_gaussian(struct gravel *g, long seed)
{
    return rng_mars_gaussian(stream(g, seed));
}
