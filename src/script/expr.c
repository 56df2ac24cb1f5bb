/* expr.c - the expression evaluator behind equal-style variables and $(...).
 *
 * A recursive-descent parser that evaluates as it parses, with LAMMPS'
 * operators and precedence (lowest first):
 *     || |^      &&      == !=      < <= > >=      + -      * / %      ^
 *     unary - and !  (bind tighter than ^, so -2^2 = 4, as in LAMMPS)
 * All binary operators are left-associative (2^3^2 = 64, as in LAMMPS).
 * Operands: numbers, (expr), math functions, group functions on the host atom
 * arrays, per-atom values x[ID] ..., constants (PI, version, on/off, yes/no,
 * true/false), v_name, and anything thermo_keyword_value() knows (step, atoms,
 * c_ID, c_ID[n], f_ID[n], ...). Errors quote the expression and never leave
 * state behind: the parser allocates nothing, except the per-atom columns of
 * expr_eval_atoms, freed on every exit. */
#include "expr.h"

#include <ctype.h>
#include <setjmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atom_custom.h"
#include "atoms.h"
#include "compute.h"
#include "engine.h"
#include "error.h"
#include "feature.h"
#include "fix.h"
#include "group.h"
#include "par.h"
#include "region.h"
#include "thermo.h"
#include "variable.h"

#define MAXDEPTH 200        /* nesting of parentheses, unary operators and v_name
                             * references together: bounds the C stack */
#define BIG 1.0e20

/* Per-atom evaluation (expr_eval_atoms): the formula is parsed once per
 * atom, in atom order. The parse visits the same operands in the same order
 * for every atom (no short circuit), so operand k's resolution is made at
 * the first atom and kept in slot k: a global value (group function, thermo
 * keyword, v_ of an equal-style variable, x[ID]: evaluated once, as LAMMPS
 * does), or a per-atom column (c_ID of a per-atom compute, v_ of an
 * atom-style variable: computed once for all atoms). */
struct aslot {
    const double *col;      /* per-atom column (NULL: global value s) */
    int stride;
    double s;
    double *owned;          /* the column when this slot computed it */
};

struct actx {
    int i;                  /* current atom (host index) */
    int first;              /* the first atom: slots are being made */
    int resolve_only;       /* no atom: make the slots (their collectives), read none */
    int k;                  /* next slot */
    int n, cap;
    struct aslot *slot;
};

struct ep {
    struct gravel *g;
    const char *text;       /* whole expression, for messages */
    const char *p;          /* cursor */
    int depth;              /* current nesting, including enclosing v_name evaluations */
    struct actx *ax;        /* per-atom evaluation, else NULL */
};

static double parse_or(struct ep *e);

static _Noreturn void ep_fail(struct ep *e, const char *what)
{
    size_t len = strlen(e->text);
    gr_error(e->g, "%s in expression '%.*s%s'", what, len > 120 ? 120 : (int)len, e->text,
             len > 120 ? "..." : "");
}

static void skip_ws(struct ep *e)
{
    while (*e->p == ' ' || *e->p == '\t' || *e->p == '\n' || *e->p == '\r')
        e->p++;
}

/* Next operator token; advances past it when it matches. */
static int accept(struct ep *e, const char *op)
{
    skip_ws(e);
    size_t n = strlen(op);
    if (strncmp(e->p, op, n) != 0)
        return 0;
    /* "<" must not eat "<=", "|" alone is not an operator */
    if (n == 1 && (op[0] == '<' || op[0] == '>' || op[0] == '!' || op[0] == '=') &&
        e->p[1] == '=')
        return 0;
    e->p += n;
    return 1;
}

static void enter(struct ep *e)
{
    if (++e->depth > MAXDEPTH)
        ep_fail(e, "nesting deeper than 200 levels (parentheses, unary operators and "
                   "v_name references together; do variables refer to each other in a cycle?)");
}

/* The next operand slot of a per-atom evaluation: made at the first atom
 * (*made = 1: the caller fills it), read back at the others. */
static struct aslot *next_slot(struct ep *e, int *made)
{
    struct actx *a = e->ax;
    *made = a->first;
    if (a->first) {
        if (a->n == a->cap) {
            int cap = a->cap ? 2 * a->cap : 8;
            struct aslot *ns = realloc(a->slot, (size_t)cap * sizeof *ns);
            if (!ns)
                ep_fail(e, "out of memory");
            a->slot = ns;
            a->cap = cap;
        }
        memset(&a->slot[a->n], 0, sizeof *a->slot);
        a->n++;
    }
    if (a->k >= a->n)
        ep_fail(e, "internal error: per-atom operands out of step");
    return &a->slot[a->k++];
}

static double slot_value(const struct ep *e, const struct aslot *s)
{
    if (e->ax->resolve_only)
        return 0.0;
    return s->col ? s->col[(size_t)s->stride * e->ax->i] : s->s;
}

/* ---- group and atom functions ---------------------------------------------- */

static int group_index(struct ep *e, const char *name)
{
    int i = group_find(e->g, name);
    if (i < 0) {
        char msg[160];
        snprintf(msg, sizeof msg, "unknown group '%.64s'", name);
        ep_fail(e, msg);
    }
    return i;
}

static int dim_index(struct ep *e, const char *s)
{
    if (strcmp(s, "x") == 0)
        return 0;
    if (strcmp(s, "y") == 0)
        return 1;
    if (strcmp(s, "z") == 0)
        return 2;
    char msg[160];
    snprintf(msg, sizeof msg, "expected x, y or z, got '%.64s'", s);
    ep_fail(e, msg);
}

/* Per-atom mass: rmass, or the per-type mass where rmass is unset. */
static double atom_mass(const struct atoms *a, int i)
{
    if (a->rmass && a->rmass[i] > 0)
        return a->rmass[i];
    if (a->type_mass && a->type[i] >= 1 && a->type[i] <= a->ntypes)
        return a->type_mass[a->type[i]];
    return 0;
}

/* inertia()'s second argument: xx yy zz xy yz xz (LAMMPS's dimdim) */
static void dimdim_index(struct ep *e, const char *s, int *r, int *c)
{
    static const char *const names[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
    static const int rows[6] = {0, 1, 2, 0, 1, 0}, cols[6] = {0, 1, 2, 1, 2, 2};
    for (int k = 0; k < 6; k++)
        if (!strcmp(s, names[k])) {
            *r = rows[k];
            *c = cols[k];
            return;
        }
    char msg[160];
    snprintf(msg, sizeof msg, "inertia() component must be xx yy zz xy yz xz, got '%.64s'", s);
    ep_fail(e, msg);
}

/* count(group), mass(group), xcm(group,dim), vcm(group,dim), fcm(group,dim),
 * bound(group,dir), ke(group), gyration(group), angmom(group,dim),
 * torque(group,dim), inertia(group,dimdim), omega(group,dim): LAMMPS's
 * group functions, the reductions of group.c on the host arrays (synced
 * first during a run; about the unwrapped centre of mass). */
static double group_function(struct ep *e, const char *fn, int nargs, char args[][GR_NAMELEN])
{
    struct gravel *g = e->g;
    int want = (strcmp(fn, "count") == 0 || strcmp(fn, "mass") == 0 || strcmp(fn, "ke") == 0 ||
                strcmp(fn, "gyration") == 0) ? 1 : 2;
    if (nargs != want) {
        char msg[160];
        snprintf(msg, sizeof msg, "%s() takes %d argument%s, got %d", fn, want,
                 want == 1 ? "" : "s", nargs);
        ep_fail(e, msg);
    }
    int igroup = group_index(e, args[0]);
    run_sync_host(g);
    if (strcmp(fn, "count") == 0)
        return (double)group_count(g, igroup);
    if (strcmp(fn, "mass") == 0)
        return group_mass(g, igroup);
    if (strcmp(fn, "xcm") == 0 || strcmp(fn, "vcm") == 0) {
        int d = dim_index(e, args[1]);
        double c[3];
        if (fn[0] == 'x') /* unwrapped through periodic images, as LAMMPS' unmap */
            group_xcm(g, igroup, group_mass(g, igroup), c);
        else
            group_vcm(g, igroup, group_mass(g, igroup), c);
        return c[d];
    }
    if (strcmp(fn, "ke") == 0)
        return group_ke(g, igroup);
    if (strcmp(fn, "fcm") == 0) {
        double f[3];
        group_fcm(g, igroup, f);
        return f[dim_index(e, args[1])];
    }
    if (strcmp(fn, "gyration") == 0 || strcmp(fn, "angmom") == 0 ||
        strcmp(fn, "torque") == 0 || strcmp(fn, "inertia") == 0 || strcmp(fn, "omega") == 0) {
        const double m = group_mass(g, igroup);
        double c[3], v[3], I[3][3];
        group_xcm(g, igroup, m, c);
        if (fn[0] == 'g')
            return group_gyration(g, igroup, m, c);
        if (fn[0] == 'i') {
            int r, col;
            dimdim_index(e, args[1], &r, &col);
            group_inertia(g, igroup, c, I);
            return I[r][col];
        }
        const int d = dim_index(e, args[1]);
        if (fn[0] == 't') {
            group_torque(g, igroup, c, v);
            return v[d];
        }
        group_angmom(g, igroup, c, v);
        if (fn[0] == 'a')
            return v[d];
        double w[3];
        group_inertia(g, igroup, c, I);
        group_omega(v, I, w);
        return w[d];
    }
    if (strcmp(fn, "bound") == 0) {
        static const char *dirs[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
        int k = -1;
        for (int j = 0; j < 6; j++)
            if (strcmp(args[1], dirs[j]) == 0)
                k = j;
        if (k < 0) {
            char msg[200];
            snprintf(msg, sizeof msg,
                     "bound() direction must be xmin xmax ymin ymax zmin zmax, got '%.64s'",
                     args[1]);
            ep_fail(e, msg);
        }
        double lo[3], hi[3];
        group_bounds(g, igroup, lo, hi);
        int d = k / 2;
        if (lo[d] > hi[d]) /* empty group: LAMMPS' BIG sentinels */
            return k % 2 ? -BIG : BIG;
        return k % 2 ? hi[d] : lo[d];
    }
    ep_fail(e, "internal: unknown group function");
}

static int is_group_function(const char *name)
{
    static const char *const fns[] = {"count", "mass", "xcm", "vcm", "fcm", "bound", "ke",
                                      "gyration", "angmom", "torque", "inertia", "omega",
                                      NULL};
    for (int k = 0; fns[k]; k++)
        if (!strcmp(name, fns[k]))
            return 1;
    return 0;
}

/* x[ID] y z vx vy vz fx fy fz radius mass type id [ID]. */
static int is_atom_value(const char *name)
{
    static const char *names[] = {"x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz",
                                  "radius", "mass", "type", "id", NULL};
    for (int i = 0; names[i]; i++)
        if (strcmp(name, names[i]) == 0)
            return 1;
    return 0;
}

/* Value `name` (is_atom_value) of host atom i. */
static double own_value(const struct atoms *a, const char *name, int i)
{
    if (!strcmp(name, "x") || !strcmp(name, "y") || !strcmp(name, "z"))
        return a->x[3 * i + (name[0] - 'x')];
    if (name[0] == 'v' && name[1])
        return a->v[3 * i + (name[1] - 'x')];
    if (name[0] == 'f' && name[1])
        return a->f[3 * i + (name[1] - 'x')];
    if (!strcmp(name, "radius"))
        return a->radius[i];
    if (!strcmp(name, "mass"))
        return atom_mass(a, i);
    if (!strcmp(name, "type"))
        return a->type[i];
    return (double)a->tag[i]; /* id */
}

static double atom_value(struct ep *e, const char *name, double idv)
{
    struct gravel *g = e->g;
    char msg[200];
    if (!(idv >= 1 && idv <= 9.0e18) || idv != floor(idv)) {
        snprintf(msg, sizeof msg, "%s[] needs a positive integer atom ID, got %g", name, idv);
        ep_fail(e, msg);
    }
    int64_t tag = (int64_t)idv;
    run_sync_host(g);
    const struct atoms *a = &g->atoms;
    int i = atoms_find_tag(a, tag);
    if (i < 0) {
        snprintf(msg, sizeof msg, "atom ID %lld in %s[] does not exist", (long long)tag, name);
        ep_fail(e, msg);
    }
    return own_value(a, name, i);
}

/* A custom property's operand (fix property/atom), as LAMMPS's variable
 * reads them: i_name d_name (per-atom vectors), i_name[I] d_name[I] (atom
 * I's value), i2_name[J] d2_name[J] (column J, per atom), i2_name[I][J]
 * d2_name[I][J] (atom I's column J). Per-atom forms need an atom-style
 * evaluation. */
static double custom_operand(struct ep *e, const char *name)
{
    struct gravel *g = e->g;
    int arr = name[1] == '2';
    const char *nm = name + (arr ? 3 : 2);
    int k = custom_find(&g->atoms, nm);
    char msg[240];
    if (k < 0) {
        snprintf(msg, sizeof msg, "custom property %.64s does not exist (define it with fix "
                                  "property/atom %.64s)", name, name);
        ep_fail(e, msg);
    }
    const struct custom_prop *pr = &g->atoms.cus.p[k];
    if (pr->isint != (name[0] == 'i') || (pr->cols != 0) != arr) {
        char have[GR_CUSTOMLEN + 4];
        snprintf(msg, sizeof msg, "custom property %.64s is %.70s, not %.64s", nm,
                 custom_prefixed(&g->atoms, k, have), name);
        ep_fail(e, msg);
    }
    double b[2];
    int nb = 0;
    while (nb < 2 && *e->p == '[') {
        e->p++;
        b[nb++] = parse_or(e);
        if (!accept(e, "]"))
            ep_fail(e, "missing ']'");
    }
    if (nb == 2 && !arr) {
        snprintf(msg, sizeof msg, "%.64s is a vector: %.64s[ID], not two indices", name, name);
        ep_fail(e, msg);
    }
    if (arr && nb == 0) {
        snprintf(msg, sizeof msg, "%.64s is an array: %.64s[J] (column J per atom) or "
                                  "%.64s[ID][J]", name, name, name);
        ep_fail(e, msg);
    }
    struct custom_ref ref = {k, 0};
    if (arr) {
        double c = b[nb - 1];
        if (!(c >= 1 && c <= pr->cols) || c != floor(c)) {
            snprintf(msg, sizeof msg, "column %g of %.64s is outside 1..%d", c, name, pr->cols);
            ep_fail(e, msg);
        }
        ref.col = (int)c - 1;
    }
    if (nb == (arr ? 2 : 1)) { /* one atom's value */
        double idv = b[0];
        struct aslot *sl = NULL;
        if (e->ax) {
            int made;
            sl = next_slot(e, &made);
            if (!made)
                return slot_value(e, sl);
        }
        if (!(idv >= 1 && idv <= 9.0e18) || idv != floor(idv)) {
            snprintf(msg, sizeof msg, "%.64s[] needs a positive integer atom ID, got %g", name,
                     idv);
            ep_fail(e, msg);
        }
        run_sync_host(g);
        int i = atoms_find_tag(&g->atoms, (int64_t)idv);
        if (i < 0) {
            snprintf(msg, sizeof msg, "atom ID %lld in %.64s[] does not exist", (long long)idv,
                     name);
            ep_fail(e, msg);
        }
        double v = custom_get(&g->atoms, ref, i);
        if (sl)
            sl->s = v;
        return v;
    }
    if (!e->ax) {
        snprintf(msg, sizeof msg, "'%.64s' is per-atom: use it in an atom-style variable, or "
                                  "name an atom: %.64s[ID]%s", name, name, arr ? "[J]" : "");
        ep_fail(e, msg);
    }
    return custom_get(&g->atoms, ref, e->ax->i);
}

/* ---- math functions --------------------------------------------------------- */

static double round_half_up(double a) /* LAMMPS' MYROUND */
{
    return (a - floor(a)) >= 0.5 ? ceil(a) : floor(a);
}

static long seed_arg(struct ep *e, const char *fn, double s)
{
    if (!(s >= 1 && s <= 2147483647.0) || s != floor(s)) {
        char msg[160];
        snprintf(msg, sizeof msg, "%s() seed must be a positive integer, got %g", fn, s);
        ep_fail(e, msg);
    }
    return (long)s;
}

/* ---- functions of the step (LAMMPS's variable doc, "Math functions") ---------
 * Each reads the current step and the run's span: beginstep (the run's first
 * step, or `run ... start`), endstep (its last, or `run ... stop`) and dt.
 * ramp(x,y): x + (y - x) (step - begin) / (end - begin), x between runs;
 * stagger(x,y), logfreq(x,y,z), logfreq2(x,y,z), logfreq3(x,y,z),
 * stride(x,y,z), stride2(x,y,z,a,b,c): the next output step after this one
 * (integer arguments, as LAMMPS truncates them; "never" is NEVER_STEP);
 * vdisplace(x,y) = x + y t,
 * swiggle(x,y,z) = x + y sin(2 pi t / z), cwiggle(x,y,z) = x + y (1 - cos(2 pi
 * t / z)), t = (step - begin) dt, each in LAMMPS's order of operations. */
static int is_step_function(const char *fn)
{
    static const char *const names[] = {"ramp",    "stagger", "logfreq",   "logfreq2",
                                        "logfreq3", "stride",  "stride2",   "vdisplace",
                                        "swiggle", "cwiggle", NULL};
    for (int i = 0; names[i]; i++)
        if (!strcmp(fn, names[i]))
            return 1;
    return 0;
}

/* "never": the largest double below 2^63, (double)(2^63 - 1 - 512): LAMMPS's
 * MAXBIGINT_DOUBLE (LAMMPS 2021 gave 2^63, which no 64-bit step can hold) */
#define NEVER_STEP 9223372036854774784.0

/* An integer argument, truncated as LAMMPS's static_cast<bigint>; one
 * outside +-2^62 (or not finite) is refused rather than overflowing. */
static bigint step_arg(struct ep *e, const char *fn, double x)
{
    if (!(fabs(x) < 4611686018427387904.0)) {
        char msg[160];
        snprintf(msg, sizeof msg, "%s(): argument %g is not a usable step count", fn, x);
        ep_fail(e, msg);
    }
    return (bigint)x;
}

static _Noreturn void step_invalid(struct ep *e, const char *fn, const char *need)
{
    char msg[200];
    snprintf(msg, sizeof msg, "invalid %s() arguments: %s", fn, need);
    ep_fail(e, msg);
}

static double step_function(struct ep *e, const char *fn, const double *a)
{
    const struct gravel *g = e->g;
    const bigint step = g->step;
    const double d = (double)(step - g->beginstep);
    if (!strcmp(fn, "ramp")) {
        if (!g->running)
            return a[0];
        double f = d;
        if (f != 0.0 && g->beginstep != g->endstep)
            f /= (double)(g->endstep - g->beginstep);
        return a[0] + f * (a[1] - a[0]);
    }
    if (!strcmp(fn, "vdisplace"))
        return a[0] + a[1] * d * g->dt;
    if (!strcmp(fn, "swiggle") || !strcmp(fn, "cwiggle")) {
        if (a[2] == 0.0)
            step_invalid(e, fn, "the period z must not be 0");
        const double w = 2.0 * M_PI / a[2] * d * g->dt;
        return a[0] + a[1] * (fn[0] == 's' ? sin(w) : 1.0 - cos(w));
    }
    const bigint x = step_arg(e, fn, a[0]), y = step_arg(e, fn, a[1]);
    if (!strcmp(fn, "stagger")) {
        if (x <= 0 || y <= 0 || x <= y)
            step_invalid(e, fn, "needs x > y > 0");
        const bigint lower = step / x * x;
        return (double)(step - lower < y ? lower + y : lower + x);
    }
    const bigint z = step_arg(e, fn, a[2]);
    if (!strcmp(fn, "logfreq")) {
        if (x <= 0 || y <= 0 || z <= 0 || y >= z)
            step_invalid(e, fn, "needs x > 0 and 0 < y < z");
        if (step < x)
            return (double)x;
        bigint lower = x;
        while (lower <= step / z) /* step >= z lower, without overflowing */
            lower *= z;
        const bigint multiple = step / lower;
        return multiple < y ? (double)(multiple + 1) * (double)lower : (double)lower * (double)z;
    }
    if (!strcmp(fn, "logfreq2")) {
        if (x <= 0 || y <= 0 || z <= 1) /* z = 1: LAMMPS's loop would never end */
            step_invalid(e, fn, "needs x, y > 0 and z > 1");
        double v = (double)x;
        if (step >= x) {
            double delta = (double)x * ((double)z - 1.0) / (double)y;
            for (bigint count = 1; (double)step >= v; count++) {
                v += delta;
                if (count % y == 0)
                    delta *= (double)z;
            }
        }
        return ceil(v);
    }
    if (!strcmp(fn, "logfreq3")) {
        if (x <= 0 || y <= 1 || z <= 0 || z - x + 1 < y)
            step_invalid(e, fn, "needs x > 0, y > 1 and z - x + 1 >= y");
        if (step > z) {
            char msg[200];
            snprintf(msg, sizeof msg, "logfreq3(): the step %lld is past its last step %lld",
                     (long long)step, (long long)z);
            ep_fail(e, msg);
        }
        double v = (double)x;
        if (step >= x) {
            double logsp = (double)x;
            const double factor = pow((double)z / (double)x, 1.0 / (double)(y - 1));
            bigint linsp = x;
            while ((double)step >= v) {
                logsp *= factor;
                linsp++;
                v = (double)linsp > logsp
                        ? (double)linsp
                        : ceil(logsp) - (double)(((bigint)ceil(logsp) - 1) / z);
            }
        }
        return v;
    }
    if (!strcmp(fn, "stride")) {
        if (x < 0 || y < 0 || z <= 0 || x > y)
            step_invalid(e, fn, "needs 0 <= x <= y and z > 0");
        if (step < x)
            return (double)x;
        if (step >= y)
            return NEVER_STEP;
        const double v = (double)(x + (step - x) / z * z + z);
        return v > (double)y ? NEVER_STEP : v;
    }
    /* stride2(x,y,z,a,b,c): stride x..y by z, and by c inside a..b */
    const bigint a4 = step_arg(e, fn, a[3]), b5 = step_arg(e, fn, a[4]);
    const bigint c6 = step_arg(e, fn, a[5]);
    if (x < 0 || y < 0 || z <= 0 || x > y || a4 < 0 || b5 < 0 || c6 <= 0 || a4 > b5 ||
        a4 < x || b5 > y)
        step_invalid(e, fn, "needs 0 <= x <= a <= b <= y and z, c > 0");
    if (step < x)
        return (double)x;
    if (step >= y)
        return NEVER_STEP;
    if (step < a4 || step > b5) {
        bigint next = x + (step - x) / z * z + z;
        if (step < a4 && next > a4)
            next = a4;
        return (double)next;
    }
    const bigint inner = a4 + (step - a4) / c6 * c6 + c6;
    if (inner <= b5)
        return (double)inner;
    const bigint next = x + (b5 - x) / z * z + z;
    return next > y ? NEVER_STEP : (double)next;
}

static double math_function(struct ep *e, const char *fn, int n, const double *a)
{
    static const struct {
        const char *name;
        int nargs;
    } table[] = {{"sqrt", 1}, {"exp", 1},   {"ln", 1},    {"log", 1},   {"abs", 1},
                 {"sin", 1},  {"cos", 1},   {"tan", 1},   {"asin", 1},  {"acos", 1},
                 {"atan", 1}, {"atan2", 2}, {"ceil", 1},  {"floor", 1}, {"round", 1},
                 {"random", 3}, {"normal", 3}, {"ramp", 2}, {"stagger", 2}, {"logfreq", 3},
                 {"logfreq2", 3}, {"logfreq3", 3}, {"stride", 3}, {"stride2", 6},
                 {"vdisplace", 2}, {"swiggle", 3}, {"cwiggle", 3}, {"ternary", 3},
                 {"sign", 1}, {NULL, 0}};
    char msg[200];
    int k = -1;
    for (int i = 0; table[i].name; i++)
        if (strcmp(fn, table[i].name) == 0)
            k = i;
    if (k < 0) {
        snprintf(msg, sizeof msg, "unknown function '%.64s()'", fn);
        ep_fail(e, msg);
    }
    if (n != table[k].nargs) {
        snprintf(msg, sizeof msg, "%s() takes %d argument%s, got %d", fn, table[k].nargs,
                 table[k].nargs == 1 ? "" : "s", n);
        ep_fail(e, msg);
    }
    double x = a[0];
    if (!strcmp(fn, "sqrt")) {
        if (x < 0)
            ep_fail(e, "sqrt() of a negative value");
        return sqrt(x);
    }
    if (!strcmp(fn, "exp"))
        return exp(x);
    if (!strcmp(fn, "ln") || !strcmp(fn, "log")) {
        if (!(x > 0))
            ep_fail(e, fn[1] == 'n' ? "ln() of a zero or negative value"
                                    : "log() of a zero or negative value");
        return fn[1] == 'n' ? log(x) : log10(x);
    }
    if (!strcmp(fn, "abs"))
        return fabs(x);
    if (!strcmp(fn, "sin"))
        return sin(x);
    if (!strcmp(fn, "cos"))
        return cos(x);
    if (!strcmp(fn, "tan"))
        return tan(x);
    if (!strcmp(fn, "asin") || !strcmp(fn, "acos")) {
        if (x < -1 || x > 1) {
            snprintf(msg, sizeof msg, "%s() of %g, outside [-1, 1]", fn, x);
            ep_fail(e, msg);
        }
        return fn[1] == 's' ? asin(x) : acos(x);
    }
    if (!strcmp(fn, "atan"))
        return atan(x);
    if (!strcmp(fn, "atan2"))
        return atan2(a[0], a[1]);
    if (!strcmp(fn, "ceil"))
        return ceil(x);
    if (!strcmp(fn, "floor"))
        return floor(x);
    if (!strcmp(fn, "round"))
        return round_half_up(x);
    if (!strcmp(fn, "ternary")) /* today's LAMMPS: y when x is not 0, else z */
        return x != 0.0 ? a[1] : a[2];
    if (!strcmp(fn, "sign")) /* today's LAMMPS: 1 for x >= 0, else -1 */
        return x >= 0.0 ? 1.0 : -1.0;
    if (is_step_function(fn))
        return step_function(e, fn, a);
    if (!strcmp(fn, "random")) {
        if (a[1] < a[0])
            ep_fail(e, "random(lo,hi,seed) needs lo <= hi");
        long seed = seed_arg(e, fn, a[2]);
        return var_random_uniform(e->g, seed) * (a[1] - a[0]) + a[0]; /* LAMMPS's order */
    }
    /* normal(mu, sigma, seed) */
    if (a[1] < 0)
        ep_fail(e, "normal(mu,sigma,seed) needs sigma >= 0");
    long seed = seed_arg(e, fn, a[2]);
    return a[0] + a[1] * var_random_gaussian(e->g, seed);
}

/* ---- operands --------------------------------------------------------------- */

static double parse_number(struct ep *e)
{
    const char *s = e->p;
    const char *q = s;
    while (isdigit((unsigned char)*q))
        q++;
    if (*q == '.') {
        q++;
        while (isdigit((unsigned char)*q))
            q++;
    }
    if (q == s + 1 && *s == '.')
        ep_fail(e, "a lone '.' is not a number");
    if ((*q == 'e' || *q == 'E') &&
        (isdigit((unsigned char)q[1]) ||
         ((q[1] == '+' || q[1] == '-') && isdigit((unsigned char)q[2])))) {
        q += 2;
        while (isdigit((unsigned char)*q))
            q++;
    }
    char buf[80];
    size_t n = (size_t)(q - s);
    if (n >= sizeof buf)
        ep_fail(e, "number with more than 79 characters");
    memcpy(buf, s, n);
    buf[n] = '\0';
    e->p = q;
    return strtod(buf, NULL);
}

/* Read an identifier [A-Za-z_][A-Za-z0-9_]* into buf; returns its length. */
static size_t read_name(struct ep *e, char *buf, size_t cap)
{
    const char *s = e->p;
    const char *q = s;
    while (isalnum((unsigned char)*q) || *q == '_')
        q++;
    size_t n = (size_t)(q - s);
    if (n >= cap)
        ep_fail(e, "name longer than 63 characters");
    memcpy(buf, s, n);
    buf[n] = '\0';
    e->p = q;
    return n;
}

/* Word arguments of a group function: group names and keywords, not expressions. */
static int parse_word_args(struct ep *e, char args[][GR_NAMELEN], int max)
{
    int n = 0;
    skip_ws(e);
    if (accept(e, ")"))
        return 0;
    for (;;) {
        skip_ws(e);
        const char *s = e->p;
        while (*e->p && *e->p != ',' && *e->p != ')' && !isspace((unsigned char)*e->p))
            e->p++;
        size_t len = (size_t)(e->p - s);
        if (len == 0)
            ep_fail(e, "empty function argument");
        if (len >= GR_NAMELEN)
            ep_fail(e, "function argument longer than 63 characters");
        if (n == max)
            ep_fail(e, "too many function arguments");
        memcpy(args[n], s, len);
        args[n][len] = '\0';
        n++;
        skip_ws(e);
        if (accept(e, ","))
            continue;
        if (accept(e, ")"))
            return n;
        ep_fail(e, "missing ')' after function arguments");
    }
}

static double parse_primary(struct ep *e)
{
    skip_ws(e);
    char c = *e->p;
    if (c == '\0')
        ep_fail(e, "unexpected end");
    if (isdigit((unsigned char)c) || c == '.')
        return parse_number(e);
    if (c == '(') {
        e->p++;
        double v = parse_or(e); /* parse_or counts the nesting */
        if (!accept(e, ")"))
            ep_fail(e, "missing ')'");
        return v;
    }
    if (!(isalpha((unsigned char)c) || c == '_')) {
        char msg[80];
        if (isprint((unsigned char)c))
            snprintf(msg, sizeof msg, "unexpected character '%c'", c);
        else
            snprintf(msg, sizeof msg, "unexpected byte 0x%02x", (unsigned char)c);
        ep_fail(e, msg);
    }
    char name[GR_NAMELEN];
    const char *start = e->p;
    read_name(e, name, sizeof name);
    char msg[240];

    /* v_name: another variable, evaluated numerically */
    if (name[0] == 'v' && name[1] == '_' && name[2]) {
        if (*e->p == '[')
            ep_fail(e, "vector variables v_name[i] are not supported");
        if (!e->ax)
            return var_compute_equal_depth(e->g, name + 2, e->depth + 1);
        int made;
        struct aslot *sl = next_slot(e, &made);
        if (made && var_is_atom(e->g, name + 2)) {
            sl->owned = malloc(((size_t)e->g->atoms.n + 1) * sizeof(double));
            if (!sl->owned)
                ep_fail(e, "out of memory");
            var_compute_atom_depth(e->g, name + 2, sl->owned, e->depth + 1);
            sl->col = sl->owned;
            sl->stride = 1;
        } else if (made) {
            sl->s = var_compute_equal_depth(e->g, name + 2, e->depth + 1);
        }
        return slot_value(e, sl);
    }
    /* c_ID, c_ID[n], f_ID[n]: served by the output module */
    if ((name[0] == 'c' || name[0] == 'f') && name[1] == '_' && name[2]) {
        for (int k = 0; k < 2 && *e->p == '['; k++) { /* c_ID[N], c_ID[I][J] */
            const char *close = strchr(e->p, ']');
            if (!close)
                ep_fail(e, "missing ']'");
            e->p = close + 1;
        }
        char ref[160];
        size_t n = (size_t)(e->p - start);
        if (n >= sizeof ref)
            ep_fail(e, "reference longer than 159 characters");
        memcpy(ref, start, n);
        ref[n] = '\0';
        double out;
        struct aslot *sl = NULL;
        if (e->ax) {
            int made;
            sl = next_slot(e, &made);
            if (!made)
                return slot_value(e, sl);
            char id[GR_NAMELEN];
            int index = 0;
            struct compute *c = name[0] == 'c' && compute_parse_ref(ref, id, &index)
                                    ? compute_find(e->g, id) : NULL;
            int col_idx, fcol;
            struct fix *fx = name[0] == 'f' && fix_parse_ref(ref, id, &col_idx, &fcol) && !fcol
                                 ? fix_find(e->g, id) : NULL;
            if ((c && c->peratom_flag) || (fx && fx->peratom_flag)) {
                int stride = 1, na = e->g->atoms.n;
                const double *col =
                    c ? compute_peratom_ref(e->g, c, index, &stride, "atom-style variable")
                      : fix_peratom_ref(e->g, ref, &stride, "atom-style variable");
                sl->owned = malloc(((size_t)na + 1) * sizeof(double));
                if (!sl->owned)
                    ep_fail(e, "out of memory");
                for (int i = 0; i < na; i++) /* a copy: the compute's buffer is reused */
                    sl->owned[i] = col[(size_t)stride * i];
                sl->col = sl->owned;
                sl->stride = 1;
                return slot_value(e, sl);
            }
        }
        if (!thermo_keyword_value(e->g, ref, &out)) {
            snprintf(msg, sizeof msg, "unknown %s '%s'", name[0] == 'c' ? "compute" : "fix", ref);
            ep_fail(e, msg);
        }
        if (sl)
            sl->s = out;
        return out;
    }
    skip_ws(e);
    if (*e->p == '(') {
        e->p++;
        double v;
        if (feature_is_function(name)) { /* is_active(...): a constant of the script */
            char args[2][GR_NAMELEN], err[200];
            int n = parse_word_args(e, args, 2), r;
            const char *cat = n == 2 && !strcmp(name, "is_defined") ? args[0] : "";
            if (!strcmp(cat, "group"))
                r = group_find(e->g, args[1]) >= 0;
            else if (!strcmp(cat, "region"))
                r = region_find(e->g, args[1]) != NULL;
            else if (!strcmp(cat, "variable"))
                r = var_exists(e->g, args[1]) != 0;
            else
                r = feature_value(e->g, name, n, args, err, sizeof err);
            if (r < 0)
                ep_fail(e, err);
            return (double)r;
        }
        if (is_group_function(name)) {
            char args[3][GR_NAMELEN];
            int n = parse_word_args(e, args, 3);
            if (e->ax) {
                int made;
                struct aslot *sl = next_slot(e, &made);
                if (made)
                    sl->s = group_function(e, name, n, args);
                return slot_value(e, sl);
            }
            v = group_function(e, name, n, args);
        } else {
            double a[6] = {0, 0, 0, 0, 0, 0};
            int n = 0;
            skip_ws(e);
            if (!accept(e, ")")) {
                for (;;) {
                    double x = parse_or(e);
                    if (n < 6)
                        a[n] = x;
                    n++;
                    if (accept(e, ","))
                        continue;
                    if (accept(e, ")"))
                        break;
                    ep_fail(e, "missing ')' after function arguments");
                }
            }
            v = math_function(e, name, n, a);
        }
        return v;
    }
    if ((name[0] == 'i' || name[0] == 'd') &&
        (name[1] == '_' || (name[1] == '2' && name[2] == '_')) && name[name[1] == '_' ? 2 : 3])
        return custom_operand(e, name);
    if (*e->p == '[' && is_atom_value(name)) {
        e->p++;
        double id = parse_or(e);
        if (!accept(e, "]"))
            ep_fail(e, "missing ']'");
        if (e->ax) {
            int made;
            struct aslot *sl = next_slot(e, &made);
            if (made)
                sl->s = atom_value(e, name, id);
            return slot_value(e, sl);
        }
        return atom_value(e, name, id);
    }
    if (e->ax && is_atom_value(name))
        return own_value(&e->g->atoms, name, e->ax->i);
    if (!strcmp(name, "PI"))
        return 3.14159265358979323846;
    if (!strcmp(name, "version"))
        return 20261123; /* date-like as LAMMPS' version constant */
    if (!strcmp(name, "on") || !strcmp(name, "yes") || !strcmp(name, "true"))
        return 1;
    if (!strcmp(name, "off") || !strcmp(name, "no") || !strcmp(name, "false"))
        return 0;
    double out;
    struct aslot *sl = NULL;
    if (e->ax) {
        int made;
        sl = next_slot(e, &made);
        if (!made)
            return slot_value(e, sl);
    }
    if (thermo_keyword_value(e->g, name, &out)) {
        if (sl)
            sl->s = out;
        return out;
    }
    if (is_atom_value(name))
        snprintf(msg, sizeof msg, "'%s' needs an atom ID: %s[ID]", name, name);
    else
        snprintf(msg, sizeof msg, "unknown name '%s' (not a function, constant, v_name or "
                 "thermo keyword)", name);
    ep_fail(e, msg);
}

static double parse_unary(struct ep *e)
{
    skip_ws(e);
    if (*e->p == '-' || *e->p == '!' || *e->p == '+') {
        char op = *e->p++;
        enter(e);
        double v = parse_unary(e);
        e->depth--;
        return op == '-' ? -v : op == '!' ? (v == 0.0 ? 1.0 : 0.0) : v;
    }
    return parse_primary(e);
}

static double parse_pow(struct ep *e)
{
    double v = parse_unary(e);
    while (accept(e, "^")) {
        double w = parse_unary(e);
        if (w == 0.0)
            v = 1.0;
        else if (v == 0.0 && w < 0.0)
            ep_fail(e, "0 raised to a negative power");
        else
            v = pow(v, w);
    }
    return v;
}

static double parse_mul(struct ep *e)
{
    double v = parse_pow(e);
    for (;;) {
        if (accept(e, "*"))
            v *= parse_pow(e);
        else if (accept(e, "/")) {
            double w = parse_pow(e);
            if (w == 0.0)
                ep_fail(e, "division by zero");
            v /= w;
        } else if (accept(e, "%")) {
            double w = parse_pow(e);
            if (w == 0.0)
                ep_fail(e, "modulo by zero");
            v = fmod(v, w);
        } else
            return v;
    }
}

static double parse_add(struct ep *e)
{
    double v = parse_mul(e);
    for (;;) {
        if (accept(e, "+"))
            v += parse_mul(e);
        else if (accept(e, "-"))
            v -= parse_mul(e);
        else
            return v;
    }
}

static double parse_rel(struct ep *e)
{
    double v = parse_add(e);
    for (;;) {
        if (accept(e, "<="))
            v = v <= parse_add(e);
        else if (accept(e, ">="))
            v = v >= parse_add(e);
        else if (accept(e, "<"))
            v = v < parse_add(e);
        else if (accept(e, ">"))
            v = v > parse_add(e);
        else
            return v;
    }
}

static double parse_eq(struct ep *e)
{
    double v = parse_rel(e);
    for (;;) {
        if (accept(e, "=="))
            v = v == parse_rel(e);
        else if (accept(e, "!="))
            v = v != parse_rel(e);
        else
            return v;
    }
}

static double parse_and(struct ep *e)
{
    double v = parse_eq(e);
    while (accept(e, "&&")) {
        double w = parse_eq(e); /* no short circuit: both sides are checked, as LAMMPS */
        v = (v != 0.0 && w != 0.0);
    }
    return v;
}

static double parse_or(struct ep *e)
{
    enter(e);
    double v = parse_and(e);
    for (;;) {
        if (accept(e, "||")) {
            double w = parse_and(e);
            v = (v != 0.0 || w != 0.0);
        } else if (accept(e, "|^")) {
            double w = parse_and(e);
            v = ((v == 0.0) != (w == 0.0));
        } else
            break;
    }
    e->depth--;
    return v;
}

static double eval_one(struct ep *e)
{
    enter(e);
    skip_ws(e);
    if (*e->p == '\0')
        ep_fail(e, "empty expression");
    double v = parse_or(e);
    skip_ws(e);
    if (*e->p != '\0') {
        char msg[120];
        snprintf(msg, sizeof msg, "unexpected '%.20s' after a complete value", e->p);
        ep_fail(e, msg);
    }
    return v;
}

static void actx_free(struct actx *a)
{
    for (int k = 0; k < a->n; k++)
        free(a->slot[k].owned);
    free(a->slot);
    free(a);
}

void expr_eval_atoms(struct gravel *g, const char *text, double *out, int depth)
{
    run_sync_host(g);
    struct actx *volatile a = calloc(1, sizeof *a);
    if (!a)
        gr_error(g, "out of memory");
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) { /* free the columns, pass the error on */
        g->err.jmp = outer;
        actx_free(a);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    for (int i = 0; i < g->atoms.n; i++) {
        a->i = i;
        a->first = i == 0;
        a->k = 0;
        struct ep e = {g, text, text, depth, a};
        out[i] = eval_one(&e);
    }
    if (g->atoms.n == 0 && par_on(g)) {
        /* a rank without atoms still takes the expression's global terms, whose
         * sums over the ranks the others are in (the value is not used) */
        a->resolve_only = a->first = 1;
        struct ep e = {g, text, text, depth, a};
        (void)eval_one(&e);
    }
    g->err.jmp = outer;
    actx_free(a);
}

double expr_eval_depth(struct gravel *g, const char *text, int depth)
{
    struct ep e = {g, text, text, depth, NULL};
    return eval_one(&e);
}

double expr_eval(struct gravel *g, const char *text)
{
    return expr_eval_depth(g, text, 0);
}

int expr_format_ok(const char *fmt)
{
    int nconv = 0;
    for (const char *p = fmt; *p; p++) {
        if (*p != '%')
            continue;
        p++;
        if (*p == '%')
            continue;
        while (*p && strchr("-+ #0", *p))
            p++;
        int nd = 0;
        while (isdigit((unsigned char)*p)) {
            p++;
            if (++nd > 3)
                return 0;
        }
        if (*p == '.') {
            p++;
            nd = 0;
            while (isdigit((unsigned char)*p)) {
                p++;
                if (++nd > 3)
                    return 0;
            }
        }
        if (!*p || !strchr("feEgG", *p))
            return 0;
        nconv++;
    }
    return nconv == 1;
}
