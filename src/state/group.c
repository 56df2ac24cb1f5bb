/* group.c - the `group` command (static groups: region, type, id, subtract,
 * union, intersect, variable, delete, clear, empty; dynamic groups and
 * `static`) and the group reductions of
 * group.h. Forms of `type` and `id`: values and ranges A:B or A:B:C, or a
 * logical condition < <= > >= == != with one value or <> with two (A <= v <= B),
 * as LAMMPS. Assigning to an existing group adds atoms to it. */
#include "group.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>

#include "args.h"
#include "atom_custom.h"
#include "atoms.h"
#include "compute.h"
#include "domain.h"
#include "dump.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "log.h"
#include "par_sum.h"
#include "region.h"
#include "device.h"
#include "variable.h"

int group_find(const struct gravel *g, const char *name)
{
    for (int i = 0; i < GR_MAXGROUP; i++)
        if (g->groups.used[i] && strcmp(g->groups.name[i], name) == 0)
            return i;
    return -1;
}

int group_create(struct gravel *g, const char *name)
{
    int i = group_find(g, name);
    if (i >= 0)
        return i;
    size_t n = strlen(name);
    if (n == 0 || n >= GR_NAMELEN)
        gr_error(g, "group ID must have 1 to %d characters", GR_NAMELEN - 1);
    for (size_t k = 0; k < n; k++)
        if (!isalnum((unsigned char)name[k]) && name[k] != '_')
            gr_error(g, "group ID '%.64s' may contain only letters, digits and underscores",
                     name);
    for (i = 1; i < GR_MAXGROUP; i++)
        if (!g->groups.used[i])
            break;
    if (i == GR_MAXGROUP)
        gr_error(g, "too many groups (at most %d including 'all')", GR_MAXGROUP);
    g->groups.used[i] = 1;
    memcpy(g->groups.name[i], name, n + 1);
    if (i >= g->groups.n)
        g->groups.n = i + 1;
    return i;
}

/* ---- reductions ------------------------------------------------------------- */

bigint group_count(const struct gravel *g, int igroup)
{
    unsigned bit = group_bit(igroup);
    bigint n = 0;
    for (int i = 0; i < g->atoms.n; i++)
        n += (g->atoms.mask[i] & bit) != 0;
    return n;
}

/* What group_sums adds up per atom (n terms each, in this order). */
enum sum_kind { S_MASS, S_P, S_MX, S_L, S_I, S_KE, S_F, S_T, S_RG };

/* Sums over the group's atoms in tag order: mass (1); momentum m v (3);
 * m x (3, x unwrapped); angular momentum about c (3); the inertia tensor
 * about c (6: xx yy zz xy yz xz); m v^2 (1); force (3); torque of the
 * forces about c (3); m |x - c|^2 (1). Through par_sum: in a
 * decomposed run (not gathered) over every rank's atoms, one process's
 * bits; otherwise the host atoms, added as they come. */
static void group_sums(struct gravel *g, int igroup, enum sum_kind kind, const double c[3],
                       double *out)
{
    static const int nterm[] = {1, 3, 3, 3, 6, 1, 3, 3, 1};
    const int n = nterm[kind];
    const unsigned bit = group_bit(igroup);
    const struct atoms *a = &g->atoms;
    const int *order = atoms_tag_order(g);
    struct par_sum s[6];
    memset(s, 0, sizeof s);
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!(a->mask[i] & bit))
            continue;
        const double m = a->rmass[i], *v = a->v + 3 * i, *f = a->f + 3 * i;
        double t[6] = {0}, u[3] = {0}, dx = 0, dy = 0, dz = 0;
        if (kind == S_MX || kind == S_L || kind == S_I || kind == S_T || kind == S_RG) {
            domain_unmap(g, a->x + 3 * i, a->image + 3 * i, u);
            if (c)
                dx = u[0] - c[0], dy = u[1] - c[1], dz = u[2] - c[2];
        }
        switch (kind) {
        case S_MASS:
            t[0] = m;
            break;
        case S_P:
            t[0] = m * v[0], t[1] = m * v[1], t[2] = m * v[2];
            break;
        case S_MX:
            t[0] = m * u[0], t[1] = m * u[1], t[2] = m * u[2];
            break;
        case S_L:
            t[0] = m * (dy * v[2] - dz * v[1]);
            t[1] = m * (dz * v[0] - dx * v[2]);
            t[2] = m * (dx * v[1] - dy * v[0]);
            break;
        case S_I: /* the off-diagonal terms subtracted: + (-t) is - t */
            t[0] = m * (dy * dy + dz * dz), t[1] = m * (dx * dx + dz * dz);
            t[2] = m * (dx * dx + dy * dy), t[3] = -(m * dx * dy);
            t[4] = -(m * dy * dz), t[5] = -(m * dx * dz);
            break;
        case S_KE:
            t[0] = m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            break;
        case S_F:
            t[0] = f[0], t[1] = f[1], t[2] = f[2];
            break;
        case S_T:
            t[0] = dy * f[2] - dz * f[1];
            t[1] = dz * f[0] - dx * f[2];
            t[2] = dx * f[1] - dy * f[0];
            break;
        case S_RG:
            t[0] = (dx * dx + dy * dy + dz * dz) * m;
            break;
        }
        for (int q = 0; q < n; q++)
            par_sum_add(g, &s[q], a->tag[i], t[q]);
    }
    for (int q = 0; q < n; q++)
        out[q] = par_sum_total(g, &s[q]);
}

double group_mass(struct gravel *g, int igroup)
{
    double m;
    group_sums(g, igroup, S_MASS, NULL, &m);
    return m;
}

void group_xcm(struct gravel *g, int igroup, double masstotal, double xcm[3])
{
    double s[3];
    group_sums(g, igroup, S_MX, NULL, s);
    for (int d = 0; d < 3; d++)
        xcm[d] = masstotal > 0 ? s[d] / masstotal : 0.0;
}

void group_vcm(struct gravel *g, int igroup, double masstotal, double vcm[3])
{
    double s[3];
    group_sums(g, igroup, S_P, NULL, s);
    for (int d = 0; d < 3; d++)
        vcm[d] = masstotal > 0 ? s[d] / masstotal : 0.0;
}

void group_bounds(const struct gravel *g, int igroup, double lo[3], double hi[3])
{
    unsigned bit = group_bit(igroup);
    const struct atoms *a = &g->atoms;
    for (int d = 0; d < 3; d++) {
        lo[d] = INFINITY;
        hi[d] = -INFINITY;
    }
    for (int i = 0; i < a->n; i++)
        if (a->mask[i] & bit)
            for (int d = 0; d < 3; d++) {
                lo[d] = fmin(lo[d], a->x[3 * i + d]);
                hi[d] = fmax(hi[d], a->x[3 * i + d]);
            }
}

double group_ke(struct gravel *g, int igroup)
{
    double ke;
    group_sums(g, igroup, S_KE, NULL, &ke);
    return 0.5 * ke;
}

void group_fcm(struct gravel *g, int igroup, double fcm[3])
{
    group_sums(g, igroup, S_F, NULL, fcm);
}

void group_torque(struct gravel *g, int igroup, const double xcm[3], double tq[3])
{
    group_sums(g, igroup, S_T, xcm, tq);
}

double group_gyration(struct gravel *g, int igroup, double masstotal, const double xcm[3])
{
    double r;
    group_sums(g, igroup, S_RG, xcm, &r);
    return masstotal > 0.0 ? sqrt(r / masstotal) : 0.0;
}

void group_angmom(struct gravel *g, int igroup, const double xcm[3], double L[3])
{
    group_sums(g, igroup, S_L, xcm, L);
}

void group_inertia(struct gravel *g, int igroup, const double xcm[3], double I[3][3])
{
    double t[6];
    group_sums(g, igroup, S_I, xcm, t);
    I[0][0] = t[0], I[1][1] = t[1], I[2][2] = t[2];
    I[0][1] = I[1][0] = t[3];
    I[1][2] = I[2][1] = t[4];
    I[0][2] = I[2][0] = t[5];
}

void group_omega(const double L[3], double I[3][3], double w[3])
{
    /* Solve I w = L in the principal frame of I (GSL symmetric eigen-solver),
     * dropping principal moments below 1e-10 of the largest: a two-atom or
     * colinear group cannot rotate about its own axis (LAMMPS does the same
     * with jacobi3 for a nearly singular I, but with an absolute threshold). */
    w[0] = w[1] = w[2] = 0;
    double m[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            m[3 * r + c] = I[r][c];
    gsl_matrix_view mv = gsl_matrix_view_array(m, 3, 3);
    gsl_vector *eval = gsl_vector_alloc(3);
    gsl_matrix *evec = gsl_matrix_alloc(3, 3);
    gsl_eigen_symmv_workspace *ws = gsl_eigen_symmv_alloc(3);
    if (eval && evec && ws && gsl_eigen_symmv(&mv.matrix, eval, evec, ws) == 0) {
        double imax = 0;
        for (int k = 0; k < 3; k++)
            imax = fmax(imax, gsl_vector_get(eval, k));
        for (int k = 0; k < 3; k++) {
            double ik = gsl_vector_get(eval, k);
            if (!(imax > 0) || ik <= 1e-10 * imax)
                continue;
            double e[3], le = 0;
            for (int d = 0; d < 3; d++) {
                e[d] = gsl_matrix_get(evec, d, k);
                le += L[d] * e[d];
            }
            for (int d = 0; d < 3; d++)
                w[d] += le / ik * e[d];
        }
    }
    gsl_eigen_symmv_free(ws);
    gsl_matrix_free(evec);
    gsl_vector_free(eval);
}

/* ---- the command ------------------------------------------------------------- */

/* Parse a value list or logical condition for `type` / `id` into a
 * predicate; sets flags[] for matching tag/type values via callback. */
struct selector {
    int logical;            /* 0: list; else one of the ops below */
    bigint a, b;
    int nlist;
    bigint (*list)[3];      /* start, stop, step */
};

enum { OP_LT = 1, OP_LE, OP_GT, OP_GE, OP_EQ, OP_NE, OP_BETWEEN };

static int sel_match(const struct selector *s, bigint v)
{
    switch (s->logical) {
    case OP_LT: return v < s->a;
    case OP_LE: return v <= s->a;
    case OP_GT: return v > s->a;
    case OP_GE: return v >= s->a;
    case OP_EQ: return v == s->a;
    case OP_NE: return v != s->a;
    case OP_BETWEEN: return v >= s->a && v <= s->b;
    default: break;
    }
    for (int k = 0; k < s->nlist; k++) {
        bigint lo = s->list[k][0], hi = s->list[k][1], st = s->list[k][2];
        if (v >= lo && v <= hi && (v - lo) % st == 0)
            return 1;
    }
    return 0;
}

static void parse_selector(struct gravel *g, int argc, char **argv, const char *what,
                           struct selector *s, bigint (*buf)[3])
{
    static const char *ops[] = {"<", "<=", ">", ">=", "==", "!=", "<>"};
    memset(s, 0, sizeof *s);
    if (argc < 1)
        gr_error(g, "group %s needs at least one value", what);
    for (int k = 0; k < 7; k++) {
        if (strcmp(argv[0], ops[k]) != 0)
            continue;
        s->logical = k + 1;
        int need = s->logical == OP_BETWEEN ? 2 : 1;
        if (argc != 1 + need)
            gr_error(g, "group %s %s needs exactly %d value%s", what, ops[k], need,
                     need > 1 ? "s" : "");
        s->a = arg_bigint(g, argv[1], what);
        if (need == 2) {
            s->b = arg_bigint(g, argv[2], what);
            if (s->a > s->b)
                gr_error(g, "group %s <> needs the smaller value first, got %s %s", what,
                         argv[1], argv[2]);
        }
        return;
    }
    s->list = buf;
    for (int k = 0; k < argc; k++) {
        char tmp[64];
        if (strlen(argv[k]) >= sizeof tmp)
            gr_error(g, "invalid %s value '%.64s'", what, argv[k]);
        strcpy(tmp, argv[k]);
        char *p1 = strchr(tmp, ':'), *p2 = NULL;
        bigint lo, hi, st = 1;
        if (p1) {
            *p1++ = '\0';
            p2 = strchr(p1, ':');
            if (p2)
                *p2++ = '\0';
            lo = arg_bigint(g, tmp, what);
            hi = arg_bigint(g, p1, what);
            if (p2) {
                st = arg_bigint(g, p2, what);
                if (st <= 0)
                    gr_error(g, "range step in '%s' must be positive", argv[k]);
            }
            if (lo > hi)
                gr_error(g, "range '%s' has its start after its end", argv[k]);
        } else {
            lo = hi = arg_bigint(g, tmp, what);
        }
        buf[k][0] = lo;
        buf[k][1] = hi;
        buf[k][2] = st;
    }
    s->nlist = argc;
}

static void print_count(struct gravel *g, int ig)
{
    gr_print(g, "%lld atoms in group %s\n", (long long)group_count(g, ig), g->groups.name[ig]);
}

static void dynamic_set(struct gravel *g, int ig)
{
    const struct group_dyn *d = &g->groups.dyn[ig];
    struct atoms *a = &g->atoms;
    const struct region *r = d->region[0] ? region_get(g, d->region) : NULL;
    double *v = d->var[0] ? var_atom_values(g, d->var) : NULL;
    struct custom_ref pr = {-1, 0};
    if (d->prop[0]) { /* LAMMPS's FixGroup: a custom vector, by its bare name */
        pr.idx = custom_find(a, d->prop);
        if (pr.idx < 0 || a->cus.p[pr.idx].cols) {
            free(v);
            gr_error(g, "custom per-atom vector %s for group dynamic %s does not exist (fix "
                        "property/atom i_%s or d_%s)", d->prop, g->groups.name[ig], d->prop,
                     d->prop);
        }
    }
    unsigned bit = group_bit(ig), parent = group_bit(d->parent);
    for (int i = 0; i < a->n; i++) {
        int in = (a->mask[i] & parent) && (!r || region_match(r, a->x + 3 * i)) &&
                 (!v || v[i] != 0.0) && (pr.idx < 0 || custom_get(a, pr, i) != 0.0);
        if (in)
            a->mask[i] |= bit;
        else
            a->mask[i] &= ~bit;
    }
    free(v);
}

void group_dynamic_update(struct gravel *g, bigint step)
{
    struct engine *e = g->eng;
    for (int ig = 1; ig < g->groups.n; ig++) {
        const struct group_dyn *d = &g->groups.dyn[ig];
        if (!g->groups.used[ig] || !d->on || (step >= 0 && step % d->every != 0))
            continue;
        run_sync_host(g); /* host order = device order from here */
        dynamic_set(g, ig);
        /* at once: the next group's variable syncs the host from the device */
        if (e && e->active && e->a.n > 0)
            eng_write(g, e->a.mask, 0, (size_t)e->a.n * sizeof(cl_uint), g->atoms.mask);
    }
}

/* group ID dynamic parent [region R] [var V] [property P] [every N]
 * (LAMMPS FixGroup; P a custom vector's bare name, i_P or d_P). */
static void define_dynamic(struct gravel *g, const char *id, int nrest, char **rest)
{
    if (nrest < 1)
        gr_error(g, "group dynamic needs a parent group");
    struct group_dyn d = {1, arg_group(g, rest[0]), 1, "", "", ""};
    for (int k = 1; k < nrest; k++) {
        const char *kw = rest[k];
        if (k + 1 >= nrest)
            gr_error(g, "group dynamic keyword '%.32s' needs a value", kw);
        const char *val = rest[++k];
        if (!strcmp(kw, "region")) {
            region_get(g, val);
            snprintf(d.region, sizeof d.region, "%s", val);
        } else if (!strcmp(kw, "var")) {
            var_check_atom(g, val, "group dynamic");
            snprintf(d.var, sizeof d.var, "%s", val);
        } else if (!strcmp(kw, "every")) {
            d.every = arg_int_range(g, val, 1, 1 << 30, "every");
        } else if (!strcmp(kw, "property")) {
            if (!custom_name_ok(val) || strlen(val) >= GR_NAMELEN)
                gr_error(g, "group dynamic property: '%.64s' is not a custom vector's name", val);
            snprintf(d.prop, sizeof d.prop, "%s", val);
        } else {
            gr_error(g, "unknown group dynamic keyword '%.32s' (region, var, property, every)",
                     kw);
        }
    }
    int ig = group_create(g, id);
    if (ig == d.parent)
        gr_error(g, "a dynamic group cannot be its own parent");
    g->groups.dyn[ig] = d;
    gr_print(g, "dynamic group %s defined\n", id);
}

/* Errors if something holds group ig by its index, which a later group
 * would inherit (LAMMPS Group::assign: "Cannot delete group currently used
 * by a fix", ... a compute, a dump; a dynamic group is a fix on its parent
 * in LAMMPS). */
static void refuse_delete_in_use(struct gravel *g, int ig)
{
    const char *id = g->groups.name[ig];
    for (int k = 0; k < g->neigh.nexclude; k++)
        if (g->neigh.exclude_group[k][0] == ig || g->neigh.exclude_group[k][1] == ig)
            gr_error(g, "group '%s' is used by neigh_modify exclude and cannot be deleted", id);
    for (int k = 1; k < g->groups.n; k++)
        if (g->groups.used[k] && g->groups.dyn[k].on && g->groups.dyn[k].parent == ig)
            gr_error(g, "group '%s' is the parent of dynamic group '%s' and cannot be deleted "
                        "(delete '%s' or make it static first)",
                     id, g->groups.name[k], g->groups.name[k]);
    for (int k = 0; k < g->styles.nfix; k++)
        if (g->styles.fix[k]->igroup == ig)
            gr_error(g, "group '%s' is used by fix %s and cannot be deleted", id,
                     g->styles.fix[k]->id);
    for (int k = 0; k < g->styles.ncompute; k++)
        if (g->styles.compute[k]->igroup == ig)
            gr_error(g, "group '%s' is used by compute %s and cannot be deleted", id,
                     g->styles.compute[k]->id);
    for (int k = 0; k < g->styles.ndump; k++)
        if (g->styles.dump[k]->igroup == ig)
            gr_error(g, "group '%s' is used by dump %s and cannot be deleted", id,
                     g->styles.dump[k]->id);
}

void cmd_group(struct gravel *g, int argc, char **argv)
{
    const char *id = argv[0], *style = argv[1];
    struct atoms *a = &g->atoms;
    if (!strcmp(style, "delete")) {
        if (argc != 2)
            gr_error(g, "group delete takes no further arguments");
        int ig = group_find(g, id);
        if (ig < 0)
            gr_error(g, "unknown group '%.64s'", id);
        if (ig == 0)
            gr_error(g, "group 'all' cannot be deleted");
        refuse_delete_in_use(g, ig);
        unsigned keep = ~group_bit(ig);
        for (int i = 0; i < a->n; i++)
            a->mask[i] &= keep;
        g->groups.used[ig] = 0;
        g->groups.name[ig][0] = '\0';
        memset(&g->groups.dyn[ig], 0, sizeof g->groups.dyn[ig]);
        return;
    }
    if (!strcmp(style, "clear")) {
        if (argc != 2)
            gr_error(g, "group clear takes no further arguments");
        int ig = group_find(g, id);
        if (ig < 0)
            gr_error(g, "unknown group '%.64s'", id);
        if (ig == 0)
            gr_error(g, "group 'all' cannot be cleared");
        unsigned keep = ~group_bit(ig);
        for (int i = 0; i < a->n; i++)
            a->mask[i] &= keep;
        return;
    }
    if (!strcmp(id, "all"))
        gr_error(g, "group 'all' always holds every atom and cannot be assigned");
    if (!strcmp(style, "dynamic")) {
        define_dynamic(g, id, argc - 2, argv + 2);
        return;
    }
    if (!strcmp(style, "static")) {
        if (argc != 2)
            gr_error(g, "group static takes no further arguments");
        int ig = group_find(g, id);
        if (ig < 0)
            gr_error(g, "unknown group '%.64s'", id);
        if (!g->groups.dyn[ig].on)
            gr_error(g, "group '%s' is not dynamic", id);
        g->groups.dyn[ig].on = 0;
        return;
    }
    {
        int ig = group_find(g, id);
        if (ig >= 0 && g->groups.dyn[ig].on)
            gr_error(g, "cannot add atoms to dynamic group '%s' (make it static first: group "
                        "%s static)", id, id);
    }
    /* validate everything before creating the group */
    int nrest = argc - 2;
    char **rest = argv + 2;
    unsigned bit;
    if (!strcmp(style, "empty")) {
        if (nrest)
            gr_error(g, "group empty takes no further arguments");
        group_create(g, id);
    } else if (!strcmp(style, "region")) {
        if (nrest != 1)
            gr_error(g, "group region needs exactly one region ID");
        struct region *r = region_get(g, rest[0]);
        region_prematch(g, r);
        bit = group_bit(group_create(g, id));
        for (int i = 0; i < a->n; i++)
            if (region_match(r, a->x + 3 * i))
                a->mask[i] |= bit;
    } else if (!strcmp(style, "type") || !strcmp(style, "id") || !strcmp(style, "molecule")) {
        int is_type = style[0] == 't', is_mol = style[0] == 'm';
        if (is_mol && !a->molecule_flag)
            gr_error(g, "group molecule requires atom attribute molecule (fix property/atom "
                        "mol)");
        struct selector s;
        bigint(*buf)[3] = gr_malloc(g, (size_t)(nrest ? nrest : 1) * sizeof *buf);
        jmp_buf *outer = g->err.jmp, here;
        g->err.jmp = &here;
        if (setjmp(here)) {
            g->err.jmp = outer;
            free(buf);
            if (outer)
                longjmp(*outer, 1);
            gr_report_error(g);
            exit(1);
        }
        parse_selector(g, nrest, rest, is_type ? "type" : is_mol ? "molecule" : "id", &s, buf);
        bit = group_bit(group_create(g, id));
        g->err.jmp = outer;
        for (int i = 0; i < a->n; i++)
            if (sel_match(&s, is_type ? a->type[i] : is_mol ? a->mol[i] : a->tag[i]))
                a->mask[i] |= bit;
        free(buf);
    } else if (!strcmp(style, "subtract") || !strcmp(style, "union") ||
               !strcmp(style, "intersect")) {
        int min = style[0] == 'u' ? 1 : 2;
        if (nrest < min)
            gr_error(g, "group %s needs at least %d group IDs", style, min);
        unsigned masks[GR_MAXGROUP];
        if (nrest > GR_MAXGROUP)
            gr_error(g, "too many group IDs");
        for (int k = 0; k < nrest; k++)
            masks[k] = group_bit(arg_group(g, rest[k]));
        bit = group_bit(group_create(g, id));
        for (int i = 0; i < a->n; i++) {
            unsigned m = a->mask[i];
            int in;
            if (style[0] == 'u') {
                in = 0;
                for (int k = 0; k < nrest; k++)
                    in |= (m & masks[k]) != 0;
            } else if (style[0] == 'i') {
                in = 1;
                for (int k = 0; k < nrest; k++)
                    in &= (m & masks[k]) != 0;
            } else {
                in = (m & masks[0]) != 0;
                for (int k = 1; k < nrest; k++)
                    if (m & masks[k])
                        in = 0;
            }
            if (in)
                a->mask[i] |= bit;
        }
    } else if (!strcmp(style, "variable")) {
        if (nrest != 1)
            gr_error(g, "group variable needs exactly one atom-style variable");
        var_check_atom(g, rest[0], "group variable");
        double *v = var_atom_values(g, rest[0]);
        bit = group_bit(group_create(g, id));
        for (int i = 0; i < a->n; i++)
            if (v[i] != 0.0)
                a->mask[i] |= bit;
        free(v);
    } else if (!strcmp(style, "include") || !strcmp(style, "molecule")) {
        gr_error(g, "group style '%s' is not supported", style);
    } else {
        gr_error(g, "unknown group style '%.32s'", style);
    }
    print_count(g, group_find(g, id));
}
